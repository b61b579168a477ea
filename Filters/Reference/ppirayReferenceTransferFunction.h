/**
 * @file   ppirayReferenceTransferFunction.h
 * @brief  the reference renderer's own transfer function pieces
 *
 * For vtkUnstructuredGridReferenceRenderer only: built from VTK's evaluation
 * by its own rule, sharing no code with vtkTransferFunctionControlPoints (the
 * GPU path), so that each checks the other (Documentation/accuracy.md).
 */
#ifndef ppirayReferenceTransferFunction_h
#define ppirayReferenceTransferFunction_h

#include "vtkColorTransferFunction.h" // for vtkColorTransferFunction
#include "vtkPiecewiseFunction.h"     // for vtkPiecewiseFunction
#include "vtkVolumeProperty.h"        // for vtkVolumeProperty

#include <algorithm> // for std::upper_bound
#include <array>     // for std::array
#include <cmath>     // for std::lround
#include <vector>    // for std::vector

namespace ppiray
{
namespace reference
{
// The transfer function as VTK's volume mappers evaluate it (colour through
// vtkColorTransferFunction::GetTable: its colour space, scale and clamping, a
// vtkDiscretizableColorTransferFunction continuous), as linear pieces between
// Breaks: every colour and opacity node, and between nodes the points of a
// bisection that stops when the function is within Tolerance of linear at
// the quarter points. Each piece keeps the function's one-sided limits at its
// ends, so jumps (repeated nodes, Step colour space, clamping off) are exact.
struct TransferFunction
{
  using RGBTau = std::array<double, 4>;
  vtkColorTransferFunction* Color = nullptr;
  vtkPiecewiseFunction* Gray = nullptr;
  vtkPiecewiseFunction* Opacity = nullptr;
  double UnitDistance = 1.0;
  std::vector<double> Breaks;
  std::vector<RGBTau> Start, End;                        // piece k: from Breaks[k] to Breaks[k + 1]
  RGBTau Below = { 0, 0, 0, 0 }, Above = { 0, 0, 0, 0 }; // outside the breaks
  // The CIEDE2000 colour space costs a colour-path search per GetTable call
  // and steps its colours by about 1/255: sampled once over its nodes (2^18
  // samples), read as nearest sample.
  std::vector<double> Stepped;
  double SteppedRange[2] = { 0, 0 };

  // (r, g, b, tau) at n >= 2 evenly spaced scalars from x0 to x1 (one
  // GetTable call: CIEDE2000 builds its colour path per call).
  std::vector<RGBTau> Sample(double x0, double x1, int n) const
  {
    std::vector<double> rgb(3 * n, 1.0);
    if (this->Color && this->Stepped.empty() && this->Color->GetScale() == VTK_CTF_LINEAR)
    {
      this->Color->GetTable(x0, x1, n, rgb.data());
    }
    else if (this->Color) // CIEDE2000, or a log scale (GetTable spaces samples in log10)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x = x0 + (x1 - x0) * i / (n - 1);
        const double u =
          (x - this->SteppedRange[0]) / (this->SteppedRange[1] - this->SteppedRange[0]);
        if (u >= 0.0 && u <= 1.0 && !this->Stepped.empty())
        {
          // nearest sample: the colours are steps
          const size_t k = static_cast<size_t>(std::lround(u * (this->Stepped.size() / 3 - 1)));
          std::copy_n(this->Stepped.data() + 3 * k, 3, rgb.data() + 3 * i);
        }
        else
        {
          this->Color->GetTable(x, x, 1, rgb.data() + 3 * i);
        }
      }
    }
    std::vector<RGBTau> v(n);
    for (int i = 0; i < n; ++i)
    {
      const double x = x0 + (x1 - x0) * i / (n - 1);
      for (int c = 0; c < 3; ++c)
      {
        v[i][c] = this->Color ? rgb[3 * i + c] : this->Gray ? this->Gray->GetValue(x) : 1.0;
      }
      v[i][3] = this->Opacity->GetValue(x) / this->UnitDistance;
    }
    return v;
  }

