// A convex tetrahedral mesh (6 x 6 x 6 voxels, 1,296 tetrahedra) with a smooth
// field and transfer function, perspective camera: baseline image; one peel.

#include "PPIRayBaseline.h"
#include "PPIRayTestScenes.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>

int TestGPURayCastConvex(int argc, char* argv[])
{
  const int n[3] = { 6, 6, 6 };
  const double origin[3] = { 0, 0, 0 };
  auto grid = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 6, origin, [](int, int, int) { return true; }, ppiray_test::Blob);
  ppiray_test::Scene scene;
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  scene.Show(mapper, grid, { 2.2, 1.4, 2.6 }, { 0.5, 0.5, 0.5 });
  scene.Window->Render();

  int errors = 0;
  if (mapper->GetNumberOfPeels() != 1)
  {
    std::cerr << "convex mesh took " << mapper->GetNumberOfPeels() << " peels, expected 1\n";
    ++errors;
  }
  const int result = ppiray_test::BaselineTest(argc, argv, scene.Window);
  return (errors == 0 && result == 0) ? 0 : 1;
}
