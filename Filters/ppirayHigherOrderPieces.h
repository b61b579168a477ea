/**
 * @file   ppirayHigherOrderPieces.h
 * @brief  quadratic and higher-order cells refined into ten-node tetrahedra
 *         in their parametric space, with VTK's map and field at the nodes
 *
 * A higher-order cell (quadratic, triquadratic, Lagrange or Bezier
 * tetrahedron, hexahedron, wedge; quadratic pyramid) maps its parametric
 * cell onto space and carries its field through the same functions:
 * x(p) = sum_i N_i(p) X_i, f(p) = sum_i N_i(p) f_i (vtkCell::InterpolateFunctions).
 * Its parametric cell is refined `levels` times (each edge halved per level):
 * - a tetrahedron by red refinement (its four corner tetrahedra and four
 *   around one diagonal of the octahedron left);
 * - a hexahedron into 8^levels sub-cubes, a wedge into 4^levels triangles
 *   (red) times 2^levels layers of prisms;
 * - a pyramid into its four corner pyramids, the top one, the one upside
 *   down under it and four tetrahedra along the base edges (apex over the
 *   base centre in a reference pyramid; VTK's parametric coordinates of a
 *   reference point (X, Y, Z) are t = Z, r = (X - Z/2)/(1 - Z), s = (Y - Z/2)/(1 - Z)).
 * Every sub-cell is split into tetrahedra as a cone from its smallest node id
 * (ppirayConformingTetrahedra.h), and every tetrahedron is a ten-node piece:
 * its corners and mid-edge nodes are the cell's map at the parametric corners
 * and edge midpoints, and carry VTK's weights there (the field of a node is
 * VTK's). Rendered as a quadratic tetrahedron with straight edges, a piece
 * holds the quadratic through its ten values: exact for a field that is
 * quadratic in the piece's parameters (any field of a quadratic tetrahedron;
 * a quadratic field in space in an affine cell of any kind), otherwise
 * VTK's field to the interpolation error of ten nodes, which falls eightfold
 * per level for a smooth field. A piece's mid-edge node lies off its edge's
 * midpoint by the map's curvature, fourfold less per level.
 *
 * Nodes on the cell's boundary are keyed by the weights of the face's corners
 * there (barycentric on a triangle, bilinear on a quadrilateral: the same
 * from both cells on the face), inner nodes by their cell: two cells sharing
 * a face, refined by the same number of levels, refine it into the same
 * triangles with the same nodes, whatever their kinds, and a face of an
 * unrefined cell (levels 0) is split as ppirayConformingTetrahedra.h splits
 * it: the pieces conform across faces.
 *
 * Each added point also carries its cell's linear weights (of the cell's
 * corners): the cell through its corners, for a cell with a NaN at a node
 * other than a corner (HigherOrderPieces::Linear).
 */
#ifndef ppirayHigherOrderPieces_h
#define ppirayHigherOrderPieces_h

#include "ppirayFiltersModule.h" // for export macro
#include "ppirayPolyhedra.h"     // for ppiray::AddedPoints
#include "vtkType.h"             // for vtkIdType

#include <array>  // for std::array
#include <vector> // for std::vector

class vtkUnstructuredGrid;

namespace ppiray
{
/** Pieces of refined higher-order cells and the points they add. */
struct HigherOrderPieces
{
  std::vector<std::array<vtkIdType, 10>> Pieces; // VTK_QUADRATIC_TETRA node order
  std::vector<vtkIdType> Cell;                   // per piece: its cell's index in the list given
  AddedPoints Added;                  // numbered from the grid's number of points on: VTK's weights
  AddedPoints Linear;                 // the same points with the weights of their cell's corners
  double MaximumMidEdgeDeviation = 0; // of the pieces (quadratic_tetrahedron::MidEdgeDeviation)
};

/**
 * Refines the cells `cellIds` of `grid` (quadratic or higher-order 3D cells)
 * `levels` times; `points` are the grid's points as 3 doubles each (e.g.
 * relative to a local origin), the added points are written in the same frame.
 */
PPIRAYFILTERS_EXPORT void RefineHigherOrderCells(vtkUnstructuredGrid* grid, const double* points,
  const std::vector<vtkIdType>& cellIds, int levels, HigherOrderPieces& out);

/**
 * The levels that bring a mid-edge offset of `deviation` edge lengths below
 * `tolerance` (deviation / 4^levels <= tolerance), at least `minimumLevels`,
 * at most `maximumLevels` and at most what keeps `pieces` x 8^levels within
 * `maximumPieces`.
 */
PPIRAYFILTERS_EXPORT int RefinementLevels(double deviation, double tolerance, vtkIdType pieces,
  int minimumLevels, int maximumLevels, vtkIdType maximumPieces);
}

#endif
