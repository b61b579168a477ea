#include "ppirayConvexSurface.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

glm::dvec3 Point(const std::vector<float>& points, unsigned int i)
{
  return glm::dvec3(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
}

// Directed edge a -> b as one key.
std::uint64_t EdgeKey(unsigned int a, unsigned int b)
{
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

// Angle of triangle (a, b, c) at a.
double CornerAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 u = b - a, v = c - a;
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

// Union-find root with path halving.
unsigned int Root(std::vector<unsigned int>& parent, unsigned int i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}
}

namespace ppiray
{
bool IsConvexSurface(
  const std::vector<float>& points, const std::vector<unsigned int>& triangles, double tolerance)
{
  const size_t count = triangles.size() / 3;
  const size_t vertices = points.size() / 3;
  if (count < 4)
  {
    return false;
  }
  // Directed edges: each must appear once, its reverse once (closed,
  // manifold, consistently wound).
  std::unordered_map<std::uint64_t, size_t> edgeTriangle;
  edgeTriangle.reserve(3 * count);
  for (size_t t = 0; t < count; ++t)
  {
    for (int e = 0; e < 3; ++e)
    {
      const unsigned int a = triangles[3 * t + e], b = triangles[3 * t + (e + 1) % 3];
      if (a >= vertices || b >= vertices || a == b ||
          !edgeTriangle.emplace(EdgeKey(a, b), t).second)
      {
        return false;
      }
    }
  }
  std::vector<double> angleSum(vertices, 0.0);
  std::vector<char> used(vertices, 0);
  std::vector<unsigned int> parent(count);
  for (size_t t = 0; t < count; ++t)
  {
    parent[t] = static_cast<unsigned int>(t);
  }
  for (size_t t = 0; t < count; ++t)
  {
    const unsigned int* v = &triangles[3 * t];
    const glm::dvec3 p[3] = { Point(points, v[0]), Point(points, v[1]), Point(points, v[2]) };
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double area2 = glm::length(n);
    for (int e = 0; e < 3; ++e)
    {
      used[v[e]] = 1;
      angleSum[v[e]] += CornerAngle(p[e], p[(e + 1) % 3], p[(e + 2) % 3]);
      const auto across = edgeTriangle.find(EdgeKey(v[(e + 1) % 3], v[e]));
      if (across == edgeTriangle.end())
      {
        return false; // an open edge
      }
      const size_t u = across->second;
      parent[Root(parent, static_cast<unsigned int>(t))] =
        Root(parent, static_cast<unsigned int>(u));
      // The neighbour's corner off the shared edge, not outside this plane.
      const unsigned int* w = &triangles[3 * u];
      for (int c = 0; c < 3; ++c)
      {
        if (w[c] != v[e] && w[c] != v[(e + 1) % 3] && area2 > 0.0 &&
            glm::dot(n, Point(points, w[c]) - p[0]) > tolerance * area2)
        {
          return false; // a concave edge
        }
      }
    }
  }
  size_t usedVertices = 0;
  for (size_t i = 0; i < vertices; ++i)
  {
    if (used[i])
    {
      ++usedVertices;
      if (angleSum[i] > 2.0 * Pi + 1e-6)
      {
        return false; // a saddle or a vertex wound more than once
      }
    }
  }
  const unsigned int root = Root(parent, 0);
  for (size_t t = 1; t < count; ++t)
  {
    if (Root(parent, static_cast<unsigned int>(t)) != root)
    {
      return false; // several parts
    }
  }
  // Sphere topology: V - E + F = 2, E = 3 F / 2.
  const long long euler = static_cast<long long>(usedVertices) -
                          static_cast<long long>(3 * count / 2) + static_cast<long long>(count);
  return euler == 2;
}
}
