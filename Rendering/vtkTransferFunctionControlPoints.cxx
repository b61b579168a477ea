#include "vtkTransferFunctionControlPoints.h"

#include "vtkColorTransferFunction.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>

vtkStandardNewMacro(vtkTransferFunctionControlPoints);

namespace
{
using Sample = std::array<double, 4>; // r, g, b, opacity

struct TransferFunctions
{
  vtkColorTransferFunction* Color = nullptr;
  vtkPiecewiseFunction* Gray = nullptr;
  vtkPiecewiseFunction* Opacity = nullptr;

  bool ColorClampedOff(double x, int side) const
  {
    double range[2];
    if (this->Color)
    {
      if (this->Color->GetClamping() || this->Color->GetSize() == 0)
      {
        return false;
      }
      this->Color->GetRange(range);
    }
    else
    {
      if (!this->Gray || this->Gray->GetClamping() || this->Gray->GetSize() == 0)
      {
        return false;
      }
      this->Gray->GetRange(range);
    }
    return (side < 0 && x <= range[0]) || (side > 0 && x >= range[1]);
  }

  bool OpacityClampedOff(double x, int side) const
  {
    if (this->Opacity->GetClamping() || this->Opacity->GetSize() == 0)
    {
      return false;
    }
    const double* range = this->Opacity->GetRange();
    return (side < 0 && x <= range[0]) || (side > 0 && x >= range[1]);
  }

  // The functions at x; side -1/+1 take the left/right limit, which differ
  // only at the ends of a function with clamping off (zero outside).
  Sample Evaluate(double x, int side = 0) const
  {
    Sample s = { 0.0, 0.0, 0.0, 0.0 };
    if (!this->ColorClampedOff(x, side))
    {
      if (this->Color)
      {
        this->Color->GetColor(x, s.data());
      }
      else if (this->Gray)
      {
        s[0] = s[1] = s[2] = this->Gray->GetValue(x);
      }
      else
      {
        s[0] = s[1] = s[2] = 1.0;
      }
    }
    if (!this->OpacityClampedOff(x, side))
    {
      s[3] = this->Opacity->GetValue(x);
    }
    return s;
  }

  // Whether the colour or opacity segment starting at or containing [x0, x1]
  // may be curved: a node with a non-default midpoint or sharpness.
  bool MayBeCurved(double x0, double x1) const
  {
    auto curved = [&](int size, auto node) {
      for (int i = 0; i + 1 < size; ++i)
      {
        double v[6];
        node(i, v);
        double next[6];
        node(i + 1, next);
        if (next[0] <= x0 || v[0] >= x1)
        {
          continue;
        }
        if (v[4] != 0.5 || v[5] != 0.0)
        {
          return true;
        }
      }
      return false;
    };
    bool result = curved(this->Opacity->GetSize(), [&](int i, double* v) {
      this->Opacity->GetNodeValue(i, v);
      v[4] = v[2];
      v[5] = v[3];
    });
    if (this->Color)
    {
      result = result || curved(this->Color->GetSize(), [&](int i, double* v) {
        this->Color->GetNodeValue(i, v);
      });
    }
    else if (this->Gray)
    {
      result = result || curved(this->Gray->GetSize(), [&](int i, double* v) {
        this->Gray->GetNodeValue(i, v);
        v[4] = v[2];
        v[5] = v[3];
      });
    }
    return result;
  }
};

double MaxDeviation(const Sample& value, const Sample& a, const Sample& b, double w)
{
  double deviation = 0.0;
  for (int c = 0; c < 4; ++c)
  {
    deviation = std::max(deviation, std::abs(value[c] - ((1.0 - w) * a[c] + w * b[c])));
  }
  return deviation;
}
}

