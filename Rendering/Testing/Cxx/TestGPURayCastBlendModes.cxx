// The projections (SetBlendModeToMaximumIntensity, ...ToMinimumIntensity,
// ...ToAverageIntensity, ...ToAdditive): exact per cell, in
// vtkGPUVolumeRayCastMapper's units. Maximum and minimum: the extreme scalar
// along each ray, coloured by the transfer function's colour and scalar
// opacity there. Average: over the parts of the ray with the scalar in
// AverageIPScalarRange, the mean of scalar opacity x normalized scalar, grey.
// Additive: the integral of scalar opacity x normalized scalar per unit
// distance, grey. Scenes (a table): a block of tetrahedra with a tunnel
// (rays leave and re-enter: the state is carried across peels) and the same
// block as native hexahedra (a cubic's extremes inside a cell; its integral
// by quadrature), the camera outside and inside the mesh; the average and
// additive scenes with an opacity that rises and falls across the range
// (control points crossed inside cells), the average one also over a part
// of the range only (rays that meet none of it draw nothing); a maximum
// projection of cell scalars (a value per cell: the image is discontinuous
// wherever a ray passes a cell edge) from inside the mesh with the near
// plane 1e-4 of the far one, where the rays' directions must be made in
// double (in float their far points lose the digits: at pixels whose rays
// pass near a cell edge, the neighbouring cell's value).
//
// Each scene against the reference renderer in the same blend mode (its own
// integral: 3-point Gauss-Legendre over its transfer-function pieces, the
// GPU's Simpson rule or 4-point quadrature on the cubic): every
// covered pixel, p99 and max at most 1/255 (8-bit rounding 0.5, float, the
// 0.1/255 transfer-function tolerance), except on the silhouette (a pixel
// with an uncovered neighbour in the reference), where at most 5 pixels may
// differ more: a ray that only touches the mesh at a boundary edge takes the
// full colour of the value there in a projection (nothing in composite), and
// whether it touches is the rasterizer's call on the GPU and a 1e-9
// tolerance in the reference (measured: 1 pixel per scene, where the GPU
// draws nothing and the reference the full colour, 104/255); against the
// composite reference, which must differ (p99 above 20/255); a baseline per
// scene. A blend mode the mapper does not draw (SLICE_BLEND) renders
// composite with a warning.

#include "PPIRayBaseline.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>

namespace
{
constexpr int Size = 150;

// Pixels above 1/255 on the silhouette of the reference's coverage.
struct Silhouette
{
  int Pixels = 0;
  double Max = 0;
};

// A reference renderer in `blend`, against `image`; with `silhouette`, the
// pixels above 1/255 next to an uncovered one are counted there, not in the check.
ppiray_test::PixelCheck AgainstReference(vtkRenderer* renderer, vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, const std::vector<unsigned char>& image, int blend,
  const double averageRange[2], Silhouette* silhouette = nullptr)
{
  vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
  reference->SetAverageIPScalarRange(averageRange[0], averageRange[1]);
  reference->SetInputData(grid);
  reference->SetVolumeProperty(property);
  reference->SetCamera(renderer->GetActiveCamera());
  reference->SetImageSize(Size, Size);
  reference->SetBlendMode(blend);
  reference->Update();
  auto* exact = vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetScalars());
  auto referenceCovers = [&](int x, int y) {
    return x < 0 || y < 0 || x >= Size || y >= Size || exact->GetComponent(y * Size + x, 3) > 0.0;
  };
  ppiray_test::PixelCheck check;
  std::vector<double> differences;
  for (int p = 0; p < Size * Size; ++p)
  {
    bool covered = false;
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double expected = 255.0 * std::min(1.0, std::max(0.0, exact->GetComponent(p, c)));
      covered = covered || std::round(expected) >= 1 || image[3 * p + c] >= 1;
      worst = std::max(worst, std::abs(image[3 * p + c] - expected));
      differences.push_back(std::abs(image[3 * p + c] - expected));
    }
    const int x = p % Size, y = p / Size;
    bool onSilhouette = false;
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        onSilhouette = onSilhouette || !referenceCovers(x + dx, y + dy);
      }
    }
    if (!covered || (silhouette && onSilhouette && worst > 1.0))
    {
      if (covered)
      {
        ++silhouette->Pixels;
        silhouette->Max = std::max(silhouette->Max, worst);
      }
      differences.resize(differences.size() - 3);
      continue;
    }
    ++check.Pixels;
    check.NaNPixels += std::isnan(exact->GetComponent(p, 0)) ? 1 : 0;
  }
  std::sort(differences.begin(), differences.end());
  if (!differences.empty())
  {
    check.P99 = differences[static_cast<size_t>(0.99 * (differences.size() - 1))];
    check.MaxDifference = differences.back();
  }
  return check;
}

