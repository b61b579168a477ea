/**
 * @file   ppirayPolyhedra.h
 * @brief  polyhedra (VTK_POLYHEDRON) as conforming tetrahedra, with VTK's field at the points added
 *
 * A polyhedron is split as a cone from a point c, the average of its points,
 * to the triangles of its faces: a triangle as it is, a quadrilateral along
 * the diagonal through its smallest point id (QuadDiagonals: the rule every
 * other cell's split follows), a face of five or more corners fanned from a
 * point at the average of its corners, added once per face (keyed by its
 * sorted point ids) and shared by the two cells on it. The split conforms
 * across faces: between polyhedra, and with the split of hexahedra, wedges
 * and pyramids.
 *
 * The points added carry VTK's interpolation there: the weights
 * vtkCell::EvaluatePosition gives for the cell's points (a polyhedron's mean
 * value coordinates, vtkMeanValueCoordinatesInterpolator; on a face they
 * reduce to the face's own, so both cells on it agree). Mean value
 * coordinates reproduce a field linear in space, so such a field renders
 * exactly; any other field is VTK's at the cell's points and the added
 * points and linear between them (the error is measured in
 * TestGPURayCastPolyhedra).
 *
 * The cone from c is valid where the polyhedron is star-shaped from c (every
 * convex polyhedron, planar faces or not): otherwise some of its tetrahedra
 * are inverted, and the march treats them as it treats any inverted cell
 * (Documentation/algorithms.md, "Degenerate, inverted and tangled cells").
 */
#ifndef ppirayPolyhedra_h
#define ppirayPolyhedra_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkNew.h"              // for vtkNew
#include "vtkType.h"             // for vtkIdType

#include <array>  // for std::array
#include <map>    // for std::map
#include <vector> // for std::vector

class vtkDataArray;
class vtkGenericCell;
class vtkUnstructuredGrid;

namespace ppiray
{
class QuadDiagonals;

/** Points a split adds, numbered after the grid's, with their interpolation weights. */
struct AddedPoints
{
  std::vector<double> Points;             // 3 per added point
  std::vector<vtkIdType> Offsets = { 0 }; // per added point: its range in Ids and Weights
  std::vector<vtkIdType> Ids;             // grid point ids
  std::vector<double> Weights;

  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->Offsets.size()) - 1; }
  /**
   * Component `component` of `values` (per grid point) at added point i: the
   * weighted sum, NaN when a weighted value is NaN.
   */
  double Value(vtkIdType i, vtkDataArray* values, int component) const;
};

class PPIRAYFILTERS_EXPORT PolyhedronSplitter
{
public:
  PolyhedronSplitter(vtkUnstructuredGrid* grid, const QuadDiagonals& diagonals, AddedPoints& added);
  ~PolyhedronSplitter();

  /**
   * Appends the tetrahedra of polyhedron `cellId` to `tets` (4 point ids each;
   * added points numbered from the grid's number of points on). Returns how
   * many; 0 for a cell with no faces.
   */
  vtkIdType Split(vtkIdType cellId, std::vector<vtkIdType>& tets);

private:
  PolyhedronSplitter(const PolyhedronSplitter&) = delete;
  void operator=(const PolyhedronSplitter&) = delete;

  // Adds point x with the cell's weights there; returns its id.
  vtkIdType AddPoint(const double x[3]);

  vtkUnstructuredGrid* Grid;
  const QuadDiagonals& Diagonals;
  AddedPoints& Added;
  vtkNew<vtkGenericCell> Cell;
  std::vector<double> CellWeights;
  std::map<std::vector<vtkIdType>, vtkIdType> FaceCentres; // sorted face ids: added point
};
}

#endif
