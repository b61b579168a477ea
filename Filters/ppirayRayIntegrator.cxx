#include "ppirayRayIntegrator.h"

#include "ppirayVolumeIntegrals.h"

#include <algorithm>
#include <limits>

namespace ppiray
{
namespace reference
{
//------------------------------------------------------------------------------
void IntegrateRay(std::vector<Segment>& segments, const TransferFunction& tf,
  const IsoSurfaces& iso, const Vec3& origin, const Vec3& direction, const Vec3& centre,
  const GradientAt& gradientAt, float rgba[4])
{
  std::sort(segments.begin(), segments.end(),
    [](const Segment& x, const Segment& y) { return x.T0 < y.T0; });
  double color[3] = { 0, 0, 0 };
  double transmittance = 1.0;
  double reached = -std::numeric_limits<double>::infinity();
  std::vector<double> cuts;
  // The volume on [t0, t1] where s goes linearly from s0 to s1.
  auto integrateLinear = [&](double t0, double t1, double s0, double s1)
  {
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
      IntegrateLinearPiece(ca, taua, cb, taub, length, emitted, transparency);
      for (int c = 0; c < 3; ++c)
      {
        color[c] += transmittance * emitted[c];
      }
      transmittance *= transparency;
    }
  };
  auto surface = [&](int i, const Segment& seg, double t)
  {
    const Vec3 x = origin + t * direction + centre;
    const Vec3 rgb =
      iso.Shaded(i, x, seg.Cell < 0 ? seg.Gradient : gradientAt(seg.Cell, t), direction);
    const double alpha = iso.Colors[i].a;
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
      if (iso.Mode == EmbeddedIsoSurfaces)
      {
        integrateLinear(t, tv, s, v);
      }
      surface(i, seg, tv);
      t = tv;
      s = v;
    }
    if (iso.Mode == EmbeddedIsoSurfaces)
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

//------------------------------------------------------------------------------
void ProjectRay(
  const std::vector<Segment>& segments, const TransferFunction& tf, bool maximum, float rgba[4])
{
  std::fill(rgba, rgba + 4, 0.0f);
  if (segments.empty())
  {
    return;
  }
  double extreme = segments.front().S0;
  for (const Segment& seg : segments)
  {
    for (double s : { seg.S0, seg.S1 })
    {
      extreme = maximum ? std::max(extreme, s) : std::min(extreme, s);
    }
  }
  double rgb[3], tau;
  tf.Evaluate(extreme, tf.Piece(extreme), rgb, tau);
  const double alpha = std::min(1.0, std::max(0.0, tau * tf.UnitDistance));
  for (int c = 0; c < 3; ++c)
  {
    rgba[c] = static_cast<float>(alpha * rgb[c]);
  }
  rgba[3] = static_cast<float>(alpha);
}
}
}
