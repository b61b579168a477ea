#include "ppirayReflexEdges.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace
{
using glm::dvec3;

constexpr double Pi = 3.14159265358979323846;

dvec3 Point(const std::vector<float>& points, unsigned int i)
{
  return dvec3(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
}

// One triangle at an edge: its index, which edge, and its angle about it.
struct Wing
{
  int Triangle;
  int Edge;
  double Angle; // of the triangle's half-plane about the edge, in [-pi, pi]
  double Turn;  // +1: the empty side lies at increasing angles, else -1
};
}

namespace ppiray
{
//------------------------------------------------------------------------------
std::vector<int> ReflexEdgePartners(
  const std::vector<float>& points, const std::vector<unsigned int>& triangles)
{
  const size_t n = triangles.size() / 3;
  std::vector<int> partners(3 * n, -1);
  // Edges (smaller index, larger index, triangle, edge), sorted to group them.
  std::vector<std::pair<std::uint64_t, std::pair<int, int>>> edges;
  edges.reserve(3 * n);
  for (size_t k = 0; k < n; ++k)
  {
    for (int e = 0; e < 3; ++e)
    {
      const std::uint64_t a = triangles[3 * k + e], b = triangles[3 * k + (e + 1) % 3];
      edges.push_back({ (std::min(a, b) << 32) | std::max(a, b), { static_cast<int>(k), e } });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<Wing> wings;
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first)
    {
      ++j;
    }
    if (j - i < 2)
    {
      i = j;
      continue;
    }
    // A frame about the edge a -> b: axis u, (x, y) across it.
    const unsigned int ia = static_cast<unsigned int>(edges[i].first >> 32);
    const unsigned int ib = static_cast<unsigned int>(edges[i].first & 0xffffffffu);
    const dvec3 a = Point(points, ia), b = Point(points, ib);
    const dvec3 u = glm::normalize(b - a);
    const dvec3 helper = std::abs(u.x) < 0.6 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    const dvec3 x = glm::normalize(glm::cross(u, helper));
    const dvec3 y = glm::cross(u, x);
    wings.clear();
    for (size_t m = i; m < j; ++m)
    {
      const int k = edges[m].second.first, e = edges[m].second.second;
      const dvec3 p0 = Point(points, triangles[3 * k]), p1 = Point(points, triangles[3 * k + 1]),
                  p2 = Point(points, triangles[3 * k + 2]);
      const dvec3 normal = glm::cross(p1 - p0, p2 - p0); // outward
      const dvec3 opposite = Point(points, triangles[3 * k + (e + 2) % 3]) - a;
      const dvec3 w = opposite - glm::dot(opposite, u) * u; // into the triangle, across the edge
      if (!(glm::length(w) > 0.0) || !(glm::length(normal) > 0.0))
      {
        continue; // no area: no side
      }
      // Turning w about u by +90 degrees gives u x w; the normal lies on that
      // side or the other.
      wings.push_back({ k, e, std::atan2(glm::dot(w, y), glm::dot(w, x)),
        glm::dot(normal, glm::cross(u, w)) > 0.0 ? 1.0 : -1.0 });
    }
    for (const Wing& from : wings)
    {
      // The next wing turning towards the normal: the smallest turn in (0, 2 pi).
      double best = 2.0 * Pi;
      int partner = -1;
      for (const Wing& to : wings)
      {
        if (to.Triangle == from.Triangle)
        {
          continue;
        }
        double turn = from.Turn * (to.Angle - from.Angle);
        turn = std::fmod(turn + 4.0 * Pi, 2.0 * Pi);
        if (turn < best)
        {
          best = turn;
          partner = to.Triangle;
        }
      }
      // A reflex edge leaves less than a half-turn empty (a crack: none).
      if (partner >= 0 && best < Pi * (1.0 - 1e-9))
      {
        partners[3 * from.Triangle + from.Edge] = partner;
      }
    }
    i = j;
  }
  return partners;
}

//------------------------------------------------------------------------------
int ListReentryFaces(const std::vector<float>& points, const std::vector<unsigned int>& triangles,
  const std::vector<int>& faceOf, const std::function<size_t(int face)>& slotOf, int reentryFace,
  std::vector<int>& neighbors)
{
  const std::vector<int> partners = ReflexEdgePartners(points, triangles);
  // Each face's partners over its triangles' edges, in the order met.
  std::map<int, std::array<int, 4>> across;
  for (size_t k = 0; k < faceOf.size(); ++k)
  {
    for (int e = 0; e < 3; ++e)
    {
      const int partner = partners[3 * k + e];
      if (partner < 0 || faceOf[partner] == faceOf[k])
      {
        continue;
      }
      auto inserted = across.emplace(faceOf[k], std::array<int, 4>{ -1, -1, -1, -1 });
      std::array<int, 4>& list = inserted.first->second;
      const int other = faceOf[partner];
      for (int& entry : list)
      {
        if (entry == other || entry < 0)
        {
          entry = other;
          break;
        }
      }
    }
  }
  int listed = 0;
  for (const auto& face : across)
  {
    if (neighbors[slotOf(face.first)] != -1)
    {
      continue; // linked already (a face partly covered by others: its list)
    }
    ++listed;
    neighbors[slotOf(face.first)] = reentryFace + static_cast<int>(neighbors.size() / 4);
    neighbors.insert(neighbors.end(), face.second.begin(), face.second.end());
  }
  return listed;
}
}
