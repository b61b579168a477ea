/**
 * @class   vtkPPIRayPassTimes
 * @brief   where a frame's time goes: GPU time per kind of pass, and their counts
 *
 * Each pass of a frame (vtkPPIRayDepthPeeling) is bracketed by GL timestamp
 * queries (vtkOpenGLRenderTimer, ARB_timer_query) when timing is on; the
 * results are read at the end of the frame (which waits for the GPU) and
 * summed per kind. Off, nothing is issued. Internal to PPIRay::Rendering;
 * the mapper reports it (vtkUnstructuredGridGPURayCastMapper::TimePasses).
 */
#ifndef vtkPPIRayPassTimes_h
#define vtkPPIRayPassTimes_h

#include <array>  // for std::array
#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

class vtkOpenGLRenderTimer;

class vtkPPIRayPassTimes
{
public:
  /** Kinds of pass; the mapper's PassKinds have the same values. */
  enum Pass
  {
    Setup = 0,             // opaque depth copied, targets cleared
    NearPlaneEntry = 1,    // the near plane's sections rasterized
    Entry = 2,             // a layer of boundary triangles rasterized, with its query
    March = 3,             // a march (full-screen)
    ContinuationCheck = 4, // whether a march left rays unfinished, with its query
    Composite = 5,         // the result over VTK's framebuffer
    NumberOfPasses = 6
  };

  vtkPPIRayPassTimes();
  ~vtkPPIRayPassTimes();

  /** Starts a frame: forgets the last one's timings; timing on or off. */
  void StartFrame(bool enabled);

  /** Starts timing a pass of kind `pass` (ends the one running, if any). */
  void Start(Pass pass);

  /** Ends the pass running, if any. */
  void Stop();

  /**
   * Ends the frame: waits for the GPU (glFinish) and sums the queries per
   * kind. Returns false if timing was off, the GL has no timer queries or a
   * result was still missing (left out of the sums).
   */
  bool EndFrame();

  /** Milliseconds of GPU time the last frame spent in passes of `pass`. */
  double GetMilliseconds(int pass) const;

  /** How many passes of that kind the last frame drew. */
  int GetCount(int pass) const;

  static const char* GetName(int pass);

  /** Deletes the queries (in the current context). */
  void ReleaseGraphicsResources();

private:
  vtkPPIRayPassTimes(const vtkPPIRayPassTimes&) = delete;
  void operator=(const vtkPPIRayPassTimes&) = delete;

  bool Enabled = false;
  int Running = -1; // the timer of the pass being timed, or -1
  std::vector<std::unique_ptr<vtkOpenGLRenderTimer>> Timers; // reused frame to frame
  std::vector<Pass> Kinds;                                   // of Timers[0, Used)
  size_t Used = 0;
  std::array<double, NumberOfPasses> Milliseconds{};
  std::array<int, NumberOfPasses> Counts{};
};

#endif
