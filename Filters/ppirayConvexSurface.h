/**
 * @file   ppirayConvexSurface.h
 * @brief  whether a closed triangle surface bounds a convex solid
 *
 * A ray meets the boundary of a convex solid in one entry and one exit, so
 * a mesh with a convex boundary needs one entry layer and no depth peel.
 * The test is local, O(triangles): the surface must be a closed, connected,
 * consistently wound 2-manifold of sphere topology (every edge in two
 * triangles of opposite direction, V - E + F = 2), convex at every edge
 * (each triangle's far corner of its neighbour not outside its plane) and
 * at every vertex (face angles summing to at most 2 pi). A connected closed
 * surface that is locally convex everywhere bounds a convex solid (the
 * local-to-global convexity theorems of Tietze and Nakajima; for immersed
 * surfaces, van Heijenoort 1952), so no pair of faces is ever compared.
 * Tolerances: a corner up to `tolerance` outside a plane (a length) and
 * angle sums up to 2 pi + 1e-6 count as flat.
 */
#ifndef ppirayConvexSurface_h
#define ppirayConvexSurface_h

#include "ppirayFiltersModule.h" // for export macro

#include <vector> // for std::vector

namespace ppiray
{
/**
 * Whether `triangles` (3 indices into `points`, x y z each; wound so their
 * normals point outward) bound a convex solid.
 */
PPIRAYFILTERS_EXPORT bool IsConvexSurface(
  const std::vector<float>& points, const std::vector<unsigned int>& triangles, double tolerance);
}

#endif
