#include "vtkUnstructuredGridConvexify.h"

#include "ppirayBoundaryFaceLinks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "ppirayConformingTetrahedra.h"
#include "ppirayGridGeometryKey.h"
#include "ppirayImaginaryTetrahedra.h"
#include "ppirayValidPointIds.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStaticPointLocator.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

vtkStandardNewMacro(vtkUnstructuredGridConvexify);

namespace
{
// Every array of `data` grown to `count` tuples, the new ones holding each
// component's minimum over the old ones (0 where it has none).
void ExtendWithMinimum(vtkDataSetAttributes* data, vtkIdType count)
{
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = data->GetArray(a);
    if (!array)
    {
      continue; // string and other non-numeric arrays keep their tuples
    }
    const int components = array->GetNumberOfComponents();
    std::vector<double> minimum(components, 0.0);
    for (int c = 0; c < components; ++c)
    {
      double range[2];
      array->GetRange(range, c);
      minimum[c] = range[0] <= range[1] ? range[0] : 0.0;
    }
    for (vtkIdType i = array->GetNumberOfTuples(); i < count; ++i)
    {
      array->InsertTuple(i, minimum.data());
    }
  }
}

// The first id of the points `grid`'s point `i` is taken as one with: points
// within `tolerance` of each other (vtkStaticPointLocator's merge, in point
// order, so the result does not depend on threads); `merged`: ids replaced.
std::vector<vtkIdType> PointsTakenAsOne(
  vtkUnstructuredGrid* grid, double tolerance, vtkIdType& merged)
{
  const vtkIdType numberOfPoints = grid->GetNumberOfPoints();
  std::vector<vtkIdType> first(numberOfPoints);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(grid);
  locator->SetTraversalOrder(vtkStaticPointLocator::POINT_ORDER);
  locator->BuildLocator();
  locator->MergePoints(tolerance, first.data());
  merged = 0;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    while (first[first[i]] != first[i])
    {
      first[i] = first[first[i]];
    }
    merged += first[i] != i ? 1 : 0;
  }
  return first;
}

// `grid`'s cells with every point id replaced by `first[id]`, so that cells
// meeting at a seam without sharing point ids (an O-grid's cut, a clip's
// points computed twice) share them; nullptr for a grid with polyhedra
// (their faces would need the same: their split's ids are replaced after).
vtkSmartPointer<vtkUnstructuredGrid> WithPointIdsReplaced(
  vtkUnstructuredGrid* grid, const std::vector<vtkIdType>& first)
{
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfValues(grid->GetNumberOfCells());
  std::vector<vtkIdType> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (grid->GetCellType(c) == VTK_POLYHEDRON)
    {
      return nullptr;
    }
    vtkIdType npts;
    const vtkIdType* pts;
    grid->GetCellPoints(c, npts, pts);
    ids.assign(pts, pts + npts);
    for (vtkIdType& id : ids)
    {
      id = first[id];
    }
    cells->InsertNextCell(npts, ids.data());
    types->SetValue(c, static_cast<unsigned char>(grid->GetCellType(c)));
  }
  auto shared = vtkSmartPointer<vtkUnstructuredGrid>::New();
  shared->SetPoints(grid->GetPoints());
  shared->SetCells(types, cells);
  shared->GetCellData()->ShallowCopy(grid->GetCellData());
  return shared;
}

// The split's tetrahedra that bound volume: ids through `first` (grid points;
// the polyhedra's added points keep theirs), those left with a repeated id
// or zero volume (exact orientation of `xyz`) removed. Returns how many;
// `leftOut[c]`: whether cell c had tetrahedra and none is kept.
vtkIdType KeepSolidTetrahedra(ppiray::TetrahedralSplit& split, const std::vector<vtkIdType>& first,
  const std::vector<double>& xyz, std::vector<unsigned char>& leftOut)
{
  for (vtkIdType c : split.CellIds)
  {
    leftOut[c] = 1;
  }
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  auto point = [&xyz](vtkIdType id)
  { return Point(xyz[3 * id], xyz[3 * id + 1], xyz[3 * id + 2]); };
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(first.size());
  const std::size_t count = split.CellIds.size();
  std::size_t kept = 0;
  for (std::size_t t = 0; t < count; ++t)
  {
    vtkIdType* tet = split.Tets.data() + 4 * t;
    for (int v = 0; v < 4; ++v)
    {
      tet[v] = tet[v] < numberOfPoints ? first[tet[v]] : tet[v];
    }
    if (tet[0] == tet[1] || tet[0] == tet[2] || tet[0] == tet[3] || tet[1] == tet[2] ||
        tet[1] == tet[3] || tet[2] == tet[3] ||
        CGAL::orientation(point(tet[0]), point(tet[1]), point(tet[2]), point(tet[3])) ==
          CGAL::COPLANAR)
    {
      continue;
    }
    std::copy(tet, tet + 4, split.Tets.data() + 4 * kept);
    leftOut[split.CellIds[t]] = 0;
    split.CellIds[kept++] = split.CellIds[t];
  }
  split.Tets.resize(4 * kept);
  split.CellIds.resize(kept);
  return static_cast<vtkIdType>(count - kept);
}

