/**
 * @file   ppirayNumerics.h
 * @brief  the CPU's small numerical functions, in double
 *
 * Special functions of the closed-form volume integrals (erfcx, Dawson),
 * the cancellation-free roots of a quadratic, and a small dense solve. Each
 * is named after what it computes; the comment at its definition gives the
 * formula and its range. The GPU has its own (GLSL) versions of what it needs:
 * the CPU reference must not share them (Documentation/accuracy.md).
 */
#ifndef ppirayNumerics_h
#define ppirayNumerics_h

#include "ppirayFiltersModule.h" // for export macro

namespace ppiray
{
/** exp(x^2) erfc(x) for x >= 0 (bounded by 1, ~ 1 / (x sqrt(pi)) for large x). */
PPIRAYFILTERS_EXPORT double Erfcx(double x);

/** Dawson's function F(x) = exp(-x^2) int_0^x exp(t^2) dt for x >= 0. */
PPIRAYFILTERS_EXPORT double Dawson(double x);

/**
 * The real roots of a x^2 + b x + c = 0 into `roots` (none, one or two,
 * unsorted); a negligible against b and c (|a| < 1e-12 max(|a|, |b|, |c|))
 * makes it linear. Without cancellation: q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2,
 * roots q / a and c / q (Press et al., Numerical Recipes, Sec. 5.6).
 */
PPIRAYFILTERS_EXPORT int QuadraticRoots(double a, double b, double c, double roots[2]);

/**
 * Solves the 4x4 system A x = r in place (x in r) by Gaussian elimination
 * with partial pivoting; false if a pivot is below `smallest`.
 */
PPIRAYFILTERS_EXPORT bool SolveLinear4(double a[4][4], double r[4], double smallest);
}

#endif
