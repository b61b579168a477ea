#include "vtkPPIRayCellBuffers.h"

#include "vtkObject.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <iomanip>
#include <sstream>

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::vtkPPIRayCellBuffers() = default;

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::~vtkPPIRayCellBuffers() = default;

//------------------------------------------------------------------------------
std::string vtkPPIRayCellBuffers::LayoutDeclarations() const
{
  const Layout layout = this->GetLayout();
  std::ostringstream glsl;
  glsl << std::setprecision(9) << std::scientific;
  glsl << "const int GEOMETRY_TEXELS = " << layout.GeometryTexels << ";\n"
       << "const int NEIGHBOR_TEXELS = " << layout.NeighborTexels << ";\n"
       << "const int FIELD_TEXELS = " << layout.FieldTexels << ";\n"
       << "const int FACES = " << layout.Faces << ";\n"
       << "const int TURN_BACK = " << layout.TurnBack
       << ";\n"
       // Markers are compared against half their value: no real value comes near.
       << "const float FLAT_CELL = " << 0.5 * layout.FlatCellMarker << ";\n"
       << "const float EMPTY_CELL = " << 0.5 * layout.EmptyCellOffset << ";\n";
  return glsl.str();
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::AppendSection(
  const std::vector<glm::dvec3>& triangles, vtkIdType cell, std::vector<float>& vertices)
{
  for (const glm::dvec3& x : triangles)
  {
    vertices.insert(vertices.end(), { static_cast<float>(x.x), static_cast<float>(x.y),
                                      static_cast<float>(x.z), static_cast<float>(cell) });
  }
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::BuildField(vtkDataArray* values, bool cellData, vtkObject* reporter)
{
  this->FieldOnGPU = false;
  const vtkIdType empty = this->ComputeField(values, cellData);
  if (empty > 0)
  {
    vtkWarningWithObjectMacro(reporter,
      << empty << " " << this->GetCellName() << " have NaN scalars; they are rendered empty.");
  }
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::ReportFoldedFaces(vtkIdType folded, vtkObject* reporter) const
{
  if (folded > 0)
  {
    vtkWarningWithObjectMacro(
      reporter, << folded << " faces join two " << this->GetCellName()
                << " on the same side (inverted cells, a tangled mesh): each stretch of a ray is "
                   "integrated once.");
  }
}

//------------------------------------------------------------------------------
bool vtkPPIRayCellBuffers::Upload(vtkOpenGLRenderWindow* context, vtkObject* reporter)
{
  const Layout layout = this->GetLayout();
  const size_t cells = static_cast<size_t>(this->GetNumberOfCells());
  const Arrays arrays = this->GetArrays();
  if (!this->GeometryOnGPU)
  {
    const bool ok =
      this->Geometry.Upload(
        context, arrays.Geometry.data(), layout.GeometryTexels * cells, 4, VTK_FLOAT) &&
      this->Neighbors.Upload(
        context, arrays.Neighbors.data(), layout.NeighborTexels * cells, 4, VTK_INT) &&
      this->BoundaryFaces.Upload(
        context, arrays.BoundaryFaces.data(), arrays.BoundaryFaces.size(), 1, VTK_INT) &&
      this->BoundaryPoints->Upload(arrays.BoundaryPoints, vtkOpenGLBufferObject::ArrayBuffer) &&
      this->BoundaryTriangles->Upload(
        arrays.BoundaryTriangles, vtkOpenGLBufferObject::ElementArrayBuffer);
    if (!ok)
    {
      vtkErrorWithObjectMacro(reporter,
        "Could not upload the mesh to the GPU (" << cells << " " << this->GetCellName() << ").");
      return false;
    }
    this->BoundaryBytes = sizeof(float) * arrays.BoundaryPoints.size() +
                          sizeof(unsigned int) * arrays.BoundaryTriangles.size();
    this->GeometryOnGPU = true;
    ++this->GeometryUploadCount;
  }
  if (!this->FieldOnGPU)
  {
    if (!this->Field.Upload(context, arrays.Field.data(), layout.FieldTexels * cells, 4, VTK_FLOAT))
    {
      vtkErrorWithObjectMacro(reporter, "Could not upload the scalar field to the GPU.");
      return false;
    }
    this->FieldOnGPU = true;
    ++this->FieldUploadCount;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::Bind(vtkShaderProgram* program, std::vector<vtkTextureObject*>& active)
{
  const Layout layout = this->GetLayout();
  const std::pair<vtkPPIRayBufferTexture*, const char*> textures[] = {
    { &this->Geometry, layout.GeometryName }, { &this->Neighbors, layout.NeighborName },
    { &this->Field, layout.FieldName }, { &this->BoundaryFaces, "boundaryFaces" }
  };
  for (const auto& texture : textures)
  {
    texture.first->GetTexture()->Activate();
    program->SetUniformi(texture.second, texture.first->GetTexture()->GetTextureUnit());
    active.push_back(texture.first->GetTexture());
  }
}

//------------------------------------------------------------------------------
size_t vtkPPIRayCellBuffers::GetGPUBytes() const
{
  return this->Geometry.GetBytes() + this->Neighbors.GetBytes() + this->Field.GetBytes() +
         this->BoundaryFaces.GetBytes() + this->BoundaryBytes;
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Geometry.ReleaseGraphicsResources(window);
  this->Neighbors.ReleaseGraphicsResources(window);
  this->Field.ReleaseGraphicsResources(window);
  this->BoundaryFaces.ReleaseGraphicsResources(window);
  this->BoundaryPoints->ReleaseGraphicsResources();
  this->BoundaryTriangles->ReleaseGraphicsResources();
  this->BoundaryBytes = 0;
  this->GeometryOnGPU = this->FieldOnGPU = false;
}
