/**
 * @class   vtkPPIRayScalarField
 * @brief   the scalar values a frame renders, chosen as VTK's volume mappers choose them
 *
 * The array (vtkAbstractMapper::GetScalars with the mapper's scalar mode and
 * array selection, point or cell data), of a multi-component array its
 * magnitude or one component, its range (NaN left out), and a shift: values
 * are stored relative to the range's centre when it lies far from zero
 * compared to its width (1e6 + O(1) keeps its digits in single precision),
 * as coordinates are relative to the bounds' centre. Internal to
 * PPIRay::Rendering.
 */
#ifndef vtkPPIRayScalarField_h
#define vtkPPIRayScalarField_h

#include "vtkNew.h"       // for vtkNew
#include "vtkTimeStamp.h" // for vtkTimeStamp

#include <string> // for std::string

class vtkDataArray;
class vtkDataSet;
class vtkDoubleArray;
class vtkObject;
class vtkShaderProgram;

class vtkPPIRayScalarField
{
public:
  vtkPPIRayScalarField();
  ~vtkPPIRayScalarField();

  /** Which scalars: vtkAbstractMapper's selection and the vector mode. */
  struct Selection
  {
    int ScalarMode;
    int ArrayAccessMode;
    int ArrayId;
    const char* ArrayName;
    bool Magnitude; // of a multi-component array, else Component
    int Component;
  };

  enum class Status
  {
    Unchanged,
    Changed,
    Failed // reported: no scalars, or infinite ones
  };
  /** Re-reads the scalars of `input` when the selection or the array changed. */
  Status Update(vtkDataSet* input, const Selection& selection, vtkObject* reporter);
  /** Forget the scalars: the next Update() reads them anew (the cells changed). */
  void Invalidate() { this->Array = nullptr; }

  /** The values to render (one component, minus GetShift()). */
  vtkDataArray* GetValues() { return this->Values; }
  bool IsCellData() const { return this->CellFlag == 1; }
  double GetShift() const { return this->Shift; }
  /** Range of the rendered values (before the shift). */
  const double* GetRange() const { return this->Range; }
  /**
   * The uniforms of the average-intensity and additive projections
   * (projection_fs.glsl): normalizedScalar, (a, b) with a v + b the value v
   * as stored (shifted) normalized to the range, (v + shift - min) /
   * (max - min), as vtkGPUVolumeRayCastMapper's projections see a scalar (1
   * for a constant field); averageRange, `averageRange` shifted as the
   * values are.
   */
  void BindProjection(vtkShaderProgram* program, const double averageRange[2]) const;
  /** When the values last changed. */
  vtkMTimeType GetMTime() const { return this->Time.GetMTime(); }

private:
  vtkPPIRayScalarField(const vtkPPIRayScalarField&) = delete;
  void operator=(const vtkPPIRayScalarField&) = delete;

  vtkDataArray* Array = nullptr; // what the values were read from
  int CellFlag = -1;
  int Component = -2; // -1: magnitude
  vtkTimeStamp Time;
  vtkDataArray* Values = nullptr; // Array itself, or Derived
  vtkNew<vtkDoubleArray> Derived;
  double Range[2] = { 0, 1 };
  double Shift = 0.0;
  // Fails with `message` as an error, reported once until the field is valid
  // again or the message changes (the mapper updates the field every frame).
  Status Fail(vtkObject* reporter, const std::string& message);
  std::string Reported; // the failure last reported
};

#endif
