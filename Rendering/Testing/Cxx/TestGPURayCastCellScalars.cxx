// Cell scalars (constant per tetrahedron), selected by name with
// SetScalarModeToUseCellFieldData while the point scalars stay active:
// baseline image and 144 pixels against the exact CPU integral.

#include "PPIRayBaseline.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCellData.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>

int TestGPURayCastCellScalars(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  const int n[3] = { 6, 6, 6 };
  const double origin[3] = { 0, 0, 0 };
  auto grid = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 6, origin, [](int, int, int) { return true; }, ppiray_test::Blob);
  // Cell value: the field at the cell centroid.
  vtkNew<vtkDoubleArray> cellValues;
  cellValues->SetName("centroid");
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    grid->GetCellPoints(c, npts, pts);
    double centroid[3] = { 0, 0, 0 };
    for (int v = 0; v < 4; ++v)
    {
      double p[3];
      grid->GetPoint(pts[v], p);
      for (int i = 0; i < 3; ++i)
      {
        centroid[i] += 0.25 * p[i];
      }
    }
    cellValues->InsertNextValue(ppiray_test::Blob(centroid[0], centroid[1], centroid[2]));
  }
  grid->GetCellData()->AddArray(cellValues);

  ppiray_test::Scene scene(300, 300);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  ppiray_test::UseTetrahedronLayout(mapper);
  mapper->SetInputData(grid);
  mapper->SetScalarModeToUseCellFieldData();
  mapper->SelectScalarArray("centroid");
  scene.Volume->SetMapper(mapper);
  scene.Renderer->GetActiveCamera()->SetPosition(2.2, 1.4, 2.6);
  scene.Renderer->GetActiveCamera()->SetFocalPoint(0.5, 0.5, 0.5);
  scene.Renderer->ResetCamera();
  scene.Window->Render();

  int errors = 0;
  const auto image = ppiray_test::ReadRGB(scene.Window);
  const auto check =
    ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, 300, 300, "centroid");
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