//------------------------------------------------------------------------------
bool vtkTransferFunctionControlPoints::Build(vtkVolumeProperty* property, int component)
{
  this->Values.clear();
  this->ColorAttenuation.clear();
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

  // Union of the nodes.
  std::vector<double> nodes;
  for (int i = 0; i < tf.Opacity->GetSize(); ++i)
  {
    double v[4];
    tf.Opacity->GetNodeValue(i, v);
    nodes.push_back(v[0]);
  }
  if (tf.Color)
  {
    for (int i = 0; i < tf.Color->GetSize(); ++i)
    {
      double v[6];
      tf.Color->GetNodeValue(i, v);
      nodes.push_back(v[0]);
    }
  }
  else if (tf.Gray)
  {
    for (int i = 0; i < tf.Gray->GetSize(); ++i)
    {
      double v[4];
      tf.Gray->GetNodeValue(i, v);
      nodes.push_back(v[0]);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (nodes.empty())
  {
    nodes.push_back(0.0);
  }

  // Control points: nodes, then bisection of curved segments.
  std::vector<std::pair<double, Sample>> points;
  auto add = [&](double x, const Sample& s) { points.emplace_back(x, s); };
  const size_t budget = static_cast<size_t>(this->MaximumNumberOfControlPoints);
  // Refine [x0, x1] (values a, b) until the midpoint and quarter points are
  // within Tolerance of the chord; adds the interior points in order.
  auto refine = [&](auto&& self, double x0, const Sample& a, double x1, const Sample& b,
                  int depth) -> void {
    const double xm = 0.5 * (x0 + x1);
    const Sample m = tf.Evaluate(xm);
    const double deviation = std::max({ MaxDeviation(m, a, b, 0.5),
      MaxDeviation(tf.Evaluate(0.5 * (x0 + xm)), a, b, 0.25),
      MaxDeviation(tf.Evaluate(0.5 * (xm + x1)), a, b, 0.75) });
    if (deviation <= this->Tolerance || depth >= 24 || points.size() + 2 > budget)
    {
      return;
    }
    self(self, x0, a, xm, m, depth + 1);
    add(xm, m);
    self(self, xm, m, x1, b, depth + 1);
  };

  for (size_t i = 0; i < nodes.size(); ++i)
  {
    const double x = nodes[i];
    const Sample left = tf.Evaluate(x, -1);
    const Sample right = tf.Evaluate(x, +1);
    add(x, left);
    if (left != right)
    {
      add(x, right);
    }
    if (i + 1 < nodes.size() && tf.MayBeCurved(x, nodes[i + 1]))
    {
      refine(refine, x, right, nodes[i + 1], tf.Evaluate(nodes[i + 1], -1), 0);
    }
  }
  if (points.size() > budget)
  {
    vtkWarningMacro("Transfer function needs more than " << budget
                                                         << " control points; truncated.");
    points.resize(budget);
  }

  double unitDistance = property->GetScalarOpacityUnitDistance(component);
  if (!(unitDistance > 0.0))
  {
    vtkWarningMacro("ScalarOpacityUnitDistance " << unitDistance << " is not positive; using 1.");
    unitDistance = 1.0;
  }
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
std::vector<float> vtkTransferFunctionControlPoints::GetTexels() const
{
  std::vector<float> texels(8 * this->Values.size(), 0.0f);
  for (size_t i = 0; i < this->Values.size(); ++i)
  {
    texels[8 * i + 0] = static_cast<float>(this->Values[i]);
    texels[8 * i + 1] = static_cast<float>(this->ColorAttenuation[4 * i + 3]);
    texels[8 * i + 4] = static_cast<float>(this->ColorAttenuation[4 * i + 0]);
    texels[8 * i + 5] = static_cast<float>(this->ColorAttenuation[4 * i + 1]);
    texels[8 * i + 6] = static_cast<float>(this->ColorAttenuation[4 * i + 2]);
  }
  return texels;
}

//------------------------------------------------------------------------------
void vtkTransferFunctionControlPoints::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumNumberOfControlPoints: " << this->MaximumNumberOfControlPoints << "\n";
  os << indent << "NumberOfControlPoints: " << this->GetNumberOfControlPoints() << "\n";
}