  void Build(vtkVolumeProperty* property, double tolerance)
  {
    this->Opacity = property->GetScalarOpacity(0);
    if (property->GetColorChannels(0) == 3)
    {
      this->Color = property->GetRGBTransferFunction(0);
    }
    else
    {
      this->Gray = property->GetGrayTransferFunction(0);
    }
    this->UnitDistance = property->GetScalarOpacityUnitDistance(0);
    if (!(this->UnitDistance > 0))
    {
      this->UnitDistance = 1.0;
    }
    if (this->Color && this->Color->GetColorSpace() == VTK_CTF_LAB_CIEDE2000 &&
        this->Color->GetScale() == VTK_CTF_LINEAR && this->Color->GetSize() > 1)
    {
      this->Color->GetRange(this->SteppedRange);
      this->Stepped.resize(3 << 18);
      this->Color->GetTable(
        this->SteppedRange[0], this->SteppedRange[1], 1 << 18, this->Stepped.data());
      tolerance = std::max(tolerance, 0.25 / 255);
    }
    std::vector<double> nodes;
    auto collect = [&](int size, auto x)
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
    if (nodes.empty())
    {
      nodes.push_back(0.0);
    }
    const double width = std::max(
      { nodes.back() - nodes.front(), std::abs(nodes.front()), std::abs(nodes.back()), 1e-300 });
    const double inside = 1e-13 * width; // one-sided limits are taken this far in
    this->Below = this->Sample(nodes.front() - inside, nodes.front() - inside, 2)[0];
    this->Above = this->Sample(nodes.back() + inside, nodes.back() + inside, 2)[0];
    // Piece [x0, x1] split until linear within tolerance at its quarter points.
    auto bisect = [&](auto&& self, double x0, double x1) -> void
    {
      const std::vector<RGBTau> v = this->Sample(x0, x1, 5);
      bool linear = true;
      for (int q = 1; q < 4; ++q)
      {
        for (int c = 0; c < 4; ++c)
        {
          const double scale = c == 3 ? 1.0 / this->UnitDistance : 1.0;
          linear = linear && std::abs(v[q][c] - (v[0][c] + (v[4][c] - v[0][c]) * q / 4.0)) <=
                               tolerance * scale;
        }
      }
      if (linear || x1 - x0 <= 4 * inside)
      {
        this->Breaks.push_back(x0);
        this->Start.push_back(v[0]);
        this->End.push_back(v[4]);
        return;
      }
      const double xm = 0.5 * (x0 + x1);
      self(self, x0, xm);
      self(self, xm, x1);
    };
    for (size_t i = 0; i + 1 < nodes.size(); ++i)
    {
      bisect(bisect, nodes[i] + inside, nodes[i + 1] - inside);
    }
    // Pieces were recorded by their start just inside a node; move the first
    // piece of each node segment back onto the node.
    for (double& x : this->Breaks)
    {
      const auto node = std::lower_bound(nodes.begin(), nodes.end(), x - 2 * inside);
      if (node != nodes.end() && std::abs(*node - x) <= 2 * inside)
      {
        x = *node;
      }
    }
    this->Breaks.push_back(nodes.back());
  }

  // The piece holding scalar s (-1: below the first break, Breaks.size() - 1:
  // above the last).
  int Piece(double s) const
  {
    return static_cast<int>(
             std::upper_bound(this->Breaks.begin(), this->Breaks.end(), s) - this->Breaks.begin()) -
           1;
  }

  // rgb and tau at s, on piece k (the linear interpolant of its limits).
  void Evaluate(double s, int k, double rgb[3], double& tau) const
  {
    RGBTau v;
    if (k < 0)
    {
      v = this->Below;
    }
    else if (k >= static_cast<int>(this->Start.size()))
    {
      v = this->Above;
    }
    else
    {
      const double x0 = this->Breaks[k], x1 = this->Breaks[k + 1];
      const double w = x1 > x0 ? std::min(1.0, std::max(0.0, (s - x0) / (x1 - x0))) : 0.0;
      for (int c = 0; c < 4; ++c)
      {
        v[c] = (1 - w) * this->Start[k][c] + w * this->End[k][c];
      }
    }
    rgb[0] = v[0];
    rgb[1] = v[1];
    rgb[2] = v[2];
    tau = v[3];
  }
};
}
}

#endif
