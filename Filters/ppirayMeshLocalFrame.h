/**
 * @file   ppirayMeshLocalFrame.h
 * @brief  a mesh's points relative to the centre of its bounds
 *
 * Cell textures store coordinates relative to the centre of the mesh's
 * bounds (differences taken in double, stored in float), so that a mesh far
 * from the origin keeps single-precision accuracy on the GPU.
 */
#ifndef ppirayMeshLocalFrame_h
#define ppirayMeshLocalFrame_h

#include "ppirayFiltersModule.h" // for export macro

#include <vector> // for std::vector

class vtkPoints;

namespace ppiray
{
/**
 * origin = centre of the bounds of `points`; local[3 p + i] = x_p[i] - origin[i].
 * Returns the length of the bounds' diagonal.
 */
PPIRAYFILTERS_EXPORT double ComputeLocalPoints(
  vtkPoints* points, double origin[3], std::vector<double>& local);
}

#endif
