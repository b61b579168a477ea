#include "vtkPPIRayMarchShader.h"

#include "ppirayMapperModes.h"

#include "ppirayVTKCompatibility.h"
#include "vtkObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkPPIRayComputeProgram.h"
#include "vtkPPIRayDepthPeeling.h"
#include "vtkPPIRayMarchQueue.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include PPIRAY_VTK_OPENGL_HEADER

#include <functional> // std::hash

#include "isosurface_fs.h"
#include "march_compute_stage_cs.h"
#include "march_fragment_stage_fs.h"
#include "projection_fs.h"
#include "ray_fs.h"
#include "transfer_function_fs.h"

//------------------------------------------------------------------------------
vtkPPIRayMarchShader::vtkPPIRayMarchShader()
  : Queue(new vtkPPIRayMarchQueue)
{
}

//------------------------------------------------------------------------------
vtkPPIRayMarchShader::~vtkPPIRayMarchShader() = default;

//------------------------------------------------------------------------------
std::string vtkPPIRayMarchShader::Compose(const std::string& traversal,
  const std::string& integration, const std::string& isoSurfaces, int blend, int stage)
{
  std::string march = traversal;
  vtkShaderProgram::Substitute(march, "//PPIRay::TransferFunction::Impl", transfer_function_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::IsoSurface::Impl", isosurface_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::IsoSurface::Dec", isoSurfaces);
  vtkShaderProgram::Substitute(march, "//PPIRay::Projection::Impl", projection_fs);
  vtkShaderProgram::Substitute(
    march, "//PPIRay::Blend::Dec", "const int BLEND = " + std::to_string(blend) + ";");
  vtkShaderProgram::Substitute(march, "//PPIRay::Integrate::Impl", integration);
  vtkShaderProgram::Substitute(march, "//PPIRay::Ray::Impl", ray_fs);
  const bool compute = stage == ppiray::MarchCompute;
  vtkShaderProgram::Substitute(
    march, "//PPIRay::MarchStage::Dec", compute ? march_compute_stage_cs : march_fragment_stage_fs);
  if (compute)
  {
    // VTK's shader cache gives fragment shaders their version; this is ours.
    vtkShaderProgram::Substitute(march, "//VTK::System::Dec", "#version 430 core");
    vtkShaderProgram::Substitute(
      march, "//PPIRay::MarchQueue::Dec", vtkPPIRayMarchQueue::Declarations());
  }
  return march;
}

//------------------------------------------------------------------------------
bool vtkPPIRayMarchShader::Ready(vtkOpenGLRenderWindow* context, const std::string& traversal,
  const std::string& integration, const std::string& isoSurfaces, int blend, int stage,
  vtkObject* reporter)
{
  this->Requested = stage;
  if (stage == ppiray::MarchAutomatic)
  {
    const std::hash<std::string> hash;
    const size_t program = hash(traversal) ^ (hash(integration) * 31) ^ (hash(isoSurfaces) * 37) ^
                           static_cast<size_t>(blend);
    stage = this->Choice.Next(
      program, !this->ComputeRefused && vtkPPIRayComputeProgram::IsSupported(context));
  }
  if (stage == ppiray::MarchCompute && !this->ComputeRefused &&
      this->ReadyCompute(
        context, Compose(traversal, integration, isoSurfaces, blend, stage), reporter))
  {
    this->Built = ppiray::MarchCompute;
    return true;
  }
  this->Built = ppiray::MarchFragment;
  return this->ReadyFragment(
    context, Compose(traversal, integration, isoSurfaces, blend, ppiray::MarchFragment), reporter);
}

//------------------------------------------------------------------------------
bool vtkPPIRayMarchShader::Probing(int stage) const
{
  return stage == ppiray::MarchAutomatic && this->Choice.Probing();
}

//------------------------------------------------------------------------------
void vtkPPIRayMarchShader::ObserveFrame(
  const vtkPPIRayDepthPeeling& peeling, long long tetrahedra, long long nativeCells)
{
  const size_t scene = vtkPPIRayStageChoice::SceneKey(tetrahedra, nativeCells);
  if (this->Requested == ppiray::MarchAutomatic && peeling.GetTargetPixels() > 0)
  {
    this->Choice.Observe(this->Built, peeling.GetFrameMilliseconds(), scene,
      peeling.GetRaysPerPixel(), peeling.GetTargetPixels());
  }
}

