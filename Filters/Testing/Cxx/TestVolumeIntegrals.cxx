// The reference renderer's closed forms against brute force:
//  - erfcx and Dawson against their defining integrals;
//  - Psi(a, b) for all signs of b - a and magnitudes 0 .. 1e4 (tau -> 0 and
//    tau -> infinity), across the series / closed-form switch at |b - a| = 2e-3;
//  - the emitted colour of a piece, int_0^D C tau T dx, against 1e6-sample
//    composite Gauss-Legendre quadrature (two points on each of 5e5
//    sub-intervals): agreement to 1e-9.

#include "ppirayVolumeIntegrals.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>

namespace
{
// Composite 2-point Gauss-Legendre with n sub-intervals on [0, 1] (2n samples).
template<typename F>
double Quadrature(F f, int n)
{
  const double h = 1.0 / n, g = 0.5 / std::sqrt(3.0);
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const double mid = (i + 0.5) * h;
    sum += f(mid - g * h) + f(mid + g * h);
  }
  return 0.5 * h * sum;
}
}

int TestVolumeIntegrals(int, char*[])
{
  int errors = 0;
  double worst = 0;
  auto check = [&](double got, double want, double tolerance, const char* what, double x, double y)
  {
    worst = std::max(worst, std::abs(got - want));
    if (!(std::abs(got - want) <= tolerance))
    {
      std::printf("FAILED %s(%g, %g): %.17g vs %.17g\n", what, x, y, got, want);
      ++errors;
    }
  };

  // Dawson F(x) = int_0^x exp(t^2 - x^2) dt; erfcx via erfc where it is exact.
  for (double x : { 0.0, 1e-3, 0.3, 1.0, 2.5, 7.0, 19.9, 20.1, 40.0 })
  {
    const double dawson =
      x * Quadrature([x](double u) { return std::exp(x * x * (u * u - 1.0)); }, 500000);
    check(ppiray::Dawson(x), dawson, 1e-10, "Dawson", x, 0);
  }
  for (double x : { 0.0, 0.5, 3.0, 10.0, 25.9 })
  {
    check(ppiray::Erfcx(x), std::exp(x * x) * std::erfc(x), 1e-13 * std::exp(0.0), "erfcx", x, 0);
  }
  // exp(900) erfc(30) to 17 digits (mpmath, 30-digit arithmetic).
  check(ppiray::Erfcx(30.0), 0.018795888861416751, 1e-15, "erfcx", 30, 0);

  // Psi and the emitted colour of a piece, D = 1 so a = tau_f, b = tau_b.
  const double values[] = { 0.0, 1e-6, 1e-3, 0.0015, 0.5, 1.0, 3.7, 10.0, 100.0, 1e4 };
  for (double a : values)
  {
    for (double b : values)
    {
      const double c = 0.5 * (b - a);
      const double psi =
        Quadrature([a, c](double u) { return std::exp(-(a * u + c * u * u)); }, 500000);
      check(ppiray::PsiClosedForm(a, b), psi, 1e-9, "Psi", a, b);

      const double cf[3] = { 1.0, 0.25, 0.0 }, cb[3] = { 0.0, 0.5, 1.0 };
      double emitted[3], transparency;
      ppiray::IntegrateLinearPiece(cf, a, cb, b, 1.0, emitted, transparency);
      for (int i = 0; i < 3; ++i)
      {
        const double brute = Quadrature(
          [&](double x)
          {
            const double color = cf[i] + (cb[i] - cf[i]) * x;
            const double tau = a + (b - a) * x;
            return color * tau * std::exp(-(a * x + c * x * x));
          },
          500000);
        check(emitted[i], brute, 1e-9, "emission", a, b);
      }
      check(transparency, std::exp(-0.5 * (a + b)), 1e-15, "transparency", a, b);
    }
  }
  // Opaque limits: an infinitely dense front emits its own colour.
  const double inf = std::numeric_limits<double>::infinity();
  const double cf[3] = { 0.3, 0.6, 0.9 }, cb[3] = { 1, 1, 1 };
  double emitted[3], transparency;
  ppiray::IntegrateLinearPiece(cf, inf, cb, 1.0, 1.0, emitted, transparency);
  check(emitted[0], 0.3, 0, "opaque front", inf, 1);
  check(transparency, 0.0, 0, "opaque transparency", inf, 1);
  check(ppiray::PsiClosedForm(1.0, inf), 0.0, 0, "Psi", 1, inf);
  std::printf("worst difference to brute force: %.2e\n", worst);
  return errors == 0 ? 0 : 1;
}
