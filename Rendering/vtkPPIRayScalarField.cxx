#include "vtkPPIRayScalarField.h"

#include "vtkAbstractMapper.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkObject.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>
#include <string>

//------------------------------------------------------------------------------
vtkPPIRayScalarField::vtkPPIRayScalarField() = default;

//------------------------------------------------------------------------------
vtkPPIRayScalarField::~vtkPPIRayScalarField() = default;

//------------------------------------------------------------------------------
vtkPPIRayScalarField::Status vtkPPIRayScalarField::Update(
  vtkDataSet* input, const Selection& selection, vtkObject* reporter)
{
  int cellFlag = 0;
  vtkDataArray* scalars =
    vtkDataArray::SafeDownCast(vtkAbstractMapper::GetScalars(input, selection.ScalarMode,
      selection.ArrayAccessMode, selection.ArrayId, selection.ArrayName, cellFlag));
  if (!scalars)
  {
    return this->Fail(
      reporter, std::string("No scalars to render: the input has no ") +
                  (selection.ArrayName && *selection.ArrayName ? selection.ArrayName : "active") +
                  " point or cell scalar array.");
  }
  // Read per cell (cellFlag 1), else per point.
  const vtkIdType needed = cellFlag == 1 ? input->GetNumberOfCells() : input->GetNumberOfPoints();
  const std::string name = scalars->GetName() ? scalars->GetName() : "";
  if (scalars->GetNumberOfTuples() < needed)
  {
    return this->Fail(reporter, "Scalar array " + name + " has " +
                                  std::to_string(scalars->GetNumberOfTuples()) + " values for " +
                                  std::to_string(needed) + (cellFlag == 1 ? " cells" : " points") +
                                  "; nothing is rendered.");
  }
  const int components = scalars->GetNumberOfComponents();
  const int component = components > 1 && selection.Magnitude
                          ? -1
                          : std::min(std::max(selection.Component, 0), components - 1);
  if (this->Array == scalars && this->CellFlag == cellFlag && this->Component == component &&
      scalars->GetMTime() <= this->Time.GetMTime())
  {
    this->Reported.clear();
    return Status::Unchanged;
  }
  if (components > 1 && component >= 0 && component != selection.Component)
  {
    vtkWarningWithObjectMacro(reporter,
      "VectorComponent " << selection.Component << " is not a component of "
                         << (scalars->GetName() ? scalars->GetName() : "the array") << " ("
                         << components << " components); using " << component << ".");
  }
  this->Array = scalars;
  this->CellFlag = cellFlag;
  this->Component = component;
  this->Time.Modified();
  double range[2];
  scalars->GetRange(range, component); // NaN left out; component -1: magnitude
  if (std::isinf(range[0]) || std::isinf(range[1]))
  {
    return this->Fail(
      reporter, "Scalar array " + name + " has infinite values; nothing is rendered.");
  }
  if (!(range[0] <= range[1]))
  {
    range[0] = range[1] = 0.0; // every value NaN: every cell empty
  }
  this->Range[0] = range[0];
  this->Range[1] = range[1];
  const double centre = 0.5 * (range[0] + range[1]);
  this->Shift = std::abs(centre) > range[1] - range[0] ? centre : 0.0;
  this->Values = scalars;
  if (components > 1 || this->Shift != 0.0)
  {
    const vtkIdType n = scalars->GetNumberOfTuples();
    this->Derived->SetNumberOfComponents(1);
    this->Derived->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double value = 0.0;
      if (component < 0)
      {
        for (int c = 0; c < components; ++c)
        {
          const double v = scalars->GetComponent(i, c);
          value += v * v;
        }
        value = std::sqrt(value);
      }
      else
      {
        value = scalars->GetComponent(i, component);
      }
      this->Derived->SetValue(i, value - this->Shift);
    }
    this->Values = this->Derived;
  }
  this->Reported.clear();
  return Status::Changed;
}

//------------------------------------------------------------------------------
vtkPPIRayScalarField::Status vtkPPIRayScalarField::Fail(
  vtkObject* reporter, const std::string& message)
{
  if (message != this->Reported)
  {
    vtkErrorWithObjectMacro(reporter, << message.c_str());
  }
  this->Reported = message;
  this->Array = nullptr;
  return Status::Failed;
}

//------------------------------------------------------------------------------
void vtkPPIRayScalarField::BindProjection(
  vtkShaderProgram* program, const double averageRange[2]) const
{
  const double width = this->Range[1] - this->Range[0];
  const float normalizing[2] = { static_cast<float>(width > 0 ? 1.0 / width : 0.0),
    static_cast<float>(width > 0 ? (this->Shift - this->Range[0]) / width : 1.0) };
  program->SetUniform2f("normalizedScalar", normalizing);
  const double limit = VTK_FLOAT_MAX;
  float range[2];
  for (int i = 0; i < 2; ++i)
  {
    range[i] = static_cast<float>(std::max(-limit, std::min(limit, averageRange[i] - this->Shift)));
  }
  program->SetUniform2f("averageRange", range);
}
