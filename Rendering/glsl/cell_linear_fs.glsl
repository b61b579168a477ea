// Linear cells without subdivision as a cell kind of the march (march_fs.glsl
// lists what a kind supplies): hexahedra (Miranda 2011), wedges, pyramids and
// tetrahedra, one grid of any of them. Cell textures
// (vtkHexahedralCellTextures), in the mesh's local frame, texels per cell
// GEOMETRY_TEXELS, NEIGHBOR_TEXELS, FIELD_TEXELS declared by
// vtkPPIRayHexahedralCellBuffers with the kinds' tables
// (ppirayLinearCellKinds.h): CELL_FACES[24 kind + 4 f + v], the faces'
// corners wound outward (-1: none), CELL_FRAME[kind], the frame's edges;
// MIXED_CELLS (false: hexahedra only), TETRAHEDRA_ONLY, PYRAMID_CELLS:
//   hexCorners[6 h .. 6 h + 5]   up to 8 corners, 24 floats, right-handed
//   hexNeighbors[2 h]            the neighbour codes through faces 0..3,
//                                [2 h + 1]: faces 4, 5, the diagonal mask, kind
//   hexCoefficients[FIELD_TEXELS h .. + 1]  c0..c7 of the field in the cell
//                                frame (hexahedron_field_fs.glsl; a pyramid's
//                                corner values, pyramid_field_fs.glsl; c0 =
//                                -3e38: empty); with QUADRATIC_FIELD, texel
//                                + 2: a quadratic tetrahedron's squares' terms
//                                (quadratic_field_fs.glsl; zero for others)
// Each quadrilateral (q0, q1, q2, q3) is two triangles split along q0-q2, or
// q1-q3 when the face's bit is set: the same split as the neighbour's, so the
// traversal is watertight on non-planar faces. The exit is the nearest
// triangle the ray actually crosses (cellExit, and where its rule cannot
// tell, cellExitSearch outside the step); if rounding lets the ray slip
// between the two (an edge), the nearest face plane it heads out of (the
// convex-cell rule). A folded entry face can be the exit too
// (exitCandidate). A flat cell (zero volume, FLAT_KIND_BIT in its kind) is crossed with zero length
// (flat_cells_fs.glsl).

//PPIRay::HexahedronField::Impl

//PPIRay::PyramidField::Impl

//PPIRay::QuadraticField::Impl

// The cell last loaded (loadCell): a handle, and its data in globals, which
// the shader compiler keeps in registers (a struct holding an array, copied
// into every function, it kept in memory: 3x the time per step).
struct Cell
{
  int id;
};
int cellKindLoaded; // ppirayLinearCellKinds.h: 0 hexahedron, 1 wedge, 2 pyramid, 3 tetrahedron
bool cellFlat;      // zero volume
vec3 cellP[8];
int cellMask; // bit f: face f split along its second diagonal
vec4 cellC;   // c0..c3
vec4 cellD;   // c4..c7
vec3 cellE;   // c8..c10 (QUADRATIC_FIELD)

// Loop iterations of a cell step spent here: the exit's two searches over 6
// faces x 2 triangles (the second, cellExitSearch, run for it by the
// march), the corners, the cubic's extrema and monotonic pieces, and a
// pyramid's field (four inversions, one more per isosurface crossed).
const bool EXIT_SEARCHES = true;
const int CELL_LOOPS = 63 +
  (PYRAMID_CELLS ? (4 + (ISO_MODE == 0 ? 0 : MAXIMUM_ISO_VALUES)) * (PYRAMID_NEWTON_STEPS + 1) : 0);

