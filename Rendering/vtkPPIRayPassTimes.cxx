#include "vtkPPIRayPassTimes.h"

#include "ppirayVTKCompatibility.h"
#include "vtkOpenGLRenderTimer.h"
#include PPIRAY_VTK_OPENGL_HEADER

//------------------------------------------------------------------------------
vtkPPIRayPassTimes::vtkPPIRayPassTimes() = default;

//------------------------------------------------------------------------------
vtkPPIRayPassTimes::~vtkPPIRayPassTimes() = default;

//------------------------------------------------------------------------------
void vtkPPIRayPassTimes::StartFrame(bool enabled)
{
  this->Enabled = enabled && vtkOpenGLRenderTimer::IsSupported();
  this->Running = -1;
  this->Used = 0;
  this->Kinds.clear();
  this->Milliseconds.fill(0.0);
  this->Counts.fill(0);
}

//------------------------------------------------------------------------------
void vtkPPIRayPassTimes::Start(Pass pass)
{
  if (!this->Enabled)
  {
    return;
  }
  this->Stop();
  if (this->Used == this->Timers.size())
  {
    this->Timers.emplace_back(new vtkOpenGLRenderTimer);
  }
  vtkOpenGLRenderTimer* timer = this->Timers[this->Used].get();
  timer->Reset();
  timer->Start();
  this->Kinds.push_back(pass);
  this->Running = static_cast<int>(this->Used++);
}

//------------------------------------------------------------------------------
void vtkPPIRayPassTimes::Stop()
{
  if (this->Running >= 0)
  {
    this->Timers[this->Running]->Stop();
    this->Running = -1;
  }
}

//------------------------------------------------------------------------------
bool vtkPPIRayPassTimes::EndFrame()
{
  this->Stop();
  if (!this->Enabled)
  {
    return false;
  }
  // The results are there once the GPU has drawn the passes.
  glFinish();
  bool complete = true;
  for (size_t i = 0; i < this->Used; ++i)
  {
    vtkOpenGLRenderTimer* timer = this->Timers[i].get();
    if (!timer->Ready())
    {
      complete = false;
      continue;
    }
    this->Milliseconds[this->Kinds[i]] += timer->GetElapsedMilliseconds();
    ++this->Counts[this->Kinds[i]];
  }
  return complete;
}

//------------------------------------------------------------------------------
double vtkPPIRayPassTimes::GetMilliseconds(int pass) const
{
  return pass >= 0 && pass < NumberOfPasses ? this->Milliseconds[pass] : 0.0;
}

//------------------------------------------------------------------------------
int vtkPPIRayPassTimes::GetCount(int pass) const
{
  return pass >= 0 && pass < NumberOfPasses ? this->Counts[pass] : 0;
}

//------------------------------------------------------------------------------
const char* vtkPPIRayPassTimes::GetName(int pass)
{
  static const char* names[NumberOfPasses] = { "setup", "near-plane entry", "entry", "march",
    "continuation check", "composite" };
  return pass >= 0 && pass < NumberOfPasses ? names[pass] : "";
}

//------------------------------------------------------------------------------
void vtkPPIRayPassTimes::ReleaseGraphicsResources()
{
  for (auto& timer : this->Timers)
  {
    timer->ReleaseGraphicsResources();
  }
  this->Timers.clear();
  this->Kinds.clear();
  this->Used = 0;
  this->Running = -1;
}
