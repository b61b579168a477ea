#include "vtkUnstructuredGridReferenceRenderer.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkCellType.h"
#include "ppirayConformingTetrahedra.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"
#include "ppirayVolumeIntegrals.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

vtkStandardNewMacro(vtkUnstructuredGridReferenceRenderer);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, VolumeProperty, vtkVolumeProperty);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, Lights, vtkLightCollection);

namespace
{
using Vec3 = std::array<double, 3>;

// The transfer function as VTK's volume mappers evaluate it (colour through
// vtkColorTransferFunction::GetTable: its colour space, scale and clamping, a
// vtkDiscretizableColorTransferFunction continuous), as linear pieces between
// Breaks: every colour and opacity node, and between nodes the points of a
// bisection that stops when the function is within Tolerance of linear at
// the quarter points. Each piece keeps the function's one-sided limits at its
// ends, so jumps (repeated nodes, Step colour space, clamping off) are exact.
struct TransferFunction
{
  using RGBTau = std::array<double, 4>;
  vtkColorTransferFunction* Color = nullptr;
  vtkPiecewiseFunction* Gray = nullptr;
  vtkPiecewiseFunction* Opacity = nullptr;
  double UnitDistance = 1.0;
  std::vector<double> Breaks;
  std::vector<RGBTau> Start, End; // piece k: from Breaks[k] to Breaks[k + 1]
  RGBTau Below = { 0, 0, 0, 0 }, Above = { 0, 0, 0, 0 }; // outside the breaks
  // The CIEDE2000 colour space costs a colour-path search per GetTable call
  // and steps its colours by about 1/255: sampled once over its nodes (2^18
  // samples), read as nearest sample.
  std::vector<double> Stepped;
  double SteppedRange[2] = { 0, 0 };

  // (r, g, b, tau) at n >= 2 evenly spaced scalars from x0 to x1 (one
  // GetTable call: CIEDE2000 builds its colour path per call).
  std::vector<RGBTau> Sample(double x0, double x1, int n) const
  {
    std::vector<double> rgb(3 * n, 1.0);
    if (this->Color && this->Stepped.empty() && this->Color->GetScale() == VTK_CTF_LINEAR)
    {
      this->Color->GetTable(x0, x1, n, rgb.data());
    }
    else if (this->Color) // CIEDE2000, or a log scale (GetTable spaces samples in log10)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x = x0 + (x1 - x0) * i / (n - 1);
        const double u =
          (x - this->SteppedRange[0]) / (this->SteppedRange[1] - this->SteppedRange[0]);
        if (u >= 0.0 && u <= 1.0 && !this->Stepped.empty())
        {
          // nearest sample: the colours are steps
          const size_t k = static_cast<size_t>(std::lround(u * (this->Stepped.size() / 3 - 1)));
          std::copy_n(this->Stepped.data() + 3 * k, 3, rgb.data() + 3 * i);
        }
        else
        {
          this->Color->GetTable(x, x, 1, rgb.data() + 3 * i);
        }
      }
    }
    std::vector<RGBTau> v(n);
    for (int i = 0; i < n; ++i)
    {
      const double x = x0 + (x1 - x0) * i / (n - 1);
      for (int c = 0; c < 3; ++c)
      {
        v[i][c] = this->Color ? rgb[3 * i + c] : this->Gray ? this->Gray->GetValue(x) : 1.0;
      }
      v[i][3] = this->Opacity->GetValue(x) / this->UnitDistance;
    }
    return v;
  }

  void Build(vtkVolumeProperty* property, double tolerance)
  {
    this->Opacity = property->GetScalarOpacity(0);
    if (property->GetColorChannels(0) == 3)
    {
      this->Color = property->GetRGBTransferFunction(0);
    }
    else
    {
      this->Gray = property->GetGrayTransferFunction(0);
    }
    this->UnitDistance = property->GetScalarOpacityUnitDistance(0);
    if (!(this->UnitDistance > 0))
    {
      this->UnitDistance = 1.0;
    }
    if (this->Color && this->Color->GetColorSpace() == VTK_CTF_LAB_CIEDE2000 &&
      this->Color->GetScale() == VTK_CTF_LINEAR && this->Color->GetSize() > 1)
    {
      this->Color->GetRange(this->SteppedRange);
      this->Stepped.resize(3 << 18);
      this->Color->GetTable(
        this->SteppedRange[0], this->SteppedRange[1], 1 << 18, this->Stepped.data());
      tolerance = std::max(tolerance, 0.25 / 255);
    }
    std::vector<double> nodes;
    auto collect = [&](int size, auto x) {
      for (int i = 0; i < size; ++i)
      {
        nodes.push_back(x(i));
      }
    };
    auto piecewise = [](vtkPiecewiseFunction* f) {
      return [f](int i) {
        double v[4];
        f->GetNodeValue(i, v);
        return v[0];
      };
    };
    collect(this->Opacity->GetSize(), piecewise(this->Opacity));
    if (this->Color)
    {
      collect(this->Color->GetSize(), [this](int i) {
        double v[6];
        this->Color->GetNodeValue(i, v);
        return v[0];
      });
    }
    else if (this->Gray)
    {
      collect(this->Gray->GetSize(), piecewise(this->Gray));
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    if (nodes.empty())
    {
      nodes.push_back(0.0);
    }
    const double width = std::max(
      { nodes.back() - nodes.front(), std::abs(nodes.front()), std::abs(nodes.back()), 1e-300 });
    const double inside = 1e-13 * width; // one-sided limits are taken this far in
    this->Below = this->Sample(nodes.front() - inside, nodes.front() - inside, 2)[0];
    this->Above = this->Sample(nodes.back() + inside, nodes.back() + inside, 2)[0];
    // Piece [x0, x1] split until linear within tolerance at its quarter points.
    auto bisect = [&](auto&& self, double x0, double x1) -> void {
      const std::vector<RGBTau> v = this->Sample(x0, x1, 5);
      bool linear = true;
      for (int q = 1; q < 4; ++q)
      {
        for (int c = 0; c < 4; ++c)
        {
          const double scale = c == 3 ? 1.0 / this->UnitDistance : 1.0;
          linear = linear &&
            std::abs(v[q][c] - (v[0][c] + (v[4][c] - v[0][c]) * q / 4.0)) <= tolerance * scale;
        }
      }
      if (linear || x1 - x0 <= 4 * inside)
      {
        this->Breaks.push_back(x0);
        this->Start.push_back(v[0]);
        this->End.push_back(v[4]);
        return;
      }
      const double xm = 0.5 * (x0 + x1);
      self(self, x0, xm);
      self(self, xm, x1);
    };
    for (size_t i = 0; i + 1 < nodes.size(); ++i)
    {
      bisect(bisect, nodes[i] + inside, nodes[i + 1] - inside);
    }
    // Pieces were recorded by their start just inside a node; move the first
    // piece of each node segment back onto the node.
    for (double& x : this->Breaks)
    {
      const auto node = std::lower_bound(nodes.begin(), nodes.end(), x - 2 * inside);
      if (node != nodes.end() && std::abs(*node - x) <= 2 * inside)
      {
        x = *node;
      }
    }
    this->Breaks.push_back(nodes.back());
  }

  // The piece holding scalar s (-1: below the first break, Breaks.size() - 1:
  // above the last).
  int Piece(double s) const
  {
    return static_cast<int>(std::upper_bound(this->Breaks.begin(), this->Breaks.end(), s) -
             this->Breaks.begin()) - 1;
  }

  // rgb and tau at s, on piece k (the linear interpolant of its limits).
  void Evaluate(double s, int k, double rgb[3], double& tau) const
  {
    RGBTau v;
    if (k < 0)
    {
      v = this->Below;
    }
    else if (k >= static_cast<int>(this->Start.size()))
    {
      v = this->Above;
    }
    else
    {
      const double x0 = this->Breaks[k], x1 = this->Breaks[k + 1];
      const double w = x1 > x0 ? std::min(1.0, std::max(0.0, (s - x0) / (x1 - x0))) : 0.0;
      for (int c = 0; c < 4; ++c)
      {
        v[c] = (1 - w) * this->Start[k][c] + w * this->End[k][c];
      }
    }
    rgb[0] = v[0];
    rgb[1] = v[1];
    rgb[2] = v[2];
    tau = v[3];
  }
};

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
  double Inverse[3][3];
  double S[4];
};

