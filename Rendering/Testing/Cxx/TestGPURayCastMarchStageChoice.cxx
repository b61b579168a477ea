// MARCH_STAGE_AUTOMATIC (the default) measures which stage marches faster
// (vtkPPIRayStageChoice): the first six frames of a scene alternate the
// fragment and compute stages, timed; the faster is kept (the smaller of the
// probe's best times it reports). Another window size keeps the choice; a
// mesh with another number of cells, or rays marched per pixel that change
// by more than a factor of two, probe again. Every frame must agree
// with the fragment stage's image within 1/255 and cover the same pixels,
// and nothing may be printed.
// With --expect-fallback (ctest runs it under MESA_GL_VERSION_OVERRIDE=3.3,
// a context without compute shaders): the fragment stage chosen at the first
// frame, without a probe and without a warning.

#include "PPIRayImageCompare.h"
#include "PPIRayMarchStageTests.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkUnstructuredGridGPURayCastStatistics.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
using Mapper = vtkUnstructuredGridGPURayCastMapper;
constexpr int F = Mapper::MARCH_STAGE_FRAGMENT;
constexpr int C = Mapper::MARCH_STAGE_COMPUTE;

// A frame in the automatic stage: the stage it ran in, the choice after it,
// and whether its image is the fragment stage's `reference` (max 1/255, the
// same channels covered, at least `least` of them).
struct Frame
{
  int Ran, Chosen;
  bool Same;
};

Frame RenderFrame(
  ppiray_test::Scene& scene, Mapper* mapper, const std::vector<unsigned char>& reference)
{
  scene.Window->Render();
  const std::vector<unsigned char> image = ppiray_test::ReadRGB(scene.Window);
  int largest = 0, differ = 0, covered = 0;
  for (size_t i = 0; i < image.size() && image.size() == reference.size(); ++i)
  {
    largest = std::max(largest, std::abs(int(image[i]) - int(reference[i])));
    differ += (image[i] > 0) != (reference[i] > 0) ? 1 : 0;
    covered += image[i] > 0 ? 1 : 0;
  }
  auto* statistics = mapper->GetStatistics();
  const bool same =
    image.size() == reference.size() && largest <= 1 && differ == 0 && covered > 300;
  std::cout << "  ran " << statistics->GetMarchStage() << ", chosen "
            << statistics->GetChosenMarchStage() << ", max " << largest << "/255, " << covered
            << " channels covered, " << differ << " in one image only\n";
  return { statistics->GetMarchStage(), statistics->GetChosenMarchStage(), same };
}

// The fragment stage's image of the scene as it is set up now.
std::vector<unsigned char> FragmentImage(ppiray_test::Scene& scene, Mapper* mapper)
{
  mapper->SetMarchStageToFragment();
  scene.Window->Render();
  std::vector<unsigned char> image = ppiray_test::ReadRGB(scene.Window);
  mapper->SetMarchStageToAutomatic();
  return image;
}

// A probe of six frames then `after` more; the number of failed checks.
// After a change of scene (`previous`: the stage chosen before; -1: none)
// up to `lead` frames, where a new mesh or rays per pixel are seen, still
// run in that stage (a new march program is seen before the frame).
int Probe(
  const char* name, ppiray_test::Scene& scene, Mapper* mapper, int previous, int lead, int after)
{
  std::cout << name << ":\n";
  const std::vector<unsigned char> reference = FragmentImage(scene, mapper);
  std::vector<Frame> frames;
  bool same = true;
  bool started = previous < 0; // whether a frame has shown the probe under way
  for (int frame = 0; frame < 7 + lead && (frames.empty() || !started || frames.back().Chosen < 0);
       ++frame)
  {
    frames.push_back(RenderFrame(scene, mapper, reference));
    same = same && frames.back().Same;
    started = started || frames.back().Chosen < 0;
  }
  auto* statistics = mapper->GetStatistics();
  const double fragment = statistics->GetMarchStageProbeTime(F);
  const double compute = statistics->GetMarchStageProbeTime(C);
  const int faster = compute > 0.0 && compute < fragment ? C : F;
  const int led = static_cast<int>(frames.size()) - 6;
  bool ok =
    led >= 0 && led <= lead && fragment > 0.0 && compute > 0.0 && frames.back().Chosen == faster;
  for (int frame = 0; ok && frame < led; ++frame)
  {
    ok = frames[frame].Ran == previous;
  }
  const int expected[6] = { F, C, F, C, F, C };
  for (int probe = 0; ok && probe < 6; ++probe)
  {
    ok = frames[lead + probe].Ran == expected[probe] &&
         (probe == 5 || frames[lead + probe].Chosen == -1);
  }
  for (int frame = 0; frame < after; ++frame)
  {
    const Frame f = RenderFrame(scene, mapper, reference);
    same = same && f.Same;
    ok = ok && f.Ran == faster && f.Chosen == faster;
  }
  if (!ok || !same)
  {
    std::cout << "FAILED: " << name << ": expected at most " << lead
              << " frames in the stage chosen before, then the probe's "
                 "stages, then the faster (probe: fragment "
              << fragment << " ms, compute " << compute
              << " ms), each the fragment stage's image within 1/255\n";
    return 1;
  }
  return 0;
}

