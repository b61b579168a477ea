// One cell's stretch of a ray, x in [0, len] past its entry point, on which
// the cell kind gives the field as a polynomial (Stretch: s(x) = w0 + w1 x
// + w2 x^2 + w3 x^3, degree 1 or 3, s(len) = sEnd): split at the
// polynomial's extrema into monotonic pieces (Miranda 2011, Sec. 3.2), each
// split at the isosurfaces it crosses, integrated piece by piece (unless
// ISO_MODE is 2) and each surface composited where it is crossed, with the
// cell's gradient there. A linear piece is integrated by the integration
// mode (integrateSegment), a cubic one by the hexahedron mode
// (integrateMonotonicPiece). Out of loops: cutAt is how far along the
// stretch the work stopped. The crossings are counted from the isovalue
// interval j carried in from the previous cell to the piece's end: a surface
// through the entry face (the scalar jumps there with cell data, or two
// cells' float evaluations of a point field differ by rounding) is
// composited once, at the entry.

// The monotonic piece [xA, xB] of the stretch, s from sA to sB.
int integrateMonotonic(Stretch s, float xA, float xB, float sA, float sB, int k,
  inout vec4 color)
{
  if (!(xB > xA))
  {
    return k;
  }
  k = stretchDegree(s) == 1 ? integrateSegment(sA, sB, xB - xA, k, color)
                    : integrateMonotonicPiece(s.w, xA, xB, sA, sB, k, color);
  cutAt += outOfLoops ? xA : 0.0;
  return k;
}

// Where s takes v in [xA, x1], on the monotonic piece [x0, x1] (s0 to s1):
// in closed form for a linear piece, else by cubicCrossing.
float stretchCrossing(Stretch s, float v, float xA, float x0, float x1, float s0, float s1)
{
  if (stretchDegree(s) == 1)
  {
    float ds = s1 - s0;
    return ds == 0.0 ? xA : clamp(x0 + (x1 - x0) * (v - s0) / ds, xA, x1);
  }
  return cubicCrossing(s.w, v, xA, x1);
}

int integrateStretch(Cell cell, Stretch s, float len, vec3 entry, vec3 direction, int k,
  inout int j, inout vec4 color)
{
  if (ISO_MODE == 0 && stretchDegree(s) == 1)
  {
    return integrateMonotonic(s, 0.0, len, s.w.x, s.sEnd, k, color);
  }
  float roots[2];
  int extrema = stretchDegree(s) == 1 ? 0 : cubicExtrema(s.w, len, roots);
  float x0 = 0.0;
  float s0 = s.w.x;
  if (ISO_MODE != 0)
  {
    j = j < 0 ? isoInterval(s0, 0) : j;
  }
  int surface = -1;
  for (int piece = 0; piece < 3 && piece <= extrema; ++piece)
  {
    float x1 = piece < extrema ? roots[piece] : len;
    float s1 = piece < extrema ? cubicValue(s.w, x1) : s.sEnd;
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
      float xv = stretchCrossing(s, v, xA, x0, x1, s0, s1);
      if (ISO_MODE == 1)
      {
        k = integrateMonotonic(s, xA, xv, sA, v, k, color);
        if (outOfLoops)
        {
          return k;
        }
      }
      vec3 y = entry + xv * direction;
      compositeIsoSurface(surface, y, fieldGradient(cell, y), direction, color);
      xA = xv;
      sA = v;
      j = next;
    }
    if (ISO_MODE != 2)
    {
      k = integrateMonotonic(s, xA, x1, sA, s1, k, color);
      if (outOfLoops)
      {
        return k;
      }
    }
    x0 = x1;
    s0 = s1;
  }
  return k;
}

// A projection (BLEND 1 to 4) along the stretch; out of loops, cutAt as above.
void projectStretch(Stretch s, float len, inout int k, inout vec3 state)
{
  if (stretchDegree(s) == 1)
  {
    projectLinearStretch(s.w.x, s.sEnd, len, k, state);
  }
  else
  {
    projectCubicStretch(s.w, len, k, state);
  }
}
