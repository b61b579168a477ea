#include "vtkPPIRayStageChoice.h"

#include "ppirayMapperModes.h"

#include <algorithm>
#include <cmath>

namespace
{
// The stage of each probe frame; a stage's first frame warms it up.
int ProbeStage(int frame)
{
  return frame % 2 == 0 ? ppiray::MarchFragment : ppiray::MarchCompute;
}

bool WarmUp(int frame)
{
  return frame < 2;
}
}

//------------------------------------------------------------------------------
int vtkPPIRayStageChoice::Next(size_t program, bool computeAvailable)
{
  if (this->Seen && program != this->Program)
  {
    this->Restart();
    this->Interruptions = 0;
    this->GaveUp = false;
  }
  this->Program = program;
  this->ComputeAvailable = computeAvailable;
  if (!computeAvailable)
  {
    this->Chosen = ppiray::MarchFragment;
  }
  return this->Chosen >= 0 ? this->Chosen : ProbeStage(this->Frame);
}

//------------------------------------------------------------------------------
void vtkPPIRayStageChoice::Observe(
  int stage, double milliseconds, size_t scene, double raysPerPixel, long long targetPixels)
{
  if (!this->ComputeAvailable || this->GaveUp)
  {
    return; // the fragment stage, or the stage kept when the scene would not hold still
  }
  const bool newScene = this->Seen && scene != this->Scene;
  this->Seen = true;
  this->Scene = scene;
  if (this->Chosen >= 0)
  {
    const bool other = OtherRaysPerPixel(raysPerPixel, this->ProbedRaysPerPixel);
    this->FramesOutside = other ? this->FramesOutside + 1 : 0;
    if (newScene || this->FramesOutside >= SettleFrames)
    {
      this->Interrupt();
    }
    return;
  }
  if (newScene || (this->Frame > 0 && targetPixels != this->ProbePixels))
  {
    this->Interrupt(); // the probe's frames would not be alike
    return;
  }
  if (stage != ProbeStage(this->Frame))
  {
    // The compute stage asked for, the fragment stage ran: the context
    // could not ready it after all.
    this->Chosen = ppiray::MarchFragment;
    return;
  }
  this->ProbePixels = targetPixels;
  this->CountProbeFrame(stage, milliseconds, raysPerPixel);
}

//------------------------------------------------------------------------------
void vtkPPIRayStageChoice::CountProbeFrame(int stage, double milliseconds, double raysPerPixel)
{
  if (!WarmUp(this->Frame) && milliseconds >= 0.0)
  {
    double& best = this->Best[stage];
    best = best < 0.0 ? milliseconds : std::min(best, milliseconds);
  }
  this->RaysPerPixelSum += raysPerPixel;
  if (++this->Frame == ProbeFrames)
  {
    this->Chosen = Faster(this->Best[ppiray::MarchFragment], this->Best[ppiray::MarchCompute]);
    this->ProbedRaysPerPixel = this->RaysPerPixelSum / ProbeFrames;
    this->Interruptions = 0;
  }
}

//------------------------------------------------------------------------------
void vtkPPIRayStageChoice::Interrupt()
{
  const int kept = this->Chosen >= 0 ? this->Chosen : this->LastChosen;
  this->LastChosen = kept;
  this->Restart();
  if (++this->Interruptions >= MaximumInterruptions)
  {
    this->Chosen = kept;
    this->GaveUp = true;
  }
}

//------------------------------------------------------------------------------
double vtkPPIRayStageChoice::GetProbeMilliseconds(int stage) const
{
  return stage == ppiray::MarchFragment || stage == ppiray::MarchCompute ? this->Best[stage] : -1.0;
}

//------------------------------------------------------------------------------
int vtkPPIRayStageChoice::Faster(double fragmentMilliseconds, double computeMilliseconds)
{
  const bool both = fragmentMilliseconds >= 0.0 && computeMilliseconds >= 0.0;
  return both && computeMilliseconds < fragmentMilliseconds ? ppiray::MarchCompute
                                                            : ppiray::MarchFragment;
}

//------------------------------------------------------------------------------
size_t vtkPPIRayStageChoice::SceneKey(long long tetrahedra, long long nativeCells)
{
  return static_cast<size_t>(tetrahedra) * 65599u + static_cast<size_t>(nativeCells);
}

//------------------------------------------------------------------------------
bool vtkPPIRayStageChoice::OtherRaysPerPixel(double raysPerPixel, double probed)
{
  // Below 1/64 counts as 1/64: a few rays more or less is the same scene.
  const double floor = 1.0 / 64.0;
  return std::abs(std::log2(std::max(raysPerPixel, floor) / std::max(probed, floor))) > 1.0;
}

//------------------------------------------------------------------------------
void vtkPPIRayStageChoice::Restart()
{
  this->Chosen = -1;
  this->Frame = 0;
  this->FramesOutside = 0;
  this->Best = { { -1.0, -1.0 } };
  this->RaysPerPixelSum = 0.0;
}
