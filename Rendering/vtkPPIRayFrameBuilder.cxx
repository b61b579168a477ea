#include "vtkPPIRayFrameBuilder.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkPPIRayCellBuffers.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace
{
// The point at normalized device coordinates (x, y, z) in the frame
// `clipToLocal` maps clip space to.
glm::dvec3 Unproject(vtkMatrix4x4* clipToLocal, double x, double y, double z)
{
  const double clip[4] = { x, y, z, 1.0 };
  double local[4];
  clipToLocal->MultiplyPoint(clip, local);
  return glm::dvec3(local[0], local[1], local[2]) / local[3];
}

// The near plane (n, d), n . x = d, n unit and towards the far plane, in
// the frame `clipToLocal` maps clip space to.
glm::dvec4 NearPlane(vtkMatrix4x4* clipToLocal)
{
  const glm::dvec3 a = Unproject(clipToLocal, -1, -1, -1);
  glm::dvec3 n = glm::normalize(
    glm::cross(Unproject(clipToLocal, 1, -1, -1) - a, Unproject(clipToLocal, -1, 1, -1) - a));
  n = glm::dot(n, Unproject(clipToLocal, 0, 0, 1) - a) < 0 ? -n : n;
  return glm::dvec4(n, glm::dot(n, a));
}

// The viewing ray's direction through the pixel at NDC (x, y),
//   d(x, y) = far(x, y) - near(x, y) = D (x, y, 1),
// is affine in (x, y) for perspective and parallel projections alike (eye
// space: (f - n) ((x + P02) / P00, (y + P12) / P11, -1), or (0, 0, n - f)):
// D, column-major, from d at three pixels, in double. In float the far
// point's w is a difference of two terms of about 1 / (2 n) that cancel to
// 1 / f: with the near plane 1e-4 of the far one (a camera inside a mesh)
// a ray passed cell edges on the wrong side.
void NdcToDirection(vtkMatrix4x4* clipToLocal, float out[9])
{
  auto direction = [clipToLocal](double x, double y)
  { return Unproject(clipToLocal, x, y, 1) - Unproject(clipToLocal, x, y, -1); };
  const glm::dvec3 d0 = direction(0, 0);
  const glm::dvec3 columns[3] = { direction(1, 0) - d0, direction(0, 1) - d0, d0 };
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      out[3 * c + r] = static_cast<float>(columns[c][r]);
    }
  }
}

// Column-major float copy of a row-major VTK matrix, for glUniformMatrix4fv.
void ColumnMajor(vtkMatrix4x4* m, float out[16])
{
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      out[4 * c + r] = static_cast<float>(m->GetElement(r, c));
    }
  }
}

// Cells a ray visits per peel at most when the setting is 0: enough for a
// ray through a mesh of `cells` as cubes, bounded by the mesh.
int DefaultMaximumSteps(vtkIdType cells)
{
  const double n = static_cast<double>(cells);
  return static_cast<int>(std::min(n + 1.0, std::max(1024.0, 64.0 * std::cbrt(n))));
}
}

//------------------------------------------------------------------------------
vtkPPIRayFrameBuilder::vtkPPIRayFrameBuilder() = default;

//------------------------------------------------------------------------------
vtkPPIRayFrameBuilder::~vtkPPIRayFrameBuilder() = default;

//------------------------------------------------------------------------------
double vtkPPIRayFrameBuilder::AdjustedSampleDistance(
  double distance, double lastTime, double allocatedTime, double minimum, double maximum)
{
  const double d = lastTime > 0.0 && allocatedTime > 0.0
                     ? distance * std::sqrt(lastTime / allocatedTime)
                     : distance;
  return std::min(std::max(d, minimum), std::max(minimum, maximum));
}

