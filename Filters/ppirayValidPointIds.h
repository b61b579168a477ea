/**
 * @file   ppirayValidPointIds.h
 * @brief  cells whose point ids lie outside the grid's points, made empty
 *
 * A cell listing a point id below 0 or at or past the number of points
 * cannot be drawn (nor read without going out of bounds). The mapper and
 * the reference renderer render the grid with every such cell turned into
 * an empty cell (VTK_EMPTY_CELL, no points), which the cell walks skip:
 * the other cells keep their ids, so cell data still lines up.
 */
#ifndef ppirayValidPointIds_h
#define ppirayValidPointIds_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkSmartPointer.h"     // for vtkSmartPointer
#include "vtkType.h"             // for vtkIdType

class vtkUnstructuredGrid;

namespace ppiray
{
/**
 * nullptr when every point id of every cell of `grid` lies in
 * [0, number of points); else a copy of `grid` (points, point and cell data
 * shared) with those cells empty, and their number in `invalidCells`.
 */
PPIRAYFILTERS_EXPORT vtkSmartPointer<vtkUnstructuredGrid> EmptyCellsWithInvalidPointIds(
  vtkUnstructuredGrid* grid, vtkIdType& invalidCells);

/** What CellsWithExtraPointIds() found: how many, and the first of them. */
struct ExtraPointIds
{
  vtkIdType Cells = 0;
  int FirstType = 0;      // its cell type
  vtkIdType FirstIds = 0; // the ids it lists
  vtkIdType TypeIds = 0;  // the ids its type has
};

/**
 * Cells of a linear type with a fixed number of points (a VTK_HEXAHEDRON's
 * 8) that list more point ids than that, e.g. a 20-node hexahedron written as a
 * VTK_HEXAHEDRON: VTK's cells, and so the mapper and the reference, use
 * their first ids only, and vtkDataSetTriangleFilter triangulates them from
 * parametric coordinates the type does not have (a tangled mesh).
 */
PPIRAYFILTERS_EXPORT ExtraPointIds CellsWithExtraPointIds(vtkUnstructuredGrid* grid);
}

#endif
