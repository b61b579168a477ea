// The one adjacency stage (ppiray::MatchCellFaces, ppirayCellAdjacency.h)
// on cells of every linear kind:
//  1. a 4x4x4 lattice of cubes, each a hexahedron, two wedges, six pyramids
//     to its centre, or four pyramids and four tetrahedra, its inner points
//     jittered: every pair of kinds that can shares faces. Against an independent
//     match (a map from sorted point ids to the cell faces on them): every
//     face seen twice is paired with its partner, every face seen once is a
//     boundary face; nothing folded or non-manifold; each cell's volume
//     (CellVolume6) positive, and without jitter summing to the lattice's;
//  2. three hexahedra on one quadrilateral (one below, two above): paired by
//     side, the below one with the first above; the other a boundary face;
//  3. two hexahedra on one side of their shared face: folded, the smaller
//     one inverted, the ray walking back in place from it;
//  4. a deforming mesh (ppiray::CellAdjacencyCache): the lattice of 1. with
//     its points moved (an inner point pushed through its neighbours, which
//     folds cells; then moved back) keeps its faces' pairs and finds only
//     the folds again, equal in every array to MatchCellFaces() of the moved
//     mesh (folds found, then none); the same cells with one flat, with one
//     cell's ids changed, or a mesh with a face of three cells (paired by
//     side) are matched again.

#include "ppirayCellAdjacency.h"
#include "ppirayInvertedSheets.h"
#include "ppirayLinearCellKinds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace
{
struct Mesh
{
  std::vector<double> Points;
  std::vector<vtkIdType> Corners; // 8 per cell
  std::vector<unsigned char> Kinds;

  vtkIdType AddPoint(double x, double y, double z)
  {
    this->Points.insert(this->Points.end(), { x, y, z });
    return static_cast<vtkIdType>(this->Points.size() / 3 - 1);
  }
  void AddCell(int kind, std::vector<vtkIdType> ids)
  {
    ids.resize(8, ids[0]);
    this->Corners.insert(this->Corners.end(), ids.begin(), ids.end());
    this->Kinds.push_back(static_cast<unsigned char>(kind));
  }
  ppiray::CellFaceMesh FaceMesh() const
  {
    return ppiray::LinearCellFaceMesh(static_cast<vtkIdType>(this->Points.size() / 3),
      this->Points.data(), this->Corners.data(), this->Kinds.data(),
      static_cast<vtkIdType>(this->Kinds.size()));
  }
};

// Cube (i, j, k) of an n^3 lattice (points (n + 1)^3, x fastest, then one
// centre point per cube) as cells of one of four decompositions.
void AddCube(Mesh& mesh, int n, int i, int j, int k, int decomposition)
{
  auto id = [&](int a, int b, int c)
  { return static_cast<vtkIdType>(a + (n + 1) * (b + (n + 1) * c)); };
  const vtkIdType c[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
    id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) };
  const vtkIdType centre = (n + 1) * (n + 1) * (n + 1) + i + n * (j + n * k);
  if (decomposition == 0)
  {
    mesh.AddCell(ppiray::HEXAHEDRON_KIND, std::vector<vtkIdType>(c, c + 8));
    return;
  }
  if (decomposition == 1) // split by the plane through c0, c2, c4, c6
  {
    mesh.AddCell(ppiray::WEDGE_KIND, { c[0], c[1], c[2], c[4], c[5], c[6] });
    mesh.AddCell(ppiray::WEDGE_KIND, { c[0], c[2], c[3], c[4], c[6], c[7] });
    return;
  }
  // A pyramid on each face (its base the face seen from inside); in the last
  // decomposition those on the bottom and top faces split into tetrahedra
  // along the diagonal through the face's smallest point id.
  const ppiray::LinearCellKindInfo& hexahedron = ppiray::LinearCellKindOf(ppiray::HEXAHEDRON_KIND);
  for (int f = 0; f < 6; ++f)
  {
    const int* q = hexahedron.Face[f];
    const vtkIdType base[4] = { c[q[3]], c[q[2]], c[q[1]], c[q[0]] };
    if (decomposition == 3 && f >= 4)
    {
      const int first = static_cast<int>(std::min_element(base, base + 4) - base) % 2;
      const vtkIdType a = base[first], b = base[first + 1], d = base[(first + 2) % 4],
                      e = base[(first + 3) % 4];
      mesh.AddCell(ppiray::TETRAHEDRON_KIND, { a, b, d, centre });
      mesh.AddCell(ppiray::TETRAHEDRON_KIND, { a, d, e, centre });
      continue;
    }
    mesh.AddCell(ppiray::PYRAMID_KIND, { base[0], base[1], base[2], base[3], centre });
  }
}

