// Exact-linear integration of a piece: the same formula as partial
// pre-integration (Moreland & Angel 2004, Sec. 4),
//   I = C_f (1 - Psi) + C_b (Psi - zeta),  zeta = exp(-(a + b) / 2),
// with a = tau_f D, b = tau_b D, c = (b - a) / 2, but Psi evaluated in closed
// form instead of read from a table (completing the square in the quadratic
// exponent; the same derivation as Filters/ppirayVolumeIntegrals.h, in float):
//   c > 0:  Psi = sqrt(pi) / (2 sqrt(c)) [erfcx(z0) - zeta erfcx(z0 + sqrt(c))],
//           z0 = a / (2 sqrt(c))
//   c < 0:  Psi = [F(w0 + sqrt(-c)) - zeta F(w0)] / sqrt(-c),  w0 = b / (2 sqrt(-c)),  F Dawson's
//   |c| < 0.05:  Psi = J0(a) - c J2(a) + c^2 / 2 J4(a)  (exp(-c u^2) to second
//           order; error below c^3 / 42 < 3e-6),  J_n(a) = int_0^1 u^n exp(-a u) du
// The weights are formed without cancellation: a short piece has Psi and
// zeta within a float's rounding of 1, so the opacity 1 - zeta and the front
// weight 1 - Psi are computed as such (their series start at the first
// order), and the back weight is their difference,
//   Psi - zeta = (1 - zeta) - (1 - Psi)
// (the two weights sum to the opacity, as the emission of a unit colour must).

const float SQRT_PI = 1.7724539;
// Loop iterations a piece may take (the loops below, every branch: the lanes
// of a SIMD group may take different ones), plus its own.
const int PIECE_LOOPS = 1 + 15 + 2 * (24 + 24) + 2 * (72 + 8);

// erfcx(x) = exp(x^2) erfc(x), x >= 0: the erf Taylor series below 1.5
// (stopped once a term is below 1e-9), the Laplace continued fraction
// 1 / (x + (1/2) / (x + 1 / (x + (3/2) / ...))) / sqrt(pi) above: 24 terms
// give a relative error below 2e-7 from x = 1.5, 10 terms below 5e-9 from 3.
float erfcx(float x)
{
  if (x < 1.5)
  {
    float x2 = x * x;
    float term = x;
    float erf = 0.0;
    for (int n = 0; n < 24; ++n)
    {
      erf += term / float(2 * n + 1);
      term *= -x2 / float(n + 1);
      if (abs(term) < 1.0e-9)
      {
        break;
      }
    }
    return exp(x2) * (1.0 - 2.0 / SQRT_PI * erf);
  }
  float v = x;
  for (int k = x < 3.0 ? 24 : 10; k > 0; --k)
  {
    v = x + 0.5 * float(k) / v;
  }
  return 1.0 / (SQRT_PI * v);
}

// Dawson's F(x) = exp(-x^2) int_0^x exp(t^2) dt, x >= 0: the positive series
// exp(-x^2) sum x^(2n+1) / (n! (2n + 1)) below 5 (no cancellation), the
// asymptotic series (1 / 2x) sum (2n - 1)!! / (2 x^2)^n above.
float dawson(float x)
{
  float x2 = x * x;
  if (x < 5.0)
  {
    float power = x;
    float sum = 0.0;
    for (int n = 0; n < 72; ++n)
    {
      float term = power / float(2 * n + 1);
      sum += term;
      if (term < 1.0e-8 * sum)
      {
        break;
      }
      power *= x2 / float(n + 1);
    }
    return exp(-x2) * sum;
  }
  float r = 0.5 / x2;
  float term = 1.0;
  float sum = 1.0;
  for (int n = 1; n < 9; ++n)
  {
    term *= float(2 * n - 1) * r;
    sum += term;
  }
  return sum / (2.0 * x);
}

// 1 - exp(-x), x >= 0: below 0.1 the series x (1 - x/2 (1 - x/3 (1 - x/4
// (1 - x/5 (1 - x/6))))) (relative error below x^6 / 5040 < 2e-10), else
// directly (no cancellation left).
float oneMinusExp(float x)
{
  if (x < 0.1)
  {
    return x * (1.0 - x / 2.0 * (1.0 - x / 3.0 * (1.0 - x / 4.0 * (1.0 - x / 5.0 * (1.0 - x / 6.0)))));
  }
  return 1.0 - exp(-x);
}

// (1 - J0, J2, J4)(a), J_n(a) = int_0^1 u^n exp(-a u) du: below a = 2 the
// series J_n = sum_k (-a)^k / (k! (n + k + 1)), whose k = 0 term of J0 is
// the 1 taken away (1 - J0 = -sum_{k>=1} (-a)^k / (k + 1)!), until a term is
// below 1e-8 relative to a (at most 16); above, the upward recurrence
// J_n = (n J_{n-1} - exp(-a)) / a from J0 = (1 - exp(-a)) / a.
vec3 exponentialMoments(float a)
{
  if (a < 2.0)
  {
    vec3 sum = vec3(0.0, 1.0 / 3.0, 1.0 / 5.0);
    float term = -a;
    for (int k = 1; k < 16; ++k)
    {
      sum += term * vec3(-1.0 / float(k + 1), 1.0 / float(k + 3), 1.0 / float(k + 5));
      term *= -a / float(k + 1);
      if (abs(term) <= 1.0e-8 * a)
      {
        break;
      }
    }
    return sum;
  }
  float e = exp(-a);
  float j0 = (1.0 - e) / a;
  float j1 = (j0 - e) / a;
  float j2 = (2.0 * j1 - e) / a;
  float j3 = (3.0 * j2 - e) / a;
  float j4 = (4.0 * j3 - e) / a;
  return vec3(1.0 - j0, j2, j4);
}

// 1 - Psi(a, b), zeta = exp(-(a + b) / 2) (the closed forms above).
float oneMinusPsi(float a, float b, float zeta)
{
  float c = 0.5 * (b - a);
  if (abs(c) < 0.05)
  {
    vec3 j = exponentialMoments(a);
    return j.x + c * j.y - 0.5 * c * c * j.z;
  }
  if (c > 0.0)
  {
    float sc = sqrt(c);
    float z0 = a / (2.0 * sc);
    return 1.0 - 0.5 * SQRT_PI / sc * (erfcx(z0) - zeta * erfcx(z0 + sc));
  }
  float sc = sqrt(-c);
  float w0 = b / (2.0 * sc);
  return 1.0 - (dawson(w0 + sc) - zeta * dawson(w0)) / sc;
}

void integratePiece(vec4 front, vec4 back, float len, inout vec4 color)
{
  float a = front.a * len;
  float b = back.a * len;
  float alpha = oneMinusExp(0.5 * (a + b));
  float frontWeight = clamp(oneMinusPsi(a, b, 1.0 - alpha), 0.0, alpha);
  vec3 emitted = front.rgb * frontWeight + back.rgb * (alpha - frontWeight);
  compositeFrontToBack(color, emitted, alpha);
}
