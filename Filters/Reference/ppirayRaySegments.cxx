#include "ppirayRaySegments.h"

#include "ppirayNumerics.h"
#include "vtkCell.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ppiray
{
namespace reference
{
namespace
{
// Where the ray meets a polygon of five or more corners (a polyhedron's
// face), taken as planar: its plane by Newell's normal through the corners'
// centre, the crossing inside by the even-odd rule in the plane.
void PolygonCrossing(
  const std::vector<Vec3>& p, const Vec3& o, const Vec3& d, std::vector<double>& ts)
{
  const size_t m = p.size();
  Vec3 normal(0.0), centre(0.0);
  for (size_t k = 0; k < m; ++k)
  {
    normal += glm::cross(p[k], p[(k + 1) % m]);
    centre += p[k] / static_cast<double>(m);
  }
  const double along = glm::dot(normal, d);
  if (!(std::abs(along) > 1e-300))
  {
    return;
  }
  const double t = glm::dot(normal, centre - o) / along;
  const Vec3 x = o + t * d;
  // Drop the normal's largest axis; count the edges crossing a ray from x.
  const int drop = std::abs(normal.x) > std::abs(normal.y)
                     ? (std::abs(normal.x) > std::abs(normal.z) ? 0 : 2)
                     : (std::abs(normal.y) > std::abs(normal.z) ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  bool inside = false;
  for (size_t k = 0, l = m - 1; k < m; l = k++)
  {
    const Vec3 a = p[k], b = p[l];
    if ((a[v] > x[v]) != (b[v] > x[v]) &&
        x[u] < a[u] + (b[u] - a[u]) * (x[v] - a[v]) / (b[v] - a[v]))
    {
      inside = !inside;
    }
  }
  if (inside)
  {
    ts.push_back(t);
  }
}

// Ray parameters t where origin + t direction crosses a cell face: a triangle
// (Moller-Trumbore), a polygon of five or more corners (PolygonCrossing), or a
// quadrilateral as the bilinear patch
// P(u, v) = (1-u)(1-v) p0 + u (1-v) p1 + u v p2 + (1-u) v p3 that the cell's
// interpolation spans (planar or not): with n1, n2 orthogonal to the ray,
// A(u, v) = (P - o) . n1 = 0 and B(u, v) = (P - o) . n2 = 0 are bilinear;
// eliminating u leaves a quadratic in v.
void FaceCrossings(
  const std::vector<Vec3>& p, const Vec3& o, const Vec3& d, std::vector<double>& ts)
{
  const double eps = 1e-12;
  if (p.size() == 3)
  {
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    const Vec3 h = glm::cross(d, e2);
    const double a = glm::dot(e1, h);
    if (std::abs(a) < 1e-300)
    {
      return;
    }
    const Vec3 s = o - p[0];
    const double u = glm::dot(s, h) / a;
    const Vec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / a;
    if (u >= -eps && v >= -eps && u + v <= 1 + eps)
    {
      ts.push_back(glm::dot(e2, q) / a);
    }
    return;
  }
  if (p.size() > 4)
  {
    PolygonCrossing(p, o, d, ts);
    return;
  }
  // Two unit vectors orthogonal to d.
  const Vec3 axis = std::abs(d[0]) < 0.6 ? Vec3{ 1, 0, 0 } : Vec3{ 0, 1, 0 };
  const Vec3 n1 = glm::normalize(glm::cross(d, axis));
  const Vec3 n2 = glm::cross(d, n1);
  double a[4], b[4];
  for (int i = 0; i < 4; ++i)
  {
    const Vec3 r = p[i] - o;
    a[i] = glm::dot(r, n1);
    b[i] = glm::dot(r, n2);
  }
  // A = A0 + Au u + Av v + Auv u v, likewise B.
  const double A0 = a[0], Au = a[1] - a[0], Av = a[3] - a[0], Auv = a[0] - a[1] + a[2] - a[3];
  const double B0 = b[0], Bu = b[1] - b[0], Bv = b[3] - b[0], Buv = b[0] - b[1] + b[2] - b[3];
  const double c2 = Bv * Auv - Av * Buv;
  const double c1 = B0 * Auv + Bv * Au - A0 * Buv - Av * Bu;
  const double c0 = B0 * Au - A0 * Bu;
  double roots[2];
  const int count = ppiray::QuadraticRoots(c2, c1, c0, roots);
  for (int k = 0; k < count; ++k)
  {
    const double v = roots[k];
    if (v < -eps || v > 1 + eps)
    {
      continue;
    }
    const double da = Au + Auv * v, db = Bu + Buv * v;
    const double u = std::abs(da) > std::abs(db) ? -(A0 + Av * v) / da : -(B0 + Bv * v) / db;
    if (!(u >= -eps && u <= 1 + eps))
    {
      continue;
    }
    const Vec3 point =
      (1 - u) * (1 - v) * p[0] + u * (1 - v) * p[1] + u * v * p[2] + (1 - u) * v * p[3];
    ts.push_back(glm::dot(point - o, d));
  }
}

// dN_i/dp_k of `cell` at pcoords into derivs[k n + i] (n nodes, k < the
// cell's dimension), by central differences of InterpolateFunctions with
// step 1e-5 (error about 1e-10: Newton's fixed point is the functions' own,
// the derivatives only steer it). VTK's InterpolateDerivs is not used: its
// layout differs between cells (node by node for Lagrange and Bezier cells,
// vtkHigherOrderInterpolation) and vtkBezierWedge's crashes in VTK 9.2.
void ShapeDerivatives(vtkCell* cell, const double pcoords[3], std::vector<double>& derivs)
{
  const int n = static_cast<int>(cell->GetNumberOfPoints());
  const int dim = cell->GetCellDimension();
  const double h = 1e-5;
  derivs.resize(dim * n);
  std::vector<double> plus(n), minus(n);
  for (int k = 0; k < dim; ++k)
  {
    double p[3] = { pcoords[0], pcoords[1], pcoords[2] };
    p[k] = pcoords[k] + h;
    cell->InterpolateFunctions(p, plus.data());
    p[k] = pcoords[k] - h;
    cell->InterpolateFunctions(p, minus.data());
    for (int i = 0; i < n; ++i)
    {
      derivs[k * n + i] = (plus[i] - minus[i]) / (2 * h);
    }
  }
}

// Where the ray o + t d meets the curved face X(r, s) = sum_i N_i(r, s) X_i
// (a quadratic or higher-order triangle or quadrilateral): Newton's method
// on X(r, s) - centre - (o + t d) = 0 in (r, s, t), with the face's own
// functions (InterpolateFunctions, InterpolateDerivs), from (r, s) = `seed`
// and t where the ray passes nearest X(seed). False where it does not
// converge, or converges outside the face's parametric domain (a triangle's
// or the unit square).
bool CurvedFaceCrossing(vtkCell* face, const Vec3& centre, const Vec3& o, const Vec3& d,
  const double seed[2], std::vector<double>& weights, std::vector<double>& derivs, double& t)
{
  const int n = static_cast<int>(face->GetNumberOfPoints());
  const bool triangle = face->GetNumberOfEdges() == 3;
  double pcoords[3] = { seed[0], seed[1], 0.0 };
  t = std::numeric_limits<double>::quiet_NaN();
  for (int iteration = 0; iteration < 16; ++iteration)
  {
    face->InterpolateFunctions(pcoords, weights.data());
    ShapeDerivatives(face, pcoords, derivs);
    Vec3 x(0.0), dr(0.0), ds(0.0);
    for (int i = 0; i < n; ++i)
    {
      double p[3];
      face->GetPoints()->GetPoint(i, p);
      const Vec3 point(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
      x += weights[i] * point;
      dr += derivs[i] * point;
      ds += derivs[n + i] * point;
    }
    t = std::isnan(t) ? glm::dot(x - o, d) / glm::dot(d, d) : t;
    const glm::dmat3 jacobian(dr, ds, -d);
    if (!(std::abs(glm::determinant(jacobian)) > 0))
    {
      return false;
    }
    const Vec3 step = glm::inverse(jacobian) * (x - o - t * d);
    pcoords[0] -= step[0];
    pcoords[1] -= step[1];
    t -= step[2];
    if (!(std::abs(pcoords[0]) < 4 && std::abs(pcoords[1]) < 4))
    {
      return false; // diverging: the ray misses the face near this seed
    }
    if (!(std::max({ std::abs(step[0]), std::abs(step[1]), std::abs(step[2]) }) > 1e-13))
    {
      const double eps = 1e-9, r = pcoords[0], s = pcoords[1];
      return triangle ? r >= -eps && s >= -eps && r + s <= 1 + eps
                      : r >= -eps && s >= -eps && r <= 1 + eps && s <= 1 + eps;
    }
  }
  return false;
}

// FaceCrossings of a nonlinear face: CurvedFaceCrossing from seeds spread
// over the face (a triangle's corners and the centroids of its four
// midpoint triangles; a quadrilateral's centre and quarter points), each
// crossing once; `centre` is subtracted from its points as from the ray's
// origin.
void NonlinearFaceCrossings(
  vtkCell* face, const Vec3& centre, const Vec3& o, const Vec3& d, std::vector<double>& ts)
{
  static const double triangleSeeds[7][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 1 / 6.0, 1 / 6.0 },
    { 4 / 6.0, 1 / 6.0 }, { 1 / 6.0, 4 / 6.0 }, { 1 / 3.0, 1 / 3.0 } };
  static const double quadSeeds[5][2] = { { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.25, 0.75 },
    { 0.75, 0.75 }, { 0.5, 0.5 } };
  const bool triangle = face->GetNumberOfEdges() == 3;
  const int seeds = triangle ? 7 : 5;
  const int n = static_cast<int>(face->GetNumberOfPoints());
  // None where the ray passes outside the ball around the nodes' centroid
  // through the farthest node, doubled (the face bulges past its nodes by
  // far less).
  Vec3 mean(0.0);
  std::vector<Vec3> nodes(n);
  for (int i = 0; i < n; ++i)
  {
    double p[3];
    face->GetPoints()->GetPoint(i, p);
    nodes[i] = Vec3(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
    mean += nodes[i] / static_cast<double>(n);
  }
  double radius2 = 0;
  for (const Vec3& x : nodes)
  {
    radius2 = std::max(radius2, glm::dot(x - mean, x - mean));
  }
  const Vec3 toMean = mean - o;
  const double along = glm::dot(toMean, d) / glm::dot(d, d);
  const Vec3 off = toMean - along * d;
  if (glm::dot(off, off) > 4.0 * radius2)
  {
    return;
  }
  std::vector<double> weights(n), derivs(3 * n);
  const size_t before = ts.size();
  for (int k = 0; k < seeds; ++k)
  {
    double t;
    if (CurvedFaceCrossing(
          face, centre, o, d, triangle ? triangleSeeds[k] : quadSeeds[k], weights, derivs, t) &&
        std::none_of(ts.begin() + before, ts.end(),
          [t](double u) { return std::abs(u - t) <= 1e-9 * std::max(1.0, std::abs(t)); }))
    {
      ts.push_back(t);
    }
  }
}
}

//------------------------------------------------------------------------------
bool InvertEdges(const Vec3 p[4], glm::dmat3& inverse)
{
  const glm::dmat3 e(p[1] - p[0], p[2] - p[0], p[3] - p[0]);
  double scale = 0;
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      scale = std::max(scale, std::abs(e[c][r]));
    }
  }
  if (!(std::abs(glm::determinant(e)) > 1e-14 * scale * scale * scale))
  {
    return false; // flat: contributes nothing
  }
  inverse = glm::inverse(e);
  return true;
}

//------------------------------------------------------------------------------
bool ClipRay(const Tetrahedron& tet, const Vec3& origin, const Vec3& direction, Segment& out)
{
  // Barycentric coordinates along the ray: lambda_v(t) = a_v + b_v t.
  const Vec3 a123 = tet.Inverse * (origin - tet.P0), b123 = tet.Inverse * direction;
  const double a[4] = { 1.0 - a123.x - a123.y - a123.z, a123.x, a123.y, a123.z };
  const double b[4] = { -b123.x - b123.y - b123.z, b123.x, b123.y, b123.z };
  // lambda_v(t) = a_v + b_v t >= 0 for all v; a ray lying in a face (b ~ 0,
  // a ~ 0) counts as inside, and the overlap is removed per ray.
  const double eps = 1e-9;
  double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
  for (int v = 0; v < 4; ++v)
  {
    if (b[v] > eps)
    {
      t0 = std::max(t0, -a[v] / b[v]);
    }
    else if (b[v] < -eps)
    {
      t1 = std::min(t1, -a[v] / b[v]);
    }
    else if (a[v] < -eps)
    {
      return false;
    }
  }
  if (!(t1 > t0))
  {
    return false;
  }
  auto scalar = [&](double t)
  {
    double s = 0;
    for (int v = 0; v < 4; ++v)
    {
      s += (a[v] + b[v] * t) * tet.S[v];
    }
    return s;
  };
  out = { t0, t1, scalar(t0), scalar(t1) };
  // grad s = sum_v S_v grad lambda_v = Inverse^T (S_1 - S_0, S_2 - S_0, S_3 - S_0).
  out.Gradient = glm::transpose(tet.Inverse) *
                 Vec3(tet.S[1] - tet.S[0], tet.S[2] - tet.S[0], tet.S[3] - tet.S[0]);
  return true;
}

//------------------------------------------------------------------------------
int InterpolatedPoints(vtkCell* cell)
{
  const int n = static_cast<int>(cell->GetNumberOfPoints());
  switch (cell->GetCellType())
  {
    case VTK_HEXAHEDRON:
    case VTK_VOXEL:
      return std::min(n, 8);
    case VTK_WEDGE:
      return std::min(n, 6);
    case VTK_PYRAMID:
      return std::min(n, 5);
    default:
      return n;
  }
}

//------------------------------------------------------------------------------
bool InverseJacobian(vtkCell* cell, const std::vector<Vec3>& nodes, const double pcoords[3],
  std::vector<double>& derivs, glm::dmat3& inverse)
{
  // dx/dp = sum_i X_i (dN_i/dp)^T, columns dx/dr, dx/ds, dx/dt.
  const int n = static_cast<int>(cell->GetNumberOfPoints());
  ShapeDerivatives(cell, pcoords, derivs);
  glm::dmat3 jacobian(0.0);
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      jacobian[k] += derivs[k * n + i] * nodes[i];
    }
  }
  if (!(std::abs(glm::determinant(jacobian)) > 0))
  {
    return false;
  }
  inverse = glm::inverse(jacobian);
  return true;
}

