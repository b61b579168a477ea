//VTK::System::Dec
#if __VERSION__ < 330
// floatBitsToUint, uintBitsToFloat (continuations, march_common_fs.glsl)
#extension GL_ARB_shader_bit_encoding : require
#endif
// March pass: per pixel, from the cell a ray enters through (entry pass) to
// the cell it leaves the mesh from, one cell at a time. One loop for every
// cell kind: a kind (cell_tetrahedron_fs.glsl, cell_hexahedron_fs.glsl,
// substituted by vtkPPIRayCellBuffers) supplies the geometry and the
// field only, through
//   struct Cell; CELL_LOOPS                  a cell as read, and what reading
//                                            and crossing it costs the budget
//   Cell loadCell(int c)
//   int boundaryEntry(code, ...)             the cell and face an entry code
//                                            enters, and where
//   int cellExit(cell, entryFace, ..., backwards, out tExit)
//                                            the face the ray leaves it by,
//                                            or EXIT_SEARCH where its rule
//                                            cannot tell (EXIT_SEARCHES)
//   int cellExitSearch(cell, entryFace, ..., out tExit)
//                                            then, the slower search
//   bool headsOutOfFace(cell, f, direction) (tangled meshes)
//   bool hasField(cell); bool fieldAlongRay(cell, ..., out Stretch)
//                                            the field along a stretch
//   vec3 fieldGradient(cell, x)              (isosurface shading)
//   int neighborCode(c, f); ivec4 neighborListTexel(i)
//   float faceEntry(c, e, ...); float outsideFace(c, e, x)
//                                            (listed faces)
// and everything else lives here once: clipping planes and opaque geometry,
// blend modes, isosurfaces and integration (stretch_fs.glsl), the loop
// budget and continuations, early termination, empty cells, folds walked
// back, cells behind their entry face, split faces, lenses and re-entry
// across reflex edges (listed_faces_fs.glsl).
//
// Neighbour codes (vtkPPIRayCellBuffers' layout): FACES c' + f', the cell
// and face entered through a face; across a folded face -(FACES c' + f' + 2),
// or -(FACES c' + f' + 2 + TURN_BACK) where the cell left is the inverted
// side; -1: boundary; SPLIT_FACE or REENTRY_FACE and more: a listed face.
// Real meshes (Documentation/algorithms.md, "Degenerate, inverted and tangled
// cells"): at a folded face the ray walks backwards (through the inverted
// cell across it, or through the inverted cell it is in), integrating
// nothing, until it crosses a folded face into the next forward part of the
// mesh; t never decreases, so no stretch is integrated twice. A walk back
// that leaves the mesh ends the peel (the next peel enters behind it).

//PPIRay::MarchCommon::Impl

//PPIRay::TransferFunction::Impl

//PPIRay::IsoSurface::Impl

//PPIRay::Projection::Impl

//PPIRay::Integrate::Impl

//PPIRay::Ray::Impl

//PPIRay::Cubic::Impl

//PPIRay::GaussLegendre::Impl

//PPIRay::MonotonicPiece::Impl

//PPIRay::ProjectionCubic::Impl

// The field on a cell's stretch of the ray, x in [0, len]:
// s(x) = w0 + w1 x + w2 x^2 + w3 x^3 of the given degree (1 or 3), s(len) = sEnd.
struct Stretch
{
  vec4 w;
  float sEnd;
  int degree;
};

// cellExit's answer where only cellExitSearch can tell the exit.
const int EXIT_SEARCH = -2;

//PPIRay::FlatCells::Impl

//PPIRay::CellKind::Impl

//PPIRay::Stretch::Impl

//PPIRay::ListedFaces::Impl

// Loop iterations a cell step may take outside its pieces (march_common_fs.glsl):
// its own, the cell kind's, the isovalue crossings and walks, and the outer
// loop's iteration of an exit search.
const int STEP_LOOPS =
  1 + CELL_LOOPS + (ISO_MODE == 0 ? 0 : 4 * MAXIMUM_ISO_VALUES) + (EXIT_SEARCHES ? 1 : 0);

