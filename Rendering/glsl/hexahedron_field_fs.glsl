// The trilinear field of a hexahedron along a ray (Miranda 2011, Sec. 3.1),
// expanded around the cell's entry point rather than the eye so that single
// precision holds: with frame coordinates uvw(x) = q + x r (x the distance
// past the entry point, q and r from the cell frame, see
// vtkHexahedronCoefficients) and
//   f(u, v, w) = c0 + c1 u + c2 v + c3 w + c4 uv + c5 vw + c6 uw + c7 uvw,
// f along the ray is the cubic w0 + w1 x + w2 x^2 + w3 x^3 with
//   w0 = f(q),  w1 = grad f(q) . r,  w2 = r^T H(q) r / 2,  w3 = c7 ru rv rw.

// c = (c0..c3), d = (c4..c7).
vec4 rayCubic(vec4 c, vec4 d, vec3 q, vec3 r)
{
  float w0 = c.x + c.y * q.x + c.z * q.y + c.w * q.z + d.x * q.x * q.y + d.y * q.y * q.z +
    d.z * q.x * q.z + d.w * q.x * q.y * q.z;
  float w1 = c.y * r.x + c.z * r.y + c.w * r.z + d.x * (q.x * r.y + r.x * q.y) +
    d.y * (q.y * r.z + r.y * q.z) + d.z * (q.x * r.z + r.x * q.z) +
    d.w * (r.x * q.y * q.z + q.x * r.y * q.z + q.x * q.y * r.z);
  float w2 = d.x * r.x * r.y + d.y * r.y * r.z + d.z * r.x * r.z +
    d.w * (r.x * r.y * q.z + r.x * q.y * r.z + q.x * r.y * r.z);
  float w3 = d.w * r.x * r.y * r.z;
  return vec4(w0, w1, w2, w3);
}

// Gradient of f in frame coordinates at (u, v, w) (Miranda 2011, Eq. 3-10):
//   df/du = c1 + c4 v + c6 w + c7 vw, df/dv = c2 + c4 u + c5 w + c7 uw,
//   df/dw = c3 + c5 v + c6 u + c7 uv;
// in the local frame grad f = T^T grad_uvw f, T the map to frame coordinates.
vec3 trilinearGradient(vec4 c, vec4 d, vec3 p)
{
  return vec3(c.y + d.x * p.y + d.z * p.z + d.w * p.y * p.z,
    c.z + d.x * p.x + d.y * p.z + d.w * p.x * p.z, c.w + d.y * p.y + d.z * p.x + d.w * p.x * p.y);
}

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