void loadCellData(int h)
{
  vec4 t0 = hexCornersTexel(GEOMETRY_TEXELS * h);
  vec4 t1 = hexCornersTexel(GEOMETRY_TEXELS * h + 1);
  vec4 t2 = hexCornersTexel(GEOMETRY_TEXELS * h + 2);
  vec4 t3 = hexCornersTexel(GEOMETRY_TEXELS * h + 3);
  vec4 t4 = hexCornersTexel(GEOMETRY_TEXELS * h + 4);
  vec4 t5 = hexCornersTexel(GEOMETRY_TEXELS * h + 5);
  cellP[0] = t0.xyz;
  cellP[1] = vec3(t0.w, t1.xy);
  cellP[2] = vec3(t1.zw, t2.x);
  cellP[3] = t2.yzw;
  cellP[4] = t3.xyz;
  cellP[5] = vec3(t3.w, t4.xy);
  cellP[6] = vec3(t4.zw, t5.x);
  cellP[7] = t5.yzw;
  ivec4 n = hexNeighborsTexel(NEIGHBOR_TEXELS * h + 1);
  cellMask = n.z;
  cellKindLoaded = n.w & (FLAT_KIND_BIT - 1);
  cellFlat = FLAT_CELLS && (n.w & FLAT_KIND_BIT) != 0;
  cellC = hexCoefficientsTexel(FIELD_TEXELS * h);
  cellD = hexCoefficientsTexel(FIELD_TEXELS * h + 1);
  cellE = QUADRATIC_FIELD ? hexCoefficientsTexel(FIELD_TEXELS * h + 2).xyz : vec3(0.0);
}

Cell loadCell(int h)
{
  Cell cell;
  cell.id = h;
  loadCellData(h);
  return cell;
}
// The kind of a cell: read only in a mixed mesh (a constant otherwise, so
// that the kind's tables fold into the code: hexahedra only, or tetrahedra
// only, quadratic ones among them).
int cellKind(Cell cell)
{
  return TETRAHEDRA_ONLY ? 3 : (MIXED_CELLS ? cellKindLoaded : 0);
}

// Triangles of face f of a cell of `kind`: 2 (a quadrilateral), 1, or 0
// (no such face); a hexahedron's 2, a constant in a mesh of hexahedra.
int faceTriangles(int kind, int f)
{
  if (!MIXED_CELLS)
  {
    return 2;
  }
  int base = 24 * kind + 4 * f;
  return CELL_FACES[base] < 0 ? 0 : (CELL_FACES[base + 3] < 0 ? 1 : 2);
}

// A triangle of a cell's face, by its corners.
struct Triangle
{
  vec3 a, b, c;
};

// The corners of triangle t (0, 1) of face f of the loaded cell of `kind`
// (corner 0's for a triangle the kind does not have: faceTriangles() tells):
// a quadrilateral (q0, q1, q2, q3) split along q0-q2 gives (q0, q1, q2),
// (q0, q2, q3); along q1-q3 (its bit in `mask`), (q1, q2, q3), (q1, q3, q0).
// In a mesh of one kind (the kind, f and t constants in unrolled loops) both
// splits' corners are read at constant indices, from registers, and the
// split chosen among the values; in a mixed mesh, whose face table is read
// at run time anyway, the indices are chosen first and three corners read.
Triangle faceTriangle(int kind, int f, int t, int mask)
{
  int base = 24 * kind + 4 * f;
  bool second = ((mask >> f) & 1) == 1;
  ivec4 q = max(ivec4(CELL_FACES[base], CELL_FACES[base + 1], CELL_FACES[base + 2],
                  CELL_FACES[base + 3]), 0);
  ivec3 along02 = t == 0 ? q.xyz : q.xzw;
  ivec3 along13 = t == 0 ? q.yzw : q.ywx;
  if (MIXED_CELLS)
  {
    ivec3 v = CELL_FACES[base + 3] < 0 ? q.xyz : (second ? along13 : along02);
    return Triangle(cellP[v.x], cellP[v.y], cellP[v.z]);
  }
  Triangle first = Triangle(cellP[along02.x], cellP[along02.y], cellP[along02.z]);
  Triangle other = Triangle(cellP[along13.x], cellP[along13.y], cellP[along13.z]);
  return second ? other : first;
}

int neighborCode(int h, int f)
{
  ivec4 n = hexNeighborsTexel(NEIGHBOR_TEXELS * h + f / 4);
  int i = f - 4 * (f / 4);
  return i == 0 ? n.x : (i == 1 ? n.y : (i == 2 ? n.z : n.w));
}

