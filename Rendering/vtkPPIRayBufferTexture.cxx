#include "vtkPPIRayBufferTexture.h"

#include "ppirayVTKCompatibility.h"
#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include PPIRAY_VTK_OPENGL_HEADER

#include <algorithm>
#include <sstream>

struct vtkPPIRayBufferTexture::Part
{
  vtkNew<vtkOpenGLBufferObject> Buffer;
  vtkNew<vtkTextureObject> Texture;
};

vtkPPIRayBufferTexture::vtkPPIRayBufferTexture() = default;
vtkPPIRayBufferTexture::~vtkPPIRayBufferTexture() = default;

//------------------------------------------------------------------------------
size_t vtkPPIRayBufferTexture::MaximumTexels(vtkOpenGLRenderWindow*)
{
  GLint texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels);
  return texels > 0 ? static_cast<size_t>(texels) : 65536; // the GL 3.1 minimum
}

//------------------------------------------------------------------------------
bool vtkPPIRayBufferTexture::Upload(vtkOpenGLRenderWindow* context, const void* data, size_t texels,
  int components, int vtkType, size_t partTexels)
{
  this->ReleaseGraphicsResources(context);
  this->Failure.clear();
  if (texels == 0)
  {
    this->Failure = "no texels";
    return false;
  }
  const size_t limit = MaximumTexels(context);
  const size_t perPart = partTexels > 0 ? std::min(partTexels, limit) : limit;
  const size_t parts = (texels + perPart - 1) / perPart;
  if (parts > static_cast<size_t>(MaximumParts))
  {
    std::ostringstream why;
    why << texels << " texels need " << parts << " buffer textures of at most " << perPart
        << " (GL_MAX_TEXTURE_BUFFER_SIZE " << limit << "); at most " << MaximumParts << " are used";
    this->Failure = why.str();
    return false;
  }
  const size_t texelBytes = static_cast<size_t>(components) * 4; // float and int32
  while (glGetError() != GL_NO_ERROR)
  {
  }
  for (size_t p = 0; p < parts; ++p)
  {
    const size_t first = p * perPart;
    const size_t count = std::min(perPart, texels - first);
    this->Parts.emplace_back(new Part);
    Part& part = *this->Parts.back();
    const bool ok = part.Buffer->Upload(static_cast<const char*>(data) + first * texelBytes,
                      count * texelBytes, vtkOpenGLBufferObject::TextureBuffer) &&
                    glGetError() == GL_NO_ERROR;
    if (!ok)
    {
      std::ostringstream why;
      why << "the GL could not store " << count * texelBytes
          << " bytes in a buffer (out of GPU memory?)";
      this->Failure = why.str();
      this->ReleaseGraphicsResources(context);
      return false;
    }
    part.Texture->SetContext(context);
    if (vtkType == VTK_INT)
    {
      part.Texture->SetInternalFormat(components == 4 ? GL_RGBA32I : GL_R32I);
    }
    else
    {
      part.Texture->SetInternalFormat(components == 4 ? GL_RGBA32F : GL_R32F);
    }
    // Its width in texels (the count GL_MAX_TEXTURE_BUFFER_SIZE bounds, which
    // vtkTextureObject checks it against), as VTK's own mappers pass it.
    if (!part.Texture->CreateTextureBuffer(
          static_cast<unsigned int>(count), components, vtkType, part.Buffer))
    {
      this->Failure = "the GL could not make a buffer texture";
      this->ReleaseGraphicsResources(context);
      return false;
    }
  }
  this->PartTexels = perPart;
  this->Bytes = texels * texelBytes;
  return true;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkPPIRayBufferTexture::GetTexture(int part)
{
  return part < this->GetNumberOfParts() ? this->Parts[part]->Texture.GetPointer() : nullptr;
}

//------------------------------------------------------------------------------
void vtkPPIRayBufferTexture::Bind(
  vtkShaderProgram* program, const std::string& name, std::vector<vtkTextureObject*>& active)
{
  for (int p = 0; p < this->GetNumberOfParts(); ++p)
  {
    vtkTextureObject* texture = this->Parts[p]->Texture;
    texture->Activate();
    const std::string sampler = p == 0 ? name : name + std::to_string(p);
    program->SetUniformi(sampler.c_str(), texture->GetTextureUnit());
    active.push_back(texture);
  }
}

//------------------------------------------------------------------------------
std::string vtkPPIRayBufferTexture::TexelFunction(
  const std::string& name, const char* samplerType, const char* texelType) const
{
  std::ostringstream glsl;
  const int parts = std::max(1, this->GetNumberOfParts());
  for (int p = 1; p < parts; ++p)
  {
    glsl << "uniform " << samplerType << " " << name << p << ";\n";
  }
  glsl << texelType << " " << name << "Texel(int i)\n{\n";
  for (int p = parts - 1; p > 0; --p)
  {
    const size_t first = static_cast<size_t>(p) * this->PartTexels;
    glsl << "  if (i >= " << first << ")\n  {\n    return texelFetch(" << name << p << ", i - "
         << first << ");\n  }\n";
  }
  glsl << "  return texelFetch(" << name << ", i);\n}\n";
  return glsl.str();
}

//------------------------------------------------------------------------------
void vtkPPIRayBufferTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& part : this->Parts)
  {
    part->Texture->ReleaseGraphicsResources(window);
    part->Buffer->ReleaseGraphicsResources();
  }
  this->Parts.clear();
  this->PartTexels = 0;
  this->Bytes = 0;
}
