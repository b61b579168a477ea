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
#include <vector>

namespace ppiray_test
{
inline std::vector<unsigned char> ReferenceRGB(vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, vtkCamera* camera, int width, int height)
{
  vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
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
}

#endif