// Texel i of the neighbour array (the lists of listed_faces_fs.glsl).
ivec4 neighborListTexel(int i)
{
  return hexNeighborsTexel(i);
}

// Whether the ray reaches triangle `tri` at parameter tf: the crossing
// point is on the inner side of its three edges (with a relative tolerance,
// so that an edge hit counts for both triangles).
bool crossesTriangle(Triangle tri, vec3 origin, vec3 direction, float tf)
{
  vec3 a = tri.a, b = tri.b, c = tri.c;
  vec3 normal = cross(b - a, c - a);
  vec3 x = origin + tf * direction;
  float tolerance = -1.0e-5 * dot(normal, normal);
  return dot(cross(b - a, x - a), normal) >= tolerance &&
    dot(cross(c - b, x - b), normal) >= tolerance && dot(cross(a - c, x - c), normal) >= tolerance;
}

// Where the ray meets the plane of triangle (a, b, c), t_f, and n . r with
// n = (b - a) x (c - a), outward for a right-handed cell: > 0 heading out,
// < 0 heading in.
void trianglePlaneCrossing(Triangle tri, vec3 origin, vec3 direction, out float along, out float tf)
{
  vec3 normal = cross(tri.b - tri.a, tri.c - tri.a);
  along = dot(normal, direction);
  tf = dot(normal, tri.a - origin) / along;
}

// Where the ray meets the plane of triangle `side` of face f of the loaded
// cell (trianglePlaneCrossing), and its corners; along = 0 (heading
// neither out nor in) where the cell's kind has no such triangle. Without
// an early return, and its callers' loops without `continue`: the shader
// compiler then unrolls them (results.md, "Cost of the one march").
void faceTriangleCrossing(Cell cell, int f, int side, vec3 origin, vec3 direction,
  out Triangle tri, out float along, out float tf)
{
  tri = faceTriangle(cellKind(cell), f, side, cellMask);
  trianglePlaneCrossing(tri, origin, direction, along, tf);
  along = side < faceTriangles(cellKind(cell), f) ? along : 0.0;
}

// The cell a boundary triangle code (2 (FACES h + f) + triangle) enters,
// `face`, and where the ray meets that triangle's plane (no earlier than
// `resume`).
int boundaryEntry(int code, vec3 origin, vec3 direction, float resume, out int face, out float t)
{
  int cell = code / (2 * FACES);
  face = (code - 2 * FACES * cell) / 2;
  Cell c = loadCell(cell);
  Triangle tri = faceTriangle(cellKind(c), face, code - 2 * FACES * cell - 2 * face, cellMask);
  vec3 n = cross(tri.b - tri.a, tri.c - tri.a);
  n = cellFlat && dot(n, direction) > 0.0 ? -n : n; // a flat cell has no outside
  t = max(dot(n, tri.a - origin) / min(dot(n, direction), -1.0e-30), resume);
  return cell;
}

// Whether a triangle of face f, met at tf, may be where the ray leaves a cell
// it entered at t through `entryFace`. A triangle of the entry face may, if
// it is met clearly ahead of t: a non-planar face folded across a grazing ray
// is crossed twice, and the ray goes back into the cell it came from (seen in
// UNISIM-II's thin layers). The entry triangle itself, and the other half of
// a planar face, are met at t: rounding cannot bounce a ray through a face.
bool exitCandidate(int f, int entryFace, float tf, float t)
{
  return f != entryFace || tf > t + 1.0e-5 * abs(t);
}

// The nearest triangle the ray crosses heading out, at or after t: its face
// (-1: none) and tHit. In a strongly non-convex cell the line can leave,
// come back in and leave again: the first face in face order with a
// crossed triangle is not always the nearest.
int nearestCrossedFace(Cell cell, int entryFace, vec3 origin, vec3 direction, float t,
  out float tHit)
{
  tHit = INFINITY;
  int hitFace = -1;
  for (int f = 0; f < 6; ++f)
  {
    for (int side = 0; side < 2; ++side)
    {
      Triangle tri;
      float along, tf;
      faceTriangleCrossing(cell, f, side, origin, direction, tri, along, tf);
      if (along > 0.0 && tf < tHit && tf >= t - 1.0e-6 * abs(t) &&
        exitCandidate(f, entryFace, tf, t) && crossesTriangle(tri, origin, direction, tf))
      {
        tHit = tf;
        hitFace = f;
      }
    }
  }
  return hitFace;
}

