// Rays that need more loop iterations than a driver lets one shader
// invocation take (Mesa's llvmpipe ends all loops together past 65,535,
// silently): a field oscillating across the range a few times per cell and
// a transfer function of 2,000 colour nodes, so each ray crosses thousands
// of control points. The march spends a budget per pass and continues the
// rays that ran out in further passes (march_common_fs.glsl); each image
// must equal the CPU reference, and the exact-linear and native hexahedron
// modes (many loop iterations per piece) must have needed continuations.
// Random cell scalars make each step jump across hundreds of control points,
// a different number in each pixel (the fuzz driver's seed 3, case 5637).
// With the opacity zero below 0.7 over a field s = x, the colour nodes are
// crossed inside one transparent run by cell segments that lie in it whole
// and are not integrated (transparentSpan): those images need no
// continuation at all.

#include "PPIRayImageCompare.h"
#include "PPIRayReferenceImage.h"
#include "PPIRayTestScenes.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
constexpr int Size = 64;

// s = 0.5 + 0.5 sin(2 pi (x + 2 y + 3 z) / 0.35): a few sweeps of [0, 1]
// per cell of a 16^3 block of the unit cube.
double Oscillating(double x, double y, double z)
{
  return 0.5 + 0.5 * std::sin(2.0 * M_PI * (x + 2.0 * y + 3.0 * z) / 0.35);
}

// A deterministic value in [0, 1) for node i, channel c.
double Hashed(int i, int c)
{
  const double v = std::sin(12.9898 * i + 78.233 * c) * 43758.5453;
  return v - std::floor(v);
}

// 2,000 random RGB colour nodes and 2,000 low opacity nodes on [0, 1]; with
// `transparentBelow` > 0, the colour nodes on [0, transparentBelow] with
// opacity zero there, and above it an opacity ramp from 0 to 1 (few control
// points).
void ManyNodes(vtkVolumeProperty* property, double transparentBelow)
{
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  for (int i = 0; i < 2000; ++i)
  {
    const double x = (transparentBelow > 0 ? transparentBelow : 1.0) * i / 1999.0;
    color->AddRGBPoint(x, Hashed(i, 0), Hashed(i, 1), Hashed(i, 2));
    opacity->AddPoint(x, transparentBelow > 0 ? 0.0 : 0.2 * Hashed(i, 3));
  }
  if (transparentBelow > 0)
  {
    opacity->AddPoint(1.0, 1.0);
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.5);
}

// The grid with a value per cell drawn from [0, 1) (Hashed) in place of its
// point scalars: along a ray the scalar jumps across hundreds of control
// points at every face, a different number in each pixel.
vtkSmartPointer<vtkUnstructuredGrid> RandomCellScalars(vtkUnstructuredGrid* grid)
{
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->ShallowCopy(grid);
  out->GetPointData()->Initialize();
  vtkNew<vtkDoubleArray> values;
  values->SetName("c");
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    values->InsertNextValue(Hashed(static_cast<int>(c), 5));
  }
  out->GetCellData()->SetScalars(values);
  return out;
}

