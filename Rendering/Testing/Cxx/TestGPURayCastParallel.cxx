// Parallel projection of the non-convex tunnel mesh, looking down the tunnel
// at an angle: baseline image and 144 pixels against the exact CPU integral.

#include "PPIRayBaseline.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>

int TestGPURayCastParallel(int argc, char* argv[])
{
  const int n[3] = { 6, 6, 6 };
  const double origin[3] = { 0, 0, 0 };
  auto keep = [](int, int j, int k) { return !(j >= 2 && j < 4 && k >= 2 && k < 4); };
  auto grid = ppiray_test::VoxelTetrahedra(n, 1.0 / 6, origin, keep, ppiray_test::Blob);

  ppiray_test::Scene scene(300, 300);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  mapper->SetInputData(grid);
  scene.Volume->SetMapper(mapper);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(3.0, 0.9, 0.8);
  camera->SetFocalPoint(0.5, 0.5, 0.5);
  scene.Renderer->ResetCamera();
  scene.Window->Render();

  int errors = 0;
  const auto image = ppiray_test::ReadRGB(scene.Window);
  const auto check =
    ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, 300, 300);
  std::cout << "peels " << mapper->GetStatistics()->GetNumberOfPeels() << ", pixels checked "
            << check.Pixels << ", max difference " << check.MaxDifference << "/255\n";
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
