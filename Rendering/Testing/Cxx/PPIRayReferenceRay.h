// Test-only CPU integration of single rays, independent of the mapper: every
// tetrahedron is clipped against the ray by brute force (no adjacency), the
// transfer function is read from the VTK functions directly (no control point
// code), and each piece is integrated by composite Gauss-Legendre quadrature of
//   I = int_0^D C(x) tau(x) exp(-int_0^x tau) dx        (no Psi table)
// with the pieces split at every colour and opacity node. Slow (O(cells) per
// ray): for checking a few dozen pixels.
#ifndef PPIRayReferenceRay_h
#define PPIRayReferenceRay_h

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkCellData.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ppiray_test
{
struct Ray
{
  std::array<double, 3> Origin;
  std::array<double, 3> Direction; // unit
};

// The ray through the centre of pixel (px, py) of `ren` (window size w x h).
inline Ray PixelRay(vtkRenderer* ren, int px, int py, int w, int h)
{
  vtkMatrix4x4* m = ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    static_cast<double>(w) / h, -1, 1);
  vtkNew<vtkMatrix4x4> inv;
  vtkMatrix4x4::Invert(m, inv);
  const double x = 2.0 * (px + 0.5) / w - 1.0, y = 2.0 * (py + 0.5) / h - 1.0;
  double nearP[4] = { x, y, -1.0, 1.0 }, farP[4] = { x, y, 1.0, 1.0 };
  inv->MultiplyPoint(nearP, nearP);
  inv->MultiplyPoint(farP, farP);
  Ray ray;
  double length = 0;
  for (int i = 0; i < 3; ++i)
  {
    ray.Origin[i] = nearP[i] / nearP[3];
    ray.Direction[i] = farP[i] / farP[3] - ray.Origin[i];
    length += ray.Direction[i] * ray.Direction[i];
  }
  for (double& v : ray.Direction)
  {
    v /= std::sqrt(length);
  }
  return ray;
}

struct Segment
{
  double T0, T1, S0, S1;
};

// Pieces of the ray inside each tetrahedron, sorted front to back.
inline std::vector<Segment> RaySegments(vtkUnstructuredGrid* grid, const Ray& ray, bool cellScalars)
{
  std::vector<Segment> segments;
  vtkDataArray* scalars =
    cellScalars ? grid->GetCellData()->GetScalars() : grid->GetPointData()->GetScalars();
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    grid->GetCellPoints(c, npts, pts);
    if (npts != 4)
    {
      continue;
    }
    double p[4][3], s[4];
    for (int v = 0; v < 4; ++v)
    {
      grid->GetPoint(pts[v], p[v]);
      s[v] = cellScalars ? scalars->GetTuple1(c) : scalars->GetTuple1(pts[v]);
    }
    // Barycentric coordinates along the ray: lambda_v(t) = a_v + b_v t.
    auto sub = [](const double* a, const double* b) {
      return std::array<double, 3>{ a[0] - b[0], a[1] - b[1], a[2] - b[2] };
    };
    auto det3 = [](const std::array<double, 3>& a, const std::array<double, 3>& b,
                  const std::array<double, 3>& cc) {
      return a[0] * (b[1] * cc[2] - b[2] * cc[1]) - a[1] * (b[0] * cc[2] - b[2] * cc[0]) +
        a[2] * (b[0] * cc[1] - b[1] * cc[0]);
    };
    const auto e1 = sub(p[1], p[0]), e2 = sub(p[2], p[0]), e3 = sub(p[3], p[0]);
    const double det = det3(e1, e2, e3);
    if (std::abs(det) < 1e-14)
    {
      continue;
    }
    const auto q = sub(ray.Origin.data(), p[0]);
    const auto& d = ray.Direction;
    // Cramer: x - p0 = l1 e1 + l2 e2 + l3 e3.
    const double a1 = det3(q, e2, e3) / det, a2 = det3(e1, q, e3) / det,
                 a3 = det3(e1, e2, q) / det;
    const double b1 = det3(d, e2, e3) / det, b2 = det3(e1, d, e3) / det,
                 b3 = det3(e1, e2, d) / det;
    const double a[4] = { 1 - a1 - a2 - a3, a1, a2, a3 };
    const double b[4] = { -b1 - b2 - b3, b1, b2, b3 };
    // a_v + b_v t >= 0 for all v. A ray parallel to a face (|b_v| tiny) is
    // inside when a_v >= -eps: a ray lying in a shared face belongs to both
    // cells (deduplicated below) instead of to neither by rounding.
    const double eps = 1e-9;
    double t0 = 0.0, t1 = 1e300;
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
        t1 = -1;
      }
    }
    if (t1 > t0)
    {
      auto scalarAt = [&](double t) {
        double value = 0;
        for (int v = 0; v < 4; ++v)
        {
          value += (a[v] + b[v] * t) * s[v];
        }
        return value;
      };
      segments.push_back({ t0, t1, scalarAt(t0), scalarAt(t1) });
    }
  }
  std::sort(segments.begin(), segments.end(),
    [](const Segment& x, const Segment& y) { return x.T0 < y.T0; });
  // A ray inside a shared face or along a shared edge lies in several cells:
  // keep each stretch of t once.
  std::vector<Segment> unique;
  double end = -1e300;
  for (Segment seg : segments)
  {
    if (seg.T1 <= end)
    {
      continue;
    }
    if (seg.T0 < end)
    {
      seg.S0 += (seg.S1 - seg.S0) * (end - seg.T0) / (seg.T1 - seg.T0);
      seg.T0 = end;
    }
    unique.push_back(seg);
    end = seg.T1;
  }
  return unique;
}

