#include "vtkPPIRayCellBuffers.h"

#include "ppirayConvexSurface.h"
#include "ppirayNonConformingFaces.h"

#include "vtkObject.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "cubic_fs.h"
#include "flat_cells_fs.h"
#include "gauss_legendre_fs.h"
#include "hexahedron_accurate_fs.h"
#include "hexahedron_fast_fs.h"
#include "listed_faces_fs.h"
#include "march_common_fs.h"
#include "march_fs.h"
#include "march_pixels_fs.h"
#include "projection_cubic_fs.h"
#include "stretch_fs.h"

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
  // A piece is one iteration of the search's loop, with one cell's planes
  // and a loop over its four faces; a reflex edge's search is one of those
  // per edge of the face, and the step loop's iteration that reached it.
  const Features features = this->GetFeatures();
  // A lens list names up to 2 faces across.
  const int pieces = std::max(features.MaximumSplitPieces, features.LensFaces ? 2 : 0);
  const int pieceLoops = 1 + layout.PlaneLoops + 4;
  const int reentryLoops = 1 + layout.FaceEdges * pieceLoops;
  glsl << "const int PLANE_LOOPS = " << layout.PlaneLoops << ";\n"
       << "const int FIELD_LOOPS = " << layout.FieldLoops << ";\n"
       << "const int SPLIT_PIECE_LOOPS = " << pieceLoops << ";\n"
       << "const int REENTRY_LOOPS = " << reentryLoops << ";\n"
       << "const int SPLIT_FACE = " << layout.SplitFace << ";\n"
       << "const bool SPLIT_FACES = " << (pieces > 0 ? "true" : "false") << ";\n"
       << "const int MAXIMUM_SPLIT_PIECES = " << pieces << ";\n"
       << "const int REENTRY_FACE = " << layout.ReentryFace << ";\n"
       << "const int FACE_EDGES = " << layout.FaceEdges << ";\n"
       << "const bool REENTRY_EDGES = " << (features.ReentryEdges ? "true" : "false") << ";\n"
       << "const bool LENS_FACES = " << (features.LensFaces ? "true" : "false") << ";\n"
       << "const int LENS_LIST = " << ppiray::LensList() << ";\n"
       << "const int EXIT_LOOPS = "
       << std::max(pieceLoops * pieces + 1, features.ReentryEdges ? reentryLoops : 0) << ";\n";
  const std::vector<CellArray> arrays = this->GetCellArrays();
  for (size_t i = 0; i < arrays.size(); ++i)
  {
    const bool integers = arrays[i].Type == VTK_INT;
    const char* sampler = integers ? "isamplerBuffer" : "samplerBuffer";
    glsl << "uniform " << sampler << " " << arrays[i].Name << ";\n"
         << this->Arrays[i].TexelFunction(arrays[i].Name, sampler, integers ? "ivec4" : "vec4");
  }
  return glsl.str();
}

