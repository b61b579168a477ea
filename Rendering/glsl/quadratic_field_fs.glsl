// A quadratic tetrahedron's field in its frame (ppirayQuadraticTetrahedra.h):
// the frame polynomial of hexahedron_field_fs.glsl (c7 = 0) plus the squares
//   e0 u^2 + e1 v^2 + e2 w^2.
// Along the ray uvw = q + x r they add to the cubic's coefficients
//   w0: sum_i e_i q_i^2,  w1: 2 sum_i e_i q_i r_i,  w2: sum_i e_i r_i^2,
// and 2 (e0 u, e1 v, e2 w) to the gradient in frame coordinates.

vec4 raySquares(vec3 e, vec3 q, vec3 r)
{
  return vec4(dot(e, q * q), 2.0 * dot(e, q * r), dot(e, r * r), 0.0);
}

vec3 squaresGradient(vec3 e, vec3 p)
{
  return 2.0 * e * p;
}
