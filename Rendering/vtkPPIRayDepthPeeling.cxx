#include "vtkPPIRayDepthPeeling.h"

#include "ppirayVTKCompatibility.h"
#include "vtkObject.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPPIRayCellBuffers.h"
#include "vtkPPIRayMarchShader.h"
#include "vtkPPIRayPeelingStateRAII.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include PPIRAY_VTK_OPENGL_HEADER

#include <algorithm>
#include <chrono>
#include <string>

#include "composite_fs.h"
#include "entry_fs.h"
#include "entry_vs.h"
#include "ray_fs.h"
#include "section_fs.h"
#include "section_vs.h"
#include "unfinished_fs.h"

namespace
{
// A full-screen pass: every fragment written, none culled or depth-tested,
// blended or not.
void UseFullScreenState(vtkOpenGLState* state, bool blend)
{
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  if (blend)
  {
    state->vtkglEnable(GL_BLEND);
  }
  else
  {
    state->vtkglDisable(GL_BLEND);
  }
}

// A render target read texel by texel.
void NearestClamped(vtkTextureObject* texture, vtkOpenGLRenderWindow* context)
{
  texture->SetContext(context);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
}

bool AllocateTarget(
  vtkTextureObject* texture, vtkOpenGLRenderWindow* context, int w, int h, int components)
{
  NearestClamped(texture, context);
  return texture->Allocate2D(w, h, components, VTK_FLOAT);
}

bool AllocateDepthTarget(vtkTextureObject* texture, vtkOpenGLRenderWindow* context, int w, int h)
{
  NearestClamped(texture, context);
  return texture->AllocateDepth(w, h, vtkTextureObject::Float32);
}
}

//------------------------------------------------------------------------------
vtkPPIRayDepthPeeling::vtkPPIRayDepthPeeling() = default;

//------------------------------------------------------------------------------
vtkPPIRayDepthPeeling::~vtkPPIRayDepthPeeling() = default;

//------------------------------------------------------------------------------
size_t vtkPPIRayDepthPeeling::GetGPUBytes() const
{
  // entry code (R32F), 2 accumulated (RGBA32F), 2 exit and projection state
  // (RGBA32F), 2 continuations (RG32F), 3 depth (32F).
  return static_cast<size_t>(this->TargetSize[0]) * this->TargetSize[1] *
         (4 + 2 * 16 + 2 * 16 + 2 * 8 + 3 * 4);
}

//------------------------------------------------------------------------------
void vtkPPIRayDepthPeeling::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Framebuffer->ReleaseGraphicsResources(window);
  this->EntryTexture->ReleaseGraphicsResources(window);
  for (int i = 0; i < 2; ++i)
  {
    this->Accumulated[i]->ReleaseGraphicsResources(window);
    this->Exit[i]->ReleaseGraphicsResources(window);
    this->Continuation[i]->ReleaseGraphicsResources(window);
    this->LayerDepth[i]->ReleaseGraphicsResources(window);
  }
  this->OpaqueDepth->ReleaseGraphicsResources(window);
  this->OpaqueDepthFormat = -2;
  this->TargetSize[0] = this->TargetSize[1] = 0;
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
    this->Query = 0;
  }
  this->Times.ReleaseGraphicsResources();
  this->EntryProgram = nullptr;
  this->EntryVAO->ReleaseGraphicsResources();
  this->EntryPoints = nullptr;
  for (auto* quad : { &this->CompositeQuad, &this->UnfinishedQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(window);
      quad->reset();
    }
  }
  this->SectionProgram = nullptr;
  this->SectionVAO->ReleaseGraphicsResources();
  this->SectionVertices->ReleaseGraphicsResources();
}

