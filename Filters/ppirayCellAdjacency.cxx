#include "ppirayCellAdjacency.h"

#include "ppirayGridGeometryKey.h"
#include "ppirayInvertedSheets.h"
#include "vtkMath.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>

namespace
{
using ppiray::CellFaceMesh;
using ppiray::CellFaceTable;

// A face's point ids, ascending; a triangle's start with -1, so a triangle
// never matches a quadrilateral.
using FaceKey = std::array<vtkIdType, 4>;

const CellFaceTable& TableOf(const CellFaceMesh& mesh, vtkIdType cell)
{
  return *mesh.Tables[mesh.Kinds ? mesh.Kinds[cell] : 0];
}

int FaceSize(const CellFaceTable& table, int f)
{
  return table.Face[f][3] < 0 ? 3 : 4;
}

// The point ids of face f of a cell, in its winding.
int FaceIds(const CellFaceMesh& mesh, vtkIdType cell, int f, vtkIdType ids[4])
{
  const CellFaceTable& table = TableOf(mesh, cell);
  const vtkIdType* corners = mesh.CornerIds + mesh.CornerStride * cell;
  const int size = FaceSize(table, f);
  for (int v = 0; v < size; ++v)
  {
    ids[v] = corners[table.Face[f][v]];
  }
  return size;
}

FaceKey SortedFace(const CellFaceMesh& mesh, vtkIdType cell, int f)
{
  vtkIdType ids[4];
  FaceKey key;
  key[0] = FaceIds(mesh, cell, f, ids) == 4 ? ids[3] : -1;
  std::copy(ids, ids + 3, key.begin() + 1);
  std::sort(key.begin(), key.end());
  return key;
}

// The number of distinct point ids of a face.
int DistinctIds(const FaceKey& key)
{
  const int first = key[0] < 0 ? 1 : 0;
  int distinct = 1;
  for (int i = first + 1; i < 4; ++i)
  {
    distinct += key[i] != key[i - 1] ? 1 : 0;
  }
  return distinct;
}

// Fewer than three distinct point ids: the face has no area.
bool IsZeroArea(const FaceKey& key)
{
  return DistinctIds(key) < 3;
}

// The plane the cells on a face are sided against (SideOfFace): a
// triangle's corners by ascending id; a quadrilateral's centre and normal
// from its cycle smallest by ids.
struct FacePlane
{
  int Size;
  const double* Corner[3];
  double Normal[3];
  double Centre[3];
};

FacePlane PlaneOf(const double* points, const vtkIdType* faceIds, int size)
{
  FacePlane plane;
  plane.Size = size;
  auto at = [&](vtkIdType id) { return points + 3 * id; };
  if (size == 3)
  {
    vtkIdType k[3] = { faceIds[0], faceIds[1], faceIds[2] };
    std::sort(k, k + 3);
    for (int v = 0; v < 3; ++v)
    {
      plane.Corner[v] = at(k[v]);
    }
    return plane;
  }
  // The smallest of the four rotations and two windings: from the smallest
  // id towards its smaller neighbour (all eight compared where ids repeat).
  const int start = static_cast<int>(std::min_element(faceIds, faceIds + 4) - faceIds);
  const int step = faceIds[(start + 1) % 4] < faceIds[(start + 3) % 4] ? 1 : 3;
  std::array<vtkIdType, 4> best;
  for (int i = 0; i < 4; ++i)
  {
    best[i] = faceIds[(start + step * i) % 4];
  }
  std::array<vtkIdType, 4> sorted = best;
  std::sort(sorted.begin(), sorted.end());
  for (int s = 0; s < 8 && std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end(); ++s)
  {
    std::array<vtkIdType, 4> cycle;
    for (int i = 0; i < 4; ++i)
    {
      cycle[i] = faceIds[(s / 2 + (s % 2 ? 3 : 1) * i) % 4];
    }
    best = std::min(best, cycle);
  }
  double d0[3], d1[3];
  vtkMath::Subtract(at(best[2]), at(best[0]), d0);
  vtkMath::Subtract(at(best[3]), at(best[1]), d1);
  vtkMath::Cross(d0, d1, plane.Normal);
  for (int k = 0; k < 3; ++k)
  {
    plane.Centre[k] = 0.25 * (at(best[0])[k] + at(best[1])[k] + at(best[2])[k] + at(best[3])[k]);
  }
  return plane;
}

// The sign of face `face`'s cell's off-face centre q (the mean of its
// corners not on the face) against the plane: a triangle (a, b, c)
// det[b - a, c - a, q - a]; a quadrilateral n . (q - centre).
int SideOfPlane(const FacePlane& plane, const CellFaceMesh& mesh, vtkIdType cell, int face)
{
  const CellFaceTable& table = TableOf(mesh, cell);
  int onFace = 0;
  for (int v = 0; v < FaceSize(table, face); ++v)
  {
    onFace |= 1 << table.Face[face][v];
  }
  const vtkIdType* corners = mesh.CornerIds + mesh.CornerStride * cell;
  double q[3] = { 0, 0, 0 };
  int off = 0;
  for (int v = 0; v < table.Corners; ++v)
  {
    if (!(onFace & (1 << v)))
    {
      const double* p = mesh.Points + 3 * corners[v];
      q[0] += p[0];
      q[1] += p[1];
      q[2] += p[2];
      ++off;
    }
  }
  q[0] /= off;
  q[1] /= off;
  q[2] /= off;
  double side;
  if (plane.Size == 3)
  {
    side = vtkUnstructuredGridCellAdjacency::SignedVolume6(
      plane.Corner[0], plane.Corner[1], plane.Corner[2], q);
  }
  else
  {
    vtkMath::Subtract(q, plane.Centre, q);
    side = vtkMath::Dot(plane.Normal, q);
  }
  return side > 0 ? 1 : (side < 0 ? -1 : 0);
}

// Two cells paired across a face fold there when both lie on the same side
// of it (neither flat: a flat cell's side is 0).
bool Folds(int side, int mateSide)
{
  return side != 0 && side == mateSide;
}

// A cell face on a shared face: the side of the face its cell lies on (0
// without coordinates), and whether the cell is flat.
struct FaceEntry
{
  int Side;
  bool Flat;
  vtkIdType Cell;
  int Face;
  bool operator<(const FaceEntry& o) const
  {
    return Side != o.Side ? Side > o.Side : (Cell != o.Cell ? Cell < o.Cell : Face < o.Face);
  }
  bool operator==(const FaceEntry& o) const { return Cell == o.Cell && Face == o.Face; }
};

// Pairs the cell faces on one face (sorted entries): a cell on the positive
// side with one on the negative side; a face left with cells on one side
// only goes through a flat cell if one is there, else the same-side cells
// pair up (folded); flat cells on a face that non-flat cells close are
// hidden (neither paired nor boundary); flat faces alone pair up. Two faces
// of one cell never pair. partner[i] = -1: none.
void PairFace(const std::vector<FaceEntry>& e, std::vector<int>& partner, std::vector<char>& hidden)
{
  partner.assign(e.size(), -1);
  hidden.assign(e.size(), 0);
  if (e.size() == 2 && !e[0].Flat && !e[1].Flat)
  {
    partner[0] = 1; // crossing, or (one side only) paired as folded
    partner[1] = 0;
    return;
  }
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
    if (partner[flat[i]] < 0 && e[flat[i]].Cell != e[flat[i + 1]].Cell)
    {
      link(flat[i], flat[i + 1]);
    }
  }
}

