/**
 * @class   vtkUnstructuredGridBoundaryFaces
 * @brief   boundary triangles of a tetrahedral grid, wound outward
 *
 * Output: a vtkPolyData sharing the input's points, with one triangle per
 * tetrahedron face that has no neighbour, wound counter-clockwise seen from
 * outside the mesh (also for negatively oriented tetrahedra). Cell data:
 * "CellId" (the owning cell of the input) and "FaceIndex" (the local face,
 * opposite that local vertex). Non-tetrahedral cells are ignored with a
 * warning. Adjacency is found by vtkUnstructuredGridCellAdjacency.
 */
#ifndef vtkUnstructuredGridBoundaryFaces_h
#define vtkUnstructuredGridBoundaryFaces_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class PPIRAYFILTERS_EXPORT vtkUnstructuredGridBoundaryFaces : public vtkPolyDataAlgorithm
{
public:
  static vtkUnstructuredGridBoundaryFaces* New();
  vtkTypeMacro(vtkUnstructuredGridBoundaryFaces, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkUnstructuredGridBoundaryFaces() = default;
  ~vtkUnstructuredGridBoundaryFaces() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkUnstructuredGridBoundaryFaces(const vtkUnstructuredGridBoundaryFaces&) = delete;
  void operator=(const vtkUnstructuredGridBoundaryFaces&) = delete;
};

#endif
