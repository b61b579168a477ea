// Baseline image comparison that sees a 10/255 change: the window's RGB
// against the -V baseline PNG, per channel, no shift tolerance (llvmpipe
// rasterizes the same way on every run). Fails when any channel differs by
// 10/255 or more, when the 99th percentile exceeds 2/255 or the mean 0.5/255
// (a small drift everywhere), or when the sizes differ. On failure the test
// image and a x10 difference image are written to the -T directory. (VTK
// 9.2's vtkRegressionTestImage threshold accepts +105/255 on every channel.)
#ifndef PPIRayBaseline_h
#define PPIRayBaseline_h

#include "PPIRayImageCompare.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkRenderWindow.h"
#include "vtksys/SystemTools.hxx"

#include <cstdio>
#include <string>
#include <vector>

namespace ppiray_test
{
// The value following `flag` in argv, or "".
inline std::string Argument(int argc, char* argv[], const char* flag)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == flag)
    {
      return argv[i + 1];
    }
  }
  return "";
}

// 0 if `window` matches its baseline (-V, with `suffix` inserted before
// ".png" for a test with several images), else 1.
inline int BaselineTest(
  int argc, char* argv[], vtkRenderWindow* window, const std::string& suffix = "")
{
  std::string baseline = Argument(argc, argv, "-V");
  const std::string temporary = Argument(argc, argv, "-T");
  if (baseline.size() > 4)
  {
    baseline.insert(baseline.size() - 4, suffix);
  }
  const int* size = window->GetSize();
  const int w = size[0], h = size[1];
  const std::vector<unsigned char> image = ReadRGB(window);
  const std::string name = vtksys::SystemTools::GetFilenameWithoutLastExtension(baseline);
  auto keep = [&](const std::vector<unsigned char>* reference)
  {
    if (temporary.empty())
    {
      return;
    }
    WritePNG(temporary + "/" + name + ".png", image, w, h);
    if (reference)
    {
      WritePNG(
        temporary + "/" + name + ".diff.png", DifferenceImage(image, *reference, 10.0), w, h);
    }
  };
  if (baseline.empty() || !vtksys::SystemTools::FileExists(baseline))
  {
    std::printf(
      "FAILED: no baseline %s (the image is in %s)\n", baseline.c_str(), temporary.c_str());
    keep(nullptr);
    return 1;
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(baseline.c_str());
  reader->Update();
  vtkImageData* png = reader->GetOutput();
  const int* dims = png->GetDimensions();
  const int channels = png->GetNumberOfScalarComponents();
  if (dims[0] != w || dims[1] != h || channels < 3)
  {
    std::printf("FAILED: baseline %s is %dx%d (%d channels), the image %dx%d\n", baseline.c_str(),
      dims[0], dims[1], channels, w, h);
    keep(nullptr);
    return 1;
  }
  std::vector<unsigned char> reference(3 * static_cast<size_t>(w) * h);
  const auto* pixels = static_cast<const unsigned char*>(png->GetScalarPointer());
  for (size_t p = 0; p < static_cast<size_t>(w) * h; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      reference[3 * p + c] = pixels[channels * p + c];
    }
  }
  const ImageDifference d = Compare(image, reference);
  std::printf(
    "baseline %s: mean %.3f p99 %.1f max %.0f /255\n", name.c_str(), d.Mean, d.P99, d.Max);
  if (d.Max >= 10 || d.P99 > 2 || d.Mean > 0.5)
  {
    std::printf("FAILED: %s differs from its baseline (bounds: max < 10, p99 <= 2, mean <= 0.5)\n",
      name.c_str());
    keep(&reference);
    return 1;
  }
  return 0;
}
}

#endif
