// Clipping planes (vtkAbstractMapper::AddClippingPlane, at most 6): each ray
// piece is cut exactly where a plane crosses it, the side a plane's normal
// points to kept, as VTK's mappers keep it; the reference renderer clips the
// same way (independently). Scenes (a table): one oblique plane, two planes
// (a wedge), six planes (a box inside the mesh), a plane through the eye with
// the camera inside the mesh, native hexahedra with two planes, and seven
// planes (the seventh ignored, with a warning).
//
// Each scene against the clipped reference: every covered pixel, p99 and max
// at most 1/255 (8-bit rounding 0.5, float, the 0.1/255 transfer-function
// tolerance); and against the unclipped reference, which must differ (p99
// above 20/255: the planes cut away most of what the rays cross); and a
// baseline per scene.

#include "PPIRayBaseline.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <array>
#include <iostream>
#include <vector>

namespace
{
constexpr int Size = 150;

struct Plane
{
  std::array<double, 3> Origin, Normal;
};

struct ClippingScene
{
  const char* Name;
  bool Hexahedra;
  std::array<double, 3> Eye, Focal;
  double Near; // 0: the camera fitted to the mesh
  std::vector<Plane> Planes;
};
}

int TestGPURayCastClipping(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  const int n[3] = { 8, 8, 8 };
  const double origin[3] = { 0, 0, 0 };
  auto all = [](int, int, int) { return true; };
  auto field = [](double x, double y, double z) { return 0.3 + 0.7 * ppiray_test::Blob(x, y, z); };
  auto tetrahedra = ppiray_test::VoxelTetrahedra(n, 1.0 / 8, origin, all, field);
  auto hexahedra = ppiray_test::BlobVoxelBlock(8).Hexahedra;

  const ClippingScene scenes[] = {
    { "OnePlane", false, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 }, 0.0,
      { { { 0.5, 0.5, 0.5 }, { -0.6, 0.5, 0.3 } } } },
    { "Wedge", false, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 }, 0.0,
      { { { 0.5, 0.5, 0.5 }, { 0.0, 1.0, 0.2 } }, { { 0.4, 0.5, 0.5 }, { 1.0, 0.0, -0.3 } } } },
    { "Box", false, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 }, 0.0,
      { { { 0.2, 0.0, 0.0 }, { 1, 0, 0 } }, { { 0.8, 0.0, 0.0 }, { -1, 0, 0 } },
        { { 0.0, 0.25, 0.0 }, { 0, 1, 0 } }, { { 0.0, 0.75, 0.0 }, { 0, -1, 0 } },
        { { 0.0, 0.0, 0.3 }, { 0, 0, 1 } }, { { 0.0, 0.0, 0.7 }, { 0, 0, -1 } } } },
    { "ThroughTheEyeInside", false, { 0.43, 0.2, 0.47 }, { 0.5, 1.0, 0.55 }, 0.01,
      { { { 0.43, 0.2, 0.47 }, { 1.0, 0.0, 0.4 } } } },
    { "HexahedraWedge", true, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 }, 0.0,
      { { { 0.5, 0.5, 0.5 }, { 0.0, 1.0, 0.2 } }, { { 0.4, 0.5, 0.5 }, { 1.0, 0.0, -0.3 } } } },
    { "SevenPlanes", false, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 }, 0.0,
      { { { 0.2, 0.0, 0.0 }, { 1, 0, 0 } }, { { 0.8, 0.0, 0.0 }, { -1, 0, 0 } },
        { { 0.0, 0.25, 0.0 }, { 0, 1, 0 } }, { { 0.0, 0.75, 0.0 }, { 0, -1, 0 } },
        { { 0.0, 0.0, 0.3 }, { 0, 0, 1 } }, { { 0.0, 0.0, 0.7 }, { 0, 0, -1 } },
        { { 0.5, 0.5, 0.5 }, { 1, 1, 1 } } } },
  };
  int errors = 0;
  for (const ClippingScene& clipping : scenes)
  {
    vtkUnstructuredGrid* grid = clipping.Hexahedra ? hexahedra.Get() : tetrahedra.Get();
    ppiray_test::Scene scene(Size, Size);
    double range[2];
    grid->GetPointData()->GetScalars()->GetRange(range);
    ppiray_test::SmoothTransferFunction(scene.Property, range[0], range[1], 0.7, 0.15);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    vtkNew<ppiray_test::MessageCollector> messages;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    vtkNew<vtkPlaneCollection> planes;
    for (const Plane& p : clipping.Planes)
    {
      vtkNew<vtkPlane> plane;
      plane->SetOrigin(p.Origin.data());
      plane->SetNormal(p.Normal.data());
      planes->AddItem(plane);
    }
    mapper->SetClippingPlanes(planes);
    scene.Show(mapper, grid, clipping.Eye, clipping.Focal);
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    if (clipping.Near > 0)
    {
      camera->SetPosition(clipping.Eye.data());
      camera->SetFocalPoint(clipping.Focal.data());
      camera->SetViewUp(0.0, 0.0, 1.0);
      camera->SetViewAngle(70.0);
      camera->SetClippingRange(clipping.Near, 3.0);
    }
    scene.Window->Render();

    const auto image = ppiray_test::ReadRGB(scene.Window);
    // The reference clips with the first six planes, as the mapper does.
    vtkNew<vtkPlaneCollection> used;
    for (int i = 0; i < std::min(planes->GetNumberOfItems(), 6); ++i)
    {
      used->AddItem(planes->GetItem(i));
    }
    const auto check = ppiray_test::CheckPixels(
      scene.Renderer, grid, scene.Property, image, Size, Size, nullptr, used);
    const auto unclipped =
      ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, Size, Size);
    std::cout << clipping.Name << ": " << planes->GetNumberOfItems() << " planes, "
              << mapper->GetStatistics()->GetNumberOfPeels() << " peels, " << check.Pixels
              << " pixels covered, p99 " << check.P99 << " max " << check.MaxDifference
              << " /255; against the unclipped reference p99 " << unclipped.P99 << "; messages ["
              << messages->Warnings << messages->Errors << "]\n";
    if (check.P99 > 1.0 || check.MaxDifference > 1.0)
    {
      std::cout << "FAILED: " << clipping.Name << " differs from the clipped reference\n";
      ++errors;
    }
    if (unclipped.P99 <= 20.0)
    {
      std::cout << "FAILED: " << clipping.Name << " looks unclipped\n";
      ++errors;
    }
    errors += ppiray_test::ExpectCoverage(check, Size * Size / 20);
    const bool warned = messages->Warnings.find("only the first 6") != std::string::npos;
    if (warned != (planes->GetNumberOfItems() > 6))
    {
      std::cout << "FAILED: " << clipping.Name << ": the warning about more than 6 planes\n";
      ++errors;
    }
    errors += ppiray_test::BaselineTest(argc, argv, scene.Window, clipping.Name);
  }
  return errors ? 1 : 0;
}