// The face of the loaded flat cell, other than `entryFace`, whose triangle
// best contains x (the largest smallest barycentric coordinate,
// flat_cells_fs.glsl); -1: none.
int flatCellExit(Cell cell, int entryFace, vec3 x)
{
  float area2[12], score[12];
  float largest = 0.0;
  for (int f = 0; f < 6; ++f)
  {
    for (int side = 0; side < 2; ++side)
    {
      Triangle tri = faceTriangle(cellKind(cell), f, side, cellMask);
      score[2 * f + side] = smallestBarycentric(tri.a, tri.b, tri.c, x, area2[2 * f + side]);
      area2[2 * f + side] = side < faceTriangles(cellKind(cell), f) ? area2[2 * f + side] : 0.0;
      largest = max(largest, area2[2 * f + side]);
    }
  }
  int best = -1;
  float bestScore = -INFINITY;
  for (int i = 0; i < 12; ++i)
  {
    if (i / 2 != entryFace && hasArea(area2[i], largest) && score[i] > bestScore)
    {
      bestScore = score[i];
      best = i / 2;
    }
  }
  return best;
}

// The face of a hexahedron across the one a walk back came in by, where it
// has a neighbour (-1: none, a boundary face with or without a re-entry
// list, or another kind).
int oppositeFace(int cell, int kind, int entryFace)
{
  int across = entryFace >= 0 && kind == 0 ? entryFace ^ 1 : -1;
  int code = across >= 0 ? neighborCode(cell, across) : -1;
  return code != -1 && !(REENTRY_EDGES && code >= REENTRY_FACE) ? across : -1;
}

// The exit planes of the loaded cell from t: the nearest face by the
// nearer of its triangles' planes the ray heads out of (exit candidates),
// planeFace (-1: none), with that triangle (near, met at tNear) and the
// face's other (far, tFar; INFINITY where it is no candidate); tNext, the
// nearest plane of any other face. Walking back: inFace, the face of the
// farthest plane it heads into other than entryFace's.
struct ExitPlanes
{
  int planeFace, inFace;
  float tNear, tFar, tNext;
  Triangle near, far;
};

ExitPlanes exitPlanes(Cell cell, int entryFace, vec3 origin, vec3 direction, float t, bool backwards)
{
  ExitPlanes e;
  e.planeFace = -1;
  e.inFace = -1;
  e.tNear = INFINITY;
  e.tFar = INFINITY;
  e.tNext = INFINITY;
  float tIn = -INFINITY;
  for (int f = 0; f < 6; ++f)
  {
    Triangle tri0, tri1;
    float along0, along1, tf0, tf1;
    faceTriangleCrossing(cell, f, 0, origin, direction, tri0, along0, tf0);
    faceTriangleCrossing(cell, f, 1, origin, direction, tri1, along1, tf1);
    float t0 = along0 > 0.0 && exitCandidate(f, entryFace, tf0, t) ? tf0 : INFINITY;
    float t1 = along1 > 0.0 && exitCandidate(f, entryFace, tf1, t) ? tf1 : INFINITY;
    float tFace = min(t0, t1);
    e.tNext = tFace < e.tNear ? e.tNear : min(e.tNext, tFace);
    if (tFace < e.tNear)
    {
      e.planeFace = f;
      e.tNear = tFace;
      e.tFar = max(t0, t1);
      e.near = t0 <= t1 ? tri0 : tri1;
      e.far = t0 <= t1 ? tri1 : tri0;
    }
    bool in0 = backwards && f != entryFace && along0 < 0.0 && tf0 > tIn;
    tIn = in0 ? tf0 : tIn;
    bool in1 = backwards && f != entryFace && along1 < 0.0 && tf1 > tIn;
    tIn = in1 ? tf1 : tIn;
    e.inFace = in0 || in1 ? f : e.inFace;
  }
  return e;
}

