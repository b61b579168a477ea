// A convex tetrahedral mesh (6 x 6 x 6 voxels, 1,296 tetrahedra) with a smooth
// field and transfer function, perspective camera: baseline image; one peel.
// Its boundary is found convex, so a frame draws one entry layer (a
// non-convex mesh draws one per peel and one that finds no fragment), and
// the pass times (TimePasses) are there: one setup, entry, march and
// composite each, every counted pass a time > 0, all of them no more than
// the frame's wall time; none without TimePasses.

#include "PPIRayBaseline.h"
#include "PPIRayTestScenes.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>

namespace
{
using Mapper = vtkUnstructuredGridGPURayCastMapper;
using Statistics = vtkUnstructuredGridGPURayCastStatistics;

// Renders with TimePasses on; the number of errors in the counts and times.
int CheckPassTimes(ppiray_test::Scene& scene, Mapper* mapper, int entryPasses, const char* what)
{
  mapper->TimePassesOn();
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  scene.Window->Render();
  scene.Window->WaitForCompletion();
  timer->StopTimer();
  mapper->TimePassesOff();
  const double wall = 1000.0 * timer->GetElapsedTime();
  int errors = 0;
  double sum = 0.0;
  std::cout << what << ": frame " << wall << " ms, CPU preparation "
            << mapper->GetStatistics()->GetPreparationTime() << " ms\n";
  for (int k = 0; k < Statistics::NUMBER_OF_PASS_KINDS; ++k)
  {
    const double ms = mapper->GetStatistics()->GetPassTime(k);
    const int passes = mapper->GetStatistics()->GetNumberOfPasses(k);
    sum += ms;
    std::cout << "  " << Statistics::GetPassKindName(k) << ": " << passes << " passes, " << ms
              << " ms\n";
    if ((passes > 0) != (ms > 0.0) || ms < 0.0)
    {
      std::cerr << what << ": " << Statistics::GetPassKindName(k) << " has " << passes
                << " passes and " << ms << " ms\n";
      ++errors;
    }
  }
  const int expected[Statistics::NUMBER_OF_PASS_KINDS] = { 1, 0, entryPasses, -1, -1, 1 };
  for (int k = 0; k < Statistics::NUMBER_OF_PASS_KINDS; ++k)
  {
    if (expected[k] >= 0 && mapper->GetStatistics()->GetNumberOfPasses(k) != expected[k])
    {
      std::cerr << what << ": " << mapper->GetStatistics()->GetNumberOfPasses(k) << " "
                << Statistics::GetPassKindName(k) << " passes, expected " << expected[k] << "\n";
      ++errors;
    }
  }
  // A march (and a continuation check) per peel at least.
  const int peels = mapper->GetStatistics()->GetNumberOfPeels();
  if (mapper->GetStatistics()->GetNumberOfPasses(Statistics::MARCH_PASS) < peels ||
      mapper->GetStatistics()->GetNumberOfPasses(Statistics::CONTINUATION_CHECK_PASS) < peels)
  {
    std::cerr << what << ": fewer marches or checks than the " << peels << " peels\n";
    ++errors;
  }
  // The GPU cannot spend more time in the passes than the frame lasted.
  if (!(sum > 0.0) || sum > wall + 1.0)
  {
    std::cerr << what << ": passes " << sum << " ms in a " << wall << " ms frame\n";
    ++errors;
  }
  // Off: nothing timed.
  scene.Window->Render();
  for (int k = 0; k < Statistics::NUMBER_OF_PASS_KINDS; ++k)
  {
    if (mapper->GetStatistics()->GetNumberOfPasses(k) != 0 ||
        mapper->GetStatistics()->GetPassTime(k) != 0.0)
    {
      std::cerr << what << ": " << Statistics::GetPassKindName(k) << " timed with TimePasses off\n";
      ++errors;
    }
  }
  return errors;
}
}

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
  if (mapper->GetStatistics()->GetNumberOfPeels() != 1)
  {
    std::cerr << "convex mesh took " << mapper->GetStatistics()->GetNumberOfPeels()
              << " peels, expected 1\n";
    ++errors;
  }
  const int result = ppiray_test::BaselineTest(argc, argv, scene.Window);
  errors += CheckPassTimes(scene, mapper, 1, "convex block");

  // The same block with a tunnel: not convex, a layer per peel and one more.
  auto tunnel = ppiray_test::TunnelAndBlock();
  vtkNew<vtkUnstructuredGridGPURayCastMapper> peeling;
  scene.Show(peeling, tunnel, { -0.9, 0.75, 0.9 }, { 0.5, 0.3, 0.3 });
  scene.Window->Render();
  const int peels = peeling->GetStatistics()->GetNumberOfPeels();
  std::cout << "tunnel and block: " << peels << " peels\n";
  if (peels < 3)
  {
    std::cerr << "tunnel and block took " << peels << " peels, expected at least 3\n";
    ++errors;
  }
  errors += CheckPassTimes(scene, peeling, peels + 1, "tunnel and block");
  return (errors == 0 && result == 0) ? 0 : 1;
}