//------------------------------------------------------------------------------
bool RefineParametricCoordinates(vtkCell* cell, const std::vector<Vec3>& nodes, const double x[3],
  double pcoords[3], double* weights, std::vector<double>& derivs, const glm::dmat3* chord)
{
  // Newton's method on r(p) = sum_i N_i(p) X_i - x = 0 from the p given,
  // with the cell's own N_i and dN_i/dp (InterpolateFunctions,
  // InterpolateDerivs), p -= J(p)^-1 r(p), until a step is below 1e-14.
  // With `chord` (J^-1 at a nearby point): the chord method first,
  // p -= chord r(p), which needs no derivatives (it converges linearly, at
  // once where the map is affine); Newton where a step is not a quarter of
  // the one before.
  const int n = static_cast<int>(cell->GetNumberOfPoints());
  derivs.resize(3 * n);
  const auto residual = [&](const double p[3])
  {
    cell->InterpolateFunctions(const_cast<double*>(p), weights);
    Vec3 r(-x[0], -x[1], -x[2]);
    for (int i = 0; i < n; ++i)
    {
      r += weights[i] * nodes[i];
    }
    return r;
  };
  const auto converged = [](const Vec3& step) {
    return !(std::max({ std::abs(step[0]), std::abs(step[1]), std::abs(step[2]) }) > 1e-14);
  };
  // Far outside the parametric cell (or NaN): diverging, x is not in the
  // cell (and some cells' functions fail there: vtkBezierWedge 9.2).
  const auto far = [](const double p[3])
  { return !(std::abs(p[0] - 0.5) < 4 && std::abs(p[1] - 0.5) < 4 && std::abs(p[2] - 0.5) < 4); };
  if (chord)
  {
    double p[3] = { pcoords[0], pcoords[1], pcoords[2] },
           previous = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < 16; ++iteration)
    {
      const Vec3 step = *chord * residual(p);
      if (converged(step)) // the weights are those at p, within 1e-14
      {
        std::copy_n(p, 3, pcoords);
        return true;
      }
      const double size = std::max({ std::abs(step[0]), std::abs(step[1]), std::abs(step[2]) });
      if (!(size < 0.25 * previous))
      {
        break; // contracting slowly (a curved map): Newton instead
      }
      previous = size;
      for (int k = 0; k < 3; ++k)
      {
        p[k] -= step[k];
      }
      if (far(p))
      {
        break;
      }
    }
  }
  for (int iteration = 0; iteration < 8; ++iteration)
  {
    const Vec3 r = residual(pcoords);
    glm::dmat3 inverse;
    if (!InverseJacobian(cell, nodes, pcoords, derivs, inverse))
    {
      break;
    }
    const Vec3 step = inverse * r;
    const double before[3] = { pcoords[0], pcoords[1], pcoords[2] };
    for (int k = 0; k < 3; ++k)
    {
      pcoords[k] -= step[k];
    }
    if (far(pcoords))
    {
      std::copy_n(before, 3, pcoords);
      break;
    }
    if (converged(step))
    {
      break;
    }
  }
  cell->InterpolateFunctions(pcoords, weights);
  return false;
}