// The face the ray leaves the cell by, entered at t through `entryFace`
// (-1 at a start inside it), and where (tExit >= t). Forwards: the nearest
// face plane the ray heads out of, if the ray crosses that triangle; else
// the same face's other triangle if the ray crosses it before any other
// face's plane (a concave fold of a non-planar face: nothing can be crossed
// earlier); else (a ray slipping between two triangles at an edge)
// EXIT_SEARCH: cellExitSearch decides. Backwards (a fold walked back): the
// face opposite the one the walk came in by (the next layer of a fold, also
// where the line entered the cell through the side), else the farthest
// plane the ray heads into. A flat cell: flatCellExit, at t.
int cellExit(Cell cell, int entryFace, vec3 origin, vec3 direction, float t, bool backwards,
  out float tExit)
{
  tExit = t;
  if (cellFlat)
  {
    return flatCellExit(cell, entryFace, origin + t * direction);
  }
  ExitPlanes e = exitPlanes(cell, entryFace, origin, direction, t, backwards);
  if (backwards)
  {
    int across = oppositeFace(cell.id, cellKind(cell), entryFace);
    return across >= 0 ? across : e.inFace;
  }
  bool ahead = e.planeFace >= 0 && e.tNear >= t - 1.0e-6 * abs(t);
  if (ahead && crossesTriangle(e.near, origin, direction, e.tNear))
  {
    tExit = max(e.tNear, t);
    return e.planeFace;
  }
  if (ahead && e.tFar <= e.tNext && crossesTriangle(e.far, origin, direction, e.tFar))
  {
    tExit = max(e.tFar, t);
    return e.planeFace;
  }
  return e.planeFace >= 0 ? EXIT_SEARCH : -1;
}

// Where cellExit's rule does not decide (EXIT_SEARCH), forwards: the
// nearest triangle the ray crosses heading out, else the nearest plane it
// heads out of (the convex-cell rule), and where (tExit >= t).
int cellExitSearch(Cell cell, int entryFace, vec3 origin, vec3 direction, float t, out float tExit)
{
  float tHit;
  int hitFace = nearestCrossedFace(cell, entryFace, origin, direction, t, tHit);
  ExitPlanes e = exitPlanes(cell, entryFace, origin, direction, t, false);
  tExit = max(hitFace >= 0 ? tHit : e.tNear, t);
  return hitFace >= 0 ? hitFace : e.planeFace;
}

// Whether the ray heads out of the cell through every triangle of face f
// (n . r > 1e-5 |n|, beyond rounding): entered by f, the cell lies behind it.
bool headsOutOfFace(Cell cell, int f, vec3 direction)
{
  if (cellFlat)
  {
    return false;
  }
  int triangles = faceTriangles(cellKind(cell), f);
  bool leaves = triangles > 0;
  for (int side = 0; side < 2; ++side)
  {
    Triangle tri = faceTriangle(cellKind(cell), f, side, cellMask);
    vec3 n = cross(tri.b - tri.a, tri.c - tri.a);
    leaves = leaves && (side >= triangles || dot(n, direction) > 1.0e-5 * length(n));
  }
  return leaves;
}

bool hasField(Cell cell)
{
  return cellC.x > EMPTY_CELL;
}

// The frame of the cell (its kind's edges from corner 0: a hexahedron's to
// corners 1, 3, 4), unless it is singular to float precision.
bool cellFrame(Cell cell, out mat3 toFrame)
{
  ivec3 axes = CELL_FRAME[cellKind(cell)];
  mat3 frame = mat3(cellP[axes.x] - cellP[0], cellP[axes.y] - cellP[0], cellP[axes.z] - cellP[0]);
  float det = determinant(frame);
  float scale = length(frame[0]) * length(frame[1]) * length(frame[2]);
  toFrame = abs(det) > 1.0e-6 * scale ? inverse(frame) : mat3(0.0);
  return abs(det) > 1.0e-6 * scale;
}

