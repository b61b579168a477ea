#include "ppirayReferenceCells.h"

#include "ppirayConformingTetrahedra.h"
#include "vtkCellType.h"
#include "vtkDataSetAttributes.h"
#include "vtkMatrix4x4.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>

namespace ppiray
{
namespace reference
{
//------------------------------------------------------------------------------
const vtkIdType* ReferenceCells::ItemPoints(vtkIdType t, vtkIdType& n) const
{
  const vtkIdType tets = this->NumberOfTetrahedra();
  if (t < tets)
  {
    n = 4;
    return this->Tetrahedra.data() + 4 * t;
  }
  n = this->GeneralOffsets[t - tets + 1] - this->GeneralOffsets[t - tets];
  return this->GeneralPoints.data() + this->GeneralOffsets[t - tets];
}

//------------------------------------------------------------------------------
bool IsGeneralCell(int type)
{
  switch (type)
  {
    case VTK_HEXAHEDRON:
    case VTK_VOXEL:
    case VTK_WEDGE:
    case VTK_PYRAMID:
    case VTK_POLYHEDRON:
    case VTK_QUADRATIC_TETRA:
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_PYRAMID:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON:
    case VTK_LAGRANGE_WEDGE:
    case VTK_BEZIER_TETRAHEDRON:
    case VTK_BEZIER_HEXAHEDRON:
    case VTK_BEZIER_WEDGE:
      return true;
    default:
      return false;
  }
}

//------------------------------------------------------------------------------
ReferenceCells CollectCells(vtkUnstructuredGrid* grid)
{
  ReferenceCells cells;
  std::vector<vtkIdType> unsupported;
  ppiray::ExtractTetrahedra(grid, cells.Tetrahedra, cells.TetrahedronCell, unsupported);
  // Cells the ghost array marks HIDDENCELL (blanked, or imaginary cells of a
  // convexified grid) contribute nothing: left out.
  vtkUnsignedCharArray* ghosts = grid->GetCellGhostArray();
  auto hidden = [ghosts](vtkIdType c)
  { return ghosts && (ghosts->GetValue(c) & vtkDataSetAttributes::HIDDENCELL) != 0; };
  if (ghosts)
  {
    size_t kept = 0;
    for (size_t t = 0; t < cells.TetrahedronCell.size(); ++t)
    {
      if (!hidden(cells.TetrahedronCell[t]))
      {
        std::copy_n(cells.Tetrahedra.begin() + 4 * t, 4, cells.Tetrahedra.begin() + 4 * kept);
        cells.TetrahedronCell[kept++] = cells.TetrahedronCell[t];
      }
    }
    cells.Tetrahedra.resize(4 * kept);
    cells.TetrahedronCell.resize(kept);
  }
  // Every other 3D cell VTK interpolates (hexahedra, voxels, wedges,
  // pyramids, polyhedra, and the quadratic and higher-order cells, with all
  // their nodes) takes the general path; their points in CSR form.
  if (!unsupported.empty())
  {
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      const int type = grid->GetCellType(c);
      if (type == VTK_TETRA || hidden(c))
      {
        continue;
      }
      if (!IsGeneralCell(type))
      {
        cells.Skipped += type != VTK_EMPTY_CELL ? 1 : 0; // an empty cell holds nothing
        continue;
      }
      vtkIdType npts;
      const vtkIdType* pts;
      grid->GetCellPoints(c, npts, pts);
      cells.General.push_back(c);
      cells.GeneralPoints.insert(cells.GeneralPoints.end(), pts, pts + npts);
      cells.GeneralOffsets.push_back(static_cast<vtkIdType>(cells.GeneralPoints.size()));
    }
  }
  return cells;
}

//------------------------------------------------------------------------------
void ScreenTiles::Build(vtkUnstructuredGrid* grid, const ReferenceCells& cells,
  vtkMatrix4x4* worldToClip, int width, int height)
{
  // Project the points: pixel coordinates (pixel i's centre at i), or flag
  // those at or behind the eye plane.
  const vtkIdType numberOfPoints = grid->GetNumberOfPoints();
  std::vector<double> pixel(2 * numberOfPoints);
  std::vector<unsigned char> behind(numberOfPoints, 0);
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    double x[4] = { 0, 0, 0, 1 };
    grid->GetPoint(p, x);
    double clip[4];
    worldToClip->MultiplyPoint(x, clip);
    if (!(clip[3] > 1e-12))
    {
      behind[p] = 1;
      continue;
    }
    pixel[2 * p] = (clip[0] / clip[3] + 1.0) * 0.5 * width - 0.5;
    pixel[2 * p + 1] = (clip[1] / clip[3] + 1.0) * 0.5 * height - 0.5;
  }

