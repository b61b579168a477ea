// Each cache is rebuilt for its own reason only (counted by the mapper):
// a transfer function edit re-uploads the control points but neither the
// geometry nor the field, and a property Modified() without new control
// points re-uploads nothing; a scalar edit re-uploads the field only; moving a
// point re-uploads the geometry. The image follows each edit, and
// GetGPUMemorySize() accounts for 96 bytes per tetrahedron plus the rest.

#include "PPIRayImageCompare.h"
#include "PPIRayTestScenes.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>

int TestGPURayCastCaches(int, char*[])
{
  const int n[3] = { 5, 5, 5 };
  const double origin[3] = { 0, 0, 0 };
  auto grid = ppiray_test::VoxelTetrahedra(
    n, 0.2, origin, [](int, int, int) { return true; }, ppiray_test::Blob);
  ppiray_test::Scene scene(120, 120);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  scene.Show(mapper, grid, { 2.2, 1.4, 2.6 }, { 0.5, 0.5, 0.5 });

  int errors = 0;
  auto expect = [&](int geometry, int field, int tf, const char* step)
  {
    std::cout << step << ": uploads geometry " << mapper->GetStatistics()->GetGeometryUploadCount()
              << ", field " << mapper->GetStatistics()->GetFieldUploadCount()
              << ", transfer function " << mapper->GetStatistics()->GetTransferFunctionUploadCount()
              << "\n";
    if (mapper->GetStatistics()->GetGeometryUploadCount() != geometry ||
        mapper->GetStatistics()->GetFieldUploadCount() != field ||
        mapper->GetStatistics()->GetTransferFunctionUploadCount() != tf)
    {
      std::cerr << "FAILED after " << step << ": expected " << geometry << " " << field << " " << tf
                << "\n";
      ++errors;
    }
  };

  scene.Window->Render();
  const auto first = ppiray_test::ReadRGB(scene.Window);
  expect(1, 1, 1, "first render");
  scene.Renderer->GetActiveCamera()->Azimuth(30);
  scene.Window->Render();
  expect(1, 1, 1, "camera move");

  // Modified() without a new transfer function (what ParaView does to its
  // lookup tables while rendering) uploads nothing.
  scene.Property->GetRGBTransferFunction()->Modified();
  scene.Property->Modified();
  scene.Window->Render();
  expect(1, 1, 1, "property touched, unchanged");

  scene.Property->GetScalarOpacity()->AddPoint(0.65, 0.9);
  scene.Window->Render();
  expect(1, 1, 2, "opacity edit");
  const auto afterTF = ppiray_test::ReadRGB(scene.Window);

  vtkDataArray* scalars = grid->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < scalars->GetNumberOfTuples(); ++p)
  {
    scalars->SetTuple1(p, 1.3 - scalars->GetTuple1(p));
  }
  scalars->Modified();
  scene.Window->Render();
  expect(1, 2, 2, "scalar edit");
  const auto afterField = ppiray_test::ReadRGB(scene.Window);

  double x[3];
  grid->GetPoints()->GetPoint(0, x);
  grid->GetPoints()->SetPoint(0, x[0] - 0.1, x[1], x[2]);
  grid->GetPoints()->Modified();
  scene.Window->Render();
  expect(2, 3, 2, "point edit");

  if (ppiray_test::Compare(first, afterTF).Max == 0 ||
      ppiray_test::Compare(afterTF, afterField).Max == 0)
  {
    std::cerr << "FAILED: an edit did not change the image\n";
    ++errors;
  }
  const vtkIdType tets = mapper->GetStatistics()->GetNumberOfTetrahedra();
  const vtkIdType bytes = mapper->GetStatistics()->GetGPUMemorySize();
  std::cout << tets << " tetrahedra, GPU bytes " << bytes << "\n";
  if (tets != 6 * 125 || bytes < 96 * tets)
  {
    std::cerr << "FAILED: GPU memory " << bytes << " below 96 B x " << tets << "\n";
    ++errors;
  }
  mapper->ReleaseGraphicsResources(scene.Window);
  if (mapper->GetStatistics()->GetGPUMemorySize() != 0)
  {
    std::cerr << "FAILED: " << mapper->GetStatistics()->GetGPUMemorySize()
              << " bytes left after release\n";
    ++errors;
  }
  scene.Window->Render();
  expect(3, 4, 3, "render after release");
  return errors == 0 ? 0 : 1;
}