//------------------------------------------------------------------------------
std::string vtkPPIRayCellBuffers::GetMarchShader(bool accurateCubics) const
{
  const Features features = this->GetFeatures();
  std::string march = march_fs;
  vtkShaderProgram::Substitute(march, "//PPIRay::MarchCommon::Impl", march_common_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::MarchPixels::Impl", march_pixels_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::Cells::Dec",
    this->LayoutDeclarations() +
      "const bool FLAT_CELLS = " + (features.FlatCells ? "true" : "false") +
      ";\nconst bool FOLDS = " + (features.Folds ? "true" : "false") + ";\n");
  vtkShaderProgram::Substitute(march, "//PPIRay::Cubic::Impl", cubic_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::GaussLegendre::Impl", gauss_legendre_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::MonotonicPiece::Impl",
    accurateCubics ? hexahedron_accurate_fs : hexahedron_fast_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::ProjectionCubic::Impl", projection_cubic_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::FlatCells::Impl", flat_cells_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::CellKind::Impl", this->GetCellShader());
  vtkShaderProgram::Substitute(march, "//PPIRay::Stretch::Impl", stretch_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::ListedFaces::Impl", listed_faces_fs);
  return march;
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
  this->ReportField(reporter);
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
  const size_t cells = static_cast<size_t>(this->GetNumberOfCells());
  const std::vector<CellArray> arrays = this->GetCellArrays();
  const Boundary boundary = this->GetBoundary();
  const size_t part = this->MaximumBufferTexels;
  auto failed = [&](const char* what, const vtkPPIRayBufferTexture& texture)
  {
    vtkErrorWithObjectMacro(reporter, "Could not upload " << what << " of " << cells << " "
                                                          << this->GetCellName()
                                                          << " to the GPU: " << texture.Why() << "."
                                                          << this->GetSmallerLayoutHint());
    return false;
  };
  const bool geometry = !this->GeometryOnGPU, field = !this->FieldOnGPU;
  for (size_t i = 0; i < arrays.size(); ++i)
  {
    const CellArray& a = arrays[i];
    if ((a.Field ? field : geometry) &&
        !this->Arrays[i].Upload(context, a.Data, a.Texels, a.Components, a.Type, part))
    {
      return failed(a.What, this->Arrays[i]);
    }
  }
  if (geometry)
  {
    for (size_t i = arrays.size(); i < MaximumArrays; ++i)
    {
      this->Arrays[i].ReleaseGraphicsResources(context); // another layout's
    }
    if (!this->BoundaryFaces.Upload(
          context, boundary.Faces.data(), boundary.Faces.size(), 1, VTK_INT) ||
        this->BoundaryFaces.GetNumberOfParts() > 1)
    {
      return failed("the boundary faces", this->BoundaryFaces);
    }
    if (!this->BoundaryPoints->Upload(boundary.Points, vtkOpenGLBufferObject::ArrayBuffer) ||
        !this->BoundaryTriangles->Upload(
          boundary.Triangles, vtkOpenGLBufferObject::ElementArrayBuffer))
    {
      vtkErrorWithObjectMacro(reporter, "Could not upload the boundary of "
                                          << cells << " " << this->GetCellName()
                                          << " to the GPU (out of GPU memory?)."
                                          << this->GetSmallerLayoutHint());
      return false;
    }
    this->BoundaryBytes =
      sizeof(float) * boundary.Points.size() + sizeof(unsigned int) * boundary.Triangles.size();
    this->GeometryOnGPU = true;
    ++this->GeometryUploadCount;
  }
  if (field)
  {
    this->FieldOnGPU = true;
    ++this->FieldUploadCount;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::Bind(vtkShaderProgram* program, std::vector<vtkTextureObject*>& active)
{
  const std::vector<CellArray> arrays = this->GetCellArrays();
  for (size_t i = 0; i < arrays.size(); ++i)
  {
    this->Arrays[i].Bind(program, arrays[i].Name, active);
  }
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
    const Boundary boundary = this->GetBoundary();
    this->Convex = ppiray::IsConvexSurface(
      boundary.Points, boundary.Triangles, 1e-6 * this->GetBoundingRadius());
    this->ConvexityCheckedAt = this->GeometryUploadCount;
  }
  return this->Convex;
}

//------------------------------------------------------------------------------
size_t vtkPPIRayCellBuffers::GetCellArrayBytes() const
{
  size_t bytes = 0;
  for (const vtkPPIRayBufferTexture& array : this->Arrays)
  {
    bytes += array.GetBytes();
  }
  return bytes;
}

//------------------------------------------------------------------------------
size_t vtkPPIRayCellBuffers::GetGPUBytes() const
{
  return this->BoundaryFaces.GetBytes() + this->BoundaryBytes + this->GetCellArrayBytes();
}

//------------------------------------------------------------------------------
void vtkPPIRayCellBuffers::ReleaseGraphicsResources(vtkWindow* window)
{
  for (vtkPPIRayBufferTexture& array : this->Arrays)
  {
    array.ReleaseGraphicsResources(window);
  }
  this->BoundaryFaces.ReleaseGraphicsResources(window);
  this->BoundaryPoints->ReleaseGraphicsResources();
  this->BoundaryTriangles->ReleaseGraphicsResources();
  this->BoundaryBytes = 0;
  this->GeometryOnGPU = this->FieldOnGPU = false;
}