  // Bin the items into tiles by their projected bounding box.
  const int tilesX = (width + Size - 1) / Size, tilesY = (height + Size - 1) / Size;
  this->TilesX = tilesX;
  this->TilesY = tilesY;
  // Tile range (x0, x1, y0, y1) of item t.
  auto tileRange = [&](vtkIdType t, int range[4])
  {
    double lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 };
    vtkIdType itemSize = 0;
    const vtkIdType* itemPoints = cells.ItemPoints(t, itemSize);
    for (vtkIdType v = 0; v < itemSize; ++v)
    {
      const vtkIdType p = itemPoints[v];
      if (behind[p])
      {
        range[0] = range[2] = 0;
        range[1] = tilesX - 1;
        range[3] = tilesY - 1;
        return;
      }
      for (int i = 0; i < 2; ++i)
      {
        lo[i] = std::min(lo[i], pixel[2 * p + i]);
        hi[i] = std::max(hi[i], pixel[2 * p + i]);
      }
    }
    const int limits[2] = { width - 1, height - 1 };
    for (int i = 0; i < 2; ++i)
    {
      const int a = static_cast<int>(std::floor(std::max(lo[i] - 1.0, -1.0)));
      const int b = static_cast<int>(std::ceil(std::min(hi[i] + 1.0, limits[i] + 1.0)));
      range[2 * i] = std::max(0, a) / Size;
      range[2 * i + 1] = std::min(limits[i], std::max(b, 0)) / Size;
      if (b < 0 || a > limits[i])
      {
        range[2 * i + 1] = range[2 * i] - 1; // off screen
      }
    }
  };
  this->GeneralBox.assign(cells.General.size(), {});
  for (size_t g = 0; g < cells.General.size(); ++g)
  {
    auto& box = this->GeneralBox[g];
    box = { 1e300, -1e300, 1e300, -1e300 };
    for (vtkIdType k = cells.GeneralOffsets[g]; k < cells.GeneralOffsets[g + 1]; ++k)
    {
      const vtkIdType p = cells.GeneralPoints[k];
      if (behind[p])
      {
        box = { -1e300, 1e300, -1e300, 1e300 };
        break;
      }
      for (int i = 0; i < 2; ++i)
      {
        box[2 * i] = std::min(box[2 * i], pixel[2 * p + i] - 1.0);
        box[2 * i + 1] = std::max(box[2 * i + 1], pixel[2 * p + i] + 1.0);
      }
    }
  }
  std::vector<vtkIdType>& tileOffsets = this->Offsets;
  tileOffsets.assign(static_cast<size_t>(tilesX) * tilesY + 1, 0);
  for (vtkIdType t = 0; t < cells.NumberOfItems(); ++t)
  {
    int r[4];
    tileRange(t, r);
    for (int ty = r[2]; ty <= r[3]; ++ty)
    {
      for (int tx = r[0]; tx <= r[1]; ++tx)
      {
        ++tileOffsets[static_cast<size_t>(ty) * tilesX + tx + 1];
      }
    }
  }
  for (size_t i = 1; i < tileOffsets.size(); ++i)
  {
    tileOffsets[i] += tileOffsets[i - 1];
  }
  std::vector<vtkIdType>& tileItems = this->Items;
  tileItems.assign(tileOffsets.back(), 0);
  {
    std::vector<vtkIdType> fill(tileOffsets.begin(), tileOffsets.end() - 1);
    for (vtkIdType t = 0; t < cells.NumberOfItems(); ++t)
    {
      int r[4];
      tileRange(t, r);
      for (int ty = r[2]; ty <= r[3]; ++ty)
      {
        for (int tx = r[0]; tx <= r[1]; ++tx)
        {
          tileItems[fill[static_cast<size_t>(ty) * tilesX + tx]++] = t;
        }
      }
    }
  }
}
}
}
