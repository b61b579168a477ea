// Tetrahedra as a cell kind of the march (march_fs.glsl lists what a kind
// supplies), read through one of two layouts (tetrahedron_planes_fs.glsl,
// tetrahedron_corners_fs.glsl, chosen by vtkPPIRayTetrahedralCellBuffers):
// facePlane(t, f) = (n_f, d_f), outward unit normal, n_f . x = d_f on face f,
// or a flat cell's corner f (x_f, FLAT_CELL); the field (g, s0),
// s(x) = g . x + s0 (s0 = -3e38: render empty), linear along a ray; and
//   neighborsTexel(NEIGHBOR_TEXELS t)[f] = the neighbour code through face f.
// The exit face is the nearest face plane the ray is heading out of
// (Weiler et al. 2003, Sec. 3.2): t_f = (d_f - n_f . o) / (n_f . r), n_f . r > 0.
// A flat cell (zero volume) is crossed with zero length, out through the face
// whose triangle best contains the point.

//PPIRay::TetrahedronLayout::Impl

// The cell last loaded (loadCell): a handle, and its data in globals (a
// struct holding an array, copied into every function, stays in memory).
struct Cell
{
  int id;
};
vec4 cellPlaneData[4]; // face planes, or a flat cell's corners
vec4 cellFieldData;    // the field (g, s0)

// Loop iterations of a cell step spent here: reading the cell (PLANE_LOOPS
// + FIELD_LOOPS), the exit search (4, a flat cell's 4 + 4), and 4 to spare.
const int CELL_LOOPS = 12 + PLANE_LOOPS + FIELD_LOOPS;
const bool EXIT_SEARCHES = false; // cellExit's planes always decide

Cell loadCell(int t)
{
  Cell cell;
  cell.id = t;
  cellPlanesAndField(t, cellPlaneData, cellFieldData);
  return cell;
}

bool isFlatCell(Cell cell)
{
  return FLAT_CELLS && cellPlaneData[0].w > FLAT_CELL;
}

int neighborCode(int t, int f)
{
  return neighborsTexel(NEIGHBOR_TEXELS * t)[f];
}

// Texel i of the neighbour array (the lists of listed_faces_fs.glsl).
ivec4 neighborListTexel(int i)
{
  return neighborsTexel(i);
}

// The cell a boundary face code (FACES t + f) enters, `face`, and where the
// ray meets that face's plane (no earlier than `resume`). A flat cell on the
// boundary: the plane of its entry triangle.
int boundaryEntry(int code, vec3 origin, vec3 direction, float resume, out int face, out float t)
{
  int cell = code / FACES;
  face = code - FACES * cell;
  vec4 plane = facePlane(cell, face);
  if (plane.w > FLAT_CELL)
  {
    vec3 a = facePlane(cell, (face + 1) & 3).xyz;
    vec3 n =
      cross(facePlane(cell, (face + 2) & 3).xyz - a, facePlane(cell, (face + 3) & 3).xyz - a);
    n = dot(n, direction) > 0.0 ? -n : n;
    plane = vec4(n, dot(n, a));
  }
  t = max((plane.w - dot(plane.xyz, origin)) / min(dot(plane.xyz, direction), -1.0e-30), resume);
  return cell;
}

// The face of a flat cell (corners c_v, face f = the three other than c_f),
// other than `entryFace`, whose triangle best contains x (the largest
// smallest barycentric coordinate, flat_cells_fs.glsl); -1: none.
int flatCellExit(vec4 c[4], int entryFace, vec3 x)
{
  float area2[4], score[4];
  float largest = 0.0;
  for (int f = 0; f < 4; ++f)
  {
    score[f] = smallestBarycentric(
      c[(f + 1) & 3].xyz, c[(f + 2) & 3].xyz, c[(f + 3) & 3].xyz, x, area2[f]);
    largest = max(largest, area2[f]);
  }
  int best = -1;
  float bestScore = -INFINITY;
  for (int f = 0; f < 4; ++f)
  {
    if (f != entryFace && hasArea(area2[f], largest) && score[f] > bestScore)
    {
      bestScore = score[f];
      best = f;
    }
  }
  return best;
}

