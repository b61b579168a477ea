// Volume and opaque geometry in one scene: a sphere inside the volume and a
// plane cutting through it. Rays stop at the opaque depth, so the volume is
// composited over the geometry where it is in front and hidden behind it.
// Baseline image, and two pixel probes: a ray that hits the sphere's centre
// carries less volume colour than the same ray without the sphere. The same
// scene in a multisampled window (VTK's default on many systems) must stop
// the rays at the resolved depth too: same centre pixel within 2/255.

#include "PPIRayBaseline.h"
#include "PPIRayImageCompare.h"
#include "PPIRayTestScenes.h"
#include "vtkActor.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>

int TestGPURayCastIntermix(int argc, char* argv[])
{
  const int n[3] = { 8, 8, 8 };
  const double origin[3] = { 0, 0, 0 };
  auto grid = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 8, origin, [](int, int, int) { return true; }, ppiray_test::Blob);

  ppiray_test::Scene scene(300, 300);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.9, 0.15);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  mapper->SetInputData(grid);
  scene.Volume->SetMapper(mapper);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.5, 0.5, 3.0);
  camera->SetFocalPoint(0.5, 0.5, 0.5);
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  const auto without = ppiray_test::ReadRGB(scene.Window);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.5, 0.5, 0.5);
  sphere->SetRadius(0.18);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.2, -0.2, 0.3);
  plane->SetPoint1(1.2, -0.2, 0.3);
  plane->SetPoint2(-0.2, 0.35, 0.3);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> planeActor;
  planeActor->SetMapper(planeMapper);
  planeActor->GetProperty()->SetColor(0.8, 0.3, 0.8);
  scene.Renderer->AddActor(sphereActor);
  scene.Renderer->AddActor(planeActor);
  scene.Window->Render();
  const auto with = ppiray_test::ReadRGB(scene.Window);

  int errors = 0;
  // Centre pixel: the sphere (white, lit) is behind half of the volume, so the
  // pixel is brighter than the volume alone but not the sphere's full white.
  const int centre = 3 * (150 * 300 + 150);
  const int sum0 = without[centre] + without[centre + 1] + without[centre + 2];
  const int sum1 = with[centre] + with[centre + 1] + with[centre + 2];
  std::cout << "centre pixel without sphere " << sum0 << ", with " << sum1 << "\n";
  if (!(sum1 > sum0) || sum1 >= 3 * 250)
  {
    std::cerr << "the volume in front of the sphere is not composited over it\n";
    ++errors;
  }
  const int result = ppiray_test::BaselineTest(argc, argv, scene.Window);

  scene.Window->SetMultiSamples(4);
  scene.Window->Render();
  const auto multisampled = ppiray_test::ReadRGB(scene.Window);
  int worst = 0;
  for (int c = 0; c < 3; ++c)
  {
    worst = std::max(worst, std::abs(multisampled[centre + c] - with[centre + c]));
  }
  std::cout << "multisampled window: centre pixel differs by " << worst << "/255\n";
  if (worst > 2)
  {
    std::cerr << "opaque depth of a multisampled framebuffer is not honoured\n";
    ++errors;
  }
  return (errors == 0 && result == 0) ? 0 : 1;
}