bool InvertEdges(const double p[4][3], double inverse[3][3])
{
  const double e[3][3] = { { p[1][0] - p[0][0], p[2][0] - p[0][0], p[3][0] - p[0][0] },
    { p[1][1] - p[0][1], p[2][1] - p[0][1], p[3][1] - p[0][1] },
    { p[1][2] - p[0][2], p[2][2] - p[0][2], p[3][2] - p[0][2] } };
  const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
    e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
    e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  double scale = 0;
  for (const auto& row : e)
  {
    for (double v : row)
    {
      scale = std::max(scale, std::abs(v));
    }
  }
  if (!(std::abs(det) > 1e-14 * scale * scale * scale))
  {
    return false; // flat: contributes nothing
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      inverse[r][c] = (e[r1][c1] * e[r2][c2] - e[r1][c2] * e[r2][c1]) / det;
    }
  }
  return true;
}

// The piece of the ray origin + t direction (t >= 0) inside the tetrahedron.
bool ClipRay(const Tetrahedron& tet, const Vec3& origin, const Vec3& direction, Segment& out)
{
  double a[4], b[4];
  const Vec3 q = { origin[0] - tet.P0[0], origin[1] - tet.P0[1], origin[2] - tet.P0[2] };
  a[0] = 1.0;
  b[0] = 0.0;
  for (int r = 0; r < 3; ++r)
  {
    a[r + 1] = tet.Inverse[r][0] * q[0] + tet.Inverse[r][1] * q[1] + tet.Inverse[r][2] * q[2];
    b[r + 1] = tet.Inverse[r][0] * direction[0] + tet.Inverse[r][1] * direction[1] +
      tet.Inverse[r][2] * direction[2];
    a[0] -= a[r + 1];
    b[0] -= b[r + 1];
  }
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
  auto scalar = [&](double t) {
    double s = 0;
    for (int v = 0; v < 4; ++v)
    {
      s += (a[v] + b[v] * t) * tet.S[v];
    }
    return s;
  };
  out = { t0, t1, scalar(t0), scalar(t1) };
  // grad s = sum_v S_v grad lambda_v = Inverse^T (S_1 - S_0, S_2 - S_0, S_3 - S_0).
  for (int i = 0; i < 3; ++i)
  {
    out.Gradient[i] = 0;
    for (int r = 0; r < 3; ++r)
    {
      out.Gradient[i] += tet.Inverse[r][i] * (tet.S[r + 1] - tet.S[0]);
    }
  }
  return true;
}

Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Ray parameters t where origin + t direction crosses a cell face: a triangle
// (Moller-Trumbore), or a quadrilateral as the bilinear patch
// P(u, v) = (1-u)(1-v) p0 + u (1-v) p1 + u v p2 + (1-u) v p3 that the cell's
// interpolation spans (planar or not): with n1, n2 orthogonal to the ray,
// A(u, v) = (P - o) . n1 = 0 and B(u, v) = (P - o) . n2 = 0 are bilinear;
// eliminating u leaves a quadratic in v.
void FaceCrossings(
  const std::vector<Vec3>& p, const Vec3& o, const Vec3& d, std::vector<double>& ts)
{
  const double eps = 1e-12;
  auto sub = [](const Vec3& a, const Vec3& b) {
    return Vec3{ a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  };
  if (p.size() == 3)
  {
    const Vec3 e1 = sub(p[1], p[0]), e2 = sub(p[2], p[0]);
    const Vec3 h = Cross(d, e2);
    const double a = Dot(e1, h);
    if (std::abs(a) < 1e-300)
    {
      return;
    }
    const Vec3 s = sub(o, p[0]);
    const double u = Dot(s, h) / a;
    const Vec3 q = Cross(s, e1);
    const double v = Dot(d, q) / a;
    if (u >= -eps && v >= -eps && u + v <= 1 + eps)
    {
      ts.push_back(Dot(e2, q) / a);
    }
    return;
  }
  // Two unit vectors orthogonal to d.
  const Vec3 axis = std::abs(d[0]) < 0.6 ? Vec3{ 1, 0, 0 } : Vec3{ 0, 1, 0 };
  Vec3 n1 = Cross(d, axis);
  const double l1 = std::sqrt(Dot(n1, n1));
  for (double& x : n1)
  {
    x /= l1;
  }
  const Vec3 n2 = Cross(d, n1);
  double a[4], b[4];
  for (int i = 0; i < 4; ++i)
  {
    const Vec3 r = sub(p[i], o);
    a[i] = Dot(r, n1);
    b[i] = Dot(r, n2);
  }
  // A = A0 + Au u + Av v + Auv u v, likewise B.
  const double A0 = a[0], Au = a[1] - a[0], Av = a[3] - a[0], Auv = a[0] - a[1] + a[2] - a[3];
  const double B0 = b[0], Bu = b[1] - b[0], Bv = b[3] - b[0], Buv = b[0] - b[1] + b[2] - b[3];
  const double c2 = Bv * Auv - Av * Buv;
  const double c1 = B0 * Auv + Bv * Au - A0 * Buv - Av * Bu;
  const double c0 = B0 * Au - A0 * Bu;
  double roots[2];
  int count = 0;
  const double scale = std::max({ std::abs(c0), std::abs(c1), std::abs(c2), 1e-300 });
  if (std::abs(c2) < 1e-12 * scale)
  {
    if (std::abs(c1) > 1e-300)
    {
      roots[count++] = -c0 / c1;
    }
  }
  else
  {
    const double disc = c1 * c1 - 4 * c2 * c0;
    if (disc >= 0)
    {
      // Stable quadratic roots.
      const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
      roots[count++] = q / c2;
      if (q != 0)
      {
        roots[count++] = c0 / q;
      }
    }
  }
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
    Vec3 point;
    for (int i = 0; i < 3; ++i)
    {
      point[i] = (1 - u) * (1 - v) * p[0][i] + u * (1 - v) * p[1][i] + u * v * p[2][i] +
        (1 - u) * v * p[3][i];
    }
    ts.push_back(Dot(sub(point, o), d));
  }
}