//------------------------------------------------------------------------------
bool InParametricDomain(int linearType, const double p[3])
{
  const double eps = 1e-9, r = p[0], s = p[1], t = p[2];
  const bool unitCube =
    r >= -eps && s >= -eps && t >= -eps && r <= 1 + eps && s <= 1 + eps && t <= 1 + eps;
  switch (linearType)
  {
    case VTK_TETRA:
      return r >= -eps && s >= -eps && t >= -eps && r + s + t <= 1 + eps;
    case VTK_WEDGE:
      return unitCube && r + s <= 1 + eps;
    default: // hexahedra; VTK's pyramid spans the unit cube too (collapsed at t = 1)
      return unitCube;
  }
}

//------------------------------------------------------------------------------
bool MapsTo(const std::vector<Vec3>& nodes, const double* weights, const double x[3])
{
  // |sum_i w_i X_i - x| within 1e-9 of the nodes' extent.
  Vec3 mapped(0.0), lo(nodes[0]), hi(nodes[0]);
  for (size_t i = 0; i < nodes.size(); ++i)
  {
    mapped += weights[i] * nodes[i];
    lo = glm::min(lo, nodes[i]);
    hi = glm::max(hi, nodes[i]);
  }
  const Vec3 miss = mapped - Vec3(x[0], x[1], x[2]);
  return glm::length(miss) <= 1e-9 * glm::length(hi - lo);
}

