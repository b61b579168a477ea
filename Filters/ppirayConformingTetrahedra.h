/**
 * @file   ppirayConformingTetrahedra.h
 * @brief  linear 3D cells split into tetrahedra that conform across shared faces
 *
 * Every quadrilateral face is split along the diagonal through its smallest
 * global point id, so the two cells that share a face split it the same way
 * and the tetrahedra of a mixed mesh (tetrahedra, hexahedra, voxels, wedges,
 * pyramids) meet face to face: the traversal stays watertight even where a
 * quadrilateral is not planar.
 *
 * A cell is split as a cone from its smallest point v: one tetrahedron (v, T)
 * for every triangle T of the faces that do not contain v (Dompierre et al.,
 * "How to subdivide pyramids, prisms and hexahedra into tetrahedra", 1999,
 * use the same smallest-index rule). The faces that contain v are fanned from
 * v, which is their smallest point too, so every face follows the rule.
 * Counts: hexahedron and voxel 6, wedge 3, pyramid 2. The cone is exact for
 * cells that are star-shaped from v (every convex cell). Collapsed hexahedra
 * (repeated corner ids) follow QuadDiagonals, and the cone runs over the
 * triangles that miss v's point id. A cell whose cone has tetrahedra of both
 * signs (not star-shaped from v: strongly warped cells) takes the first
 * corner by id whose cone has one sign. The
 * field becomes linear in each tetrahedron (the subdivision error hexahedra
 * rendered natively avoid).
 *
 * Quadratic and higher-order cells are split through their linear corners.
 */
#ifndef ppirayConformingTetrahedra_h
#define ppirayConformingTetrahedra_h

#include "ppirayFiltersModule.h"  // for export macro
#include "ppirayPolyhedra.h"      // for ppiray::AddedPoints
#include "vtkCellArray.h"         // for ForEachCell
#include "vtkCellArrayIterator.h" // for ForEachCell
#include "vtkCellType.h"          // for VTK_VOXEL
#include "vtkSmartPointer.h"      // for ForEachCell
#include "vtkType.h"
#include "vtkUnstructuredGrid.h" // for ForEachCell

#include <array>  // for std::array
#include <map>    // for std::map
#include <vector> // for std::vector

namespace ppiray
{
/**
 * visit(cellId, cellType, npts, pts) for every cell of `grid`, in order;
 * empty cells (VTK_EMPTY_CELL: nothing to draw) are passed over.
 */
template<typename Visit>
void ForEachCell(vtkUnstructuredGrid* grid, Visit&& visit)
{
  vtkCellArray* cells = grid ? grid->GetCells() : nullptr;
  if (!cells)
  {
    return;
  }
  auto iter = vtk::TakeSmartPointer(cells->NewIterator());
  vtkIdType cellId = 0;
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell(), ++cellId)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    iter->GetCurrentCell(npts, pts);
    const int type = grid->GetCellType(cellId);
    if (type != VTK_EMPTY_CELL)
    {
      visit(cellId, type, npts, pts);
    }
  }
}

/** The linear cell a cell type is rendered as. */
struct LinearShape
{
  int Type;         // VTK_TETRA, VTK_HEXAHEDRON (also for voxels), VTK_WEDGE, VTK_PYRAMID; 0: none
  int Corners;      // its number of corners: the first points of the cell
  bool HigherOrder; // the corners of a quadratic (or higher-order) cell
};

/** LinearShape of a VTK cell type ({0, 0, false} for cells not rendered). */
PPIRAYFILTERS_EXPORT LinearShape LinearShapeOf(int cellType);

