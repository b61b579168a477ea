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
