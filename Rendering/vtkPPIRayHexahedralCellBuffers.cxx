#include "vtkPPIRayHexahedralCellBuffers.h"

#include "ppirayBoundaryFaceLinks.h"
#include "vtkCellData.h"

#include "vtkShaderProgram.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include "ppirayPlaneSection.h"

#include "gauss_legendre_fs.h"
#include "hexahedron_accurate_fs.h"
#include "hexahedron_fast_fs.h"
#include "hexahedron_field_fs.h"
#include "march_common_fs.h"
#include "march_hexahedra_fs.h"
#include "projection_cubic_fs.h"

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::Layout vtkPPIRayHexahedralCellBuffers::GetLayout() const
{
  using Cells = vtkHexahedralCellTextures;
  return { Cells::CornerTexels(), Cells::NeighborTexels(), Cells::CoefficientTexels(), 6,
    Cells::TurnBack(), 0.0f, Cells::TransparentCellOffset() };
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
      Cells::CoefficientTexels() * n, 4, VTK_FLOAT, true } };
}

//------------------------------------------------------------------------------
vtkPPIRayCellBuffers::Features vtkPPIRayHexahedralCellBuffers::GetFeatures() const
{
  Features features;
  features.Folds = this->Cells->GetNumberOfFoldedFaces() > 0;
  return features;
}

//------------------------------------------------------------------------------
std::string vtkPPIRayHexahedralCellBuffers::GetMarchShader(int hexahedronMode) const
{
  std::string march = march_hexahedra_fs;
  vtkShaderProgram::Substitute(march, "//PPIRay::HexahedronField::Impl", hexahedron_field_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::Hexahedron::Impl",
    hexahedronMode == vtkUnstructuredGridGPURayCastMapper::HEXAHEDRON_ACCURATE
      ? hexahedron_accurate_fs
      : hexahedron_fast_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::GaussLegendre::Impl", gauss_legendre_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::ProjectionCubic::Impl", projection_cubic_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::MarchCommon::Impl", march_common_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::Cells::Dec",
    this->LayoutDeclarations() + "const bool FLAT_CELLS = false;\nconst bool FOLDS = " +
      (this->GetFeatures().Folds ? "true" : "false") + ";");
  return march;
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
    return BuildResult::Declined;
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
      reporter, << "Rendering hexahedra without subdivision needs a mesh of hexahedra only; "
                << hexes.GetNumberOfOtherCells() << " other cells: splitting all "
                << grid->GetNumberOfCells() << " cells into tetrahedra instead.");
    return BuildResult::Declined;
  }
  if (hexes.GetNumberOfFlatHexahedra() > 0)
  {
    vtkWarningWithObjectMacro(
      reporter, << hexes.GetNumberOfFlatHexahedra() << " zero-volume hexahedra skipped.");
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
      << " quadratic (or higher-order) hexahedra are rendered through their linear corners "
         "only.");
  }
  if (hexes.GetNumberOfNonManifoldFaces() > 0)
  {
    vtkWarningWithObjectMacro(
      reporter, << hexes.GetNumberOfNonManifoldFaces()
                << " faces are shared by more than two hexahedra (non-manifold mesh).");
  }
  this->ReportFoldedFaces(hexes.GetNumberOfFoldedFaces(), reporter);
  return BuildResult::Built;
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
    if (ppiray::HexahedronSection(p, plane, triangles))
    {
      AppendSection(triangles, h, vertices);
    }
  }
}
