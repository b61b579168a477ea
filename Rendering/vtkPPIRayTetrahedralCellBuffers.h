/**
 * @class   vtkPPIRayTetrahedralCellBuffers
 * @brief   tetrahedra on the GPU: planes, neighbour codes, linear field
 *
 * vtkTetrahedralCellTextures (any mesh of 3D linear cells, split into
 * conforming tetrahedra) behind vtkPPIRayCellBuffers, marched by
 * glsl/march_fs.glsl as the cell kind glsl/cell_tetrahedron_fs.glsl, the
 * cells read as the layout says (tetrahedron_planes_fs.glsl,
 * tetrahedron_corners_fs.glsl). Internal to
 * PPIRay::Rendering.
 */
#ifndef vtkPPIRayTetrahedralCellBuffers_h
#define vtkPPIRayTetrahedralCellBuffers_h

#include "vtkPPIRayCellBuffers.h"

#include "vtkNew.h"                     // for vtkNew
#include "vtkTetrahedralCellTextures.h" // for vtkTetrahedralCellTextures

class vtkPPIRayTetrahedralCellBuffers : public vtkPPIRayCellBuffers
{
public:
  Layout GetLayout() const override;
  Features GetFeatures() const override;
  const char* GetCellName() const override { return "tetrahedra"; }
  const char* GetSmallerLayoutHint() const override;
  BuildResult BuildGeometry(vtkUnstructuredGrid* grid, vtkObject* reporter) override;
  const ppiray::StageTimes& GetGeometryStageTimes() const override
  {
    return this->Cells->GetStageTimes();
  }
  vtkObject* GetGeometryBuilder() const override { return this->Cells; }
  const double* GetOrigin() const override { return this->Cells->GetOrigin(); }
  vtkIdType GetNumberOfCells() const override { return this->Cells->GetNumberOfTetrahedra(); }
  double GetMaximumSegmentLength() const override { return this->Cells->GetMaximumEdgeLength(); }
  double GetBoundingRadius() const override { return 0.5 * this->Cells->GetLength(); }
  void PlaneSection(const glm::dvec4& plane, std::vector<float>& vertices) const override;

  /** Tetrahedra rendered with a volume (flat ones are crossed, not counted). */
  vtkIdType GetNumberOfTetrahedra() const
  {
    return this->Cells->GetNumberOfTetrahedra() - this->Cells->GetNumberOfDegenerateTetrahedra();
  }

  /**
   * The layout of the next BuildGeometry() (vtkTetrahedralCellTextures::
   * Layouts); after a successful build, GetTextures()->GetLayout() is the
   * one built (a failed build leaves the textures' counts and arrays
   * undefined, and nothing is drawn).
   */
  void SetLayout(int layout) { this->Cells->SetLayout(layout); }

  /** The cell textures behind the buffers (counts of what was built). */
  vtkTetrahedralCellTextures* GetTextures() { return this->Cells; }

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

private:
  vtkNew<vtkTetrahedralCellTextures> Cells;
};

#endif
