/**
 * @class   vtkPPIRayBufferTexture
 * @brief   one array on the GPU as a buffer texture (texelFetch from a samplerBuffer)
 *
 * Owns a vtkOpenGLBufferObject and the vtkTextureObject viewing it; used for
 * the per-cell textures, the boundary face map and the control points.
 * Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayBufferTexture_h
#define vtkPPIRayBufferTexture_h

#include "vtkNew.h"  // for vtkNew
#include "vtkType.h" // for vtkIdType
#include <cstddef>   // for size_t

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkPPIRayBufferTexture
{
public:
  vtkPPIRayBufferTexture();
  ~vtkPPIRayBufferTexture();

  /**
   * Upload `texels` texels of `components` (1 or 4) values of `vtkType`
   * (VTK_FLOAT or VTK_INT; integers are read with an isamplerBuffer).
   */
  bool Upload(
    vtkOpenGLRenderWindow* context, const void* data, size_t texels, int components, int vtkType);

  vtkTextureObject* GetTexture() { return this->Texture; }
  size_t GetBytes() const { return this->Bytes; }
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayBufferTexture(const vtkPPIRayBufferTexture&) = delete;
  void operator=(const vtkPPIRayBufferTexture&) = delete;

  vtkNew<vtkOpenGLBufferObject> Buffer;
  vtkNew<vtkTextureObject> Texture;
  size_t Bytes = 0;
};

#endif
