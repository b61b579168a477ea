#include "vtkConformingTetrahedra.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>

namespace
{
// Faces of the linear cells in VTK's point order (orientation does not matter:
// the consumers orient each tetrahedron by the sign of its volume). -1 ends a
// triangle.
using Face = std::array<int, 4>;
const Face HexahedronFaces[] = { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 },
  { 3, 7, 6, 2 }, { 0, 3, 2, 1 }, { 4, 5, 6, 7 } };
const Face WedgeFaces[] = { { 0, 1, 2, -1 }, { 3, 5, 4, -1 }, { 0, 3, 4, 1 }, { 1, 4, 5, 2 },
  { 2, 5, 3, 0 } };
const Face PyramidFaces[] = { { 0, 3, 2, 1 }, { 0, 1, 4, -1 }, { 1, 2, 4, -1 }, { 2, 3, 4, -1 },
  { 3, 0, 4, -1 } };
}

namespace ppiray
{
LinearShape LinearShapeOf(int type)
{
  switch (type)
  {
    case VTK_TETRA:
      return { VTK_TETRA, 4, false };
    case VTK_HEXAHEDRON:
    case VTK_VOXEL:
      return { VTK_HEXAHEDRON, 8, false };
    case VTK_WEDGE:
      return { VTK_WEDGE, 6, false };
    case VTK_PYRAMID:
      return { VTK_PYRAMID, 5, false };
    case VTK_QUADRATIC_TETRA:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_BEZIER_TETRAHEDRON:
      return { VTK_TETRA, 4, true };
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON:
    case VTK_BEZIER_HEXAHEDRON:
      return { VTK_HEXAHEDRON, 8, true };
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_LAGRANGE_WEDGE:
    case VTK_BEZIER_WEDGE:
      return { VTK_WEDGE, 6, true };
    case VTK_QUADRATIC_PYRAMID:
      return { VTK_PYRAMID, 5, true };
    default:
      return { 0, 0, false };
  }
}
}

namespace
{

// Tetrahedra (apex, triangle) over the faces of `faces` that miss the apex;
// a quadrilateral splits along the diagonal through its smallest point id.
template <size_t N>
void AppendCone(const Face (&faces)[N], const vtkIdType* pts, int apex,
  std::vector<vtkIdType>& tets)
{
  for (const Face& face : faces)
  {
    const int n = face[3] < 0 ? 3 : 4;
    if (std::find(face.begin(), face.begin() + n, apex) != face.begin() + n)
    {
      continue;
    }
    const vtkIdType a = pts[face[0]], b = pts[face[1]], c = pts[face[2]];
    if (n == 3)
    {
      tets.insert(tets.end(), { pts[apex], a, b, c });
      continue;
    }
    const vtkIdType d = pts[face[3]];
    if (ppiray::SplitsAlongFirstDiagonal(a, b, c, d))
    {
      tets.insert(tets.end(), { pts[apex], a, b, c, pts[apex], a, c, d });
    }
    else
    {
      tets.insert(tets.end(), { pts[apex], b, c, d, pts[apex], b, d, a });
    }
  }
}

int SmallestPoint(const vtkIdType* pts, int n)
{
  return static_cast<int>(std::min_element(pts, pts + n) - pts);
}
}

namespace ppiray
{
//------------------------------------------------------------------------------
vtkIdType TetrahedralSplit::GetNumberOfUnsupportedCells() const
{
  vtkIdType count = 0;
  for (size_t i = 1; i < this->Unsupported.size(); i += 2)
  {
    count += this->Unsupported[i];
  }
  return count;
}

//------------------------------------------------------------------------------
int TetrahedraPerCell(int linearCellType)
{
  switch (linearCellType)
  {
    case VTK_TETRA:
      return 1;
    case VTK_HEXAHEDRON:
    case VTK_VOXEL:
      return 6;
    case VTK_WEDGE:
      return 3;
    case VTK_PYRAMID:
      return 2;
    default:
      return 0;
  }
}

//------------------------------------------------------------------------------
void SplitIntoTetrahedra(vtkUnstructuredGrid* grid, bool tetrahedraOnly, TetrahedralSplit& split)
{
  split = TetrahedralSplit();
  if (!grid)
  {
    return;
  }
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  split.Tets.reserve(4 * numberOfCells);
  split.CellIds.reserve(numberOfCells);
  ForEachCell(grid, [&](vtkIdType cellId, int type, vtkIdType npts, const vtkIdType* pts) {
    const LinearShape shape = LinearShapeOf(type);
    const bool accepted = shape.Type != 0 && npts >= shape.Corners &&
      (!tetrahedraOnly || (type == VTK_TETRA && npts == 4));
    if (!accepted)
    {
      auto it = split.Unsupported.begin();
      for (; it != split.Unsupported.end(); it += 2)
      {
        if (*it == type)
        {
          ++*(it + 1);
          break;
        }
      }
      if (it == split.Unsupported.end())
      {
        split.Unsupported.push_back(type);
        split.Unsupported.push_back(1);
      }
      return;
    }
    const size_t before = split.Tets.size();
    vtkIdType corners[8];
    for (int i = 0; i < shape.Corners; ++i)
    {
      corners[i] = pts[HexahedronCorner(type, i)];
    }
    const int apex = SmallestPoint(corners, shape.Corners);
    switch (shape.Type)
    {
      case VTK_TETRA:
        split.Tets.insert(split.Tets.end(), corners, corners + 4);
        break;
      case VTK_HEXAHEDRON:
        AppendCone(HexahedronFaces, corners, apex, split.Tets);
        break;
      case VTK_WEDGE:
        AppendCone(WedgeFaces, corners, apex, split.Tets);
        break;
      default:
        AppendCone(PyramidFaces, corners, apex, split.Tets);
        break;
    }
    split.CellIds.insert(split.CellIds.end(), (split.Tets.size() - before) / 4, cellId);
    split.NumberOfSplitCells += shape.Type != VTK_TETRA ? 1 : 0;
    split.NumberOfQuadraticCells += shape.HigherOrder ? 1 : 0;
  });
}
}
