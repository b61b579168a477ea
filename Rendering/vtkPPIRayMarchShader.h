/**
 * @class   vtkPPIRayMarchShader
 * @brief   the march program: a traversal, an integration mode, isosurfaces, composed
 *
 * As VTK's vtkVolumeShaderComposer: the march pass's shader is the
 * traversal of the cells (vtkPPIRayCellBuffers::GetMarchShader(), with its
 * layout), with the transfer function lookup, the isosurfaces, the
 * projection (BLEND, a ppiray::Projection: 0 composite, 1 maximum,
 * 2 minimum, 3 average intensity, 4 additive), the
 * integration mode's segment integral (vtkPPIRaySegmentIntegrator), the
 * viewing ray and the stage substituted at their //PPIRay:: markers. The
 * stage is where the same march runs: a fragment shader over a full-screen
 * quad, or a compute shader over the rays of a ray queue
 * (march_fragment_stage_fs.glsl, march_compute_stage_cs.glsl,
 * vtkPPIRayMarchQueue). The program is rebuilt only when the
 * composed source changes. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayMarchShader_h
#define vtkPPIRayMarchShader_h

#include "vtkPPIRayStageChoice.h" // for vtkPPIRayStageChoice
#include "vtkSmartPointer.h"      // for vtkSmartPointer

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkPPIRayComputeProgram;
class vtkPPIRayDepthPeeling;
class vtkPPIRayMarchQueue;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkPPIRayMarchShader
{
public:
  vtkPPIRayMarchShader();
  ~vtkPPIRayMarchShader();

  /**
   * The shader of `traversal` with the other parts substituted, for `stage`
   * (a ppiray::MarchStage: MarchCompute, else the fragment stage).
   */
  static std::string Compose(const std::string& traversal, const std::string& integration,
    const std::string& isoSurfaces, int blend, int stage);

  /**
   * Builds (when the source changed) and binds the program of the composed
   * shader in `stage` (ppiray::MarchStage; MarchAutomatic: the one
   * vtkPPIRayStageChoice gives for this frame); a compute stage asked for
   * that the context cannot run, or that does not compile, gives the
   * fragment stage, with one warning (automatic: silently where the context
   * has no compute shaders). False (reported) when no program builds.
   */
  bool Ready(vtkOpenGLRenderWindow* context, const std::string& traversal,
    const std::string& integration, const std::string& isoSurfaces, int blend, int stage,
    vtkObject* reporter);

  /** Whether the next frame in `stage` must be timed (an automatic stage's probe). */
  bool Probing(int stage) const;

  /**
   * What the frame `peeling` drew with the program last readied cost (none
   * if it drew nothing): its passes' time on the clock, its rays marched
   * per pixel and target size, for the mesh of `tetrahedra` and
   * `nativeCells` (vtkPPIRayStageChoice::SceneKey; the automatic stage's
   * measurement, vtkPPIRayStageChoice::Observe).
   */
  void ObserveFrame(
    const vtkPPIRayDepthPeeling& peeling, long long tetrahedra, long long nativeCells);

  /** The automatic stage's choice and its probe. */
  const vtkPPIRayStageChoice& GetChoice() const { return this->Choice; }

  /** The stage of the program last readied: MarchFragment or MarchCompute. */
  int GetStage() const { return this->Built; }
  /** The program last readied, for its uniforms. */
  vtkShaderProgram* GetProgram() const;

  /**
   * One march pass over a width x height target, over the pixels that have
   * a ray (vtkPPIRayMarchQueue; read from `inputs`: entry code, previous
   * accumulated colour, exit, continuation, active on their units;
   * `raysAtMost` bounds their number): the fragment stage draws the quad
   * into the framebuffer's three draw buffers (set by the caller); the
   * compute stage stores into `targets` (accumulated, exit, continuation)
   * bound as images.
   */
  void Run(vtkOpenGLRenderWindow* context, vtkOpenGLFramebufferObject* framebuffer, int width,
    int height, vtkTextureObject* const inputs[4], vtkTextureObject* const targets[3],
    long long raysAtMost);

  /** GPU memory of the ray queue and the ray mask (0 until they ran). */
  size_t GetGPUBytes() const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayMarchShader(const vtkPPIRayMarchShader&) = delete;
  void operator=(const vtkPPIRayMarchShader&) = delete;

  bool ReadyCompute(vtkOpenGLRenderWindow* context, const std::string& source, vtkObject* reporter);
  bool ReadyFragment(
    vtkOpenGLRenderWindow* context, const std::string& source, vtkObject* reporter);

  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string Source; // what Quad was built from
  vtkSmartPointer<vtkPPIRayComputeProgram> Compute;
  std::string ComputeSource;   // what Compute was built from
  bool ComputeRefused = false; // warned once: the fragment stage from then on
  std::unique_ptr<vtkPPIRayMarchQueue> Queue;
  int Built = 0; // ppiray::MarchFragment
  int Requested = 0;
  vtkPPIRayStageChoice Choice;
};

#endif