// The corners a linear 3D cell interpolates from: a cell may list more point
// ids than its type has corners (a 20-node serendipity hexahedron written as
// VTK_HEXAHEDRON); the type's own functions use the first ones.
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

// The pieces of the ray inside a hexahedron, voxel, wedge or pyramid, with the
// cell's own (isoparametric) interpolation: the ray's crossings with every
// face (FaceCrossings) cut it into intervals, an interval whose midpoint is
// inside the cell (parametric distance 0) is inside; each inside interval is
// split until the interpolated scalar is linear along the ray within
// `tolerance` at its quarter points and midpoint, and every piece is then
// integrated exactly like a tetrahedron's. `cellId` >= 0 selects cell scalars.
// A piece is split at most MaximumSplitDepth times; `unresolved` counts the
// pieces accepted there without meeting the tolerance.
constexpr int MaximumSplitDepth = 24;
void GeneralCellSegments(vtkIdType id, vtkGenericCell* cell, vtkDataArray* scalars,
  vtkIdType cellId, const Vec3& origin, const Vec3& direction, const Vec3& centre, double tolerance,
  std::vector<Segment>& out, long long& unresolved)
{
  const int n = InterpolatedPoints(cell);
  std::vector<double> weights(std::max(static_cast<int>(cell->GetNumberOfPoints()), 8)), values(n);
  for (int v = 0; v < n; ++v)
  {
    values[v] = cellId >= 0 ? scalars->GetComponent(cellId, 0)
                            : scalars->GetComponent(cell->GetPointId(v), 0);
    if (std::isnan(values[v]))
    {
      return; // a cell with a NaN scalar is empty, as in the mapper
    }
  }
  std::vector<double> ts = { 0.0 };
  std::vector<Vec3> corners;
  for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
  {
    vtkCell* face = cell->GetFace(f);
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
  auto evaluate = [&](double t, double& s) {
    double x[3], pcoords[3], dist2;
    int subId;
    for (int i = 0; i < 3; ++i)
    {
      x[i] = origin[i] + t * direction[i] + centre[i];
    }
    const int found = cell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, weights.data());
    s = 0.0;
    for (int v = 0; v < n; ++v)
    {
      s += weights[v] * values[v];
    }
    // EvaluatePosition itself accepts 1e-3 outside the parametric domain.
    return found != -1 && cell->GetParametricDistance(pcoords) <= 1e-9;
  };
  // [a, b] with its midpoint m known: the quarter points decide, and become
  // the midpoints of the halves.
  auto linearize = [&](auto&& self, double a, double sa, double sm, double b, double sb,
                     int depth) -> void {
    double sq1, sq3;
    const double m = 0.5 * (a + b);
    evaluate(0.5 * (a + m), sq1);
    evaluate(0.5 * (m + b), sq3);
    const double deviation = std::max({ std::abs(sm - 0.5 * (sa + sb)),
      std::abs(sq1 - 0.75 * sa - 0.25 * sb), std::abs(sq3 - 0.25 * sa - 0.75 * sb) });
    if (depth >= MaximumSplitDepth || !(deviation > tolerance))
    {
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
    if (b > a && evaluate(0.5 * (a + b), sm))
    {
      double sa, sb;
      evaluate(a, sa);
      evaluate(b, sb);
      linearize(linearize, a, sa, sm, b, sb, 0);
    }
  }
}

// Isosurfaces: the values (ascending), the transfer function's colour and
// opacity there, and Phong lighting with the property's coefficients and the
// lights (world coordinates; positional lights as point lights).
struct IsoSurfaces
{
  int Mode = 0; // 0: none, 1: embedded in the volume, 2: surfaces only
  std::vector<double> Values;
  std::vector<std::array<double, 4>> Colors;
  bool Shade = false;
  double Ambient = 0, Diffuse = 1, Specular = 0, Power = 1;
  struct Light
  {
    bool Positional;
    Vec3 Vector; // towards the light (directional), or its position
    Vec3 DiffuseColor, SpecularColor; // times intensity
  };
  std::vector<Light> Lights;

  // The next surface crossed from interval j (number of values <= s) on the
  // way to s, or -1; j moves past it.
  int NextCrossing(double s, int& j) const
  {
    if (j < static_cast<int>(this->Values.size()) && this->Values[j] <= s)
    {
      return j++;
    }
    if (j > 0 && this->Values[j - 1] > s)
    {
      return --j;
    }
    return -1;
  }

  // Phong: C (Ka + Kd sum_l max(n.l, 0) D_l) + Ks sum_l [n.l > 0] max(n.h, 0)^P S_l,
  // n the normalized gradient turned towards the viewer.
  void Shaded(int i, const Vec3& x, const Vec3& g, const Vec3& direction, double rgb[3]) const
  {
    const auto& c = this->Colors[i];
    if (!this->Shade)
    {
      std::copy(c.begin(), c.begin() + 3, rgb);
      return;
    }
    const Vec3 view = { -direction[0], -direction[1], -direction[2] };
    const double norm = std::sqrt(Dot(g, g));
    Vec3 n = norm > 0 ? Vec3{ g[0] / norm, g[1] / norm, g[2] / norm } : view;
    if (Dot(n, view) < 0)
    {
      n = { -n[0], -n[1], -n[2] };
    }
    double diffuse[3] = { 0, 0, 0 }, specular[3] = { 0, 0, 0 };
    for (const Light& light : this->Lights)
    {
      Vec3 l = light.Vector;
      if (light.Positional)
      {
        l = { l[0] - x[0], l[1] - x[1], l[2] - x[2] };
        const double d = std::sqrt(Dot(l, l));
        l = { l[0] / d, l[1] / d, l[2] / d };
      }
      const double nl = Dot(n, l);
      if (nl <= 0)
      {
        continue;
      }
      Vec3 h = { l[0] + view[0], l[1] + view[1], l[2] + view[2] };
      const double hn = std::sqrt(Dot(h, h));
      const double nh = hn > 0 ? std::max(0.0, Dot(n, h) / hn) : 0.0;
      const double highlight = std::pow(nh, this->Power);
      for (int k = 0; k < 3; ++k)
      {
        diffuse[k] += nl * light.DiffuseColor[k];
        specular[k] += highlight * light.SpecularColor[k];
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      rgb[k] = c[k] * (this->Ambient + this->Diffuse * diffuse[k]) + this->Specular * specular[k];
    }
  }
};

// The isosurfaces of `property` in `mode` (IsoSurfaces::Mode), lit by `lights`.
IsoSurfaces BuildIsoSurfaces(vtkVolumeProperty* property, int mode, vtkLightCollection* lights)
{
  IsoSurfaces iso;
  vtkContourValues* contours = property->GetIsoSurfaceValues();
  iso.Mode =
    (mode == 2 || contours->GetNumberOfContours() > 0) ? mode : 0; // 2 without values: empty
  if (!iso.Mode)
  {
    return iso;
  }
  for (int i = 0; i < contours->GetNumberOfContours(); ++i)
  {
    if (!std::isnan(contours->GetValue(i)))
    {
      iso.Values.push_back(contours->GetValue(i));
    }
  }
  std::sort(iso.Values.begin(), iso.Values.end());
  iso.Values.erase(std::unique(iso.Values.begin(), iso.Values.end()), iso.Values.end());
  for (double v : iso.Values)
  {
    std::array<double, 4> c = { 1, 1, 1, 1 };
    if (property->GetColorChannels(0) == 3)
    {
      property->GetRGBTransferFunction(0)->GetTable(v, v, 1, c.data());
    }
    else
    {
      c[0] = c[1] = c[2] = property->GetGrayTransferFunction(0)->GetValue(v);
    }
    c[3] = std::min(1.0, std::max(0.0, property->GetScalarOpacity(0)->GetValue(v)));
    iso.Colors.push_back(c);
  }
  iso.Shade = property->GetShade(0) != 0;
  iso.Ambient = property->GetAmbient(0);
  iso.Diffuse = property->GetDiffuse(0);
  iso.Specular = property->GetSpecular(0);
  iso.Power = property->GetSpecularPower(0);
  if (lights)
  {
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      if (!light->GetSwitch())
      {
        continue;
      }
      IsoSurfaces::Light l;
      double position[3], focalPoint[3];
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focalPoint);
      l.Positional = light->GetPositional() != 0;
      Vec3 towards = { position[0] - focalPoint[0], position[1] - focalPoint[1],
        position[2] - focalPoint[2] };
      const double norm = std::sqrt(Dot(towards, towards));
      for (int k = 0; k < 3; ++k)
      {
        l.Vector[k] = l.Positional ? position[k] : towards[k] / norm;
        l.DiffuseColor[k] = light->GetIntensity() * light->GetDiffuseColor()[k];
        l.SpecularColor[k] = light->GetIntensity() * light->GetSpecularColor()[k];
      }
      iso.Lights.push_back(l);
    }
  }
  return iso;
}

