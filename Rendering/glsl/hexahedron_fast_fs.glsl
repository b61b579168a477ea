// HEXAHEDRON_FAST (Miranda 2011, Ch. 4): each monotonic piece of the cubic
// (between its extrema, and isosurfaces) integrated as if the scalar were
// linear between the piece's end values, by the integration mode's
// integrateSegment() (control point stops with the Psi table by default;
// out of loops, cutAt past xA as it says).
int integrateMonotonicPiece(vec4 w, float xA, float x1, float sA, float s1, int k,
  inout vec4 color)
{
  return x1 > xA ? integrateSegment(sA, s1, x1 - xA, k, color) : k;
}