int CheckLattice(double amplitude)
{
  const int n = 4;
  Mesh mesh;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-amplitude, amplitude);
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        const bool inner = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        mesh.AddPoint(i + (inner ? jitter(random) : 0), j + (inner ? jitter(random) : 0),
          k + (inner ? jitter(random) : 0));
      }
    }
  }
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        mesh.AddPoint(i + 0.5, j + 0.5, k + 0.5);
      }
    }
  }
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        AddCube(mesh, n, i, j, k, (i / 2 + j + 2 * k) % 4);
      }
    }
  }
  const ppiray::CellFaceMesh faces = mesh.FaceMesh();
  const ppiray::CellAdjacency adjacency = ppiray::MatchCellFaces(faces);

  // The independent match.
  std::map<std::array<vtkIdType, 4>, std::vector<std::pair<vtkIdType, int>>> onFace;
  for (vtkIdType cell = 0; cell < faces.NumberOfCells; ++cell)
  {
    const ppiray::LinearCellKindInfo& kind = ppiray::LinearCellKindOf(mesh.Kinds[cell]);
    for (int f = 0; f < kind.Faces; ++f)
    {
      std::array<vtkIdType, 4> key;
      for (int v = 0; v < 4; ++v)
      {
        key[v] = kind.Face[f][v] < 0 ? -1 : mesh.Corners[8 * cell + kind.Face[f][v]];
      }
      std::sort(key.begin(), key.end());
      onFace[key].push_back({ cell, f });
    }
  }
  std::set<std::pair<int, int>> kindPairs;
  size_t boundary = 0, mismatches = 0;
  for (const auto& entry : onFace)
  {
    const auto& cells = entry.second;
    if (cells.size() == 1)
    {
      ++boundary;
      mismatches += adjacency.Neighbors[6 * cells[0].first + cells[0].second] == -1 ? 0 : 1;
      continue;
    }
    for (int s = 0; s < 2; ++s)
    {
      const auto& self = cells[s];
      const auto& other = cells[1 - s];
      mismatches += adjacency.Neighbors[6 * self.first + self.second] == other.first &&
                        adjacency.NeighborFaces[6 * self.first + self.second] == other.second
                      ? 0
                      : 1;
    }
    kindPairs.insert(std::minmax<int>(mesh.Kinds[cells[0].first], mesh.Kinds[cells[1].first]));
  }
  double volume6 = 0;
  vtkIdType negative = 0;
  for (vtkIdType cell = 0; cell < faces.NumberOfCells; ++cell)
  {
    const double v = ppiray::CellVolume6(ppiray::LinearCellKindOf(mesh.Kinds[cell]),
      mesh.Corners.data() + 8 * cell, mesh.Points.data());
    volume6 += v;
    negative += v > 0 ? 0 : 1;
  }
  std::cout << "lattice, jitter " << amplitude << ": " << faces.NumberOfCells << " cells, "
            << onFace.size() << " faces, " << boundary << " seen once, boundary "
            << adjacency.BoundaryFaces.size() / 2 << ", mismatches " << mismatches
            << ", kind pairs " << kindPairs.size() << " (";
  for (const auto& pair : kindPairs)
  {
    std::cout << " " << pair.first << pair.second;
  }
  std::cout << " ), folded " << adjacency.NumberOfFoldedFaces << ", non-manifold "
            << adjacency.NumberOfNonManifoldFaces << ", volume " << volume6 / 6 << ", negative "
            << negative << "\n";
  // Pairs of kinds that share faces: all ten but hexahedron-tetrahedron (a
  // hexahedron's faces are quadrilaterals, a tetrahedron's triangles).
  if (mismatches != 0 || adjacency.BoundaryFaces.size() / 2 != boundary || kindPairs.size() != 9 ||
      adjacency.NumberOfFoldedFaces != 0 || adjacency.NumberOfNonManifoldFaces != 0 ||
      negative != 0 || (amplitude == 0 && std::abs(volume6 / 6 - n * n * n) > 1e-9))
  {
    std::cerr << "lattice: the stage disagrees with the independent match\n";
    return 1;
  }
  return 0;
}

