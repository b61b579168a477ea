//VTK::System::Dec
#if __VERSION__ < 330
// floatBitsToUint, uintBitsToFloat (continuations, march_common_fs.glsl)
#extension GL_ARB_shader_bit_encoding : require
#endif
// March pass: per pixel, from the cell a ray enters through (entry pass) to
// the cell it leaves the mesh from, one tetrahedron at a time.
//
// The cells, in the mesh's local frame, as one of two layouts gives them
// (tetrahedron_planes_fs.glsl, tetrahedron_corners_fs.glsl, chosen by
// vtkPPIRayTetrahedralCellBuffers): facePlane(t, f) = (n_f, d_f), outward
// unit normal, n_f . x = d_f on face f, or a flat cell's corner f (x_f,
// FLAT_CELL); the field (g, s0), s(x) = g . x + s0 (s0 = -3e38: render
// empty); and
//   neighborsTexel(NEIGHBOR_TEXELS t)[f] = 4 t' + f' of the cell and face
//                         through face f; across a folded face -(4 t' + f' + 2),
//                         or -(4 t' + f' + 2 + TURN_BACK) where t is the
//                         inverted side; -1: boundary
// The exit face is the nearest face plane the ray is heading out of
// (Weiler et al. 2003, Sec. 3.2): t_f = (d_f - n_f . o) / (n_f . r), n_f . r > 0.
// Every segment is integrated by integrateSegment(), the integration mode,
// substituted below with the transfer function lookup.
//
// Real meshes (Documentation/algorithms.md, "Degenerate, inverted and tangled
// cells"): a flat cell is crossed with zero length; at a folded face the ray
// walks backwards (through the inverted cell across it, or through the
// inverted cell it is in), out through the face where the line enters each
// cell, integrating nothing, until it crosses a folded face into the next
// forward part of the mesh; t never decreases, so no stretch is integrated
// twice.

//PPIRay::MarchCommon::Impl

//PPIRay::TetrahedronCells::Impl

//PPIRay::TransferFunction::Impl

//PPIRay::IsoSurface::Impl

//PPIRay::Projection::Impl

//PPIRay::Integrate::Impl

// Loop iterations a cell step may take outside its pieces (march_common_fs.glsl):
// its own, reading the cell (PLANE_LOOPS + FIELD_LOOPS), the exit loop (4,
// a flat cell's 4 + 4), the isovalue crossings and walks.
const int STEP_LOOPS =
  13 + PLANE_LOOPS + FIELD_LOOPS + (ISO_MODE == 0 ? 0 : 4 * MAXIMUM_ISO_VALUES);

// One cell's stretch of the ray, x in [0, len] past `entry`, on which s goes
// linearly from sFront to sBack (gradient g): the volume integrated up to
// each isosurface crossed (at x = len (v - sFront) / (sBack - sFront)), unless
// ISO_MODE is 2, each surface composited there, and on to the exit. The
// crossings are those from the interval j carried in from the previous cell to
// sBack: a surface through the entry face (the scalar jumps there with cell
// data, or the two cells' float evaluations of a point field differ by
// rounding) is composited once, at the entry (x clamped to 0).
int integrateTetrahedronSegment(float sFront, float sBack, float len, vec3 g, vec3 entry,
  vec3 direction, int k, inout int j, inout vec4 color)
{
  if (ISO_MODE == 0)
  {
    return integrateSegment(sFront, sBack, len, k, color);
  }
  j = j < 0 ? isoInterval(sFront, 0) : j;
  int surface = -1;
  float x = 0.0;
  float sA = sFront;
  float ds = sBack - sFront;
  for (int i = 0; i < MAXIMUM_ISO_VALUES; ++i)
  {
    int next = nextIsoCrossing(sBack, j, surface);
    if (surface < 0)
    {
      break;
    }
    float v = isoValues[surface];
    float xv = ds == 0.0 ? x : clamp(len * (v - sFront) / ds, x, len);
    if (ISO_MODE == 1 && xv > x)
    {
      k = integrateSegment(sA, v, xv - x, k, color);
      if (outOfLoops)
      {
        cutAt += x;
        return k;
      }
    }
    compositeIsoSurface(surface, entry + xv * direction, g, direction, color);
    x = xv;
    sA = v;
    j = next;
  }
  if (ISO_MODE != 2 && len > x)
  {
    k = integrateSegment(sA, sBack, len - x, k, color);
    cutAt += x;
  }
  return k;
}

