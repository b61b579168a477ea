// Level of detail (ImageSampleDistance, AutoAdjustSampleDistances), the way
// vtkUnstructuredGridVolumeRayCastMapper has it, on a non-convex tetrahedral
// scene (the tunnel beside a block: 3 peels) at 200 x 200:
// - with time to spare (the window's default desired update rate) the
//   automatic distance is 1 and the image is identical, bit for bit, to a
//   fixed distance of 1;
// - a fixed distance of 4 casts 50 x 50 rays: smaller render targets (GPU
//   bytes), an image that differs but covers the same pixels within 8 % (the
//   bilinear up-scaling spreads the silhouette by up to 2 pixels: +3.9 %
//   measured), within 4/255 of the full image at p90 (a smooth field varies
//   little over 4 pixels; 1 measured) and 64/255 at most (silhouette and
//   tunnel edges, where up-scaling blends across the edge; 14 measured);
// - asking for 10,000 frames per second while interacting drives the
//   distance to its maximum within 3 frames (each frame takes well over
//   0.1 ms here), and the first frame with time to spare is back to 1 and
//   to the identical full image;
// - a distance below 1 is clamped to 1 (no supersampling).

#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

int TestGPURayCastLevelOfDetail(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  const int size = 200;
  ppiray_test::Scene scene(size, size);
  auto grid = ppiray_test::TunnelAndBlock();
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.7, 0.1);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  scene.Show(mapper, grid, { -0.9, 0.75, 0.9 }, { 0.5, 0.3, 0.3 });
  int errors = 0;
  auto fail = [&](bool bad, const char* what)
  {
    if (bad)
    {
      std::printf("FAILED: %s\n", what);
      ++errors;
    }
  };
  auto render = [&]()
  {
    scene.Window->Render();
    return ppiray_test::ReadRGB(scene.Window);
  };
  auto covered = [](const std::vector<unsigned char>& rgb)
  {
    int n = 0;
    for (size_t p = 0; p < rgb.size(); p += 3)
    {
      n += (rgb[p] | rgb[p + 1] | rgb[p + 2]) ? 1 : 0;
    }
    return n;
  };

  // Time to spare: every pixel.
  const auto automatic = render();
  const auto automaticAgain = render();
  const float automaticDistance = mapper->GetImageSampleDistance();
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetImageSampleDistance(1.0f);
  const auto full = render();
  const vtkIdType fullBytes = mapper->GetStatistics()->GetGPUMemorySize();
  std::printf("automatic distance %.2f, image %s the fixed distance 1's; %d pixels covered, "
              "%lld GPU bytes, %d peels\n",
    automaticDistance, automaticAgain == full ? "identical to" : "DIFFERENT from", covered(full),
    static_cast<long long>(fullBytes), mapper->GetStatistics()->GetNumberOfPeels());
  fail(automaticDistance != 1.0f || automaticAgain != full || automatic != full,
    "with time to spare the automatic level of detail is not every pixel");
  fail(covered(full) < size * size / 10, "the scene covers too few pixels");
  fail(mapper->GetStatistics()->GetNumberOfPeels() < 2, "the scene is meant to need several peels");

  // A fixed distance of 4.
  mapper->SetImageSampleDistance(4.0f);
  const auto coarse = render();
  const vtkIdType coarseBytes = mapper->GetStatistics()->GetGPUMemorySize();
  std::vector<int> differences;
  int largest = 0;
  for (size_t i = 0; i < full.size(); ++i)
  {
    const int d = std::abs(int(coarse[i]) - int(full[i]));
    largest = std::max(largest, d);
    if (full[i] || coarse[i])
    {
      differences.push_back(d);
    }
  }
  std::sort(differences.begin(), differences.end());
  const int p90 = differences.empty() ? 0 : differences[differences.size() * 9 / 10];
  std::printf("distance 4: %d pixels covered, p90 %d, max %d /255 from the full image, %lld GPU "
              "bytes\n",
    covered(coarse), p90, largest, static_cast<long long>(coarseBytes));
  fail(largest == 0, "a distance of 4 did not change the image");
  fail(std::abs(covered(coarse) - covered(full)) > 0.08 * covered(full),
    "a distance of 4 covers other pixels");
  fail(p90 > 4 || largest > 64, "a distance of 4 is too far from the full image");
  fail(coarseBytes >= fullBytes, "a distance of 4 did not make the render targets smaller");

  // Interacting: a high desired update rate.
  mapper->AutoAdjustSampleDistancesOn();
  mapper->SetImageSampleDistance(1.0f);
  scene.Window->SetDesiredUpdateRate(10000.0);
  std::vector<float> distances;
  for (int frame = 0; frame < 3; ++frame)
  {
    render();
    distances.push_back(mapper->GetImageSampleDistance());
  }
  scene.Window->SetDesiredUpdateRate(0.0001);
  const auto still = render();
  std::printf("interacting: distances %.2f %.2f %.2f (maximum %.2f), then still: %.2f, image %s\n",
    distances[0], distances[1], distances[2], mapper->GetMaximumImageSampleDistance(),
    mapper->GetImageSampleDistance(), still == full ? "identical" : "DIFFERENT");
  fail(distances.back() != mapper->GetMaximumImageSampleDistance(),
    "interacting did not reach the maximum distance");
  fail(mapper->GetImageSampleDistance() != 1.0f || still != full,
    "the first still frame is not the full image");

  mapper->SetImageSampleDistance(0.5f);
  fail(mapper->GetImageSampleDistance() != 1.0f, "a distance below 1 was not clamped");
  return errors ? 1 : 0;
}
