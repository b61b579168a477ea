#include "ppirayConformingTetrahedra.h"

#include "ppirayLinearCellKinds.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace
{
// The faces of the linear cells: ppirayLinearCellKinds.h (their orientation
// does not matter here: the consumers orient each tetrahedron by the sign of
// its volume). A face is 4 corner indices, -1 ending a triangle.
using Face = std::array<int, 4>;
const ppiray::LinearCellKindInfo& HexahedronKind =
  ppiray::LinearCellKindOf(ppiray::HEXAHEDRON_KIND);

Face FaceOf(const ppiray::LinearCellKindInfo& kind, int f)
{
  const int* q = kind.Face[f];
  return { q[0], q[1], q[2], q[3] };
}
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

// Tetrahedra (apex, triangle) over the triangles of the faces of a cell of
// `kind` that miss the apex's point (a cone from it); quadrilaterals split by
// `diagonals`. For a cell without repeated points these are the triangles of
// the faces that do not contain the apex: the diagonal of the others goes
// through it.
void AppendCone(const ppiray::LinearCellKindInfo& kind, const vtkIdType* pts, int apex,
  const ppiray::QuadDiagonals& diagonals, std::vector<vtkIdType>& tets)
{
  const vtkIdType v = pts[apex];
  for (int f = 0; f < kind.Faces; ++f)
  {
    const Face face = FaceOf(kind, f);
    const vtkIdType q[4] = { pts[face[0]], pts[face[1]], pts[face[2]],
      face[3] < 0 ? -1 : pts[face[3]] };
    const bool quadrilateral = face[3] >= 0;
    const bool second = quadrilateral && !diagonals.AlongFirstDiagonal(q[0], q[1], q[2], q[3]);
    for (int t = 0; t < (quadrilateral ? 2 : 1); ++t)
    {
      const vtkIdType a = q[ppiray::QuadTriangleCorner(t, 0, second)];
      const vtkIdType b = q[ppiray::QuadTriangleCorner(t, 1, second)];
      const vtkIdType c = q[ppiray::QuadTriangleCorner(t, 2, second)];
      if (a != v && b != v && c != v)
      {
        tets.insert(tets.end(), { v, a, b, c });
      }
    }
  }
}

// Whether face f of hexahedron c (corner ids), split along its second
// diagonal or not, has a triangle whose three corners all lie on another
// face of the cell.
bool FoldsOntoAnotherFace(const vtkIdType c[8], int f, bool second)
{
  const Face face = FaceOf(HexahedronKind, f);
  for (int t = 0; t < 2; ++t)
  {
    vtkIdType triangle[3];
    for (int v = 0; v < 3; ++v)
    {
      triangle[v] = c[face[ppiray::QuadTriangleCorner(t, v, second)]];
    }
    for (int g = 0; g < 6; ++g)
    {
      const Face other = FaceOf(HexahedronKind, g);
      const vtkIdType ids[4] = { c[other[0]], c[other[1]], c[other[2]], c[other[3]] };
      auto onOther = [&](vtkIdType id) { return std::find(ids, ids + 4, id) != ids + 4; };
      if (g != f && onOther(triangle[0]) && onOther(triangle[1]) && onOther(triangle[2]))
      {
        return true;
      }
    }
  }
  return false;
}

std::array<vtkIdType, 4> SortedIds(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d)
{
  std::array<vtkIdType, 4> ids = { a, b, c, d };
  std::sort(ids.begin(), ids.end());
  return ids;
}

// Six times the signed volume of tetrahedron t (four point ids of `grid`).
double SignedVolume6(vtkUnstructuredGrid* grid, const vtkIdType* t)
{
  double p[4][3];
  for (int i = 0; i < 4; ++i)
  {
    grid->GetPoint(t[i], p[i]);
  }
  return vtkUnstructuredGridCellAdjacency::SignedVolume6(p[0], p[1], p[2], p[3]);
}

// Whether the `n` tetrahedra at `tets` (point ids, 4 each) all have one sign
// (volumes below 1e-9 of the largest count as none).
bool OneSign(vtkUnstructuredGrid* grid, const vtkIdType* tets, size_t n)
{
  double volumes[12]; // a cone has at most 2 triangles per face of 6
  n = std::min<size_t>(n, 12);
  double scale = 0;
  for (size_t i = 0; i < n; ++i)
  {
    volumes[i] = SignedVolume6(grid, tets + 4 * i);
    scale = std::max(scale, std::abs(volumes[i]));
  }
  bool positive = false, negative = false;
  for (size_t i = 0; i < n; ++i)
  {
    positive |= volumes[i] > 1e-9 * scale;
    negative |= volumes[i] < -1e-9 * scale;
  }
  return !(positive && negative);
}

// A cone is exact when the cell is star-shaped from its apex. A strongly
// non-convex cell (a warped hexahedron of a reservoir grid, or one next to a
// face split against the smallest-id rule) may not be star-shaped from its
// smallest point: some tetrahedra then lie over triangles seen from behind,
// with the opposite sign, and overlap the others; the consumers, which orient
// every tetrahedron by its sign, would count that volume twice. Then the
// first corner (by id) whose cone has one sign replaces the cone from
// tets[first] on; if none has, the cone from the smallest point stays.
void ConeFromStarPoint(vtkUnstructuredGrid* grid, const ppiray::LinearCellKindInfo& kind,
  const vtkIdType* c, const ppiray::QuadDiagonals& diagonals, size_t first,
  std::vector<vtkIdType>& tets)
{
  if (OneSign(grid, tets.data() + first, (tets.size() - first) / 4))
  {
    return;
  }
  const int corners = kind.Corners;
  int order[8];
  std::iota(order, order + corners, 0);
  std::sort(order, order + corners, [&](int a, int b) { return c[a] < c[b]; });
  std::vector<vtkIdType> cone;
  for (int i = 1; i < corners; ++i)
  {
    if (c[order[i]] == c[order[i - 1]])
    {
      continue; // the same point
    }
    cone.clear();
    AppendCone(kind, c, order[i], diagonals, cone);
    if (OneSign(grid, cone.data(), cone.size() / 4))
    {
      tets.resize(first);
      tets.insert(tets.end(), cone.begin(), cone.end());
      return;
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
void ExtractTetrahedra(vtkUnstructuredGrid* grid, std::vector<vtkIdType>& tets,
  std::vector<vtkIdType>& cellIds, std::vector<vtkIdType>& unsupported)
{
  TetrahedralSplit split;
  SplitIntoTetrahedra(grid, /*tetrahedraOnly=*/true, split);
  tets = std::move(split.Tets);
  cellIds = std::move(split.CellIds);
  unsupported = std::move(split.Unsupported);
}

//------------------------------------------------------------------------------
void QuadDiagonals::AddHexahedron(const vtkIdType c[8])
{
  std::array<vtkIdType, 8> sorted;
  std::copy(c, c + 8, sorted.begin());
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end())
  {
    return; // no repeated corner: nothing can fold
  }
  for (int f = 0; f < 6; ++f)
  {
    const Face q = FaceOf(HexahedronKind, f);
    const auto ids = SortedIds(c[q[0]], c[q[1]], c[q[2]], c[q[3]]);
    const bool second = !SplitsAlongFirstDiagonal(c[q[0]], c[q[1]], c[q[2]], c[q[3]]);
    if (std::adjacent_find(ids.begin(), ids.end()) == ids.end() &&
        FoldsOntoAnotherFace(c, f, second) && !FoldsOntoAnotherFace(c, f, !second))
    {
      this->Unfolded.emplace(
        ids, std::array<vtkIdType, 2>{ c[q[second ? 0 : 1]], c[q[second ? 2 : 3]] });
    }
  }
}

//------------------------------------------------------------------------------
void QuadDiagonals::Build(vtkUnstructuredGrid* grid)
{
  this->Unfolded.clear();
  ForEachCell(grid,
    [&](vtkIdType, int type, vtkIdType npts, const vtkIdType* pts)
    {
      const LinearShape shape = LinearShapeOf(type);
      if (shape.Type == VTK_HEXAHEDRON && npts >= 8)
      {
        vtkIdType corners[8];
        for (int i = 0; i < 8; ++i)
        {
          corners[i] = pts[HexahedronCorner(type, i)];
        }
        this->AddHexahedron(corners);
      }
    });
}

//------------------------------------------------------------------------------
bool QuadDiagonals::AlongFirstDiagonal(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d) const
{
  if (!this->Unfolded.empty())
  {
    const auto it = this->Unfolded.find(SortedIds(a, b, c, d));
    if (it != this->Unfolded.end())
    {
      return it->second[0] == a || it->second[0] == c;
    }
  }
  return SplitsAlongFirstDiagonal(a, b, c, d);
}

//------------------------------------------------------------------------------
void AppendConeSplit(int kind, const vtkIdType* pts, std::vector<int>& tets)
{
  const auto& info = LinearCellKindOf(kind);
  if (kind == TETRAHEDRON_KIND)
  {
    tets.insert(tets.end(), { 0, 1, 2, 3 });
    return;
  }
  std::vector<vtkIdType> cone;
  AppendCone(info, pts, SmallestPoint(pts, info.Corners), QuadDiagonals(), cone);
  for (const vtkIdType id : cone)
  {
    tets.push_back(static_cast<int>(std::find(pts, pts + info.Corners, id) - pts));
  }
}

//------------------------------------------------------------------------------
void SplitIntoTetrahedra(vtkUnstructuredGrid* grid, bool tetrahedraOnly, TetrahedralSplit& split)
{
  // Cleared, not replaced: the storage passed in (a rebuild's) is reused.
  split.Tets.clear();
  split.CellIds.clear();
  split.Added = AddedPoints();
  split.NumberOfSplitCells = split.NumberOfPolyhedra = split.NumberOfQuadraticCells = 0;
  split.Unsupported.clear();
  if (!grid)
  {
    return;
  }
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  split.Tets.reserve(4 * numberOfCells);
  split.CellIds.reserve(numberOfCells);
  QuadDiagonals diagonals;
  if (!tetrahedraOnly)
  {
    diagonals.Build(grid);
  }
  PolyhedronSplitter polyhedra(grid, diagonals, split.Added);
  ForEachCell(grid,
    [&](vtkIdType cellId, int type, vtkIdType npts, const vtkIdType* pts)
    {
      if (type == VTK_POLYHEDRON && !tetrahedraOnly)
      {
        const vtkIdType made = polyhedra.Split(cellId, split.Tets);
        split.CellIds.insert(split.CellIds.end(), made, cellId);
        split.NumberOfSplitCells += made > 0 ? 1 : 0;
        split.NumberOfPolyhedra += made > 0 ? 1 : 0;
        return;
      }
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
      if (shape.Type == VTK_TETRA)
      {
        split.Tets.insert(split.Tets.end(), corners, corners + 4);
      }
      else
      {
        const auto& kind = LinearCellKindOf(LinearCellKindOfType(shape.Type));
        AppendCone(kind, corners, apex, diagonals, split.Tets);
        ConeFromStarPoint(grid, kind, corners, diagonals, before, split.Tets);
      }
      split.CellIds.insert(split.CellIds.end(), (split.Tets.size() - before) / 4, cellId);
      split.NumberOfSplitCells += shape.Type != VTK_TETRA ? 1 : 0;
      split.NumberOfQuadraticCells += shape.HigherOrder ? 1 : 0;
    });
}
}