// Front-to-back composite of the sorted, de-overlapped segments, each split
// at every transfer-function break and integrated in closed form; with
// isosurfaces, also split where the scalar crosses an isovalue (and at jumps
// between cells), the surface composited there. `gradientAt(cell, t)`: the
// field gradient of a general cell at ray parameter t.
template <typename GradientAt>
void IntegrateRay(std::vector<Segment>& segments, const TransferFunction& tf,
  const IsoSurfaces& iso, const Vec3& origin, const Vec3& direction, const Vec3& centre,
  GradientAt&& gradientAt, float rgba[4])
{
  std::sort(segments.begin(), segments.end(),
    [](const Segment& x, const Segment& y) { return x.T0 < y.T0; });
  double color[3] = { 0, 0, 0 };
  double transmittance = 1.0;
  double reached = -std::numeric_limits<double>::infinity();
  std::vector<double> cuts;
  // The volume on [t0, t1] where s goes linearly from s0 to s1.
  auto integrateLinear = [&](double t0, double t1, double s0, double s1) {
    cuts.assign({ 0.0, 1.0 });
    const double lo = std::min(s0, s1), hi = std::max(s0, s1);
    auto first = std::upper_bound(tf.Breaks.begin(), tf.Breaks.end(), lo);
    for (auto it = first; it != tf.Breaks.end() && *it < hi; ++it)
    {
      cuts.push_back((*it - s0) / (s1 - s0));
    }
    std::sort(cuts.begin(), cuts.end());
    for (size_t k = 0; k + 1 < cuts.size(); ++k)
    {
      const double u0 = cuts[k], u1 = cuts[k + 1];
      const double length = (u1 - u0) * (t1 - t0);
      if (!(length > 0))
      {
        continue;
      }
      // The transfer-function piece this ray piece lies in, found at its
      // middle: at a jump both ends are on a break.
      const double sa = s0 + (s1 - s0) * u0, sb = s0 + (s1 - s0) * u1;
      const int piece = tf.Piece(s0 + (s1 - s0) * 0.5 * (u0 + u1));
      double ca[3], cb[3], taua, taub, emitted[3], transparency;
      tf.Evaluate(sa, piece, ca, taua);
      tf.Evaluate(sb, piece, cb, taub);
      ppiray::IntegrateLinearPiece(ca, taua, cb, taub, length, emitted, transparency);
      for (int c = 0; c < 3; ++c)
      {
        color[c] += transmittance * emitted[c];
      }
      transmittance *= transparency;
    }
  };
  auto surface = [&](int i, const Segment& seg, double t) {
    const Vec3 x = { origin[0] + t * direction[0] + centre[0],
      origin[1] + t * direction[1] + centre[1], origin[2] + t * direction[2] + centre[2] };
    double rgb[3];
    iso.Shaded(i, x, seg.Cell < 0 ? seg.Gradient : gradientAt(seg.Cell, t), direction, rgb);
    const double alpha = iso.Colors[i][3];
    for (int c = 0; c < 3; ++c)
    {
      color[c] += transmittance * alpha * rgb[c];
    }
    transmittance *= 1.0 - alpha;
  };
  int j = -1; // isovalue interval along the ray, reset where the ray leaves the mesh
  for (Segment seg : segments)
  {
    if (seg.T1 <= reached)
    {
      continue;
    }
    const bool gap = seg.T0 > reached + 1e-9 * std::max(std::abs(reached), seg.T1 - seg.T0);
    if (seg.T0 < reached)
    {
      seg.S0 += (seg.S1 - seg.S0) * (reached - seg.T0) / (seg.T1 - seg.T0);
      seg.T0 = reached;
    }
    reached = seg.T1;
    if (!iso.Mode)
    {
      integrateLinear(seg.T0, seg.T1, seg.S0, seg.S1);
      continue;
    }
    if (j < 0 || gap)
    {
      j = static_cast<int>(
        std::upper_bound(iso.Values.begin(), iso.Values.end(), seg.S0) - iso.Values.begin());
    }
    for (int i; (i = iso.NextCrossing(seg.S0, j)) >= 0;)
    {
      surface(i, seg, seg.T0); // the scalar jumped at the cell boundary
    }
    double t = seg.T0, s = seg.S0;
    for (int i; (i = iso.NextCrossing(seg.S1, j)) >= 0;)
    {
      const double v = iso.Values[i];
      const double tv = seg.S1 == seg.S0
                          ? t
                          : std::min(seg.T1, std::max(t, seg.T0 + (v - seg.S0) / (seg.S1 - seg.S0) *
                                                                    (seg.T1 - seg.T0)));
      if (iso.Mode == 1)
      {
        integrateLinear(t, tv, s, v);
      }
      surface(i, seg, tv);
      t = tv;
      s = v;
    }
    if (iso.Mode == 1)
    {
      integrateLinear(t, seg.T1, s, seg.S1);
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    rgba[c] = static_cast<float>(color[c]);
  }
  rgba[3] = static_cast<float>(1.0 - transmittance);
}
}

