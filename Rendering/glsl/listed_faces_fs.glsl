// Listed exit faces: a boundary face whose neighbour code names a list in the
// neighbour array instead of one cell (vtkPPIRayCellBuffers' SPLIT_FACE,
// REENTRY_FACE). Resolved by the march outside its step loop, once per
// crossing, through the cell kind's faceEntry() and outsideFace().

// Width of the pixel at ray parameter t: how far the next pixel's ray is
// from this one there.
float pixelFootprint(float t)
{
  vec2 ndc = 2.0 * pixelCentre() - 1.0;
  vec3 o, d, o1, d1;
  pixelRay(ndc, o, d);
  pixelRay(ndc + vec2(2.0 / float(textureSize(previousAccumulated, 0).x), 0.0), o1, d1);
  return length(o1 + t * d1 - o - t * d);
}

// Out through a boundary face with reflex edges (its partners across its
// edges, FACE_EDGES at most, listed first at texel `list`, ppirayReflexEdges.h), at ray
// parameter t: the partner the ray enters within a quarter of a pixel's
// width further on, if any (t moves to that entry), else -1. Depth peeling
// finds such an entry by rasterization, which within a fraction of a pixel
// of the edge may give the pixel to the face the ray left instead; the ray's
// own arithmetic decides here, as it did for the exit. An entry is crossing
// a partner's face inwards inside the face (to float rounding). The pixel's
// width is found only for an entry.
int reentryAcrossEdge(int list, vec3 origin, vec3 direction, inout float t)
{
  ivec4 across = neighborListTexel(list);
  float tEntry = INFINITY;
  int entry = -1;
  for (int i = 0; i < FACE_EDGES && across[i] >= 0; ++i)
  {
    int c = across[i] / FACES;
    int e = across[i] - FACES * c;
    float te;
    float outside = faceEntry(c, e, origin, direction, t, te);
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

// Out through a boundary face split into pieces (the imaginary faces of a
// convexified grid on it, or the faces of other cells that meet it
// geometrically, ppirayNonConformingFaces.h; listed from texel `list`: n,
// then their codes): the piece x (the exit point at ray parameter t, on the
// face) lies in, the one it is least outside of (outsideFace), so a point on
// an edge between pieces goes to one of them. -1: none within rounding
// (1e-5 of |t| + |x|): the ray leaves the mesh where pieces do not cover the
// face. EXIT_LOOPS: SPLIT_PIECE_LOOPS per piece.
int splitFacePiece(int list, int n, vec3 x, float t)
{
  int piece = -1;
  float leastOutside = INFINITY;
  for (int i = 0; i < MAXIMUM_SPLIT_PIECES && i < n; ++i)
  {
    int code = neighborListTexel(list + (i + 1) / 4)[(i + 1) & 3];
    int c = code / FACES;
    float outside = outsideFace(c, code - FACES * c, x);
    if (outside < leastOutside)
    {
      leastOutside = outside;
      piece = code;
    }
  }
  loopsLeft -= SPLIT_PIECE_LOOPS * min(n, MAXIMUM_SPLIT_PIECES) + 1; // and the outer step loop's iteration
  return leastOutside <= 1.0e-5 * (abs(t) + length(x)) ? piece : -1;
}

// Out through one side of a lens (a quadrilateral split along one diagonal
// here and along the other across it, ppirayNonConformingFaces.h; its `n`
// faces across listed in texel `list` after n): the face across that the
// ray crosses first, at t or later, inside it to rounding (faceEntry), and t
// moves to that crossing: the part of the lens that neither side's cells
// cover is passed, the part both cover integrated once. Else (the ray is
// inside the far side's cells already and its faces' planes are behind it,
// or it grazes them) the face across least outside of which the exit point
// lies, t kept; -1 where the ray heads into neither.
int lensPiece(int list, int n, vec3 origin, vec3 direction, inout float t)
{
  ivec4 across = neighborListTexel(list);
  int crossed = -1, nearest = -1;
  float tCross = INFINITY, leastOutside = INFINITY;
  for (int i = 0; i < 2 && i < n; ++i)
  {
    int c = across[i + 1] / FACES;
    float te;
    float outside = faceEntry(c, across[i + 1] - FACES * c, origin, direction, t, te);
    if (outside <= 1.0e-5 * (abs(te) + length(origin + te * direction)) && te < tCross)
    {
      tCross = te;
      crossed = across[i + 1];
    }
    if (outside < leastOutside)
    {
      leastOutside = outside;
      nearest = across[i + 1];
    }
  }
  loopsLeft -= SPLIT_PIECE_LOOPS * min(n, 2) + 1; // and the outer step loop's iteration
  t = crossed >= 0 ? tCross : t;
  return crossed >= 0 ? crossed : nearest;
}

// The cell and face a listed exit face `code`, left at t, enters (t moves
// to a re-entry or past a lens), or -1.
int listedFaceEntry(int code, vec3 origin, vec3 direction, inout float t)
{
  if (REENTRY_EDGES && code >= REENTRY_FACE)
  {
    return reentryAcrossEdge(code - REENTRY_FACE, origin, direction, t);
  }
  int list = code - SPLIT_FACE;
  int n = neighborListTexel(list).x;
  if (LENS_FACES && n >= LENS_LIST)
  {
    return lensPiece(list, n - LENS_LIST, origin, direction, t);
  }
  return splitFacePiece(list, n, origin + t * direction, t);
}
