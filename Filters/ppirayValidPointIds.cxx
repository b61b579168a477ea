#include "ppirayValidPointIds.h"

#include "ppirayConformingTetrahedra.h"
#include "ppirayVTKCompatibility.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <map>
#include <vector>

namespace ppiray
{
//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> EmptyCellsWithInvalidPointIds(
  vtkUnstructuredGrid* grid, vtkIdType& invalidCells)
{
  invalidCells = 0;
  vtkCellArray* cells = grid ? grid->GetCells() : nullptr;
  if (!cells)
  {
    return nullptr;
  }
  const vtkIdType numberOfPoints = grid->GetNumberOfPoints();
  std::vector<bool> invalid(grid->GetNumberOfCells(), false);
  ForEachCell(grid,
    [&](vtkIdType cellId, int, vtkIdType npts, const vtkIdType* pts)
    {
      for (vtkIdType i = 0; i < npts && !invalid[cellId]; ++i)
      {
        invalid[cellId] = pts[i] < 0 || pts[i] >= numberOfPoints;
      }
      invalidCells += invalid[cellId] ? 1 : 0;
    });
  if (invalidCells == 0)
  {
    return nullptr;
  }
  vtkNew<vtkCellArray> kept;
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfValues(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    grid->GetCellPoints(c, npts, pts);
    kept->InsertNextCell(invalid[c] ? 0 : npts, pts);
    types->SetValue(c, invalid[c] ? VTK_EMPTY_CELL : grid->GetCellType(c));
  }
  // Polyhedra keep their faces; an emptied one has none.
  auto valid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  valid->ShallowCopy(grid);
  compat::SetCellsKeepingPolyhedra(valid, grid, types, kept, invalid);
  return valid;
}

//------------------------------------------------------------------------------
ExtraPointIds CellsWithExtraPointIds(vtkUnstructuredGrid* grid)
{
  // The linear cell types with a fixed number of points, and that number.
  static const std::map<int, vtkIdType> fixed = { { VTK_VERTEX, 1 }, { VTK_LINE, 2 },
    { VTK_TRIANGLE, 3 }, { VTK_PIXEL, 4 }, { VTK_QUAD, 4 }, { VTK_TETRA, 4 }, { VTK_VOXEL, 8 },
    { VTK_HEXAHEDRON, 8 }, { VTK_WEDGE, 6 }, { VTK_PYRAMID, 5 }, { VTK_PENTAGONAL_PRISM, 10 },
    { VTK_HEXAGONAL_PRISM, 12 } };
  ExtraPointIds extra;
  ForEachCell(grid,
    [&](vtkIdType, int type, vtkIdType npts, const vtkIdType*)
    {
      const auto found = fixed.find(type);
      if (found == fixed.end() || npts <= found->second)
      {
        return;
      }
      if (extra.Cells++ == 0)
      {
        extra.FirstType = type;
        extra.FirstIds = npts;
        extra.TypeIds = found->second;
      }
    });
  return extra;
}
}