//------------------------------------------------------------------------------
int LocateInNonlinearCell(vtkCell* cell, const std::vector<Vec3>& nodes, int linearType,
  const double x[3], double pcoords[3], double* weights, std::vector<double>& derivs)
{
  // Newton from the parametric centre; from VTK's EvaluatePosition where
  // that does not reach x. Inside where the map reaches x from the
  // parametric domain: VTK's own answer is wrong for some cells
  // (vtkLagrangeWedge 9.2 leaves r + s <= 1 unchecked in EvaluatePosition
  // and GetParametricDistance).
  cell->GetParametricCenter(pcoords);
  RefineParametricCoordinates(cell, nodes, x, pcoords, weights, derivs);
  if (!MapsTo(nodes, weights, x))
  {
    int subId;
    double dist2;
    if (cell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, weights) == -1)
    {
      return 0;
    }
    RefineParametricCoordinates(cell, nodes, x, pcoords, weights, derivs);
  }
  return MapsTo(nodes, weights, x) && InParametricDomain(linearType, pcoords) ? 1 : 0;
}

//------------------------------------------------------------------------------
int CornerCellType(int type, int& corners)
{
  switch (type)
  {
    case VTK_QUADRATIC_TETRA:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_BEZIER_TETRAHEDRON:
      corners = 4;
      return VTK_TETRA;
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON:
    case VTK_BEZIER_HEXAHEDRON:
      corners = 8;
      return VTK_HEXAHEDRON;
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_LAGRANGE_WEDGE:
    case VTK_BEZIER_WEDGE:
      corners = 6;
      return VTK_WEDGE;
    case VTK_QUADRATIC_PYRAMID:
      corners = 5;
      return VTK_PYRAMID;
    default:
      corners = 0;
      return 0;
  }
}

