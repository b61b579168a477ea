/**
 * @class   vtkPPIRayMarchShader
 * @brief   the march program: a traversal, an integration mode, isosurfaces, composed
 *
 * As VTK's vtkVolumeShaderComposer: the march pass's fragment shader is the
 * traversal of the cells (vtkPPIRayCellBuffers::GetMarchShader(), with its
 * layout), with the transfer function lookup, the isosurfaces, the
 * projection (BLEND, a ppiray::Projection: 0 composite, 1 maximum,
 * 2 minimum, 3 average intensity, 4 additive), the
 * integration mode's segment integral (vtkPPIRaySegmentIntegrator) and the
 * viewing ray substituted at their //PPIRay:: markers. The program is
 * rebuilt only when the composed source changes. Internal to
 * PPIRay::Rendering.
 */
#ifndef vtkPPIRayMarchShader_h
#define vtkPPIRayMarchShader_h

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkWindow;

class vtkPPIRayMarchShader
{
public:
  vtkPPIRayMarchShader();
  ~vtkPPIRayMarchShader();

  /** The fragment shader of `traversal` with the other parts substituted. */
  static std::string Compose(const std::string& traversal, const std::string& integration,
    const std::string& isoSurfaces, int blend);

  /**
   * The program of the composed shader, ready to use; null (reported) when
   * it does not build.
   */
  vtkOpenGLQuadHelper* Ready(vtkOpenGLRenderWindow* context, const std::string& traversal,
    const std::string& integration, const std::string& isoSurfaces, int blend, vtkObject* reporter);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayMarchShader(const vtkPPIRayMarchShader&) = delete;
  void operator=(const vtkPPIRayMarchShader&) = delete;

  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string Source; // what Quad was built from
};

#endif
