/**
 * @file   ppirayRayIntegrator.h
 * @brief  the reference renderer's integral along one ray
 *
 * For vtkUnstructuredGridReferenceRenderer only: the closed-form integrals
 * of ppirayVolumeIntegrals.h over the ray's segments (ppirayRaySegments.h),
 * split at the transfer function's breaks (ppirayReferenceTransferFunction.h),
 * with the isosurfaces of ppirayIsoSurfaces.h.
 */
#ifndef ppirayRayIntegrator_h
#define ppirayRayIntegrator_h

#include "ppirayIsoSurfaces.h"               // for ppiray::IsoSurfaces
#include "ppirayRaySegments.h"               // for Segment, Vec3
#include "ppirayReferenceTransferFunction.h" // for TransferFunction

#include <functional> // for std::function

namespace ppiray
{
namespace reference
{
/** The field gradient of general cell `cell` at ray parameter t. */
using GradientAt = std::function<Vec3(vtkIdType cell, double t)>;

// Front-to-back composite of the sorted, de-overlapped segments, each split
// at every transfer-function break and integrated in closed form; with
// isosurfaces, also split where the scalar crosses an isovalue (and at jumps
// between cells), the surface composited there. `gradientAt(cell, t)`: the
// field gradient of a general cell at ray parameter t.
void IntegrateRay(std::vector<Segment>& segments, const TransferFunction& tf,
  const IsoSurfaces& iso, const Vec3& origin, const Vec3& direction, const Vec3& centre,
  const GradientAt& gradientAt, float rgba[4]);

/** A projection's blend mode and what the average and additive ones read. */
struct Projection
{
  enum Mode
  {
    Maximum = 1, // vtkVolumeMapper's values
    Minimum = 2,
    Average = 3,
    Additive = 4
  };
  int Blend = Maximum;
  double Normalize[2] = { 1, 0 };    // n(s) = Normalize[0] s + Normalize[1]
  double AverageRange[2] = { 0, 0 }; // AVERAGE_INTENSITY_BLEND's scalar range
};

/**
 * A projection of the segments, as vtkGPUVolumeRayCastMapper defines it.
 * Maximum or minimum intensity: the extreme of their end values (the scalar
 * is linear on each), coloured by the transfer function there with alpha =
 * its scalar opacity (tau x unit distance), premultiplied. Average: over the
 * parts with s in AverageRange, unit distance x int tau(s) n(s) dt / int dt;
 * additive: int tau(s) n(s) dt; both grey, clamped to 1, alpha 1 (n: the
 * scalar normalized to the field's range). Zero where no segment counts.
 */
void ProjectRay(
  std::vector<Segment>& segments, const TransferFunction& tf, const Projection& how, float rgba[4]);
}
}

#endif