//------------------------------------------------------------------------------
vtkUnstructuredGridReferenceRenderer::vtkUnstructuredGridReferenceRenderer()
{
  this->SetNumberOfInputPorts(1);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkUnstructuredGridReferenceRenderer::~vtkUnstructuredGridReferenceRenderer()
{
  this->SetVolumeProperty(nullptr);
  this->SetCamera(nullptr);
  this->SetLights(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkUnstructuredGridReferenceRenderer::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->VolumeProperty)
  {
    time = std::max(time, this->VolumeProperty->GetMTime());
  }
  if (this->Camera)
  {
    time = std::max(time, this->Camera->GetMTime());
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridReferenceRenderer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridReferenceRenderer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->ImageSize[0] - 1, 0, this->ImageSize[1] - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 4);
  return 1;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridReferenceRenderer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  vtkNew<vtkFloatArray> rgba;
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  rgba->Fill(0.0);
  output->GetPointData()->SetScalars(rgba);
  if (!this->VolumeProperty || !this->Camera || !this->VolumeProperty->GetScalarOpacity(0))
  {
    vtkErrorMacro("A volume property with a scalar opacity function and a camera are required.");
    return 1;
  }
  if (!input || input->GetNumberOfCells() == 0)
  {
    return 1;
  }
  int association = 0;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, input, association);
  if (!scalars)
  {
    vtkErrorMacro("No scalars to render.");
    return 1;
  }
  const bool cellScalars = association == vtkDataObject::FIELD_ASSOCIATION_CELLS;

  std::vector<vtkIdType> tets, cellIds, unsupported;
  ppiray::ExtractTetrahedra(input, tets, cellIds, unsupported);
  // Quadratic and higher-order tetrahedra: the linear tetrahedron of their
  // corners (the first four points), as the mapper renders them.
  vtkIdType cornerTets = 0;
  for (size_t u = 0; u < unsupported.size(); u += 2)
  {
    const int type = static_cast<int>(unsupported[u]);
    if (type != VTK_QUADRATIC_TETRA && type != VTK_LAGRANGE_TETRAHEDRON &&
      type != VTK_BEZIER_TETRAHEDRON)
    {
      continue;
    }
    for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
    {
      if (input->GetCellType(c) == type)
      {
        vtkIdType npts;
        const vtkIdType* pts;
        input->GetCellPoints(c, npts, pts);
        tets.insert(tets.end(), pts, pts + 4);
        cellIds.push_back(c);
        ++cornerTets;
      }
    }
  }
  if (cornerTets)
  {
    vtkWarningMacro(<< cornerTets << " higher-order tetrahedra rendered through their corners.");
  }
  const vtkIdType numberOfTets = static_cast<vtkIdType>(cellIds.size());
  // Hexahedra, voxels, wedges and pyramids take the general path; their
  // points in CSR form.
  std::vector<vtkIdType> generalCells, generalOffsets = { 0 }, generalPoints;
  vtkIdType skipped = 0;
  if (!unsupported.empty())
  {
    for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
    {
      const int type = input->GetCellType(c);
      if (type == VTK_TETRA || type == VTK_QUADRATIC_TETRA || type == VTK_LAGRANGE_TETRAHEDRON ||
        type == VTK_BEZIER_TETRAHEDRON)
      {
        continue;
      }
      if (type != VTK_HEXAHEDRON && type != VTK_VOXEL && type != VTK_WEDGE && type != VTK_PYRAMID)
      {
        ++skipped;
        continue;
      }
      vtkIdType npts;
      const vtkIdType* pts;
      input->GetCellPoints(c, npts, pts);
      generalCells.push_back(c);
      generalPoints.insert(generalPoints.end(), pts, pts + npts);
      generalOffsets.push_back(static_cast<vtkIdType>(generalPoints.size()));
    }
  }
  if (skipped)
  {
    vtkWarningMacro(<< skipped << " cells of other types than linear 3D cells skipped.");
  }
  const vtkIdType numberOfItems = numberOfTets + static_cast<vtkIdType>(generalCells.size());
  double scalarRange[2];
  scalars->GetRange(scalarRange, 0);
  const double linearTolerance =
    this->QuadratureTolerance * std::max(scalarRange[1] - scalarRange[0], 1e-300);

  TransferFunction tf;
  tf.Build(this->VolumeProperty, this->TransferFunctionTolerance);
  const IsoSurfaces iso = BuildIsoSurfaces(this->VolumeProperty,
    this->BlendMode == ISOSURFACE_BLEND ? 2 : (this->EmbedIsoSurfaces ? 1 : 0), this->Lights);

  // Camera: clip <-> world, with world shifted to the centre of the bounds.
  double bounds[6];
  input->GetBounds(bounds);
  const Vec3 centre = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  vtkNew<vtkMatrix4x4> worldToClip, clipToWorld;
  worldToClip->DeepCopy(this->Camera->GetCompositeProjectionTransformMatrix(
    static_cast<double>(width) / height, -1, 1));
  vtkMatrix4x4::Invert(worldToClip, clipToWorld);

  // Project the points: pixel coordinates (pixel i's centre at i), or flag
  // those at or behind the eye plane.
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  std::vector<double> pixel(2 * numberOfPoints);
  std::vector<unsigned char> behind(numberOfPoints, 0);
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    double x[4] = { 0, 0, 0, 1 };
    input->GetPoint(p, x);
    double clip[4];
    worldToClip->MultiplyPoint(x, clip);
    if (!(clip[3] > 1e-12))
    {
      behind[p] = 1;
      continue;
    }
    pixel[2 * p] = (clip[0] / clip[3] + 1.0) * 0.5 * width - 0.5;
    pixel[2 * p + 1] = (clip[1] / clip[3] + 1.0) * 0.5 * height - 0.5;
  }

  // Bin tetrahedra into 16 x 16 pixel tiles by their projected bounding box.
  constexpr int TileSize = 16;
  const int tilesX = (width + TileSize - 1) / TileSize, tilesY = (height + TileSize - 1) / TileSize;
  // Tile range of item t: tetrahedron t, or general cell t - numberOfTets.
  auto tileRange = [&](vtkIdType t, int range[4]) {
    double lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 };
    const vtkIdType* itemPoints = t < numberOfTets
      ? tets.data() + 4 * t
      : generalPoints.data() + generalOffsets[t - numberOfTets];
    const vtkIdType itemSize = t < numberOfTets
      ? 4
      : generalOffsets[t - numberOfTets + 1] - generalOffsets[t - numberOfTets];
    for (vtkIdType v = 0; v < itemSize; ++v)
    {
      const vtkIdType p = itemPoints[v];
      if (behind[p])
      {
        range[0] = range[2] = 0;
        range[1] = tilesX - 1;
        range[3] = tilesY - 1;
        return;
      }
      for (int i = 0; i < 2; ++i)
      {
        lo[i] = std::min(lo[i], pixel[2 * p + i]);
        hi[i] = std::max(hi[i], pixel[2 * p + i]);
      }
    }
    const int limits[2] = { width - 1, height - 1 };
    for (int i = 0; i < 2; ++i)
    {
      const int a = static_cast<int>(std::floor(std::max(lo[i] - 1.0, -1.0)));
      const int b = static_cast<int>(std::ceil(std::min(hi[i] + 1.0, limits[i] + 1.0)));
      range[2 * i] = std::max(0, a) / TileSize;
      range[2 * i + 1] = std::min(limits[i], std::max(b, 0)) / TileSize;
      if (b < 0 || a > limits[i])
      {
        range[2 * i + 1] = range[2 * i] - 1; // off screen
      }
    }
  };
  // Pixel box of each general cell, its corners' projections widened by a
  // pixel: a linear 3D cell lies in the convex hull of its corners (bilinear
  // faces included), so a ray outside the box misses the cell. Everything
  // when a corner is behind the eye.
  std::vector<std::array<double, 4>> generalBox(generalCells.size());
  for (size_t g = 0; g < generalCells.size(); ++g)
  {
    auto& box = generalBox[g];
    box = { 1e300, -1e300, 1e300, -1e300 };
    for (vtkIdType k = generalOffsets[g]; k < generalOffsets[g + 1]; ++k)
    {
      const vtkIdType p = generalPoints[k];
      if (behind[p])
      {
        box = { -1e300, 1e300, -1e300, 1e300 };
        break;
      }
      for (int i = 0; i < 2; ++i)
      {
        box[2 * i] = std::min(box[2 * i], pixel[2 * p + i] - 1.0);
        box[2 * i + 1] = std::max(box[2 * i + 1], pixel[2 * p + i] + 1.0);
      }
    }
  }
  std::vector<vtkIdType> tileOffsets(static_cast<size_t>(tilesX) * tilesY + 1, 0);
  for (vtkIdType t = 0; t < numberOfItems; ++t)
  {
    int r[4];
    tileRange(t, r);
    for (int ty = r[2]; ty <= r[3]; ++ty)
    {
      for (int tx = r[0]; tx <= r[1]; ++tx)
      {
        ++tileOffsets[static_cast<size_t>(ty) * tilesX + tx + 1];
      }
    }
  }
  for (size_t i = 1; i < tileOffsets.size(); ++i)
  {
    tileOffsets[i] += tileOffsets[i - 1];
  }
  std::vector<vtkIdType> tileTets(tileOffsets.back());
  {
    std::vector<vtkIdType> fill(tileOffsets.begin(), tileOffsets.end() - 1);
    for (vtkIdType t = 0; t < numberOfItems; ++t)
    {
      int r[4];
      tileRange(t, r);
      for (int ty = r[2]; ty <= r[3]; ++ty)
      {
        for (int tx = r[0]; tx <= r[1]; ++tx)
        {
          tileTets[fill[static_cast<size_t>(ty) * tilesX + tx]++] = t;
        }
      }
    }
  }

  float* out = rgba->GetPointer(0);
  const int numberOfTiles = tilesX * tilesY;
  std::atomic<int> tilesDone(0);
  std::atomic<long long> unresolvedPieces(0);
  const std::thread::id caller = std::this_thread::get_id();
  this->UpdateProgress(0.0);
