#include "vtkUnstructuredGridCellAdjacency.h"

#include "vtkConformingTetrahedra.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <atomic>

vtkStandardNewMacro(vtkUnstructuredGridCellAdjacency);

namespace
{
// Face f is opposite vertex f, wound counter-clockwise seen from outside a
// positively oriented tetrahedron.
constexpr int TetFaces[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

bool TetHasPoint(const vtkIdType* tet, vtkIdType p)
{
  return tet[0] == p || tet[1] == p || tet[2] == p || tet[3] == p;
}
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridCellAdjacency::FaceVertex(int f, int v)
{
  return TetFaces[f][v];
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridCellAdjacency::SignedVolume6(
  const double p0[3], const double p1[3], const double p2[3], const double p3[3])
{
  const double a[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  const double b[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
  const double c[3] = { p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2] };
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
    a[2] * (b[0] * c[1] - b[1] * c[0]);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridCellAdjacency::ExtractTetrahedra(vtkUnstructuredGrid* grid,
  std::vector<vtkIdType>& tets, std::vector<vtkIdType>& cellIds,
  std::vector<vtkIdType>& unsupported)
{
  ppiray::TetrahedralSplit split;
  ppiray::SplitIntoTetrahedra(grid, /*tetrahedraOnly=*/true, split);
  tets = std::move(split.Tets);
  cellIds = std::move(split.CellIds);
  unsupported = std::move(split.Unsupported);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridCellAdjacency::Build(vtkIdType numberOfPoints, const vtkIdType* tets,
  vtkIdType numberOfTets, const unsigned char* ignore)
{
  // Point-to-tetrahedron links by counting sort: offsets[p]..offsets[p+1].
  std::vector<vtkIdType> offsets(numberOfPoints + 1, 0);
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
    if (ignore && ignore[t])
    {
      continue;
    }
    for (int v = 0; v < 4; ++v)
    {
      ++offsets[tets[4 * t + v] + 1];
    }
  }
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    offsets[p + 1] += offsets[p];
  }
  std::vector<vtkIdType> links(offsets[numberOfPoints]);
  {
    std::vector<vtkIdType> fill(offsets.begin(), offsets.end() - 1);
    for (vtkIdType t = 0; t < numberOfTets; ++t)
    {
      if (ignore && ignore[t])
      {
        continue;
      }
      for (int v = 0; v < 4; ++v)
      {
        links[fill[tets[4 * t + v]]++] = t;
      }
    }
  }

  this->Neighbors.assign(4 * numberOfTets, -1);
  std::atomic<vtkIdType> nonManifold(0);

#pragma omp parallel for schedule(static)
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
    if (ignore && ignore[t])
    {
      continue;
    }
    const vtkIdType* tet = tets + 4 * t;
    for (int f = 0; f < 4; ++f)
    {
      const vtkIdType a = tet[TetFaces[f][0]];
      const vtkIdType b = tet[TetFaces[f][1]];
      const vtkIdType c = tet[TetFaces[f][2]];
      // Scan the tetrahedra around the face point with the fewest of them.
      vtkIdType pivot = a;
      for (vtkIdType p : { b, c })
      {
        if (offsets[p + 1] - offsets[p] < offsets[pivot + 1] - offsets[pivot])
        {
          pivot = p;
        }
      }
      vtkIdType found = -1;
      int matches = 0;
      for (vtkIdType k = offsets[pivot]; k < offsets[pivot + 1]; ++k)
      {
        const vtkIdType other = links[k];
        if (other == t)
        {
          continue;
        }
        const vtkIdType* o = tets + 4 * other;
        if (TetHasPoint(o, a) && TetHasPoint(o, b) && TetHasPoint(o, c))
        {
          if (found < 0)
          {
            found = other;
          }
          ++matches;
        }
      }
      if (matches > 1)
      {
        ++nonManifold;
      }
      this->Neighbors[4 * t + f] = found;
    }
  }
  this->NumberOfNonManifoldFaces = nonManifold.load();

  this->BoundaryFaces.clear();
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
    if (ignore && ignore[t])
    {
      continue;
    }
    for (int f = 0; f < 4; ++f)
    {
      if (this->Neighbors[4 * t + f] < 0)
      {
        this->BoundaryFaces.push_back(t);
        this->BoundaryFaces.push_back(f);
      }
    }
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridCellAdjacency::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTetrahedra: " << this->Neighbors.size() / 4 << "\n";
  os << indent << "NumberOfBoundaryFaces: " << this->GetNumberOfBoundaryFaces() << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
}
