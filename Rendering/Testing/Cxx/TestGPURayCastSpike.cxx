// A transfer function with 36 control points, among them a one-value-wide
// opacity spike (0 -> 1 -> 0 over one scalar unit of a 0..100 range) that
// no sampling-based mapper can be relied on to hit: baseline image, and 144
// pixels checked against an exact per-ray CPU integration split at every
// control point (vtkUnstructuredGridReferenceRenderer, via PPIRayPixelCheck.h).

#include "PPIRayBaseline.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>

int TestGPURayCastSpike(int argc, char* argv[])
{
  const int n[3] = { 8, 8, 8 };
  const double origin[3] = { 0, 0, 0 };
  auto grid = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 8, origin, [](int, int, int) { return true; },
    [](double x, double y, double z) { return 100.0 * ppiray_test::Blob(x, y, z) / 1.3; });

  ppiray_test::Scene scene(300, 300);
  ppiray_test::SpikeTransferFunction(scene.Property);

  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  scene.Show(mapper, grid, { 2.0, 1.5, 2.5 }, { 0.5, 0.5, 0.5 });
  scene.Window->Render();

  int errors = 0;
  const auto image = ppiray_test::ReadRGB(scene.Window);
  const auto check =
    ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, 300, 300);
  std::cout << "control points: "
            << scene.Property->GetRGBTransferFunction()->GetSize() +
                 scene.Property->GetScalarOpacity()->GetSize()
            << ", pixels checked " << check.Pixels << ", max difference " << check.MaxDifference
            << "/255\n";
  // Bound: 8-bit rounding (0.5) plus the 0.999 early termination (0.26) plus
  // the Psi table's bilinear error; 2/255 leaves room for llvmpipe's float
  // rounding while any skipped spike shows as tens of levels.
  // 8-bit rounding 0.5, float and the 0.1/255 transfer-function tolerance
  if (check.MaxDifference > 1.0)
  {
    std::cerr << "pixels differ from the exact integral by up to " << check.MaxDifference
              << "/255\n";
    ++errors;
  }
  errors += ppiray_test::ExpectCoverage(check, 5000);
  const int result = ppiray_test::BaselineTest(argc, argv, scene.Window);
  return (errors == 0 && result == 0) ? 0 : 1;
}