/** Position in a cell's point list of corner i in VTK_HEXAHEDRON order (voxels differ). */
inline int HexahedronCorner(int cellType, int i)
{
  static const int voxel[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
  return cellType == VTK_VOXEL ? voxel[i] : i;
}

/** What SplitIntoTetrahedra found, per kind of input cell. */
struct TetrahedralSplit
{
  std::vector<vtkIdType> Tets;      // 4 point ids per tetrahedron
  std::vector<vtkIdType> CellIds;   // input cell of each tetrahedron
  AddedPoints Added;                // points the polyhedra's split adds (ids after the grid's)
  vtkIdType NumberOfSplitCells = 0; // hexahedra, voxels, wedges, pyramids, polyhedra
  vtkIdType NumberOfPolyhedra = 0;
  vtkIdType NumberOfQuadraticCells = 0; // rendered through their linear corners
  std::vector<vtkIdType> Unsupported;   // pairs (cell type, count), left out
  vtkIdType GetNumberOfUnsupportedCells() const;
};

/**
 * The tetrahedra of `grid` as four point ids each (`tets`) and their cell ids
 * (`cellIds`); other cell types are counted per type in `unsupported` (pairs
 * of cell type, count), and left out (SplitIntoTetrahedra, tetrahedra only).
 */
PPIRAYFILTERS_EXPORT void ExtractTetrahedra(vtkUnstructuredGrid* grid, std::vector<vtkIdType>& tets,
  std::vector<vtkIdType>& cellIds, std::vector<vtkIdType>& unsupported);

/**
 * The tetrahedra of `grid`: its tetrahedra as they are and, unless
 * `tetrahedraOnly`, the conforming split of its hexahedra, voxels, wedges and
 * pyramids (linear or not) and its polyhedra (ppirayPolyhedra.h: with points
 * added). Other cells are counted in Unsupported. `split` is cleared first,
 * its vectors' storage kept (a rebuild passes the last one's in).
 */
PPIRAYFILTERS_EXPORT void SplitIntoTetrahedra(
  vtkUnstructuredGrid* grid, bool tetrahedraOnly, TetrahedralSplit& split);

/**
 * The cone split of a linear cell of `kind` (ppiray::LinearCellKind) with
 * distinct corner ids `pts` (in VTK's order for the kind) from its smallest
 * corner, quadrilaterals along the diagonal through their smallest id: 4
 * corner indices (into pts) per tetrahedron appended to `tets`.
 */
PPIRAYFILTERS_EXPORT void AppendConeSplit(int kind, const vtkIdType* pts, std::vector<int>& tets);

/**
 * The diagonal rule: true if quadrilateral (a, b, c, d) is split along a-c,
 * false if along b-d; the diagonal through the smallest of the four ids.
 */
inline bool SplitsAlongFirstDiagonal(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d)
{
  return (a < c ? a : c) < (b < d ? b : d);
}

/**
 * Corner (0..3) of quadrilateral (q0, q1, q2, q3) that is corner v (0..2) of
 * its triangle t (0, 1): along q0-q2 the triangles are (q0, q1, q2),
 * (q0, q2, q3); along q1-q3 they are (q1, q2, q3), (q1, q3, q0). Both keep
 * the quadrilateral's winding.
 */
inline int QuadTriangleCorner(int t, int v, bool secondDiagonal)
{
  static const int first[2][3] = { { 0, 1, 2 }, { 0, 2, 3 } };
  static const int second[2][3] = { { 1, 2, 3 }, { 1, 3, 0 } };
  return secondDiagonal ? second[t][v] : first[t][v];
}

/**
 * The diagonals of a mesh's quadrilaterals: SplitsAlongFirstDiagonal, except
 * on faces of collapsed hexahedra (repeated corner ids) where that split puts
 * a triangle's three corners all on another face of the cell. Such a triangle
 * folds onto the other face and the cell's triangles enclose only part of
 * it: a pyramid written as a hexahedron (4, 5, 6 on 0, 1, 2) whose slanted
 * face (0, 1, 2, 7) is split along 0-2 loses the tetrahedron (0, 1, 2, 7).
 * Such a face is split along its other diagonal, in every cell that has it
 * (the exception is keyed by the face's point ids).
 */
class PPIRAYFILTERS_EXPORT QuadDiagonals
{
public:
  /** The exceptions of the hexahedra and voxels of `grid`. */
  void Build(vtkUnstructuredGrid* grid);
  /** The exceptions of one hexahedron, corner ids in VTK_HEXAHEDRON order. */
  void AddHexahedron(const vtkIdType c[8]);
  /** True if quadrilateral (a, b, c, d) is split along a-c, false if along b-d. */
  bool AlongFirstDiagonal(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d) const;
  /** Faces split against the smallest-id rule. */
  vtkIdType GetNumberOfUnfoldedFaces() const
  {
    return static_cast<vtkIdType>(this->Unfolded.size());
  }

private:
  std::map<std::array<vtkIdType, 4>, std::array<vtkIdType, 2>> Unfolded; // sorted ids: diagonal
};
}

#endif
