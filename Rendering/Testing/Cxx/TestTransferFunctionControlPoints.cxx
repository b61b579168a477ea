// Control points of a transfer function against VTK's own evaluation
// (vtkColorTransferFunction::GetTable, vtkPiecewiseFunction::GetValue) on a
// dense sampling, for every colour space, log scale, clamping off, repeated
// nodes, sharpness 1 and ParaView's vtkDiscretizableColorTransferFunction:
// within Tolerance everywhere except in a 1e-9-wide window at each jump;
// every node a control point; jumps (where VTK's evaluation has them: a
// sharpness of 1 is a step in VTK 9.2, a steep curve in 9.6) kept as two
// points at one scalar;
// attenuation opacity / unit distance; the transparent runs of the texels
// (zero opacity on all of each, none left out, none longer) against VTK's
// opacity function.

#include "vtkColorTransferFunction.h"
#include "vtkDiscretizableColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSmartPointer.h"
#include "vtkTransferFunctionControlPoints.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
// The control points' piecewise-linear (r, g, b, tau) at s, constant outside;
// at a jump, the right limit.
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

struct Case
{
  std::string Name;
  std::function<void(vtkColorTransferFunction*, vtkPiecewiseFunction*)> Make;
  int MinimumJumps = 0; // jumps the function has (two control points at one scalar)
  // Largest deviation allowed (max, p99), 1/255 units (0: the builder's Tolerance).
  double Bound = 0;
  double P99Bound = 0;
};

// ParaView's default map, "Cool to Warm": Diverging between two nodes.
void CoolToWarm(vtkColorTransferFunction* color, double lo, double hi)
{
  color->SetColorSpaceToDiverging();
  color->AddRGBPoint(lo, 0.231373, 0.298039, 0.752941);
  color->AddRGBPoint(hi, 0.705882, 0.0156863, 0.14902);
}

void Ramp(vtkPiecewiseFunction* opacity, double lo, double hi)
{
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(hi, 0.8);
}

// Three nodes, the middle one off the straight line.
void ThreeNodes(vtkColorTransferFunction* color)
{
  color->AddRGBPoint(0.0, 0.1, 0.1, 0.9);
  color->AddRGBPoint(40.0, 0.9, 0.9, 0.2);
  color->AddRGBPoint(100.0, 0.8, 0.1, 0.1);
}