//------------------------------------------------------------------------------
bool vtkPPIRayFrameBuilder::Build(vtkRenderer* ren, vtkVolume* vol, vtkPPIRayCellBuffers& cells,
  const Settings& settings, vtkObject* reporter)
{
  vtkPPIRayDepthPeeling::Frame& frame = this->Frame;
  ren->GetTiledSizeAndOrigin(&frame.Width, &frame.Height, &frame.X0, &frame.Y0);
  if (frame.Width <= 0 || frame.Height <= 0)
  {
    return false;
  }
  const double distance = std::max(1.0, settings.ImageSampleDistance);
  frame.TargetWidth = std::max(1, static_cast<int>(std::ceil(frame.Width / distance)));
  frame.TargetHeight = std::max(1, static_cast<int>(std::ceil(frame.Height / distance)));

  // Matrices: the cells' local frame (mesh coordinates minus the centre of
  // its bounds) to world and to clip space, and back, composed in double.
  vtkNew<vtkMatrix4x4> localToClip, clipToLocal;
  this->LocalToWorld->Identity();
  for (int i = 0; i < 3; ++i)
  {
    this->LocalToWorld->SetElement(i, 3, cells.GetOrigin()[i]);
  }
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix(), this->LocalToWorld, this->LocalToWorld);
  vtkMatrix4x4::Multiply4x4(ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
                              ren->GetTiledAspectRatio(), -1, 1),
    this->LocalToWorld, localToClip);
  vtkMatrix4x4::Invert(localToClip, clipToLocal);
  ColumnMajor(localToClip, frame.LocalToClip);
  ColumnMajor(clipToLocal, frame.ClipToLocal);
  NdcToDirection(clipToLocal, frame.NdcToDirection);

  // A projection's colour is that of its last extreme: no early stop.
  frame.TerminationAlpha =
    settings.Projection ? 2.0f : static_cast<float>(settings.TerminationOpacity);
  frame.MaximumPeels = settings.MaximumPeels;
  // A camera inside the mesh: rays start at the near plane in the cells it
  // cuts (none when it passes outside the mesh's bounding sphere).
  this->Section.clear();
  const glm::dvec4 nearPlane = NearPlane(clipToLocal);
  if (std::abs(nearPlane.w) < cells.GetBoundingRadius())
  {
    cells.PlaneSection(nearPlane, this->Section);
  }
  frame.Section = &this->Section;
  this->ClippingPlanesInLocalFrame(settings.ClippingPlanes, reporter);
  frame.ClippingPlanes = &this->ClippingPlanes;
  frame.CountCellSteps = settings.CountCellSteps;
  frame.TimePasses = settings.TimePasses;
  frame.TimeFrame = settings.TimeFrame;
  frame.ConvexBoundary = cells.IsBoundaryConvex();
  this->MaximumSteps = settings.MaximumSteps > 0 ? settings.MaximumSteps
                                                 : DefaultMaximumSteps(cells.GetNumberOfCells());
  return true;
}

//------------------------------------------------------------------------------
void vtkPPIRayFrameBuilder::ClippingPlanesInLocalFrame(
  vtkPlaneCollection* planes, vtkObject* reporter)
{
  // A vtkPlane (origin o, normal n) keeps n . (x - o) >= 0 in world
  // coordinates: p = (n, -n . o); with x = L y (L: local to world) that is
  // (L^T p) . y >= 0 in the local frame.
  this->ClippingPlanes.clear();
  const int count = planes ? planes->GetNumberOfItems() : 0;
  if (count > 6 && count != this->ClippingPlanesWarned)
  {
    vtkWarningWithObjectMacro(
      reporter, << count << " clipping planes; only the first 6 clip the volume.");
  }
  this->ClippingPlanesWarned = count > 6 ? count : 0;
  for (int i = 0; i < std::min(count, 6); ++i)
  {
    vtkPlane* plane = planes->GetItem(i);
    const double* n = plane->GetNormal();
    const double* o = plane->GetOrigin();
    const double world[4] = { n[0], n[1], n[2], -(n[0] * o[0] + n[1] * o[1] + n[2] * o[2]) };
    for (int c = 0; c < 4; ++c)
    {
      double local = 0.0;
      for (int r = 0; r < 4; ++r)
      {
        local += world[r] * this->LocalToWorld->GetElement(r, c);
      }
      this->ClippingPlanes.push_back(static_cast<float>(local));
    }
  }
}

//------------------------------------------------------------------------------
int vtkPPIRayFrameBuilder::CountOverlappingVolumes(vtkRenderer* ren, vtkVolume* vol)
{
  double bounds[6];
  vol->GetBounds(bounds);
  int overlapping = 0;
  vtkVolumeCollection* volumes = ren->GetVolumes();
  vtkCollectionSimpleIterator it;
  volumes->InitTraversal(it);
  while (vtkVolume* other = volumes->GetNextVolume(it))
  {
    // A prop that wraps `vol` (ParaView's vtkPVLODVolume) shares its mapper.
    vtkAbstractVolumeMapper* mapper = other->GetMapper();
    if (other == vol || !mapper || mapper == vol->GetMapper() || !other->GetVisibility() ||
        !mapper->IsA("vtkUnstructuredGridGPURayCastMapper"))
    {
      continue;
    }
    const double* b = other->GetBounds();
    bool overlaps = b != nullptr;
    for (int i = 0; overlaps && i < 3; ++i)
    {
      overlaps = b[2 * i] <= bounds[2 * i + 1] && bounds[2 * i] <= b[2 * i + 1];
    }
    overlapping += overlaps ? 1 : 0;
  }
  return overlapping;
}