// Whether face g of a cell has exactly the points of the key (a triangle's
// starting with -1).
bool FaceHasKey(const CellFaceMesh& mesh, vtkIdType cell, int g, const FaceKey& key)
{
  const CellFaceTable& table = TableOf(mesh, cell);
  const int size = FaceSize(table, g);
  if ((size == 3) != (key[0] < 0))
  {
    return false;
  }
  const vtkIdType* corners = mesh.CornerIds + mesh.CornerStride * cell;
  for (int v = 0; v < size; ++v)
  {
    if (std::find(key.begin(), key.end(), corners[table.Face[g][v]]) == key.end())
    {
      return false;
    }
  }
  return SortedFace(mesh, cell, g) == key; // (0, 1, 1, 0) is not (0, 1, 2, 4)
}

// Which corners of a cell hold one of the key's point ids (bit v: corner v)
// and which of the key's entries a corner holds (bit i: key[i]).
struct KeyCorners
{
  unsigned Corners = 0;
  unsigned Entries = 0;
};

KeyCorners CornersOnKey(const CellFaceTable& table, const vtkIdType* corners, const FaceKey& key)
{
  KeyCorners on;
  for (int v = 0; v < table.Corners; ++v)
  {
    for (int i = 0; i < 4; ++i)
    {
      const unsigned equal = corners[v] == key[i] ? 1u : 0u;
      on.Corners |= equal << v;
      on.Entries |= equal << i;
    }
  }
  return on;
}

