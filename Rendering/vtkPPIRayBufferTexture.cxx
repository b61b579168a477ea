#include "vtkPPIRayBufferTexture.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

vtkPPIRayBufferTexture::vtkPPIRayBufferTexture() = default;
vtkPPIRayBufferTexture::~vtkPPIRayBufferTexture() = default;

//------------------------------------------------------------------------------
bool vtkPPIRayBufferTexture::Upload(
  vtkOpenGLRenderWindow* context, const void* data, size_t texels, int components, int vtkType)
{
  this->ReleaseGraphicsResources(context);
  const size_t valueSize = 4; // float and int32
  const size_t bytes = texels * components * valueSize;
  if (texels == 0)
  {
    return false;
  }
  if (!this->Buffer->Upload(
        static_cast<const char*>(data), bytes, vtkOpenGLBufferObject::TextureBuffer))
  {
    return false;
  }
  this->Texture->SetContext(context);
  if (vtkType == VTK_INT)
  {
    this->Texture->SetInternalFormat(components == 4 ? GL_RGBA32I : GL_R32I);
  }
  else
  {
    this->Texture->SetInternalFormat(components == 4 ? GL_RGBA32F : GL_R32F);
  }
  if (!this->Texture->CreateTextureBuffer(
        static_cast<unsigned int>(texels * components), components, vtkType, this->Buffer))
  {
    return false;
  }
  this->Bytes = bytes;
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayBufferTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
  this->Buffer->ReleaseGraphicsResources();
  this->Bytes = 0;
}