// The next cell and the face it is entered by, out of `cell` through
// `exitFace` whose neighbour code is `code` (not -1); `backwards` updated
// across a fold.
void nextCell(int code, int exitFace, inout int cell, inout int entryFace, inout bool backwards)
{
  bool folded = FOLDS && code < -1;
  int next = folded ? -code - 2 : code;
  bool turnBack = FOLDS && next >= TURN_BACK;
  next -= turnBack ? TURN_BACK : 0;
  if (folded && turnBack && !backwards)
  {
    // Out of an inverted cell into a forward one: back through this one.
    backwards = true;
    entryFace = exitFace;
    return;
  }
  backwards = backwards != folded;
  cell = next / FACES;
  entryFace = next - FACES * cell;
}

// The ray through one pixel, this peel (main() of the stage calls it).
void marchRay()
{
  ivec2 pixel = marchPixel();
  vec4 before;
  float resume;
  int startCell, startFace;
  bool resumeBackwards;
  int stepsTaken;
  int entryCode =
    enterPeel(pixel, before, resume, startCell, startFace, resumeBackwards, stepsTaken);
  if (entryCode < 0 && startCell < 0)
  {
    return;
  }
  // The ray through the pixel centre, in the local frame.
  vec2 ndc = 2.0 * pixelCentre() - 1.0;
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
    cell = boundaryEntry(entryCode, origin, direction, resume, entryFace, t);
  }
  int k = -1;
  int j = -1; // isovalue interval, set at the first cell
  vec4 color = vec4(0.0);
  float reached = t;
  bool backwards = resumeBackwards;
  float continuation = 0.0;
  int step = stepsTaken;
  // The steps, cell to cell; a listed exit face (split, or with reflex
  // edges) or an exit only cellExitSearch can tell ends them, is resolved
  // here, outside the step loop (once per crossing, not in every step of
  // the lanes that run together), and the steps go on: from the cell the
  // listed face gives, or with the step whose exit was searched for (at
  // most one search and one listed face per step: 2 maximumSteps rounds).
  bool searched = false; // the exit of the step the loop resumes with
  int searchedFace = -1;
  float searchedExit = t;
  for (int listed = 0; listed < 2 * maximumSteps; ++listed)
  {
    int pending = -1;
    bool search = false;
    for (; step < maximumSteps; ++step)
    {
      if (!spendLoops(STEP_LOOPS))
      {
        continuation = continuationCode(cell, entryFace, backwards);
        reached = t;
        break;
      }
      Cell c = loadCell(cell);
      bool walkingBack = FOLDS && backwards;
      float tExit = searchedExit;
      int exitFace = searchedFace;
      if (!(EXIT_SEARCHES && searched))
      {
        exitFace = cellExit(c, entryFace, origin, direction, t, walkingBack, tExit);
      }
      searched = false;
      if (EXIT_SEARCHES && exitFace == EXIT_SEARCH)
      {
        search = true;
        break;
      }
      if ((FOLDS || FLAT_CELLS) && !walkingBack && entryFace >= 0 &&
        headsOutOfFace(c, entryFace, direction))
      {
        tExit = t; // the cell lies behind the face it was entered by: none of it here
      }
      if (!walkingBack && exitFace >= 0)
      {
        float tEnd = min(tExit, tStop);
        float tFrom = max(t, tKept);
        Stretch s;
        if (hasField(c) && tEnd > tFrom &&
          fieldAlongRay(c, origin + tFrom * direction, origin + tEnd * direction, tEnd - tFrom,
            direction, s))
        {
          if (BLEND == 0)
          {
            k = integrateStretch(c, s, tEnd - tFrom, origin + tFrom * direction, direction, k, j, color);
          }
          else
          {
            projectStretch(s, tEnd - tFrom, k, projection);
          }
          if (outOfLoops)
          {
            continuation = continuationCode(cell, entryFace, backwards);
            reached = tFrom + cutAt;
            break;
          }
        }
        else if (!hasField(c))
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
      if (exitFace < 0)
      {
        break;
      }
      int code = neighborCode(cell, exitFace);
      if ((SPLIT_FACES || REENTRY_EDGES) && code >= SPLIT_FACE)
      {
        pending = walkingBack ? -1 : code;
        break;
      }
      if (code == -1)
      {
        break;
      }
      nextCell(code, exitFace, cell, entryFace, backwards);
    }
    if (EXIT_SEARCHES && search)
    {
      searchedFace = cellExitSearch(loadCell(cell), entryFace, origin, direction, t, searchedExit);
      searched = true;
      continue;
    }
    if (pending < 0)
    {
      break;
    }
    int next = listedFaceEntry(pending, origin, direction, t);
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
