#include "vtkPPIRayHexahedralCellBuffers.h"

#include "ppirayBoundaryFaceLinks.h"
#include "vtkCellData.h"

#include "vtkShaderProgram.h"
#include "vtkUnstructuredGrid.h"

#include "ppirayPlaneSection.h"

#include "cell_linear_fs.h"
#include "hexahedron_field_fs.h"
#include "pyramid_field_fs.h"
#include "quadratic_field_fs.h"

#include "ppirayLinearCellKinds.h"

#include <algorithm>
#include <cmath>
#include <sstream>

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::Layout vtkPPIRayHexahedralCellBuffers::GetLayout() const
{
  // A face's "planes": its cell and the 6 x 2 triangles outsideFace() visits;
  // a quadrilateral has four edges across which to re-enter.
  using Cells = vtkHexahedralCellTextures;
  return { Cells::CornerTexels(), Cells::NeighborTexels(), this->Cells->GetCoefficientTexels(), 6,
    Cells::TurnBack(), 0.0f, Cells::TransparentCellOffset(), Cells::SplitFace(),
    Cells::ReentryFace(), 13, 0, 4 };
}

//------------------------------------------------------------------------------
const char* vtkPPIRayHexahedralCellBuffers::GetCellName() const
{
  const vtkHexahedralCellTextures& cells = *this->Cells;
  return cells.GetNumberOfCellsOfKind(ppiray::HEXAHEDRON_KIND) < cells.GetNumberOfHexahedra()
           ? "cells"
           : "hexahedra";
}

//------------------------------------------------------------------------------
std::vector<vtkPPIRayCellBuffers::CellArray> vtkPPIRayHexahedralCellBuffers::GetCellArrays() const
{
  using Cells = vtkHexahedralCellTextures;
  const auto& c = *this->Cells;
  const size_t n = static_cast<size_t>(c.GetNumberOfHexahedra());
  return { { "hexCorners", "the cell geometry", c.GetCorners().data(), Cells::CornerTexels() * n, 4,
             VTK_FLOAT, false },
    { "hexNeighbors", "the neighbours", c.GetNeighbors().data(), c.GetNeighbors().size() / 4, 4,
      VTK_INT, false },
    { "hexCoefficients", "the scalar field", c.GetCoefficients().data(),
      c.GetCoefficientTexels() * n, 4, VTK_FLOAT, true } };
}

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::Features vtkPPIRayHexahedralCellBuffers::GetFeatures() const
{
  Features features;
  features.FlatCells = this->Cells->GetNumberOfFlatHexahedra() > 0;
  features.Folds = this->Cells->GetNumberOfFoldedFaces() > 0;
  features.MaximumSplitPieces = this->Cells->GetMaximumPiecesPerFace();
  features.ReentryEdges = this->Cells->GetNumberOfReentryFaces() > 0;
  features.LensFaces = this->Cells->GetNumberOfLensFaces() > 0;
  return features;
}

