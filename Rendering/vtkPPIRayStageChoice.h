/**
 * @class   vtkPPIRayStageChoice
 * @brief   MARCH_STAGE_AUTOMATIC: the march stage measured faster for the scene on screen
 *
 * Which stage marches faster depends on the GPU (a data-center part's raster
 * path is a sliver of the chip) and on the scene (the compute stage's ray
 * queue pays where few pixels have a ray; results.md, "March stages"), so
 * the choice is measured where the mapper runs: the first frames of a scene
 * alternate the stages (fragment, compute, three times each, the frame's
 * passes timed on the clock between two waits for the GPU), the first frame
 * of each only warms it up (its program built), and the stage whose best
 * frame took less time is kept.
 *
 * The same scene means the same march program, the same numbers of cells,
 * and rays marched per pixel (over a frame's passes) within a factor of two
 * of the probe's (off for SettleFrames frames in a row: a camera moving
 * closer or away, not one frame of another viewport); anything else probes
 * again. Not the target size or the points: a level of detail that changes
 * the one, or a deforming mesh the other, from frame to frame would probe
 * for ever; a probe's own frames must share their target size, else it
 * starts again. A scene that will not hold still (MaximumInterruptions
 * probes in a row cut short) keeps the stage chosen last, the fragment
 * stage if none, until the march program changes. Where the context has no
 * compute shaders, the fragment stage without a probe. No OpenGL here: the
 * mapper's march shader asks and reports. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayStageChoice_h
#define vtkPPIRayStageChoice_h

#include <array>   // for std::array
#include <cstddef> // for size_t

class vtkPPIRayStageChoice
{
public:
  /** Frames a probe takes, alternating from the fragment stage. */
  static constexpr int ProbeFrames = 6;
  /** Frames in a row with other rays per pixel that probe again. */
  static constexpr int SettleFrames = 3;
  /** Probes in a row cut short by a changing scene before the last choice is kept. */
  static constexpr int MaximumInterruptions = 3;

  /**
   * The stage (ppiray::MarchStage, never MarchAutomatic) the next frame
   * marches in; `program`: a key of the march program (a new one probes
   * again); `computeAvailable`: whether the context can run the compute
   * stage.
   */
  int Next(size_t program, bool computeAvailable);

  /** Whether the next frame is (or may start) a probe: time its passes. */
  bool Probing() const { return this->Chosen < 0; }

  /**
   * What a frame cost: the stage it ran in (ppiray::MarchStage),
   * `milliseconds` its passes took (< 0: not timed), `scene` a key of the
   * mesh (SceneKey), `raysPerPixel` the rays its march passes marched per
   * pixel of the target, `targetPixels` the target's size. A frame whose
   * scene differs from the last one's probes again from the next frame.
   */
  void Observe(
    int stage, double milliseconds, size_t scene, double raysPerPixel, long long targetPixels);

  /** The stage chosen, or -1 while probing. */
  int GetChosen() const { return this->Chosen; }

  /** The best timed frame of the last probe in `stage` (ms; < 0: none). */
  double GetProbeMilliseconds(int stage) const;

  /** A scene key: the mesh's numbers of tetrahedra and of cells marched natively. */
  static size_t SceneKey(long long tetrahedra, long long nativeCells);

  /** The stage kept after a probe: the faster; the fragment stage on a tie or without both. */
  static int Faster(double fragmentMilliseconds, double computeMilliseconds);

  /** Whether rays per pixel differ from the probe's by more than a factor of two. */
  static bool OtherRaysPerPixel(double raysPerPixel, double probed);

private:
  void Restart();
  void CountProbeFrame(int stage, double milliseconds, double raysPerPixel);
  // A probe cut short by the scene: start again, or keep the last choice.
  void Interrupt();

  int Chosen = -1; // ppiray::MarchStage, or -1 while probing
  int Frame = 0;   // of the probe
  std::array<double, 2> Best{ { -1.0, -1.0 } };
  double RaysPerPixelSum = 0.0; // over the probe's frames
  double ProbedRaysPerPixel = 0.0;
  size_t Program = 0;
  size_t Scene = 0;
  bool Seen = false; // Program and Scene hold a frame's keys
  bool ComputeAvailable = true;
  long long ProbePixels = 0; // the target size of the probe's frames
  int FramesOutside = 0;     // in a row, rays per pixel off the probe's
  int Interruptions = 0;     // probes in a row cut short
  int LastChosen = 0;        // ppiray::MarchFragment
  bool GaveUp = false;
};

#endif
