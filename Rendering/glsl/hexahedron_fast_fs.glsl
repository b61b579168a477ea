// HEXAHEDRON_FAST (Miranda 2011, Ch. 4): the cubic split at its extrema into
// monotonic pieces, each integrated as if the scalar were linear between the
// piece's end values, by the integration mode's integrateSegment() (control
// point stops with the Psi table by default).
int integrateHexahedronSegment(vec4 w, float len, int k, inout vec4 color)
{
  float roots[2];
  int n = cubicExtrema(w, len, roots);
  float x0 = 0.0;
  float s0 = w.x;
  for (int i = 0; i <= n; ++i)
  {
    float x1 = i < n ? roots[i] : len;
    float s1 = cubicValue(w, x1);
    if (x1 > x0)
    {
      k = integrateSegment(s0, s1, x1 - x0, k, color);
    }
    x0 = x1;
    s0 = s1;
  }
  return k;
}
