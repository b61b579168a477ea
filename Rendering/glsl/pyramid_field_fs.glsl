// VTK's pyramid (vtkPyramid: corners p0..p3 the base, p4 the apex) maps
// parametric (r, s, t) to
//   x(r, s, t) = (1 - t) B(r, s) + t p4,
//   B(r, s) = (1 - r)(1 - s) p0 + r (1 - s) p1 + r s p2 + (1 - r) s p3,
// and interpolates its corner values v_i with the same functions. Its
// inverse is rational (a central projection from the apex), so the field
// along a ray is not a polynomial: the march takes the cubic through VTK's
// field at the stretch's ends and at its quarter points x = len / 4 and
// 3 len / 4 (Chebyshev-Lobatto nodes), exact at both ends, so the field stays
// continuous from cell to cell (Documentation/algorithms.md, "Cell kinds",
// states and measures the error).

// Loop iterations of one inversion (pyramidParametric).
const int PYRAMID_NEWTON_STEPS = 8;

vec3 pyramidPoint(vec3 p[8], vec3 rst)
{
  float r = rst.x, s = rst.y, t = rst.z;
  vec3 base = (1.0 - r) * (1.0 - s) * p[0] + r * (1.0 - s) * p[1] + r * s * p[2] +
    (1.0 - r) * s * p[3];
  return (1.0 - t) * base + t * p[4];
}

// Columns dx/dr, dx/ds, dx/dt.
mat3 pyramidJacobian(vec3 p[8], vec3 rst)
{
  float r = rst.x, s = rst.y, t = rst.z;
  vec3 dr = (1.0 - t) * ((1.0 - s) * (p[1] - p[0]) + s * (p[2] - p[3]));
  vec3 ds = (1.0 - t) * ((1.0 - r) * (p[3] - p[0]) + r * (p[2] - p[1]));
  vec3 base = (1.0 - r) * (1.0 - s) * p[0] + r * (1.0 - s) * p[1] + r * s * p[2] +
    (1.0 - r) * s * p[3];
  return mat3(dr, ds, p[4] - base);
}

// (r, s, t) of a point x inside the pyramid: Newton's method from the
// centre's parameters, t kept below 1 (the apex, where r and s are free).
vec3 pyramidParametric(vec3 p[8], vec3 x)
{
  vec3 rst = vec3(0.5, 0.5, 0.25);
  for (int i = 0; i < PYRAMID_NEWTON_STEPS; ++i)
  {
    mat3 jacobian = pyramidJacobian(p, rst);
    if (abs(determinant(jacobian)) < 1.0e-30)
    {
      break;
    }
    rst -= inverse(jacobian) * (pyramidPoint(p, rst) - x);
    rst = vec3(clamp(rst.xy, -0.5, 1.5), min(rst.z, 1.0 - 1.0e-6));
  }
  return rst;
}

// VTK's field at (r, s, t): v = (v0..v3), apex value v4.
float pyramidValue(vec4 v, float v4, vec3 rst)
{
  float r = rst.x, s = rst.y, t = rst.z;
  float base =
    (1.0 - r) * (1.0 - s) * v.x + r * (1.0 - s) * v.y + r * s * v.z + (1.0 - r) * s * v.w;
  return (1.0 - t) * base + t * v4;
}

// The gradient of VTK's field at x: J^-T (df/dr, df/ds, df/dt).
vec3 pyramidGradient(vec3 p[8], vec4 v, float v4, vec3 x)
{
  vec3 rst = pyramidParametric(p, x);
  float r = rst.x, s = rst.y, t = rst.z;
  float dr = (1.0 - t) * ((1.0 - s) * (v.y - v.x) + s * (v.z - v.w));
  float ds = (1.0 - t) * ((1.0 - r) * (v.w - v.x) + r * (v.z - v.y));
  float base =
    (1.0 - r) * (1.0 - s) * v.x + r * (1.0 - s) * v.y + r * s * v.z + (1.0 - r) * s * v.w;
  mat3 jacobian = pyramidJacobian(p, rst);
  return abs(determinant(jacobian)) < 1.0e-30
    ? vec3(0.0)
    : transpose(inverse(jacobian)) * vec3(dr, ds, v4 - base);
}

// The cubic s(x) = w0 + w1 x + w2 x^2 + w3 x^3 through f0..f3 at
// x = 0, len / 4, 3 len / 4, len: Newton's divided differences in
// xi = x / len, expanded (xi (xi - 1/4) = xi^2 - xi / 4,
// xi (xi - 1/4)(xi - 3/4) = xi^3 - xi^2 + 3 xi / 16), then scaled to x.
vec4 cubicThroughLobattoNodes(vec4 f, float len)
{
  float d10 = 4.0 * (f.y - f.x), d11 = 2.0 * (f.z - f.y), d12 = 4.0 * (f.w - f.z);
  float d20 = (d11 - d10) / 0.75, d21 = (d12 - d11) / 0.75;
  float d3 = d21 - d20;
  vec4 a = vec4(f.x, d10 - 0.25 * d20 + 0.1875 * d3, d20 - d3, d3);
  float inverseLength = 1.0 / len;
  return a * vec4(1.0, inverseLength, inverseLength * inverseLength,
               inverseLength * inverseLength * inverseLength);
}

// VTK's pyramid field on the stretch from `entry` to `entry + len direction`,
// as the cubic through it at the Lobatto nodes (4 PYRAMID_NEWTON_STEPS loops).
// sEnd: the field at the far end.
vec4 pyramidStretch(vec3 p[8], vec4 v, float v4, vec3 entry, vec3 direction, float len,
  out float sEnd)
{
  vec4 f;
  for (int i = 0; i < 4; ++i)
  {
    float x = len * (i == 0 ? 0.0 : (i == 1 ? 0.25 : (i == 2 ? 0.75 : 1.0)));
    f[i] = pyramidValue(v, v4, pyramidParametric(p, entry + x * direction));
  }
  sEnd = f.w;
  return cubicThroughLobattoNodes(f, len);
}
