/**
 * @class   vtkPPIRayHexahedralCellBuffers
 * @brief   linear cells on the GPU without subdivision: corners, neighbour codes, field per kind
 *
 * vtkHexahedralCellTextures (a mesh of hexahedra, voxels, wedges, pyramids
 * and tetrahedra) behind vtkPPIRayCellBuffers, marched by glsl/march_fs.glsl
 * with the cell kind glsl/cell_linear_fs.glsl: the field along the ray a
 * cubic (hexahedron_field_fs.glsl; pyramid_field_fs.glsl) integrated as the
 * hexahedron mode says (hexahedron_accurate_fs.glsl, hexahedron_fast_fs.glsl).
 * BuildGeometry() declines a mesh with any other cell, and one whose cells
 * have no frame at any corner: those are rendered as tetrahedra. Internal to
 * PPIRay::Rendering.
 */
#ifndef vtkPPIRayHexahedralCellBuffers_h
#define vtkPPIRayHexahedralCellBuffers_h

#include "vtkPPIRayCellBuffers.h"

#include "vtkHexahedralCellTextures.h" // for vtkHexahedralCellTextures
#include "vtkNew.h"                    // for vtkNew

class vtkPPIRayHexahedralCellBuffers : public vtkPPIRayCellBuffers
{
public:
  Layout GetLayout() const override;
  Features GetFeatures() const override;
  const char* GetCellName() const override;
  BuildResult BuildGeometry(vtkUnstructuredGrid* grid, vtkObject* reporter) override;
  const ppiray::StageTimes& GetGeometryStageTimes() const override
  {
    return this->Cells->GetStageTimes();
  }
  vtkObject* GetGeometryBuilder() const override { return this->Cells; }
  const double* GetOrigin() const override { return this->Cells->GetOrigin(); }
  vtkIdType GetNumberOfCells() const override { return this->Cells->GetNumberOfHexahedra(); }
  double GetMaximumSegmentLength() const override { return this->Cells->GetMaximumCellDiameter(); }
  double GetBoundingRadius() const override { return 0.5 * this->Cells->GetLength(); }
  void PlaneSection(const glm::dvec4& plane, std::vector<float>& vertices) const override;
  /** vtkHexahedralCellTextures::SetMinimumRefinementLevel() of the next build. */
  void SetSubdivisionLevel(int level) { this->Cells->SetMinimumRefinementLevel(level); }
  /** Cells of a kind (ppiray::LinearCellKind) in the last geometry built. */
  vtkIdType GetNumberOfCellsOfKind(int kind) const
  {
    return this->Cells->GetNumberOfCellsOfKind(kind);
  }

protected:
  std::string GetCellShader() const override;
  std::vector<CellArray> GetCellArrays() const override;
  Boundary GetBoundary() const override
  {
    const auto& c = *this->Cells;
    return { c.GetBoundaryPoints(), c.GetBoundaryTriangles(), c.GetBoundaryFaces() };
  }
  vtkIdType ComputeField(vtkDataArray* values, bool cellData) override
  {
    this->Cells->BuildField(values, cellData, 0);
    return this->Cells->GetNumberOfNaNScalars();
  }
  void ReportField(vtkObject* reporter) const override;

private:
  vtkNew<vtkHexahedralCellTextures> Cells;
};

#endif