#pragma omp parallel for schedule(dynamic)
  for (int tile = 0; tile < numberOfTiles; ++tile)
  {
    const int tx = tile % tilesX, ty = tile / tilesX;
    long long unresolved = 0;
    std::vector<Tetrahedron> local;
    std::vector<size_t> localGeneral; // indices into generalCells
    vtkNew<vtkGenericCell> cell;
    vtkNew<vtkGenericCell> gradientCell;
    std::vector<double> values, weights, derivatives;
    Vec3 origin, direction;
    // The interpolated field's gradient in general cell c at the ray's t.
    auto gradientAt = [&](vtkIdType c, double t) -> Vec3 {
      if (cellScalars)
      {
        return { 0, 0, 0 };
      }
      input->GetCell(c, gradientCell);
      const int n = InterpolatedPoints(gradientCell);
      values.resize(n);
      weights.resize(std::max(n, 8));
      for (int v = 0; v < n; ++v)
      {
        values[v] = scalars->GetComponent(gradientCell->GetPointId(v), 0);
      }
      double x[3], pcoords[3], dist2, g[3] = { 0, 0, 0 };
      for (int i = 0; i < 3; ++i)
      {
        x[i] = origin[i] + t * direction[i] + centre[i];
      }
      int subId = 0;
      gradientCell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, weights.data());
      gradientCell->Derivatives(subId, pcoords, values.data(), 1, g);
      return { g[0], g[1], g[2] };
    };
    for (vtkIdType k = tileOffsets[tile]; k < tileOffsets[tile + 1]; ++k)
    {
      const vtkIdType t = tileTets[k];
      if (t >= numberOfTets)
      {
        localGeneral.push_back(static_cast<size_t>(t - numberOfTets));
        continue;
      }
      double p[4][3];
      Tetrahedron tet;
      for (int v = 0; v < 4; ++v)
      {
        const vtkIdType id = tets[4 * t + v];
        input->GetPoints()->GetPoint(id, p[v]);
        for (int i = 0; i < 3; ++i)
        {
          p[v][i] -= centre[i];
        }
        tet.S[v] = cellScalars ? scalars->GetComponent(cellIds[t], 0)
                               : scalars->GetComponent(id, 0);
      }
      if (std::isnan(tet.S[0] + tet.S[1] + tet.S[2] + tet.S[3]) || !InvertEdges(p, tet.Inverse))
      {
        continue;
      }
      tet.P0 = { p[0][0], p[0][1], p[0][2] };
      local.push_back(tet);
    }
    std::vector<Segment> segments;
    for (int py = ty * TileSize; py < std::min(height, (ty + 1) * TileSize); ++py)
    {
      for (int px = tx * TileSize; px < std::min(width, (tx + 1) * TileSize); ++px)
      {
        double ndcNear[4] = { 2.0 * (px + 0.5) / width - 1.0, 2.0 * (py + 0.5) / height - 1.0,
          -1.0, 1.0 };
        double ndcFar[4] = { ndcNear[0], ndcNear[1], 1.0, 1.0 };
        double nearPoint[4], farPoint[4];
        clipToWorld->MultiplyPoint(ndcNear, nearPoint);
        clipToWorld->MultiplyPoint(ndcFar, farPoint);
        double length = 0;
        for (int i = 0; i < 3; ++i)
        {
          origin[i] = nearPoint[i] / nearPoint[3] - centre[i];
          direction[i] = farPoint[i] / farPoint[3] - centre[i] - origin[i];
          length += direction[i] * direction[i];
        }
        length = std::sqrt(length);
        for (double& d : direction)
        {
          d /= length;
        }
        segments.clear();
        for (const Tetrahedron& tet : local)
        {
          Segment seg;
          if (ClipRay(tet, origin, direction, seg))
          {
            segments.push_back(seg);
          }
        }
        for (size_t g : localGeneral)
        {
          const auto& box = generalBox[g];
          if (px < box[0] || px > box[1] || py < box[2] || py > box[3]) // pixel centres at integers
          {
            continue;
          }
          const vtkIdType c = generalCells[g];
          input->GetCell(c, cell);
          GeneralCellSegments(c, cell, scalars, cellScalars ? c : -1, origin, direction, centre,
            linearTolerance, segments, unresolved);
        }
        IntegrateRay(segments, tf, iso, origin, direction, centre, gradientAt,
          out + 4 * (static_cast<size_t>(py) * width + px));
      }
    }
    unresolvedPieces += unresolved;
    const int done = ++tilesDone;
    if (std::this_thread::get_id() == caller) // observers run on the calling thread only
    {
      this->UpdateProgress(static_cast<double>(done) / numberOfTiles);
    }
  }
  this->UpdateProgress(1.0);
  if (unresolvedPieces > 0)
  {
    vtkWarningMacro(<< unresolvedPieces << " ray pieces in general cells were split "
                    << MaximumSplitDepth << " times and still not linear within "
                    << "QuadratureTolerance: the image may be off by more there.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "TransferFunctionTolerance: " << this->TransferFunctionTolerance << "\n";
  os << indent << "QuadratureTolerance: " << this->QuadratureTolerance << "\n";
  os << indent << "BlendMode: " << this->BlendMode << "\n";
  os << indent << "EmbedIsoSurfaces: " << this->EmbedIsoSurfaces << "\n";
  os << indent << "Lights: " << this->Lights << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
}
