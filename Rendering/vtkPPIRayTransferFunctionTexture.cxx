#include "vtkPPIRayTransferFunctionTexture.h"

#include "vtkObject.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolumeProperty.h"

//------------------------------------------------------------------------------
vtkPPIRayTransferFunctionTexture::vtkPPIRayTransferFunctionTexture() = default;

//------------------------------------------------------------------------------
vtkPPIRayTransferFunctionTexture::~vtkPPIRayTransferFunctionTexture() = default;

//------------------------------------------------------------------------------
bool vtkPPIRayTransferFunctionTexture::Update(
  vtkVolumeProperty* property, double fieldShift, vtkObject* reporter)
{
  const bool unchanged =
    this->Property == property && property->GetMTime() <= this->CheckTime.GetMTime();
  if (unchanged && this->Shift == fieldShift)
  {
    return this->ControlPoints->GetNumberOfControlPoints() > 0;
  }
  if (unchanged && this->ControlPoints->GetNumberOfControlPoints() > 0)
  {
    // Only the field's shift moved: the same control points, texels anew.
    this->Shift = fieldShift;
    this->Texels = this->ControlPoints->GetTexels(fieldShift);
    this->Time.Modified();
    this->OnGPU = false;
    return true;
  }
  this->Property = property;
  this->CheckTime.Modified();
  if (!this->ControlPoints->Build(property, 0))
  {
    this->Texels.clear();
    this->Time.Modified();
    this->OnGPU = false;
    vtkErrorWithObjectMacro(reporter, "The volume property has no scalar opacity function.");
    return false;
  }
  this->Shift = fieldShift;
  std::vector<float> texels = this->ControlPoints->GetTexels(fieldShift);
  if (texels != this->Texels)
  {
    this->Texels = std::move(texels);
    this->Time.Modified();
    this->OnGPU = false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkPPIRayTransferFunctionTexture::Upload(vtkOpenGLRenderWindow* context, vtkObject* reporter)
{
  if (this->OnGPU)
  {
    return true;
  }
  if (!this->Texture.Upload(context, this->Texels.data(), this->Texels.size() / 4, 4, VTK_FLOAT))
  {
    vtkErrorWithObjectMacro(reporter, "Could not upload the transfer function to the GPU.");
    return false;
  }
  this->OnGPU = true;
  ++this->UploadCount;
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayTransferFunctionTexture::Bind(
  vtkShaderProgram* program, std::vector<vtkTextureObject*>& active)
{
  vtkTextureObject* texture = this->Texture.GetTexture();
  texture->Activate();
  program->SetUniformi("controlPoints", texture->GetTextureUnit());
  program->SetUniformi("numberOfControlPoints", this->ControlPoints->GetNumberOfControlPoints());
  active.push_back(texture);
}

//------------------------------------------------------------------------------
void vtkPPIRayTransferFunctionTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Texture.ReleaseGraphicsResources(window);
  this->OnGPU = false;
}
