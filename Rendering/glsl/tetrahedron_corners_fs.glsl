// Tetrahedra as their corners (vtkTetrahedralCellTextures::COMPACT; face data
// computed from the vertices as in Maximo et al. 2008, Sec. 4.1),
// GEOMETRY_TEXELS = FIELD_TEXELS = 1 per cell, one texel per point:
//   cellCorners[t] = the point ids of corners 0..3, the fourth plus
//                    INVERTED_CORNERS (an inverted cell) or FLAT_CORNERS
//                    (a flat one)
//   points[i]      = (x_i, s_i), s_i the point's scalar (0 for cell scalars)
//   cellValues[t]  = added to the interpolated s: the cell scalar, 0, or
//                    -3e38 (render empty)
// The planes and field are those the PLANES layout stores
// (tetrahedron_planes_fs.glsl), computed in float. Face f is the corners
// other than x_f wound as FACE_CORNERS[f], outward for a positive cell:
//   n_f = +-normalize((b - a) x (c - a)),  d_f = n_f . (a + b + c) / 3.
// The linear interpolant s(x) = sum_v s_v lambda_v(x) with the barycentric
// lambda_v(x) = (d_v - n_v . x) / h_v, h_v = d_v - n_v . x_v the height of
// corner v over face v:
//   g = -sum_v (s_v / h_v) n_v,  s0 = sum_v (s_v / h_v) d_v.

// Corners (x_v, s_v) of cell t; returns its flags.
int cornersOfCell(int t, out vec4 x[4])
{
  ivec4 ids = cellCornersTexel(t);
  int flags = ids.w & (INVERTED_CORNERS | FLAT_CORNERS);
  ids.w -= flags;
  for (int v = 0; v < 4; ++v)
  {
    x[v] = pointsTexel(ids[v]);
  }
  return flags;
}

// Plane (n_f, d_f) of face f of the cell with corners x, or a flat cell's
// corner f with the FLAT_CELL marker.
vec4 planeOfFace(vec4 x[4], int flags, int f)
{
  ivec3 c = FACE_CORNERS[f];
  vec3 a = x[c.x].xyz;
  vec3 b = x[c.y].xyz;
  vec3 d = x[c.z].xyz;
  vec3 n = normalize(cross(b - a, d - a));
  n = (flags & INVERTED_CORNERS) != 0 ? -n : n;
  return (flags & FLAT_CORNERS) != 0 ? vec4(x[f].xyz, 2.0 * FLAT_CELL)
                                     : vec4(n, dot(n, (a + b + d) / 3.0));
}

vec4 facePlane(int t, int f)
{
  vec4 x[4];
  int flags = cornersOfCell(t, x);
  return planeOfFace(x, flags, f);
}

// The four planes of a cell from its corners.
void planesOfCorners(vec4 x[4], int flags, out vec4 p[4])
{
  for (int f = 0; f < 4; ++f)
  {
    p[f] = planeOfFace(x, flags, f);
  }
}

void cellPlanes(int t, out vec4 p[4])
{
  vec4 x[4];
  int flags = cornersOfCell(t, x);
  planesOfCorners(x, flags, p);
}

void cellPlanesAndField(int t, out vec4 p[4], out vec4 field)
{
  vec4 x[4];
  int flags = cornersOfCell(t, x);
  planesOfCorners(x, flags, p);
  float value = cellValuesTexel(t).x;
  field = vec4(0.0, 0.0, 0.0, value);
  if (value > EMPTY_CELL && (flags & FLAT_CORNERS) == 0)
  {
    for (int v = 0; v < 4; ++v)
    {
      float w = x[v].w / (p[v].w - dot(p[v].xyz, x[v].xyz));
      field += w * vec4(-p[v].xyz, p[v].w);
    }
  }
}
