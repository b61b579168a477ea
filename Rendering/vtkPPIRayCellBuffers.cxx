#include "vtkPPIRayCellBuffers.h"

#include "ppirayConvexSurface.h"

#include "vtkObject.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
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
  // Listed exit faces: split boundary faces (convexified grids) and faces
  // with reflex edges; the search at one is taken from the loop budget after
  // the fact (EXIT_LOOPS, march_common_fs.glsl).
  const Features features = this->GetFeatures();
  const int pieces = features.MaximumSplitPieces;
  glsl << "const int SPLIT_FACE = " << layout.SplitFace << ";\n"
       << "const bool SPLIT_FACES = " << (pieces > 0 ? "true" : "false") << ";\n"
       << "const int MAXIMUM_SPLIT_PIECES = " << pieces << ";\n"
       << "const int REENTRY_FACE = " << layout.ReentryFace << ";\n"
       << "const bool REENTRY_EDGES = " << (features.ReentryEdges ? "true" : "false") << ";\n"
       << "const int EXIT_LOOPS = " << std::max(8 * pieces + 1, features.ReentryEdges ? 17 : 0)
       << ";\n";
  glsl << this->Geometry.TexelFunction(layout.GeometryName, "samplerBuffer", "vec4")
       << this->Neighbors.TexelFunction(layout.NeighborName, "isamplerBuffer", "ivec4")
       << this->Field.TexelFunction(layout.FieldName, "samplerBuffer", "vec4");
  return glsl.str();
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::AppendSection(
  const std::vector<glm::dvec3>& triangles, vtkIdType cell, std::vector<float>& vertices)
{
  // The entry code of a start cell (march_common_fs.glsl, enterPeel): the
  // bits 2 cell + 1 + 2^23 of a positive normal float, exact for any cell.
  const std::uint32_t bits = static_cast<std::uint32_t>(2 * cell + 1) + (1u << 23);
  float code;
  std::memcpy(&code, &bits, sizeof(code));
  for (const glm::dvec3& x : triangles)
  {
    vertices.insert(vertices.end(),
      { static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z), code });
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
  const size_t part = this->MaximumBufferTexels;
  auto failed = [&](const char* what, const vtkPPIRayBufferTexture& texture)
  {
    vtkErrorWithObjectMacro(reporter, "Could not upload "
                                        << what << " of " << cells << " " << this->GetCellName()
                                        << " to the GPU: " << texture.Why() << ".");
    return false;
  };
  if (!this->GeometryOnGPU)
  {
    if (!this->Geometry.Upload(
          context, arrays.Geometry.data(), layout.GeometryTexels * cells, 4, VTK_FLOAT, part))
    {
      return failed("the cell geometry", this->Geometry);
    }
    if (!this->Neighbors.Upload(
          context, arrays.Neighbors.data(), arrays.Neighbors.size() / 4, 4, VTK_INT, part))
    {
      return failed("the neighbours", this->Neighbors);
    }
    if (!this->BoundaryFaces.Upload(
          context, arrays.BoundaryFaces.data(), arrays.BoundaryFaces.size(), 1, VTK_INT) ||
        this->BoundaryFaces.GetNumberOfParts() > 1)
    {
      return failed("the boundary faces", this->BoundaryFaces);
    }
    if (!this->BoundaryPoints->Upload(arrays.BoundaryPoints, vtkOpenGLBufferObject::ArrayBuffer) ||
        !this->BoundaryTriangles->Upload(
          arrays.BoundaryTriangles, vtkOpenGLBufferObject::ElementArrayBuffer))
    {
      vtkErrorWithObjectMacro(reporter, "Could not upload the boundary of "
                                          << cells << " " << this->GetCellName()
                                          << " to the GPU (out of GPU memory?).");
      return false;
    }
    this->BoundaryBytes = sizeof(float) * arrays.BoundaryPoints.size() +
                          sizeof(unsigned int) * arrays.BoundaryTriangles.size();
    this->GeometryOnGPU = true;
    ++this->GeometryUploadCount;
  }
  if (!this->FieldOnGPU)
  {
    if (!this->Field.Upload(
          context, arrays.Field.data(), layout.FieldTexels * cells, 4, VTK_FLOAT, part))
    {
      return failed("the scalar field", this->Field);
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
  this->Geometry.Bind(program, layout.GeometryName, active);
  this->Neighbors.Bind(program, layout.NeighborName, active);
  this->Field.Bind(program, layout.FieldName, active);
  this->BoundaryFaces.Bind(program, "boundaryFaces", active);
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::SetMaximumBufferTexels(size_t texels)
{
  if (texels != this->MaximumBufferTexels)
  {
    this->MaximumBufferTexels = texels;
    this->GeometryOnGPU = false;
    this->FieldOnGPU = false;
  }
}

//------------------------------------------------------------------------------
bool vtkPPIRayCellBuffers::IsBoundaryConvex()
{
  if (this->ConvexityCheckedAt != this->GeometryUploadCount)
  {
    const Arrays arrays = this->GetArrays();
    this->Convex = ppiray::IsConvexSurface(
      arrays.BoundaryPoints, arrays.BoundaryTriangles, 1e-6 * this->GetBoundingRadius());
    this->ConvexityCheckedAt = this->GeometryUploadCount;
  }
  return this->Convex;
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