//------------------------------------------------------------------------------
bool vtkPPIRayMarchShader::ReadyCompute(
  vtkOpenGLRenderWindow* context, const std::string& source, vtkObject* reporter)
{
  if (!this->Compute || source != this->ComputeSource)
  {
    if (this->Compute)
    {
      this->Compute->ReleaseGraphicsResources(context);
    }
    this->Compute = vtkSmartPointer<vtkPPIRayComputeProgram>::New();
    this->ComputeSource = source;
    std::string why;
    if (!vtkPPIRayComputeProgram::IsSupported(context))
    {
      why = "this OpenGL context has no compute shaders (GL 4.3)";
    }
    else if (!this->Compute->Build(source))
    {
      why = this->Compute->GetError();
    }
    else if (!this->Queue->Build(why) && why.empty())
    {
      why = "the ray queue pass does not build";
    }
    if (!why.empty())
    {
      vtkWarningWithObjectMacro(reporter, "The march runs as a fragment shader: " << why << ".");
      this->Compute = nullptr;
      this->ComputeSource.clear();
      this->ComputeRefused = true;
      return false;
    }
  }
  return context->GetShaderCache()->ReadyShaderProgram(this->Compute) != nullptr;
}

//------------------------------------------------------------------------------
bool vtkPPIRayMarchShader::ReadyFragment(
  vtkOpenGLRenderWindow* context, const std::string& source, vtkObject* reporter)
{
  if (this->Quad && source == this->Source && !this->Quad->Program)
  {
    return false; // reported when it was built
  }
  if (!this->Quad || source != this->Source)
  {
    if (this->Quad)
    {
      this->Quad->ReleaseGraphicsResources(context);
    }
    this->Quad.reset(new vtkOpenGLQuadHelper(context, nullptr, source.c_str(), ""));
    this->Source = source;
  }
  else
  {
    context->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program)
  {
    vtkErrorWithObjectMacro(reporter, "Could not build the march shader.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkPPIRayMarchShader::GetProgram() const
{
  if (this->Built == ppiray::MarchCompute)
  {
    return this->Compute;
  }
  return this->Quad ? this->Quad->Program : nullptr;
}

//------------------------------------------------------------------------------
void vtkPPIRayMarchShader::Run(vtkOpenGLRenderWindow* context,
  vtkOpenGLFramebufferObject* framebuffer, int width, int height, vtkTextureObject* const inputs[4],
  vtkTextureObject* const targets[3], long long raysAtMost)
{
  if (this->Built != ppiray::MarchCompute)
  {
    const bool masked = vtkPPIRayMarchQueue::MaskPays(raysAtMost, width, height) &&
                        this->Queue->Mask(context, framebuffer, width, height, inputs);
    context->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
    const int size[2] = { width, height };
    this->Quad->Program->SetUniform2i("targetSize", size);
    this->Quad->Render();
    if (masked)
    {
      this->Queue->EndMask(context, framebuffer);
    }
    return;
  }
  const GLenum formats[3] = { GL_RGBA32F, GL_RGBA32F, GL_RG32F };
  for (int i = 0; i < 3; ++i)
  {
    glBindImageTexture(
      static_cast<GLuint>(i), targets[i]->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, formats[i]);
  }
  this->Queue->Gather(context, width, height, inputs);
  context->GetShaderCache()->ReadyShaderProgram(this->Compute);
  const int size[2] = { width, height };
  this->Compute->SetUniform2i("targetSize", size);
  this->Queue->DispatchMarch();
  for (int i = 0; i < 3; ++i)
  {
    glBindImageTexture(static_cast<GLuint>(i), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, formats[i]);
  }
}

//------------------------------------------------------------------------------
size_t vtkPPIRayMarchShader::GetGPUBytes() const
{
  return this->Queue->GetGPUBytes();
}

//------------------------------------------------------------------------------
void vtkPPIRayMarchShader::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  this->Source.clear();
  if (this->Compute)
  {
    this->Compute->ReleaseGraphicsResources(window);
    this->Compute = nullptr;
  }
  this->ComputeSource.clear();
  this->ComputeRefused = false;
  this->Choice = vtkPPIRayStageChoice();
  this->Queue->ReleaseGraphicsResources(window);
}
