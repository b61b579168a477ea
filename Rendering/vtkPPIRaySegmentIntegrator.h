/**
 * @class   vtkPPIRaySegmentIntegrator
 * @brief   one integration mode of the march: its GLSL, its textures, its uniforms
 *
 * What vtkUnstructuredGridVolumeRayIntegrator is to VTK's CPU ray caster: the
 * march hands every cell segment (s_front, s_back, length) to the shader
 * function integrateSegment() that GetShaderCode() defines; Update() makes
 * the mode's tables current (the Psi texture of PARTIAL_PRE_INTEGRATION, the
 * 3D table of FULL_PRE_INTEGRATION) and Bind() gives them to the program.
 * New() makes the integrator of a ppiray::IntegrationMode
 * (ppirayMapperModes.h). Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRaySegmentIntegrator_h
#define vtkPPIRaySegmentIntegrator_h

#include "vtkType.h" // for vtkMTimeType

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkTransferFunctionControlPoints;
class vtkWindow;

class vtkPPIRaySegmentIntegrator
{
public:
  virtual ~vtkPPIRaySegmentIntegrator() = default;

  /** The integrator of a ppiray::IntegrationMode value. */
  static std::unique_ptr<vtkPPIRaySegmentIntegrator> New(int integrationMode);
  virtual int GetIntegrationMode() const = 0;

  /** GLSL defining integrateSegment() (with the piece integral it uses). */
  virtual std::string GetShaderCode() const = 0;

  /** What the tables are built from. */
  struct Inputs
  {
    vtkTransferFunctionControlPoints* ControlPoints;
    double FieldRange[2];
    double FieldShift;
    double MaximumSegmentLength;
    vtkMTimeType SourceTime; // the latest change of the above
    int PsiTableSize;
    int PreIntegrationTableSize;
  };
  /** Makes the mode's tables current; false (reported) on failure. */
  virtual bool Update(vtkOpenGLRenderWindow*, const Inputs&, vtkObject*) { return true; }
  /** Activates the mode's textures and sets its uniforms. */
  virtual void Bind(vtkShaderProgram*, std::vector<vtkTextureObject*>&) {}

  virtual size_t GetGPUBytes() const { return 0; }
  /** Seconds the last table build took (0: no table). */
  virtual double GetTableBuildTime() const { return 0.0; }
  virtual void ReleaseGraphicsResources(vtkWindow*) {}

protected:
  vtkPPIRaySegmentIntegrator() = default;

private:
  vtkPPIRaySegmentIntegrator(const vtkPPIRaySegmentIntegrator&) = delete;
  void operator=(const vtkPPIRaySegmentIntegrator&) = delete;
};

#endif
