// A non-convex mesh: a block with a square tunnel through it, beside a second,
// separate block. Seen at an angle, rays leave and re-enter the mesh several
// times, so depth peeling needs several layers: at least 3 peels, a baseline
// image, and 144 pixels against the exact per-ray CPU integral.

#include "PPIRayBaseline.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>

int TestGPURayCastNonConvex(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  auto grid = ppiray_test::TunnelAndBlock();

  ppiray_test::Scene scene(300, 300);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.7, 0.1);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  ppiray_test::UseTetrahedronLayout(mapper);
  mapper->SetInputData(grid);
  scene.Volume->SetMapper(mapper);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(-0.9, 0.75, 0.9);
  camera->SetFocalPoint(0.5, 0.3, 0.3);
  scene.Renderer->ResetCamera();
  scene.Window->Render();

  int errors = 0;
  std::cout << "peels: " << mapper->GetStatistics()->GetNumberOfPeels() << "\n";
  if (mapper->GetStatistics()->GetNumberOfPeels() < 3)
  {
    std::cerr << "expected at least 3 peels, got " << mapper->GetStatistics()->GetNumberOfPeels()
              << "\n";
    ++errors;
  }
  const auto image = ppiray_test::ReadRGB(scene.Window);
  const auto check =
    ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, 300, 300);
  std::cout << "pixels checked " << check.Pixels << ", max difference " << check.MaxDifference
            << "/255\n";
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
