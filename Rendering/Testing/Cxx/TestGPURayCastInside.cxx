// A camera inside the mesh: every ray starts at the near plane in the cell
// its start point lies in (the sections of the cells the near plane cuts,
// vtkPPIRayDepthPeeling), and marches on as usual; the reference renderer's
// rays start at the near plane too. Scenes (a table): a block of tetrahedra
// and the same block as native hexahedra, perspective and parallel, the eye
// inside a cell, the near plane exactly on a layer of faces (the sections of
// the cells in front of it only), and near a vertex of the mesh; the block
// has a hole the rays cross, so peels follow the start.
//
// Each scene against the reference: every covered pixel, p99 and max at most
// 1/255 (8-bit rounding 0.5, float, the 0.1/255 transfer-function
// tolerance: nothing else separates the two), the covered
// pixels (the whole window: the eye is inside and the field nowhere
// transparent, so a ray that does not start inside leaves a pixel black and
// fails the count), and a baseline per scene. Without the near-plane start
// (the sections left out) every scene fails: p99 187 to 200/255.

#include "PPIRayBaseline.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <array>
#include <iostream>
#include <string>

namespace
{
constexpr int Size = 150;

struct InsideScene
{
  const char* Name;
  bool Hexahedra;
  bool Parallel;
  std::array<double, 3> Eye, Focal;
  double Near; // distance of the near plane from the eye
};
}

int TestGPURayCastInside(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  // [0, 1]^3 in 8^3 voxels, a tunnel of 2 x 2 voxels removed along x at
  // mid-height: rays from inside leave into the tunnel and re-enter.
  const int n[3] = { 8, 8, 8 };
  const double origin[3] = { 0, 0, 0 };
  auto keep = [](int, int j, int k) { return !(j >= 5 && j < 7 && k >= 3 && k < 5); };
  auto field = [](double x, double y, double z) { return 0.3 + 0.7 * ppiray_test::Blob(x, y, z); };
  auto tetrahedra = ppiray_test::VoxelTetrahedra(n, 1.0 / 8, origin, keep, field);
  // The same block as hexahedra: the voxels' six tetrahedra share their
  // corners, so each voxel is a hexahedron of the tetrahedra's points.
  auto hexahedra = vtkSmartPointer<vtkUnstructuredGrid>::New();
  {
    vtkNew<vtkUnstructuredGrid> voxels;
    voxels->SetPoints(tetrahedra->GetPoints());
    voxels->GetPointData()->ShallowCopy(tetrahedra->GetPointData());
    auto id = [&](int i, int j, int k)
    {
      double x[3] = { i / 8.0, j / 8.0, k / 8.0 };
      return tetrahedra->FindPoint(x);
    };
    for (int k = 0; k < n[2]; ++k)
    {
      for (int j = 0; j < n[1]; ++j)
      {
        for (int i = 0; i < n[0]; ++i)
        {
          if (keep(i, j, k))
          {
            const vtkIdType v[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
              id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
              id(i, j + 1, k + 1) };
            hexahedra->InsertNextCell(VTK_HEXAHEDRON, 8, v);
          }
        }
      }
    }
    hexahedra->SetPoints(voxels->GetPoints());
    hexahedra->GetPointData()->ShallowCopy(voxels->GetPointData());
  }

  const InsideScene scenes[] = {
    { "TetrahedraPerspective", false, false, { 0.43, 0.2, 0.47 }, { 0.5, 1.0, 0.55 }, 0.01 },
    { "TetrahedraParallel", false, true, { 0.43, 0.2, 0.47 }, { 0.5, 1.0, 0.55 }, 0.01 },
    // The near plane on the faces y = 2/8 (eye at y = 0.2, near 0.05).
    { "TetrahedraNearPlaneOnFaces", false, false, { 0.45, 0.2, 0.52 }, { 0.45, 1.0, 0.52 }, 0.05 },
    // The eye 1e-4 from the vertex (3/8, 2/8, 4/8), the near plane 1e-3 away.
    { "TetrahedraNearVertex", false, false, { 0.3751, 0.2501, 0.5001 }, { 0.9, 0.9, 0.7 }, 0.001 },
    { "HexahedraPerspective", true, false, { 0.43, 0.2, 0.47 }, { 0.5, 1.0, 0.55 }, 0.01 },
    { "HexahedraParallel", true, true, { 0.43, 0.2, 0.47 }, { 0.5, 1.0, 0.55 }, 0.01 },
    { "HexahedraNearPlaneOnFaces", true, false, { 0.45, 0.2, 0.52 }, { 0.45, 1.0, 0.52 }, 0.05 },
  };
  int errors = 0;
  for (const InsideScene& inside : scenes)
  {
    vtkUnstructuredGrid* grid = inside.Hexahedra ? hexahedra.Get() : tetrahedra.Get();
    ppiray_test::Scene scene(Size, Size);
    double range[2];
    grid->GetPointData()->GetScalars()->GetRange(range);
    // Opacity from 0.35 at the smallest value to 0.7: no pixel is clear.
    ppiray_test::SmoothTransferFunction(
      scene.Property, 2 * range[0] - range[1], range[1], 0.7, 0.15);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
    ppiray_test::UseTetrahedronLayout(mapper);
    vtkNew<ppiray_test::MessageCollector> messages;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    mapper->SetInputData(grid);
    scene.Volume->SetMapper(mapper);
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetPosition(inside.Eye.data());
    camera->SetFocalPoint(inside.Focal.data());
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(70.0);
    camera->SetParallelProjection(inside.Parallel);
    camera->SetParallelScale(0.25);
    camera->SetClippingRange(inside.Near, 3.0);
    scene.Window->Render();

    const auto image = ppiray_test::ReadRGB(scene.Window);
    const auto check =
      ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, Size, Size);
    std::cout << inside.Name << ": " << grid->GetNumberOfCells() << " cells, "
              << mapper->GetStatistics()->GetNumberOfPeels() << " peels, " << check.Pixels
              << " pixels covered, p99 " << check.P99 << " max " << check.MaxDifference
              << " /255; messages [" << messages->Warnings << messages->Errors << "]\n";
    if (check.P99 > 1.0 || check.MaxDifference > 1.0)
    {
      std::cout << "FAILED: " << inside.Name << " differs from the reference\n";
      ++errors;
    }
    errors += ppiray_test::ExpectCoverage(check, Size * Size);
    if (inside.Hexahedra &&
        mapper->GetStatistics()->GetNumberOfHexahedra() != grid->GetNumberOfCells())
    {
      std::cout << "FAILED: " << inside.Name << ": not rendered as native hexahedra\n";
      ++errors;
    }
    errors += ppiray_test::BaselineTest(argc, argv, scene.Window, inside.Name);
  }
  return errors ? 1 : 0;
}
