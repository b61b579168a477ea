// Control points of a transfer function: the union of the colour and opacity
// nodes; curved segments (sharpness / midpoint) refined until the linear
// interpolant is within Tolerance of the function everywhere (checked on a
// dense sampling, not only at the bisection points); clamping off gives steps
// (two points at one scalar); attenuation is opacity / unit distance.

#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTransferFunctionControlPoints.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>

namespace
{
// The control points' piecewise-linear (r, g, b, tau) at s, constant outside.
void Interpolate(vtkTransferFunctionControlPoints* cp, double s, double out[4])
{
  const auto& v = cp->GetValues();
  const auto& c = cp->GetColorAttenuation();
  const int n = cp->GetNumberOfControlPoints();
  int k = 0;
  while (k + 1 < n && v[k + 1] <= s)
  {
    ++k;
  }
  const int hi = std::min(k + 1, n - 1);
  const double w = (hi == k || s <= v[k]) ? 0.0 : std::min(1.0, (s - v[k]) / (v[hi] - v[k]));
  for (int i = 0; i < 4; ++i)
  {
    out[i] = (1 - w) * c[4 * k + i] + w * c[4 * hi + i];
  }
}
}

int TestTransferFunctionControlPoints(int, char*[])
{
  int errors = 0;
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.0, 0.0, 1.0);
  color->AddRGBPoint(30.0, 0.0, 1.0, 0.0, 0.5, 0.0);
  color->AddRGBPoint(100.0, 1.0, 0.0, 0.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(10.0, 0.0, 0.3, 0.8); // curved segment [10, 60]
  opacity->AddPoint(60.0, 0.9);
  opacity->AddPoint(80.0, 0.2);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(2.0);

  vtkNew<vtkTransferFunctionControlPoints> cp;
  cp->Build(property);
  const int n = cp->GetNumberOfControlPoints();
  std::printf("%d control points (6 nodes + refinement of the curved segment)\n", n);
  if (n <= 6)
  {
    std::printf("FAILED: the curved opacity segment was not refined\n");
    ++errors;
  }
  for (double node : { 0.0, 10.0, 30.0, 60.0, 80.0, 100.0 })
  {
    bool found = false;
    for (double v : cp->GetValues())
    {
      found = found || v == node;
    }
    if (!found)
    {
      std::printf("FAILED: node %g is not a control point\n", node);
      ++errors;
    }
  }
  // Dense check: colour within tolerance, attenuation within tolerance / unit distance.
  double worst = 0;
  for (int i = -100; i <= 1100; ++i)
  {
    const double s = 0.1 * i;
    double got[4];
    Interpolate(cp, s, got);
    double rgb[3];
    color->GetColor(s, rgb);
    const double tau = opacity->GetValue(s) / 2.0;
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(got[c] - rgb[c]));
    }
    worst = std::max(worst, 2.0 * std::abs(got[3] - tau));
  }
  // Bisection checks 3 points per sub-segment; a smooth curve between them
  // deviates a little more: allow twice the tolerance.
  std::printf("max deviation %.2e (tolerance %.2e)\n", worst, cp->GetTolerance());
  if (worst > 2 * cp->GetTolerance())
  {
    std::printf("FAILED: control points deviate from the transfer function\n");
    ++errors;
  }

  // Clamping off: zero outside [10, 80]: steps at both ends.
  opacity->ClampingOff();
  cp->Build(property);
  int steps = 0;
  for (int i = 0; i + 1 < cp->GetNumberOfControlPoints(); ++i)
  {
    steps += cp->GetValues()[i] == cp->GetValues()[i + 1] ? 1 : 0;
  }
  double below[4], above[4];
  Interpolate(cp, 5.0, below);
  Interpolate(cp, 90.0, above);
  std::printf("clamping off: %d steps, tau(5) = %g, tau(90) = %g\n", steps, below[3], above[3]);
  if (steps != 1 || below[3] != 0.0 || above[3] != 0.0)
  {
    // At 10 the opacity is already 0: only the step at 80 (0.2 -> 0) is real.
    std::printf("FAILED: clamping off not honoured\n");
    ++errors;
  }
  return errors == 0 ? 0 : 1;
}
