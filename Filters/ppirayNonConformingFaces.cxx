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
int AppendFaceList(std::vector<int>& neighbors, const std::vector<int>& codes, int listBase)
{
  const int code = listBase + static_cast<int>(neighbors.size() / 4);
  neighbors.push_back(static_cast<int>(codes.size()));
  neighbors.insert(neighbors.end(), codes.begin(), codes.end());
  neighbors.resize(4 * ((neighbors.size() + 3) / 4), -1);
  return code;
}
}