bool AllFinite(vtkPoints* points)
{
  double p[3];
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return false;
    }
  }
  return true;
}
// The boundary triangles of the conforming split (faces with no
// neighbour), wound outward, and the input cell each belongs to.
void OutwardBoundaryTriangles(vtkIdType numberOfPoints, const std::vector<double>& xyz,
  const ppiray::TetrahedralSplit& split, std::vector<vtkIdType>& triangles,
  std::vector<vtkIdType>& owner)
{
  vtkNew<vtkUnstructuredGridCellAdjacency> adjacency;
  adjacency->Build(numberOfPoints, split.Tets.data(), static_cast<vtkIdType>(split.CellIds.size()));
  const std::vector<vtkIdType>& faces = adjacency->GetBoundaryFaces();
  const vtkIdType numberOfFaces = adjacency->GetNumberOfBoundaryFaces();
  triangles.assign(3 * numberOfFaces, 0);
  owner.assign(numberOfFaces, 0);
  for (vtkIdType k = 0; k < numberOfFaces; ++k)
  {
    const vtkIdType t = faces[2 * k];
    const int f = static_cast<int>(faces[2 * k + 1]);
    const vtkIdType* tet = split.Tets.data() + 4 * t;
    for (int v = 0; v < 3; ++v)
    {
      triangles[3 * k + v] = tet[vtkUnstructuredGridCellAdjacency::FaceVertex(f, v)];
    }
    // Wound outward (FaceVertex's order is, for a positive tetrahedron).
    if (vtkUnstructuredGridCellAdjacency::SignedVolume6(
          &xyz[3 * tet[0]], &xyz[3 * tet[1]], &xyz[3 * tet[2]], &xyz[3 * tet[3]]) < 0)
    {
      std::swap(triangles[3 * k + 1], triangles[3 * k + 2]);
    }
    owner[k] = split.CellIds[t];
  }
}

double BoundsDiagonal(const double b[6])
{
  return std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

// The box around the points `tets` use, inflated by `margin` times its
// diagonal on every side (by `margin` where the points are one point).
void InflatedBox(
  const std::vector<double>& xyz, const std::vector<vtkIdType>& tets, double margin, double box[6])
{
  for (int a = 0; a < 3; ++a)
  {
    box[2 * a] = std::numeric_limits<double>::max();
    box[2 * a + 1] = -std::numeric_limits<double>::max();
  }
  for (vtkIdType id : tets)
  {
    for (int a = 0; a < 3; ++a)
    {
      box[2 * a] = std::min(box[2 * a], xyz[3 * id + a]);
      box[2 * a + 1] = std::max(box[2 * a + 1], xyz[3 * id + a]);
    }
  }
  const double diagonal = BoundsDiagonal(box);
  const double reach = margin * (diagonal > 0.0 ? diagonal : 1.0);
  for (int a = 0; a < 3; ++a)
  {
    box[2 * a] -= reach;
    box[2 * a + 1] += reach;
  }
}

// The output: `grid`, then the points its polyhedra's split added (`added`,
// xyz), the fill's new points and imaginary tetrahedra, hidden, with the
// input cells across their faces (BoundaryCellArrayName; LeftOutOfFill on
// the input cells `leftOut`); point and cell arrays extended with their
// minimum.
void AppendImaginaryCells(vtkUnstructuredGrid* grid, const std::vector<double>& added,
  const ppiray::ImaginaryTetrahedra& fill, const std::vector<vtkIdType>& owner,
  const std::vector<unsigned char>& leftOut, vtkUnstructuredGrid* output)
{
  output->DeepCopy(grid);
  vtkPoints* points = output->GetPoints();
  if ((!fill.NewPoints.empty() || !added.empty()) && points->GetDataType() != VTK_DOUBLE)
  {
    // New points lie on the input's faces: stored in float they would be
    // off them by float rounding, enough to break the faces' conformity.
    vtkNew<vtkPoints> doubles;
    doubles->SetDataTypeToDouble();
    doubles->SetNumberOfPoints(points->GetNumberOfPoints());
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      doubles->SetPoint(i, points->GetPoint(i));
    }
    output->SetPoints(doubles);
    points = doubles;
  }
  for (std::size_t i = 0; i < added.size(); i += 3)
  {
    points->InsertNextPoint(&added[i]);
  }
  for (const auto& p : fill.NewPoints)
  {
    points->InsertNextPoint(p.data());
  }
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  const vtkIdType numberOfImaginary = static_cast<vtkIdType>(fill.Tets.size() / 4);
  for (vtkIdType t = 0; t < numberOfImaginary; ++t)
  {
    output->InsertNextCell(VTK_TETRA, 4, fill.Tets.data() + 4 * t);
  }
  ExtendWithMinimum(output->GetPointData(), points->GetNumberOfPoints());
  ExtendWithMinimum(output->GetCellData(), numberOfCells + numberOfImaginary);

  // Imaginary cells: hidden (VTK's ghost flag for cells never shown).
  vtkUnsignedCharArray* ghosts = output->GetCellGhostArray();
  if (!ghosts)
  {
    ghosts = output->AllocateCellGhostArray();
  }
  for (vtkIdType c = numberOfCells; c < numberOfCells + numberOfImaginary; ++c)
  {
    ghosts->SetValue(c, vtkDataSetAttributes::HIDDENCELL);
  }
  vtkNew<vtkIdTypeArray> across;
  across->SetName(ppiray::BoundaryCellArrayName);
  across->SetNumberOfComponents(4);
  across->SetNumberOfTuples(numberOfCells + numberOfImaginary);
  across->Fill(-1);
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    across->SetTypedComponent(c, 0, leftOut[c] ? ppiray::LeftOutOfFill : -1);
  }
  for (vtkIdType t = 0; t < numberOfImaginary; ++t)
  {
    for (int f = 0; f < 4; ++f)
    {
      const vtkIdType triangle = fill.BoundaryTriangle[4 * t + f];
      across->SetTypedComponent(numberOfCells + t, f, triangle >= 0 ? owner[triangle] : -1);
    }
  }
  output->GetCellData()->AddArray(across);
}

