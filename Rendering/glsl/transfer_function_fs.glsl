// Transfer function lookup shared by the integration modes: control points
// (vtkTransferFunctionControlPoints), 2 texels each: (s, tau), (r, g, b).
uniform samplerBuffer controlPoints;
uniform int numberOfControlPoints;

// Transfer function: piecewise linear between control points, constant outside.
float controlPointValue(int i)
{
  return texelFetch(controlPoints, 2 * i).x;
}

// (r, g, b, tau) of the transfer function at scalar s, with s in the control
// interval [s_k, s_k+1] (k = -1 or n - 1: clamped to the end points).
vec4 transferFunction(float s, int k)
{
  int n = numberOfControlPoints;
  int lo = clamp(k, 0, n - 1);
  int hi = clamp(k + 1, 0, n - 1);
  vec4 a = texelFetch(controlPoints, 2 * lo);
  vec4 b = texelFetch(controlPoints, 2 * hi);
  vec4 ca = vec4(texelFetch(controlPoints, 2 * lo + 1).rgb, a.y);
  vec4 cb = vec4(texelFetch(controlPoints, 2 * hi + 1).rgb, b.y);
  float w = (hi == lo || b.x <= a.x) ? 0.0 : clamp((s - a.x) / (b.x - a.x), 0.0, 1.0);
  return mix(ca, cb, w);
}

// Index k with s_k <= s < s_k+1 (-1 below the first point), moved from the
// previous cell's index: the scalar is continuous along a ray for point data,
// so this is usually zero or one step. Bounded by the number of points.
// Its steps are taken from the loop budget.
int controlInterval(float s, int k)
{
  int n = numberOfControlPoints;
  k = clamp(k, -1, n - 1);
  int i = 0;
  for (; i < n && k + 1 < n && controlPointValue(k + 1) <= s; ++i)
  {
    ++k;
  }
  int j = 0;
  for (; j < n && k >= 0 && controlPointValue(k) > s; ++j)
  {
    --k;
  }
  loopsLeft -= i + j; // taken after the fact from the reserve (march_common_fs.glsl)
  return k;
}

// Walking s monotonically from the control interval k towards sEnd (ds: the
// direction): the next control point value strictly before sEnd, in sB, and
// the interval beyond it; or sEnd and k itself when none is left. Index
// arithmetic, no re-lookup: a value landing exactly on a control point cannot
// loop (the role of next_s_iso in Espinha & Celes 2005, Sec. 3.2).
int nextControlCrossing(float ds, float sEnd, int k, out float sB)
{
  int n = numberOfControlPoints;
  if (ds > 0.0 && k + 1 < n && controlPointValue(k + 1) < sEnd)
  {
    sB = controlPointValue(k + 1);
    return k + 1;
  }
  if (ds < 0.0 && k >= 0 && controlPointValue(k) > sEnd)
  {
    sB = controlPointValue(k);
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
