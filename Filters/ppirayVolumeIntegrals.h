/**
 * @file   ppirayVolumeIntegrals.h
 * @brief  closed-form integrals of the emission-absorption model, in double
 *
 * For a ray piece of length D on which colour C and attenuation tau are linear
 * (front f to back b), with a = tau_f D, b = tau_b D, c = (b - a) / 2:
 *
 *   zeta = exp(-(a + b) / 2)                                      transparency
 *   Psi  = int_0^1 exp(-(a u + c u^2)) du       (Moreland & Angel 2004, Eq. 9)
 *   I    = C_f (1 - Psi) + C_b (Psi - zeta)      emitted colour, premultiplied
 *
 * The exponent is quadratic in u, so Psi is an error-function expression:
 *   c > 0:  Psi = sqrt(pi) / (2 sqrt(c)) [erfcx(z0) - zeta erfcx(z1)],
 *           z0 = a / (2 sqrt(c)), z1 = z0 + sqrt(c)            (complete the square)
 *   c < 0:  Psi = [F(w1) - zeta F(w0)] / sqrt(-c),  F Dawson's function,
 *           w0 = b / (2 sqrt(-c)), w1 = w0 + sqrt(-c)          (reverse u, complete the square)
 *   c ~ 0:  Psi = sum_k (-c)^k / k! J_2k(a),  J_n(a) = int_0^1 u^n e^{-a u} du
 * Both closed forms are differences of bounded functions (erfcx, Dawson),
 * free of overflow for any a, b >= 0, including tau -> 0 and tau -> infinity.
 *
 * Used by the CPU reference renderer; deliberately shares nothing with the
 * GPU path (which tabulates Psi by quadrature), so that each checks the other.
 */
#ifndef ppirayVolumeIntegrals_h
#define ppirayVolumeIntegrals_h

#include "ppirayFiltersModule.h" // for export macro
#include "ppirayNumerics.h"      // for Erfcx, Dawson

namespace ppiray
{
/** Psi(a, b) above for a, b >= 0 (infinite arguments allowed). */
PPIRAYFILTERS_EXPORT double PsiClosedForm(double a, double b);

/**
 * Emitted premultiplied colour and transparency of a piece of length
 * `length` with linear colour and attenuation from front to back.
 */
PPIRAYFILTERS_EXPORT void IntegrateLinearPiece(const double colorFront[3], double tauFront,
  const double colorBack[3], double tauBack, double length, double emitted[3],
  double& transparency);
}

#endif