// Premultiplied RGBA of one ray, front to back, over nothing.
inline std::array<double, 4> IntegrateRay(
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, const Ray& ray, bool cellScalars)
{
  vtkColorTransferFunction* color = property->GetRGBTransferFunction();
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  const double unit = property->GetScalarOpacityUnitDistance();
  std::vector<double> nodes;
  for (int i = 0; i < color->GetSize(); ++i)
  {
    double v[6];
    color->GetNodeValue(i, v);
    nodes.push_back(v[0]);
  }
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double v[4];
    opacity->GetNodeValue(i, v);
    nodes.push_back(v[0]);
  }
  std::sort(nodes.begin(), nodes.end());

  // 8-point Gauss-Legendre on [0, 1].
  static const double gx[8] = { 0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
    0.4082826787521751, 0.5917173212478249, 0.7627662049581645, 0.8983332387068134,
    0.9801449282487681 };
  static const double gw[8] = { 0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
    0.1813418916891810, 0.1813418916891810, 0.1568533229389436, 0.1111905172266872,
    0.0506142681451881 };

  std::array<double, 4> out = { 0, 0, 0, 0 };
  for (const Segment& seg : RaySegments(grid, ray, cellScalars))
  {
    // Split points in t at every node value strictly between S0 and S1.
    std::vector<double> cuts = { seg.T0, seg.T1 };
    for (double node : nodes)
    {
      if ((node - seg.S0) * (node - seg.S1) < 0)
      {
        cuts.push_back(seg.T0 + (seg.T1 - seg.T0) * (node - seg.S0) / (seg.S1 - seg.S0));
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (size_t k = 0; k + 1 < cuts.size(); ++k)
    {
      const double ta = cuts[k], tb = cuts[k + 1], D = tb - ta;
      if (D <= 0)
      {
        continue;
      }
      auto scalar = [&](double t) {
        return seg.S0 + (seg.S1 - seg.S0) * (t - seg.T0) / (seg.T1 - seg.T0);
      };
      const double sa = scalar(ta), sb = scalar(tb);
      double ca[3], cb[3];
      color->GetColor(sa, ca);
      color->GetColor(sb, cb);
      const double taua = opacity->GetValue(sa) / unit, taub = opacity->GetValue(sb) / unit;
      // Sub-intervals fine enough for the decay scale 1 / tau.
      const int pieces = std::min(100000, std::max(16, static_cast<int>(8 * std::max(taua, taub) * D)));
      double emitted[3] = { 0, 0, 0 };
      for (int m = 0; m < pieces; ++m)
      {
        for (int g = 0; g < 8; ++g)
        {
          const double x = D * (m + gx[g]) / pieces, w = gw[g] * D / pieces;
          const double u = x / D;
          const double tau = taua + (taub - taua) * u;
          const double transparency = std::exp(-(taua * x + 0.5 * (taub - taua) * x * u));
          for (int c = 0; c < 3; ++c)
          {
            emitted[c] += w * (ca[c] + (cb[c] - ca[c]) * u) * tau * transparency;
          }
        }
      }
      const double alpha = 1.0 - std::exp(-0.5 * (taua + taub) * D);
      for (int c = 0; c < 3; ++c)
      {
        out[c] += (1.0 - out[3]) * emitted[c];
      }
      out[3] += (1.0 - out[3]) * alpha;
    }
  }
  return out;
}
}

#endif
