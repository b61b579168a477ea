// Transfer function lookup shared by the integration modes: piecewise linear
// between control points s_0 <= ... <= s_n-1, constant outside. Three texels
// per control interval k = -1 .. n - 1 (vtkTransferFunctionControlPoints::
// GetTexels): f(s_k) = (r, g, b, tau), its slope f' in s, and the ends
// (s_k, s_k+1) (-+INFINITY past the first and last point) with the transparent
// run [a, b] around k (tau = 0 on all of it; empty, a > b, where tau is not
// zero on k), so that
//   f(s) = f(s_k) + f' (s - s_k),  s in [s_k, s_k+1].
uniform samplerBuffer controlPoints;
uniform int numberOfControlPoints;

vec4 intervalTexel(int k, int i)
{
  return texelFetch(controlPoints, 3 * (k + 1) + i);
}

// (s_k, s_k+1) of interval k.
vec2 intervalEnds(int k)
{
  return intervalTexel(k, 2).xy;
}

// Whether tau = 0 on all of the scalar span between sA and sB, sA in control
// interval k: then a segment on which s stays in the span emits and absorbs
// nothing (zeta = 1, I = 0) and is not integrated. The ends texel is the one
// the interval lookup has just read.
bool transparentSpan(float sA, float sB, int k)
{
  vec2 run = intervalTexel(k, 2).zw;
  return min(sA, sB) >= run.x && max(sA, sB) <= run.y;
}

// (r, g, b, tau) of the transfer function at scalar s, with s in the control
// interval k (clamped to its ends).
vec4 transferFunction(float s, int k)
{
  vec2 ends = intervalEnds(k);
  return intervalTexel(k, 0) + intervalTexel(k, 1) * (clamp(s, ends.x, ends.y) - ends.x);
}

// The transfer function where a walk that crossed a control point enters
// interval k: upwards, its low end f(s_k) (past a jump, the right limit);
// downwards, `left`, its value where the walk left the interval above (equal
// but across a jump below, which the walk crosses next as a piece of zero
// length).
vec4 transferFunctionEntered(int k, float ds, vec4 left)
{
  return ds > 0.0 ? intervalTexel(k, 0) : left;
}

// Index k with s_k <= s < s_k+1 (-1 below the first point), the largest k
// with s_k <= s, searched from the previous index: that interval, then the
// next one towards s (the scalar is continuous along a ray for point data:
// usually zero or one step), then bisection of what is left (a jump: cell
// data, a new peel). Each probe narrows the bracket s_lo <= s < s_hi
// (s_-1 = -infinity, s_n = +infinity), so at most CONTROL_SEARCH_LOOPS
// probes whatever the jump: the lanes of a SIMD group that march together
// take about as many as each other (a driver's loop limit counts the
// group's iterations, not each lane's). One probe is one texel read, and
// the loop one branch, since a software rasterizer runs every lane through
// all the code. Its probes are taken from the loop budget.
int controlInterval(float s, int k)
{
  int lo = -1;
  int hi = numberOfControlPoints;
  int probe = clamp(k, lo, hi - 1);
  int i = 0;
  for (; i < CONTROL_SEARCH_LOOPS && hi - lo > 1; ++i)
  {
    vec2 ends = intervalEnds(probe);
    if (ends.x <= s && s < ends.y)
    {
      lo = probe;
      break;
    }
    bool above = s >= ends.y;
    lo = above ? probe + 1 : lo;
    hi = above ? hi : probe;
    probe = i == 0 ? (above ? probe + 1 : probe - 1) : lo + (hi - lo) / 2;
    probe = clamp(probe, lo, hi - 1);
  }
  loopsLeft -= i; // taken after the fact from the reserve (march_common_fs.glsl)
  return lo;
}

// Walking s monotonically from the control interval k towards sEnd (ds: the
// direction): the next control point value strictly before sEnd, in sB, and
// the interval beyond it; or sEnd and k itself when none is left. Index
// arithmetic, no re-lookup: a value landing exactly on a control point cannot
// loop (the role of next_s_iso in Espinha & Celes 2005, Sec. 3.2).
int nextControlCrossing(float ds, float sEnd, int k, out float sB)
{
  int n = numberOfControlPoints;
  vec2 ends = intervalEnds(k);
  if (ds > 0.0 && k + 1 < n && ends.y < sEnd)
  {
    sB = ends.y;
    return k + 1;
  }
  if (ds < 0.0 && k >= 0 && ends.x > sEnd)
  {
    sB = ends.x;
    return k - 1;
  }
  sB = sEnd;
  return k;
}

void compositeFrontToBack(inout vec4 color, vec3 emitted, float alpha)
{
  color.rgb += (1.0 - color.a) * emitted;
  color.a += (1.0 - color.a) * alpha;
}