// The face the ray leaves the cell by, entered at t through `entryFace`
// (-1 at a start inside it), and where (tExit >= t; t for a flat cell).
// Forwards: the nearest plane the ray heads out of. Backwards (the cell's
// stretch lies behind t, a fold walked back): the face the line enters it
// by, the farthest plane it heads into. -1: none.
int cellExit(Cell cell, int entryFace, vec3 origin, vec3 direction, float t, bool backwards,
  out float tExit)
{
  tExit = t;
  if (isFlatCell(cell))
  {
    return flatCellExit(cellPlaneData, entryFace, origin + t * direction);
  }
  float tFace = backwards ? -INFINITY : INFINITY;
  int exitFace = -1;
  for (int f = 0; f < 4; ++f)
  {
    float along = dot(cellPlaneData[f].xyz, direction);
    float tf = (cellPlaneData[f].w - dot(cellPlaneData[f].xyz, origin)) / along;
    bool better = backwards ? (along < 0.0 && tf > tFace) : (along > 0.0 && tf < tFace);
    if (f != entryFace && better)
    {
      tFace = tf;
      exitFace = f;
    }
  }
  tExit = backwards ? t : max(tFace, t);
  return exitFace;
}

// Never needed (EXIT_SEARCHES): the march's interface.
int cellExitSearch(Cell cell, int entryFace, vec3 origin, vec3 direction, float t, out float tExit)
{
  tExit = t;
  return -1;
}

// Whether the ray heads out of the cell through face f (n_f . r > 1e-5,
// beyond rounding): entered by f, the cell lies behind it.
bool headsOutOfFace(Cell cell, int f, vec3 direction)
{
  // Selected at constant indices: an indexed read would keep the planes in
  // memory for the whole step loop.
  vec3 n = f == 0 ? cellPlaneData[0].xyz
                  : (f == 1 ? cellPlaneData[1].xyz
                            : (f == 2 ? cellPlaneData[2].xyz : cellPlaneData[3].xyz));
  return !isFlatCell(cell) && dot(n, direction) > 1.0e-5;
}

bool hasField(Cell cell)
{
  return cellFieldData.w > EMPTY_CELL;
}

// The field on the stretch from `entry` to `exit` (len apart): linear,
// evaluated at both ends.
bool fieldAlongRay(Cell cell, vec3 entry, vec3 exit, float len, vec3 direction, out Stretch s)
{
  s.degree = 1;
  float sFront = dot(cellFieldData.xyz, entry) + cellFieldData.w;
  s.sEnd = dot(cellFieldData.xyz, exit) + cellFieldData.w;
  s.w = vec4(sFront, (s.sEnd - sFront) / len, 0.0, 0.0);
  return true;
}

// The degree of a stretch's field (a constant where the kind has one).
int stretchDegree(Stretch s)
{
  return 1;
}

vec3 fieldGradient(Cell cell, vec3 x)
{
  return cellFieldData.xyz;
}

// How far x lies outside the planes p other than e: max_f (n_f . x - d_f).
float outsidePlanesBut(vec4 p[4], int e, vec3 x)
{
  float outside = -INFINITY;
  for (int f = 0; f < 4; ++f)
  {
    outside = f == e ? outside : max(outside, dot(p[f].xyz, x) - p[f].w);
  }
  return outside;
}

// How far x, on face e of cell t, lies outside that face: outside the
// cell's three other planes (n_f . x - d_f), or, the cell flat, outside the
// triangle of the corners other than e (PLANE_LOOPS + 4 iterations).
float outsideFace(int t, int e, vec3 x)
{
  vec4 p[4];
  cellPlanes(t, p);
  if (FLAT_CELLS && p[0].w > FLAT_CELL)
  {
    return outsideTriangle(p[(e + 1) & 3].xyz, p[(e + 2) & 3].xyz, p[(e + 3) & 3].xyz, x);
  }
  return outsidePlanesBut(p, e, x);
}

// Where the ray, at tMin or later, enters cell t through face e (te), and how
// far that point lies outside the face; INFINITY where the ray does not head
// in through it or the cell is flat (PLANE_LOOPS + 4 iterations).
float faceEntry(int t, int e, vec3 origin, vec3 direction, float tMin, out float te)
{
  vec4 p[4];
  cellPlanes(t, p);
  vec4 pe = p[e];
  float along = dot(pe.xyz, direction);
  te = max((pe.w - dot(pe.xyz, origin)) / along, tMin);
  if ((FLAT_CELLS && pe.w > FLAT_CELL) || !(along < 0.0))
  {
    return INFINITY;
  }
  vec3 y = origin + te * direction;
  return outsidePlanesBut(p, e, y);
}
