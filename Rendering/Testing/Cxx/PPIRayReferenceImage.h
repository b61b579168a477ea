// The CPU reference renderer's image as 8-bit RGB over black, the way a
// window read-back (PPIRayImageCompare.h's ReadRGB) sees the volume.
#ifndef PPIRayReferenceImage_h
#define PPIRayReferenceImage_h

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReferenceRenderer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace ppiray_test
{
inline std::vector<unsigned char> ReferenceRGB(vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, vtkCamera* camera, int width, int height,
  double quadratureTolerance = 1e-6)
{
  vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
  reference->SetQuadratureTolerance(quadratureTolerance);
  reference->SetInputData(grid);
  reference->SetVolumeProperty(property);
  reference->SetCamera(camera);
  reference->SetImageSize(width, height);
  reference->Update();
  auto* rgba = vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetScalars());
  std::vector<unsigned char> rgb(3 * static_cast<size_t>(width) * height);
  for (int i = 0; i < width * height; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = std::min(1.0, std::max(0.0, static_cast<double>(rgba->GetComponent(i, c))));
      rgb[3 * i + c] = static_cast<unsigned char>(std::lround(255.0 * v));
    }
  }
  return rgb;
}

// Statistics of per-channel |image - reference| in 1/255 units.
struct ReferenceError
{
  double P99 = 0, P999 = 0, Max = 0, Mean = 0;
};

// `image`: a window's RGB over black (ReadRGB); `exact`: the reference
// renderer's RGBA in [0, 1] (NaN: no reference value, skipped).
inline ReferenceError AgainstReference(
  const std::vector<unsigned char>& image, vtkFloatArray* exact)
{
  std::vector<double> d;
  for (vtkIdType p = 0; p < exact->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double value = exact->GetComponent(p, c);
      if (!std::isnan(value))
      {
        d.push_back(std::abs(image[3 * p + c] - 255.0 * std::min(1.0, value)));
      }
    }
  }
  ReferenceError e;
  if (d.empty())
  {
    return e;
  }
  e.Mean = std::accumulate(d.begin(), d.end(), 0.0) / d.size();
  std::sort(d.begin(), d.end());
  e.P99 = d[static_cast<size_t>(0.99 * (d.size() - 1))];
  e.P999 = d[static_cast<size_t>(0.999 * (d.size() - 1))];
  e.Max = d.back();
  return e;
}
}

#endif