// continuations: 1 the image must have needed some, -1 none, 0 either.
int Check(const std::string& name, vtkUnstructuredGrid* grid,
  vtkUnstructuredGridGPURayCastMapper* mapper, double transparentBelow, int continuations)
{
  ppiray_test::Scene scene(Size, Size);
  ManyNodes(scene.Property, transparentBelow);
  scene.Show(mapper, grid, { 1.6, 1.3, 2.2 }, { 0.5, 0.5, 0.5 });
  scene.Window->Render();
  const auto image = ppiray_test::ReadRGB(scene.Window);
  const auto exact =
    ppiray_test::ReferenceRGB(grid, scene.Property, scene.Renderer->GetActiveCamera(), Size, Size);
  std::vector<double> d;
  int covered = 0;
  for (int p = 0; p < Size * Size; ++p)
  {
    bool lit = false;
    for (int c = 0; c < 3; ++c)
    {
      lit = lit || exact[3 * p + c] > 0 || image[3 * p + c] > 0;
    }
    covered += lit ? 1 : 0;
    for (int c = 0; lit && c < 3; ++c)
    {
      d.push_back(std::abs(static_cast<double>(image[3 * p + c]) - exact[3 * p + c]));
    }
  }
  std::sort(d.begin(), d.end());
  const double p99 = d.empty() ? 0.0 : d[static_cast<size_t>(0.99 * (d.size() - 1))];
  const double max = d.empty() ? 0.0 : d.back();
  std::cout << name << ": " << mapper->GetStatistics()->GetNumberOfContinuations()
            << " continuations, " << covered << " pixels covered, p99 " << p99 << ", max " << max
            << " /255\n";
  int errors = 0;
  // Bounds: both rounded to 8 bits (1) plus float rounding over thousands of
  // pieces per ray; a ray cut short is tens of levels dark.
  if (p99 > 1.0 || max > 3.0)
  {
    std::cerr << name << ": differs from the reference (p99 " << p99 << ", max " << max << ")\n";
    ++errors;
  }
  if (covered < Size * Size / 4)
  {
    std::cerr << name << ": only " << covered << " pixels covered\n";
    ++errors;
  }
  if (continuations > 0 && mapper->GetStatistics()->GetNumberOfContinuations() == 0)
  {
    std::cerr << name << ": no continuation pass; the scene no longer exceeds the budget\n";
    ++errors;
  }
  if (continuations < 0 && mapper->GetStatistics()->GetNumberOfContinuations() > 0)
  {
    std::cerr << name << ": " << mapper->GetStatistics()->GetNumberOfContinuations()
              << " continuation passes; transparent spans were split at control points\n";
    ++errors;
  }
  return errors;
}
}

int TestGPURayCastLoopBudget(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  const int n[3] = { 16, 16, 16 };
  const double origin[3] = { 0, 0, 0 };
  auto tetrahedra = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 16, origin, [](int, int, int) { return true; }, Oscillating);
  auto hexahedra = ppiray_test::FieldVoxelBlock(16, Oscillating, "s").Hexahedra;

  int errors = 0;
  vtkNew<vtkUnstructuredGridGPURayCastMapper> ppi;
  errors += Check("tetrahedra, partial pre-integration", tetrahedra, ppi, 0.0, 0);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> exact;
  exact->SetIntegrationModeToExactLinear();
  errors += Check("tetrahedra, exact linear", tetrahedra, exact, 0.0, 1);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> accurate;
  accurate->SetHexahedronMode(vtkUnstructuredGridGPURayCastMapper::HEXAHEDRON_ACCURATE);
  errors += Check("native hexahedra, accurate", hexahedra, accurate, 0.0, 1);
  // Cell scalars at random: each step looks the control interval up afresh
  // (a search of fixed length, not a walk from the last one; walks of
  // different lengths in neighbouring pixels made a SIMD group of llvmpipe
  // exceed its loop limit where no single ray exceeded the budget).
  vtkNew<vtkUnstructuredGridGPURayCastMapper> cellData;
  errors +=
    Check("tetrahedra, random cell scalars", RandomCellScalars(tetrahedra), cellData, 0.0, 0);
  // s = x: each cell's segment spans 1/16 of the range, about 180 colour
  // nodes, and the cells below 0.7 are transparent whole.
  auto ramp = [](double x, double, double) { return x; };
  auto rampTetrahedra = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 16, origin, [](int, int, int) { return true; }, ramp);
  auto rampHexahedra = ppiray_test::FieldVoxelBlock(16, ramp, "s").Hexahedra;
  errors +=
    Check("tetrahedra, exact linear, s = x, transparent below 0.7", rampTetrahedra, exact, 0.7, -1);
  errors += Check(
    "native hexahedra, accurate, s = x, transparent below 0.7", rampHexahedra, accurate, 0.7, -1);
  return errors == 0 ? 0 : 1;
}
