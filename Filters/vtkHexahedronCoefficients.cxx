#include "vtkHexahedronCoefficients.h"

#include "ppirayConformingTetrahedra.h"
#include "ppirayNumerics.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkHexahedron.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkHexahedronCoefficients);

namespace
{
// See vtkHexahedronCoefficients::CornerNeighbor.
const int CornerFrames[8][3] = { { 1, 3, 4 }, { 2, 0, 5 }, { 3, 1, 6 }, { 0, 2, 7 }, { 7, 5, 0 },
  { 4, 6, 1 }, { 5, 7, 2 }, { 6, 4, 3 } };

// Distance between the lines of a quadrilateral's diagonals q0q2 and q1q3,
// relative to the longer diagonal: |(q1 - q0) . (d1 x d2)| / |d1 x d2| / max|d|.
double FaceNonPlanarity(const double* q0, const double* q1, const double* q2, const double* q3)
{
  double d1[3], d2[3], e[3], n[3];
  vtkMath::Subtract(q2, q0, d1);
  vtkMath::Subtract(q3, q1, d2);
  vtkMath::Subtract(q1, q0, e);
  vtkMath::Cross(d1, d2, n);
  const double length = std::max(vtkMath::Norm(d1), vtkMath::Norm(d2));
  const double area = vtkMath::Norm(n);
  if (!(area > 1e-300) || !(length > 0))
  {
    return 0.0; // degenerate face: reported as a collapsed edge instead
  }
  return std::abs(vtkMath::Dot(e, n)) / area / length;
}

// The isoparametric coefficients of a parallelepiped (corners at the unit cube's).
void UnitCubeCoefficients(const double s[8], double c[8])
{
  c[0] = s[0];
  c[1] = s[1] - s[0];
  c[2] = s[3] - s[0];
  c[3] = s[4] - s[0];
  c[4] = s[0] - s[1] + s[2] - s[3];
  c[5] = s[0] - s[3] - s[4] + s[7];
  c[6] = s[0] - s[1] - s[4] + s[5];
  c[7] = -s[0] + s[1] - s[2] + s[3] + s[4] - s[5] + s[6] - s[7];
}
}

//------------------------------------------------------------------------------
vtkHexahedronCoefficients::vtkHexahedronCoefficients()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
bool vtkHexahedronCoefficients::ToFrame(const double frame[12], const double x[3], double uvw[3])
{
  // Solve [a b c] (u, v, w) = x - p0 by Cramer's rule.
  const double* a = frame + 3;
  const double* b = frame + 6;
  const double* c = frame + 9;
  const double det = vtkMath::Determinant3x3(a, b, c);
  double scale = vtkMath::Norm(a) * vtkMath::Norm(b) * vtkMath::Norm(c);
  if (!(std::abs(det) > 1e-14 * scale))
  {
    return false;
  }
  double d[3];
  vtkMath::Subtract(x, frame, d);
  uvw[0] = vtkMath::Determinant3x3(d, b, c) / det;
  uvw[1] = vtkMath::Determinant3x3(a, d, c) / det;
  uvw[2] = vtkMath::Determinant3x3(a, b, d) / det;
  return true;
}

//------------------------------------------------------------------------------
double vtkHexahedronCoefficients::EvaluateField(const double c[8], const double uvw[3])
{
  const double u = uvw[0], v = uvw[1], w = uvw[2];
  return c[0] + c[1] * u + c[2] * v + c[3] * w + c[4] * u * v + c[5] * v * w + c[6] * u * w +
         c[7] * u * v * w;
}

//------------------------------------------------------------------------------
int vtkHexahedronCoefficients::CornerNeighbor(int corner, int axis)
{
  return CornerFrames[corner][axis];
}

//------------------------------------------------------------------------------
bool vtkHexahedronCoefficients::FitCoefficients(
  const double p[8][3], const double s[8], double frame[12], double c[8])
{
  // Frame at corner 0 along its edges.
  std::copy(p[0], p[0] + 3, frame);
  vtkMath::Subtract(p[1], p[0], frame + 3);
  vtkMath::Subtract(p[3], p[0], frame + 6);
  vtkMath::Subtract(p[4], p[0], frame + 9);
  // c0..c3 from corners 0, 1, 3, 4 (at (0,0,0), (1,0,0), (0,1,0), (0,0,1) by
  // construction), c4..c7 from the other four corners.
  UnitCubeCoefficients(s, c);
  const int others[4] = { 2, 5, 6, 7 };
  double a[4][4], r[4];
  for (int row = 0; row < 4; ++row)
  {
    double uvw[3];
    if (!ToFrame(frame, p[others[row]], uvw))
    {
      return false;
    }
    const double u = uvw[0], v = uvw[1], w = uvw[2];
    a[row][0] = u * v;
    a[row][1] = v * w;
    a[row][2] = u * w;
    a[row][3] = u * v * w;
    r[row] = s[others[row]] - (c[0] + c[1] * u + c[2] * v + c[3] * w);
  }
  if (!ppiray::SolveLinear4(a, r, 1e-10))
  {
    return false;
  }
  std::copy(r, r + 4, c + 4);
  return true;
}

