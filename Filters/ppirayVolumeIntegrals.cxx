#include "ppirayVolumeIntegrals.h"

#include "ppirayNumerics.h"

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
template<int N>
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
