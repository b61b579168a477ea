#include "vtkPreIntegrationTable.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPsiTable.h"
#include "vtkTimerLog.h"
#include "vtkTransferFunctionControlPoints.h"

#include <algorithm>
#include <array>
#include <cmath>

vtkStandardNewMacro(vtkPreIntegrationTable);

namespace
{
using RGBA = std::array<double, 4>;

// (r, g, b, tau) of the control points' piecewise-linear function at s, with
// k the control interval of s (s_k <= s < s_k+1; -1 below, n - 1 above).
std::array<double, 4> Evaluate(vtkTransferFunctionControlPoints* cp, double s, int k)
{
  const auto& v = cp->GetValues();
  const auto& c = cp->GetColorAttenuation();
  const int n = cp->GetNumberOfControlPoints();
  const int lo = std::min(std::max(k, 0), n - 1), hi = std::min(std::max(k + 1, 0), n - 1);
  const double w = (hi == lo || v[hi] <= v[lo])
                     ? 0.0
                     : std::min(1.0, std::max(0.0, (s - v[lo]) / (v[hi] - v[lo])));
  return { (1 - w) * c[4 * lo] + w * c[4 * hi], (1 - w) * c[4 * lo + 1] + w * c[4 * hi + 1],
    (1 - w) * c[4 * lo + 2] + w * c[4 * hi + 2], (1 - w) * c[4 * lo + 3] + w * c[4 * hi + 3] };
}

int Interval(vtkTransferFunctionControlPoints* cp, double s)
{
  const auto& v = cp->GetValues();
  return static_cast<int>(std::upper_bound(v.begin(), v.end(), s) - v.begin()) - 1;
}

// Exact premultiplied colour and opacity of a segment of length `length` from
// sFront to sBack: split at the control points strictly between, each piece
// I = C_f (1 - Psi) + C_b (Psi - zeta) (Moreland & Angel 2004, Sec. 4).
RGBA IntegrateSegment(
  vtkTransferFunctionControlPoints* cp, double sFront, double sBack, double length)
{
  const auto& v = cp->GetValues();
  std::vector<double> cuts = { sFront };
  const double lo = std::min(sFront, sBack), hi = std::max(sFront, sBack);
  std::vector<double> inner;
  for (double x : v)
  {
    if (x > lo && x < hi)
    {
      inner.push_back(x);
    }
  }
  if (sBack < sFront)
  {
    std::reverse(inner.begin(), inner.end());
  }
  cuts.insert(cuts.end(), inner.begin(), inner.end());
  cuts.push_back(sBack);
  RGBA out = { 0, 0, 0, 0 };
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    const double sa = cuts[i], sb = cuts[i + 1];
    const double d = sBack == sFront ? length : length * (sb - sa) / (sBack - sFront);
    if (!(d > 0))
    {
      continue;
    }
    // Both ends evaluated in the interval the piece lies in.
    const int k = Interval(cp, 0.5 * (sa + sb));
    const auto a = Evaluate(cp, sa, k), b = Evaluate(cp, sb, k);
    const double zeta = std::exp(-0.5 * d * (a[3] + b[3]));
    const double psi = vtkPsiTable::Psi(a[3] * d, b[3] * d);
    for (int c = 0; c < 3; ++c)
    {
      out[c] += (1 - out[3]) * (a[c] * (1 - psi) + b[c] * (psi - zeta));
    }
    out[3] += (1 - out[3]) * (1 - zeta);
  }
  return out;
}
}

//------------------------------------------------------------------------------
void vtkPreIntegrationTable::Build(vtkTransferFunctionControlPoints* cp, double sMin, double sMax,
  double maximumLength, int scalarSize, int lengthSize)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const int n = std::max(scalarSize, 2), m = std::max(lengthSize, 2);
  if (!(sMax > sMin))
  {
    sMax = sMin + 1.0;
  }
  this->ScalarSize = n;
  this->LengthSize = m;
  this->ScalarRange[0] = sMin;
  this->ScalarRange[1] = sMax;
  this->MaximumLength = maximumLength;
  this->Table.assign(static_cast<size_t>(n) * n * m * 4, 0.0f);
  const double dl = maximumLength / (m - 1);
  auto scalar = [&](int i) { return sMin + (sMax - sMin) * i / (n - 1); };
  auto at = [&](int i, int j, int k) -> float*
  { return this->Table.data() + 4 * ((static_cast<size_t>(k) * n + j) * n + i); };

  // Slice 1: exact integrals over length dl (slice 0, length 0, stays zero).
#pragma omp parallel for schedule(static)
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const RGBA e = IntegrateSegment(cp, scalar(i), scalar(j), dl);
      std::copy(e.begin(), e.end(), at(i, j, 1));
    }
  }

  // Linear interpolation in a slice along s_back (front on the grid) or along
  // s_front (back on the grid); x in texel units.
  auto alongBack = [&](int i, double x, int k, int c)
  {
    const int j = std::min(static_cast<int>(x), n - 2);
    const double w = x - j;
    return (1 - w) * at(i, j, k)[c] + w * at(i, j + 1, k)[c];
  };
  auto alongFront = [&](double x, int j, int k, int c)
  {
    const int i = std::min(static_cast<int>(x), n - 2);
    const double w = x - i;
    return (1 - w) * at(i, j, k)[c] + w * at(i + 1, j, k)[c];
  };

  // Slices 2 .. m-1 (Weiler et al. 2003, Eqs. 5-6): length (k-1) dl + dl =
  // front part dl (slice 1) then back part (k-1) dl (slice k-1), split at
  // s_p = ((k-1) s_f + s_b) / k, in texel units x_p = ((k-1) i + j) / k.
  for (int k = 2; k < m; ++k)
  {
#pragma omp parallel for schedule(static)
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double xp = ((k - 1.0) * i + j) / k;
        float* out = at(i, j, k);
        const double frontAlpha = alongBack(i, xp, 1, 3);
        for (int c = 0; c < 4; ++c)
        {
          out[c] = static_cast<float>(
            alongBack(i, xp, 1, c) + (1.0 - frontAlpha) * alongFront(xp, j, k - 1, c));
        }
      }
    }
  }
  timer->StopTimer();
  this->BuildTime = timer->GetElapsedTime();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPreIntegrationTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->ScalarSize << " x " << this->ScalarSize << " x "
     << this->LengthSize << "\n";
  os << indent << "ScalarRange: " << this->ScalarRange[0] << " " << this->ScalarRange[1] << "\n";
  os << indent << "MaximumLength: " << this->MaximumLength << "\n";
  os << indent << "BuildTime: " << this->BuildTime << " s\n";
}
