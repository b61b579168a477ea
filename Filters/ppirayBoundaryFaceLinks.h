/**
 * @file   ppirayBoundaryFaceLinks.h
 * @brief  boundary faces of a mesh joined to the imaginary cells on them
 *
 * A convexified grid (vtkUnstructuredGridConvexify) fills the space around a
 * mesh with imaginary tetrahedra whose faces conform to the mesh's boundary
 * triangles, but not always through the same point ids: a triangle may be
 * split into several pieces by Steiner points, or met through the first
 * point id at a place where the mesh uses another (a seam). The adjacency by
 * point ids then leaves both sides open and a ray would end there. The cell
 * array BoundaryCellArrayName ("ppirayBoundaryCell", 4 components: face f
 * of a cell, opposite its corner f) names, per imaginary face on the
 * boundary, the input cell across it. LinkBoundaryFaces() finds, for each
 * such open face, the open face of that cell's tetrahedra it lies in
 * (coplanar, its centroid inside), and keeps the links of the mesh faces
 * whose pieces' areas add up to the face's: a face not covered stays open on
 * both sides (depth peeling goes on there).
 */
#ifndef ppirayBoundaryFaceLinks_h
#define ppirayBoundaryFaceLinks_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkType.h"

#include <vector>

class vtkUnstructuredGrid;

namespace ppiray
{
/// The cell array that names the input cell across each imaginary face.
constexpr const char* BoundaryCellArrayName = "ppirayBoundaryCell";
/// Its first component on an input cell that bounds nothing (zero volume):
/// the fill was made without it.
constexpr vtkIdType LeftOutOfFill = -2;

/**
 * The tetrahedra `tets` (4 point ids each) of `grid`'s cells `cellIds` but
 * those of cells the fill was made without (LeftOutOfFill): they have no
 * volume, and the imaginary faces name the cells beside them.
 */
PPIRAYFILTERS_EXPORT void RemoveCellsLeftOutOfFill(
  vtkUnstructuredGrid* grid, std::vector<vtkIdType>& tets, std::vector<vtkIdType>& cellIds);

struct BoundaryFaceLinks
{
  /// Open mesh faces (4 tetrahedron + face) joined to the imaginary faces on
  /// them: Pieces[Offsets[i] .. Offsets[i + 1]) for Faces[i].
  std::vector<vtkIdType> Faces;
  std::vector<vtkIdType> Offsets{ 0 };
  std::vector<vtkIdType> Pieces;
  /// Mesh faces named by pieces that do not cover them (left open).
  vtkIdType UncoveredFaces = 0;
  /// Imaginary faces whose named cell has no open face under them (left open).
  vtkIdType UnmatchedPieces = 0;
};

/**
 * Links of the open faces of the tetrahedra `tets` (4 point ids each, of
 * `grid`'s cells `cellIds`, in cell order) to the imaginary faces on them.
 * `local`: the points (3 doubles each), `open[4 t + f]`: whether face f of
 * tetrahedron t is a boundary face, `flat[t]`: whether it has no volume (a
 * flat mesh tetrahedron is never linked; a flat imaginary one is a piece
 * like the others, crossed with zero length). Empty without the cell array.
 */
PPIRAYFILTERS_EXPORT BoundaryFaceLinks LinkBoundaryFaces(vtkUnstructuredGrid* grid,
  const std::vector<vtkIdType>& tets, const std::vector<vtkIdType>& cellIds, const double* local,
  const std::vector<unsigned char>& open, const std::vector<unsigned char>& flat);
}

#endif
