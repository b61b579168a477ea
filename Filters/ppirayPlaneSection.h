/**
 * @file   ppirayPlaneSection.h
 * @brief  the section of a tetrahedron by a plane, as a convex polygon
 *
 * For rays that start inside the mesh: the cells cut by the camera's near
 * plane are drawn as their sections, each pixel of a section then starts its
 * ray in that cell (vtkPPIRayDepthPeeling). A plane n . x = d cuts a
 * tetrahedron where the signed distances s_v = n . p_v - d of its corners
 * change sign: on each such edge (a, b) at p_a + s_a / (s_a - s_b) (p_b - p_a),
 * three points (one corner apart from the others) or four (two and two). A
 * corner on the plane counts as behind it, so a face in the plane is part of
 * the section of the cell in front of it only. Another linear cell's section
 * is the union of the sections of tetrahedra that fill it (exact for planar
 * faces).
 */
#ifndef ppirayPlaneSection_h
#define ppirayPlaneSection_h

#include "ppirayFiltersModule.h" // for export macro

#include <glm/vec3.hpp> // for glm::dvec3
#include <glm/vec4.hpp> // for glm::dvec4
#include <vector>       // for std::vector

namespace ppiray
{
/**
 * The section of tetrahedron `p` by the plane (n, d) = (plane.xyz, plane.w)
 * as triangles (3 points each, appended to `triangles`): none when the plane
 * misses it (or the cell lies behind it, touching it), one or two otherwise.
 * Returns how many.
 */
PPIRAYFILTERS_EXPORT int TetrahedronSection(
  const glm::dvec3 p[4], const glm::dvec4& plane, std::vector<glm::dvec3>& triangles);

/**
 * The section of a linear cell of kind `kind` (ppirayLinearCellKinds.h;
 * corners `p`) as the sections of the tetrahedra from its corner 0 to the
 * fan triangles of the faces that do not touch it (a hexahedron: the six
 * tetrahedra around its diagonal 0-6). Exact for planar faces.
 */
PPIRAYFILTERS_EXPORT int CellSection(
  int kind, const glm::dvec3 p[8], const glm::dvec4& plane, std::vector<glm::dvec3>& triangles);
}

#endif