// Whether the loaded cell's field has second-order terms in its frame (a
// wedge's products, a quadratic tetrahedron's): not a linear tetrahedron.
bool nonlinearField(Cell cell)
{
  return cellKind(cell) != 3 ||
    (QUADRATIC_FIELD && (any(notEqual(cellD.xyz, vec3(0.0))) || any(notEqual(cellE, vec3(0.0)))));
}

// The field on the stretch past `entry` (len long): in the cell frame a
// polynomial in x expanded at the entry point (trilinear: a cubic; a
// quadratic tetrahedron's: a quadratic; a linear one's: linear), none where
// the frame is singular; a pyramid's by pyramidStretch.
bool fieldAlongRay(Cell cell, vec3 entry, vec3 exit, float len, vec3 direction, out Stretch s)
{
  s.degree = nonlinearField(cell) ? 3 : 1;
  if (PYRAMID_CELLS && cellKind(cell) == 2)
  {
    s.w = pyramidStretch(cellP, cellC, cellD.x, entry, direction, len, s.sEnd);
    return true;
  }
  mat3 toFrame;
  bool regular = cellFrame(cell, toFrame);
  vec3 q = toFrame * (entry - cellP[0]), r = toFrame * direction;
  s.w = rayCubic(cellC, cellD, q, r) + (QUADRATIC_FIELD ? raySquares(cellE, q, r) : vec4(0.0));
  s.sEnd = cubicValue(s.w, len);
  return regular;
}

// The degree of a stretch's field (a constant where the kind has one).
int stretchDegree(Stretch s)
{
  return MIXED_CELLS ? s.degree : 3;
}

// The field's gradient at x in the local frame: through the cell frame,
// grad f = T^T grad_uvw f; a pyramid's, pyramidGradient.
vec3 fieldGradient(Cell cell, vec3 x)
{
  if (PYRAMID_CELLS && cellKind(cell) == 2)
  {
    return pyramidGradient(cellP, cellC, cellD.x, x);
  }
  mat3 toFrame;
  cellFrame(cell, toFrame);
  vec3 p = toFrame * (x - cellP[0]);
  return transpose(toFrame) *
    (trilinearGradient(cellC, cellD, p) + (QUADRATIC_FIELD ? squaresGradient(cellE, p) : vec3(0.0)));
}

// How far x, on face e of cell h, lies outside that face: outside the
// cell's other faces' triangle planes (unit normals); a flat cell's, outside
// the nearer of face e's triangles in their planes.
float outsideFace(int h, int e, vec3 x)
{
  Cell cell = loadCell(h);
  if (cellFlat)
  {
    Triangle u = faceTriangle(cellKind(cell), e, 0, cellMask);
    Triangle w = faceTriangle(cellKind(cell), e, 1, cellMask);
    float second = faceTriangles(cellKind(cell), e) > 1 ? outsideTriangle(w.a, w.b, w.c, x) : INFINITY;
    return min(outsideTriangle(u.a, u.b, u.c, x), second);
  }
  float outside = -INFINITY;
  for (int f = 0; f < 6; ++f)
  {
    for (int side = 0; side < 2; ++side)
    {
      Triangle tri = faceTriangle(cellKind(cell), f, side, cellMask);
      vec3 n = normalize(cross(tri.b - tri.a, tri.c - tri.a));
      bool other = f != e && side < faceTriangles(cellKind(cell), f);
      outside = max(outside, other ? dot(n, x - tri.a) : -INFINITY);
    }
  }
  return outside;
}

// Where the ray, at tMin or later, enters cell h through face e (te:
// the nearer of its two triangles' planes it heads into), and how far that
// point lies outside the face; INFINITY where it heads in through neither
// or the cell is flat.
float faceEntry(int h, int e, vec3 origin, vec3 direction, float tMin, out float te)
{
  Cell cell = loadCell(h);
  te = INFINITY;
  if (cellFlat)
  {
    return INFINITY;
  }
  for (int side = 0; side < 2; ++side)
  {
    Triangle tri;
    float along, tf;
    faceTriangleCrossing(cell, e, side, origin, direction, tri, along, tf);
    if (along < 0.0)
    {
      te = min(te, max(tf, tMin));
    }
  }
  return te < INFINITY ? outsideFace(h, e, origin + te * direction) : INFINITY;
}
