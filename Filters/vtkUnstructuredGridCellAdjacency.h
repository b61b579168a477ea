/**
 * @class   vtkUnstructuredGridCellAdjacency
 * @brief   face neighbours of a tetrahedral mesh, in linear time and in parallel
 *
 * Given the four point ids of each tetrahedron, finds for every face the other
 * tetrahedron that shares its three points (or -1 on the boundary). Local face
 * f of a tetrahedron is the face opposite its vertex f, with the vertex order of
 * vtkUnstructuredGridCellAdjacency::FaceVertex (outward for a positively oriented
 * tetrahedron).
 *
 * The algorithm builds point-to-cell links with a counting sort, then for every
 * face scans the cells around the face point that has fewest of them: O(cells)
 * for bounded vertex degree, parallel over cells with OpenMP.
 *
 * Cells marked in an optional mask are left out: their faces are not matched,
 * and their neighbours see a boundary there (the mapper uses this to drop
 * zero-volume tetrahedra).
 */
#ifndef vtkUnstructuredGridCellAdjacency_h
#define vtkUnstructuredGridCellAdjacency_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <vector> // for std::vector

class vtkUnstructuredGrid;

class PPIRAYFILTERS_EXPORT vtkUnstructuredGridCellAdjacency : public vtkObject
{
public:
  static vtkUnstructuredGridCellAdjacency* New();
  vtkTypeMacro(vtkUnstructuredGridCellAdjacency, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Vertex v (0..2) of local face f (0..3) of a tetrahedron: face f is opposite
   * vertex f and is wound counter-clockwise seen from outside a positively
   * oriented tetrahedron (det[p1-p0, p2-p0, p3-p0] > 0).
   */
  static int FaceVertex(int f, int v);

  /**
   * The tetrahedra of `grid` as four point ids each (`tets`) and their cell ids
   * (`cellIds`); other cell types are counted per type in `unsupported` (pairs
   * of cell type, count), and left out.
   */
  static void ExtractTetrahedra(vtkUnstructuredGrid* grid, std::vector<vtkIdType>& tets,
    std::vector<vtkIdType>& cellIds, std::vector<vtkIdType>& unsupported);

  /**
   * Six times the signed volume of the tetrahedron (p0, p1, p2, p3):
   * det[p1 - p0, p2 - p0, p3 - p0].
   */
  static double SignedVolume6(
    const double p0[3], const double p1[3], const double p2[3], const double p3[3]);

  /**
   * Compute the neighbours of `numberOfTets` tetrahedra whose point ids are
   * `tets[4 * i + 0..3]`. `ignore`, if given, has one entry per tetrahedron;
   * non-zero entries are left out of the mesh.
   */
  void Build(vtkIdType numberOfPoints, const vtkIdType* tets, vtkIdType numberOfTets,
    const unsigned char* ignore = nullptr);

  /**
   * Neighbour of face f of tetrahedron t is GetNeighbors()[4 * t + f], -1 on
   * the boundary (and for left-out tetrahedra).
   */
  const std::vector<vtkIdType>& GetNeighbors() const { return this->Neighbors; }

  /**
   * Boundary faces as pairs (tetrahedron, local face), in tetrahedron order.
   */
  const std::vector<vtkIdType>& GetBoundaryFaces() const { return this->BoundaryFaces; }

  vtkIdType GetNumberOfBoundaryFaces() const
  {
    return static_cast<vtkIdType>(this->BoundaryFaces.size() / 2);
  }

  /**
   * Faces shared by more than two tetrahedra (a non-manifold mesh): the first
   * match is kept.
   */
  vtkGetMacro(NumberOfNonManifoldFaces, vtkIdType);

protected:
  vtkUnstructuredGridCellAdjacency() = default;
  ~vtkUnstructuredGridCellAdjacency() override = default;

  std::vector<vtkIdType> Neighbors;
  std::vector<vtkIdType> BoundaryFaces;
  vtkIdType NumberOfNonManifoldFaces = 0;

private:
  vtkUnstructuredGridCellAdjacency(const vtkUnstructuredGridCellAdjacency&) = delete;
  void operator=(const vtkUnstructuredGridCellAdjacency&) = delete;
};

#endif
