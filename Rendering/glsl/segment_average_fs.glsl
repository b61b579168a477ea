// Average-colour integration of a whole cell segment (Shirley & Tuchman;
// Moreland & Angel 2004, Eq. 3), the approximation projected-tetrahedra
// mappers use: constant colour, the mean of the transfer function's colours
// at the segment's ends, and attenuation linear along the segment:
//   zeta = exp(-D (tau_f + tau_b) / 2),   I = (C_f + C_b) / 2 (1 - zeta).
// No stop at control points: a transfer-function feature between the two
// end values is missed, which is what this mode is there to measure.
int integrateSegment(float sFront, float sBack, float len, int k, inout vec4 color)
{
  int kFront = controlInterval(sFront, k);
  int kBack = controlInterval(sBack, kFront);
  vec4 front = transferFunction(sFront, kFront);
  vec4 back = transferFunction(sBack, kBack);
  float zeta = exp(-0.5 * len * (front.a + back.a));
  compositeFrontToBack(color, 0.5 * (front.rgb + back.rgb) * (1.0 - zeta), 1.0 - zeta);
  return kBack;
}