int Check(const Case& test, vtkColorTransferFunction* color)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  test.Make(color, opacity);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  const double unitDistance = 2.0;
  property->SetScalarOpacityUnitDistance(unitDistance);
  vtkNew<vtkTransferFunctionControlPoints> cp;
  cp->Build(property);
  const auto& values = cp->GetValues();
  std::vector<double> jumps;
  for (size_t i = 0; i + 1 < values.size(); ++i)
  {
    if (values[i] == values[i + 1] ||
        values[i + 1] - values[i] <= 1e-11 * std::max(1.0, std::abs(values[i])))
    {
      jumps.push_back(values[i]);
    }
  }
  double range[2] = { opacity->GetRange()[0], opacity->GetRange()[1] };
  range[0] = std::min(range[0], color->GetRange()[0]);
  range[1] = std::max(range[1], color->GetRange()[1]);
  const double width = range[1] - range[0];
  // Dense sampling just off the nodes, colours in one GetTable call (the
  // CIEDE2000 space builds its colour path per call).
  double worst = 0, worstAt = 0;
  const int samples = 24001;
  const double first = range[0] - 0.05 * width + 1e-7 * width;
  const double last = range[1] + 0.05 * width + 1e-7 * width;
  std::vector<double> table(3 * samples);
  if (color->GetScale() == VTK_CTF_LINEAR)
  {
    color->GetTable(first, last, samples, table.data());
  }
  else
  {
    for (int i = 0; i < samples; ++i) // GetTable spaces samples evenly in log10
    {
      const double s = first + (last - first) * i / (samples - 1);
      color->GetTable(s, s, 1, table.data() + 3 * i);
    }
  }
  // Where VTK's own evaluation jumps: neighbouring samples (1/24,000 of the
  // range apart) more than 0.1 apart. A sharpness of 1 is a step in VTK 9.2
  // and a steep continuous curve in VTK 9.6: a jump is expected only where
  // VTK has one.
  int vtkJumps = 0;
  for (int i = 1; i < samples; ++i)
  {
    const double s0 = first + (last - first) * (i - 1) / (samples - 1);
    const double s1 = first + (last - first) * i / (samples - 1);
    bool jump = std::abs(opacity->GetValue(s1) - opacity->GetValue(s0)) > 0.1;
    for (int c = 0; c < 3; ++c)
    {
      jump = jump || std::abs(table[3 * i + c] - table[3 * (i - 1) + c]) > 0.1;
    }
    vtkJumps += jump ? 1 : 0;
  }
  std::vector<double> deviations;
  for (int i = 0; i < samples; ++i)
  {
    const double s = first + (last - first) * i / (samples - 1);
    bool nearJump = false;
    for (double j : jumps)
    {
      nearJump = nearJump || std::abs(s - j) < 1e-9 * std::max(1.0, width);
    }
    if (nearJump)
    {
      continue;
    }
    double got[4];
    Interpolate(cp, s, got);
    double deviation = std::abs(got[3] * unitDistance - opacity->GetValue(s));
    for (int c = 0; c < 3; ++c)
    {
      deviation = std::max(deviation, std::abs(got[c] - table[3 * i + c]));
    }
    deviations.push_back(deviation);
    if (deviation > worst)
    {
      worst = deviation;
      worstAt = s;
    }
  }
  std::sort(deviations.begin(), deviations.end());
  const double p99 = deviations[static_cast<size_t>(0.99 * (deviations.size() - 1))];
  int missing = 0;
  for (int i = 0; i < color->GetSize(); ++i)
  {
    double node[6];
    color->GetNodeValue(i, node);
    bool found = false;
    for (double v : values)
    {
      found = found || v == node[0];
    }
    missing += found ? 0 : 1;
  }
  std::printf("%-34s %5d control points, %2zu jumps (VTK's %d), deviation p99 %.3f max %.3f/255 "
              "at %g\n",
    test.Name.c_str(), cp->GetNumberOfControlPoints(), jumps.size(), vtkJumps, 255 * p99,
    255 * worst, worstAt);
  std::fflush(stdout);
  int errors = 0;
  const double bound = test.Bound > 0 ? test.Bound / 255 : cp->GetTolerance();
  const double p99Bound = test.P99Bound > 0 ? test.P99Bound / 255 : cp->GetTolerance();
  if (worst > bound || p99 > p99Bound)
  {
    std::printf("FAILED: %s deviates from VTK's evaluation by more than %.3f/255\n",
      test.Name.c_str(), 255 * bound);
    ++errors;
  }
  const int expectedJumps = std::min(test.MinimumJumps, vtkJumps);
  if (static_cast<int>(jumps.size()) < expectedJumps)
  {
    std::printf("FAILED: %s: %zu jumps kept, expected at least %d\n", test.Name.c_str(),
      jumps.size(), expectedJumps);
    ++errors;
  }
  if (missing > 0 || cp->GetTruncated())
  {
    std::printf("FAILED: %s: %d colour nodes are not control points, truncated %d\n",
      test.Name.c_str(), missing, cp->GetTruncated());
    ++errors;
  }
  return errors;
}
}