//------------------------------------------------------------------------------
std::string vtkPPIRayHexahedralCellBuffers::GetCellShader() const
{
  // The kinds' faces, wound outward, and frames (ppirayLinearCellKinds.h).
  std::ostringstream kinds;
  kinds << "const int CELL_FACES[" << 24 * ppiray::NUMBER_OF_KINDS << "] = int[]("
        << "\n  ";
  for (int kind = 0; kind < ppiray::NUMBER_OF_KINDS; ++kind)
  {
    for (int f = 0; f < 6; ++f)
    {
      for (int v = 0; v < 4; ++v)
      {
        kinds << (kind || f || v ? ", " : "") << ppiray::LinearCellKindOf(kind).Face[f][v];
      }
    }
  }
  kinds << ");\nconst ivec3 CELL_FRAME[" << ppiray::NUMBER_OF_KINDS << "] = ivec3[](";
  for (int kind = 0; kind < ppiray::NUMBER_OF_KINDS; ++kind)
  {
    const int* frame = ppiray::LinearCellKindOf(kind).Frame;
    kinds << (kind ? ", " : "") << "ivec3(" << std::max(frame[0], 0) << ", "
          << std::max(frame[1], 0) << ", " << std::max(frame[2], 0) << ")";
  }
  const vtkHexahedralCellTextures& cells = *this->Cells;
  const bool mixed =
    cells.GetNumberOfCellsOfKind(ppiray::HEXAHEDRON_KIND) < cells.GetNumberOfHexahedra();
  kinds << ");\nconst int FLAT_KIND_BIT = " << ppiray::FLAT_KIND_BIT
        << ";\nconst bool MIXED_CELLS = " << (mixed ? "true" : "false")
        << ";\nconst bool PYRAMID_CELLS = "
        << (cells.GetNumberOfCellsOfKind(ppiray::PYRAMID_KIND) > 0 ? "true" : "false")
        << ";\nconst bool TETRAHEDRA_ONLY = "
        << (cells.GetNumberOfCellsOfKind(ppiray::TETRAHEDRON_KIND) == cells.GetNumberOfHexahedra()
               ? "true"
               : "false")
        << ";\nconst bool QUADRATIC_FIELD = " << (cells.HasQuadraticField() ? "true" : "false")
        << ";\n";
  std::string glsl = cell_linear_fs;
  vtkShaderProgram::Substitute(
    glsl, "//PPIRay::HexahedronField::Impl", kinds.str() + hexahedron_field_fs);
  vtkShaderProgram::Substitute(glsl, "//PPIRay::PyramidField::Impl", pyramid_field_fs);
  vtkShaderProgram::Substitute(glsl, "//PPIRay::QuadraticField::Impl", quadratic_field_fs);
  return glsl;
}

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::BuildResult vtkPPIRayHexahedralCellBuffers::BuildGeometry(
  vtkUnstructuredGrid* grid, vtkObject* reporter)
{
  this->GeometryOnGPU = this->FieldOnGPU = false;
  vtkHexahedralCellTextures& hexes = *this->Cells;
  hexes.BuildGeometry(grid);
  if (hexes.GetNumberOfHexahedra() == 0)
  {
    return BuildResult::Declined; // tetrahedra only, or nothing to render natively
  }
  if (hexes.GetNumberOfOtherCells() > 0 &&
      grid->GetCellData()->GetArray(ppiray::BoundaryCellArrayName))
  {
    vtkWarningWithObjectMacro(reporter,
      << "A convexified grid's imaginary cells are tetrahedra: its " << hexes.GetNumberOfHexahedra()
      << " hexahedra are split into tetrahedra too (rendered with linear pieces, not natively).");
    return BuildResult::Declined;
  }
  if (hexes.GetNumberOfOtherCells() > 0)
  {
    vtkWarningWithObjectMacro(
      reporter, << "Rendering cells without subdivision needs a mesh of hexahedra, voxels, wedges, "
                   "pyramids and tetrahedra only; "
                << hexes.GetNumberOfOtherCells() << " other cells: splitting all "
                << grid->GetNumberOfCells() << " cells into tetrahedra instead.");
    return BuildResult::Declined;
  }
  if (hexes.GetNumberOfFlatHexahedra() > 0)
  {
    vtkWarningWithObjectMacro(reporter, << hexes.GetNumberOfFlatHexahedra() << " zero-volume "
                                        << this->GetCellName() << ": crossed with zero length.");
  }
  if (hexes.GetNumberOfSingularFrames() > 0)
  {
    vtkWarningWithObjectMacro(
      reporter, << hexes.GetNumberOfSingularFrames()
                << " hexahedra have no frame at any corner (flat cells): splitting all "
                << grid->GetNumberOfCells() << " cells into tetrahedra instead.");
    return BuildResult::Declined;
  }
  if (6 * hexes.GetNumberOfHexahedra() > VTK_INT_MAX / 2 ||
      hexes.GetBoundaryFaces().size() > (1u << 24))
  {
    vtkErrorWithObjectMacro(
      reporter, "Mesh too large: " << hexes.GetNumberOfHexahedra() << " hexahedra and "
                                   << hexes.GetBoundaryFaces().size()
                                   << " boundary triangles (limits 178956970 and 16777216).");
    return BuildResult::Failed;
  }
  if (hexes.GetNumberOfQuadraticCells() > 0)
  {
    vtkWarningWithObjectMacro(reporter,
      << hexes.GetNumberOfQuadraticCells()
      << " quadratic tetrahedra have a mid-edge node so far off its edge that the cell may fold: "
         "rendered through their linear corners.");
  }
  const double deviation = hexes.GetMaximumMidEdgeDeviation();
  const int levels = hexes.GetRefinementLevels();
  if (deviation / std::pow(4.0, levels) > hexes.CurvedEdgeTolerance())
  {
    vtkWarningWithObjectMacro(reporter,
      << "Curved higher-order cells (a mid-edge node up to " << deviation
      << " of its edge's length off the midpoint) refined " << levels
      << " levels, as many as the piece limit allows: rendered with straight edges within "
      << deviation / std::pow(4.0, levels) << " of an edge.");
  }
  if (hexes.GetNumberOfNonManifoldFaces() > 0)
  {
    vtkWarningWithObjectMacro(reporter,
      << hexes.GetNumberOfNonManifoldFaces() << " cell faces lie on faces shared by more than two "
      << this->GetCellName() << " (non-manifold mesh): paired by side.");
  }
  this->ReportFoldedFaces(hexes.GetNumberOfFoldedFaces(), reporter);
  return BuildResult::Built;
}

//------------------------------------------------------------------------------
void vtkPPIRayHexahedralCellBuffers::ReportField(vtkObject* reporter) const
{
  if (this->Cells->GetNumberOfLinearizedCells() > 0)
  {
    vtkWarningWithObjectMacro(
      reporter, << this->Cells->GetNumberOfLinearizedCells()
                << " quadratic or higher-order cells have a NaN scalar at a node other than a "
                   "corner (none at a corner): rendered through their corners.");
  }
}

//------------------------------------------------------------------------------
void vtkPPIRayHexahedralCellBuffers::PlaneSection(
  const glm::dvec4& plane, std::vector<float>& vertices) const
{
  const vtkHexahedralCellTextures& cells = *this->Cells;
  const float* corners = cells.GetCorners().data();
  const int stride = 4 * vtkHexahedralCellTextures::CornerTexels();
  std::vector<glm::dvec3> triangles;
  for (vtkIdType h = 0; h < cells.GetNumberOfHexahedra(); ++h)
  {
    glm::dvec3 p[8];
    for (int v = 0; v < 8; ++v)
    {
      const float* x = corners + stride * h + 3 * v;
      p[v] = glm::dvec3(x[0], x[1], x[2]);
    }
    triangles.clear();
    if (ppiray::CellSection(cells.GetKinds()[h], p, plane, triangles))
    {
      AppendSection(triangles, h, vertices);
    }
  }
}
