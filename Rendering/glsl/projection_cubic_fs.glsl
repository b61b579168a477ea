// Projections through a hexahedron (projection_fs.glsl says what each blend
// mode computes), where s along the ray is the cubic w on [0, len]: the
// extremes at the ends and at the roots of w'; average and additive on each
// monotonic piece, kept to AverageIPScalarRange (average), split at every
// control point crossed (cubicCrossing), and int tau(s) n(s) dx on a sub-piece
// by 4-point Gauss-Legendre: tau and n are linear in s there, so the
// integrand is a polynomial of degree 6 in x and the rule is exact. Out of
// loops: stops at a control point, cutAt that far along the stretch (the
// extremes are met whole first).

// int tau n dx over [xA, xB], tau linear from tauA at sA to tauB at sB.
float cubicPieceMoment(vec4 w, float xA, float xB, float sA, float sB, float tauA, float tauB)
{
  float ds = sB - sA;
  float mid = 0.5 * (xA + xB);
  float halfWidth = 0.5 * (xB - xA);
  float moment = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    float s = cubicValue(w, mid + (i < 2 ? -1.0 : 1.0) * GAUSS_NODE[i % 2] * halfWidth);
    float tau = ds == 0.0 ? 0.5 * (tauA + tauB) : mix(tauA, tauB, clamp((s - sA) / ds, 0.0, 1.0));
    moment += GAUSS_WEIGHT[i % 2] * tau * (normalizedScalar.x * s + normalizedScalar.y);
  }
  return moment * halfWidth;
}

void projectCubicStretch(vec4 w, float len, inout int k, inout vec3 state)
{
  float roots[2];
  int extrema = cubicExtrema(w, len, roots);
  float x0 = 0.0;
  float s0 = cubicValue(w, 0.0);
  if (BLEND == 1 || BLEND == 2)
  {
    meetScalar(s0, state);
    meetScalar(cubicValue(w, len), state);
    for (int i = 0; i < extrema; ++i)
    {
      meetScalar(cubicValue(w, roots[i]), state);
    }
    return;
  }
  state.y = BLEND == 3 ? state.y : 1.0;
  int n = numberOfControlPoints;
  for (int piece = 0; piece <= extrema; ++piece)
  {
    float x1 = piece < extrema ? roots[piece] : len;
    float s1 = cubicValue(w, x1);
    float xA = x0, xEnd = x1;
    float sA = s0, sEnd = s1;
    x0 = x1;
    s0 = s1;
    if (BLEND == 3)
    {
      // The monotonic piece's part inside the range: one interval.
      vec2 kept = averageRangeFraction(sA, sEnd);
      if (!(kept.y > kept.x))
      {
        continue;
      }
      float sFrom = mix(sA, sEnd, kept.x);
      float sTo = mix(sA, sEnd, kept.y);
      float xFrom = kept.x > 0.0 ? cubicCrossing(w, sFrom, xA, xEnd) : xA;
      xEnd = kept.y < 1.0 ? cubicCrossing(w, sTo, xA, xEnd) : xEnd;
      xA = xFrom;
      sA = sFrom;
      sEnd = sTo;
    }
    k = controlInterval(sA, k);
    float ds = sEnd - sA;
    for (int i = 0; i <= n; ++i)
    {
      if (!spendLoops(1 + 32))
      {
        cutAt = xA;
        return;
      }
      float sB;
      int nextK = nextControlCrossing(ds, sEnd, k, sB);
      float xB = nextK == k ? xEnd : cubicCrossing(w, sB, xA, xEnd);
      state.y += BLEND == 3 ? xB - xA : 0.0;
      state.x += cubicPieceMoment(
        w, xA, xB, sA, sB, transferFunction(sA, k).a, transferFunction(sB, k).a);
      if (nextK == k)
      {
        break;
      }
      k = nextK;
      xA = xB;
      sA = sB;
    }
  }
}
