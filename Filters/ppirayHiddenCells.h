/**
 * @file   ppirayHiddenCells.h
 * @brief  cells the grid's ghost array marks hidden
 *
 * vtkDataSetAttributes::HIDDENCELL in the cell ghost array ("vtkGhostType")
 * is VTK's flag for cells that belong to a grid but are never shown:
 * blanked cells, and the imaginary cells of a convexified grid
 * (vtkUnstructuredGridConvexify). The mapper traverses them and renders them
 * empty.
 */
#ifndef ppirayHiddenCells_h
#define ppirayHiddenCells_h

#include "vtkDataSetAttributes.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <vector>

namespace ppiray
{
/// 1 for each of `cellIds` (cells of `grid`) marked hidden, else 0.
inline std::vector<unsigned char> HiddenCells(
  vtkUnstructuredGrid* grid, const std::vector<vtkIdType>& cellIds)
{
  std::vector<unsigned char> hidden(cellIds.size(), 0);
  vtkUnsignedCharArray* ghosts = grid->GetCellGhostArray();
  if (!ghosts)
  {
    return hidden;
  }
  for (size_t i = 0; i < cellIds.size(); ++i)
  {
    const vtkIdType c = cellIds[i];
    hidden[i] =
      c < ghosts->GetNumberOfValues() && (ghosts->GetValue(c) & vtkDataSetAttributes::HIDDENCELL)
        ? 1
        : 0;
  }
  return hidden;
}
}

#endif