//------------------------------------------------------------------------------
void GeneralCellSegments(vtkIdType id, vtkGenericCell* cell, vtkDataArray* scalars,
  vtkIdType cellId, const Vec3& origin, const Vec3& direction, const Vec3& centre, double tolerance,
  std::vector<Segment>& out, long long& unresolved)
{
  int n = InterpolatedPoints(cell), cornerCount;
  const int cornerType = CornerCellType(cell->GetCellType(), cornerCount);
  std::vector<double> weights(std::max(static_cast<int>(cell->GetNumberOfPoints()), 8)), values(n);
  bool throughCorners = false;
  for (int v = 0; v < n; ++v)
  {
    values[v] = cellId >= 0 ? scalars->GetComponent(cellId, 0)
                            : scalars->GetComponent(cell->GetPointId(v), 0);
    if (std::isnan(values[v]) && v >= cornerCount && cornerCount > 0)
    {
      throughCorners = true; // a NaN past the corners: the corners' linear cell's field
    }
    else if (std::isnan(values[v]))
    {
      return; // a cell with a NaN scalar is empty, as in the mapper
    }
  }
  // Through the corners: the linear cell's functions at the same parametric
  // coordinates (the linear cell of the corners where the cell is affine).
  vtkSmartPointer<vtkGenericCell> linear;
  if (throughCorners)
  {
    linear = vtkSmartPointer<vtkGenericCell>::New();
    linear->SetCellType(cornerType);
    n = cornerCount;
  }
  std::vector<double> ts = { 0.0 };
  std::vector<Vec3> corners;
  for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
  {
    vtkCell* face = cell->GetFace(f);
    if (!face->IsLinear())
    {
      NonlinearFaceCrossings(face, centre, origin, direction, ts);
      continue;
    }
    const int m = static_cast<int>(face->GetNumberOfPoints());
    corners.resize(m);
    for (int k = 0; k < m; ++k)
    {
      double x[3];
      face->GetPoints()->GetPoint(k, x);
      corners[k] = { x[0] - centre[0], x[1] - centre[1], x[2] - centre[2] };
    }
    if (face->GetCellType() == VTK_PIXEL)
    {
      std::swap(corners[2], corners[3]); // pixel order to cyclic order
    }
    FaceCrossings(corners, origin, direction, ts);
  }
  std::sort(ts.begin(), ts.end());
  // A polyhedron's EvaluatePosition casts random rays (IsInside) from
  // vtkMath's one generator, which is not thread-safe: it decides only
  // whether an interval's midpoint is inside (serialized), and the field
  // along the interval comes from InterpolateFunctions (mean value
  // coordinates at x), which casts none.
  const bool polyhedron = cell->GetCellType() == VTK_POLYHEDRON;
  // A nonlinear cell's EvaluatePosition stops its Newton iteration at about
  // 1e-5 in parametric coordinates (vtkQuadraticTetra): refined, so that the
  // field along the ray is smooth enough for `tolerance`.
  const bool nonlinear = !polyhedron && !cell->IsLinear();
  std::vector<double> derivs;
  double midpoint[3] = { 0, 0, 0 }; // pcoords of the last inside test's point
  glm::dmat3 chord(1.0);            // the map's inverse Jacobian there
  bool hasChord = false, chordWorks = true;
  std::vector<Vec3> nodes(nonlinear ? cell->GetNumberOfPoints() : 0);
  for (size_t i = 0; i < nodes.size(); ++i)
  {
    double p[3];
    cell->GetPoints()->GetPoint(static_cast<vtkIdType>(i), p);
    nodes[i] = Vec3(p[0], p[1], p[2]);
  }
  auto evaluate = [&](double t, double& s, bool insideTest)
  {
    double x[3], pcoords[3], dist2;
    int subId, found = 1;
    for (int i = 0; i < 3; ++i)
    {
      x[i] = origin[i] + t * direction[i] + centre[i];
    }
    if (polyhedron && insideTest)
    {
#pragma omp critical(ppirayPolyhedronEvaluate)
      found = cell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, weights.data());
    }
    else if (polyhedron)
    {
      cell->InterpolateFunctions(x, weights.data()); // a polyhedron's takes x itself
    }
    else if (nonlinear && !insideTest)
    {
      // Inside an interval whose midpoint was found: from there, with the
      // map's inverse Jacobian there.
      // Once that fails in this cell, Newton alone.
      std::copy_n(midpoint, 3, pcoords);
      chordWorks = RefineParametricCoordinates(
        cell, nodes, x, pcoords, weights.data(), derivs, hasChord && chordWorks ? &chord : nullptr);
    }
    else if (nonlinear)
    {
      found = LocateInNonlinearCell(cell, nodes, cornerType, x, pcoords, weights.data(), derivs);
      std::copy_n(pcoords, 3, midpoint);
      hasChord = InverseJacobian(cell, nodes, midpoint, derivs, chord);
    }
    else
    {
      found = cell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, weights.data());
    }
    if (linear)
    {
      linear->InterpolateFunctions(pcoords, weights.data());
    }
    s = 0.0;
    for (int v = 0; v < n; ++v)
    {
      s += weights[v] * values[v];
    }
    // EvaluatePosition itself accepts 1e-3 outside the parametric domain, so
    // the parametric distance decides too; it alone does not (a quadratic
    // tetrahedron's measures r, s, t but not 1 - r - s - t); a polyhedron's
    // says whether x is inside.
    return found == 1 && (polyhedron || cell->GetParametricDistance(pcoords) <= 1e-9);
  };
  // [a, b] with its midpoint m known: the quarter points decide, and become
  // the midpoints of the halves. At most MaximumSplitDepth levels and
  // MaximumPiecesPerCell pieces along the ray in this cell.
  int pieces = 0;
  auto linearize = [&](auto&& self, double a, double sa, double sm, double b, double sb,
                     int depth) -> void
  {
    double sq1, sq3;
    const double m = 0.5 * (a + b);
    evaluate(0.5 * (a + m), sq1, false);
    evaluate(0.5 * (m + b), sq3, false);
    const double deviation = std::max({ std::abs(sm - 0.5 * (sa + sb)),
      std::abs(sq1 - 0.75 * sa - 0.25 * sb), std::abs(sq3 - 0.25 * sa - 0.75 * sb) });
    if (depth >= MaximumSplitDepth || pieces + 2 >= MaximumPiecesPerCell ||
        !(deviation > tolerance))
    {
      pieces += 2;
      unresolved += deviation > tolerance ? 1 : 0;
      out.push_back({ a, m, sa, sm, { 0, 0, 0 }, id });
      out.push_back({ m, b, sm, sb, { 0, 0, 0 }, id });
      return;
    }
    self(self, a, sa, sq1, m, sm, depth + 1);
    self(self, m, sm, sq3, b, sb, depth + 1);
  };
  for (size_t k = 0; k + 1 < ts.size(); ++k)
  {
    const double a = std::max(ts[k], 0.0), b = ts[k + 1];
    double sm;
    if (b > a && evaluate(0.5 * (a + b), sm, true))
    {
      double sa, sb;
      evaluate(a, sa, false);
      evaluate(b, sb, false);
      linearize(linearize, a, sa, sm, b, sb, 0);
    }
  }
}

