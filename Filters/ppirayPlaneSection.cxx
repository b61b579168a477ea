#include "ppirayPlaneSection.h"

#include "ppirayLinearCellKinds.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace ppiray
{
//------------------------------------------------------------------------------
int TetrahedronSection(
  const glm::dvec3 p[4], const glm::dvec4& plane, std::vector<glm::dvec3>& triangles)
{
  // Corners on the plane count as behind it (s <= 0): a face lying in the
  // plane belongs to the section of the cell in front of it only, so the
  // sections of a conforming mesh do not overlap and leave no gap.
  const glm::dvec3 n(plane);
  double s[4];
  int behind = 0;
  for (int v = 0; v < 4; ++v)
  {
    s[v] = glm::dot(n, p[v]) - plane.w;
    behind += s[v] <= 0 ? 1 : 0;
  }
  if (behind == 0 || behind == 4)
  {
    return 0;
  }
  // One point per edge from behind to in front: three or four.
  glm::dvec3 points[4];
  int count = 0;
  for (int a = 0; a < 4; ++a)
  {
    for (int b = 0; b < 4; ++b)
    {
      if (s[a] <= 0 && s[b] > 0)
      {
        points[count++] = p[a] + (s[a] / (s[a] - s[b])) * (p[b] - p[a]);
      }
    }
  }
  if (count == 4)
  {
    // A convex quadrilateral: order its points by angle around their centre.
    const glm::dvec3 centre = 0.25 * (points[0] + points[1] + points[2] + points[3]);
    const glm::dvec3 u = points[0] - centre;
    const glm::dvec3 w = glm::cross(n, u);
    double angle[4];
    for (int i = 0; i < 4; ++i)
    {
      const glm::dvec3 r = points[i] - centre;
      angle[i] = std::atan2(glm::dot(r, w), glm::dot(r, u));
    }
    int order[4] = { 0, 1, 2, 3 };
    std::sort(order, order + 4, [&](int x, int y) { return angle[x] < angle[y]; });
    triangles.insert(triangles.end(), { points[order[0]], points[order[1]], points[order[2]],
                                        points[order[0]], points[order[2]], points[order[3]] });
    return 2;
  }
  triangles.insert(triangles.end(), { points[0], points[1], points[2] });
  return 1;
}

//------------------------------------------------------------------------------
int CellSection(
  int kind, const glm::dvec3 p[8], const glm::dvec4& plane, std::vector<glm::dvec3>& triangles)
{
  // The tetrahedra from corner 0 to the fan triangles of the faces that do
  // not touch it (a hexahedron: the six around its diagonal 0-6).
  const LinearCellKindInfo& info = LinearCellKindOf(kind);
  int count = 0;
  for (int f = 0; f < info.Faces; ++f)
  {
    const int* q = info.Face[f];
    const int size = FaceSize(kind, f);
    if (std::find(q, q + size, 0) != q + size)
    {
      continue;
    }
    for (int t = 0; t + 2 < size; ++t)
    {
      const glm::dvec3 tet[4] = { p[0], p[q[0]], p[q[t + 1]], p[q[t + 2]] };
      count += TetrahedronSection(tet, plane, triangles);
    }
  }
  return count;
}

}