// The corners of face g, as bits.
unsigned FaceCorners(const CellFaceTable& table, int g)
{
  unsigned mask = 0;
  for (int v = 0; v < FaceSize(table, g); ++v)
  {
    mask |= 1u << table.Face[g][v];
  }
  return mask;
}

int PopCount(unsigned mask)
{
  int count = 0;
  for (; mask != 0; mask &= mask - 1)
  {
    ++count;
  }
  return count;
}

// The cell faces on the face of cell c's face f (sorted ids `key`), by cell
// and face (Side 0), scanned around the face's point with the fewest cells;
// false, with the scan cut short, where one comes before (c, f). A cell
// holding each of the key's distinct ids at one corner has a face on the key
// where that face's corners are exactly those; where ids repeat (in the key
// or in the cell), every face is compared by ids.
bool CellFacesFrom(const CellFaceMesh& mesh, vtkIdType c, int f, const FaceKey& key,
  const std::vector<vtkIdType>& offsets, const std::vector<int>& links,
  std::vector<FaceEntry>& entries)
{
  const int first = key[0] < 0 ? 1 : 0;
  const int distinct = DistinctIds(key);
  const bool keyDistinct = distinct == 4 - first;
  const unsigned allEntries = first == 0 ? 0xFu : 0xEu;
  // The cells around the face's two points with the fewest cells (merged
  // by cell id), then those with its other points too.
  std::array<vtkIdType, 4> byDegree = key;
  std::sort(byDegree.begin() + first, byDegree.end(),
    [&](vtkIdType p, vtkIdType q)
    { return offsets[p + 1] - offsets[p] < offsets[q + 1] - offsets[q]; });
  const int *a = links.data() + offsets[byDegree[first]],
            *aEnd = links.data() + offsets[byDegree[first] + 1];
  const int *b = links.data() + offsets[byDegree[first + 1]],
            *bEnd = links.data() + offsets[byDegree[first + 1] + 1];
  entries.clear();
  while (a < aEnd && b < bEnd)
  {
    if (*a != *b)
    {
      (*a < *b ? a : b) += 1;
      continue;
    }
    const vtkIdType other = *a;
    for (; a < aEnd && *a == other; ++a)
    {
    }
    for (; b < bEnd && *b == other; ++b)
    {
    }
    const CellFaceTable& table = TableOf(mesh, other);
    const KeyCorners on = CornersOnKey(table, mesh.CornerIds + mesh.CornerStride * other, key);
    if (on.Entries != allEntries)
    {
      continue;
    }
    const bool byCorners = keyDistinct && PopCount(on.Corners) == distinct;
    for (int g = 0; g < table.Faces; ++g)
    {
      const bool onFace =
        byCorners ? FaceCorners(table, g) == on.Corners : FaceHasKey(mesh, other, g, key);
      if (onFace && (other != c || g != f))
      {
        if (other < c || (other == c && g < f))
        {
          return false;
        }
        entries.push_back({ 0, mesh.Flat && mesh.Flat[other], other, g });
      }
    }
  }
  entries.push_back({ 0, mesh.Flat && mesh.Flat[c], c, f });
  std::sort(entries.begin(), entries.end());
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  return true;
}

