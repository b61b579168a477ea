#include "ppirayQuadraticTetrahedra.h"

#include "vtkCellType.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>

namespace ppiray
{
namespace quadratic_tetrahedron
{
//------------------------------------------------------------------------------
bool IsQuadraticTetrahedron(int type, vtkIdType npts)
{
  return (type == VTK_QUADRATIC_TETRA || type == VTK_LAGRANGE_TETRAHEDRON) && npts == 10;
}

//------------------------------------------------------------------------------
int EdgeBetween(int a, int b)
{
  for (int k = 0; k < 6; ++k)
  {
    if ((Edge[k][0] == a && Edge[k][1] == b) || (Edge[k][0] == b && Edge[k][1] == a))
    {
      return k;
    }
  }
  return 0;
}

//------------------------------------------------------------------------------
void RenumberEdgeNodes(const int corner[4], const vtkIdType in[6], vtkIdType out[6])
{
  for (int k = 0; k < 6; ++k)
  {
    out[k] = in[EdgeBetween(corner[Edge[k][0]], corner[Edge[k][1]])];
  }
}

//------------------------------------------------------------------------------
void FrameCoefficients(const double s[4], const double m[6], double c[11])
{
  const double s0 = s[0];
  const double m0[3] = { m[0], m[2], m[3] }; // edges (0,1), (2,0), (0,3)
  double linear[3], square[3];
  for (int i = 0; i < 3; ++i)
  {
    linear[i] = 4 * m0[i] - s[i + 1] - 3 * s0;
    square[i] = 2 * s[i + 1] - 4 * m0[i] + 2 * s0;
  }
  auto product = [&](double mij, int i, int j)
  { return 4 * mij - 4 * s0 - 2 * (linear[i] + linear[j]) - (square[i] + square[j]); };
  c[0] = s0;
  std::copy_n(linear, 3, c + 1);
  c[4] = product(m[1], 0, 1); // uv: edge (1,2)
  c[5] = product(m[5], 1, 2); // vw: edge (2,3)
  c[6] = product(m[4], 0, 2); // uw: edge (1,3)
  c[7] = 0;
  std::copy_n(square, 3, c + 8);
}

//------------------------------------------------------------------------------
double MidEdgeDeviation(const double nodes[10][3])
{
  double deviation = 0;
  for (int k = 0; k < 6; ++k)
  {
    const double* a = nodes[Edge[k][0]];
    const double* b = nodes[Edge[k][1]];
    const double* x = nodes[4 + k];
    double offset[3];
    for (int i = 0; i < 3; ++i)
    {
      offset[i] = x[i] - 0.5 * (a[i] + b[i]);
    }
    const double length = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
    const double d = vtkMath::Norm(offset);
    deviation = std::max(deviation, length > 0 ? d / length : (d > 0 ? 1.0 : 0.0));
  }
  return deviation;
}
}
}
