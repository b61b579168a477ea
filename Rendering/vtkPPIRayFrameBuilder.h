/**
 * @class   vtkPPIRayFrameBuilder
 * @brief   a frame's view of the cells: viewport, matrices, near-plane sections, clipping planes,
 * loop budget
 *
 * From the renderer's camera and viewport, the volume's matrix and the
 * cells' local frame, builds what the depth peeling draws a frame with
 * (vtkPPIRayDepthPeeling::Frame): the local frame to clip space and back, in
 * double then float; the ray direction per pixel; the sections of the cells
 * the near plane cuts (a camera inside the mesh); the clipping planes in the
 * local frame; the march's step budget. Also the level-of-detail rule of
 * VTK's CPU ray caster. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayFrameBuilder_h
#define vtkPPIRayFrameBuilder_h

#include "vtkNew.h"
#include "vtkPPIRayDepthPeeling.h" // for Frame

#include <vector> // for std::vector

class vtkMatrix4x4;
class vtkObject;
class vtkPPIRayCellBuffers;
class vtkPlaneCollection;
class vtkRenderer;
class vtkVolume;

class vtkPPIRayFrameBuilder
{
public:
  /** The mapper's settings a frame depends on. */
  struct Settings
  {
    int Projection = 0; // ppiray::Projection
    double TerminationOpacity = 0.999;
    int MaximumPeels = 64;
    int MaximumSteps = 0; // 0: chosen from the number of cells
    bool CountCellSteps = false;
    bool TimePasses = false;
    bool TimeFrame = false; // the automatic stage's probe (Frame::TimeFrame)
    double ImageSampleDistance = 1.0;
    vtkPlaneCollection* ClippingPlanes = nullptr;
  };

  vtkPPIRayFrameBuilder();
  ~vtkPPIRayFrameBuilder();

  /**
   * Builds the frame of `cells` as `ren`'s camera sees them through `vol`'s
   * matrix. False (nothing to draw) when the viewport is empty. Warns through
   * `reporter` when more than 6 clipping planes are set.
   */
  bool Build(vtkRenderer* ren, vtkVolume* vol, vtkPPIRayCellBuffers& cells,
    const Settings& settings, vtkObject* reporter);

  /** The last frame built; its Section and ClippingPlanes point into this builder. */
  const vtkPPIRayDepthPeeling::Frame& GetFrame() const { return this->Frame; }

  /** The cells' local frame (mesh coordinates minus GetOrigin()) to world. */
  vtkMatrix4x4* GetLocalToWorld() const { return this->LocalToWorld; }

  /**
   * Cells one ray visits per peel at most: the setting, or
   * min(cells + 1, max(1024, 64 cbrt(cells))) when it is 0.
   */
  int GetMaximumSteps() const { return this->MaximumSteps; }

  /**
   * The level of detail of vtkUnstructuredGridVolumeRayCastMapper:
   *   d <- d sqrt(last frame's time / allocated time),
   * clamped to [minimum, max(minimum, maximum)]; d when either time is 0.
   */
  static double AdjustedSampleDistance(
    double distance, double lastTime, double allocatedTime, double minimum, double maximum);

  /**
   * The other visible volumes of `ren` rendered by a PPIRay mapper whose
   * bounds overlap `vol`'s (a prop wrapping `vol`, sharing its mapper, is
   * not another).
   */
  static int CountOverlappingVolumes(vtkRenderer* ren, vtkVolume* vol);

private:
  vtkPPIRayFrameBuilder(const vtkPPIRayFrameBuilder&) = delete;
  void operator=(const vtkPPIRayFrameBuilder&) = delete;

  // The clipping planes (at most 6) in the local frame, 4 floats each.
  void ClippingPlanesInLocalFrame(vtkPlaneCollection* planes, vtkObject* reporter);

  vtkPPIRayDepthPeeling::Frame Frame;
  vtkNew<vtkMatrix4x4> LocalToWorld;
  std::vector<float> Section;        // this frame's near-plane sections
  std::vector<float> ClippingPlanes; // this frame's clipping planes, local frame
  int ClippingPlanesWarned = 0;      // the count of planes last warned about
  int MaximumSteps = 0;
};

#endif
