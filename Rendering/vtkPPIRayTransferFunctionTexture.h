/**
 * @class   vtkPPIRayTransferFunctionTexture
 * @brief   the transfer function on the GPU: its control points as a buffer texture
 *
 * vtkTransferFunctionControlPoints of a vtkVolumeProperty (VTK's own
 * evaluation as linear pieces), stored relative to the field's shift and
 * read by glsl/transfer_function_fs.glsl. A property can be Modified()
 * without a new transfer function (ParaView touches its lookup tables while
 * rendering): only new control points count as a change. Internal to
 * PPIRay::Rendering.
 */
#ifndef vtkPPIRayTransferFunctionTexture_h
#define vtkPPIRayTransferFunctionTexture_h

#include "vtkNew.h"                           // for vtkNew
#include "vtkPPIRayBufferTexture.h"           // for vtkPPIRayBufferTexture
#include "vtkTimeStamp.h"                     // for vtkTimeStamp
#include "vtkTransferFunctionControlPoints.h" // for vtkTransferFunctionControlPoints

#include <vector> // for std::vector

class vtkObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkVolumeProperty;
class vtkWindow;

class vtkPPIRayTransferFunctionTexture
{
public:
  vtkPPIRayTransferFunctionTexture();
  ~vtkPPIRayTransferFunctionTexture();

  /**
   * Control points of `property` for a field stored minus `fieldShift`;
   * false (reported) when the property has no scalar opacity function.
   */
  bool Update(vtkVolumeProperty* property, double fieldShift, vtkObject* reporter);
  /** Uploads new control points; false (reported) on failure. */
  bool Upload(vtkOpenGLRenderWindow* context, vtkObject* reporter);
  /** Activates the texture and sets controlPoints and numberOfControlPoints. */
  void Bind(vtkShaderProgram* program, std::vector<vtkTextureObject*>& active);

  vtkTransferFunctionControlPoints* GetControlPoints() { return this->ControlPoints; }
  /** When the control points last changed. */
  vtkMTimeType GetMTime() const { return this->Time.GetMTime(); }
  int GetUploadCount() const { return this->UploadCount; }
  size_t GetGPUBytes() const { return this->Texture.GetBytes(); }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayTransferFunctionTexture(const vtkPPIRayTransferFunctionTexture&) = delete;
  void operator=(const vtkPPIRayTransferFunctionTexture&) = delete;

  vtkNew<vtkTransferFunctionControlPoints> ControlPoints;
  vtkVolumeProperty* Property = nullptr;
  vtkTimeStamp CheckTime; // when the property was last looked at
  vtkTimeStamp Time;      // when the control points last changed
  double Shift = 0.0;     // the shift Texels were made with
  std::vector<float> Texels;
  vtkPPIRayBufferTexture Texture;
  bool OnGPU = false;
  int UploadCount = 0;
};

#endif