// Whether any cell of the mesh is flat (zero volume).
bool HasFlatCell(const CellFaceMesh& mesh)
{
  return mesh.Flat && std::any_of(mesh.Flat, mesh.Flat + mesh.NumberOfCells,
                        [](unsigned char flat) { return flat != 0; });
}

// Which side of each fold is inverted (ppirayInvertedSheets.h); none
// without folds or coordinates.
std::vector<unsigned char> InvertedCells(const CellFaceMesh& mesh, const ppiray::CellAdjacency& a)
{
  if (!mesh.Points || a.NumberOfFoldedFaces == 0)
  {
    return std::vector<unsigned char>(mesh.NumberOfCells, 0);
  }
  return ppiray::InvertedSheets(
    mesh.NumberOfCells, mesh.FaceSlots,
    [&](vtkIdType c, int f) { return vtkIdType{ a.Neighbors[mesh.FaceSlots * c + f] }; },
    [&](vtkIdType c, int f) { return a.Folded[mesh.FaceSlots * c + f] != 0; },
    [&](vtkIdType c)
    {
      return std::abs(
        ppiray::CellVolume6(TableOf(mesh, c), mesh.CornerIds + mesh.CornerStride * c, mesh.Points));
    });
}

// What MatchCellFaces() knows of a cell face: written by its face's match,
// hidden (a flat cell's face that other cells close), no area.
enum FaceFlag : unsigned char
{
  MATCHED = 1,
  HIDDEN = 2,
  ZERO_AREA = 4
};

// Point-to-cell links by counting sort: cells around point p are
// links[offsets[p]..offsets[p+1]) (a cell with a repeated point id is
// listed there twice).
void LinkPoints(const CellFaceMesh& mesh, std::vector<vtkIdType>& offsets, std::vector<int>& links)
{
  offsets.assign(mesh.NumberOfPoints + 1, 0);
  auto forEachCorner = [&](auto&& visit)
  {
    for (vtkIdType c = 0; c < mesh.NumberOfCells; ++c)
    {
      const vtkIdType* corners = mesh.CornerIds + mesh.CornerStride * c;
      for (int v = 0; v < TableOf(mesh, c).Corners; ++v)
      {
        visit(c, corners[v]);
      }
    }
  };
  forEachCorner([&](vtkIdType, vtkIdType p) { ++offsets[p + 1]; });
  for (vtkIdType p = 0; p < mesh.NumberOfPoints; ++p)
  {
    offsets[p + 1] += offsets[p];
  }
  links.resize(offsets[mesh.NumberOfPoints]);
  std::vector<vtkIdType> fill(offsets.begin(), offsets.end() - 1);
  forEachCorner([&](vtkIdType c, vtkIdType p) { links[fill[p]++] = static_cast<int>(c); });
}
}