//------------------------------------------------------------------------------
bool vtkPPIRayDepthPeeling::Prepare(vtkOpenGLRenderWindow* context, int width, int height,
  vtkPPIRayCellBuffers& cells, vtkObject* reporter)
{
  if (this->TargetSize[0] != width || this->TargetSize[1] != height)
  {
    const bool ok = AllocateTarget(this->EntryTexture, context, width, height, 1) &&
                    AllocateTarget(this->Accumulated[0], context, width, height, 4) &&
                    AllocateTarget(this->Accumulated[1], context, width, height, 4) &&
                    AllocateTarget(this->Exit[0], context, width, height, 4) &&
                    AllocateTarget(this->Exit[1], context, width, height, 4) &&
                    AllocateTarget(this->Continuation[0], context, width, height, 2) &&
                    AllocateTarget(this->Continuation[1], context, width, height, 2) &&
                    AllocateDepthTarget(this->LayerDepth[0], context, width, height) &&
                    AllocateDepthTarget(this->LayerDepth[1], context, width, height);
    if (!ok)
    {
      vtkErrorWithObjectMacro(
        reporter, "Could not allocate " << width << "x" << height << " render targets.");
      this->TargetSize[0] = this->TargetSize[1] = 0;
      return false;
    }
    this->TargetSize[0] = width;
    this->TargetSize[1] = height;
  }
  this->Framebuffer->SetContext(context);
  if (!this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  vtkOpenGLShaderCache* cache = context->GetShaderCache();
  if (!this->EntryProgram)
  {
    std::string fragment = entry_fs;
    vtkShaderProgram::Substitute(fragment, "//PPIRay::Ray::Impl", ray_fs);
    this->EntryProgram = cache->ReadyShaderProgram(entry_vs, fragment.c_str(), "");
  }
  else
  {
    cache->ReadyShaderProgram(this->EntryProgram);
  }
  if (!this->EntryProgram)
  {
    vtkErrorWithObjectMacro(reporter, "Could not build the entry shader.");
    return false;
  }
  if (this->EntryPoints != cells.GetBoundaryPoints() ||
      this->EntryPointsUpload != cells.GetGeometryUploadCount())
  {
    // The vertex array reads the boundary points' buffer as it was bound.
    this->EntryVAO->Bind();
    this->EntryVAO->AddAttributeArray(this->EntryProgram, cells.GetBoundaryPoints(), "vertexMC", 0,
      3 * sizeof(float), VTK_FLOAT, 3, false);
    this->EntryVAO->Release();
    this->EntryPoints = cells.GetBoundaryPoints();
    this->EntryPointsUpload = cells.GetGeometryUploadCount();
  }
  if (!this->CompositeQuad)
  {
    this->CompositeQuad.reset(new vtkOpenGLQuadHelper(context, nullptr, composite_fs, ""));
  }
  if (!this->UnfinishedQuad)
  {
    this->UnfinishedQuad.reset(new vtkOpenGLQuadHelper(context, nullptr, unfinished_fs, ""));
  }
  if (!this->CompositeQuad->Program || !this->UnfinishedQuad->Program)
  {
    vtkErrorWithObjectMacro(reporter, "Could not build the composite shaders.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayDepthPeeling::CopyOpaqueDepth(
  vtkOpenGLRenderWindow* context, int source, const Frame& frame, vtkObject* reporter)
{
  vtkOpenGLState* state = context->GetState();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, source);
  const GLenum attachment = source ? GL_DEPTH_ATTACHMENT : GL_DEPTH;
  GLint bits = 0, type = 0, stencil = 0;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencil);
  int format = stencil > 0        ? -1
               : type == GL_FLOAT ? vtkTextureObject::Float32
               : bits >= 32       ? vtkTextureObject::Fixed32
               : bits >= 24       ? vtkTextureObject::Fixed24
                                  : vtkTextureObject::Fixed16;
  if (bits == 0)
  {
    format = vtkTextureObject::Float32; // no depth buffer: nothing is opaque
  }
  const int width = frame.TargetWidth, height = frame.TargetHeight;
  if (this->OpaqueDepthFormat != format ||
      this->OpaqueDepth->GetWidth() != static_cast<unsigned>(width) ||
      this->OpaqueDepth->GetHeight() != static_cast<unsigned>(height))
  {
    this->OpaqueDepth->SetContext(context);
    this->OpaqueDepth->SetMinificationFilter(vtkTextureObject::Nearest);
    this->OpaqueDepth->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (format < 0)
    {
      this->OpaqueDepth->AllocateDepthStencil(width, height);
    }
    else
    {
      this->OpaqueDepth->AllocateDepth(width, height, format);
    }
    this->OpaqueDepthFormat = format;
  }
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
  fbo->Bind(GL_DRAW_FRAMEBUFFER);
  fbo->AddDepthAttachment(this->OpaqueDepth);
  while (glGetError() != GL_NO_ERROR)
  {
  }
  bool copied = false;
  if (bits > 0)
  {
    // At a reduced resolution each target pixel takes the depth nearest its
    // centre.
    glBlitFramebuffer(frame.X0, frame.Y0, frame.X0 + frame.Width, frame.Y0 + frame.Height, 0, 0,
      width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    copied = glGetError() == GL_NO_ERROR;
  }
  if (!copied)
  {
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
    if (bits > 0)
    {
      vtkWarningWithObjectMacro(reporter, "Could not read the depth buffer ("
                                            << bits
                                            << " bits): opaque geometry does not stop the rays.");
    }
  }
  fbo->RemoveDepthAttachment();
}

//------------------------------------------------------------------------------
int vtkPPIRayDepthPeeling::Render(vtkOpenGLRenderWindow* context, const Frame& frame,
  vtkPPIRayCellBuffers& cells, vtkPPIRayMarchShader& march, const MarchInputs& marchInputs,
  bool& cut, vtkObject* reporter)
{
  cut = false;
  this->FrameMilliseconds = -1.0;
  this->RaysMarched = this->TargetPixels = 0; // no frame drawn yet
  this->Times.StartFrame(frame.TimePasses);
  if (!this->Prepare(context, frame.TargetWidth, frame.TargetHeight, cells, reporter))
  {
    return -1;
  }
  if (frame.TimeFrame)
  {
    glFinish(); // what was drawn before (and the targets' allocation) is not this frame's
  }
  const auto start = std::chrono::steady_clock::now();
  this->Times.Start(vtkPPIRayPassTimes::Setup);
  vtkOpenGLState* state = context->GetState();
  vtkPPIRayPeelingStateRAII saved(state);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  // Opaque depth: VTK's depth buffer under this renderer's viewport.
  state->PushFramebufferBindings();
  int source = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &source);
  this->CopyOpaqueDepth(context, source, frame, reporter);
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
  fbo->Bind();
  state->vtkglViewport(0, 0, frame.TargetWidth, frame.TargetHeight);
  // Nothing accumulated yet; no march has stopped anywhere.
  this->Current = 0;
  this->Layer = 0;
  fbo->AddColorAttachment(0, this->Accumulated[0]);
  fbo->AddColorAttachment(1, this->Exit[0]);
  fbo->AddColorAttachment(2, this->Continuation[0]);
  fbo->ActivateDrawBuffers(3);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  fbo->RemoveColorAttachment(2);
  fbo->RemoveColorAttachment(1);

  int peel = 0;
  this->Continuations = 0;
  this->CellSteps = 0;
  this->TargetPixels = static_cast<long long>(frame.TargetWidth) * frame.TargetHeight;
  bool finished = true;
  if (frame.Section && !frame.Section->empty() && this->EnterAtNearPlane(context, frame, reporter))
  {
    finished = this->MarchToEnd(context, frame, march, marchInputs) && finished;
    ++peel;
  }
  bool entered = false;
  for (int layer = 0; peel < frame.MaximumPeels; ++peel, ++layer)
  {
    if (frame.ConvexBoundary && layer == 1)
    {
      entered = false; // every ray met its one entry face in the first layer
      break;
    }
    entered = this->Enter(context, frame, cells, layer == 0);
    if (!entered)
    {
      break;
    }
    finished = this->MarchToEnd(context, frame, march, marchInputs) && finished;
  }
  cut = peel == frame.MaximumPeels && entered;
  if (!finished)
  {
    vtkWarningWithObjectMacro(
      reporter, "Some rays were still unfinished after "
                  << MaximumContinuations
                  << " passes of the march's loop budget: they are cut where they stopped.");
  }
  fbo->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  this->Times.Start(vtkPPIRayPassTimes::Composite);
  this->Composite(context, frame);
  this->Times.EndFrame();
  if (frame.TimeFrame)
  {
    glFinish();
    this->FrameMilliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return peel;
}

//------------------------------------------------------------------------------
bool vtkPPIRayDepthPeeling::MarchToEnd(vtkOpenGLRenderWindow* context, const Frame& frame,
  vtkPPIRayMarchShader& march, const MarchInputs& marchInputs)
{
  this->March(context, frame, march, marchInputs);
  for (int pass = 0; this->Unfinished(context); ++pass)
  {
    if (pass == MaximumContinuations)
    {
      // Given up: the rays stay where they stopped, not continued by the
      // next peel's march.
      vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
      fbo->AddColorAttachment(0, this->Continuation[this->Current]);
      fbo->ActivateDrawBuffers(1);
      context->GetState()->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      context->GetState()->vtkglClear(GL_COLOR_BUFFER_BIT);
      return false;
    }
    this->March(context, frame, march, marchInputs);
    ++this->Continuations;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayDepthPeeling::ClearEntries(vtkOpenGLRenderWindow* context)
{
  vtkOpenGLState* state = context->GetState();
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
  fbo->RemoveDepthAttachment();
  fbo->AddColorAttachment(0, this->EntryTexture);
  fbo->ActivateDrawBuffers(1);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  UseFullScreenState(state, false);
}

//------------------------------------------------------------------------------
bool vtkPPIRayDepthPeeling::Unfinished(vtkOpenGLRenderWindow* context)
{
  this->Times.Start(vtkPPIRayPassTimes::ContinuationCheck);
  this->ClearEntries(context);
  vtkShaderProgram* program = this->UnfinishedQuad->Program;
  context->GetShaderCache()->ReadyShaderProgram(program);
  vtkTextureObject* continuation = this->Continuation[this->Current];
  continuation->Activate();
  program->SetUniformi("continuation", continuation->GetTextureUnit());
  glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  this->UnfinishedQuad->Render();
  glEndQuery(GL_SAMPLES_PASSED);
  continuation->Deactivate();
  GLuint samplesPassed = 0;
  glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &samplesPassed);
  this->Times.Stop();
  this->RaysAtMost = samplesPassed;
  return samplesPassed > 0;
}

//------------------------------------------------------------------------------
bool vtkPPIRayDepthPeeling::Enter(
  vtkOpenGLRenderWindow* context, const Frame& frame, vtkPPIRayCellBuffers& cells, bool firstLayer)
{
  this->Times.Start(vtkPPIRayPassTimes::Entry);
  vtkOpenGLState* state = context->GetState();
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
  fbo->AddColorAttachment(0, this->EntryTexture);
  fbo->AddDepthAttachment(this->LayerDepth[this->Layer]);
  fbo->ActivateDrawBuffers(1);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_BACK);

  context->GetShaderCache()->ReadyShaderProgram(this->EntryProgram);
  vtkShaderProgram* entry = this->EntryProgram;
  vtkTextureObject* inputs[] = { this->LayerDepth[1 - this->Layer], this->OpaqueDepth,
    this->Accumulated[this->Current] };
  const char* names[] = { "previousLayerDepth", "opaqueDepth", "accumulated" };
  for (int i = 0; i < 3; ++i)
  {
    inputs[i]->Activate();
    entry->SetUniformi(names[i], inputs[i]->GetTextureUnit());
  }
  entry->SetUniformMatrix4x4("localToClip", const_cast<float*>(frame.LocalToClip));
  entry->SetUniformi("firstLayer", firstLayer ? 1 : 0);
  const float viewport[2] = { static_cast<float>(frame.TargetWidth),
    static_cast<float>(frame.TargetHeight) };
  entry->SetUniform2f("viewportSize", viewport);
  SetRayUniforms(entry, frame);
  entry->SetUniformf("terminationAlpha", frame.TerminationAlpha);
  this->EntryVAO->Bind();
  cells.GetBoundaryTriangles()->Bind();
  glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(cells.GetNumberOfBoundaryIndices()),
    GL_UNSIGNED_INT, nullptr);
  glEndQuery(GL_SAMPLES_PASSED);
  cells.GetBoundaryTriangles()->Release();
  this->EntryVAO->Release();
  for (auto* texture : inputs)
  {
    texture->Deactivate();
  }
  GLuint samplesPassed = 0;
  glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &samplesPassed);
  this->Times.Stop();
  this->Layer = 1 - this->Layer;
  // Fragments that passed, overlapping ones counted each: at least the rays.
  this->RaysAtMost = samplesPassed;
  return samplesPassed > 0;
}

