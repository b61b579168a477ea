/**
 * @class   vtkPPIRayMarchQueue
 * @brief   the compute stage's ray queue: live pixels listed, the march dispatched over them
 *
 * Before each compute march pass, a small compute pass
 * (march_queue_cs.glsl) lists the pixels whose ray the pass takes (an entry
 * or a continuation) in a shader storage buffer and writes every other
 * pixel's targets itself; the march is then dispatched indirectly, one
 * invocation per listed ray (march_compute_stage_cs.glsl), so that work
 * groups hold live rays only, however few a peel or a continuation pass
 * has. Both shaders declare the list with Declarations(). Internal to
 * PPIRay::Rendering.
 */
#ifndef vtkPPIRayMarchQueue_h
#define vtkPPIRayMarchQueue_h

#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <string> // for std::string

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

  /** The list's bytes on the GPU. */
  size_t GetGPUBytes() const { return this->Bytes; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayMarchQueue(const vtkPPIRayMarchQueue&) = delete;
  void operator=(const vtkPPIRayMarchQueue&) = delete;

  vtkSmartPointer<vtkPPIRayComputeProgram> Program;
  unsigned int Buffer = 0; // rays, the indirect dispatch (3), then one pixel per slot
  size_t Bytes = 0;
};

#endif
