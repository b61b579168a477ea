#include "vtkPsiTable.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

vtkStandardNewMacro(vtkPsiTable);

namespace
{
constexpr int GaussOrder = 16;

// Gauss-Legendre nodes and weights on [-1, 1]: roots of P_n by Newton's method
// from the Chebyshev guess cos(pi (i + 3/4) / (n + 1/2)).
struct GaussLegendreRule
{
  std::array<double, GaussOrder> Nodes;
  std::array<double, GaussOrder> Weights;
  GaussLegendreRule()
  {
    const int n = GaussOrder;
    for (int i = 0; i < n; ++i)
    {
      double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
      double derivative = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration)
      {
        // Legendre recurrence: (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1}.
        double p0 = 1.0, p1 = x;
        for (int k = 1; k < n; ++k)
        {
          const double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
          p0 = p1;
          p1 = p2;
        }
        derivative = n * (x * p1 - p0) / (x * x - 1.0);
        const double dx = p1 / derivative;
        x -= dx;
        if (std::abs(dx) < 1e-16)
        {
          break;
        }
      }
      this->Nodes[i] = x;
      this->Weights[i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
  }
};

const GaussLegendreRule& Rule()
{
  static const GaussLegendreRule rule;
  return rule;
}

// Exponent of the Psi integrand: E(u) = a u + (b - a) u^2 / 2, increasing in u.
double Exponent(double a, double b, double u)
{
  return a * u + 0.5 * (b - a) * u * u;
}

double GaussLegendre(double a, double b, double u0, double u1)
{
  const GaussLegendreRule& rule = Rule();
  const double half = 0.5 * (u1 - u0);
  const double mid = 0.5 * (u1 + u0);
  double sum = 0.0;
  for (int i = 0; i < GaussOrder; ++i)
  {
    sum += rule.Weights[i] * std::exp(-Exponent(a, b, mid + half * rule.Nodes[i]));
  }
  return half * sum;
}
}

//------------------------------------------------------------------------------
double vtkPsiTable::Psi(double a, double b)
{
  if (std::isinf(a) || std::isinf(b))
  {
    return 0.0;
  }
  a = std::max(a, 0.0);
  b = std::max(b, 0.0);
  // The integrand exp(-E(u)) decays on the scale u ~ 1 / max(a, b) (or
  // 1 / sqrt(b) when a = 0): sub-intervals [0, h], [h, 2h], [2h, 4h], ...
  // resolve it; stop once the integrand is below 1e-30 of its start.
  const double scale = std::max({ a, b, std::sqrt(b), 1.0 });
  double u0 = 0.0;
  double u1 = std::min(1.0, 0.25 / scale);
  double sum = 0.0;
  while (u0 < 1.0)
  {
    sum += GaussLegendre(a, b, u0, u1);
    if (Exponent(a, b, u1) > 70.0)
    {
      break;
    }
    u0 = u1;
    u1 = std::min(1.0, 2.0 * u1);
  }
  return sum;
}

//------------------------------------------------------------------------------
double vtkPsiTable::PsiOfGamma(double gammaFront, double gammaBack)
{
  // tau D = gamma / (1 - gamma), infinite at gamma = 1.
  auto tauD = [](double gamma)
  { return gamma >= 1.0 ? std::numeric_limits<double>::infinity() : gamma / (1.0 - gamma); };
  return Psi(tauD(gammaFront), tauD(gammaBack));
}

//------------------------------------------------------------------------------
const std::vector<float>& vtkPsiTable::GetTable(int size)
{
  static std::mutex mutex;
  static std::map<int, std::vector<float>> tables;
  std::lock_guard<std::mutex> lock(mutex);
  size = std::max(size, 2);
  std::vector<float>& table = tables[size];
  if (table.empty())
  {
    table.resize(static_cast<size_t>(size) * size);
#pragma omp parallel for schedule(dynamic)
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        // u = 1 - sqrt(1 - gamma)  <=>  gamma = 1 - (1 - u)^2.
        const double uf = static_cast<double>(i) / (size - 1);
        const double ub = static_cast<double>(j) / (size - 1);
        table[static_cast<size_t>(j) * size + i] = static_cast<float>(
          PsiOfGamma(1.0 - (1.0 - uf) * (1.0 - uf), 1.0 - (1.0 - ub) * (1.0 - ub)));
      }
    }
  }
  return table;
}

//------------------------------------------------------------------------------
void vtkPsiTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