// The unit cube's corners at heights z0 (bottom, ids given) and z1 (top, new).
void AddBox(Mesh& mesh, const vtkIdType bottom[4], double z1, vtkIdType top[4])
{
  const double xy[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  for (int v = 0; v < 4; ++v)
  {
    top[v] = mesh.AddPoint(xy[v][0], xy[v][1], z1);
  }
  mesh.AddCell(ppiray::HEXAHEDRON_KIND,
    { bottom[0], bottom[1], bottom[2], bottom[3], top[0], top[1], top[2], top[3] });
}

// A = [0,1]^3, B above it to z = 2, C above it to z = 1.5: three hexahedra
// on A's top face.
Mesh ThreeOnAFace()
{
  Mesh mesh;
  vtkIdType base[4], middle[4], upper[4], other[4];
  for (int v = 0; v < 4; ++v)
  {
    base[v] = mesh.AddPoint(v == 1 || v == 2, v >= 2, 0);
  }
  AddBox(mesh, base, 1, middle);
  AddBox(mesh, middle, 2, upper);
  AddBox(mesh, middle, 1.5, other);
  return mesh;
}

int CheckSharedFaces()
{
  int failures = 0;
  const int top = 5, bottom = 4; // hexahedron faces z+ and z-
  {
    const Mesh mesh = ThreeOnAFace();
    const ppiray::CellAdjacency a = ppiray::MatchCellFaces(mesh.FaceMesh());
    const bool cBoundary =
      std::find(a.BoundaryFaces.begin(), a.BoundaryFaces.end(), 2) != a.BoundaryFaces.end();
    std::cout << "three on a face: non-manifold " << a.NumberOfNonManifoldFaces << ", A-top "
              << a.Neighbors[6 * 0 + top] << ", B-bottom " << a.Neighbors[6 * 1 + bottom]
              << ", C-bottom " << a.Neighbors[6 * 2 + bottom] << ", folded "
              << a.NumberOfFoldedFaces << "\n";
    if (a.NumberOfNonManifoldFaces != 3 || a.Neighbors[6 * 0 + top] != 1 ||
        a.Neighbors[6 * 1 + bottom] != 0 || a.Neighbors[6 * 2 + bottom] != -1 || !cBoundary ||
        a.NumberOfFoldedFaces != 0)
    {
      std::cerr << "three hexahedra on a face: not paired by side\n";
      ++failures;
    }
  }
  {
    // A = [0,1]^3 and D = [0,1]^2 x [0.5, 1] sharing A's top face as theirs.
    Mesh mesh;
    vtkIdType base[4], middle[4];
    for (int v = 0; v < 4; ++v)
    {
      base[v] = mesh.AddPoint(v == 1 || v == 2, v >= 2, 0);
    }
    AddBox(mesh, base, 1, middle);
    vtkIdType low[4];
    for (int v = 0; v < 4; ++v)
    {
      low[v] = mesh.AddPoint(v == 1 || v == 2, v >= 2, 0.5);
    }
    mesh.AddCell(ppiray::HEXAHEDRON_KIND,
      { low[0], low[1], low[2], low[3], middle[0], middle[1], middle[2], middle[3] });
    const ppiray::CellAdjacency a = ppiray::MatchCellFaces(mesh.FaceMesh());
    std::cout << "folded: folded faces " << a.NumberOfFoldedFaces << ", A-top "
              << a.Neighbors[6 * 0 + top] << " folded " << int(a.Folded[6 * 0 + top])
              << ", inverted " << int(a.Inverted[0]) << int(a.Inverted[1]) << "\n";
    if (a.NumberOfFoldedFaces != 1 || a.Neighbors[6 * 0 + top] != 1 ||
        a.Neighbors[6 * 1 + top] != 0 || !a.Folded[6 * 0 + top] || !a.Folded[6 * 1 + top] ||
        a.Inverted[0] || !a.Inverted[1] || !ppiray::WalksBackInPlace(a.Inverted, 1, 0) ||
        ppiray::WalksBackInPlace(a.Inverted, 0, 1))
    {
      std::cerr << "two hexahedra on one side of a face: not folded\n";
      ++failures;
    }
  }
  {
    // A pyramid written as a hexahedron (repeated corner ids: faces of two
    // distinct ids have no area) under a hexahedron sharing its slanted face.
    Mesh mesh;
    const double x[9][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 1, 1 },
      { 0, 0, 1.5 }, { 1, 0, 1.5 }, { 1, 1, 1.5 }, { 0, 1, 1.5 } };
    for (const auto& p : x)
    {
      mesh.AddPoint(p[0], p[1], p[2]);
    }
    mesh.AddCell(ppiray::HEXAHEDRON_KIND, { 3, 0, 1, 2, 4, 0, 1, 2 });
    mesh.AddCell(ppiray::HEXAHEDRON_KIND, { 0, 1, 2, 4, 5, 6, 7, 8 });
    const ppiray::CellAdjacency a = ppiray::MatchCellFaces(mesh.FaceMesh());
    std::cout << "pyramid as a hexahedron: slanted face's neighbour " << a.Neighbors[6 * 0 + top]
              << " face " << int(a.NeighborFaces[6 * 0 + top]) << ", boundary faces "
              << a.BoundaryFaces.size() / 2 << "\n";
    if (a.Neighbors[6 * 0 + top] != 1 || a.NeighborFaces[6 * 0 + top] != bottom ||
        a.Neighbors[6 * 1 + bottom] != 0 || a.BoundaryFaces.size() / 2 != 3 + 5)
    {
      std::cerr << "pyramid as a hexahedron: not matched to the hexahedron above\n";
      ++failures;
    }
  }
  return failures;
}

