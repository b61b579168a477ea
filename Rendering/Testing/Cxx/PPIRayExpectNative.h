// Renders a grid natively (or split, HEXAHEDRON_SUBDIVIDE) and checks the
// image against the reference renderer (PPIRayPixelCheck.h).
#ifndef PPIRayExpectNative_h
#define PPIRayExpectNative_h

#include "PPIRayImageCompare.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <iostream>
#include <vector>

namespace ppiray_test
{
// Renders `grid` in HexahedronMode `mode` in the scene's size x size window
// and checks it against the reference: at least 10,000 covered pixels, no
// NaN, p99 and max within the bounds; one peel, every cell native (or
// refined into native pieces; none when split). `cellArray`: cell scalars by that name; `out`,
// `image`: the check and the image read back. Returns the number of failures.
inline int ExpectNative(const char* what, Scene& scene, vtkUnstructuredGridGPURayCastMapper* mapper,
  vtkUnstructuredGrid* grid, int mode, int size, double p99Bound, double maxBound,
  PixelCheck* out = nullptr, const char* cellArray = nullptr,
  std::vector<unsigned char>* image = nullptr)
{
  mapper->SetHexahedronMode(mode);
  mapper->SetInputData(grid);
  scene.Window->Render();
  const auto rgb = ReadRGB(scene.Window);
  const auto check = CheckPixels(scene.Renderer, grid, scene.Property, rgb, size, size, cellArray);
  auto* statistics = mapper->GetStatistics();
  std::cout << what << ": native cells " << statistics->GetNumberOfNativeCells() << ", peels "
            << statistics->GetNumberOfPeels() << ", ";
  int errors = ExpectCoverage(check, 10000);
  const bool split = mode == vtkUnstructuredGridGPURayCastMapper::HEXAHEDRON_SUBDIVIDE;
  if (statistics->GetNumberOfPeels() != 1 ||
      (split ? statistics->GetNumberOfNativeCells() != 0
             : statistics->GetNumberOfNativeCells() < grid->GetNumberOfCells()))
  {
    std::cerr << "FAILED: not one peel, or not every cell native\n";
    ++errors;
  }
  if (check.P99 > p99Bound || check.MaxDifference > maxBound)
  {
    std::cerr << "FAILED: " << what << " (bounds: p99 " << p99Bound << ", max " << maxBound
              << ")\n";
    ++errors;
  }
  if (out)
  {
    *out = check;
  }
  if (image)
  {
    *image = rgb;
  }
  return errors;
}
}

#endif