namespace ppiray
{
//------------------------------------------------------------------------------
int SideOfFace(
  const CellFaceMesh& mesh, vtkIdType cell, int face, const vtkIdType* faceIds, int size)
{
  return mesh.Points ? SideOfPlane(PlaneOf(mesh.Points, faceIds, size), mesh, cell, face) : 0;
}

//------------------------------------------------------------------------------
vtkIdType NearestSolidCell(
  vtkIdType cell, const int* neighbors, int slots, const unsigned char* flat)
{
  std::vector<vtkIdType> queue = { cell };
  for (size_t k = 0; k < queue.size() && k < 64; ++k)
  {
    for (int g = 0; g < slots; ++g)
    {
      const vtkIdType n = neighbors[slots * queue[k] + g];
      if (n < 0 || std::find(queue.begin(), queue.end(), n) != queue.end())
      {
        continue;
      }
      if (!flat[n])
      {
        return n;
      }
      queue.push_back(n);
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
double CellVolume6(const CellFaceTable& table, const vtkIdType* corners, const double* points)
{
  auto at = [&](int v) { return points + 3 * corners[v]; };
  double volume6 = 0;
  for (int f = 0; f < table.Faces; ++f)
  {
    const int* q = table.Face[f];
    for (int t = 0; t + 2 < FaceSize(table, f); ++t)
    {
      volume6 += vtkUnstructuredGridCellAdjacency::SignedVolume6(
        at(0), at(q[0]), at(q[t + 1]), at(q[t + 2]));
    }
  }
  return volume6;
}

//------------------------------------------------------------------------------
CellAdjacency MatchCellFaces(const CellFaceMesh& mesh)
{
  CellAdjacency result;
  if (mesh.NumberOfCells > MaximumAdjacencyCells)
  {
    return result;
  }
  std::vector<vtkIdType> offsets;
  std::vector<int> links;
  LinkPoints(mesh, offsets, links);

  const vtkIdType slots = mesh.FaceSlots * mesh.NumberOfCells;
  result.Neighbors.assign(slots, -1);
  result.NeighborFaces.assign(slots, -1);
  result.Folded.assign(slots, 0);
  std::atomic<vtkIdType> nonManifold(0), folded(0);
  // What is known of each cell face (FaceFlag bits). MATCHED: written,
  // skipped when its own turn comes (a face whose writer has not yet been
  // reached is matched again, and left to it). A slot has one writer (the
  // thread of its face's first cell face), so a bit is set by load and store.
  std::unique_ptr<std::atomic<unsigned char>[]> flags(new std::atomic<unsigned char>[slots]());
  auto setFlag = [&](vtkIdType slot, unsigned char bit)
  {
    flags[slot].store(flags[slot].load(std::memory_order_relaxed) | bit, std::memory_order_relaxed);
  };
  auto hasFlag = [&](vtkIdType slot, unsigned char bit)
  { return (flags[slot].load(std::memory_order_relaxed) & bit) != 0; };

  // Each face is matched once, by the first of its cell faces (by cell,
  // then face), which writes every cell face on it: no two threads write
  // one slot.
#pragma omp parallel
  {
    std::vector<FaceEntry> entries;
    std::vector<int> partner;
    std::vector<char> hidden;
    vtkIdType localNonManifold = 0, localFolded = 0;
#pragma omp for schedule(static)
    for (vtkIdType c = 0; c < mesh.NumberOfCells; ++c)
    {
      for (int f = 0; f < TableOf(mesh, c).Faces; ++f)
      {
        if (hasFlag(mesh.FaceSlots * c + f, MATCHED))
        {
          continue; // written by the first cell face on it
        }
        const FaceKey key = SortedFace(mesh, c, f);
        if (IsZeroArea(key))
        {
          setFlag(mesh.FaceSlots * c + f, ZERO_AREA);
          continue;
        }
        if (!CellFacesFrom(mesh, c, f, key, offsets, links, entries) || entries.size() < 2)
        {
          continue; // another cell face's, or a boundary face
        }
        if (mesh.Points)
        {
          vtkIdType ids[4];
          const FacePlane plane = PlaneOf(mesh.Points, ids, FaceIds(mesh, c, f, ids));
          for (FaceEntry& e : entries)
          {
            e.Side = e.Flat ? 0 : SideOfPlane(plane, mesh, e.Cell, e.Face);
          }
        }
        std::sort(entries.begin(), entries.end());
        PairFace(entries, partner, hidden);
        localNonManifold += entries.size() > 2 ? static_cast<vtkIdType>(entries.size()) : 0;
        for (size_t i = 0; i < entries.size(); ++i)
        {
          const vtkIdType slot = mesh.FaceSlots * entries[i].Cell + entries[i].Face;
          setFlag(slot, MATCHED | (hidden[i] ? HIDDEN : 0));
          if (partner[i] < 0)
          {
            continue;
          }
          const FaceEntry& mate = entries[partner[i]];
          result.Neighbors[slot] = static_cast<int>(mate.Cell);
          result.NeighborFaces[slot] = static_cast<signed char>(mate.Face);
          const bool isFolded = !entries[i].Flat && !mate.Flat && Folds(entries[i].Side, mate.Side);
          result.Folded[slot] = isFolded ? 1 : 0;
          localFolded += isFolded ? 1 : 0;
        }
      }
    }
    nonManifold += localNonManifold;
    folded += localFolded;
  }
  result.NumberOfNonManifoldFaces = nonManifold.load();
  result.NumberOfFoldedFaces = folded.load() / 2; // each pair counted from both faces

  result.Inverted = InvertedCells(mesh, result);
  result.ByIds = result.NumberOfNonManifoldFaces == 0 && !HasFlatCell(mesh);

  // A flat cell with a hidden face lies on a face that other cells close:
  // none of its faces is a boundary.
  for (vtkIdType c = 0; c < mesh.NumberOfCells; ++c)
  {
    const vtkIdType first = mesh.FaceSlots * c;
    bool detached = false;
    for (int f = 0; f < mesh.FaceSlots; ++f)
    {
      detached = detached || hasFlag(first + f, HIDDEN);
    }
    for (int f = 0; f < TableOf(mesh, c).Faces; ++f)
    {
      if (result.Neighbors[first + f] < 0 && !hasFlag(first + f, ZERO_AREA) && !detached)
      {
        result.BoundaryFaces.push_back(c);
        result.BoundaryFaces.push_back(f);
      }
    }
  }
  return result;
}

//------------------------------------------------------------------------------
bool RefoldCellFaces(const CellFaceMesh& mesh, CellAdjacency& adjacency)
{
  if (!adjacency.ByIds || !mesh.Points || HasFlatCell(mesh) ||
      adjacency.Neighbors.size() != static_cast<size_t>(mesh.FaceSlots * mesh.NumberOfCells))
  {
    return false;
  }
  // Each pair from its first cell face, against the plane MatchCellFaces()
  // sides it by (PlaneOf: the same from either cell face).
  CellAdjacency& a = adjacency;
  vtkIdType folded = 0;
#pragma omp parallel for schedule(static) reduction(+ : folded)
  for (vtkIdType c = 0; c < mesh.NumberOfCells; ++c)
  {
    for (int f = 0; f < TableOf(mesh, c).Faces; ++f)
    {
      const vtkIdType slot = mesh.FaceSlots * c + f;
      const vtkIdType n = a.Neighbors[slot];
      const int g = a.NeighborFaces[slot];
      if (n < c || (n == c && g < f))
      {
        continue; // a boundary face, or the pair's second cell face
      }
      vtkIdType ids[4];
      const FacePlane plane = PlaneOf(mesh.Points, ids, FaceIds(mesh, c, f, ids));
      const bool isFolded = Folds(SideOfPlane(plane, mesh, c, f), SideOfPlane(plane, mesh, n, g));
      a.Folded[slot] = a.Folded[mesh.FaceSlots * n + g] = isFolded ? 1 : 0;
      folded += isFolded ? 1 : 0;
    }
  }
  a.NumberOfFoldedFaces = folded;
  a.Inverted = InvertedCells(mesh, a);
  return true;
}

//------------------------------------------------------------------------------
const CellAdjacency& CellAdjacencyCache::Update(const CellFaceMesh& mesh)
{
  // The cells by their corner ids, kinds and face tables, and the number of points.
  ContentDigest cells =
    DigestBytes(mesh.CornerIds, sizeof(vtkIdType) * mesh.CornerStride * mesh.NumberOfCells);
  if (mesh.Kinds)
  {
    cells = DigestBytes(mesh.Kinds, mesh.NumberOfCells, cells);
  }
  const vtkIdType shape[3] = { mesh.NumberOfPoints, mesh.CornerStride, mesh.FaceSlots };
  cells = DigestBytes(shape, sizeof(shape), cells);
  cells = DigestBytes(mesh.Tables, sizeof(mesh.Tables), cells);
  this->Kept = this->Valid && cells == this->Cells && RefoldCellFaces(mesh, this->Adjacency);
  if (!this->Kept)
  {
    this->Adjacency = MatchCellFaces(mesh);
  }
  this->Cells = cells;
  this->Valid = true;
  return this->Adjacency;
}
}
