#include "ppirayNonConformingFaces.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace
{
using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;

// An edge by its point ids, the smaller first.
using Edge = std::array<vtkIdType, 2>;

Edge EdgeOf(vtkIdType p, vtkIdType q)
{
  return { std::min(p, q), std::max(p, q) };
}

// An edge's ids (each below 2^32) in one key.
std::uint64_t Packed(const Edge& e)
{
  return (static_cast<std::uint64_t>(e[0]) << 32) | static_cast<std::uint64_t>(e[1]);
}

// Whether some corners of `faces` are at the same places with other ids;
// then `merged` is `faces` with each such corner's id replaced by the
// smallest id at its place.
bool MergedPlaces(const double* points, const std::vector<ppiray::OpenFace>& faces,
  std::vector<ppiray::OpenFace>& merged)
{
  std::vector<vtkIdType> ids;
  for (const ppiray::OpenFace& face : faces)
  {
    ids.insert(ids.end(), face.Points.begin(), face.Points.begin() + 3 * face.Triangles);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  auto placeOf = [&](vtkIdType id) {
    return std::array<double, 3>{ points[3 * id], points[3 * id + 1], points[3 * id + 2] };
  };
  std::vector<vtkIdType> byPlace = ids;
  std::sort(byPlace.begin(), byPlace.end(),
    [&](vtkIdType a, vtkIdType b)
    {
      const auto pa = placeOf(a), pb = placeOf(b);
      return pa != pb ? pa < pb : a < b;
    });
  std::vector<std::pair<vtkIdType, vtkIdType>> renamed; // id, smallest id at its place
  for (size_t k = 1; k < byPlace.size(); ++k)
  {
    if (placeOf(byPlace[k]) == placeOf(byPlace[k - 1]))
    {
      const vtkIdType first = renamed.empty() || renamed.back().first != byPlace[k - 1]
                                ? byPlace[k - 1]
                                : renamed.back().second;
      renamed.push_back({ byPlace[k], first });
    }
  }
  if (renamed.empty())
  {
    return false;
  }
  std::sort(renamed.begin(), renamed.end());
  merged = faces;
  for (ppiray::OpenFace& face : merged)
  {
    for (int v = 0; v < 3 * face.Triangles; ++v)
    {
      auto found = std::lower_bound(
        renamed.begin(), renamed.end(), std::make_pair(face.Points[v], vtkIdType(-1)));
      face.Points[v] =
        found != renamed.end() && found->first == face.Points[v] ? found->second : face.Points[v];
    }
  }
  return true;
}

// No face matched to any.
ppiray::FaceOverlaps NoOverlaps(vtkIdType count)
{
  ppiray::FaceOverlaps none;
  none.Offsets.assign(count + 1, 0);
  none.Covered.assign(count, 0);
  return none;
}

// Plane, size and bounds of an open face.
struct FaceGeometry
{
  Vec3 Normal{ 0.0 }; // unit, outward
  double Offset = 0;  // Normal . x on the plane
  double Area = 0;
  double Diameter = 0; // of its bounding box
  Vec3 Lo{ 0.0 }, Hi{ 0.0 };
  bool Planar = false;
};

Vec3 PointOf(const double* points, vtkIdType id)
{
  return Vec3(points[3 * id], points[3 * id + 1], points[3 * id + 2]);
}

// Area vector sum_t (b - a) x (c - a) / 2 over the face's triangles; the
// face is planar when every corner lies within 1e-5 of its diameter of the
// plane through their centre.
FaceGeometry Measure(const double* points, const ppiray::OpenFace& face)
{
  FaceGeometry g;
  const int corners = 3 * face.Triangles;
  Vec3 area(0.0), centre(0.0);
  g.Lo = g.Hi = PointOf(points, face.Points[0]);
  for (int t = 0; t < face.Triangles; ++t)
  {
    const Vec3 a = PointOf(points, face.Points[3 * t]), b = PointOf(points, face.Points[3 * t + 1]),
               c = PointOf(points, face.Points[3 * t + 2]);
    area += 0.5 * glm::cross(b - a, c - a);
  }
  for (int v = 0; v < corners; ++v)
  {
    const Vec3 x = PointOf(points, face.Points[v]);
    centre += x / static_cast<double>(corners);
    g.Lo = glm::min(g.Lo, x);
    g.Hi = glm::max(g.Hi, x);
  }
  g.Area = glm::length(area);
  g.Diameter = glm::length(g.Hi - g.Lo);
  if (!(g.Area > 0))
  {
    return g;
  }
  g.Normal = area / g.Area;
  g.Offset = glm::dot(g.Normal, centre);
  g.Planar = true;
  for (int v = 0; v < corners; ++v)
  {
    const double off = glm::dot(g.Normal, PointOf(points, face.Points[v])) - g.Offset;
    g.Planar = g.Planar && std::abs(off) <= 1e-5 * g.Diameter;
  }
  return g;
}

// Twice the signed area of triangle (a, b, c) in the plane.
double Cross2(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Area of the intersection of two triangles in the plane: a clipped by the
// three half-planes of b (Sutherland-Hodgman; b counter-clockwise), then the
// shoelace formula.
double TriangleOverlap(const Vec2 a[3], Vec2 b[3])
{
  if (Cross2(b[0], b[1], b[2]) < 0)
  {
    std::swap(b[1], b[2]);
  }
  Vec2 polygon[9], clipped[9];
  int n = 3;
  std::copy(a, a + 3, polygon);
  for (int e = 0; e < 3 && n > 0; ++e)
  {
    const Vec2 p = b[e], q = b[(e + 1) % 3];
    int m = 0;
    for (int i = 0; i < n; ++i)
    {
      const Vec2 x = polygon[i], y = polygon[(i + 1) % n];
      const double sx = Cross2(p, q, x), sy = Cross2(p, q, y);
      if (sx >= 0)
      {
        clipped[m++] = x;
      }
      if ((sx >= 0) != (sy >= 0))
      {
        clipped[m++] = x + (sx / (sx - sy)) * (y - x);
      }
    }
    n = std::min(m, 9);
    std::copy(clipped, clipped + n, polygon);
  }
  double twice = 0;
  for (int i = 0; i < n; ++i)
  {
    twice += polygon[i].x * polygon[(i + 1) % n].y - polygon[(i + 1) % n].x * polygon[i].y;
  }
  return 0.5 * std::abs(twice);
}

// Area of the overlap of faces a and b projected on a's plane.
double FaceOverlap(const double* points, const ppiray::OpenFace& a, const ppiray::OpenFace& b,
  const FaceGeometry& ga)
{
  const Vec3 n = ga.Normal;
  const Vec3 u = glm::normalize(
    std::abs(n.x) < 0.6 ? glm::cross(n, Vec3(1, 0, 0)) : glm::cross(n, Vec3(0, 1, 0)));
  const Vec3 v = glm::cross(n, u);
  auto project = [&](vtkIdType id)
  {
    const Vec3 x = PointOf(points, id);
    return Vec2(glm::dot(u, x), glm::dot(v, x));
  };
  double overlap = 0;
  for (int s = 0; s < a.Triangles; ++s)
  {
    const Vec2 ta[3] = { project(a.Points[3 * s]), project(a.Points[3 * s + 1]),
      project(a.Points[3 * s + 2]) };
    for (int t = 0; t < b.Triangles; ++t)
    {
      Vec2 tb[3] = { project(b.Points[3 * t]), project(b.Points[3 * t + 1]),
        project(b.Points[3 * t + 2]) };
      overlap += TriangleOverlap(ta, tb);
    }
  }
  return overlap;
}

// Whether faces a and b (other cells) face each other in one plane.
bool FaceEachOther(
  const double* points, const ppiray::OpenFace& b, const FaceGeometry& ga, const FaceGeometry& gb)
{
  if (!ga.Planar || !gb.Planar || !(glm::dot(ga.Normal, gb.Normal) < -(1 - 1e-6)))
  {
    return false;
  }
  const double tolerance = 1e-5 * std::max(ga.Diameter, gb.Diameter);
  for (int v = 0; v < 3 * b.Triangles; ++v)
  {
    if (std::abs(glm::dot(ga.Normal, PointOf(points, b.Points[v])) - ga.Offset) > tolerance)
    {
      return false;
    }
  }
  return true;
}

// One side of a quadrilateral split into two triangles: its open faces
// (one of two triangles, or two of one; -1: none), their cells, its two
// triangles' point ids, its corners' (sorted) and the ends of the diagonal
// the triangles share and of the other.
struct Quadrilateral
{
  std::array<vtkIdType, 4> Corners;
  std::array<vtkIdType, 2> Faces;
  std::array<vtkIdType, 2> Cells;
  std::array<vtkIdType, 6> Ids;
  Edge Diagonal, Other;
  Vec3 Area{ 0.0 };    // IsSide()
  vtkIdType Apex = -1; // a corner of a cell of the side off it (OpenFace::Apex)
};

// The side made of the two triangles at ids[0..6) if they have four distinct
// corners and share an edge.
bool QuadrilateralOf(const vtkIdType ids[6], Quadrilateral& q)
{
  std::copy(ids, ids + 6, q.Ids.begin());
  std::array<vtkIdType, 6> sorted = q.Ids;
  std::sort(sorted.begin(), sorted.end());
  if (std::unique(sorted.begin(), sorted.end()) - sorted.begin() != 4)
  {
    return false;
  }
  std::copy(sorted.begin(), sorted.begin() + 4, q.Corners.begin());
  // The diagonal: the corners in both triangles; the other: in one each.
  vtkIdType shared[2] = { -1, -1 }, single[2] = { -1, -1 };
  int nShared = 0, nSingle = 0;
  for (const vtkIdType c : q.Corners)
  {
    const bool first = std::find(ids, ids + 3, c) != ids + 3;
    const bool second = std::find(ids + 3, ids + 6, c) != ids + 6;
    if (first && second && nShared < 2)
    {
      shared[nShared++] = c;
    }
    else if (first != second && nSingle < 2)
    {
      single[nSingle++] = c;
    }
  }
  if (nShared != 2 || nSingle != 2)
  {
    return false;
  }
  q.Diagonal = EdgeOf(shared[0], shared[1]);
  q.Other = EdgeOf(single[0], single[1]);
  return true;
}

// Whether a quadrilateral's two triangles have area and lie within 60
// degrees of each other (unit normals' dot product above 1/2): one side of
// a surface, not two faces at a sharp edge; fills its area vector, the sum of
// (b - a) x (c - a) / 2.
bool IsSide(const double* points, Quadrilateral& q)
{
  Vec3 areas[2];
  for (int t = 0; t < 2; ++t)
  {
    const Vec3 a = PointOf(points, q.Ids[3 * t]), b = PointOf(points, q.Ids[3 * t + 1]),
               c = PointOf(points, q.Ids[3 * t + 2]);
    areas[t] = 0.5 * glm::cross(b - a, c - a);
  }
  const double l0 = glm::length(areas[0]), l1 = glm::length(areas[1]);
  q.Area = areas[0] + areas[1];
  return l0 > 0 && l1 > 0 && glm::dot(areas[0], areas[1]) > 0.5 * l0 * l1;
}

// The corner of a one-triangle face not on edge e.
vtkIdType OppositeCorner(const ppiray::OpenFace& face, const Edge& e)
{
  for (int v = 0; v < 3; ++v)
  {
    if (face.Points[v] != e[0] && face.Points[v] != e[1])
    {
      return face.Points[v];
    }
  }
  return -1;
}

// Whether one-triangle faces a and b, sharing the edge (p, q), are wound
// alike (the edge runs the other way in b).
bool WoundAlike(const ppiray::OpenFace& a, const ppiray::OpenFace& b, vtkIdType p, vtkIdType q)
{
  auto runs = [](const ppiray::OpenFace& face, vtkIdType from, vtkIdType to)
  {
    for (int e = 0; e < 3; ++e)
    {
      if (face.Points[e] == from && face.Points[(e + 1) % 3] == to)
      {
        return true;
      }
    }
    return false;
  };
  return runs(a, p, q) ? runs(b, q, p) : (runs(a, q, p) && runs(b, p, q));
}

// Whether side a's cell lies beyond side b: its apex on b's outer side
// (A . (x - c) > 0, A b's area vector, c its corners' mean; true where no
// apex is given).
bool Beyond(const double* points, const Quadrilateral& a, const Quadrilateral& b)
{
  if (a.Apex < 0)
  {
    return true;
  }
  Vec3 centre(0.0);
  for (int v = 0; v < 6; ++v)
  {
    centre += PointOf(points, b.Ids[v]) / 6.0;
  }
  return glm::dot(b.Area, PointOf(points, a.Apex) - centre) > 0.0;
}

// Whether two sides with the same corners face each other across a lens
// (of zero thickness where they are split alike: a quadrilateral face
// against two triangles): area vectors opposite, no cell on both sides,
// each side's cell beyond the other.
bool AcrossLens(const double* points, const Quadrilateral& a, const Quadrilateral& b)
{
  for (const vtkIdType c : a.Cells)
  {
    if (c == b.Cells[0] || c == b.Cells[1])
    {
      return false;
    }
  }
  return glm::dot(a.Area, b.Area) < 0.0 && Beyond(points, a, b) && Beyond(points, b, a);
}

// Buckets of a uniform grid holding the faces whose bounds meet them.
struct FaceGrid
{
  double Cell = 1;
  double Grow = 0; // bounds grown by this much (1e-5 of the largest diameter)
  Vec3 Origin{ 0.0 };
  std::unordered_map<std::uint64_t, std::vector<vtkIdType>> Buckets;

  glm::i64vec3 Index(const Vec3& x) const
  {
    return glm::i64vec3(glm::floor((x - this->Origin) / this->Cell));
  }
  static std::uint64_t Key(const glm::i64vec3& i)
  {
    return (static_cast<std::uint64_t>(i.x) & 0x1FFFFF) |
           ((static_cast<std::uint64_t>(i.y) & 0x1FFFFF) << 21) |
           ((static_cast<std::uint64_t>(i.z) & 0x1FFFFF) << 42);
  }
};

// Buckets of a face's bounds (slightly grown), or none when they are more
// than 4096 (a face far larger than the others is not matched).
bool BucketRange(const FaceGrid& grid, const FaceGeometry& g, glm::i64vec3& lo, glm::i64vec3& hi)
{
  lo = grid.Index(g.Lo - Vec3(grid.Grow));
  hi = grid.Index(g.Hi + Vec3(grid.Grow));
  const glm::i64vec3 count = hi - lo + glm::i64vec3(1);
  return count.x * count.y * count.z <= 4096;
}
}

namespace ppiray
{
//------------------------------------------------------------------------------
FaceOverlaps MatchNonConformingFaces(const double* points, const std::vector<OpenFace>& faces)
{
  const vtkIdType count = static_cast<vtkIdType>(faces.size());
  std::vector<FaceGeometry> geometry(count);
  FaceGrid grid;
  vtkIdType measured = 0;
  for (vtkIdType i = 0; i < count; ++i)
  {
    geometry[i] = Measure(points, faces[i]);
    if (geometry[i].Planar)
    {
      grid.Grow = std::max(grid.Grow, 1e-5 * geometry[i].Diameter);
      grid.Origin = measured++ == 0 ? geometry[i].Lo : glm::min(grid.Origin, geometry[i].Lo);
    }
  }
  FaceOverlaps result;
  result.Covered.assign(count, 0);
  if (measured == 0)
  {
    result.Offsets.assign(count + 1, 0);
    return result;
  }
  std::vector<double> sizes;
  for (const FaceGeometry& g : geometry)
  {
    if (g.Planar)
    {
      sizes.push_back(g.Diameter);
    }
  }
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  grid.Cell = std::max(2.0 * sizes[sizes.size() / 2], 1e-300);
  grid.Origin -= Vec3(grid.Cell);
  for (vtkIdType i = 0; i < count; ++i)
  {
    glm::i64vec3 lo, hi;
    if (!geometry[i].Planar || !BucketRange(grid, geometry[i], lo, hi))
    {
      continue;
    }
    for (auto z = lo.z; z <= hi.z; ++z)
      for (auto y = lo.y; y <= hi.y; ++y)
        for (auto x = lo.x; x <= hi.x; ++x)
          grid.Buckets[FaceGrid::Key({ x, y, z })].push_back(i);
  }
  // Each pair once: in the bucket of the lower corner of their bounds'
  // intersection.
  std::vector<std::array<vtkIdType, 2>> pairs;
  std::vector<double> overlaps;
  for (const auto& bucket : grid.Buckets)
  {
    const std::vector<vtkIdType>& ids = bucket.second;
    for (size_t p = 0; p < ids.size(); ++p)
    {
      for (size_t q = p + 1; q < ids.size(); ++q)
      {
        const vtkIdType i = ids[p], j = ids[q];
        const FaceGeometry &gi = geometry[i], &gj = geometry[j];
        const Vec3 lo = glm::max(gi.Lo, gj.Lo) - Vec3(grid.Grow);
        const Vec3 hi = glm::min(gi.Hi, gj.Hi) + Vec3(grid.Grow);
        if (faces[i].Cell == faces[j].Cell || glm::any(glm::greaterThan(lo, hi)) ||
            FaceGrid::Key(grid.Index(lo)) != bucket.first ||
            !FaceEachOther(points, faces[j], gi, gj) || !FaceEachOther(points, faces[i], gj, gi))
        {
          continue;
        }
        const double overlap = FaceOverlap(points, faces[i], faces[j], gi);
        if (overlap > 1e-6 * std::min(gi.Area, gj.Area))
        {
          pairs.push_back({ i, j });
          overlaps.push_back(overlap);
        }
      }
    }
  }
  // Per face, in face order: the faces across and how much of it they cover.
  std::vector<vtkIdType> counts(count + 1, 0);
  std::vector<double> covered(count, 0.0);
  for (size_t k = 0; k < pairs.size(); ++k)
  {
    for (int s = 0; s < 2; ++s)
    {
      ++counts[pairs[k][s] + 1];
      covered[pairs[k][s]] += overlaps[k];
    }
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    counts[i + 1] += counts[i];
    result.Covered[i] = covered[i] >= (1 - 1e-5) * geometry[i].Area ? 1 : 0;
  }
  result.Offsets = counts;
  result.Across.resize(counts[count]);
  std::vector<vtkIdType> fill(counts.begin(), counts.end() - 1);
  for (const auto& pair : pairs)
  {
    result.Across[fill[pair[0]]++] = pair[1];
    result.Across[fill[pair[1]]++] = pair[0];
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    std::sort(
      result.Across.begin() + result.Offsets[i], result.Across.begin() + result.Offsets[i + 1]);
  }
  return result;
}

//------------------------------------------------------------------------------
std::vector<vtkIdType> PairCoincidentFaces(const double* points, const std::vector<OpenFace>& faces)
{
  // Key: the face's distinct corners' places, sorted (a triangle's fourth is +inf).
  using Place = std::array<double, 3>;
  using Key = std::array<Place, 4>;
  const vtkIdType count = static_cast<vtkIdType>(faces.size());
  std::vector<Key> keys(count);
  std::vector<Vec3> areas(count, Vec3(0.0));
  for (vtkIdType i = 0; i < count; ++i)
  {
    const OpenFace& face = faces[i];
    std::array<vtkIdType, 6> ids = face.Points;
    std::sort(ids.begin(), ids.begin() + 3 * face.Triangles);
    const auto end = std::unique(ids.begin(), ids.begin() + 3 * face.Triangles);
    keys[i].fill(Place{ HUGE_VAL, HUGE_VAL, HUGE_VAL });
    for (auto id = ids.begin(); id != end && id - ids.begin() < 4; ++id)
    {
      keys[i][id - ids.begin()] = { points[3 * *id], points[3 * *id + 1], points[3 * *id + 2] };
    }
    std::sort(keys[i].begin(), keys[i].end());
    for (int t = 0; t < face.Triangles; ++t)
    {
      const Vec3 a = PointOf(points, face.Points[3 * t]),
                 b = PointOf(points, face.Points[3 * t + 1]),
                 c = PointOf(points, face.Points[3 * t + 2]);
      areas[i] += glm::cross(b - a, c - a);
    }
  }
  std::vector<vtkIdType> order(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    order[i] = i;
  }
  std::sort(
    order.begin(), order.end(), [&](vtkIdType a, vtkIdType b) { return keys[a] < keys[b]; });
  std::vector<vtkIdType> partner(count, -1);
  for (vtkIdType k = 0; k < count;)
  {
    vtkIdType n = 1;
    while (k + n < count && keys[order[k + n]] == keys[order[k]])
    {
      ++n;
    }
    const vtkIdType a = order[k], b = order[k + 1 < count ? k + 1 : k];
    if (n == 2 && faces[a].Cell != faces[b].Cell && glm::dot(areas[a], areas[b]) < 0.0)
    {
      partner[a] = b;
      partner[b] = a;
    }
    k += n;
  }
  return partner;
}

//------------------------------------------------------------------------------
FaceOverlaps MatchSplitQuadrilaterals(const double* points, const std::vector<OpenFace>& given)
{
  // Ids must fit 32 bits (edges are packed in 64; else no lenses matched).
  const vtkIdType count = static_cast<vtkIdType>(given.size());
  for (const OpenFace& face : given)
  {
    for (int v = 0; v < 3 * face.Triangles; ++v)
    {
      if (face.Points[v] < 0 || static_cast<std::uint64_t>(face.Points[v]) > UINT32_MAX)
      {
        return NoOverlaps(count);
      }
    }
  }
  // Points at the same places as one id (a seam's duplicated points).
  std::vector<OpenFace> merged;
  const std::vector<OpenFace>& faces = MergedPlaces(points, given, merged) ? merged : given;
  // The edges of one-triangle faces (point ids packed in 64 bits), sorted,
  // with their faces (the two triangles of a side share one), and the
  // diagonals of faces of two.
  std::vector<std::pair<std::uint64_t, vtkIdType>> edges;
  std::vector<std::uint64_t> splits;
  edges.reserve(3 * faces.size());
  for (vtkIdType i = 0; i < count; ++i)
  {
    const OpenFace& face = faces[i];
    Quadrilateral q;
    if (face.Triangles == 2 && QuadrilateralOf(face.Points.data(), q))
    {
      splits.push_back(Packed(q.Diagonal));
    }
    for (int e = 0; face.Triangles == 1 && e < 3; ++e)
    {
      edges.push_back({ Packed(EdgeOf(face.Points[e], face.Points[(e + 1) % 3])), i });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::sort(splits.begin(), splits.end());
  auto isEdge = [&](const Edge& e)
  {
    const std::uint64_t key = Packed(e);
    auto found = std::lower_bound(
      edges.begin(), edges.end(), key, [](const auto& a, std::uint64_t k) { return a.first < k; });
    return found != edges.end() && found->first == key;
  };
  auto isSplit = [&](const Edge& e)
  { return std::binary_search(splits.begin(), splits.end(), Packed(e)); };
  // The sides. A side can face another only where its other diagonal is an
  // edge of open triangles too or splits a face of two, or its own diagonal
  // splits one (a face of two against two triangles): the sides of a
  // boundary surface are not built.
  std::vector<Quadrilateral> sides;
  for (vtkIdType i = 0; i < count; ++i)
  {
    Quadrilateral q;
    if (faces[i].Triangles == 2 && QuadrilateralOf(faces[i].Points.data(), q) &&
        (isEdge(q.Diagonal) || isEdge(q.Other)) && IsSide(points, q))
    {
      q.Faces = { i, -1 };
      q.Cells = { faces[i].Cell, faces[i].Cell };
      q.Apex = faces[i].Apex;
      sides.push_back(q);
    }
  }
  for (size_t k = 0; k < edges.size();)
  {
    size_t n = 1;
    while (k + n < edges.size() && edges[k + n].first == edges[k].first)
    {
      ++n;
    }
    const Edge diagonal = { static_cast<vtkIdType>(edges[k].first >> 32),
      static_cast<vtkIdType>(edges[k].first & 0xFFFFFFFFull) };
    const vtkIdType a = edges[k].second, b = edges[k + n - 1].second;
    k += n;
    if (n != 2)
    {
      continue;
    }
    const Edge other =
      EdgeOf(OppositeCorner(faces[a], diagonal), OppositeCorner(faces[b], diagonal));
    const vtkIdType ids[6] = { faces[a].Points[0], faces[a].Points[1], faces[a].Points[2],
      faces[b].Points[0], faces[b].Points[1], faces[b].Points[2] };
    Quadrilateral q;
    if ((isEdge(other) || isSplit(other) || isSplit(diagonal)) &&
        WoundAlike(faces[a], faces[b], diagonal[0], diagonal[1]) && QuadrilateralOf(ids, q) &&
        IsSide(points, q))
    {
      q.Faces = { a, b };
      q.Cells = { faces[a].Cell, faces[b].Cell };
      q.Apex = faces[a].Apex;
      sides.push_back(q);
    }
  }
  std::sort(sides.begin(), sides.end(),
    [](const Quadrilateral& a, const Quadrilateral& b) { return a.Corners < b.Corners; });
  // The matches (pairs of sides), then per face the faces across; a match
  // with a face in another is left alone as a whole.
  std::vector<std::array<size_t, 2>> pairs;
  std::vector<unsigned char> matches(count, 0);
  for (size_t k = 0; k < sides.size();)
  {
    size_t n = 1;
    while (k + n < sides.size() && sides[k + n].Corners == sides[k].Corners)
    {
      ++n;
    }
    if (n == 2 && AcrossLens(points, sides[k], sides[k + 1]))
    {
      pairs.push_back({ k, k + 1 });
      for (size_t s = k; s < k + 2; ++s)
      {
        for (const vtkIdType f : sides[s].Faces)
        {
          if (f >= 0 && matches[f] < 2)
          {
            ++matches[f];
          }
        }
      }
    }
    k += n;
  }
  std::vector<std::array<vtkIdType, 2>> across(count, { -1, -1 });
  std::vector<unsigned char> linked(count, 0);
  for (const auto& pair : pairs)
  {
    bool alone = true;
    for (const size_t s : pair)
    {
      for (const vtkIdType f : sides[s].Faces)
      {
        alone = alone && (f < 0 || matches[f] == 1);
      }
    }
    for (int s = 0; alone && s < 2; ++s)
    {
      for (const vtkIdType f : sides[pair[s]].Faces)
      {
        if (f >= 0)
        {
          across[f] = sides[pair[1 - s]].Faces;
          linked[f] = 1;
        }
      }
    }
  }
  FaceOverlaps result;
  result.Covered.assign(count, 0);
  result.Offsets.assign(count + 1, 0);
  for (vtkIdType i = 0; i < count; ++i)
  {
    result.Offsets[i + 1] = result.Offsets[i];
    if (!linked[i])
    {
      continue;
    }
    result.Covered[i] = 1;
    for (const vtkIdType f : across[i])
    {
      if (f >= 0)
      {
        result.Across.push_back(f);
        ++result.Offsets[i + 1];
      }
    }
  }
  return result;
}

//------------------------------------------------------------------------------
int AppendFaceList(
  std::vector<int>& neighbors, const std::vector<int>& codes, int listBase, bool lens)
{
  const int code = listBase + static_cast<int>(neighbors.size() / 4);
  neighbors.push_back(static_cast<int>(codes.size()) + (lens ? LensList() : 0));
  neighbors.insert(neighbors.end(), codes.begin(), codes.end());
  neighbors.resize(4 * ((neighbors.size() + 3) / 4), -1);
  return code;
}
}
