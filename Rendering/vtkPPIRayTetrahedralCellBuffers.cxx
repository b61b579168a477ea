#include "vtkPPIRayTetrahedralCellBuffers.h"

#include "vtkShaderProgram.h"
#include "vtkUnstructuredGrid.h"

#include "ppirayPlaneSection.h"
#include "ppirayVTKCompatibility.h"

#include "cell_tetrahedron_fs.h"
#include "tetrahedron_corners_fs.h"
#include "tetrahedron_planes_fs.h"

#include "vtkUnstructuredGridCellAdjacency.h"

#include <sstream>

namespace
{
// "3 VTK_TRIANGLE, 1 VTK_LINE" of (type, count) pairs.
std::string CellTypesMessage(const std::vector<vtkIdType>& typesAndCounts)
{
  std::ostringstream message;
  for (size_t i = 0; i < typesAndCounts.size(); i += 2)
  {
    message << (i ? ", " : "") << typesAndCounts[i + 1] << " "
            << ppiray::compat::CellClassName(static_cast<int>(typesAndCounts[i]));
  }
  return message.str();
}
}

//------------------------------------------------------------------------------
const char* vtkPPIRayTetrahedralCellBuffers::GetSmallerLayoutHint() const
{
  return this->Cells->GetLayout() == vtkTetrahedralCellTextures::PLANES
           ? " (the mapper's compact tetrahedron layout, SetTetrahedronLayoutToCompact, needs "
             "about "
             "half the memory)"
           : "";
}

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::Layout vtkPPIRayTetrahedralCellBuffers::GetLayout() const
{
  using Cells = vtkTetrahedralCellTextures;
  if (this->Cells->GetLayout() == Cells::COMPACT)
  {
    // Read: the corners' texel and 4 points, 4 planes; the field 4 more.
    return { 1, Cells::NeighborTexels(), 1, 4, Cells::TurnBack(), Cells::FlatCellMarker(),
      Cells::TransparentCellOffset(), Cells::SplitFace(), Cells::ReentryFace(), 8, 4 };
  }
  return { Cells::FacePlaneTexels(), Cells::NeighborTexels(), Cells::FieldTexels(), 4,
    Cells::TurnBack(), Cells::FlatCellMarker(), Cells::TransparentCellOffset(), Cells::SplitFace(),
    Cells::ReentryFace(), 4, 0 };
}

//------------------------------------------------------------------------------
std::vector<vtkPPIRayCellBuffers::CellArray> vtkPPIRayTetrahedralCellBuffers::GetCellArrays() const
{
  using Cells = vtkTetrahedralCellTextures;
  const auto& c = *this->Cells;
  const size_t n = static_cast<size_t>(c.GetNumberOfTetrahedra());
  const CellArray neighbors = { "neighbors", "the neighbours", c.GetNeighbors().data(),
    c.GetNeighbors().size() / 4, 4, VTK_INT, false };
  if (c.GetLayout() == Cells::COMPACT)
  {
    return { { "cellCorners", "the cell corners", c.GetCellCorners().data(), n, 4, VTK_INT, false },
      neighbors,
      { "points", "the points", c.GetPointTexels().data(), c.GetPointTexels().size() / 4, 4,
        VTK_FLOAT, true },
      { "cellValues", "the scalar field", c.GetCellValues().data(), n, 1, VTK_FLOAT, true } };
  }
  return { { "facePlanes", "the cell geometry", c.GetFacePlanes().data(),
             Cells::FacePlaneTexels() * n, 4, VTK_FLOAT, false },
    neighbors,
    { "field", "the scalar field", c.GetField().data(), Cells::FieldTexels() * n, 4, VTK_FLOAT,
      true } };
}

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::Features vtkPPIRayTetrahedralCellBuffers::GetFeatures() const
{
  Features features;
  features.FlatCells = this->Cells->GetNumberOfDegenerateTetrahedra() > 0;
  features.Folds = this->Cells->GetNumberOfFoldedFaces() > 0;
  features.MaximumSplitPieces = this->Cells->GetMaximumPiecesPerFace();
  features.ReentryEdges = this->Cells->GetNumberOfReentryFaces() > 0;
  features.LensFaces = this->Cells->GetNumberOfLensFaces() > 0;
  return features;
}

