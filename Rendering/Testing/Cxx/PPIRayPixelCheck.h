// Checks rendered pixels against PPIRayReferenceRay.h on a regular grid of
// sample pixels; prints the worst difference (1/255 units).
#ifndef PPIRayPixelCheck_h
#define PPIRayPixelCheck_h

#include "PPIRayImageCompare.h"
#include "PPIRayReferenceRay.h"

#include <iostream>

namespace ppiray_test
{
struct PixelCheck
{
  double MaxDifference = 0; // 1/255 units
  int Pixels = 0;
  int NaNPixels = 0;
};

// `image` is the window's RGB over a black background: the premultiplied colour.
inline PixelCheck CheckPixels(vtkRenderer* ren, vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, const std::vector<unsigned char>& image, int w, int h, int stride,
  bool cellScalars = false)
{
  PixelCheck check;
  for (int py = stride / 2; py < h; py += stride)
  {
    for (int px = stride / 2; px < w; px += stride)
    {
      const auto ref = IntegrateRay(grid, property, PixelRay(ren, px, py, w, h), cellScalars);
      for (int c = 0; c < 3; ++c)
      {
        if (std::isnan(ref[c]))
        {
          ++check.NaNPixels;
          continue;
        }
        const double gpu = image[3 * (py * w + px) + c];
        const double diff = std::abs(gpu - 255.0 * std::min(1.0, ref[c]));
        if (diff > check.MaxDifference)
        {
          check.MaxDifference = diff;
        }
      }
      ++check.Pixels;
    }
  }
  return check;
}
}

#endif