//------------------------------------------------------------------------------
bool vtkPPIRayDepthPeeling::EnterAtNearPlane(
  vtkOpenGLRenderWindow* context, const Frame& frame, vtkObject* reporter)
{
  this->Times.Start(vtkPPIRayPassTimes::NearPlaneEntry);
  this->RaysAtMost = static_cast<long long>(frame.TargetWidth) * frame.TargetHeight; // not counted
  vtkOpenGLShaderCache* cache = context->GetShaderCache();
  if (this->SectionProgram)
  {
    cache->ReadyShaderProgram(this->SectionProgram);
  }
  else
  {
    this->SectionProgram = cache->ReadyShaderProgram(section_vs, section_fs, "");
  }
  if (!this->SectionProgram ||
      !this->SectionVertices->Upload(*frame.Section, vtkOpenGLBufferObject::ArrayBuffer))
  {
    vtkErrorWithObjectMacro(reporter, "Could not draw the near plane's sections.");
    return false;
  }
  this->ClearEntries(context);
  this->SectionProgram->SetUniformMatrix4x4("localToClip", const_cast<float*>(frame.LocalToClip));
  this->SectionVAO->Bind();
  this->SectionVAO->AddAttributeArray(this->SectionProgram, this->SectionVertices, "vertexMC", 0,
    4 * sizeof(float), VTK_FLOAT, 4, false);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(frame.Section->size() / 4));
  this->SectionVAO->Release();
  this->Times.Stop();
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayDepthPeeling::March(vtkOpenGLRenderWindow* context, const Frame& frame,
  vtkPPIRayMarchShader& march, const MarchInputs& marchInputs)
{
  // From the entry cell to where the ray leaves the mesh, composited under
  // what earlier peels accumulated (ping-pong).
  this->Times.Start(vtkPPIRayPassTimes::March);
  vtkOpenGLState* state = context->GetState();
  vtkOpenGLFramebufferObject* fbo = this->Framebuffer;
  const int next = 1 - this->Current;
  fbo->RemoveDepthAttachment();
  fbo->AddColorAttachment(0, this->Accumulated[next]);
  fbo->AddColorAttachment(1, this->Exit[next]);
  fbo->AddColorAttachment(2, this->Continuation[next]);
  fbo->ActivateDrawBuffers(3);
  UseFullScreenState(state, false);

  vtkShaderProgram* program = march.GetProgram();
  context->GetShaderCache()->ReadyShaderProgram(program);
  std::vector<vtkTextureObject*> textures = { this->EntryTexture, this->OpaqueDepth,
    this->Accumulated[this->Current], this->Exit[this->Current],
    this->Continuation[this->Current] };
  const char* names[] = { "entryTriangle", "opaqueDepth", "previousAccumulated", "previousExit",
    "previousContinuation" };
  for (size_t i = 0; i < textures.size(); ++i)
  {
    textures[i]->Activate();
    program->SetUniformi(names[i], textures[i]->GetTextureUnit());
  }
  SetRayUniforms(program, frame);
  marchInputs(program, textures);
  vtkTextureObject* const targets[3] = { this->Accumulated[next], this->Exit[next],
    this->Continuation[next] };
  vtkTextureObject* const inputs[4] = { this->EntryTexture, this->Accumulated[this->Current],
    this->Exit[this->Current], this->Continuation[this->Current] };
  march.Run(context, fbo, frame.TargetWidth, frame.TargetHeight, inputs, targets, this->RaysAtMost);
  this->Times.Stop();
  this->RaysMarched += std::min(this->RaysAtMost, this->TargetPixels);
  for (auto* texture : textures)
  {
    texture->Deactivate();
  }
  if (frame.CountCellSteps)
  {
    this->CellSteps += this->FinishedRaySteps(frame);
  }
  fbo->RemoveColorAttachment(2);
  fbo->RemoveColorAttachment(1);
  this->Current = next;
}