//------------------------------------------------------------------------------
std::string vtkPPIRayTetrahedralCellBuffers::GetCellShader() const
{
  std::string cells = cell_tetrahedron_fs;
  std::string declarations;
  const bool compact = this->Cells->GetLayout() == vtkTetrahedralCellTextures::COMPACT;
  if (compact)
  {
    // The corners' flags and the faces' corners, wound outward
    // (vtkUnstructuredGridCellAdjacency::FaceVertex).
    std::ostringstream corners;
    corners << "const int INVERTED_CORNERS = " << vtkTetrahedralCellTextures::InvertedCorners()
            << ";\nconst int FLAT_CORNERS = " << vtkTetrahedralCellTextures::FlatCorners()
            << ";\nconst ivec3 FACE_CORNERS[4] = ivec3[4](";
    for (int f = 0; f < 4; ++f)
    {
      corners << (f ? ", " : "") << "ivec3(" << vtkUnstructuredGridCellAdjacency::FaceVertex(f, 0)
              << ", " << vtkUnstructuredGridCellAdjacency::FaceVertex(f, 1) << ", "
              << vtkUnstructuredGridCellAdjacency::FaceVertex(f, 2) << ")";
    }
    corners << ");\n";
    declarations = corners.str();
  }
  vtkShaderProgram::Substitute(cells, "//PPIRay::TetrahedronLayout::Impl",
    declarations + (compact ? tetrahedron_corners_fs : tetrahedron_planes_fs));
  return cells;
}

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::BuildResult vtkPPIRayTetrahedralCellBuffers::BuildGeometry(
  vtkUnstructuredGrid* grid, vtkObject* reporter)
{
  this->GeometryOnGPU = this->FieldOnGPU = false;
  if (this->Cells->GetLayout() == vtkTetrahedralCellTextures::COMPACT &&
      grid->GetNumberOfPoints() > vtkTetrahedralCellTextures::InvertedCorners())
  {
    vtkErrorWithObjectMacro(reporter, "Mesh too large for the compact layout: "
                                        << grid->GetNumberOfPoints() << " points (limit "
                                        << vtkTetrahedralCellTextures::InvertedCorners() << ").");
    return BuildResult::Failed;
  }
  const bool built = this->Cells->BuildGeometry(grid);
  vtkTetrahedralCellTextures& cells = *this->Cells;
  if (cells.GetNumberOfUnsupportedCells() > 0)
  {
    vtkErrorWithObjectMacro(reporter, "Skipped "
                                        << cells.GetNumberOfUnsupportedCells()
                                        << " cells that are not 3D cells with 4 to 8 corners: "
                                        << CellTypesMessage(cells.GetUnsupportedCellTypes()));
  }
  if (cells.GetNumberOfQuadraticCells() > 0)
  {
    vtkWarningWithObjectMacro(reporter,
      << cells.GetNumberOfQuadraticCells()
      << " quadratic (or higher-order) cells are rendered through their linear corners only.");
  }
  if (!built)
  {
    vtkErrorWithObjectMacro(
      reporter, "No 3D cells to render (" << grid->GetNumberOfCells() << " cells).");
    return BuildResult::Failed;
  }
  if (cells.GetNumberOfTetrahedra() > (VTK_INT_MAX / 4) ||
      cells.GetNeighbors().size() / 4 >=
        static_cast<size_t>(vtkTetrahedralCellTextures::TurnBack()) ||
      cells.GetBoundaryFaces().size() > (1u << 24))
  {
    vtkErrorWithObjectMacro(
      reporter, "Mesh too large: " << cells.GetNumberOfTetrahedra() << " tetrahedra and "
                                   << cells.GetBoundaryFaces().size()
                                   << " boundary faces (limits 536870911 and 16777216).");
    return BuildResult::Failed;
  }
  if (cells.GetNumberOfDegenerateTetrahedra() > 0)
  {
    vtkWarningWithObjectMacro(reporter, << cells.GetNumberOfDegenerateTetrahedra()
                                        << " zero-volume tetrahedra: crossed with zero length.");
  }
  if (cells.GetNumberOfNonManifoldFaces() > 0)
  {
    vtkWarningWithObjectMacro(reporter,
      << cells.GetNumberOfNonManifoldFaces()
      << " tetrahedron faces are shared by more than two tetrahedra (non-manifold mesh): paired "
         "by side.");
  }
  this->ReportFoldedFaces(cells.GetNumberOfFoldedFaces(), reporter);
  if (cells.GetNumberOfUnlinkedFaces() > 0)
  {
    vtkWarningWithObjectMacro(reporter,
      << cells.GetNumberOfUnlinkedFaces()
      << " boundary faces of the convexified mesh could not be joined to the imaginary cells on "
         "them (not covered, or split into more than "
      << vtkTetrahedralCellTextures::MaximumPieces()
      << " pieces): rays leave the mesh there and re-enter by depth peeling.");
  }
  return BuildResult::Built;
}

//------------------------------------------------------------------------------
void vtkPPIRayTetrahedralCellBuffers::PlaneSection(
  const glm::dvec4& plane, std::vector<float>& vertices) const
{
  const vtkTetrahedralCellTextures& cells = *this->Cells;
  const std::vector<vtkIdType>& tets = cells.GetTetrahedra();
  const double* local = cells.GetLocalPoints().data();
  std::vector<glm::dvec3> triangles;
  for (vtkIdType t = 0; t < cells.GetNumberOfTetrahedra(); ++t)
  {
    if (cells.IsFlat(t))
    {
      continue; // no area to start in
    }
    glm::dvec3 p[4];
    for (int v = 0; v < 4; ++v)
    {
      const double* x = local + 3 * tets[4 * t + v];
      p[v] = glm::dvec3(x[0], x[1], x[2]);
    }
    triangles.clear();
    if (ppiray::TetrahedronSection(p, plane, triangles))
    {
      AppendSection(triangles, t, vertices);
    }
  }
}
