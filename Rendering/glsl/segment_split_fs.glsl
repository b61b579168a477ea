// Segment integration with stops at every control point (partial
// pre-integration and exact-linear modes): the pieces between control points
// have linear colour and attenuation; integratePiece() is the mode's integral.
// A segment of length `len` on which s goes linearly from sFront to sBack:
// split at every control point value strictly between them
// (nextControlCrossing), each piece integrated by integratePiece(). Returns
// the control interval at sBack. Out of loops (PIECE_LOOPS a piece): stops at
// a control point, cutAt that far along the segment, returning its interval.
// A transparent segment (transparentSpan) is not split nor integrated: it
// returns the interval at sFront, from which the next segment's
// controlInterval() walks.
int integrateSegment(float sFront, float sBack, float len, int k, inout vec4 color)
{
  int n = numberOfControlPoints;
  k = controlInterval(sFront, k);
  if (transparentSpan(sFront, sBack, k))
  {
    return k;
  }
  float ds = sBack - sFront;
  float sA = sFront;
  vec4 tfA = transferFunction(sA, k);
  for (int i = 0; i <= n; ++i)
  {
    if (!spendLoops(PIECE_LOOPS))
    {
      cutAt = ds == 0.0 ? 0.0 : len * (sA - sFront) / ds;
      break;
    }
    float sB;
    int nextK = nextControlCrossing(ds, sBack, k, sB);
    vec4 tfB = transferFunction(sB, k);
    float pieceLength = ds == 0.0 ? len : len * (sB - sA) / ds;
    integratePiece(tfA, tfB, pieceLength, color);
    if (nextK == k)
    {
      break;
    }
    k = nextK;
    sA = sB;
    tfA = transferFunctionEntered(k, ds, tfB);
  }
  return k;
}
