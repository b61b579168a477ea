/**
 * @file   ppirayReflexEdges.h
 * @brief  boundary triangles that face each other across a reflex edge
 *
 * Where a mesh's boundary surface bends inwards (a reflex edge: the empty
 * side of the edge spans less than 180 degrees — the rim of a hole, the tip
 * of a crack, cells touching along an edge), a ray that leaves the mesh
 * through one triangle near the edge may enter it again at once through the
 * triangle across the empty side. Depth peeling finds that entry by
 * rasterization, which near the edge can disagree with the ray's own
 * arithmetic and lose it; the march checks these partners itself.
 */
#ifndef ppirayReflexEdges_h
#define ppirayReflexEdges_h

#include "ppirayFiltersModule.h" // for export macro

#include <functional>
#include <vector>

namespace ppiray
{
/**
 * For each triangle of a surface (`triangles`: 3 indices into `points`, 3
 * floats each, wound counter-clockwise seen from outside), the triangle
 * across each of its edges e = (v_e, v_e+1) on the empty side, where that
 * side's wedge is under 180 degrees: 3 ints per triangle, -1 where there is
 * none. Around an edge shared by several triangles (non-manifold), the
 * partner is the next triangle turning from this one about the edge towards
 * its outward normal; the wedge angle is that turn.
 */
PPIRAYFILTERS_EXPORT std::vector<int> ReflexEdgePartners(
  const std::vector<float>& points, const std::vector<unsigned int>& triangles);

/**
 * The re-entry lists of a cell layout, for any cell kind: the boundary
 * surface (`points`, `triangles` as above) whose triangle k lies on the
 * boundary face `faceOf[k]` (a face code, FACES c + f; a quadrilateral is
 * two triangles), and the layout's neighbour array `neighbors` (texels of
 * 4 ints). Each boundary face with a reflex edge gets the neighbour code
 * `reentryFace` + i, `neighbors[slotOf(face)]`, where texel i, appended,
 * holds the faces across its edges (at most 4; -1 for none left). The faces
 * of one face's own triangles are not partners; a face linked already (its
 * slot not -1: a list of faces across it) keeps its code. Returns the faces
 * listed.
 */
PPIRAYFILTERS_EXPORT int ListReentryFaces(const std::vector<float>& points,
  const std::vector<unsigned int>& triangles, const std::vector<int>& faceOf,
  const std::function<size_t(int face)>& slotOf, int reentryFace, std::vector<int>& neighbors);
}

#endif
