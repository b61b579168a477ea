/**
 * @file   ppirayReferenceView.h
 * @brief  the reference renderer's view: the camera's matrices, pixel rays and clipping planes
 *
 * For vtkUnstructuredGridReferenceRenderer only. Rays and planes are in the
 * renderer's frame (world minus the centre of the bounds, ppirayRaySegments.h),
 * the camera's matrices in world coordinates.
 */
#ifndef ppirayReferenceView_h
#define ppirayReferenceView_h

#include "ppirayRaySegments.h" // for Vec3
#include "vtkMatrix4x4.h"      // for vtkMatrix4x4
#include "vtkNew.h"            // for vtkNew

#include <glm/vec4.hpp> // for glm::dvec4
#include <vector>       // for std::vector

class vtkCamera;
class vtkPlaneCollection;

namespace ppiray
{
namespace reference
{
struct ReferenceView
{
  int Width = 0, Height = 0; // pixels
  Vec3 Centre = { 0, 0, 0 }; // of the bounds: the renderer's frame is world - Centre
  vtkNew<vtkMatrix4x4> WorldToClip, ClipToWorld;
  std::vector<glm::dvec4> ClippingPlanes; // (n, d): the frame's y is kept where n . y + d >= 0

  /**
   * The view of `camera` (its composite projection at aspect width / height,
   * depth -1 to 1) on a grid with `bounds`, with the first 6 of `planes`
   * (may be null).
   */
  void Build(
    vtkCamera* camera, const double bounds[6], vtkPlaneCollection* planes, int width, int height);

  /**
   * The ray through the centre of pixel (px, py): from its point on the near
   * plane (NDC z = -1) towards its point on the far plane (z = 1), direction
   * normalized.
   */
  void PixelRay(int px, int py, Vec3& origin, Vec3& direction) const;
};
}
}

#endif
