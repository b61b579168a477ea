/**
 * @file   ppirayReferenceCells.h
 * @brief  the cells the reference renderer integrates, and where they fall on the screen
 *
 * For vtkUnstructuredGridReferenceRenderer only. Items are the linear
 * tetrahedra followed by the general cells (hexahedra, voxels, wedges,
 * pyramids, polyhedra, and quadratic, Lagrange and Bezier cells with all
 * their nodes: integrated with VTK's own interpolation, IsGeneralCell());
 * other cells are counted and skipped. ScreenTiles bins the items into square tiles of
 * pixels by their projected bounding boxes (conservative: a cell with a
 * corner at or behind the eye plane covers every tile).
 */
#ifndef ppirayReferenceCells_h
#define ppirayReferenceCells_h

#include "vtkType.h" // for vtkIdType

#include <array>  // for std::array
#include <vector> // for std::vector

class vtkMatrix4x4;
class vtkUnstructuredGrid;

namespace ppiray
{
namespace reference
{
struct ReferenceCells
{
  std::vector<vtkIdType> Tetrahedra;      // 4 point ids each
  std::vector<vtkIdType> TetrahedronCell; // the grid cell of each
  std::vector<vtkIdType> General;         // grid cell ids of the general cells
  std::vector<vtkIdType> GeneralOffsets = { 0 };
  std::vector<vtkIdType> GeneralPoints; // their point ids, CSR by GeneralOffsets
  vtkIdType Skipped = 0;                // cells of other types

  vtkIdType NumberOfTetrahedra() const
  {
    return static_cast<vtkIdType>(this->TetrahedronCell.size());
  }
  vtkIdType NumberOfItems() const
  {
    return this->NumberOfTetrahedra() + static_cast<vtkIdType>(this->General.size());
  }
  /** Point ids of item t (tetrahedron t, or general cell t - NumberOfTetrahedra()). */
  const vtkIdType* ItemPoints(vtkIdType t, vtkIdType& n) const;
};

/** Whether cells of `type` take the general path. */
bool IsGeneralCell(int type);

/** The items of `grid`. */
ReferenceCells CollectCells(vtkUnstructuredGrid* grid);

struct ScreenTiles
{
  static constexpr int Size = 16; // pixels per tile side
  int TilesX = 0, TilesY = 0;
  std::vector<vtkIdType> Offsets; // items of tile i: Items[Offsets[i]] .. Items[Offsets[i + 1] - 1]
  std::vector<vtkIdType> Items;
  // Per general cell: its corners' pixel box (x0, x1, y0, y1) widened by a
  // pixel; a linear 3D cell lies in the convex hull of its corners (bilinear
  // faces included), so a ray outside the box misses the cell.
  std::vector<std::array<double, 4>> GeneralBox;

  /** Bins of `cells` of `grid` seen through `worldToClip` in a width x height image. */
  void Build(vtkUnstructuredGrid* grid, const ReferenceCells& cells, vtkMatrix4x4* worldToClip,
    int width, int height);
};
}
}

#endif
