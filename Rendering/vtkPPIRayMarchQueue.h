/**
 * @class   vtkPPIRayMarchQueue
 * @brief   the march over the pixels that have a ray only: a list (compute), a mask (fragment)
 *
 * A march pass takes the rays of the pixels with an entry code or a
 * continuation (march_pixels_fs.glsl); elsewhere it only passes the earlier
 * peels' targets through, yet a pass over the whole target would run the
 * march's whole body there (SIMD lanes are masked, not skipped). So before
 * each march pass a small pass writes those pixels' targets itself and
 * marks the others:
 * - compute stage (Gather(), DispatchMarch()): lists them in a shader
 *   storage buffer (march_queue_cs.glsl) and the march is dispatched
 *   indirectly, one invocation per listed ray (march_compute_stage_cs.glsl),
 *   so that work groups hold rays only; both shaders declare the list with
 *   Declarations();
 * - fragment stage (Mask(), EndMask()): writes a depth of its own, 0 where a
 *   ray is, 1 elsewhere (march_mask_fs.glsl), and the march's quad is
 *   depth-tested against it, so fragments without a ray are not shaded;
 *   only where at most half the pixels can have a ray (MaskPays()), since
 *   the mask pass costs a pass over the target.
 * Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayMarchQueue_h
#define vtkPPIRayMarchQueue_h

#include "vtkNew.h"          // for vtkNew
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <memory> // for std::unique_ptr

#include <string> // for std::string

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkPPIRayComputeProgram;
class vtkTextureObject;
class vtkWindow;

class vtkPPIRayMarchQueue
{
public:
  vtkPPIRayMarchQueue();
  ~vtkPPIRayMarchQueue();

  /** The march's invocations per work group along its one dimension. */
  static constexpr int MarchGroupSize = 64;

  /**
   * The GLSL both shaders substitute at //PPIRay::MarchQueue::Dec: the group
   * size and march_queue_dec_cs.glsl (the list, the targets as images).
   */
  static std::string Declarations();

  /** Builds the queue pass; false with `error` set where it does not build. */
  bool Build(std::string& error);

  /**
   * Lists the live pixels of a width x height target: reads `inputs` (the
   * entry code, the previous accumulated colour, exit and continuation,
   * active on their texture units) and writes the other pixels into the
   * `targets` bound as images 0 to 2 by the caller. Leaves the queue pass's
   * program bound.
   */
  void Gather(
    vtkOpenGLRenderWindow* context, int width, int height, vtkTextureObject* const inputs[4]);

  /** Runs the bound march program over the listed rays. */
  void DispatchMarch();

  /**
   * Whether the fragment stage's mask pays for its pass: where at most half
   * of the target's pixels can have a ray (`raysAtMost`).
   */
  static bool MaskPays(long long raysAtMost, int width, int height)
  {
    return 2 * raysAtMost <= static_cast<long long>(width) * height;
  }

  /**
   * The fragment stage's mask: writes the depth of `framebuffer` (a depth
   * target of its own attached) 0 where the march takes a ray, 1 elsewhere,
   * and the other pixels' targets (the framebuffer's three draw buffers);
   * leaves the depth test set so that a full-screen quad drawn next is
   * shaded where a ray is only. EndMask() detaches it.
   */
  bool Mask(vtkOpenGLRenderWindow* context, vtkOpenGLFramebufferObject* framebuffer, int width,
    int height, vtkTextureObject* const inputs[4]);
  void EndMask(vtkOpenGLRenderWindow* context, vtkOpenGLFramebufferObject* framebuffer);

  /** The list's and the mask's bytes on the GPU. */
  size_t GetGPUBytes() const
  {
    return this->Bytes + 4 * static_cast<size_t>(this->MaskSize[0]) * this->MaskSize[1];
  }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayMarchQueue(const vtkPPIRayMarchQueue&) = delete;
  void operator=(const vtkPPIRayMarchQueue&) = delete;

  vtkSmartPointer<vtkPPIRayComputeProgram> Program;
  unsigned int Buffer = 0; // rays, the indirect dispatch (3), then one pixel per slot
  size_t Bytes = 0;
  std::unique_ptr<vtkOpenGLQuadHelper> MaskQuad;
  vtkNew<vtkTextureObject> MaskDepth;
  int MaskSize[2] = { 0, 0 };
};

#endif
