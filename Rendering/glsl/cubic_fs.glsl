// A cubic along the ray, s(x) = w0 + w1 x + w2 x^2 + w3 x^3 (w = (w0, w1,
// w2, w3), x the distance past a cell's entry point): its value, slope,
// antiderivative, extrema and crossings. The march's stretches of a cell
// (stretch_fs.glsl) are such polynomials of degree 1 to 3.

float cubicValue(vec4 w, float x)
{
  return w.x + x * (w.y + x * (w.z + x * w.w));
}

float cubicSlope(vec4 w, float x)
{
  return w.y + x * (2.0 * w.z + 3.0 * x * w.w);
}

// Antiderivative of the cubic, zero at x = 0.
float cubicIntegral(vec4 w, float x)
{
  return x * (w.x + x * (0.5 * w.y + x * (w.z / 3.0 + 0.25 * x * w.w)));
}

// The extrema of the cubic strictly inside (0, len), sorted: the roots of
// f' = w1 + 2 w2 x + 3 w3 x^2, by the cancellation-free quadratic formula
// (q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, roots q / a and c / q).
int cubicExtrema(vec4 w, float len, out float roots[2])
{
  float a = 3.0 * w.w, b = 2.0 * w.z, c = w.y;
  int n = 0;
  roots[0] = len;
  roots[1] = len;
  float candidates[2];
  int m = 0;
  if (a == 0.0)
  {
    if (b != 0.0)
    {
      candidates[m++] = -c / b;
    }
  }
  else
  {
    float disc = b * b - 4.0 * a * c;
    if (disc > 0.0)
    {
      float q = -0.5 * (b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
      candidates[m++] = q / a;
      if (q != 0.0)
      {
        candidates[m++] = c / q;
      }
    }
  }
  for (int i = 0; i < m; ++i)
  {
    float x = candidates[i];
    if (x > 1.0e-6 * len && x < len * (1.0 - 1.0e-6))
    {
      roots[n++] = x;
    }
  }
  if (n == 2 && roots[1] < roots[0])
  {
    float swap = roots[0];
    roots[0] = roots[1];
    roots[1] = swap;
  }
  return n;
}

// The x in [lo, hi] where the cubic, monotonic there, takes `target`:
// Newton's method kept inside a shrinking bracket, bisecting whenever a
// Newton step would leave it (never leaves [lo, hi]; at most 32 steps).
// A target the rounded cubic does not bracket (one just crossed at lo,
// e.g. the second of two equal control points, a jump of the transfer
// function) is taken at the nearer end.
float cubicCrossing(vec4 w, float target, float lo, float hi)
{
  float gLo = cubicValue(w, lo) - target;
  float gHi = cubicValue(w, hi) - target;
  if (gLo != 0.0 && gHi != 0.0 && (gLo < 0.0) == (gHi < 0.0))
  {
    return abs(gLo) <= abs(gHi) ? lo : hi;
  }
  float x = gHi == gLo ? 0.5 * (lo + hi) : clamp(lo - gLo * (hi - lo) / (gHi - gLo), lo, hi);
  float tolerance = 1.0e-7 * max(hi - lo, 1.0e-30);
  for (int i = 0; i < 32; ++i)
  {
    float g = cubicValue(w, x) - target;
    if (g == 0.0)
    {
      break;
    }
    if ((g < 0.0) == (gLo < 0.0))
    {
      lo = x;
      gLo = g;
    }
    else
    {
      hi = x;
    }
    float slope = cubicSlope(w, x);
    float next = slope != 0.0 ? x - g / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi))
    {
      next = 0.5 * (lo + hi);
    }
    if (abs(next - x) <= tolerance || hi - lo <= tolerance)
    {
      x = next;
      break;
    }
    x = next;
  }
  return x;
}
