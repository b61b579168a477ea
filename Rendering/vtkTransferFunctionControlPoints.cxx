#include "vtkTransferFunctionControlPoints.h"

#include "vtkColorTransferFunction.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkTransferFunctionControlPoints);

namespace
{
using Sample = std::array<double, 4>; // r, g, b, opacity

// The transfer functions as VTK's volume mappers evaluate them: colour through
// vtkColorTransferFunction::GetTable (the continuous function in its colour
// space and scale, with its clamping; non-virtual, so a
// vtkDiscretizableColorTransferFunction is not discretized, as in
// vtkOpenGLVolumeRGBTable), grey and opacity through vtkPiecewiseFunction::GetValue.
struct TransferFunctions
{
  vtkColorTransferFunction* Color = nullptr;
  vtkPiecewiseFunction* Gray = nullptr;
  vtkPiecewiseFunction* Opacity = nullptr;

  // The functions at n >= 2 evenly spaced scalars from x0 to x1, in one
  // GetTable call (the CIEDE2000 space builds its colour path per call).
  std::vector<Sample> Evaluate(double x0, double x1, int n) const
  {
    std::vector<double> x(n), rgb(3 * n, 1.0);
    for (int i = 0; i < n; ++i)
    {
      x[i] = i == n - 1 ? x1 : x0 + (x1 - x0) * i / (n - 1);
    }
    if (this->Color && this->Dense.empty() && this->Color->GetScale() == VTK_CTF_LINEAR)
    {
      this->Color->GetTable(x0, x1, n, rgb.data());
    }
    else if (this->Color)
    {
      // A log scale spaces GetTable's samples evenly in log10: one by one.
      for (int i = 0; i < n; ++i)
      {
        if (this->Dense.empty())
        {
          this->Color->GetTable(x[i], x[i], 1, rgb.data() + 3 * i);
        }
        else
        {
          this->DenseColor(x[i], rgb.data() + 3 * i);
        }
      }
    }
    else if (this->Gray)
    {
      for (int i = 0; i < n; ++i)
      {
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = this->Gray->GetValue(x[i]);
      }
    }
    std::vector<Sample> samples(n);
    for (int i = 0; i < n; ++i)
    {
      samples[i] = { rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], this->Opacity->GetValue(x[i]) };
    }
    return samples;
  }

  // VTK's CIEDE2000 space searches a colour path in every GetTable call (0.1 s
  // here) and its colours step by about 1/255 along it: inside the colour
  // nodes it is sampled once, DenseSamples per scalar range, and read by
  // linear interpolation.
  static constexpr int DenseSamples = 1 << 16;
  std::vector<double> Dense;
  double DenseRange[2] = { 0, 0 };

  void SampleDensely()
  {
    if (!this->Color || this->Color->GetColorSpace() != VTK_CTF_LAB_CIEDE2000 ||
        this->Color->GetScale() != VTK_CTF_LINEAR || this->Color->GetSize() < 2)
    {
      return;
    }
    this->Color->GetRange(this->DenseRange);
    this->Dense.resize(3 * DenseSamples);
    this->Color->GetTable(
      this->DenseRange[0], this->DenseRange[1], DenseSamples, this->Dense.data());
  }

  void DenseColor(double x, double rgb[3]) const
  {
    const double u = (x - this->DenseRange[0]) / (this->DenseRange[1] - this->DenseRange[0]);
    if (!(u >= 0.0 && u <= 1.0))
    {
      this->Color->GetTable(x, x, 1, rgb);
      return;
    }
    const double f = u * (DenseSamples - 1);
    const int i = std::min(static_cast<int>(f), DenseSamples - 2);
    const double w = f - i;
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = (1.0 - w) * this->Dense[3 * i + c] + w * this->Dense[3 * i + 3 + c];
    }
  }

  // One-sided limits at x, {below, above}: the functions jump at repeated
  // nodes, at the ends of a function with clamping off, between the nodes of
  // the Step colour space and at the midpoint of a segment of sharpness 1.
  std::vector<Sample> Limits(double x) const
  {
    return this->Evaluate(std::nextafter(x, -std::numeric_limits<double>::infinity()),
      std::nextafter(x, std::numeric_limits<double>::infinity()), 2);
  }

  // Scalar values of every colour, grey and opacity node, sorted, unique.
  std::vector<double> Nodes() const
  {
    std::vector<double> nodes;
    auto collect = [&nodes](int size, auto x)
    {
      for (int i = 0; i < size; ++i)
      {
        nodes.push_back(x(i));
      }
    };
    auto piecewise = [](vtkPiecewiseFunction* f)
    {
      return [f](int i)
      {
        double v[4];
        f->GetNodeValue(i, v);
        return v[0];
      };
    };
    collect(this->Opacity->GetSize(), piecewise(this->Opacity));
    if (this->Color)
    {
      collect(this->Color->GetSize(),
        [this](int i)
        {
          double v[6];
          this->Color->GetNodeValue(i, v);
          return v[0];
        });
    }
    else if (this->Gray)
    {
      collect(this->Gray->GetSize(), piecewise(this->Gray));
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
  }
};

