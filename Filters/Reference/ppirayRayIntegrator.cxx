#include "ppirayRayIntegrator.h"

#include "ppirayVolumeIntegrals.h"

#include <algorithm>
#include <limits>

namespace ppiray
{
namespace reference
{
namespace
{
// The part of `seg` past `reached` (segments sorted by T0: no stretch of the
// ray counted twice where cells overlap); false if nothing is left.
bool TrimToUnreached(Segment& seg, double& reached)
{
  if (seg.T1 <= reached)
  {
    return false;
  }
  if (seg.T0 < reached)
  {
    seg.S0 += (seg.S1 - seg.S0) * (reached - seg.T0) / (seg.T1 - seg.T0);
    seg.T0 = reached;
  }
  reached = seg.T1;
  return true;
}

// [t0, t1], where s goes linearly from s0 to s1, cut at every transfer
// function break: piece(sa, sb, length, k) for each part of positive length,
// k the transfer-function piece it lies in (found at its middle: at a jump
// both ends are on a break). `cuts`: scratch space.
template<typename Piece>
void ForEachTransferFunctionPiece(const TransferFunction& tf, double t0, double t1, double s0,
  double s1, std::vector<double>& cuts, const Piece& piece)
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
    if (length > 0)
    {
      piece(s0 + (s1 - s0) * u0, s0 + (s1 - s0) * u1, length,
        tf.Piece(s0 + (s1 - s0) * 0.5 * (u0 + u1)));
    }
  }
}
}

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
    ForEachTransferFunctionPiece(tf, t0, t1, s0, s1, cuts,
      [&](double sa, double sb, double length, int piece)
      {
        double ca[3], cb[3], taua, taub, emitted[3], transparency;
        tf.Evaluate(sa, piece, ca, taua);
        tf.Evaluate(sb, piece, cb, taub);
        IntegrateLinearPiece(ca, taua, cb, taub, length, emitted, transparency);
        for (int c = 0; c < 3; ++c)
        {
          color[c] += transmittance * emitted[c];
        }
        transmittance *= transparency;
      });
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
    const bool gap = seg.T0 > reached + 1e-9 * std::max(std::abs(reached), seg.T1 - seg.T0);
    if (!TrimToUnreached(seg, reached))
    {
      continue;
    }
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
  std::vector<Segment>& segments, const TransferFunction& tf, const Projection& how, float rgba[4])
{
  std::fill(rgba, rgba + 4, 0.0f);
  if (segments.empty())
  {
    return;
  }
  if (how.Blend == Projection::Maximum || how.Blend == Projection::Minimum)
  {
    double extreme = segments.front().S0;
    for (const Segment& seg : segments)
    {
      for (double s : { seg.S0, seg.S1 })
      {
        extreme = how.Blend == Projection::Maximum ? std::max(extreme, s) : std::min(extreme, s);
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
    return;
  }
  // int tau(s) n(s) dt and int dt over the parts of the ray with s in the
  // range (additive: all of it); tau n is quadratic in s on a transfer
  // function piece: 3-point Gauss-Legendre there, exact.
  const bool average = how.Blend == Projection::Average;
  const double lo = average ? how.AverageRange[0] : -std::numeric_limits<double>::infinity();
  const double hi = average ? how.AverageRange[1] : std::numeric_limits<double>::infinity();
  constexpr double node = 0.7745966692414834, weights[3] = { 5.0 / 9, 8.0 / 9, 5.0 / 9 };
  std::sort(segments.begin(), segments.end(),
    [](const Segment& x, const Segment& y) { return x.T0 < y.T0; });
  double moment = 0.0, length = 0.0;
  double reached = -std::numeric_limits<double>::infinity();
  std::vector<double> cuts;
  for (Segment seg : segments)
  {
    if (!TrimToUnreached(seg, reached))
    {
      continue;
    }
    // The fraction [u0, u1] of the segment inside [lo, hi].
    double u0 = 0.0, u1 = 1.0;
    const double ds = seg.S1 - seg.S0;
    if (ds != 0.0)
    {
      const double a = (lo - seg.S0) / ds, b = (hi - seg.S0) / ds;
      u0 = std::min(1.0, std::max(0.0, std::min(a, b)));
      u1 = std::min(1.0, std::max(0.0, std::max(a, b)));
    }
    else if (seg.S0 < lo || seg.S0 > hi)
    {
      continue;
    }
    const double t0 = seg.T0 + u0 * (seg.T1 - seg.T0), t1 = seg.T0 + u1 * (seg.T1 - seg.T0);
    if (!(t1 > t0))
    {
      continue;
    }
    length += t1 - t0;
    ForEachTransferFunctionPiece(tf, t0, t1, seg.S0 + u0 * ds, seg.S0 + u1 * ds, cuts,
      [&](double sa, double sb, double pieceLength, int piece)
      {
        for (int i = 0; i < 3; ++i)
        {
          const double s = 0.5 * (sa + sb) + 0.5 * (sb - sa) * node * (i - 1);
          double rgb[3], tau;
          tf.Evaluate(s, piece, rgb, tau);
          const double normalized = how.Normalize[0] * s + how.Normalize[1];
          moment += 0.5 * pieceLength * weights[i] * tau * normalized;
        }
      });
  }
  double grey = 0.0;
  if (average)
  {
    if (!(length > 0))
    {
      return;
    }
    grey = tf.UnitDistance * moment / length;
  }
  else
  {
    grey = moment;
  }
  grey = std::min(1.0, std::max(0.0, grey));
  std::fill(rgba, rgba + 3, static_cast<float>(grey));
  rgba[3] = 1.0f;
}
}
}
