// The march as a fragment shader and as a compute shader (SetMarchStage):
// the same GLSL in two stages, each computing the pixel centre from the
// pixel's index (pixelCentre()), so every image must agree (max 1/255 per
// channel, for a GPU compiler that contracts the two stages' arithmetic
// differently; llvmpipe gives identical images) and cover the same pixels. Scenes: tetrahedra
// around a cavity (several peels), hexahedra natively, a maximum-intensity projection, a clipping
// plane, and a field that crosses thousands of transfer-function nodes per ray (loop-budget
// continuations: the compute stage's march must continue where the fragment stage's does). Each
// compute frame must have run in the compute stage (statistics), where the context has compute
// shaders (GL 4.3).
// With --expect-fallback (ctest runs it under MESA_GL_VERSION_OVERRIDE=3.3,
// a context without compute shaders): compute asked for, the fragment stage
// taken, one warning, the fragment stage's image. Nothing else may be
// printed by any VTK object (the passes around the march, e.g. the ray
// mask's and queue's, in both stages): no error, no other warning.

#include "PPIRayImageCompare.h"
#include "PPIRayMarchStageTests.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkUnstructuredGridGPURayCastStatistics.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
using Mapper = vtkUnstructuredGridGPURayCastMapper;
constexpr int Size = 120;

struct Stages
{
  std::vector<unsigned char> Fragment, Compute;
  int ComputeRan = -1;
  int Continuations = 0;
  std::string Warnings;
};

// `grid` rendered by one mapper in the fragment stage, then the compute stage.
Stages RenderBoth(ppiray_test::Scene& scene, vtkUnstructuredGrid* grid,
  const std::array<double, 3>& eye, const std::function<void(Mapper*)>& configure)
{
  vtkNew<Mapper> mapper;
  vtkNew<ppiray_test::MessageCollector> messages;
  mapper->AddObserver(vtkCommand::WarningEvent, messages);
  mapper->AddObserver(vtkCommand::ErrorEvent, messages);
  configure(mapper);
  scene.Show(mapper, grid, eye, { 0.5, 0.5, 0.5 });
  Stages out;
  mapper->SetMarchStageToFragment();
  scene.Window->Render();
  out.Fragment = ppiray_test::ReadRGB(scene.Window);
  out.Continuations = mapper->GetStatistics()->GetNumberOfContinuations();
  mapper->SetMarchStageToCompute();
  scene.Window->Render();
  out.Compute = ppiray_test::ReadRGB(scene.Window);
  out.ComputeRan = mapper->GetStatistics()->GetMarchStage();
  out.Continuations =
    std::min(out.Continuations, mapper->GetStatistics()->GetNumberOfContinuations());
  out.Warnings = messages->Warnings + messages->Errors;
  return out;
}

int Check(const char* name, const Stages& s, bool fallback)
{
  int largest = 0, covered = 0, coverage = 0;
  for (size_t i = 0; i < s.Fragment.size(); ++i)
  {
    largest = std::max(largest, std::abs(int(s.Fragment[i]) - int(s.Compute[i])));
    covered += s.Fragment[i] > 0 ? 1 : 0;
    coverage += (s.Fragment[i] > 0) != (s.Compute[i] > 0) ? 1 : 0;
  }
  std::cout << name << ": stage " << s.ComputeRan << ", continuations " << s.Continuations
            << ", max " << largest << "/255 over " << covered << " channels, " << coverage
            << " covered in one stage only [" << s.Warnings << "]\n";
  const int expected = fallback ? Mapper::MARCH_STAGE_FRAGMENT : Mapper::MARCH_STAGE_COMPUTE;
  const bool warned = s.Warnings.find("fragment shader") != std::string::npos;
  if (s.ComputeRan != expected || largest > 1 || coverage > 0 || covered < 3000 ||
      warned != fallback)
  {
    std::cout << "FAILED: " << name << ": expected the " << (fallback ? "fragment" : "compute")
              << " stage, within 1/255 of the fragment stage, the same pixels covered"
              << (fallback ? ", one warning" : ", no warning") << "\n";
    return 1;
  }
  return 0;
}
}

namespace
{
constexpr int Skipped = -1;

// Every scene in both stages; the number of failed checks, or Skipped.
int RenderAllScenes(bool fallback)
{
  ppiray_test::Scene scene(Size, Size);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 3.0, 0.7, 0.1);
  const int n[3] = { 6, 6, 6 };
  const double origin[3] = { 0, 0, 0 };
  auto cavity = ppiray_test::CavityTetrahedra(6);
  auto hexahedra = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 6, origin, [](int, int, int) { return true; },
    [](double x, double y, double z) { return x + y * z + z; }, /*hexahedra=*/true);
  auto none = [](Mapper*) {};
  int errors = 0;
  const Stages first = RenderBoth(scene, cavity, { 2.2, 1.6, 2.5 }, none);
  if (fallback && first.ComputeRan == Mapper::MARCH_STAGE_COMPUTE)
  {
    std::cout << "The context still has compute shaders (MESA_GL_VERSION_OVERRIDE is Mesa's): "
                 "skipped.\n";
    return Skipped;
  }
  errors += Check("tetrahedra around a cavity", first, fallback);
  if (fallback)
  {
    return errors;
  }
  errors += Check("hexahedra natively",
    RenderBoth(
      scene, hexahedra, { 2.0, -1.4, 1.8 }, [](Mapper* m) { m->SetHexahedronModeToAccurate(); }),
    false);
  errors += Check("maximum intensity",
    RenderBoth(
      scene, cavity, { -1.5, 2.0, 2.4 }, [](Mapper* m) { m->SetBlendModeToMaximumIntensity(); }),
    false);
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.5, 0.5, 0.5);
  plane->SetNormal(1.0, 0.3, -0.2);
  errors += Check("a clipping plane",
    RenderBoth(scene, cavity, { 2.2, 1.6, 2.5 }, [&](Mapper* m) { m->AddClippingPlane(plane); }),
    false);
  // 2,000 colour and opacity nodes over a field sweeping the range a few
  // times per cell, integrated exactly (many loop iterations per piece).
  vtkNew<vtkColorTransferFunction> many;
  vtkNew<vtkPiecewiseFunction> faint;
  for (int k = 0; k < 2000; ++k)
  {
    const double u = k / 1999.0;
    many->AddRGBPoint(3.0 * u, 0.5 + 0.5 * std::sin(40 * u), 0.5 + 0.5 * std::cos(60 * u), u);
    faint->AddPoint(3.0 * u, 0.1 + 0.1 * std::sin(70 * u));
  }
  scene.Property->SetColor(many);
  scene.Property->SetScalarOpacity(faint);
  auto wavy = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 6, origin, [](int, int, int) { return true; },
    [](double x, double y, double z) { return 1.5 + 1.5 * std::sin(40.0 * (x + 2 * y + 3 * z)); });
  const Stages budget = RenderBoth(
    scene, wavy, { 2.2, 1.6, 2.5 }, [](Mapper* m) { m->SetIntegrationModeToExactLinear(); });
  errors += Check("thousands of transfer-function nodes", budget, false);
  if (budget.Continuations == 0)
  {
    std::cout << "FAILED: expected loop-budget continuations\n";
    ++errors;
  }
  return errors;
}
}

int TestGPURayCastMarchStages(int argc, char* argv[])
{
  const bool fallback = ppiray_test::ExpectFallback(argc, argv);
  // The fallback's one warning is the mapper's (RenderBoth checks it).
  return ppiray_test::RunPrintingNothing([&] { return RenderAllScenes(fallback); }, fallback);
}