// The output of the same geometry convexified before (`last`: its points and
// cells shared, its hidden flags and cells across kept) with `input`'s point
// and cell arrays, extended with their minimum.
void WithAttributesOf(
  vtkUnstructuredGrid* input, vtkUnstructuredGrid* last, vtkUnstructuredGrid* output)
{
  output->CopyStructure(last);
  output->GetPointData()->DeepCopy(input->GetPointData());
  output->GetCellData()->DeepCopy(input->GetCellData());
  ExtendWithMinimum(output->GetPointData(), last->GetNumberOfPoints());
  ExtendWithMinimum(output->GetCellData(), last->GetNumberOfCells());
  output->GetCellData()->AddArray(last->GetCellGhostArray());
  output->GetCellData()->AddArray(last->GetCellData()->GetArray(ppiray::BoundaryCellArrayName));
}
}

//------------------------------------------------------------------------------
// The last fill, kept for the same geometry (a time series' next step).
struct vtkUnstructuredGridConvexify::vtkInternals
{
  ppiray::GridGeometryKey Key;
  vtkNew<vtkUnstructuredGrid> Last;
  bool Valid = false;
  double Margin = 0.0;
  double Tolerance = 0.0;
};

//------------------------------------------------------------------------------
vtkUnstructuredGridConvexify::vtkUnstructuredGridConvexify()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkUnstructuredGridConvexify::~vtkUnstructuredGridConvexify() = default;

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridConvexify::BoundaryCellArrayName()
{
  return ppiray::BoundaryCellArrayName;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridConvexify::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }
  // The geometry of the last fill (its counts still stand): only the arrays are new.
  vtkInternals& last = *this->Internals;
  const bool sameGeometry = last.Key.Update(input) != ppiray::GridGeometryKey::Match::Changed;
  if (sameGeometry && last.Valid && last.Margin == this->Margin &&
      last.Tolerance == this->Tolerance)
  {
    vtkNew<vtkTimerLog> reuse;
    reuse->StartTimer();
    WithAttributesOf(input, last.Last, output);
    reuse->StopTimer();
    this->ExecutionTime = reuse->GetElapsedTime();
    return 1;
  }
  last.Valid = false;
  this->NumberOfImaginaryCells = 0;
  this->NumberOfSteinerPoints = 0;
  this->NumberOfAddedPoints = 0;
  this->NumberOfMergedPoints = 0;
  this->NumberOfFlatTetrahedra = 0;
  this->NumberOfDroppedTriangles = 0;
  this->ExecutionTime = 0.0;
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  // Every early return leaves the input as the output.
  output->ShallowCopy(input);
  if (!input->GetPoints() || input->GetNumberOfCells() == 0)
  {
    return 1;
  }
  if (!AllFinite(input->GetPoints()))
  {
    vtkErrorMacro("Infinite or NaN point coordinates: the grid was not convexified.");
    return 1;
  }
  vtkIdType invalidCells = 0;
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    ppiray::EmptyCellsWithInvalidPointIds(input, invalidCells);
  if (invalidCells > 0)
  {
    vtkWarningMacro(<< invalidCells << " cells with point ids outside [0, "
                    << input->GetNumberOfPoints() << ") were emptied.");
  }
  else
  {
    grid = input;
  }

  // The fill sees the mesh with points within the tolerance taken as one and
  // without zero-volume tetrahedra (the output keeps the input's cells;
  // imaginary cells use the first id at each place).
  double bounds[6];
  grid->GetBounds(bounds);
  vtkIdType mergedPoints = 0;
  const std::vector<vtkIdType> first =
    PointsTakenAsOne(grid, this->Tolerance * BoundsDiagonal(bounds), mergedPoints);
  vtkSmartPointer<vtkUnstructuredGrid> sealed =
    mergedPoints > 0 ? WithPointIdsReplaced(grid, first) : nullptr;
  ppiray::TetrahedralSplit split;
  ppiray::SplitIntoTetrahedra(sealed ? sealed.Get() : grid.Get(), false, split);
  if (split.GetNumberOfUnsupportedCells() > 0)
  {
    vtkWarningMacro(<< split.GetNumberOfUnsupportedCells()
                    << " cells that are not linear or quadratic 3D cells are left out: imaginary "
                       "cells may fill their space.");
  }
  // The points the split uses: the grid's, then the polyhedra's added ones.
  const vtkIdType numberOfPoints = grid->GetNumberOfPoints() + split.Added.GetNumberOfPoints();
  std::vector<double> xyz(3 * grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    grid->GetPoints()->GetPoint(i, &xyz[3 * i]);
  }
  xyz.insert(xyz.end(), split.Added.Points.begin(), split.Added.Points.end());
  this->NumberOfMergedPoints = mergedPoints;
  std::vector<unsigned char> leftOut(grid->GetNumberOfCells(), 0);
  this->NumberOfFlatTetrahedra = KeepSolidTetrahedra(split, first, xyz, leftOut);
  if (split.CellIds.empty())
  {
    vtkWarningMacro("No 3D cells with volume: nothing to convexify.");
    return 1;
  }
  this->UpdateProgress(0.05);

  // The boundary: triangles of the conforming split with no neighbour.
  std::vector<vtkIdType> triangles, owner;
  OutwardBoundaryTriangles(numberOfPoints, xyz, split, triangles, owner);
  double box[6];
  InflatedBox(xyz, split.Tets, this->Margin, box);
  const ppiray::ImaginaryTetrahedra fill = ppiray::FillBoxAroundSurface(
    xyz, triangles, box, [this](double done) { this->UpdateProgress(0.1 + 0.8 * done); });
  this->NumberOfDroppedTriangles = fill.DroppedTriangles;
  if (!fill.Error.empty())
  {
    vtkErrorMacro("Not convexified: " << fill.Error << ".");
    return 1;
  }

  AppendImaginaryCells(grid, split.Added.Points, fill, owner, leftOut, output);
  last.Last->ShallowCopy(output);
  last.Valid = true;
  last.Margin = this->Margin;
  last.Tolerance = this->Tolerance;

  this->NumberOfImaginaryCells = static_cast<vtkIdType>(fill.Tets.size() / 4);
  this->NumberOfSteinerPoints = fill.SteinerPoints;
  this->NumberOfAddedPoints =
    split.Added.GetNumberOfPoints() + static_cast<vtkIdType>(fill.NewPoints.size());
  timer->StopTimer();
  this->ExecutionTime = timer->GetElapsedTime();
  return 1;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridConvexify::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Margin: " << this->Margin << "\n";
  os << indent << "NumberOfImaginaryCells: " << this->NumberOfImaginaryCells << "\n";
  os << indent << "NumberOfSteinerPoints: " << this->NumberOfSteinerPoints << "\n";
  os << indent << "NumberOfAddedPoints: " << this->NumberOfAddedPoints << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "NumberOfMergedPoints: " << this->NumberOfMergedPoints << "\n";
  os << indent << "NumberOfFlatTetrahedra: " << this->NumberOfFlatTetrahedra << "\n";
  os << indent << "NumberOfDroppedTriangles: " << this->NumberOfDroppedTriangles << "\n";
  os << indent << "ExecutionTime: " << this->ExecutionTime << "\n";
}
