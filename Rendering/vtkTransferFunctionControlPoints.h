/**
 * @class   vtkTransferFunctionControlPoints
 * @brief   a volume property's transfer function as piecewise-linear control points
 *
 * The ray integral is exact per piece only where colour and attenuation are
 * linear in the scalar (Moreland & Angel 2004; Espinha & Celes 2005, Sec. 3.2),
 * so the transfer function is turned into control points (s_i, rgb_i, tau_i)
 * with linear interpolation between them and constant extension outside.
 * The function is the one VTK's volume mappers render: colour from
 * vtkColorTransferFunction::GetTable (every colour space, log scale, clamping;
 * a vtkDiscretizableColorTransferFunction continuous, as in
 * vtkOpenGLVolumeRGBTable), opacity from vtkPiecewiseFunction::GetValue.
 * - every colour and opacity node is a control point, taken twice (its left
 *   and right limits) where the function jumps there: repeated nodes, the
 *   ends of a function with clamping off, the Step colour space;
 * - each segment between nodes is bisected until the chord is within
 *   Tolerance of VTK's evaluation at seven interior points of every piece
 *   (colour in [0, 1], opacity in [0, 1]); a jump inside a segment (sharpness
 *   1) is narrowed down to 1e-12 of the scalar range, a step in single
 *   precision;
 * - at most MaximumNumberOfControlPoints, with a warning past that.
 * Attenuation follows VTK's unstructured mappers: tau = opacity / unit
 * distance, emission = colour * tau.
 */
#ifndef vtkTransferFunctionControlPoints_h
#define vtkTransferFunctionControlPoints_h

#include "ppirayRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <vector> // for std::vector

class vtkVolumeProperty;

class PPIRAYRENDERING_EXPORT vtkTransferFunctionControlPoints : public vtkObject
{
public:
  static vtkTransferFunctionControlPoints* New();
  vtkTypeMacro(vtkTransferFunctionControlPoints, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Largest deviation of the piecewise-linear interpolant from the transfer
   * function (default 0.1/255 of the colour and opacity range [0, 1]).
   */
  vtkSetClampMacro(Tolerance, double, 1e-6, 0.1);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Upper bound on the number of control points (default 4096).
   */
  vtkSetClampMacro(MaximumNumberOfControlPoints, int, 2, 1 << 20);
  vtkGetMacro(MaximumNumberOfControlPoints, int);
  ///@}

  /**
   * Sample `property`'s colour (RGB or gray) and scalar opacity functions of
   * `component`. Returns false if it has no usable function.
   */
  bool Build(vtkVolumeProperty* property, int component = 0);

  /** Number of control points. */
  int GetNumberOfControlPoints() const { return static_cast<int>(this->Values.size()); }

  /** Scalar value of each control point, non-decreasing. */
  const std::vector<double>& GetValues() const { return this->Values; }

  /** (r, g, b, tau) of each control point, tau in 1 / world units. */
  const std::vector<double>& GetColorAttenuation() const { return this->ColorAttenuation; }

  /**
   * The unit distance tau was divided by: the property's
   * ScalarOpacityUnitDistance, or 1 where that is not positive (warned).
   */
  double GetUnitDistance() const { return this->UnitDistance; }

  /**
   * Whether the last Build() stopped at MaximumNumberOfControlPoints before
   * reaching Tolerance.
   */
  bool GetTruncated() const { return this->Truncated; }

  /**
   * The layout the march shader reads (transfer_function_fs.glsl): three
   * RGBA32F texels per control interval k = -1 .. n - 1 (below the first
   * point, between points, from the last point on): (r, g, b, tau) at its
   * low end, their derivative in s, and (s_k - shift, s_k+1 - shift, a, b)
   * with -+3e38 past the first and last point; the scalar stored relative to
   * `shift` as the field is. Constant outside the points and across a jump.
   * [a, b] is the transparent run k belongs to: the span of the longest chain
   * of consecutive transparent intervals containing k (IsTransparentInterval),
   * so that a segment whose scalar stays in it contributes nothing and is not
   * integrated; a = 3e38, b = -3e38 (empty) where k is not transparent.
   */
  std::vector<float> GetTexels(double shift = 0.0) const;

  /**
   * Whether tau is zero on all of control interval k (-1 .. n - 1): zero at
   * both its ends (tau is linear between them, constant outside the points).
   */
  bool IsTransparentInterval(int k) const;

protected:
  vtkTransferFunctionControlPoints() = default;
  ~vtkTransferFunctionControlPoints() override = default;

  double Tolerance = 0.1 / 255.0;
  int MaximumNumberOfControlPoints = 4096;
  bool Truncated = false;
  double UnitDistance = 1.0;
  std::vector<double> Values;
  std::vector<double> ColorAttenuation;

private:
  vtkTransferFunctionControlPoints(const vtkTransferFunctionControlPoints&) = delete;
  void operator=(const vtkTransferFunctionControlPoints&) = delete;
};

#endif