struct BlendScene
{
  const char* Name;
  bool Hexahedra;
  int Blend;
  bool Inside;
  double AverageRange[2];   // fractions of the scalar range (average only)
  bool CellScalars = false; // a hashed value per cell instead of the blob
  double Near = 0.01;       // the near plane's distance when inside (far: 3)
};

// Opacity rising and falling across [lo, hi] (control points inside the
// cells), a colour ramp; `unitDistance` sets the additive scale.
void RiseAndFallTransferFunction(
  vtkVolumeProperty* property, double lo, double hi, double peak, double unitDistance)
{
  ppiray_test::SmoothTransferFunction(property, lo, hi, peak, unitDistance);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  opacity->RemoveAllPoints();
  opacity->AddPoint(lo, 0.2 * peak);
  opacity->AddPoint(lo + 0.4 * (hi - lo), peak);
  opacity->AddPoint(lo + 0.6 * (hi - lo), 0.1 * peak);
  opacity->AddPoint(hi, 0.7 * peak);
}
}

int TestGPURayCastBlendModes(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  const int n[3] = { 8, 8, 8 };
  const double origin[3] = { 0, 0, 0 };
  auto keep = [](int, int j, int k) { return !(j >= 5 && j < 7 && k >= 3 && k < 5); };
  auto tetrahedra = ppiray_test::VoxelTetrahedra(n, 1.0 / 8, origin, keep, ppiray_test::Blob);
  auto hexahedra = ppiray_test::BlobVoxelBlock(8).Hexahedra;
  // The tetrahedra with a value per cell in [0, 1), hashed from its id.
  vtkNew<vtkUnstructuredGrid> cellTetrahedra;
  cellTetrahedra->ShallowCopy(tetrahedra);
  cellTetrahedra->GetPointData()->Initialize();
  vtkNew<vtkFloatArray> cellValues;
  cellValues->SetName("hashed");
  for (vtkIdType c = 0; c < cellTetrahedra->GetNumberOfCells(); ++c)
  {
    const double v = std::sin(12.9898 * c) * 43758.5453;
    cellValues->InsertNextValue(static_cast<float>(v - std::floor(v)));
  }
  cellTetrahedra->GetCellData()->SetScalars(cellValues);

  using Mapper = vtkUnstructuredGridGPURayCastMapper;
  const BlendScene scenes[] = {
    { "TetrahedraMaximum", false, Mapper::MAXIMUM_INTENSITY_BLEND, false, { 0, 1 } },
    { "TetrahedraMinimum", false, Mapper::MINIMUM_INTENSITY_BLEND, false, { 0, 1 } },
    { "TetrahedraMaximumInside", false, Mapper::MAXIMUM_INTENSITY_BLEND, true, { 0, 1 } },
    { "HexahedraMaximum", true, Mapper::MAXIMUM_INTENSITY_BLEND, false, { 0, 1 } },
    { "HexahedraMinimum", true, Mapper::MINIMUM_INTENSITY_BLEND, false, { 0, 1 } },
    { "TetrahedraAverage", false, Mapper::AVERAGE_INTENSITY_BLEND, false, { 0, 1 } },
    { "TetrahedraAverageRange", false, Mapper::AVERAGE_INTENSITY_BLEND, false, { 0.55, 0.8 } },
    { "TetrahedraAdditive", false, Mapper::ADDITIVE_BLEND, false, { 0, 1 } },
    { "TetrahedraAdditiveInside", false, Mapper::ADDITIVE_BLEND, true, { 0, 1 } },
    { "HexahedraAverageRange", true, Mapper::AVERAGE_INTENSITY_BLEND, false, { 0.55, 0.8 } },
    { "HexahedraAdditive", true, Mapper::ADDITIVE_BLEND, false, { 0, 1 } },
    { "TetrahedraCellMaximumNearPlane", false, Mapper::MAXIMUM_INTENSITY_BLEND, true, { 0, 1 },
      true, 3e-4 },
  };
  int errors = 0;
  for (const BlendScene& blend : scenes)
  {
    vtkUnstructuredGrid* grid = blend.CellScalars ? cellTetrahedra.Get()
                                : blend.Hexahedra ? hexahedra.Get()
                                                  : tetrahedra.Get();
    ppiray_test::Scene scene(Size, Size);
    double range[2];
    vtkDataArray* scalars =
      blend.CellScalars ? grid->GetCellData()->GetScalars() : grid->GetPointData()->GetScalars();
    scalars->GetRange(range);
    const double averageRange[2] = { range[0] + blend.AverageRange[0] * (range[1] - range[0]),
      range[0] + blend.AverageRange[1] * (range[1] - range[0]) };
    if (blend.Blend <= Mapper::MINIMUM_INTENSITY_BLEND)
    {
      // Opacity from 0.45 at the smallest value to 0.9: a minimum projection
      // is as visible as a maximum one.
      ppiray_test::SmoothTransferFunction(
        scene.Property, 2 * range[0] - range[1], range[1], 0.9, 0.15);
    }
    else
    {
      // Additive: about 0.6 on the longest rays.
      RiseAndFallTransferFunction(scene.Property, range[0], range[1], 0.9, 0.8);
    }
    vtkNew<Mapper> mapper;
    vtkNew<ppiray_test::MessageCollector> messages;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    mapper->SetBlendMode(blend.Blend);
    mapper->SetAverageIPScalarRange(averageRange[0], averageRange[1]);
    scene.Show(mapper, grid, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    if (blend.Inside)
    {
      vtkCamera* camera = scene.Renderer->GetActiveCamera();
      camera->SetPosition(0.43, 0.2, 0.47);
      camera->SetFocalPoint(0.5, 1.0, 0.55);
      camera->SetViewUp(0.0, 0.0, 1.0);
      camera->SetViewAngle(70.0);
      camera->SetClippingRange(blend.Near, 3.0);
    }
    scene.Window->Render();
    const auto image = ppiray_test::ReadRGB(scene.Window);
    Silhouette silhouette;
    const auto check = AgainstReference(
      scene.Renderer, grid, scene.Property, image, blend.Blend, averageRange, &silhouette);
    const auto composite = AgainstReference(scene.Renderer, grid, scene.Property, image,
      vtkUnstructuredGridReferenceRenderer::COMPOSITE_BLEND, averageRange);
    std::cout << blend.Name << ": " << mapper->GetStatistics()->GetNumberOfPeels() << " peels, "
              << check.Pixels << " pixels covered, p99 " << check.P99 << " max "
              << check.MaxDifference << " /255, " << silhouette.Pixels
              << " silhouette pixels above 1 (max " << silhouette.Max << "); against composite p99 "
              << composite.P99 << "; messages [" << messages->Warnings << messages->Errors << "]\n";
    if (check.P99 > 1.0 || check.MaxDifference > 1.0 || silhouette.Pixels > 5)
    {
      std::cout << "FAILED: " << blend.Name << " differs from the reference\n";
      ++errors;
    }
    if (composite.P99 <= 20.0)
    {
      std::cout << "FAILED: " << blend.Name << " looks composite\n";
      ++errors;
    }
    // The partial average range is met by about a tenth of the rays.
    const bool partRange = blend.AverageRange[1] - blend.AverageRange[0] < 1;
    errors += ppiray_test::ExpectCoverage(check, Size * Size / (partRange ? 20 : 10));
    if (!messages->Warnings.empty() || !messages->Errors.empty())
    {
      std::cout << "FAILED: " << blend.Name << ": unexpected messages\n";
      ++errors;
    }
    errors += ppiray_test::BaselineTest(argc, argv, scene.Window, blend.Name);
  }

  // The same field as image data through VTK's own GPU ray caster in each
  // projection: the hexahedra are the image's voxels and HEXAHEDRON_ACCURATE
  // interpolates them trilinearly as the image mapper does, so what may
  // differ is VTK's sampling (a sampled maximum falls short of the exact one
  // by at most f'' h^2 / 8; a sum or mean of samples h apart differs from
  // the integral by about one sample at each end of the ray: h = 1/400 here,
  // below 1/255) and its 1D colour and opacity tables (their resolution):
  // p99 at most 1/255, the same covered pixels within 1%, and at most 5
  // pixels more than 3/255 apart (measured: 1, the silhouette pixel whose
  // ray only touches the block's edge, met by VTK's box and missed by our
  // entry rasterization, as against the reference above). Additive: VTK
  // sums opacity x normalized scalar per sample, ours integrates it per unit
  // distance, so the unit distance is the sample distance here (and the
  // opacity small enough that the sum stays below 1).
  struct VTKScene
  {
    const char* Name;
    int Blend;
    double Peak; // of the opacity
  };
  const double h = 1.0 / 400;
  for (const VTKScene& blend : { VTKScene{ "maximum", Mapper::MAXIMUM_INTENSITY_BLEND, 0.9 },
         VTKScene{ "average", Mapper::AVERAGE_INTENSITY_BLEND, 0.9 },
         VTKScene{ "additive", Mapper::ADDITIVE_BLEND, 0.002 } })
  {
    auto block = ppiray_test::BlobVoxelBlock(8);
    ppiray_test::Scene scene(Size, Size);
    double range[2];
    block.Image->GetPointData()->GetScalars()->GetRange(range);
    const double averageRange[2] = { range[0] + 0.55 * (range[1] - range[0]),
      range[0] + 0.8 * (range[1] - range[0]) };
    if (blend.Blend == Mapper::MAXIMUM_INTENSITY_BLEND)
    {
      ppiray_test::SmoothTransferFunction(
        scene.Property, 2 * range[0] - range[1], range[1], blend.Peak, 0.15);
    }
    else
    {
      RiseAndFallTransferFunction(scene.Property, range[0], range[1], blend.Peak, h);
    }
    vtkNew<Mapper> mapper;
    mapper->SetBlendMode(blend.Blend);
    mapper->SetAverageIPScalarRange(averageRange[0], averageRange[1]);
    scene.Show(mapper, block.Hexahedra, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    scene.Window->Render();
    const auto ours = ppiray_test::ReadRGB(scene.Window);
    vtkNew<vtkGPUVolumeRayCastMapper> vtk;
    vtk->SetInputData(block.Image);
    vtk->SetBlendMode(blend.Blend);
    vtk->SetAverageIPScalarRange(averageRange[0], averageRange[1]);
    vtk->SetAutoAdjustSampleDistances(0);
    vtk->SetSampleDistance(h);
    scene.Volume->SetMapper(vtk);
    scene.Window->Render();
    const auto theirs = ppiray_test::ReadRGB(scene.Window);
    const auto d = ppiray_test::Compare(ours, theirs);
    int covered[2] = { 0, 0 }, apart = 0;
    double brightest = 0;
    for (size_t p = 0; p < ours.size(); p += 3)
    {
      covered[0] += std::max({ ours[p], ours[p + 1], ours[p + 2] }) > 0 ? 1 : 0;
      covered[1] += std::max({ theirs[p], theirs[p + 1], theirs[p + 2] }) > 0 ? 1 : 0;
      bool far = false;
      for (int c = 0; c < 3; ++c)
      {
        far = far || std::abs(ours[p + c] - theirs[p + c]) > 3;
        brightest = std::max(brightest, static_cast<double>(theirs[p + c]));
      }
      apart += far ? 1 : 0;
    }
    std::cout << blend.Name << " against vtkGPUVolumeRayCastMapper on the image: p99 " << d.P99
              << " max " << d.Max << " mean " << d.Mean << "; covered " << covered[0] << " and "
              << covered[1] << "; " << apart << " pixels more than 3/255 apart; VTK's brightest "
              << brightest << "\n";
    if (d.P99 > 1.0 || apart > 5 || std::abs(covered[0] - covered[1]) > covered[1] / 100 ||
        brightest < 40)
    {
      std::cout << "FAILED: " << blend.Name << " differs from VTK's on the same field\n";
      ++errors;
    }
  }

  // A blend mode not drawn: composite, with a warning.
  {
    ppiray_test::Scene scene(Size, Size);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.9, 0.15);
    vtkNew<Mapper> mapper;
    vtkNew<ppiray_test::MessageCollector> messages;
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    mapper->SetBlendMode(6); // vtkVolumeMapper::SLICE_BLEND
    scene.Show(mapper, tetrahedra, { 2.5, -1.5, 1.8 }, { 0.5, 0.5, 0.5 });
    scene.Window->Render();
    const auto image = ppiray_test::ReadRGB(scene.Window);
    const double everything[2] = { VTK_FLOAT_MIN, VTK_FLOAT_MAX };
    const auto check = AgainstReference(scene.Renderer, tetrahedra, scene.Property, image,
      vtkUnstructuredGridReferenceRenderer::COMPOSITE_BLEND, everything);
    std::cout << "SLICE_BLEND: against composite p99 " << check.P99 << " max "
              << check.MaxDifference << "; warnings [" << messages->Warnings << "]\n";
    if (check.MaxDifference > 1.0 || messages->Warnings.find("not supported") == std::string::npos)
    {
      std::cout << "FAILED: an unsupported blend mode is not composite with a warning\n";
      ++errors;
    }
  }
  return errors ? 1 : 0;
}
