/**
 * @file   ppirayRaySegments.h
 * @brief  the reference renderer's ray-cell segments: where a ray is in a cell, and its scalar
 * there
 *
 * For vtkUnstructuredGridReferenceRenderer only (it shares nothing with the
 * GPU march): a tetrahedron clipped by its barycentric coordinates; a
 * hexahedron, voxel, wedge or pyramid cut at its faces' crossings (bilinear
 * faces exactly) and split until the cell's own interpolation is linear
 * along the ray. In the renderer's frame (world minus the centre of the
 * bounds), in double.
 */
#ifndef ppirayRaySegments_h
#define ppirayRaySegments_h

#include "vtkType.h" // for vtkIdType

#include <glm/mat3x3.hpp> // for glm::dmat3
#include <glm/vec2.hpp>   // for glm::dvec2
#include <glm/vec3.hpp>   // for glm::dvec3
#include <glm/vec4.hpp>   // for glm::dvec4
#include <vector>         // for std::vector

class vtkCell;
class vtkDataArray;
class vtkGenericCell;

namespace ppiray
{
namespace reference
{
using Vec3 = glm::dvec3;

// A ray piece on which the scalar is linear; its field gradient (constant in
// a tetrahedron) or, in a general cell, the cell whose gradient is evaluated
// where an isosurface is found.
struct Segment
{
  double T0, T1, S0, S1;
  Vec3 Gradient = { 0, 0, 0 };
  vtkIdType Cell = -1;
};

// Precomputed per tetrahedron (per tile): barycentric coordinates of x are
// lambda_{1..3} = Inverse (x - P0), lambda_0 = 1 - sum.
struct Tetrahedron
{
  Vec3 P0;
  glm::dmat3 Inverse;
  double S[4];
};

/**
 * The inverse of the edge matrix E = (p1 - p0, p2 - p0, p3 - p0) (columns);
 * false when the tetrahedron is flat (|det E| <= 1e-14 max|E_ij|^3).
 */
bool InvertEdges(const Vec3 p[4], glm::dmat3& inverse);

// The piece of the ray origin + t direction (t >= 0) inside the tetrahedron.
bool ClipRay(const Tetrahedron& tet, const Vec3& origin, const Vec3& direction, Segment& out);

// The corners a linear 3D cell interpolates from: a cell may list more point
// ids than its type has corners (a 20-node serendipity hexahedron written as
// VTK_HEXAHEDRON); the type's own functions use the first ones.
int InterpolatedPoints(vtkCell* cell);

// pcoords of x in `cell` (its points `nodes`) refined from the pcoords given
// by Newton's method on the cell's own functions, and the interpolation
// weights there; with `chord` (the map's inverse Jacobian near there), by the
// chord method first (true where that converged).
bool RefineParametricCoordinates(vtkCell* cell, const std::vector<glm::dvec3>& nodes,
  const double x[3], double pcoords[3], double* weights, std::vector<double>& derivs,
  const glm::dmat3* chord = nullptr);

// The inverse of the Jacobian dx/dp of `cell`'s map at pcoords (false where
// it is singular).
bool InverseJacobian(vtkCell* cell, const std::vector<glm::dvec3>& nodes, const double pcoords[3],
  std::vector<double>& derivs, glm::dmat3& inverse);

// Whether parametric coordinates p lie in the parametric cell of a cell whose
// corners form `linearType` (CornerCellType(); the unit cube for 0).
bool InParametricDomain(int linearType, const double p[3]);

// Whether the map sum_i weights_i nodes_i reaches x (within 1e-9 of the
// nodes' extent).
bool MapsTo(const std::vector<glm::dvec3>& nodes, const double* weights, const double x[3]);

// Where x lies in a nonlinear cell (its points `nodes`, its corners'
// `linearType`): pcoords and the weights there, 1 inside, 0 outside.
int LocateInNonlinearCell(vtkCell* cell, const std::vector<glm::dvec3>& nodes, int linearType,
  const double x[3], double pcoords[3], double* weights, std::vector<double>& derivs);

// The linear type of a quadratic or higher-order cell's corners (its first
// `corners` points; 0 and 0 for other cells).
int CornerCellType(int type, int& corners);

// The pieces of the ray inside a hexahedron, voxel, wedge, pyramid,
// polyhedron or higher-order cell, with the cell's own interpolation
// (isoparametric; a polyhedron's mean value coordinates; a higher-order
// cell with a NaN at a node past its corners, by the rule the mapper states,
// through its corners: the linear cell's functions at its parametric
// coordinates): the ray's crossings with every
// face (FaceCrossings) cut it into intervals, an interval whose midpoint is
// inside the cell (parametric distance 0) is inside; each inside interval is
// split until the interpolated scalar is linear along the ray within
// `tolerance` at its quarter points and midpoint, and every piece is then
// integrated exactly like a tetrahedron's. `cellId` >= 0 selects cell scalars.
// A piece is split at most MaximumSplitDepth levels deep, and the ray's
// stretch in the cell into at most MaximumPiecesPerCell pieces; `unresolved`
// counts the pieces accepted there without meeting the tolerance.
constexpr int MaximumSplitDepth = 24;
constexpr int MaximumPiecesPerCell = 4096;
void GeneralCellSegments(vtkIdType id, vtkGenericCell* cell, vtkDataArray* scalars,
  vtkIdType cellId, const Vec3& origin, const Vec3& direction, const Vec3& centre, double tolerance,
  std::vector<Segment>& out, long long& unresolved);

/**
 * The part [lo, hi] of the ray origin + t direction, t >= 0, that the planes
 * (n, d) keep, n . x + d >= 0 each (lo > hi: none).
 */
glm::dvec2 KeptRange(
  const std::vector<glm::dvec4>& planes, const Vec3& origin, const Vec3& direction);

/** The segments cut to t in `range` (the scalar linear along each), empty ones removed. */
void ClipSegments(std::vector<Segment>& segments, const glm::dvec2& range);
}
}

#endif