// Two meshes in turn, frame after frame: after three probes cut short, the
// stage chosen last is kept, without a probe.
int Unsettled(ppiray_test::Scene& scene, Mapper* mapper)
{
  std::cout << "a mesh that changes every frame:\n";
  const int kept = mapper->GetStatistics()->GetChosenMarchStage();
  vtkSmartPointer<vtkUnstructuredGrid> meshes[2] = { ppiray_test::CavityTetrahedra(6),
    ppiray_test::CavityTetrahedra(7) };
  bool ok = kept >= 0;
  for (int frame = 0; frame < 7; ++frame)
  {
    mapper->SetInputData(meshes[frame % 2]);
    scene.Window->Render();
    auto* statistics = mapper->GetStatistics();
    std::cout << "  ran " << statistics->GetMarchStage() << ", chosen "
              << statistics->GetChosenMarchStage() << "\n";
    ok = ok && (frame < 2 || (statistics->GetChosenMarchStage() == kept &&
                               (frame < 3 || statistics->GetMarchStage() == kept)));
  }
  if (!ok)
  {
    std::cout << "FAILED: expected the stage chosen before (" << kept
              << ") kept from the third frame, without a probe after it\n";
  }
  return ok ? 0 : 1;
}

int RenderAll(bool fallback)
{
  ppiray_test::Scene scene(120, 120);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 3.0, 0.7, 0.1);
  auto cavity = ppiray_test::CavityTetrahedra(6);
  vtkNew<Mapper> mapper;
  scene.Show(mapper, cavity, { 2.2, 1.6, 2.5 }, { 0.5, 0.5, 0.5 });
  if (fallback)
  {
    std::cout << "a context without compute shaders:\n";
    const std::vector<unsigned char> reference = FragmentImage(scene, mapper);
    int errors = 0;
    for (int frame = 0; frame < 3; ++frame)
    {
      const Frame f = RenderFrame(scene, mapper, reference);
      if (frame == 0 && f.Chosen < 0)
      {
        return -1; // probing: the context has compute shaders
      }
      if (!f.Same || f.Ran != F || f.Chosen != F)
      {
        std::cout << "FAILED: frame " << frame << ": expected the fragment stage, chosen\n";
        ++errors;
      }
    }
    return errors;
  }
  int errors = Probe("a scene's first frames", scene, mapper, -1, 0, 2);
  const int chosen = mapper->GetStatistics()->GetChosenMarchStage();
  std::cout << "another window size (the same choice):\n";
  scene.Window->SetSize(150, 130);
  const std::vector<unsigned char> resized = FragmentImage(scene, mapper);
  for (int frame = 0; frame < 2; ++frame)
  {
    const Frame f = RenderFrame(scene, mapper, resized);
    if (!f.Same || f.Ran != chosen || f.Chosen != chosen)
    {
      std::cout << "FAILED: another window size, frame " << frame << ": expected stage " << chosen
                << ", no probe, the fragment stage's image within 1/255\n";
      ++errors;
    }
  }
  scene.Show(mapper, ppiray_test::CavityTetrahedra(8), { 2.2, 1.6, 2.5 }, { 0.5, 0.5, 0.5 });
  errors += Probe("another mesh", scene, mapper, chosen, 1, 1);
  // Farther away, the mesh covers a few pixels: its rays per pixel are a
  // fraction of the probe's for three frames in a row, which probes again.
  scene.Renderer->GetActiveCamera()->Zoom(0.4);
  errors += Probe("a fraction of the pixels", scene, mapper,
    mapper->GetStatistics()->GetChosenMarchStage(), 3, 1);
  return errors + Unsettled(scene, mapper);
}
}

int TestGPURayCastMarchStageChoice(int argc, char* argv[])
{
  const bool fallback = ppiray_test::ExpectFallback(argc, argv);
  return ppiray_test::RunPrintingNothing([&] { return RenderAll(fallback); }, false);
}
