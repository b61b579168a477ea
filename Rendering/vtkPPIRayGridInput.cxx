#include "vtkPPIRayGridInput.h"

#include "ppirayValidPointIds.h"

#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridAlgorithm.h"

#include <cmath>

namespace
{
// Whether every point coordinate is finite.
bool FiniteCoordinates(vtkPoints* points)
{
  if (!points)
  {
    return true;
  }
  vtkDataArray* data = points->GetData();
  const vtkIdType n = data->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!std::isfinite(data->GetComponent(i / 3, static_cast<int>(i % 3))))
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkPPIRayGridInput::vtkPPIRayGridInput() = default;

//------------------------------------------------------------------------------
vtkPPIRayGridInput::~vtkPPIRayGridInput() = default;

//------------------------------------------------------------------------------
vtkUnstructuredGridBase* vtkPPIRayGridInput::Rendered(vtkUnstructuredGridBase* input, int mode,
  vtkUnstructuredGridAlgorithm* convexifier, vtkObject* reporter)
{
  const bool convexify = mode == ppiray::NonConvexConvexify ||
                         (mode == ppiray::NonConvexAutomatic && this->Choice.Convexifies(input));
  this->LastMode = mode;
  this->LastRendered = convexify ? this->Convexified(input, convexifier, reporter) : input;
  this->LastChoice =
    this->LastRendered != input ? ppiray::NonConvexConvexify : ppiray::NonConvexPeel;
  return this->LastRendered;
}

//------------------------------------------------------------------------------
vtkUnstructuredGridBase* vtkPPIRayGridInput::Convexified(
  vtkUnstructuredGridBase* input, vtkUnstructuredGridAlgorithm* convexifier, vtkObject* reporter)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (!convexifier || !grid)
  {
    if (!this->ConvexifyWarned)
    {
      vtkWarningWithObjectMacro(
        reporter, << (convexifier ? "The input is not a vtkUnstructuredGrid"
                                  : "No Convexifier (e.g. vtkUnstructuredGridConvexify)")
                  << ": NON_CONVEX_CONVEXIFY peels instead.");
      this->ConvexifyWarned = true;
    }
    return input;
  }
  if (this->ConvexifiedInput != input || input->GetMTime() > this->ConvexifiedTime.GetMTime() ||
      convexifier->GetMTime() > this->ConvexifiedTime.GetMTime())
  {
    convexifier->SetInputData(grid);
    convexifier->Update();
    this->Convexifier->ShallowCopy(convexifier->GetOutput());
    convexifier->SetInputData(nullptr);
    this->ConvexifiedInput = input;
    this->ConvexifiedTime.Modified();
  }
  return this->Convexifier;
}

//------------------------------------------------------------------------------
vtkUnstructuredGrid* vtkPPIRayGridInput::Validated(
  vtkUnstructuredGridBase* input, vtkObject* reporter)
{
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (!grid)
  {
    this->Copy->DeepCopy(input);
    grid = this->Copy;
  }
  if (!FiniteCoordinates(grid->GetPoints()))
  {
    vtkErrorWithObjectMacro(
      reporter, "The input has infinite or NaN point coordinates; nothing is rendered.");
    return nullptr;
  }
  const ppiray::ExtraPointIds extra = ppiray::CellsWithExtraPointIds(grid);
  if (extra.Cells > 0)
  {
    vtkWarningWithObjectMacro(reporter, << extra.Cells
                                        << " cells list more point ids than their type has (a "
                                        << vtkCellTypes::GetClassNameFromTypeId(extra.FirstType)
                                        << " with " << extra.FirstIds << ", not " << extra.TypeIds
                                        << "): only the first are used, as in VTK. A cell "
                                           "with mid-edge nodes has its own type (a 20-node "
                                           "hexahedron is a VTK_QUADRATIC_HEXAHEDRON).");
  }
  vtkIdType invalidCells = 0;
  this->ValidCells = ppiray::EmptyCellsWithInvalidPointIds(grid, invalidCells);
  if (this->ValidCells)
  {
    vtkErrorWithObjectMacro(reporter, << invalidCells << " cells list point ids outside [0, "
                                      << grid->GetNumberOfPoints() << "): they are not rendered.");
    return this->ValidCells;
  }
  return grid;
}
