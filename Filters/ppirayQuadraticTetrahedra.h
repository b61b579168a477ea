/**
 * @file   ppirayQuadraticTetrahedra.h
 * @brief  a quadratic tetrahedron's field in its frame, and how straight its edges are
 *
 * VTK_QUADRATIC_TETRA (and VTK_LAGRANGE_TETRAHEDRON of order 2, the same
 * ten nodes: corners 0..3, then the mid-edge nodes of the edges
 * (0,1), (1,2), (2,0), (0,3), (1,3), (2,3)) interpolates with
 *   N_i = l_i (2 l_i - 1) at the corners, N_ab = 4 l_a l_b at the mid-edge nodes
 * (l the barycentric coordinates; vtkQuadraticTetra::InterpolationFunctions).
 * When every mid-edge node lies at its edge's midpoint the cell is the affine
 * image of VTK's parametric tetrahedron, its parametric coordinates are the
 * frame coordinates (u, v, w) = (l_1, l_2, l_3) of the edges from corner 0
 * (ppirayLinearCellKinds.h), and the field is the quadratic
 *   f = c0 + c1 u + c2 v + c3 w + c4 uv + c5 vw + c6 uw + c8 u^2 + c9 v^2 + c10 w^2
 * whose coefficients follow from the node values (FrameCoefficients). Along
 * a ray it is a quadratic in the ray parameter, which the march integrates
 * exactly as it does a hexahedron's cubic.
 */
#ifndef ppirayQuadraticTetrahedra_h
#define ppirayQuadraticTetrahedra_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkType.h"             // for vtkIdType

namespace ppiray
{
namespace quadratic_tetrahedron
{
/** Corners of edge k, in the order of the mid-edge nodes 4 + k. */
constexpr int Edge[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };

/** Coefficients in the frame polynomial (above): c[0..10], c[7] (uvw) zero. */
constexpr int Coefficients = 11;

/** Whether a cell of `type` with `npts` points is a ten-node quadratic tetrahedron. */
PPIRAYFILTERS_EXPORT bool IsQuadraticTetrahedron(int type, vtkIdType npts);

/** The edge (0..5) between corners a and b (a != b, both 0..3). */
PPIRAYFILTERS_EXPORT int EdgeBetween(int a, int b);

/**
 * Mid-edge node ids after the corners are renumbered, corner i becoming the
 * old corner `corner[i]`: out[k] = in[EdgeBetween(corner[Edge[k][0]], corner[Edge[k][1]])].
 */
PPIRAYFILTERS_EXPORT void RenumberEdgeNodes(
  const int corner[4], const vtkIdType in[6], vtkIdType out[6]);

/**
 * c[0..10] of the field with corner values s[0..3] and mid-edge values m[0..5]:
 * along frame axis i, f(e_i) = s_i and f(e_i / 2) = m_0i give
 *   c_i = 4 m_0i - s_i - 3 s_0,  c_ii = 2 s_i - 4 m_0i + 2 s_0,
 * and at the midpoint of e_i and e_j
 *   c_ij = 4 m_ij - 4 s_0 - 2 (c_i + c_j) - (c_ii + c_jj).
 */
PPIRAYFILTERS_EXPORT void FrameCoefficients(const double s[4], const double m[6], double c[11]);

/**
 * The largest distance of a mid-edge node from its edge's midpoint relative
 * to that edge's length (0: straight edges, evenly parametrized; the field is
 * then exactly FrameCoefficients' polynomial), of the nodes x (corners 0..3,
 * then the mid-edge nodes).
 */
PPIRAYFILTERS_EXPORT double MidEdgeDeviation(const double x[10][3]);

/**
 * Beyond this MidEdgeDeviation a cell's map may fold: along an edge the
 * quadratic map is one-to-one only while the mid-edge node lies within a
 * quarter of the edge of its midpoint.
 */
constexpr double FoldingDeviation = 0.25;
}
}

#endif
