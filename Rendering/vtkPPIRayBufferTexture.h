/**
 * @class   vtkPPIRayBufferTexture
 * @brief   one array on the GPU as buffer textures (texelFetch from a samplerBuffer)
 *
 * Owns the vtkOpenGLBufferObject(s) and the vtkTextureObject(s) viewing
 * them; used for the per-cell textures, the boundary face map and the
 * control points. An array longer than one buffer texture may be
 * (GL_MAX_TEXTURE_BUFFER_SIZE texels) is stored in consecutive parts of at
 * most that many texels, read in GLSL by the function TexelFunction()
 * writes. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayBufferTexture_h
#define vtkPPIRayBufferTexture_h

#include "vtkType.h" // for vtkIdType
#include <cstddef>   // for size_t
#include <memory>    // for std::unique_ptr
#include <string>    // for std::string
#include <vector>    // for std::vector

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkPPIRayBufferTexture
{
public:
  vtkPPIRayBufferTexture();
  ~vtkPPIRayBufferTexture();

  /** Parts an array may be split into (each takes a texture unit). */
  static constexpr int MaximumParts = 6;

  /**
   * Upload `texels` texels of `components` (1 or 4) values of `vtkType`
   * (VTK_FLOAT or VTK_INT; integers are read with an isamplerBuffer), in
   * parts of at most `partTexels` texels (0: the context's
   * GL_MAX_TEXTURE_BUFFER_SIZE). False when it needs more than
   * MaximumParts parts or the GL cannot hold it (`Why()` says which).
   */
  bool Upload(vtkOpenGLRenderWindow* context, const void* data, size_t texels, int components,
    int vtkType, size_t partTexels = 0);

  /** GL_MAX_TEXTURE_BUFFER_SIZE of `context` (texels). */
  static size_t MaximumTexels(vtkOpenGLRenderWindow* context);

  /** The reason the last Upload failed. */
  const std::string& Why() const { return this->Failure; }

  vtkTextureObject* GetTexture(int part = 0);
  int GetNumberOfParts() const { return static_cast<int>(this->Parts.size()); }
  size_t GetBytes() const { return this->Bytes; }

  /**
   * Activates every part and binds it to the sampler `name` (part 0), `name1`,
   * `name2`... (appended to `active`).
   */
  void Bind(
    vtkShaderProgram* program, const std::string& name, std::vector<vtkTextureObject*>& active);

  /**
   * GLSL: the samplers of the parts after the first (`samplerType`, e.g.
   * "samplerBuffer"; the first, `name`, is declared by the shader itself)
   * and `texelType name##Texel(int i)`, texel i of the whole array.
   */
  std::string TexelFunction(
    const std::string& name, const char* samplerType, const char* texelType) const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayBufferTexture(const vtkPPIRayBufferTexture&) = delete;
  void operator=(const vtkPPIRayBufferTexture&) = delete;

  struct Part;
  std::vector<std::unique_ptr<Part>> Parts;
  size_t PartTexels = 0; // texels of every part but the last
  size_t Bytes = 0;
  std::string Failure;
};

#endif