// The transparent runs GetTexels stores with each control interval, checked
// against VTK's own opacity: zero at 1,000 samples across each run, not zero
// just past a finite end (a run is as long as it can be), and every interval
// whose samples are all zero inside a run.
int CheckTransparentRuns()
{
  vtkNew<vtkColorTransferFunction> color;
  for (double s : { 0.0, 10.0, 20.0, 45.0, 80.0, 90.0, 100.0 })
  {
    color->AddRGBPoint(s, s / 100.0, 0.5, 1.0 - s / 100.0);
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(30.0, 0.0);
  opacity->AddPoint(50.0, 0.5);
  opacity->AddPoint(55.0, 0.0);
  opacity->AddPoint(58.0, 0.0);
  opacity->AddPoint(60.0, 0.4);
  opacity->AddPoint(70.0, 0.0);
  opacity->AddPoint(100.0, 0.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkTransferFunctionControlPoints> cp;
  cp->Build(property);
  const std::vector<float> texels = cp->GetTexels();
  const int n = cp->GetNumberOfControlPoints();
  int errors = 0;
  int runs = 0;
  for (int k = -1; k < n; ++k)
  {
    const float* t = &texels[12 * (k + 1)];
    const double lo = std::max<double>(t[8], -1000.0);
    const double hi = std::min<double>(t[9], 1000.0);
    bool zero = true;
    for (int i = 0; i <= 1000; ++i)
    {
      zero = zero && opacity->GetValue(lo + (hi - lo) * i / 1000.0) == 0.0;
    }
    const bool inRun = t[10] <= t[8] && t[9] <= t[11];
    if (zero != inRun || zero != cp->IsTransparentInterval(k) || (!inRun && t[10] <= t[11]))
    {
      std::printf("FAILED: interval %d [%g, %g]: VTK's opacity %s zero, run [%g, %g]\n", k, lo, hi,
        zero ? "all" : "not all", t[10], t[11]);
      ++errors;
    }
    if (!inRun || (k >= 0 && texels[12 * k + 11] == t[11]))
    {
      continue; // the run was checked at its first interval
    }
    ++runs;
    const double a = std::max<double>(t[10], -1000.0);
    const double b = std::min<double>(t[11], 1000.0);
    for (int i = 0; i <= 1000; ++i)
    {
      if (opacity->GetValue(a + (b - a) * i / 1000.0) != 0.0)
      {
        std::printf("FAILED: run [%g, %g] not transparent at %g\n", a, b, a + (b - a) * i / 1000.0);
        ++errors;
        break;
      }
    }
    for (double end : { double(t[10]) - 0.01, double(t[11]) + 0.01 })
    {
      if (std::abs(end) < 1000.0 && opacity->GetValue(end) == 0.0)
      {
        std::printf("FAILED: run [%g, %g] stops short of %g\n", t[10], t[11], end);
        ++errors;
      }
    }
  }
  // [-inf, 30], [55, 58], [70, inf], each across several colour nodes.
  if (runs != 3)
  {
    std::printf("FAILED: %d transparent runs, expected 3\n", runs);
    ++errors;
  }
  return errors;
}

int TestTransferFunctionControlPoints(int, char*[])
{
  std::vector<Case> cases;
  cases.push_back(
    { "RGB, curved opacity (sharpness)", [](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
      {
        ThreeNodes(c);
        o->AddPoint(10.0, 0.0, 0.3, 0.8);
        o->AddPoint(60.0, 0.9);
        o->AddPoint(80.0, 0.2);
      } });
  for (const char* space : { "HSV", "HSV wrapping", "Lab", "CIEDE2000", "Diverging" })
  {
    const std::string name = space;
    // VTK's CIEDE2000 colours step by up to 5/255 along its path: the
    // control points follow a 65,536-sample table of it to half a step
    // (vtkTransferFunctionControlPoints), so max is bounded by a step and
    // p99 by a step of 1/255.
    const double bound = name == "CIEDE2000" ? 5.0 : 0.0;
    const double p99Bound = name == "CIEDE2000" ? 1.0 : 0.0;
    cases.push_back({ name,
      [name](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
      {
        ThreeNodes(c);
        if (name == "HSV" || name == "HSV wrapping")
        {
          c->SetColorSpaceToHSV();
          c->SetHSVWrap(name == "HSV wrapping");
        }
        else if (name == "Lab")
        {
          c->SetColorSpaceToLab();
        }
        else if (name == "CIEDE2000")
        {
          c->SetColorSpaceToLabCIEDE2000();
        }
        else
        {
          c->SetColorSpaceToDiverging();
        }
        Ramp(o, 0.0, 100.0);
      },
      0, bound, p99Bound });
  }
  cases.push_back(
    { "Cool to Warm (ParaView default)", [](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
      {
        CoolToWarm(c, -3.0, 7.0);
        Ramp(o, -3.0, 7.0);
      } });
  cases.push_back({ "Step colour space",
    [](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
    {
      ThreeNodes(c);
      c->SetColorSpaceToStep();
      Ramp(o, 0.0, 100.0);
    },
    2 });
  cases.push_back({ "log10 scale", [](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
    {
      c->AddRGBPoint(1.0, 0.1, 0.1, 0.9);
      c->AddRGBPoint(1000.0, 0.9, 0.2, 0.1);
      c->SetScaleToLog10();
      Ramp(o, 1.0, 1000.0);
    } });
  cases.push_back({ "clamping off (zero outside)",
    [](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
    {
      ThreeNodes(c);
      c->ClampingOff();
      o->AddPoint(10.0, 0.3);
      o->AddPoint(80.0, 0.2);
      o->ClampingOff();
    },
    2 });
  cases.push_back({ "repeated nodes (steps)",
    [](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
    {
      c->AllowDuplicateScalarsOn();
      c->AddRGBPoint(0.0, 0.1, 0.1, 0.9);
      c->AddRGBPoint(50.0, 0.1, 0.9, 0.1);
      c->AddRGBPoint(50.0, 0.9, 0.1, 0.1);
      c->AddRGBPoint(100.0, 0.9, 0.9, 0.1);
      o->AllowDuplicateScalarsOn();
      o->AddPoint(0.0, 0.1);
      o->AddPoint(30.0, 0.1);
      o->AddPoint(30.0, 0.9);
      o->AddPoint(100.0, 0.5);
    },
    2 });
  cases.push_back({ "sharpness 1 (step inside a segment)",
    [](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
    {
      ThreeNodes(c);
      o->AddPoint(0.0, 0.1, 0.3, 1.0);
      o->AddPoint(100.0, 0.9);
    },
    1 });

  int errors = CheckTransparentRuns();
  for (const Case& test : cases)
  {
    vtkNew<vtkColorTransferFunction> color;
    errors += Check(test, color);
  }
  // ParaView's lookup-table class, discretized: VTK's volume mappers render
  // its continuous function (GetTable is not virtual), and so do we.
  vtkNew<vtkDiscretizableColorTransferFunction> discrete;
  discrete->DiscretizeOn();
  discrete->SetNumberOfValues(8);
  errors += Check({ "Discretizable (Discretize on)",
                    [](vtkColorTransferFunction* c, vtkPiecewiseFunction* o)
                    {
                      CoolToWarm(c, 0.0, 1.0);
                      Ramp(o, 0.0, 1.0);
                    } },
    discrete);

  // A budget too small for the function: a warning and the flag.
  vtkNew<vtkColorTransferFunction> color;
  CoolToWarm(color, 0.0, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  Ramp(opacity, 0.0, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkTransferFunctionControlPoints> cp;
  cp->SetMaximumNumberOfControlPoints(4);
  cp->GlobalWarningDisplayOff();
  cp->Build(property);
  if (!cp->GetTruncated() || cp->GetNumberOfControlPoints() > 4)
  {
    std::printf(
      "FAILED: a 4-point budget was not reported (%d points)\n", cp->GetNumberOfControlPoints());
    ++errors;
  }
  return errors == 0 ? 0 : 1;
}
