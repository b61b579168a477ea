#include "vtkPPIRayTetrahedralCellBuffers.h"

#include "vtkShaderProgram.h"
#include "vtkUnstructuredGrid.h"

#include "ppirayPlaneSection.h"
#include "ppirayVTKCompatibility.h"

#include "march_common_fs.h"
#include "march_fs.h"

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
vtkPPIRayCellBuffers::Layout vtkPPIRayTetrahedralCellBuffers::GetLayout() const
{
  using Cells = vtkTetrahedralCellTextures;
  return { "facePlanes", Cells::FacePlaneTexels(), "neighbors", Cells::NeighborTexels(), "field",
    Cells::FieldTexels(), 4, Cells::TurnBack(), Cells::FlatCellMarker(),
    Cells::TransparentCellOffset(), Cells::SplitFace(), Cells::ReentryFace() };
}

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::Features vtkPPIRayTetrahedralCellBuffers::GetFeatures() const
{
  Features features;
  features.FlatCells = this->Cells->GetNumberOfDegenerateTetrahedra() > 0;
  features.Folds = this->Cells->GetNumberOfFoldedFaces() > 0;
  features.MaximumSplitPieces = this->Cells->GetMaximumPiecesPerFace();
  features.ReentryEdges = this->Cells->GetNumberOfReentryFaces() > 0;
  return features;
}

//------------------------------------------------------------------------------
std::string vtkPPIRayTetrahedralCellBuffers::GetMarchShader(int) const
{
  std::string march = march_fs;
  vtkShaderProgram::Substitute(march, "//PPIRay::MarchCommon::Impl", march_common_fs);
  const Features features = this->GetFeatures();
  vtkShaderProgram::Substitute(march, "//PPIRay::Cells::Dec",
    this->LayoutDeclarations() +
      "const bool FLAT_CELLS = " + (features.FlatCells ? "true" : "false") +
      ";\nconst bool FOLDS = " + (features.Folds ? "true" : "false") + ";");
  return march;
}

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::BuildResult vtkPPIRayTetrahedralCellBuffers::BuildGeometry(
  vtkUnstructuredGrid* grid, vtkObject* reporter)
{
  this->GeometryOnGPU = this->FieldOnGPU = false;
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
