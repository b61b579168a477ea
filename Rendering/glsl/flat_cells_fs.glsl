// Zero-volume (flat) cells, for every cell kind: a flat cell is crossed with
// zero length, out through the face other than the entry face whose
// triangle best contains the point (algorithms.md, "Degenerate, inverted
// and tangled cells").

// The smallest barycentric coordinate of x projected on the plane of
// triangle (a, b, c): with m = (b - a) x (c - a),
// lambda_a = m . ((b - x) x (c - x)) / |m|^2, and cyclically; >= 0 inside.
// area2 = |m|^2 (four times the squared area).
float smallestBarycentric(vec3 a, vec3 b, vec3 c, vec3 x, out float area2)
{
  vec3 m = cross(b - a, c - a);
  area2 = dot(m, m);
  float la = dot(m, cross(b - x, c - x)) / area2;
  float lb = dot(m, cross(c - x, a - x)) / area2;
  return min(min(la, lb), 1.0 - la - lb);
}

// Whether a triangle with |m|^2 = area2 has an area to speak of among
// triangles up to `largest`: faces of (relatively) zero area are never an
// exit.
bool hasArea(float area2, float largest)
{
  return area2 > 1.0e-8 * largest;
}

// How far x lies outside triangle (a, b, c) in its plane: the largest
// distance past one of its edges, m_i . (v_i - x) with m_i the unit inward
// normal of edge v_i v_i+1 in the plane (negative inside).
float outsideTriangle(vec3 a, vec3 b, vec3 c, vec3 x)
{
  vec3 v[3] = vec3[3](a, b, c);
  vec3 n = cross(b - a, c - a);
  float outside = -INFINITY;
  for (int i = 0; i < 3; ++i)
  {
    vec3 inward = normalize(cross(n, v[(i + 1) % 3] - v[i]));
    outside = max(outside, dot(inward, v[i] - x));
  }
  return outside;
}
