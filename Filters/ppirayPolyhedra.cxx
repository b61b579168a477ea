#include "ppirayPolyhedra.h"

#include "ppirayConformingTetrahedra.h"
#include "vtkCell.h"
#include "vtkDataArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ppiray
{
//------------------------------------------------------------------------------
double AddedPoints::Value(vtkIdType i, vtkDataArray* values, int component) const
{
  double value = 0.0;
  for (vtkIdType k = this->Offsets[i]; k < this->Offsets[i + 1]; ++k)
  {
    const double v = values->GetComponent(this->Ids[k], component);
    if (std::isnan(v))
    {
      return std::numeric_limits<double>::quiet_NaN();
    }
    value += this->Weights[k] * v;
  }
  return value;
}

//------------------------------------------------------------------------------
PolyhedronSplitter::PolyhedronSplitter(
  vtkUnstructuredGrid* grid, const QuadDiagonals& diagonals, AddedPoints& added)
  : Grid(grid)
  , Diagonals(diagonals)
  , Added(added)
{
}

//------------------------------------------------------------------------------
PolyhedronSplitter::~PolyhedronSplitter() = default;

//------------------------------------------------------------------------------
vtkIdType PolyhedronSplitter::AddPoint(const double x[3])
{
  // VTK's interpolation weights of the cell's points at x.
  const vtkIdType n = this->Cell->GetNumberOfPoints();
  this->CellWeights.assign(std::max<vtkIdType>(n, 8), 0.0);
  double closest[3], pcoords[3], dist2;
  int subId;
  this->Cell->EvaluatePosition(x, closest, subId, pcoords, dist2, this->CellWeights.data());
  for (vtkIdType v = 0; v < n; ++v)
  {
    if (this->CellWeights[v] != 0.0)
    {
      this->Added.Ids.push_back(this->Cell->GetPointId(v));
      this->Added.Weights.push_back(this->CellWeights[v]);
    }
  }
  this->Added.Offsets.push_back(static_cast<vtkIdType>(this->Added.Ids.size()));
  this->Added.Points.insert(this->Added.Points.end(), x, x + 3);
  return this->Grid->GetNumberOfPoints() + this->Added.GetNumberOfPoints() - 1;
}

//------------------------------------------------------------------------------
vtkIdType PolyhedronSplitter::Split(vtkIdType cellId, std::vector<vtkIdType>& tets)
{
  this->Grid->GetCell(cellId, this->Cell);
  const int faces = this->Cell->GetNumberOfFaces();
  const vtkIdType n = this->Cell->GetNumberOfPoints();
  if (faces < 4 || n < 4)
  {
    return 0;
  }
  // The cone's apex: the average of the cell's points.
  double centre[3] = { 0, 0, 0 };
  for (vtkIdType v = 0; v < n; ++v)
  {
    double x[3];
    this->Cell->GetPoints()->GetPoint(v, x);
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += x[k] / static_cast<double>(n);
    }
  }
  const vtkIdType apex = this->AddPoint(centre);
  const size_t before = tets.size();
  auto cone = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    tets.insert(tets.end(), { apex, a, b, c });
  };
  for (int f = 0; f < faces; ++f)
  {
    vtkCell* face = this->Cell->GetFace(f);
    const vtkIdType m = face->GetNumberOfPoints();
    std::vector<vtkIdType> ids(m);
    for (vtkIdType k = 0; k < m; ++k)
    {
      ids[k] = face->GetPointId(k);
    }
    if (m == 3)
    {
      cone(ids[0], ids[1], ids[2]);
    }
    else if (m == 4)
    {
      const bool first = this->Diagonals.AlongFirstDiagonal(ids[0], ids[1], ids[2], ids[3]);
      for (int t = 0; t < 2; ++t)
      {
        cone(ids[QuadTriangleCorner(t, 0, !first)], ids[QuadTriangleCorner(t, 1, !first)],
          ids[QuadTriangleCorner(t, 2, !first)]);
      }
    }
    else if (m > 4)
    {
      std::vector<vtkIdType> key = ids;
      std::sort(key.begin(), key.end());
      auto it = this->FaceCentres.find(key);
      if (it == this->FaceCentres.end())
      {
        double middle[3] = { 0, 0, 0 };
        for (vtkIdType k = 0; k < m; ++k)
        {
          double x[3];
          face->GetPoints()->GetPoint(k, x);
          for (int c = 0; c < 3; ++c)
          {
            middle[c] += x[c] / static_cast<double>(m);
          }
        }
        it = this->FaceCentres.emplace(key, this->AddPoint(middle)).first;
      }
      for (vtkIdType k = 0; k < m; ++k)
      {
        cone(it->second, ids[k], ids[(k + 1) % m]);
      }
    }
  }
  return static_cast<vtkIdType>((tets.size() - before) / 4);
}
}
