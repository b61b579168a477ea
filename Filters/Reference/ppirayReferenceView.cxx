#include "ppirayReferenceView.h"

#include "vtkCamera.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace ppiray
{
namespace reference
{
namespace
{
// Planes n . (x - o) >= 0 in the frame y = x - centre: n . y + n . (centre - o) >= 0.
std::vector<glm::dvec4> ClippingPlanesAbout(vtkPlaneCollection* planes, const Vec3& centre)
{
  std::vector<glm::dvec4> clippingPlanes;
  const int numberOfPlanes = planes ? planes->GetNumberOfItems() : 0;
  for (int i = 0; i < std::min(numberOfPlanes, 6); ++i)
  {
    vtkPlane* plane = planes->GetItem(i);
    const Vec3 n = glm::make_vec3(plane->GetNormal()), o = glm::make_vec3(plane->GetOrigin());
    clippingPlanes.emplace_back(n, glm::dot(n, centre - o));
  }
  return clippingPlanes;
}
}

//------------------------------------------------------------------------------
void ReferenceView::Build(
  vtkCamera* camera, const double bounds[6], vtkPlaneCollection* planes, int width, int height)
{
  this->Width = width;
  this->Height = height;
  this->Centre = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  this->WorldToClip->DeepCopy(
    camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1, 1));
  vtkMatrix4x4::Invert(this->WorldToClip, this->ClipToWorld);
  this->ClippingPlanes = ClippingPlanesAbout(planes, this->Centre);
}

//------------------------------------------------------------------------------
void ReferenceView::PixelRay(int px, int py, Vec3& origin, Vec3& direction) const
{
  double ndcNear[4] = { 2.0 * (px + 0.5) / this->Width - 1.0, 2.0 * (py + 0.5) / this->Height - 1.0,
    -1.0, 1.0 };
  double ndcFar[4] = { ndcNear[0], ndcNear[1], 1.0, 1.0 };
  double nearPoint[4], farPoint[4];
  this->ClipToWorld->MultiplyPoint(ndcNear, nearPoint);
  this->ClipToWorld->MultiplyPoint(ndcFar, farPoint);
  origin = Vec3(nearPoint[0], nearPoint[1], nearPoint[2]) / nearPoint[3] - this->Centre;
  direction = glm::normalize(
    Vec3(farPoint[0], farPoint[1], farPoint[2]) / farPoint[3] - this->Centre - origin);
}
}
}
