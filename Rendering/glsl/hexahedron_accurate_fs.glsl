// HEXAHEDRON_ACCURATE (Miranda 2011, Ch. 3): the cubic split at its extrema
// into monotonic pieces, each split at every control point it crosses (found
// by cubicCrossing), so that on a piece [xA, xB] colour C and attenuation tau
// are linear in the scalar s = f(x) between their values at sA and sB. There
//   Z(x) = int_xA^x tau(f(y)) dy
//        = tau_A (x - xA) + (tau_B - tau_A) / (sB - sA) (F(x) - F(xA) - sA (x - xA))
// exactly (F the cubic's antiderivative), and the emitted colour
//   I = int_xA^xB C(f(x)) tau(f(x)) exp(-Z(x)) dx
// by 4-point Gauss-Legendre quadrature on 1 to 8 equal sub-intervals (more
// when the piece is optically thick, where exp(-Z) varies fastest).
// Loop iterations a piece may take: its own, cubicCrossing's, the quadrature's.
const int CUBIC_PIECE_LOOPS = 1 + 32 + 8 * 5;

void integrateCubicPiece(vec4 w, float xA, float xB, float sA, float sB, vec4 tfA, vec4 tfB,
  inout vec4 color)
{
  float len = xB - xA;
  if (!(len > 0.0))
  {
    return;
  }
  float ds = sB - sA;
  float slope = abs(ds) > 1.0e-12 * max(abs(sA), 1.0) ? (tfB.a - tfA.a) / ds : 0.0;
  float tauA = slope == 0.0 ? 0.5 * (tfA.a + tfB.a) : tfA.a;
  float FA = cubicIntegral(w, xA);
  float zTotal = tauA * len + slope * (cubicIntegral(w, xB) - FA - sA * len);
  int parts = int(clamp(ceil(zTotal * 0.5), 1.0, 8.0));
  float h = len / float(parts);
  vec3 emitted = vec3(0.0);
  for (int j = 0; j < parts; ++j)
  {
    float mid = xA + (float(j) + 0.5) * h;
    for (int i = 0; i < 4; ++i)
    {
      float x = mid + (i < 2 ? -1.0 : 1.0) * GAUSS_NODE[i % 2] * 0.5 * h;
      float s = cubicValue(w, x);
      float u = ds == 0.0 ? 0.0 : clamp((s - sA) / ds, 0.0, 1.0);
      vec4 tf = mix(tfA, tfB, u);
      float z = tauA * (x - xA) + slope * (cubicIntegral(w, x) - FA - sA * (x - xA));
      emitted += GAUSS_WEIGHT[i % 2] * 0.5 * h * tf.rgb * tf.a * exp(-z);
    }
  }
  compositeFrontToBack(color, emitted, 1.0 - exp(-zTotal));
}

// One monotonic piece [xA, x1] of the cubic (sA to s1), split at every
// control point it crosses; not integrated where transparent (transparentSpan).
// Out of loops: stops at a control point, cutAt that far past xA.
int integrateMonotonicPiece(vec4 w, float xA, float x1, float sA, float s1, int k,
  inout vec4 color)
{
  int n = numberOfControlPoints;
  k = controlInterval(sA, k);
  if (transparentSpan(sA, s1, k))
  {
    return k;
  }
  float ds = s1 - sA;
  vec4 tfA = transferFunction(sA, k);
  float xStart = xA;
  for (int i = 0; i <= n; ++i)
  {
    if (!spendLoops(CUBIC_PIECE_LOOPS))
    {
      cutAt = xA - xStart;
      break;
    }
    float sB;
    int nextK = nextControlCrossing(ds, s1, k, sB);
    float xB = nextK == k ? x1 : cubicCrossing(w, sB, xA, x1);
    vec4 tfB = transferFunction(sB, k);
    integrateCubicPiece(w, xA, xB, sA, sB, tfA, tfB, color);
    if (nextK == k)
    {
      break;
    }
    k = nextK;
    xA = xB;
    sA = sB;
    tfA = transferFunctionEntered(k, ds, tfB);
  }
  return k;
}
