#include "ppirayMeshLocalFrame.h"

#include "vtkPoints.h"

#include <cmath>

namespace ppiray
{
double ComputeLocalPoints(vtkPoints* points, double origin[3], std::vector<double>& local)
{
  double bounds[6];
  points->GetBounds(bounds);
  double length2 = 0;
  for (int i = 0; i < 3; ++i)
  {
    origin[i] = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
    length2 += (bounds[2 * i + 1] - bounds[2 * i]) * (bounds[2 * i + 1] - bounds[2 * i]);
  }
  const vtkIdType n = points->GetNumberOfPoints();
  local.resize(3 * n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    for (int i = 0; i < 3; ++i)
    {
      local[3 * p + i] = x[i] - origin[i];
    }
  }
  return std::sqrt(length2);
}
}
