// Per-channel image differences in 1/255 units: mean, 99th percentile, max.
#ifndef PPIRayImageCompare_h
#define PPIRayImageCompare_h

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace ppiray_test
{
struct ImageDifference
{
  double Mean = 0;
  double P99 = 0;
  double Max = 0;
};

// RGB of the window's back buffer after the last render, row-major from the bottom.
inline std::vector<unsigned char> ReadRGB(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels);
  return std::vector<unsigned char>(
    pixels->GetPointer(0), pixels->GetPointer(0) + 3 * size[0] * size[1]);
}

// Write an RGB buffer (from ReadRGB) as PNG, for looking at a failure.
inline void WritePNG(const std::string& path, const std::vector<unsigned char>& rgb, int w, int h)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(rgb.begin(), rgb.end(), static_cast<unsigned char*>(image->GetScalarPointer()));
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}

// |a - b| * gain, per channel, as an image.
inline std::vector<unsigned char> DifferenceImage(
  const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, double gain)
{
  std::vector<unsigned char> d(a.size());
  for (size_t i = 0; i < a.size(); ++i)
  {
    d[i] = static_cast<unsigned char>(
      std::min(255.0, gain * std::abs(static_cast<double>(a[i]) - b[i])));
  }
  return d;
}

inline ImageDifference Compare(
  const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  ImageDifference d;
  std::vector<double> all(a.size());
  for (size_t i = 0; i < a.size(); ++i)
  {
    all[i] = std::abs(static_cast<double>(a[i]) - static_cast<double>(b[i]));
    d.Mean += all[i];
  }
  d.Mean /= std::max<size_t>(1, all.size());
  std::sort(all.begin(), all.end());
  if (!all.empty())
  {
    d.P99 = all[static_cast<size_t>(0.99 * (all.size() - 1))];
    d.Max = all.back();
  }
  return d;
}
}

#endif
