//VTK::System::Dec
#if __VERSION__ < 330
// floatBitsToUint, uintBitsToFloat (continuations, march_common_fs.glsl)
#extension GL_ARB_shader_bit_encoding : require
#endif
// March pass for hexahedral meshes rendered without subdivision (Miranda
// 2011): per pixel, from the cell a ray enters through (entry pass) to where
// it leaves the mesh, one hexahedron at a time.
//
// Cell textures (vtkHexahedralCellTextures), in the mesh's local frame (texels
// per cell: GEOMETRY_TEXELS = 6, NEIGHBOR_TEXELS = FIELD_TEXELS = 2, declared
// by vtkPPIRayHexahedralCellBuffers):
//   hexCorners[6 h .. 6 h + 5]   the 8 corners, 24 floats, right-handed
//   hexNeighbors[2 h]            6 h' + f' (the cell and face entered) through
//                                faces 0..3, [2 h + 1]: faces 4, 5, the diagonal
//                                mask, 0 (-1: boundary; across a folded face
//                                -(6 h' + f' + 2), or -(6 h' + f' + 2 + TURN_BACK)
//                                where h is the inverted side)
//   hexCoefficients[2 h .. + 1]  c0..c7 of the field in the cell frame (c0 = -3e38: empty)
// Each face (q0, q1, q2, q3) of vtkHexahedron is two triangles split along
// q0-q2, or q1-q3 when the face's bit is set: the same split as the
// neighbour's, so the traversal is watertight on non-planar faces. The exit
// is the nearest triangle the ray actually crosses; if rounding lets the ray
// slip between the two (an edge), the nearest face plane it heads out of
// (the convex-cell rule of the tetrahedral march). A folded entry face can be
// the exit too (exitCandidate). Across a folded face (both cells on one side
// of it: a tangled mesh) the ray walks backwards (through the inverted cell
// across it, or through the inverted cell it is in), across each cell to
// the face opposite the one it came in by, integrating nothing, until it
// crosses a folded face into the next forward part; if that walk leaves the
// mesh, the plain walk goes on from the fold (Documentation/algorithms.md).

//PPIRay::MarchCommon::Impl

// vtkHexahedron's faces, wound outward.
const int FACE[24] =
  int[24](0, 4, 7, 3, 1, 2, 6, 5, 0, 1, 5, 4, 3, 7, 6, 2, 0, 3, 2, 1, 4, 5, 6, 7);

//PPIRay::TransferFunction::Impl

//PPIRay::IsoSurface::Impl

//PPIRay::Projection::Impl

//PPIRay::Integrate::Impl

//PPIRay::Ray::Impl

//PPIRay::HexahedronField::Impl

//PPIRay::GaussLegendre::Impl

//PPIRay::Hexahedron::Impl

//PPIRay::ProjectionCubic::Impl

// One cell's stretch of the ray, x in [0, len] past the entry point: the
// cubic w split at its extrema into monotonic pieces, each split at the
// isosurfaces it crosses (cubicCrossing), the volume integrated piece by
// piece by the hexahedron mode (unless ISO_MODE is 2) and each surface
// composited where it is crossed, with the trilinear gradient at the root
// (c, d: coefficients; q + x r: frame coordinates; toFrame: local to frame).
// The crossings are counted from the interval j carried in from the previous
// cell, so a surface through the entry face (a jump of cell data, or rounding
// between the two cells' evaluations of a point field) is composited once, at
// the entry (cubicCrossing's nearer end).
int integrateHexahedronSegment(vec4 w, float len, vec4 c, vec4 d, vec3 q, vec3 r, mat3 toFrame,
  vec3 entry, vec3 direction, int k, inout int j, inout vec4 color)
{
  float roots[2];
  int extrema = cubicExtrema(w, len, roots);
  float x0 = 0.0;
  float s0 = w.x;
  int surface = -1;
  if (ISO_MODE != 0)
  {
    j = j < 0 ? isoInterval(s0, 0) : j;
  }
  for (int piece = 0; piece <= extrema; ++piece)
  {
    float x1 = piece < extrema ? roots[piece] : len;
    float s1 = cubicValue(w, x1);
    float xA = x0;
    float sA = s0;
    for (int i = 0; ISO_MODE != 0 && i < MAXIMUM_ISO_VALUES; ++i)
    {
      int next = nextIsoCrossing(s1, j, surface);
      if (surface < 0)
      {
        break;
      }
      float v = isoValues[surface];
      float xv = cubicCrossing(w, v, xA, x1);
      if (ISO_MODE == 1)
      {
        k = integrateMonotonicPiece(w, xA, xv, sA, v, k, color);
      }
      compositeIsoSurface(surface, entry + xv * direction,
        transpose(toFrame) * trilinearGradient(c, d, q + xv * r), direction, color);
      xA = xv;
      sA = v;
      j = next;
    }
    if (ISO_MODE != 2)
    {
      k = integrateMonotonicPiece(w, xA, x1, sA, s1, k, color);
    }
    x0 = x1;
    s0 = s1;
  }
  return k;
}

