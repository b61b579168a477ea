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
 * the section of the cell in front of it only. A hexahedron's section is
 * the union of the sections of its six tetrahedra around the diagonal 0-6
 * (exact for planar faces).
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
 * The section of the hexahedron with corners `p` (VTK_HEXAHEDRON order) as
 * the sections of its six tetrahedra around the diagonal 0-6.
 */
PPIRAYFILTERS_EXPORT int HexahedronSection(
  const glm::dvec3 p[8], const glm::dvec4& plane, std::vector<glm::dvec3>& triangles);
}

#endif
