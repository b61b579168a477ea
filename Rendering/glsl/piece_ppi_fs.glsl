// Partial pre-integration (Moreland & Angel 2004, Sec. 4): on a piece of
// length D where colour C and attenuation tau are linear (front f to back b),
//   zeta = exp(-D (tau_f + tau_b) / 2)                      transparency
//   Psi  = int_0^1 exp(-D (tau_f u + (tau_b - tau_f) u^2 / 2)) du
//   I    = C_f (1 - Psi) + C_b (Psi - zeta)                 emitted, premultiplied
// with Psi read from a table that does not depend on the transfer function,
// indexed by u = 1 - 1 / sqrt(tau D + 1) (x: front, y: back), a reparametrized
// gamma = tau D / (tau D + 1) that removes the square-root edge of Psi at
// gamma_b -> 1 (see vtkPsiTable.h).
uniform sampler2D psiTable;
const int PIECE_LOOPS = 1;
uniform float psiTableSize;

void integratePiece(vec4 front, vec4 back, float len, inout vec4 color)
{
  float tauDFront = front.a * len;
  float tauDBack = back.a * len;
  float zeta = exp(-0.5 * (tauDFront + tauDBack));
  vec2 u = 1.0 - inversesqrt(vec2(tauDFront, tauDBack) + 1.0);
  // Texel centres sit at u = i / (N - 1).
  vec2 uv = (u * (psiTableSize - 1.0) + 0.5) / psiTableSize;
  float psi = texture(psiTable, uv).r;
  vec3 emitted = front.rgb * (1.0 - psi) + back.rgb * (psi - zeta);
  compositeFrontToBack(color, emitted, 1.0 - zeta);
}
