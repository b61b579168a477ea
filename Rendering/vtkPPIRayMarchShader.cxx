#include "vtkPPIRayMarchShader.h"

#include "vtkObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"

#include "isosurface_fs.h"
#include "projection_fs.h"
#include "ray_fs.h"
#include "transfer_function_fs.h"

//------------------------------------------------------------------------------
vtkPPIRayMarchShader::vtkPPIRayMarchShader() = default;

//------------------------------------------------------------------------------
vtkPPIRayMarchShader::~vtkPPIRayMarchShader() = default;

//------------------------------------------------------------------------------
std::string vtkPPIRayMarchShader::Compose(const std::string& traversal,
  const std::string& integration, const std::string& isoSurfaces, int blend)
{
  std::string march = traversal;
  vtkShaderProgram::Substitute(march, "//PPIRay::TransferFunction::Impl", transfer_function_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::IsoSurface::Impl", isosurface_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::IsoSurface::Dec", isoSurfaces);
  vtkShaderProgram::Substitute(march, "//PPIRay::Projection::Impl", projection_fs);
  vtkShaderProgram::Substitute(
    march, "//PPIRay::Blend::Dec", "const int BLEND = " + std::to_string(blend) + ";");
  vtkShaderProgram::Substitute(march, "//PPIRay::Integrate::Impl", integration);
  vtkShaderProgram::Substitute(march, "//PPIRay::Ray::Impl", ray_fs);
  return march;
}

//------------------------------------------------------------------------------
vtkOpenGLQuadHelper* vtkPPIRayMarchShader::Ready(vtkOpenGLRenderWindow* context,
  const std::string& traversal, const std::string& integration, const std::string& isoSurfaces,
  int blend, vtkObject* reporter)
{
  std::string source = Compose(traversal, integration, isoSurfaces, blend);
  if (this->Quad && source == this->Source && !this->Quad->Program)
  {
    return nullptr; // reported when it was built
  }
  if (!this->Quad || source != this->Source)
  {
    if (this->Quad)
    {
      this->Quad->ReleaseGraphicsResources(context);
    }
    this->Quad.reset(new vtkOpenGLQuadHelper(context, nullptr, source.c_str(), ""));
    this->Source = std::move(source);
  }
  else
  {
    context->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program)
  {
    vtkErrorWithObjectMacro(reporter, "Could not build the march shader.");
    return nullptr;
  }
  return this->Quad.get();
}

//------------------------------------------------------------------------------
void vtkPPIRayMarchShader::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  this->Source.clear();
}
