#include "ppirayNumerics.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ppiray
{
namespace
{
constexpr double SqrtPi = 1.7724538509055160273;
}

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
int QuadraticRoots(double a, double b, double c, double roots[2])
{
  const double scale = std::max({ std::abs(a), std::abs(b), std::abs(c), 1e-300 });
  if (std::abs(a) < 1e-12 * scale)
  {
    if (std::abs(b) > 1e-300)
    {
      roots[0] = -c / b;
      return 1;
    }
    return 0;
  }
  const double discriminant = b * b - 4 * a * c;
  if (discriminant < 0)
  {
    return 0;
  }
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  roots[0] = q / a;
  if (q == 0)
  {
    return 1;
  }
  roots[1] = c / q;
  return 2;
}

//------------------------------------------------------------------------------
bool SolveLinear4(double a[4][4], double r[4], double smallest)
{
  for (int col = 0; col < 4; ++col)
  {
    int pivot = col;
    for (int row = col + 1; row < 4; ++row)
    {
      if (std::abs(a[row][col]) > std::abs(a[pivot][col]))
      {
        pivot = row;
      }
    }
    if (!(std::abs(a[pivot][col]) > smallest))
    {
      return false;
    }
    std::swap(a[col], a[pivot]);
    std::swap(r[col], r[pivot]);
    for (int row = col + 1; row < 4; ++row)
    {
      const double factor = a[row][col] / a[col][col];
      for (int k = col; k < 4; ++k)
      {
        a[row][k] -= factor * a[col][k];
      }
      r[row] -= factor * r[col];
    }
  }
  for (int row = 3; row >= 0; --row)
  {
    double sum = r[row];
    for (int k = row + 1; k < 4; ++k)
    {
      sum -= a[row][k] * r[k];
    }
    r[row] = sum / a[row][row];
  }
  return true;
}
}
