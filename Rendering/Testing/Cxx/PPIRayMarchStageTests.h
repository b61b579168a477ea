// What the march-stage tests share (TestGPURayCastMarchStages,
// TestGPURayCastMarchStageChoice): --expect-fallback (ctest runs those
// variants under MESA_GL_VERSION_OVERRIDE=3.3, a context without compute
// shaders), a run that fails on anything a VTK object prints, and a mesh
// of several peels.
#ifndef PPIRayMarchStageTests_h
#define PPIRayMarchStageTests_h

#include "PPIRayTestScenes.h"

#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"
#include "vtkStringOutputWindow.h"

#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>

namespace ppiray_test
{
// n^3 voxels of the unit cube as tetrahedra, without the middle third's
// (a cavity: several peels), the field x + y^2 + z.
inline vtkSmartPointer<vtkUnstructuredGrid> CavityTetrahedra(int n)
{
  const int dims[3] = { n, n, n };
  const double origin[3] = { 0, 0, 0 };
  const int a = n / 3, b = 2 * n / 3;
  return VoxelTetrahedra(
    dims, 1.0 / n, origin,
    [a, b](int i, int j, int k)
    { return !(i >= a && i < b && j >= a && j < b && k >= a && k < b); },
    [](double x, double y, double z) { return x + y * y + z; });
}

// Whether the arguments hold --expect-fallback.
inline bool ExpectFallback(int argc, char* argv[])
{
  bool fallback = false;
  for (int i = 1; i < argc; ++i)
  {
    fallback = fallback || std::strcmp(argv[i], "--expect-fallback") == 0;
  }
  return fallback;
}

// The exit code of `scenes` (its number of failed checks; negative: the
// context still has compute shaders, skipped) run with VTK's output window
// captured: it fails on anything printed (`warningsExpected`: on errors
// only, the fallback's warning being checked by the scenes).
inline int RunPrintingNothing(const std::function<int()>& scenes, bool warningsExpected)
{
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkNew<vtkStringOutputWindow> printed;
  vtkOutputWindow::SetInstance(printed);
  const int errors = scenes();
  vtkOutputWindow::SetInstance(previous);
  if (errors < 0)
  {
    std::cout << "The context still has compute shaders (MESA_GL_VERSION_OVERRIDE is Mesa's): "
                 "skipped.\n";
    return 125;
  }
  const std::string text = printed->GetOutput();
  const bool quiet = warningsExpected ? text.find("ERROR") == std::string::npos : text.empty();
  if (!quiet)
  {
    std::cout << "FAILED: printed by VTK objects:\n" << text << "\n";
  }
  return errors == 0 && quiet ? EXIT_SUCCESS : EXIT_FAILURE;
}
}

#endif
