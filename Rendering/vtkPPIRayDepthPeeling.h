/**
 * @class   vtkPPIRayDepthPeeling
 * @brief   the passes of a frame: opaque depth, entry and march per peel, composite
 *
 * Owns the render targets (sized to the viewport), the entry program and
 * its vertex array, the occlusion query and the composite program. A frame:
 * VTK's depth buffer under the viewport is copied (opaque geometry stops the
 * rays); where the near plane cuts the mesh, a first march starts each ray
 * there in the cell whose section covers the pixel (section_vs.glsl,
 * section_fs.glsl); then per peel an entry pass rasterizes the next layer of
 * front-facing boundary triangles (entry_vs.glsl, entry_fs.glsl) and the
 * march pass integrates from there (a full-screen quad of the march program,
 * its cell and transfer-function inputs bound by the caller), composited
 * under the earlier peels in ping-pong targets, until no fragment enters (an
 * entry past where opaque geometry or a clipping plane ends the ray is none); the
 * result is composited over VTK's framebuffer (composite_fs.glsl). GL state
 * is restored by vtkPPIRayPeelingStateRAII. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayDepthPeeling_h
#define vtkPPIRayDepthPeeling_h

#include "vtkNew.h"             // for vtkNew
#include "vtkPPIRayPassTimes.h" // for vtkPPIRayPassTimes

#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <vector>     // for std::vector

class vtkObject;
class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkPPIRayMarchShader;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkPPIRayCellBuffers;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkPPIRayDepthPeeling
{
public:
  vtkPPIRayDepthPeeling();
  ~vtkPPIRayDepthPeeling();

  struct Frame
  {
    int X0, Y0, Width, Height; // the renderer's tiled viewport
    // The resolution the rays are cast at (the viewport's divided by the
    // image sample distance); the composite pass scales it up bilinearly.
    int TargetWidth, TargetHeight;
    float LocalToClip[16];   // column-major: the mesh's local frame to clip space
    float ClipToLocal[16];   // and back
    float NdcToDirection[9]; // column-major: D, the ray direction D (x, y, 1) at NDC (x, y)
    float TerminationAlpha;  // a pixel this opaque takes no more peels
    int MaximumPeels;
    // The sections of the cells the near plane cuts (PlaneSection(): x, y,
    // z, cell per vertex), or null: the first march starts there.
    const std::vector<float>* Section = nullptr;
    // Clipping planes in the local frame, (n, d) each, n . x + d >= 0 kept
    // (at most 6), or null.
    const std::vector<float>* ClippingPlanes = nullptr;
    // Count the march's cell steps (a read-back per march pass: slow).
    bool CountCellSteps = false;
    // Time every pass with GL timer queries (waits for the GPU at the end).
    bool TimePasses = false;
    // Time the frame's passes on the clock, waiting for the GPU before and
    // after them (the automatic march stage's probe).
    bool TimeFrame = false;
    // The boundary bounds a convex solid: one entry layer, no peel after it.
    bool ConvexBoundary = false;
  };
  /** Binds the march program's inputs other than the peeling's own. */
  using MarchInputs = std::function<void(vtkShaderProgram*, std::vector<vtkTextureObject*>&)>;

  /**
   * Renders a frame of `cells` with `march` (a program reading
   * march_common_fs.glsl's inputs); returns the number of peels, -1 on
   * failure (reported). `cut`: whether MaximumPeels stopped it.
   */
  int Render(vtkOpenGLRenderWindow* context, const Frame& frame, vtkPPIRayCellBuffers& cells,
    vtkPPIRayMarchShader& march, const MarchInputs& marchInputs, bool& cut, vtkObject* reporter);

  /**
   * Passes the last frame added where rays ran out of the march's loop
   * budget (march_common_fs.glsl) and were continued.
   */
  int GetNumberOfContinuations() const { return this->Continuations; }

  /**
   * Cell steps the last frame's marches took, over every pixel and peel
   * (Frame::CountCellSteps; else 0).
   */
  long long GetNumberOfCellSteps() const { return this->CellSteps; }

  /** The last frame's target size in pixels (0: no frame drawn). */
  long long GetTargetPixels() const { return this->TargetPixels; }
  /**
   * Rays the last frame's march passes marched (at most: each pass's entry
   * or continuation query) per pixel of the target, over all passes.
   */
  double GetRaysPerPixel() const
  {
    return this->TargetPixels > 0 ? double(this->RaysMarched) / double(this->TargetPixels) : 0.0;
  }
  /** Milliseconds the last frame's passes took (Frame::TimeFrame; else -1). */
  double GetFrameMilliseconds() const { return this->FrameMilliseconds; }
  /** The last frame's GPU time per kind of pass (Frame::TimePasses; else 0). */
  const vtkPPIRayPassTimes& GetPassTimes() const { return this->Times; }

  /** Continuation passes after one march, at most (then a warning). */
  static constexpr int MaximumContinuations = 1024;

  size_t GetGPUBytes() const;
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayDepthPeeling(const vtkPPIRayDepthPeeling&) = delete;
  void operator=(const vtkPPIRayDepthPeeling&) = delete;

  bool Prepare(vtkOpenGLRenderWindow* context, int width, int height, vtkPPIRayCellBuffers& cells,
    vtkObject* reporter);
  // VTK's depth (resolving multisampling) into a texture of the very same
  // format, as glBlitFramebuffer requires for depth.
  void CopyOpaqueDepth(
    vtkOpenGLRenderWindow* context, int source, const Frame& frame, vtkObject* reporter);
  // The next layer of boundary triangles into EntryTexture; whether any
  // fragment entered.
  bool Enter(vtkOpenGLRenderWindow* context, const Frame& frame, vtkPPIRayCellBuffers& cells,
    bool firstLayer);
  // The sections of the cells cut by the near plane into EntryTexture.
  bool EnterAtNearPlane(vtkOpenGLRenderWindow* context, const Frame& frame, vtkObject* reporter);
  void March(vtkOpenGLRenderWindow* context, const Frame& frame, vtkPPIRayMarchShader& march,
    const MarchInputs& marchInputs);
  // March, then continue the rays that ran out of the loop budget until none
  // is left (at most MaximumContinuations passes; false if some were left).
  bool MarchToEnd(vtkOpenGLRenderWindow* context, const Frame& frame, vtkPPIRayMarchShader& march,
    const MarchInputs& marchInputs);
  // EntryTexture bound alone and cleared (no entries), for a flat pass.
  void ClearEntries(vtkOpenGLRenderWindow* context);
  // Whether the last march left rays unfinished (clears EntryTexture, so the
  // next march starts no new ray).
  bool Unfinished(vtkOpenGLRenderWindow* context);
  void Composite(vtkOpenGLRenderWindow* context, const Frame& frame);
  // The steps of the rays the last march finished: the continuation
  // target's step counts where it holds no continuation (a continued ray is
  // counted when it finishes, its count carried across passes).
  long long FinishedRaySteps(const Frame& frame);
  // The viewing ray's uniforms (ray_fs.glsl): clipToLocal, the clipping planes.
  static void SetRayUniforms(vtkShaderProgram* program, const Frame& frame);

  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkTextureObject> EntryTexture;
  vtkNew<vtkTextureObject> Accumulated[2];  // ping-pong: colour so far
  vtkNew<vtkTextureObject> Exit[2];         // ping-pong: where the last march stopped, projection
  vtkNew<vtkTextureObject> Continuation[2]; // ping-pong: where rays ran out of loops, steps
  vtkNew<vtkTextureObject> LayerDepth[2];
  vtkNew<vtkTextureObject> OpaqueDepth; // same format as VTK's depth buffer
  int OpaqueDepthFormat = -2;
  int TargetSize[2] = { 0, 0 };
  int Current = 0; // the Accumulated and Exit the next pass reads
  int Layer = 0;   // the LayerDepth the next entry pass writes
  unsigned int Query = 0;

  vtkShaderProgram* EntryProgram = nullptr; // owned by the shader cache
  vtkNew<vtkOpenGLVertexArrayObject> EntryVAO;
  vtkOpenGLBufferObject* EntryPoints = nullptr; // the buffer EntryVAO reads
  int EntryPointsUpload = -1;                   // its upload count then
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> UnfinishedQuad;
  int Continuations = 0;
  // At least the rays the next march pass takes (the last entry or
  // continuation pass's query; the target's pixels where not counted).
  long long RaysAtMost = 0;
  long long CellSteps = 0;
  long long RaysMarched = 0;  // over the frame's march passes
  long long TargetPixels = 0; // of the frame's targets
  double FrameMilliseconds = -1.0;
  vtkPPIRayPassTimes Times;

  vtkShaderProgram* SectionProgram = nullptr; // owned by the shader cache
  vtkNew<vtkOpenGLVertexArrayObject> SectionVAO;
  vtkNew<vtkOpenGLBufferObject> SectionVertices;
};

#endif
