#include "vtkUnstructuredGridCellAdjacency.h"

#include "ppirayInvertedSheets.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <atomic>

vtkStandardNewMacro(vtkUnstructuredGridCellAdjacency);

namespace
{
// Face f is opposite vertex f, wound counter-clockwise seen from outside a
// positively oriented tetrahedron.
constexpr int TetFaces[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

using FaceKey = std::array<vtkIdType, 3>;

// The point ids of local face f, ascending.
FaceKey SortedFace(const vtkIdType* tet, int f)
{
  FaceKey key = { tet[TetFaces[f][0]], tet[TetFaces[f][1]], tet[TetFaces[f][2]] };
  std::sort(key.begin(), key.end());
  return key;
}

// A tetrahedron face on a shared face: the side of the face its fourth
// point lies on (0 without coordinates), and whether it is flat.
struct FaceEntry
{
  int Side;
  bool Flat;
  vtkIdType Tet;
  int Face;
  bool operator<(const FaceEntry& o) const
  {
    return Side != o.Side ? Side > o.Side : (Tet != o.Tet ? Tet < o.Tet : Face < o.Face);
  }
  bool operator==(const FaceEntry& o) const { return Tet == o.Tet && Face == o.Face; }
};

// The side of the plane through key[0..2] (in that order) that the point of
// tetrahedron t opposite face f lies on: sign of det[b - a, c - a, q - a];
// 0 without coordinates.
int Side(const vtkIdType* tets, vtkIdType t, int f, const FaceKey& key, const double* points)
{
  if (!points)
  {
    return 0;
  }
  const double volume6 = vtkUnstructuredGridCellAdjacency::SignedVolume6(
    points + 3 * key[0], points + 3 * key[1], points + 3 * key[2], points + 3 * tets[4 * t + f]);
  return volume6 > 0 ? 1 : (volume6 < 0 ? -1 : 0);
}

// Pairs the tetrahedron faces on one face (sorted entries): a cell on the
// positive side with one on the negative side; a face left with cells on
// one side only goes through a flat tetrahedron if one is there, else the
// same-side cells pair up (folded); flat tetrahedra on a face that non-flat
// cells close are hidden (neither paired nor boundary); flat faces alone
// pair up. Two faces of one tetrahedron never pair. partner[i] = -1: none.
void PairFace(const std::vector<FaceEntry>& e, std::vector<int>& partner, std::vector<char>& hidden)
{
  partner.assign(e.size(), -1);
  hidden.assign(e.size(), 0);
  std::vector<int> plus, minus, rest, flat;
  for (int i = 0; i < static_cast<int>(e.size()); ++i)
  {
    (e[i].Flat ? flat : (e[i].Side > 0 ? plus : (e[i].Side < 0 ? minus : rest))).push_back(i);
  }
  auto link = [&](int a, int b)
  {
    partner[a] = b;
    partner[b] = a;
  };
  const size_t crossing = std::min(plus.size(), minus.size());
  for (size_t i = 0; i < crossing; ++i)
  {
    link(plus[i], minus[i]);
  }
  rest.insert(rest.end(), plus.begin() + crossing, plus.end());
  rest.insert(rest.end(), minus.begin() + crossing, minus.end());
  size_t firstFlat = 0;
  if (!rest.empty() && !flat.empty())
  {
    link(rest.front(), flat.front());
    rest.erase(rest.begin());
    firstFlat = 1;
  }
  for (size_t i = 0; i + 1 < rest.size(); i += 2)
  {
    link(rest[i], rest[i + 1]);
  }
  if (crossing > 0 && firstFlat == 0)
  {
    for (int i : flat)
    {
      hidden[i] = 1;
    }
    return;
  }
  for (size_t i = firstFlat; i + 1 < flat.size(); ++i)
  {
    if (partner[flat[i]] < 0 && e[flat[i]].Tet != e[flat[i + 1]].Tet)
    {
      link(flat[i], flat[i + 1]);
    }
  }
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
void vtkUnstructuredGridCellAdjacency::Build(vtkIdType numberOfPoints, const vtkIdType* tets,
  vtkIdType numberOfTets, const double* points, const unsigned char* flat)
{
  // Point-to-tetrahedron links by counting sort: offsets[p]..offsets[p+1]
  // (a tetrahedron with a repeated point id is listed there twice).
  std::vector<vtkIdType> offsets(numberOfPoints + 1, 0);
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
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
      for (int v = 0; v < 4; ++v)
      {
        links[fill[tets[4 * t + v]]++] = t;
      }
    }
  }

  this->Neighbors.assign(4 * numberOfTets, -1);
  this->NeighborFaces.assign(4 * numberOfTets, -1);
  this->Folded.assign(4 * numberOfTets, 0);
  std::vector<unsigned char> zeroArea(4 * numberOfTets, 0), hiddenFace(4 * numberOfTets, 0);
  std::atomic<vtkIdType> nonManifold(0), folded(0);

#pragma omp parallel
  {
    std::vector<FaceEntry> entries;
    std::vector<int> partner;
    std::vector<char> hidden;
#pragma omp for schedule(static)
    for (vtkIdType t = 0; t < numberOfTets; ++t)
    {
      for (int f = 0; f < 4; ++f)
      {
        const FaceKey key = SortedFace(tets + 4 * t, f);
        if (key[0] == key[1] || key[1] == key[2])
        {
          zeroArea[4 * t + f] = 1;
          continue;
        }
        // Every tetrahedron face with these three points, scanned around the
        // face point with the fewest tetrahedra.
        vtkIdType pivot = key[0];
        for (vtkIdType p : { key[1], key[2] })
        {
          if (offsets[p + 1] - offsets[p] < offsets[pivot + 1] - offsets[pivot])
          {
            pivot = p;
          }
        }
        entries.clear();
        for (vtkIdType k = offsets[pivot]; k < offsets[pivot + 1]; ++k)
        {
          const vtkIdType other = links[k];
          for (int g = 0; g < 4; ++g)
          {
            if (SortedFace(tets + 4 * other, g) == key)
            {
              const bool isFlat = flat && flat[other];
              entries.push_back(
                { isFlat ? 0 : Side(tets, other, g, key, points), isFlat, other, g });
            }
          }
        }
        std::sort(entries.begin(), entries.end());
        entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
        if (entries.size() > 2)
        {
          ++nonManifold;
        }
        PairFace(entries, partner, hidden);
        const int self = static_cast<int>(
          std::find(entries.begin(), entries.end(), FaceEntry{ 0, false, t, f }) - entries.begin());
        hiddenFace[4 * t + f] = hidden[self];
        if (partner[self] >= 0)
        {
          const FaceEntry& mate = entries[partner[self]];
          this->Neighbors[4 * t + f] = mate.Tet;
          this->NeighborFaces[4 * t + f] = static_cast<signed char>(mate.Face);
          if (!entries[self].Flat && !mate.Flat && entries[self].Side != 0 &&
              entries[self].Side == mate.Side)
          {
            this->Folded[4 * t + f] = 1;
            ++folded;
          }
        }
      }
    }
  }
  this->NumberOfNonManifoldFaces = nonManifold.load();
  this->NumberOfFoldedFaces = folded.load() / 2; // each counted from both sides

  // Which side of each fold is inverted.
  if (points)
  {
    this->Inverted = ppiray::InvertedSheets(
      numberOfTets, 4, [&](vtkIdType t, int f) { return this->Neighbors[4 * t + f]; },
      [&](vtkIdType t, int f) { return this->Folded[4 * t + f] != 0; },
      [&](vtkIdType t)
      {
        const vtkIdType* tet = tets + 4 * t;
        return std::abs(SignedVolume6(
          points + 3 * tet[0], points + 3 * tet[1], points + 3 * tet[2], points + 3 * tet[3]));
      });
  }
  else
  {
    this->Inverted.assign(numberOfTets, 0);
  }

  // A flat tetrahedron with a hidden face lies on a face that other cells
  // close: none of its faces is a boundary.
  this->BoundaryFaces.clear();
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
    const bool detached =
      hiddenFace[4 * t] || hiddenFace[4 * t + 1] || hiddenFace[4 * t + 2] || hiddenFace[4 * t + 3];
    for (int f = 0; f < 4; ++f)
    {
      if (this->Neighbors[4 * t + f] < 0 && !zeroArea[4 * t + f] && !detached)
      {
        this->BoundaryFaces.push_back(t);
        this->BoundaryFaces.push_back(f);
      }
    }
  }
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridCellAdjacency::WalksBackInPlace(vtkIdType t, vtkIdType n) const
{
  return ppiray::WalksBackInPlace(this->Inverted, t, n);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridCellAdjacency::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTetrahedra: " << this->Neighbors.size() / 4 << "\n";
  os << indent << "NumberOfBoundaryFaces: " << this->GetNumberOfBoundaryFaces() << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
  os << indent << "NumberOfFoldedFaces: " << this->NumberOfFoldedFaces << "\n";
}