// Whether two adjacencies are equal in every array and count.
bool SameAdjacency(const ppiray::CellAdjacency& a, const ppiray::CellAdjacency& b)
{
  return a.Neighbors == b.Neighbors && a.NeighborFaces == b.NeighborFaces && a.Folded == b.Folded &&
         a.Inverted == b.Inverted && a.BoundaryFaces == b.BoundaryFaces &&
         a.NumberOfNonManifoldFaces == b.NumberOfNonManifoldFaces &&
         a.NumberOfFoldedFaces == b.NumberOfFoldedFaces && a.ByIds == b.ByIds;
}

// One update of the cache: the number of errors (not kept where `kept`, or
// kept where not; any array unlike MatchCellFaces()'s).
int ExpectUpdate(ppiray::CellAdjacencyCache& cache, const ppiray::CellFaceMesh& mesh, bool kept,
  const char* step, vtkIdType* folded = nullptr)
{
  const ppiray::CellAdjacency& a = cache.Update(mesh);
  const ppiray::CellAdjacency fresh = ppiray::MatchCellFaces(mesh);
  std::cout << "deforming, " << step << ": kept " << cache.WasKept() << ", folded faces "
            << a.NumberOfFoldedFaces << " (fresh " << fresh.NumberOfFoldedFaces << ")\n";
  if (folded)
  {
    *folded = a.NumberOfFoldedFaces;
  }
  if (cache.WasKept() != kept || !SameAdjacency(a, fresh))
  {
    std::cerr << "deforming, " << step << ": expected " << (kept ? "kept" : "matched again")
              << " and equal to MatchCellFaces()\n";
    return 1;
  }
  return 0;
}

int CheckDeforming()
{
  const int n = 4;
  Mesh mesh;
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        mesh.AddPoint(i, j, k);
      }
    }
  }
  for (int c = 0; c < n * n * n; ++c)
  {
    mesh.AddPoint(c % n + 0.5, (c / n) % n + 0.5, c / (n * n) + 0.5);
  }
  for (int c = 0; c < n * n * n; ++c)
  {
    AddCube(mesh, n, c % n, (c / n) % n, c / (n * n), c % 4);
  }
  int failures = 0;
  ppiray::CellAdjacencyCache cache;
  failures += ExpectUpdate(cache, mesh.FaceMesh(), false, "first");
  // Lattice point (2, 2, 2) pushed through the cells beside it, to
  // (4, 2.4, 2.7): cells turn inside out, folding faces.
  const vtkIdType pushed = 2 + (n + 1) * (2 + (n + 1) * 2);
  const std::vector<double> original = mesh.Points;
  mesh.Points[3 * pushed] += 2.0;
  mesh.Points[3 * pushed + 1] += 0.4;
  mesh.Points[3 * pushed + 2] += 0.7;
  vtkIdType folded = 0;
  failures += ExpectUpdate(cache, mesh.FaceMesh(), true, "a point pushed through", &folded);
  if (folded == 0)
  {
    std::cerr << "deforming: pushing a point through its neighbours folded nothing\n";
    ++failures;
  }
  mesh.Points = original;
  failures += ExpectUpdate(cache, mesh.FaceMesh(), true, "moved back", &folded);
  failures += folded == 0 ? 0 : 1;

  std::vector<unsigned char> flat(mesh.Kinds.size(), 0);
  flat[5] = 1;
  ppiray::CellFaceMesh withFlat = mesh.FaceMesh();
  withFlat.Flat = flat.data();
  failures += ExpectUpdate(cache, withFlat, false, "a flat cell");
  failures += ExpectUpdate(cache, withFlat, false, "a flat cell again");
  failures += ExpectUpdate(cache, mesh.FaceMesh(), false, "no flat cell");
  std::swap(mesh.Corners[8 * 3], mesh.Corners[8 * 3 + 1]);
  failures += ExpectUpdate(cache, mesh.FaceMesh(), false, "a cell's ids changed");

  Mesh three = ThreeOnAFace();
  ppiray::CellAdjacencyCache threeCache;
  failures += ExpectUpdate(threeCache, three.FaceMesh(), false, "three on a face");
  three.Points.back() += 0.1; // a top corner of C
  failures += ExpectUpdate(threeCache, three.FaceMesh(), false, "three on a face, moved");
  return failures;
}
}

int TestCellAdjacency(int, char*[])
{
  // Unjittered, the cells' volumes sum to the lattice's; jittered, shared
  // quadrilaterals are not planar and the two cells on one fan it from
  // different corners, so only the signs are checked.
  const int failures = CheckLattice(0) + CheckLattice(0.15) + CheckSharedFaces() + CheckDeforming();
  return failures == 0 ? 0 : 1;
}