// max_c |value_c - lerp(a_c, b_c, w)|
double DistanceToChord(const Sample& value, const Sample& a, const Sample& b, double w)
{
  double distance = 0.0;
  for (int c = 0; c < 4; ++c)
  {
    distance = std::max(distance, std::abs(value[c] - ((1.0 - w) * a[c] + w * b[c])));
  }
  return distance;
}

double MaxDifference(const Sample& a, const Sample& b)
{
  return DistanceToChord(a, b, b, 0.0);
}
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionControlPoints::Build(vtkVolumeProperty* property, int component)
{
  this->Values.clear();
  this->ColorAttenuation.clear();
  this->Truncated = false;
  if (!property || !property->GetScalarOpacity(component))
  {
    return false;
  }
  TransferFunctions tf;
  tf.Opacity = property->GetScalarOpacity(component);
  if (property->GetColorChannels(component) == 3)
  {
    tf.Color = property->GetRGBTransferFunction(component);
  }
  else
  {
    tf.Gray = property->GetGrayTransferFunction(component);
  }
  tf.SampleDensely();
  // The CIEDE2000 steps are followed to half a step.
  const double tolerance =
    tf.Dense.empty() ? this->Tolerance : std::max(this->Tolerance, 0.5 / 255);
  std::vector<double> nodes = tf.Nodes();
  if (nodes.empty())
  {
    nodes.push_back(0.0);
  }
  // A jump is located to this width; narrower, two points are one step.
  const double resolution = 1e-12 * std::max({ nodes.back() - nodes.front(),
                                      std::abs(nodes.front()), std::abs(nodes.back()) });

  std::vector<std::pair<double, Sample>> points;
  const size_t budget = static_cast<size_t>(this->MaximumNumberOfControlPoints);
  auto add = [&](double x, const Sample& s)
  {
    if (points.size() < budget)
    {
      points.emplace_back(x, s);
    }
    else
    {
      this->Truncated = true;
    }
  };
  // Bisect [x0, x1] (values a, b at its ends) until the chord is within
  // Tolerance of the function at seven interior points; adds interior points in
  // order. A jump inside is narrowed down to `resolution`.
  auto refine = [&](auto&& self, double x0, const Sample& a, double x1, const Sample& b) -> void
  {
    const std::vector<Sample> inside = tf.Evaluate(x0, x1, 9);
    double distance = 0.0;
    for (int k = 1; k < 8; ++k)
    {
      distance = std::max(distance, DistanceToChord(inside[k], a, b, k / 8.0));
    }
    if (distance <= tolerance || x1 - x0 <= resolution || points.size() >= budget)
    {
      this->Truncated = this->Truncated || (distance > tolerance && x1 - x0 > resolution);
      return;
    }
    const double xm = 0.5 * (x0 + x1);
    self(self, x0, a, xm, inside[4]);
    add(xm, inside[4]);
    self(self, xm, inside[4], x1, b);
  };

  // Each node as its value or, where the function jumps, as its left and
  // right limits (a limit taken a rounding step off the node is not exactly
  // the value there: beside a zero-opacity stretch it is not zero);
  // between nodes, the refined segment. Outside, constant extension of the
  // first and last points.
  std::vector<Sample> limits = tf.Limits(nodes[0]);
  for (size_t i = 0; i < nodes.size(); ++i)
  {
    const double x = nodes[i];
    if (MaxDifference(limits[0], limits[1]) > 0.5 * tolerance)
    {
      add(x, limits[0]);
      add(x, limits[1]);
    }
    else
    {
      add(x, tf.Evaluate(x, x, 2)[0]);
    }
    if (i + 1 < nodes.size())
    {
      const Sample start = points.back().second;
      limits = tf.Limits(nodes[i + 1]);
      refine(refine, x, start, nodes[i + 1], limits[0]);
    }
  }
  if (this->Truncated)
  {
    vtkWarningMacro(
      "The transfer function needs more than "
      << budget << " control points to stay within " << tolerance
      << " of VTK's evaluation; the rest of its scalar range is linearly interpolated.");
  }

  double unitDistance = property->GetScalarOpacityUnitDistance(component);
  if (!(unitDistance > 0.0))
  {
    vtkWarningMacro("ScalarOpacityUnitDistance " << unitDistance << " is not positive; using 1.");
    unitDistance = 1.0;
  }
  this->UnitDistance = unitDistance;
  for (const auto& p : points)
  {
    this->Values.push_back(p.first);
    this->ColorAttenuation.push_back(p.second[0]);
    this->ColorAttenuation.push_back(p.second[1]);
    this->ColorAttenuation.push_back(p.second[2]);
    this->ColorAttenuation.push_back(p.second[3] / unitDistance);
  }
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
std::vector<float> vtkTransferFunctionControlPoints::GetTexels(double shift) const
{
  // Interval k = -1 .. n - 1 at texels 3 (k + 1) .. 3 (k + 1) + 2:
  //   (r, g, b, tau) at s_k,  d(r, g, b, tau) / ds,  (s_k, s_k+1, a, b),
  // [a, b] the transparent run k lies in (tau = 0 on all of it; a > b if
  // tau is not zero on k),
  // so that on [s_k, s_k+1]  f(s) = f(s_k) + f'(s) (s - s_k). The slope is
  // taken over the ends as the shader has them (rounded to float), so f
  // reaches f(s_k+1) at the rounded s_k+1; zero where they round to one value.
  const size_t n = this->Values.size();
  std::vector<float> texels(12 * (n + 1), 0.0f);
  if (n == 0)
  {
    return texels;
  }
  const float infinity = 3.0e38f; // INFINITY of march_common_fs.glsl
  for (size_t interval = 0; interval <= n; ++interval)
  {
    const size_t lo = interval == 0 ? 0 : interval - 1; // k = interval - 1, clamped
    const size_t hi = interval == n ? n - 1 : interval;
    const float sLo = interval == 0 ? -infinity : static_cast<float>(this->Values[lo] - shift);
    const float sHi = interval == n ? infinity : static_cast<float>(this->Values[hi] - shift);
    const double width = interval == 0 || interval == n ? 0.0 : double(sHi) - double(sLo);
    float* t = &texels[12 * interval];
    for (int c = 0; c < 4; ++c)
    {
      const double a = this->ColorAttenuation[4 * lo + c];
      const double b = this->ColorAttenuation[4 * hi + c];
      t[c] = static_cast<float>(a);
      t[4 + c] = width > 0.0 ? static_cast<float>((b - a) / width) : 0.0f;
    }
    t[8] = sLo;
    t[9] = sHi;
    t[10] = infinity; // not transparent: an empty run, filled below
    t[11] = -infinity;
  }
  for (size_t first = 0; first <= n;)
  {
    size_t end = first;
    while (end <= n && this->IsTransparentInterval(static_cast<int>(end) - 1))
    {
      ++end;
    }
    for (size_t interval = first; interval < end; ++interval)
    {
      texels[12 * interval + 10] = texels[12 * first + 8];
      texels[12 * interval + 11] = texels[12 * (end - 1) + 9];
    }
    first = end == first ? first + 1 : end;
  }
  return texels;
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionControlPoints::IsTransparentInterval(int k) const
{
  const int n = static_cast<int>(this->Values.size());
  if (n == 0 || k < -1 || k >= n)
  {
    return false;
  }
  const int lo = std::max(k, 0);
  const int hi = std::min(k + 1, n - 1);
  return this->ColorAttenuation[4 * lo + 3] == 0.0 && this->ColorAttenuation[4 * hi + 3] == 0.0;
}

//------------------------------------------------------------------------------
void vtkTransferFunctionControlPoints::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumNumberOfControlPoints: " << this->MaximumNumberOfControlPoints << "\n";
  os << indent << "NumberOfControlPoints: " << this->GetNumberOfControlPoints() << "\n";
  os << indent << "Truncated: " << this->Truncated << "\n";
}
