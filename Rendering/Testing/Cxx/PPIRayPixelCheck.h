// Checks every rendered pixel against the CPU reference renderer
// (vtkUnstructuredGridReferenceRenderer: double precision, exact per piece,
// no code shared with the GPU path); reports the worst difference and the
// 99th percentile in 1/255 units over the covered pixels, how many pixels
// either image covers and how many reference pixels are NaN.
#ifndef PPIRayPixelCheck_h
#define PPIRayPixelCheck_h

#include "PPIRayImageCompare.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReferenceRenderer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ppiray_test
{
struct PixelCheck
{
  double MaxDifference = 0; // 1/255 units
  double P99 = 0;
  int Pixels = 0; // pixels compared: covered by either image
  int NaNPixels = 0;
};

// `image` is the window's RGB over a black background: the premultiplied
// colour. `cellArray` names the cell scalars to render, else the active point
// scalars are used; `clippingPlanes` clip the reference's rays.
inline PixelCheck CheckPixels(vtkRenderer* ren, vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, const std::vector<unsigned char>& image, int w, int h,
  const char* cellArray = nullptr, vtkPlaneCollection* clippingPlanes = nullptr)
{
  vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetVolumeProperty(property);
  reference->SetCamera(ren->GetActiveCamera());
  reference->SetImageSize(w, h);
  reference->SetClippingPlanes(clippingPlanes);
  if (cellArray)
  {
    reference->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, cellArray);
  }
  reference->Update();
  auto* exact = vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetScalars());
  PixelCheck check;
  std::vector<double> differences;
  for (int p = 0; p < w * h; ++p)
  {
    bool nan = false, covered = false;
    double d[3];
    for (int c = 0; c < 3; ++c)
    {
      const double value = exact->GetComponent(p, c);
      nan = nan || std::isnan(value);
      const double expected = 255.0 * std::min(1.0, std::max(0.0, value));
      covered = covered || std::round(expected) >= 1 || image[3 * p + c] >= 1;
      d[c] = std::abs(image[3 * p + c] - expected);
    }
    if (nan)
    {
      ++check.NaNPixels;
      continue;
    }
    if (!covered)
    {
      continue;
    }
    ++check.Pixels;
    differences.insert(differences.end(), d, d + 3);
  }
  if (!differences.empty())
  {
    std::sort(differences.begin(), differences.end());
    check.P99 = differences[static_cast<size_t>(0.99 * (differences.size() - 1))];
    check.MaxDifference = differences.back();
  }
  return check;
}

// 1 (and a message) if the check saw NaN or fewer than `minimumPixels`
// covered pixels, else 0.
inline int ExpectCoverage(const PixelCheck& check, int minimumPixels)
{
  std::printf("pixels compared %d (p99 %.2f, max %.2f /255), NaN %d\n", check.Pixels, check.P99,
    check.MaxDifference, check.NaNPixels);
  if (check.NaNPixels > 0 || check.Pixels < minimumPixels)
  {
    std::printf("FAILED: %d NaN reference pixels, %d pixels covered (at least %d expected)\n",
      check.NaNPixels, check.Pixels, minimumPixels);
    return 1;
  }
  return 0;
}

// ExpectCoverage, and 1 more if p99 or max exceeds the suite's bound against
// the reference: 1/255 (8-bit rounding 0.5, float, the 0.1/255
// transfer-function tolerance).
inline int ExpectReference(const char* what, const PixelCheck& check, int minimumPixels)
{
  std::printf("%s: ", what);
  int errors = ExpectCoverage(check, minimumPixels);
  if (check.P99 > 1.0 || check.MaxDifference > 1.0)
  {
    std::printf("FAILED: %s differs from the reference\n", what);
    ++errors;
  }
  return errors;
}
}

#endif
