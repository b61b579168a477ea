#include "ppirayVolumeIntegrals.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
constexpr double SqrtPi = 1.7724538509055160273;

// J_n(a) = int_0^1 u^n exp(-a u) du for n = 0..N-1: the series
// sum_k (-a)^k / (k! (n + k + 1)) for small a (to the first term below
// 1e-17 of the sum: all later ones are smaller), else the upward recurrence
// J_n = (n J_{n-1} - e^{-a}) / a from J_0 = (1 - e^{-a}) / a.
template <int N>
void MomentsOfExponential(double a, double (&j)[N])
{
  if (a < 1.0)
  {
    for (int n = 0; n < N; ++n)
    {
      double term = 1.0, sum = 0.0;
      for (int k = 0; k < 60; ++k)
      {
        const double added = term / (n + k + 1);
        sum += added;
        if (std::abs(added) < 1e-17 * sum)
        {
          break;
        }
        term *= -a / (k + 1);
      }
      j[n] = sum;
    }
    return;
  }
  const double ea = std::exp(-a);
  j[0] = -std::expm1(-a) / a;
  for (int n = 1; n < N; ++n)
  {
    j[n] = (n * j[n - 1] - ea) / a;
  }
}
}

namespace ppiray
{
//------------------------------------------------------------------------------
// erfcx(x) = exp(x^2) erfc(x): direct below 26 (erfc keeps its relative
// accuracy there), else the asymptotic series 1/(x sqrt(pi)) sum (-1)^n (2n-1)!! / (2x^2)^n.
double Erfcx(double x)
{
  if (x < 26.0)
  {
    return std::exp(x * x) * std::erfc(x);
  }
  const double r = 1.0 / (2.0 * x * x);
  double term = 1.0, sum = 1.0;
  for (int n = 1; n < 8; ++n)
  {
    term *= -(2.0 * n - 1.0) * r;
    sum += term;
  }
  return sum / (x * SqrtPi);
}

//------------------------------------------------------------------------------
// Dawson F(x) = (sqrt(pi) / 2) exp(-x^2) erfi(x), with the all-positive series
// erfi(x) = (2 / sqrt(pi)) sum x^(2n+1) / (n! (2n + 1)) below 20 (no
// cancellation; exp(x^2) < 1e174), else F ~ 1/(2x) sum (2n-1)!! / (2x^2)^n.
double Dawson(double x)
{
  if (x < 20.0)
  {
    const double x2 = x * x;
    double power = x, sum = 0.0;
    for (int n = 0; n < 2000; ++n)
    {
      const double term = power / (2.0 * n + 1.0);
      sum += term;
      if (term < 1e-17 * sum)
      {
        break;
      }
      power *= x2 / (n + 1.0);
    }
    return std::exp(-x2) * sum;
  }
  const double r = 1.0 / (2.0 * x * x);
  double term = 1.0, sum = 1.0;
  for (int n = 1; n < 10; ++n)
  {
    term *= (2.0 * n - 1.0) * r;
    sum += term;
  }
  return sum / (2.0 * x);
}

//------------------------------------------------------------------------------
double PsiClosedForm(double a, double b)
{
  if (std::isinf(a) || std::isinf(b))
  {
    return 0.0;
  }
  a = std::max(a, 0.0);
  b = std::max(b, 0.0);
  const double c = 0.5 * (b - a);
  const double zeta = std::exp(-0.5 * (a + b));
  if (std::abs(c) < 1e-3)
  {
    // exp(-c u^2) = sum_k (-c u^2)^k / k!, four terms: error < c^4 / 24 < 5e-14.
    double j[7];
    MomentsOfExponential(a, j);
    return j[0] - c * j[2] + 0.5 * c * c * j[4] - c * c * c / 6.0 * j[6];
  }
  if (c > 0)
  {
    const double sc = std::sqrt(c);
    const double z0 = a / (2.0 * sc);
    return SqrtPi / (2.0 * sc) * (Erfcx(z0) - zeta * Erfcx(z0 + sc));
  }
  const double sc = std::sqrt(-c);
  const double w0 = b / (2.0 * sc);
  return (Dawson(w0 + sc) - zeta * Dawson(w0)) / sc;
}

//------------------------------------------------------------------------------
void IntegrateLinearPiece(const double colorFront[3], double tauFront, const double colorBack[3],
  double tauBack, double length, double emitted[3], double& transparency)
{
  const double a = tauFront * length, b = tauBack * length;
  const double psi = PsiClosedForm(a, b);
  transparency = (std::isinf(a) || std::isinf(b)) ? 0.0 : std::exp(-0.5 * (a + b));
  for (int i = 0; i < 3; ++i)
  {
    emitted[i] = colorFront[i] * (1.0 - psi) + colorBack[i] * (psi - transparency);
  }
}
}
