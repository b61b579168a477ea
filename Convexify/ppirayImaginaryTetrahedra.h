/**
 * @file   ppirayImaginaryTetrahedra.h
 * @brief  tetrahedra filling a box minus the volume a closed surface bounds
 *
 * The space between a mesh and a convex box around it, filled with
 * tetrahedra that conform to the mesh's boundary (Weiler et al. 2003, Sec.
 * 3.3: "imaginary" cells, so that every ray enters the convex set once).
 * The box faces and the boundary triangles are the constraints of a
 * conforming constrained Delaunay triangulation (CGAL >= 6.1,
 * make_conforming_constrained_Delaunay_triangulation_3: it may insert
 * Steiner points on constraint edges and faces, so a boundary triangle can be
 * covered by several imaginary faces). A cell of the triangulation lies
 * outside the mesh when reaching it from the box crosses the boundary an
 * even number of times (parity flood fill over the cell adjacency), which
 * also finds cavities and the space between several parts. Triangles that
 * bound nothing are left out: degenerate ones (exactly collinear corners)
 * and pairs on the same points (both sides of a seam).
 */
#ifndef ppirayImaginaryTetrahedra_h
#define ppirayImaginaryTetrahedra_h

#include "vtkType.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace ppiray
{
struct ImaginaryTetrahedra
{
  /// Points added after the input's: the box corners and Steiner points.
  std::vector<std::array<double, 3>> NewPoints;
  /// 4 point ids per tetrahedron, positively oriented; an id at or past the
  /// input's number of points is NewPoints[id - numberOfPoints].
  std::vector<vtkIdType> Tets;
  /// Input triangle of each face of each tetrahedron that lies on one (4 per
  /// tetrahedron, face f opposite corner f; -1 elsewhere).
  std::vector<vtkIdType> BoundaryTriangle;
  /// Steiner points the triangulation inserted on the boundary.
  vtkIdType SteinerPoints = 0;
  /// Boundary triangles that bound nothing: degenerate, or on the same
  /// points as another (both sides of a seam).
  vtkIdType DroppedTriangles = 0;
  /// Cells of the triangulation inside the mesh (dropped).
  vtkIdType InsideCells = 0;
  /// Empty on success, else why nothing was made.
  std::string Error;
};

/**
 * Imaginary tetrahedra filling `box` (xmin, xmax, ymin, ymax, zmin, zmax)
 * minus the volume bounded by `triangles` (3 ids each into `points`, xyz
 * per point; any orientation). The triangles must form closed surfaces that
 * neither intersect each other nor the box (checked: an Error otherwise).
 * `progress` receives a fraction in [0, 1].
 */
ImaginaryTetrahedra FillBoxAroundSurface(const std::vector<double>& points,
  const std::vector<vtkIdType>& triangles, const double box[6],
  const std::function<void(double)>& progress);
}

#endif
