/**
 * @file   ppirayCurvedTetrahedra.h
 * @brief  curved quadratic tetrahedra refined into pieces with straight edges
 *
 * A quadratic tetrahedron whose mid-edge nodes lie off its edges' midpoints
 * maps VTK's parametric tetrahedron onto a curved cell (x(p) = sum_i N_i(p)
 * X_i, vtkQuadraticTetra's functions). Refined `levels` times in parametric
 * space (red refinement: each tetrahedron into its four corner tetrahedra
 * and the four around one diagonal of the octahedron left), every piece is
 * again a ten-node tetrahedron: its corners and mid-edge nodes are the
 * curved map at the piece's parametric corners and edge midpoints, and the
 * cell's field restricted to it is a quadratic in its own barycentric
 * coordinates, exactly, taken from its ten node values. A piece's mid-edge
 * node lies off its edge's midpoint by 4^-levels of the cell's offset
 * (the map's second derivative times the squared edge length), so rendering
 * the pieces with straight edges leaves a geometric error that shrinks
 * fourfold per level; the field is VTK's in the pieces' parametric frame.
 *
 * Nodes on a face or an edge are keyed by the face's or edge's point ids and
 * their lattice position, so that two cells sharing a face refine it into the
 * same triangles with the same nodes: the pieces conform across cells
 * refined by the same number of levels.
 *
 * A cell with a NaN at a mid-edge node (not at a corner) is taken through
 * its corners, as an unrefined one is: its added points carry the corners'
 * barycentric weights too (RefinedTetrahedra::Linear).
 */
#ifndef ppirayCurvedTetrahedra_h
#define ppirayCurvedTetrahedra_h

#include "ppirayFiltersModule.h" // for export macro
#include "ppirayPolyhedra.h"     // for ppiray::AddedPoints
#include "vtkType.h"             // for vtkIdType

#include <array>  // for std::array
#include <vector> // for std::vector

namespace ppiray
{
/** Barycentric coordinates of a piece's four corners in its cell, times the resolution. */
using PieceCorners = std::array<std::array<unsigned char, 4>, 4>;

/**
 * The field through a cell's corners (values s[0..3]) at a piece's corners
 * `corners`, `resolution` as RefinedTetrahedra::Resolution.
 */
PPIRAYFILTERS_EXPORT void LinearCornerValues(
  const PieceCorners& corners, int resolution, const double s[4], double out[4]);

/** Pieces of refined quadratic tetrahedra and the points they add. */
struct RefinedTetrahedra
{
  std::vector<std::array<vtkIdType, 10>> Pieces; // VTK_QUADRATIC_TETRA node order
  std::vector<vtkIdType> Cell;                   // per piece: its cell's index in the input
  // Per piece: its corners' barycentric coordinates in its cell, times
  // Resolution (for a field taken through the cell's corners).
  std::vector<PieceCorners> Corners;
  int Resolution = 1;
  AddedPoints Added; // numbered from the first id after the points given
  // The same points with the barycentric weights of their cell's corners:
  // the field of a cell taken through its corners (a NaN at a mid-edge node).
  AddedPoints Linear;
};

/**
 * Refines `cells` (ten node ids each into `points`, 3 doubles per point,
 * `numberOfPoints` of them) `levels` times: 8^levels pieces per cell.
 */
PPIRAYFILTERS_EXPORT void RefineQuadraticTetrahedra(const double* points, vtkIdType numberOfPoints,
  const std::vector<std::array<vtkIdType, 10>>& cells, int levels, RefinedTetrahedra& out);

/**
 * The levels that bring a mid-edge offset of `deviation` edge lengths below
 * `tolerance` (deviation / 4^levels <= tolerance), at most `maximumLevels`
 * and at most what keeps `cells` x 8^levels within `maximumPieces`.
 */
PPIRAYFILTERS_EXPORT int RefinementLevels(
  double deviation, double tolerance, vtkIdType cells, int maximumLevels, vtkIdType maximumPieces);
}

#endif