//PPIRay::Ray::Impl

// Width of the pixel at ray parameter t: how far the next pixel's ray is
// from this one there.
float pixelFootprint(float t)
{
  vec2 ndc = 2.0 * texCoord - 1.0;
  vec3 o, d, o1, d1;
  pixelRay(ndc, o, d);
  pixelRay(ndc + vec2(2.0 / float(textureSize(previousAccumulated, 0).x), 0.0), o1, d1);
  return length(o1 + t * d1 - o - t * d);
}

// Out through a boundary face with reflex edges (its partners across its
// three edges listed at texel `list`, ppirayReflexEdges.h), at ray
// parameter t: the partner the ray enters within a quarter of a pixel's
// width further on, if any (t moves to that entry), else -1. Depth peeling
// finds such an entry by rasterization, which within a fraction of a pixel
// of the edge may give the pixel to the face the ray left instead; the ray's
// own arithmetic decides here, as it did for the exit. An entry is crossing
// the face plane of a partner (cell c, face e) inwards (n_e . direction < 0)
// inside c's other three planes (to float rounding). The pixel's width is
// found only for an entry.
int reentryAcrossEdge(int list, vec3 origin, vec3 direction, inout float t)
{
  ivec4 across = neighborsTexel(list);
  float tEntry = INFINITY;
  int entry = -1;
  for (int i = 0; i < 3; ++i)
  {
    int c = max(across[i], 0) / FACES;
    int e = max(across[i], 0) - FACES * c;
    vec4 p[4];
    cellPlanes(c, p);
    vec4 pe = p[e];
    float along = dot(pe.xyz, direction);
    if (across[i] < 0 || (FLAT_CELLS && pe.w > FLAT_CELL) || !(along < 0.0))
    {
      continue;
    }
    float te = max((pe.w - dot(pe.xyz, origin)) / along, t);
    vec3 y = origin + te * direction;
    float outside = -INFINITY;
    for (int f = 0; f < 4; ++f)
    {
      outside = f == e ? outside : max(outside, dot(p[f].xyz, y) - p[f].w);
    }
    if (te < tEntry && outside <= 1.0e-6 * abs(te))
    {
      tEntry = te;
      entry = across[i];
    }
  }
  loopsLeft -= REENTRY_LOOPS; // and the outer step loop's iteration
  if (entry < 0 || tEntry - t > 0.25 * pixelFootprint(t))
  {
    return -1;
  }
  t = tEntry;
  return entry;
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

// Out through a boundary face split into pieces (the imaginary faces of a
// convexified grid on it, listed from texel `list`: n, then their codes): the
// piece x (the exit point, on the face) lies in. x lies in the face of piece
// (cell c, face e) when it is inside c's three other face planes
// (n_f . x <= d_f), or, c flat (its corners stored), inside the triangle of
// the corners other than e; the piece it is least outside of is taken, so a
// point on an edge between pieces goes to one of them. -1: no piece (not
// reached for a valid list). EXIT_LOOPS: SPLIT_PIECE_LOOPS per piece.
int splitFacePiece(int list, vec3 x)
{
  int n = neighborsTexel(list).x;
  int piece = -1;
  float leastOutside = INFINITY;
  for (int i = 0; i < MAXIMUM_SPLIT_PIECES && i < n; ++i)
  {
    int code = neighborsTexel(list + (i + 1) / 4)[(i + 1) & 3];
    int c = code / FACES;
    int e = code - FACES * c;
    vec4 p[4];
    cellPlanes(c, p);
    float outside = -INFINITY;
    if (FLAT_CELLS && p[0].w > FLAT_CELL)
    {
      outside = outsideTriangle(p[(e + 1) & 3].xyz, p[(e + 2) & 3].xyz, p[(e + 3) & 3].xyz, x);
    }
    else
    {
      for (int f = 0; f < 4; ++f)
      {
        outside = f == e ? outside : max(outside, dot(p[f].xyz, x) - p[f].w);
      }
    }
    if (outside < leastOutside)
    {
      leastOutside = outside;
      piece = code;
    }
  }
  loopsLeft -= SPLIT_PIECE_LOOPS * min(n, MAXIMUM_SPLIT_PIECES) + 1; // and the outer step loop's iteration
  return piece;
}


// The face of a flat cell (corners c_v, face f = the three other than c_f),
// other than `entryFace`, whose triangle best contains x: the largest
// smallest barycentric coordinate of x projected on the face's plane,
// lambda_a = m . ((b - x) x (c - x)) / |m|^2 with m = (b - a) x (c - a);
// faces of (relatively) zero area are never taken. -1: none.
int flatCellExit(vec4 c[4], int entryFace, vec3 x)
{
  vec3 m[4];
  float largest = 0.0;
  for (int f = 0; f < 4; ++f)
  {
    vec3 a = c[(f + 1) & 3].xyz;
    m[f] = cross(c[(f + 2) & 3].xyz - a, c[(f + 3) & 3].xyz - a);
    largest = max(largest, dot(m[f], m[f]));
  }
  int best = -1;
  float bestScore = -INFINITY;
  for (int f = 0; f < 4; ++f)
  {
    float area2 = dot(m[f], m[f]);
    if (f == entryFace || !(area2 > 1.0e-8 * largest))
    {
      continue;
    }
    vec3 a = c[(f + 1) & 3].xyz - x, b = c[(f + 2) & 3].xyz - x, d = c[(f + 3) & 3].xyz - x;
    float la = dot(m[f], cross(b, d)) / area2;
    float lb = dot(m[f], cross(d, a)) / area2;
    float score = min(min(la, lb), 1.0 - la - lb);
    if (score > bestScore)
    {
      bestScore = score;
      best = f;
    }
  }
  return best;
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 before;
  float resume;
  int startCell, startFace;
  bool resumeBackwards;
  int stepsTaken;
  int cellFace = enterPeel(pixel, before, resume, startCell, startFace, resumeBackwards, stepsTaken);
  if (cellFace < 0 && startCell < 0)
  {
    return;
  }
  // The ray through the pixel centre, in the local frame.
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

  // Into the first cell: through its entry face, or already in it at the
  // near plane (t = 0) when the ray starts inside the mesh, or where the
  // previous pass ran out of loops.
  int cell = startCell;
  int entryFace = startFace;
  float t = resume;
  if (startCell < 0)
  {
    cell = cellFace / FACES;
    entryFace = cellFace - FACES * cell;
    vec4 plane = facePlane(cell, entryFace);
    if (plane.w > FLAT_CELL)
    {
      // A flat cell on the boundary: the plane of its entry triangle.
      vec3 a = facePlane(cell, (entryFace + 1) & 3).xyz;
      vec3 n = cross(facePlane(cell, (entryFace + 2) & 3).xyz - a,
        facePlane(cell, (entryFace + 3) & 3).xyz - a);
      n = dot(n, direction) > 0.0 ? -n : n;
      plane = vec4(n, dot(n, a));
    }
    t = max((plane.w - dot(plane.xyz, origin)) / min(dot(plane.xyz, direction), -1.0e-30), resume);
  }
  int k = -1;
  int j = -1; // isovalue interval, set at the first cell
  vec4 color = vec4(0.0);
  float reached = t;
  bool backwards = resumeBackwards;
  float continuation = 0.0;
  int step = stepsTaken;
  // The steps, cell to cell; a listed exit face (split, or with reflex
  // edges) ends them, is resolved here, outside the step loop (once per
  // crossing, not in every step of the lanes that run together), and the
  // steps go on from the cell it gives.
  for (int listed = 0; listed < maximumSteps; ++listed)
  {
    int pending = -1;
    for (; step < maximumSteps; ++step)
    {
      if (!spendLoops(STEP_LOOPS))
      {
        continuation = continuationCode(cell, entryFace, backwards);
        reached = t;
        break;
      }
      vec4 p[4];
      vec4 g;
      cellPlanesAndField(cell, p, g);
      int exitFace = -1;
      bool flatCell = FLAT_CELLS && p[0].w > FLAT_CELL;
      if (flatCell)
      {
        exitFace = flatCellExit(p, entryFace, origin + t * direction);
      }
      else
      {
        // Forwards: out through the nearest plane the ray heads out of.
        // Backwards (the cell's stretch lies behind t): out through the face
        // the line enters it by, the farthest plane it heads into.
        bool walkingBack = FOLDS && backwards;
        float tExit = walkingBack ? -INFINITY : INFINITY;
        for (int f = 0; f < 4; ++f)
        {
          float along = dot(p[f].xyz, direction);
          float tf = (p[f].w - dot(p[f].xyz, origin)) / along;
          bool better = walkingBack ? (along < 0.0 && tf > tExit) : (along > 0.0 && tf < tExit);
          if (f != entryFace && better)
          {
            tExit = tf;
            exitFace = f;
          }
        }
        if (exitFace >= 0 && !walkingBack)
        {
          tExit = max(tExit, t);
          float tEnd = min(tExit, tStop);
          float tFrom = max(t, tKept);
          if (g.w > EMPTY_CELL && tEnd > tFrom)
          {
            float sFront = dot(g.xyz, origin + tFrom * direction) + g.w;
            float sBack = dot(g.xyz, origin + tEnd * direction) + g.w;
            if (BLEND == 0)
            {
              k = integrateTetrahedronSegment(sFront, sBack, tEnd - tFrom, g.xyz,
                origin + tFrom * direction, direction, k, j, color);
            }
            else
            {
              projectLinearStretch(sFront, sBack, tEnd - tFrom, k, projection);
            }
            if (outOfLoops)
            {
              continuation = continuationCode(cell, entryFace, backwards);
              reached = tFrom + cutAt;
              break;
            }
          }
          else if (g.w <= EMPTY_CELL)
          {
            j = isoIntervalAfterEmpty(j, tEnd - tFrom, tEnd);
          }
          reached = max(reached, tEnd);
          if (tExit >= tStop || before.a + (1.0 - before.a) * color.a >= terminationAlpha)
          {
            break;
          }
          t = tExit;
        }
      }
      if (exitFace < 0)
      {
        break;
      }
      int next = neighborsTexel(NEIGHBOR_TEXELS * cell)[exitFace];
      if ((SPLIT_FACES || REENTRY_EDGES) && next >= SPLIT_FACE)
      {
        pending = backwards ? -1 : next;
        break;
      }
      if (next == -1)
      {
        break;
      }
      bool folded = FOLDS && next < -1;
      next = folded ? -next - 2 : next;
      bool turnBack = FOLDS && next >= TURN_BACK;
      next -= turnBack ? TURN_BACK : 0;
      if (folded && turnBack && !backwards)
      {
        // Out of an inverted cell into a forward one: back through this one.
        backwards = true;
        entryFace = exitFace;
        continue;
      }
      backwards = backwards != folded;
      cell = next / FACES;
      entryFace = next - FACES * cell;
    }
    if (pending < 0)
    {
      break;
    }
    int next = REENTRY_EDGES && pending >= REENTRY_FACE
      ? reentryAcrossEdge(pending - REENTRY_FACE, origin, direction, t)
      : splitFacePiece(pending - SPLIT_FACE, origin + t * direction);
    if (next < 0)
    {
      break;
    }
    cell = next / FACES;
    entryFace = next - FACES * cell;
    ++step;
  }
  finishPeel(before, color, reached, projection);
  writeContinuation(continuation, step);
}
