// Accuracy against VTK's own unstructured mappers on a smooth transfer
// function, where they agree with the exact integral to about 1/255: the
// same scene with vtkUnstructuredGridVolumeZSweepMapper and
// vtkUnstructuredGridVolumeRayCastMapper (image sample distance 1, no
// auto-adjust). Prints mean / p99 / max per-channel differences (1/255 units)
// and bounds them; also bounds the two VTK mappers against each other, so a
// failure tells which side moved.

#include "PPIRayImageCompare.h"
#include "PPIRayTestScenes.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"

#include <iostream>

namespace
{
std::vector<unsigned char> RenderWith(
  vtkUnstructuredGridVolumeMapper* mapper, vtkUnstructuredGrid* grid, bool parallel)
{
  ppiray_test::Scene scene(200, 200);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
  mapper->SetInputData(grid);
  scene.Volume->SetMapper(mapper);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(2.0, 1.1, 2.4);
  camera->SetFocalPoint(0.5, 0.5, 0.5);
  camera->SetParallelProjection(parallel);
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  return ppiray_test::ReadRGB(scene.Window);
}
}

int TestGPURayCastAccuracy(int argc, char* argv[])
{
  std::string temporary = ".";
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-T")
    {
      temporary = argv[i + 1];
    }
  }
  const int n[3] = { 8, 8, 8 };
  const double origin[3] = { 0, 0, 0 };
  auto grid = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 8, origin, [](int, int, int) { return true; }, ppiray_test::Blob);

  int errors = 0;
  for (bool parallel : { false, true })
  {
    vtkNew<vtkUnstructuredGridGPURayCastMapper> ours;
    vtkNew<vtkUnstructuredGridVolumeZSweepMapper> zsweep;
    zsweep->SetImageSampleDistance(1.0);
    zsweep->AutoAdjustSampleDistancesOff();
    vtkNew<vtkUnstructuredGridVolumeRayCastMapper> raycast;
    raycast->SetImageSampleDistance(1.0);
    raycast->AutoAdjustSampleDistancesOff();

    const auto a = RenderWith(ours, grid, parallel);
    const auto z = RenderWith(zsweep, grid, parallel);
    const auto r = RenderWith(raycast, grid, parallel);
    const auto dz = ppiray_test::Compare(a, z);
    const auto dr = ppiray_test::Compare(a, r);
    const auto dzr = ppiray_test::Compare(z, r);
    const char* label = parallel ? "parallel" : "perspective";
    const std::string prefix = temporary + "/TestGPURayCastAccuracy-" + label;
    ppiray_test::WritePNG(prefix + "-ppiray.png", a, 200, 200);
    ppiray_test::WritePNG(prefix + "-zsweep.png", z, 200, 200);
    ppiray_test::WritePNG(prefix + "-raycast.png", r, 200, 200);
    ppiray_test::WritePNG(
      prefix + "-diff-zsweep.png", ppiray_test::DifferenceImage(a, z, 10), 200, 200);
    ppiray_test::WritePNG(
      prefix + "-diff-raycast.png", ppiray_test::DifferenceImage(a, r, 10), 200, 200);
    std::cout << label << " ours vs ZSweep:  mean " << dz.Mean << " p99 " << dz.P99 << " max "
              << dz.Max << "\n";
    std::cout << label << " ours vs RayCast: mean " << dr.Mean << " p99 " << dr.P99 << " max "
              << dr.Max << "\n";
    std::cout << label << " ZSweep vs RayCast: mean " << dzr.Mean << " p99 " << dzr.P99 << " max "
              << dzr.Max << "\n";
    // Bounds (1/255 units). Measured here: ours vs ZSweep mean 0.84 / p99 9,
    // ours vs RayCast mean 0.59 / p99 6, while ZSweep vs RayCast differ by
    // mean 1.03 / p99 11 (ZSweep shows its tetrahedra, RayCast has line
    // artefacts; ours matches the exact integral to 0.5/255, see
    // TestGPURayCastSpike). So: ours must be at most as far from each as they
    // are from each other (p99), and within one level on average.
    if (dz.Mean > 1.0 || dr.Mean > 1.0 || dz.P99 > dzr.P99 || dr.P99 > dzr.P99)
    {
      std::cerr << label << ": ours is further from VTK's mappers than the bound\n";
      ++errors;
    }
  }
  return errors == 0 ? 0 : 1;
}
