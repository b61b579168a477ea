#include "vtkPPIRayMarchQueue.h"

#include "ppirayVTKCompatibility.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPPIRayComputeProgram.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkWindow.h"
#include PPIRAY_VTK_OPENGL_HEADER

#include "march_mask_fs.h"
#include "march_pixels_fs.h"
#include "march_queue_cs.h"
#include "march_queue_dec_cs.h"

namespace
{
// The list's header: the number of rays, then the march's indirect dispatch
// (groups along x, y, z), as march_queue_dec_cs.glsl's RayQueue block lays it out.
constexpr GLuint EmptyHeader[4] = { 0, 0, 1, 1 };
constexpr GLintptr DispatchOffset = sizeof(GLuint);
constexpr GLuint QueueBinding = 0;
// The queue pass's work groups: QueueGroupSide^2 pixels (march_queue_cs.glsl).
constexpr int QueueGroupSide = 8;

// march_pixels_fs.glsl's inputs, active on their texture units.
void SetPixelInputs(vtkShaderProgram* program, vtkTextureObject* const inputs[4])
{
  const char* names[4] = { "entryTriangle", "previousAccumulated", "previousExit",
    "previousContinuation" };
  for (int i = 0; i < 4; ++i)
  {
    program->SetUniformi(names[i], inputs[i]->GetTextureUnit());
  }
}
}

//------------------------------------------------------------------------------
vtkPPIRayMarchQueue::vtkPPIRayMarchQueue() = default;

//------------------------------------------------------------------------------
vtkPPIRayMarchQueue::~vtkPPIRayMarchQueue() = default;

//------------------------------------------------------------------------------
std::string vtkPPIRayMarchQueue::Declarations()
{
  return "#define MARCH_GROUP_SIZE " + std::to_string(MarchGroupSize) + "u\n" + march_queue_dec_cs;
}

//------------------------------------------------------------------------------
bool vtkPPIRayMarchQueue::Build(std::string& error)
{
  if (this->Program)
  {
    return true;
  }
  std::string source = march_queue_cs;
  vtkShaderProgram::Substitute(source, "//PPIRay::MarchQueue::Dec", Declarations());
  vtkShaderProgram::Substitute(source, "//PPIRay::MarchPixels::Impl", march_pixels_fs);
  auto program = vtkSmartPointer<vtkPPIRayComputeProgram>::New();
  if (!program->Build(source))
  {
    error = program->GetError();
    return false;
  }
  this->Program = program;
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayMarchQueue::Gather(
  vtkOpenGLRenderWindow* context, int width, int height, vtkTextureObject* const inputs[4])
{
  const size_t bytes = sizeof(EmptyHeader) + sizeof(GLuint) * static_cast<size_t>(width) * height;
  if (!this->Buffer)
  {
    glGenBuffers(1, &this->Buffer);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffer);
  if (bytes != this->Bytes)
  {
    glBufferData(
      GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_COPY);
    this->Bytes = bytes;
  }
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(EmptyHeader), EmptyHeader);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, QueueBinding, this->Buffer);

  context->GetShaderCache()->ReadyShaderProgram(this->Program);
  SetPixelInputs(this->Program, inputs);
  const int size[2] = { width, height };
  this->Program->SetUniform2i("targetSize", size);
  vtkPPIRayComputeProgram::Dispatch(width, height, QueueGroupSide, QueueGroupSide);
}

//------------------------------------------------------------------------------
void vtkPPIRayMarchQueue::DispatchMarch()
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, QueueBinding, this->Buffer);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, this->Buffer);
  glDispatchComputeIndirect(DispatchOffset);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, QueueBinding, 0);
}

//------------------------------------------------------------------------------
bool vtkPPIRayMarchQueue::Mask(vtkOpenGLRenderWindow* context,
  vtkOpenGLFramebufferObject* framebuffer, int width, int height, vtkTextureObject* const inputs[4])
{
  if (!this->MaskQuad)
  {
    std::string source = march_mask_fs;
    vtkShaderProgram::Substitute(source, "//PPIRay::MarchPixels::Impl", march_pixels_fs);
    this->MaskQuad.reset(new vtkOpenGLQuadHelper(context, nullptr, source.c_str(), ""));
  }
  if (this->MaskSize[0] != width || this->MaskSize[1] != height)
  {
    this->MaskDepth->SetContext(context);
    if (!this->MaskDepth->AllocateDepth(width, height, vtkTextureObject::Float32))
    {
      return false;
    }
    this->MaskSize[0] = width;
    this->MaskSize[1] = height;
  }
  vtkShaderProgram* program = this->MaskQuad->Program;
  if (!program || !context->GetShaderCache()->ReadyShaderProgram(program))
  {
    return false;
  }
  framebuffer->AddDepthAttachment(this->MaskDepth);
  vtkOpenGLState* state = context->GetState();
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  SetPixelInputs(program, inputs);
  this->MaskQuad->Render();
  // The quad is drawn at depth 0.5: in front of a masked pixel's 1 only.
  state->vtkglDepthFunc(GL_GREATER);
  state->vtkglDepthMask(GL_FALSE);
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayMarchQueue::EndMask(
  vtkOpenGLRenderWindow* context, vtkOpenGLFramebufferObject* framebuffer)
{
  framebuffer->RemoveDepthAttachment();
  context->GetState()->vtkglDisable(GL_DEPTH_TEST);
  context->GetState()->vtkglDepthMask(GL_TRUE);
}

//------------------------------------------------------------------------------
void vtkPPIRayMarchQueue::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->MaskQuad)
  {
    this->MaskQuad->ReleaseGraphicsResources(window);
    this->MaskQuad.reset();
  }
  this->MaskDepth->ReleaseGraphicsResources(window);
  this->MaskSize[0] = this->MaskSize[1] = 0;
  if (this->Buffer)
  {
    glDeleteBuffers(1, &this->Buffer);
    this->Buffer = 0;
    this->Bytes = 0;
  }
  if (this->Program)
  {
    this->Program->ReleaseGraphicsResources(window);
    this->Program = nullptr;
  }
}
