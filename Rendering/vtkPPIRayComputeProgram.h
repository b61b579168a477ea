/**
 * @class   vtkPPIRayComputeProgram
 * @brief   a GL compute program that VTK's shader cache binds like any other
 *
 * VTK 9.2's vtkShaderProgram compiles vertex, fragment and geometry shaders
 * only. This one holds a program linked from one compute shader (GL 4.3),
 * built here, and is otherwise a vtkShaderProgram: vtkOpenGLShaderCache
 * binds and releases it, SetUniform*() set its uniforms, its
 * ReleaseGraphicsResources() deletes it. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayComputeProgram_h
#define vtkPPIRayComputeProgram_h

#include "vtkShaderProgram.h"

#include <string> // for std::string

class vtkOpenGLRenderWindow;

class vtkPPIRayComputeProgram : public vtkShaderProgram
{
public:
  static vtkPPIRayComputeProgram* New();
  vtkTypeMacro(vtkPPIRayComputeProgram, vtkShaderProgram);

  /** Whether `context` runs compute shaders (GL 4.3 or later). */
  static bool IsSupported(vtkOpenGLRenderWindow* context);

  /**
   * Compiles and links `source` (a whole compute shader, #version first) in
   * the current context; false with GetError() set when it does not build.
   */
  bool Build(const std::string& source);

  /**
   * Runs the program (bound by the shader cache) over width x height
   * invocations in work groups of groupWidth x groupHeight (its local size),
   * then makes its image stores visible to every later read (texture
   * fetches, framebuffer reads).
   */
  static void Dispatch(int width, int height, int groupWidth, int groupHeight);

protected:
  vtkPPIRayComputeProgram();
  ~vtkPPIRayComputeProgram() override;

private:
  vtkPPIRayComputeProgram(const vtkPPIRayComputeProgram&) = delete;
  void operator=(const vtkPPIRayComputeProgram&) = delete;
};

#endif
