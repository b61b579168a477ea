// Tetrahedra as stored planes (vtkTetrahedralCellTextures::PLANES; Espinha &
// Celes 2005, Sec. 3.1), GEOMETRY_TEXELS = 4 and FIELD_TEXELS = 1 per cell:
//   facePlanes[4 t + f] = (n_f, d_f), outward unit normal, n_f . x = d_f on
//                         face f; a flat cell: its corners (x_v, FLAT_CELL)
//   field[t]            = (g, s0): s(x) = g . x + s0 (s0 = -3e38: render empty)

// Plane of face f of cell t (a flat cell: its corner f).
vec4 facePlane(int t, int f)
{
  return facePlanesTexel(GEOMETRY_TEXELS * t + f);
}

// The four planes of cell t (PLANE_LOOPS).
void cellPlanes(int t, out vec4 p[4])
{
  for (int f = 0; f < 4; ++f)
  {
    p[f] = facePlane(t, f);
  }
}

// The planes of cell t and its field (g, s0) (PLANE_LOOPS + FIELD_LOOPS).
void cellPlanesAndField(int t, out vec4 p[4], out vec4 field)
{
  cellPlanes(t, p);
  field = fieldTexel(FIELD_TEXELS * t);
}
