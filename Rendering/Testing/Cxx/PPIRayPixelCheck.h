// Checks rendered pixels against the CPU reference renderer
// (vtkUnstructuredGridReferenceRenderer: double precision, exact per piece,
// no code shared with the GPU path) on a regular grid of sample pixels;
// reports the worst difference in 1/255 units.
#ifndef PPIRayPixelCheck_h
#define PPIRayPixelCheck_h

#include "PPIRayImageCompare.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReferenceRenderer.h"
#include "vtkVolumeProperty.h"

#include <cmath>

namespace ppiray_test
{
struct PixelCheck
{
  double MaxDifference = 0; // 1/255 units
  int Pixels = 0;
  int NaNPixels = 0;
};

// `image` is the window's RGB over a black background: the premultiplied
// colour. `cellArray` names the cell scalars to render, else the active point
// scalars are used.
inline PixelCheck CheckPixels(vtkRenderer* ren, vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, const std::vector<unsigned char>& image, int w, int h, int stride,
  const char* cellArray = nullptr)
{
  vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetVolumeProperty(property);
  reference->SetCamera(ren->GetActiveCamera());
  reference->SetImageSize(w, h);
  if (cellArray)
  {
    reference->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, cellArray);
  }
  reference->Update();
  auto* exact = vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetScalars());
  PixelCheck check;
  for (int py = stride / 2; py < h; py += stride)
  {
    for (int px = stride / 2; px < w; px += stride)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double value = exact->GetComponent(py * w + px, c);
        if (std::isnan(value))
        {
          ++check.NaNPixels;
          continue;
        }
        const double gpu = image[3 * (py * w + px) + c];
        check.MaxDifference =
          std::max(check.MaxDifference, std::abs(gpu - 255.0 * std::min(1.0, value)));
      }
      ++check.Pixels;
    }
  }
  return check;
}
}

#endif