//------------------------------------------------------------------------------
glm::dvec2 KeptRange(
  const std::vector<glm::dvec4>& planes, const Vec3& origin, const Vec3& direction)
{
  glm::dvec2 range(0.0, std::numeric_limits<double>::infinity());
  for (const glm::dvec4& plane : planes)
  {
    // n . (origin + t direction) + d = b + a t >= 0.
    const double a = glm::dot(Vec3(plane), direction);
    const double b = glm::dot(Vec3(plane), origin) + plane.w;
    if (a > 0)
    {
      range.x = std::max(range.x, -b / a);
    }
    else if (a < 0)
    {
      range.y = std::min(range.y, -b / a);
    }
    else if (b < 0)
    {
      range.y = -1.0;
    }
  }
  return range;
}

//------------------------------------------------------------------------------
void ClipSegments(std::vector<Segment>& segments, const glm::dvec2& range)
{
  if (range.x <= 0 && std::isinf(range.y))
  {
    return;
  }
  size_t kept = 0;
  for (Segment seg : segments)
  {
    const double t0 = std::max(seg.T0, range.x), t1 = std::min(seg.T1, range.y);
    if (!(t1 > t0))
    {
      continue;
    }
    const double slope = seg.T1 > seg.T0 ? (seg.S1 - seg.S0) / (seg.T1 - seg.T0) : 0.0;
    const double s0 = seg.S0 + slope * (t0 - seg.T0), s1 = seg.S0 + slope * (t1 - seg.T0);
    seg.T0 = t0;
    seg.T1 = t1;
    seg.S0 = s0;
    seg.S1 = s1;
    segments[kept++] = seg;
  }
  segments.resize(kept);
}
}
}