void loadCorners(int h, out vec3 p[8])
{
  vec4 t0 = hexCornersTexel(GEOMETRY_TEXELS * h);
  vec4 t1 = hexCornersTexel(GEOMETRY_TEXELS * h + 1);
  vec4 t2 = hexCornersTexel(GEOMETRY_TEXELS * h + 2);
  vec4 t3 = hexCornersTexel(GEOMETRY_TEXELS * h + 3);
  vec4 t4 = hexCornersTexel(GEOMETRY_TEXELS * h + 4);
  vec4 t5 = hexCornersTexel(GEOMETRY_TEXELS * h + 5);
  p[0] = t0.xyz;
  p[1] = vec3(t0.w, t1.xy);
  p[2] = vec3(t1.zw, t2.x);
  p[3] = t2.yzw;
  p[4] = t3.xyz;
  p[5] = vec3(t3.w, t4.xy);
  p[6] = vec3(t4.zw, t5.x);
  p[7] = t5.yzw;
}

// Corner indices of triangle t (0, 1) of face f.
ivec3 faceTriangle(int f, int t, int mask)
{
  bool second = ((mask >> f) & 1) == 1;
  int q0 = FACE[4 * f], q1 = FACE[4 * f + 1], q2 = FACE[4 * f + 2], q3 = FACE[4 * f + 3];
  if (second)
  {
    return t == 0 ? ivec3(q1, q2, q3) : ivec3(q1, q3, q0);
  }
  return t == 0 ? ivec3(q0, q1, q2) : ivec3(q0, q2, q3);
}

// The neighbour code through face f of hexahedron h.
int neighborThrough(int h, int f)
{
  ivec4 n = hexNeighborsTexel(NEIGHBOR_TEXELS * h + f / 4);
  int i = f - 4 * (f / 4);
  return i == 0 ? n.x : (i == 1 ? n.y : (i == 2 ? n.z : n.w));
}

// 6 h' + f' of a neighbour code (-1: none).
int neighborEntry(int code)
{
  int entry = code < -1 ? -code - 2 : code;
  return entry >= TURN_BACK ? entry - TURN_BACK : entry;
}

// Whether the ray reaches triangle v (corner indices into p) at parameter tf:
// the crossing point is on the inner side of its three edges (with a
// relative tolerance, so that an edge hit counts for both triangles).
bool crossesTriangle(vec3 p[8], ivec3 v, vec3 origin, vec3 direction, float tf)
{
  vec3 a = p[v.x], b = p[v.y], c = p[v.z];
  vec3 normal = cross(b - a, c - a);
  vec3 x = origin + tf * direction;
  float tolerance = -1.0e-5 * dot(normal, normal);
  return dot(cross(b - a, x - a), normal) >= tolerance &&
    dot(cross(c - b, x - b), normal) >= tolerance && dot(cross(a - c, x - c), normal) >= tolerance;
}

