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
 * The tetrahedra's use of the one adjacency stage every cell layout shares
 * (ppiray::MatchCellFaces, ppirayCellAdjacency.h, which states the rules):
 * linear time, parallel over cells; faces shared by more than two
 * tetrahedra (zero-volume tetrahedra between two triangulations of a
 * quadrilateral, collapsed hexahedra, tangled regions) paired by the side
 * of the face their fourth point lies on; flat (zero-volume) tetrahedra
 * between the others; folded faces and the inverted side of each fold for
 * the ray caster (IsFolded(), WalksBackInPlace()). Build() again with the
 * same tetrahedra (a deforming mesh) finds only the folds again
 * (ppiray::CellAdjacencyCache; WasKept()).
 */
#ifndef vtkUnstructuredGridCellAdjacency_h
#define vtkUnstructuredGridCellAdjacency_h

#include "ppirayCellAdjacency.h" // for ppiray::CellAdjacencyCache
#include "ppirayFiltersModule.h" // for export macro
#include "vtkObject.h"

#include <vector> // for std::vector

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
   * Six times the signed volume of the tetrahedron (p0, p1, p2, p3):
   * det[p1 - p0, p2 - p0, p3 - p0].
   */
  static double SignedVolume6(
    const double p0[3], const double p1[3], const double p2[3], const double p3[3]);

  /**
   * Compute the neighbours of `numberOfTets` tetrahedra whose point ids are
   * `tets[4 * i + 0..3]`. `points` (3 doubles per point), if given, orders
   * the tetrahedra on a face shared by more than two by side and finds the
   * folded faces; `flat` (one entry per tetrahedron), if given, marks
   * zero-volume tetrahedra (they lie on neither side).
   */
  void Build(vtkIdType numberOfPoints, const vtkIdType* tets, vtkIdType numberOfTets,
    const double* points = nullptr, const unsigned char* flat = nullptr);

  /**
   * Neighbour of face f of tetrahedron t is GetNeighbors()[4 * t + f], -1 on
   * the boundary (and for left-out tetrahedra).
   */
  const std::vector<int>& GetNeighbors() const { return this->Get().Neighbors; }

  /**
   * The neighbour's local face that face f of tetrahedron t is paired with,
   * GetNeighborFaces()[4 * t + f], -1 where there is no neighbour.
   */
  const std::vector<signed char>& GetNeighborFaces() const { return this->Get().NeighborFaces; }

  /** Whether face f of tetrahedron t and its neighbour's face are folded. */
  bool IsFolded(vtkIdType t, int f) const { return this->Get().Folded[4 * t + f] != 0; }

  /**
   * Whether tetrahedron t is on the inverted side of the mesh's folds
   * (ppirayInvertedSheets.h; needs the coordinates).
   */
  bool IsInverted(vtkIdType t) const { return this->Get().Inverted[t] != 0; }

  /**
   * At a folded face from tetrahedron t into n: whether the ray walks back
   * through t (ppiray::WalksBackInPlace).
   */
  bool WalksBackInPlace(vtkIdType t, vtkIdType n) const;

  /**
   * Boundary faces as pairs (tetrahedron, local face), in tetrahedron order.
   */
  const std::vector<vtkIdType>& GetBoundaryFaces() const { return this->Get().BoundaryFaces; }

  vtkIdType GetNumberOfBoundaryFaces() const
  {
    return static_cast<vtkIdType>(this->Get().BoundaryFaces.size() / 2);
  }

  /**
   * Tetrahedron faces whose three points more than two tetrahedron faces
   * share (paired by side, see above).
   */
  vtkIdType GetNumberOfNonManifoldFaces() const { return this->Get().NumberOfNonManifoldFaces; }

  /** Folded faces: pairs of tetrahedron faces whose cells lie on one side. */
  vtkIdType GetNumberOfFoldedFaces() const { return this->Get().NumberOfFoldedFaces; }

  /** Whether the last Build() kept the faces' pairs of the one before (the same tetrahedra). */
  bool WasKept() const { return this->Cache.WasKept(); }

protected:
  vtkUnstructuredGridCellAdjacency() = default;
  ~vtkUnstructuredGridCellAdjacency() override = default;

  const ppiray::CellAdjacency& Get() const { return this->Cache.Get(); }
  ppiray::CellAdjacencyCache Cache;

private:
  vtkUnstructuredGridCellAdjacency(const vtkUnstructuredGridCellAdjacency&) = delete;
  void operator=(const vtkUnstructuredGridCellAdjacency&) = delete;
};

#endif