//------------------------------------------------------------------------------
long long vtkPPIRayDepthPeeling::FinishedRaySteps(const Frame& frame)
{
  // march_common_fs.glsl's third output: (continuation code, steps so far).
  std::vector<float> texels(2 * static_cast<size_t>(frame.TargetWidth) * frame.TargetHeight);
  this->Framebuffer->ActivateReadBuffer(2);
  glReadPixels(0, 0, frame.TargetWidth, frame.TargetHeight, GL_RG, GL_FLOAT, texels.data());
  this->Framebuffer->DeactivateReadBuffer();
  long long steps = 0;
  for (size_t i = 0; i < texels.size(); i += 2)
  {
    steps += texels[i] > 0.0f ? 0 : static_cast<long long>(texels[i + 1]);
  }
  return steps;
}

//------------------------------------------------------------------------------
void vtkPPIRayDepthPeeling::SetRayUniforms(vtkShaderProgram* program, const Frame& frame)
{
  program->SetUniformMatrix4x4("clipToLocal", const_cast<float*>(frame.ClipToLocal));
  program->SetUniformMatrix3x3("ndcToDirection", const_cast<float*>(frame.NdcToDirection));
  float planes[6][4] = {};
  const size_t count =
    frame.ClippingPlanes ? std::min<size_t>(frame.ClippingPlanes->size() / 4, 6) : 0;
  for (size_t i = 0; i < 4 * count; ++i)
  {
    planes[i / 4][i % 4] = (*frame.ClippingPlanes)[i];
  }
  program->SetUniformi("numberOfClippingPlanes", static_cast<int>(count));
  program->SetUniform4fv("clippingPlanes", 6, planes);
}

//------------------------------------------------------------------------------
void vtkPPIRayDepthPeeling::Composite(vtkOpenGLRenderWindow* context, const Frame& frame)
{
  vtkOpenGLState* state = context->GetState();
  state->vtkglViewport(frame.X0, frame.Y0, frame.Width, frame.Height);
  UseFullScreenState(state, true);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglDepthMask(GL_FALSE);
  vtkShaderProgram* program = this->CompositeQuad->Program;
  context->GetShaderCache()->ReadyShaderProgram(program);
  vtkTextureObject* accumulated = this->Accumulated[this->Current];
  // Scaled up bilinearly from a reduced resolution (premultiplied colour).
  const bool scaled = frame.TargetWidth != frame.Width || frame.TargetHeight != frame.Height;
  accumulated->SetMagnificationFilter(
    scaled ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  accumulated->SetMinificationFilter(scaled ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  accumulated->Activate();
  program->SetUniformi("accumulated", accumulated->GetTextureUnit());
  this->CompositeQuad->Render();
  accumulated->Deactivate();
}