// Where the ray meets the plane of triangle v (corner indices into p), t_f,
// and n . r with n = (p_v1 - p_v0) x (p_v2 - p_v0), outward for a
// right-handed cell: > 0 heading out, < 0 heading in.
void trianglePlaneCrossing(vec3 p[8], ivec3 v, vec3 origin, vec3 direction, out float along,
  out float tf)
{
  vec3 normal = cross(p[v.y] - p[v.x], p[v.z] - p[v.x]);
  along = dot(normal, direction);
  tf = dot(normal, p[v.x] - origin) / along;
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

// Loop iterations a cell step may take outside its pieces (march_common_fs.glsl):
// its own, the two searches over 6 faces x 2 triangles, the corners, the
// cubic's extrema and monotonic pieces, the isovalue crossings and walks.
const int HEX_STEP_LOOPS = 64 + (ISO_MODE == 0 ? 0 : 4 * MAXIMUM_ISO_VALUES);

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 before;
  float resume;
  int startCell, startFace;
  bool resumeBackwards;
  int stepsTaken;
  int code = enterPeel(pixel, before, resume, startCell, startFace, resumeBackwards, stepsTaken); // 2 (FACES h + f) + t
  if (code < 0 && startCell < 0)
  {
    return;
  }

  vec2 ndc = 2.0 * texCoord - 1.0;
  vec3 origin, direction;
  pixelRay(ndc, origin, direction);

  // A projection's state so far (earlier peels).
  vec3 projection = previousProjection(pixel);

  // Opaque geometry stops the ray at its depth; clipping planes keep
  // [tKept, tStop] of it.
  vec2 kept = keptRange(origin, direction);
  float tKept = kept.x;
  float tStop = min(opaqueStop(opaqueDepth, pixel, ndc, origin, direction), kept.y);

  // Into the first cell: through a triangle of its entry face, or already in
  // it at the near plane (t = 0) when the ray starts inside the mesh, or
  // where the previous pass ran out of loops.
  int cell = startCell < 0 ? code / (2 * FACES) : startCell;
  vec3 p[8];
  loadCorners(cell, p);
  int mask = hexNeighborsTexel(NEIGHBOR_TEXELS * cell + 1).z;
  int entryFace = startFace;
  float t = resume;
  if (startCell < 0)
  {
    entryFace = (code - 2 * FACES * cell) / 2;
    ivec3 tri = faceTriangle(entryFace, code - 2 * FACES * cell - 2 * entryFace, mask);
    vec3 n0 = cross(p[tri.y] - p[tri.x], p[tri.z] - p[tri.x]);
    t = max(dot(n0, p[tri.x] - origin) / min(dot(n0, direction), -1.0e-30), resume);
  }

  int k = -1;
  int j = -1; // isovalue interval, set at the first cell
  vec4 color = vec4(0.0);
  float reached = t;
  bool backwards = resumeBackwards;
  int foldCell = -1, foldFace = -1;
  float continuation = 0.0;
  int step = stepsTaken;
  for (; step < maximumSteps; ++step)
  {
    // The loop budget, per cell step: a step left unfinished is redone whole
    // by the next pass, whose first step always finishes (progress); a walk
    // back (nothing integrated, a fold to return to) is never cut.
    loopsWaived = step == stepsTaken;
    if (!backwards && !spendLoops(HEX_STEP_LOOPS))
    {
      continuation = continuationCode(cell, entryFace, false);
      reached = t;
      break;
    }
    // Exit: the nearest face plane the ray heads out of (the convex-cell
    // rule), accepted if the ray crosses that triangle; else (a concave fold
    // of a non-planar face) the nearest triangle actually crossed. Walking
    // back: the face opposite the one the walk came in by (the next layer of
    // a fold, also where the line entered the cell through the side), else
    // the farthest plane the ray heads into.
    float tPlane = INFINITY, tIn = -INFINITY;
    int planeFace = -1, planeSide = 0, inFace = -1;
    for (int f = 0; f < 6; ++f)
    {
      for (int side = 0; side < 2; ++side)
      {
        ivec3 v = faceTriangle(f, side, mask);
        float along, tf;
        trianglePlaneCrossing(p, v, origin, direction, along, tf);
        if (along > 0.0 && tf < tPlane && exitCandidate(f, entryFace, tf, t))
        {
          tPlane = tf;
          planeFace = f;
          planeSide = side;
        }
        if (FOLDS && f != entryFace && along < 0.0 && tf > tIn)
        {
          tIn = tf;
          inFace = f;
        }
      }
    }
    int exitFace = -1;
    float tExit = t;
    if (FOLDS && backwards)
    {
      int across = entryFace >= 0 ? entryFace ^ 1 : -1;
      exitFace = across >= 0 && neighborThrough(cell, across) != -1 ? across : inFace;
    }
    else
    {
      float tHit = INFINITY;
      int hitFace = -1;
      if (planeFace >= 0 && tPlane >= t - 1.0e-6 * abs(t) &&
        crossesTriangle(p, faceTriangle(planeFace, planeSide, mask), origin, direction, tPlane))
      {
        tHit = tPlane;
        hitFace = planeFace;
      }
      for (int f = 0; f < 6 && hitFace < 0; ++f)
      {
        for (int side = 0; side < 2; ++side)
        {
          ivec3 v = faceTriangle(f, side, mask);
          float along, tf;
          trianglePlaneCrossing(p, v, origin, direction, along, tf);
          if (along > 0.0 && tf < tHit && tf >= t - 1.0e-6 * abs(t) &&
            exitCandidate(f, entryFace, tf, t) && crossesTriangle(p, v, origin, direction, tf))
          {
            tHit = tf;
            hitFace = f;
          }
        }
      }
      exitFace = hitFace >= 0 ? hitFace : planeFace;
      tExit = hitFace >= 0 ? tHit : tPlane;
      if (exitFace < 0)
      {
        break;
      }
      tExit = max(tExit, t);
      float tEnd = min(tExit, tStop);
      reached = tEnd;
      float tFrom = max(t, tKept);
      vec4 c0 = hexCoefficientsTexel(FIELD_TEXELS * cell);
      if (c0.x > EMPTY_CELL && tEnd > tFrom)
      {
        mat3 frame = mat3(p[1] - p[0], p[3] - p[0], p[4] - p[0]);
        float det = determinant(frame);
        float scale = length(frame[0]) * length(frame[1]) * length(frame[2]);
        if (abs(det) > 1.0e-6 * scale)
        {
          mat3 toFrame = inverse(frame);
          vec3 entry = origin + tFrom * direction;
          vec3 q = toFrame * (entry - p[0]);
          vec3 r = toFrame * direction;
          vec4 c1 = hexCoefficientsTexel(FIELD_TEXELS * cell + 1);
          vec4 w = rayCubic(c0, c1, q, r);
          vec4 colorBefore = color;
          vec3 projectionBefore = projection;
          int kBefore = k, jBefore = j;
          if (BLEND == 0)
          {
            k = integrateHexahedronSegment(
              w, tEnd - tFrom, c0, c1, q, r, toFrame, entry, direction, k, j, color);
          }
          else
          {
            projectCubicStretch(w, tEnd - tFrom, k, projection);
          }
          if (outOfLoops)
          {
            color = colorBefore;
            projection = projectionBefore;
            k = kBefore;
            j = jBefore;
            continuation = continuationCode(cell, entryFace, false);
            reached = t;
            break;
          }
        }
      }
      else if (c0.x <= EMPTY_CELL)
      {
        j = isoIntervalAfterEmpty(j, tEnd - tFrom, tEnd);
      }
      if (tExit >= tStop || before.a + (1.0 - before.a) * color.a >= terminationAlpha)
      {
        break;
      }
    }
    int code = exitFace >= 0 ? neighborThrough(cell, exitFace) : -1;
    if (code == -1 && !(FOLDS && backwards))
    {
      break;
    }
    // The next cell and the face it is entered by.
    bool walkingBack = backwards;
    int next = neighborEntry(code);
    int nextCell = next / FACES, nextFace = next - FACES * nextCell;
    if (code == -1)
    {
      // The walk back left the mesh: on from the fold instead.
      nextCell = foldCell;
      nextFace = foldFace;
      backwards = false;
    }
    else if (FOLDS && !backwards && code < -1 - TURN_BACK)
    {
      // Out of an inverted cell into a forward one: back through this one.
      nextCell = cell;
      nextFace = exitFace;
      backwards = true;
    }
    else
    {
      backwards = FOLDS && (backwards != (code < -1));
    }
    if (!walkingBack)
    {
      // Where a walk back that starts here goes on from if it fails.
      foldCell = nextCell;
      foldFace = nextFace;
    }
    t = tExit;
    cell = nextCell;
    entryFace = nextFace;
    loadCorners(cell, p);
    mask = hexNeighborsTexel(NEIGHBOR_TEXELS * cell + 1).z;
  }
  finishPeel(before, color, reached, projection);
  writeContinuation(continuation, step);
}