//------------------------------------------------------------------------------
int vtkHexahedronCoefficients::ComputeCell(const double p[8][3], const double s[8],
  double tolerancePlanarity, double toleranceCollapse, double frame[12], double c[8],
  double* nonPlanarity)
{
  int flags = 0;
  // Edges: collapsed when much shorter than the longest.
  double shortest = VTK_DOUBLE_MAX, longest = 0.0;
  for (int e = 0; e < 12; ++e)
  {
    const vtkIdType* ends = vtkHexahedron::GetEdgeArray(e);
    const double length = std::sqrt(vtkMath::Distance2BetweenPoints(p[ends[0]], p[ends[1]]));
    shortest = std::min(shortest, length);
    longest = std::max(longest, length);
  }
  if (!(shortest > toleranceCollapse * longest))
  {
    flags |= COLLAPSED_EDGE;
  }

  // Corner frames: a negative one means the cell is inverted (folded) there.
  const double volumeScale = longest * longest * longest;
  for (int i = 0; i < 8; ++i)
  {
    double e0[3], e1[3], e2[3];
    vtkMath::Subtract(p[CornerNeighbor(i, 0)], p[i], e0);
    vtkMath::Subtract(p[CornerNeighbor(i, 1)], p[i], e1);
    vtkMath::Subtract(p[CornerNeighbor(i, 2)], p[i], e2);
    if (vtkMath::Determinant3x3(e0, e1, e2) < -1e-12 * volumeScale)
    {
      flags |= INVERTED;
    }
  }

  // Faces.
  double worst = 0.0;
  for (int f = 0; f < 6; ++f)
  {
    const vtkIdType* q = vtkHexahedron::GetFaceArray(f);
    worst = std::max(worst, FaceNonPlanarity(p[q[0]], p[q[1]], p[q[2]], p[q[3]]));
  }
  if (nonPlanarity)
  {
    *nonPlanarity = worst;
  }
  if (worst > tolerancePlanarity)
  {
    flags |= NON_PLANAR_FACE;
  }

  if (!FitCoefficients(p, s, frame, c))
  {
    flags |= SINGULAR; // the parallelepiped formulas were kept
  }
  return flags;
}

//------------------------------------------------------------------------------
int vtkHexahedronCoefficients::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (!input || !output)
  {
    return 0;
  }
  output->ShallowCopy(input);
  const vtkIdType numberOfCells = input->GetNumberOfCells();
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, inputVector);
  if (numberOfCells > 0 && !scalars)
  {
    vtkWarningMacro("No point scalars: coefficients of a zero field.");
  }

  vtkNew<vtkDoubleArray> frames;
  frames->SetName("HexahedronFrame");
  frames->SetNumberOfComponents(12);
  frames->SetNumberOfTuples(numberOfCells);
  vtkNew<vtkDoubleArray> coefficients;
  coefficients->SetName("HexahedronCoefficients");
  coefficients->SetNumberOfComponents(8);
  coefficients->SetNumberOfTuples(numberOfCells);
  vtkNew<vtkUnsignedCharArray> quality;
  quality->SetName("HexahedronQuality");
  quality->SetNumberOfTuples(numberOfCells);
  vtkNew<vtkFloatArray> planarity;
  planarity->SetName("FaceNonPlanarity");
  planarity->SetNumberOfTuples(numberOfCells);

  // Point ids of every cell, for random access in parallel.
  std::vector<vtkIdType> offsets(numberOfCells + 1, 0), ids;
  ids.reserve(8 * numberOfCells);
  ppiray::ForEachCell(input,
    [&](vtkIdType cellId, int, vtkIdType npts, const vtkIdType* pts)
    {
      ids.insert(ids.end(), pts, pts + npts);
      offsets[cellId + 1] = static_cast<vtkIdType>(ids.size());
    });

  vtkPoints* points = input->GetPoints();
  const vtkIdType block = 65536;
  for (vtkIdType begin = 0; begin < numberOfCells && !this->GetAbortExecute(); begin += block)
  {
    const vtkIdType end = std::min(numberOfCells, begin + block);
#pragma omp parallel for schedule(static)
    for (vtkIdType cellId = begin; cellId < end; ++cellId)
    {
      double frame[12] = { 0 }, c[8] = { 0 }, deviation = 0.0;
      int flags = NOT_A_HEXAHEDRON;
      const int type = input->GetCellType(cellId);
      if (ppiray::LinearShapeOf(type).Type == VTK_HEXAHEDRON &&
          offsets[cellId + 1] - offsets[cellId] >= 8)
      {
        const vtkIdType* pts = ids.data() + offsets[cellId];
        double corners[8][3], values[8];
        for (int i = 0; i < 8; ++i)
        {
          const vtkIdType id = pts[ppiray::HexahedronCorner(type, i)];
          points->GetPoint(id, corners[i]);
          values[i] = scalars ? scalars->GetComponent(id, 0) : 0.0;
        }
        flags = ComputeCell(corners, values, this->NonPlanarityTolerance,
          this->CollapsedEdgeTolerance, frame, c, &deviation);
      }
      frames->SetTypedTuple(cellId, frame);
      coefficients->SetTypedTuple(cellId, c);
      quality->SetValue(cellId, static_cast<unsigned char>(flags));
      planarity->SetValue(cellId, static_cast<float>(deviation));
    }
    this->UpdateProgress(static_cast<double>(end) / numberOfCells);
  }

  vtkCellData* cellData = output->GetCellData();
  cellData->AddArray(frames);
  cellData->AddArray(coefficients);
  cellData->AddArray(quality);
  cellData->AddArray(planarity);
  return 1;
}

//------------------------------------------------------------------------------
void vtkHexahedronCoefficients::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NonPlanarityTolerance: " << this->NonPlanarityTolerance << "\n";
  os << indent << "CollapsedEdgeTolerance: " << this->CollapsedEdgeTolerance << "\n";
}
