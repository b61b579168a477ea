/**
 * @class   vtkTransferFunctionControlPoints
 * @brief   a volume property's transfer function as piecewise-linear control points
 *
 * The ray integral is exact per piece only where colour and attenuation are
 * linear in the scalar (Moreland & Angel 2004; Espinha & Celes 2005, Sec. 3.2),
 * so the transfer function is turned into control points (s_i, rgb_i, tau_i)
 * with linear interpolation between them and constant extension outside:
 * - the union of the colour and scalar-opacity nodes;
 * - a segment whose nodes have a non-default midpoint or sharpness (curved)
 *   is bisected until the linear interpolant is within Tolerance of the
 *   function at every bisection midpoint (colour in [0, 1], opacity in [0, 1]),
 *   up to MaximumNumberOfControlPoints in total;
 * - a function with clamping off is zero outside its range: a step is two
 *   control points at the same scalar.
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
   * Largest deviation of the piecewise-linear interpolant from a curved
   * segment (default 1/1024 of the colour and opacity range [0, 1]).
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
   * Two RGBA32F texels per control point, (s, tau, 0, 0) then (r, g, b, 0):
   * the layout the march shader reads.
   */
  std::vector<float> GetTexels() const;

protected:
  vtkTransferFunctionControlPoints() = default;
  ~vtkTransferFunctionControlPoints() override = default;

  double Tolerance = 1.0 / 1024.0;
  int MaximumNumberOfControlPoints = 4096;
  std::vector<double> Values;
  std::vector<double> ColorAttenuation;

private:
  vtkTransferFunctionControlPoints(const vtkTransferFunctionControlPoints&) = delete;
  void operator=(const vtkTransferFunctionControlPoints&) = delete;
};

#endif
