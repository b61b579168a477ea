/**
 * @class   vtkUnstructuredGridConvexify
 * @brief   fills the convex box around an unstructured grid with imaginary tetrahedra
 *
 * Output: the input's cells and points unchanged, followed by tetrahedra
 * that fill an axis-aligned box around the mesh (inflated by Margin times
 * the diagonal on every side) minus the mesh itself: the space between the
 * mesh and the box, its cavities, holes and the gaps between its parts.
 * They conform to the mesh's boundary (as its cells are split into
 * tetrahedra for rendering, ppirayConformingTetrahedra.h): each boundary
 * triangle is the face of one imaginary tetrahedron, or is split by Steiner
 * points into several whose union it is. The box is convex, so a ray through
 * the output enters it once and leaves it once (Weiler et al. 2003, Sec. 3.3).
 *
 * Imaginary cells are marked in the ghost array ("vtkGhostType",
 * vtkDataSetAttributes::HIDDENCELL: part of the grid, never shown) and, for
 * each of their faces on a boundary triangle, "ppirayBoundaryCell" gives the
 * input cell across it (-1 elsewhere; 4 components, face f opposite corner
 * f; on an input cell the fill was made without, -2 in the first, see
 * below). Point and cell arrays take each component's minimum over the input on
 * the new points and cells (finite, ranges unchanged: imaginary cells emit
 * nothing). Built with a conforming constrained Delaunay triangulation
 * (CGAL >= 6.1; GPL, hence this module of its own).
 *
 * What bounds no volume is left out of the fill, as ParaView's Clip and
 * Tetrahedralize leave it: points within Tolerance of each other are taken
 * as one, tetrahedra of zero volume (flat, or with corners taken as one) are
 * left out, so that faces shared by more than two cells pair up, and so are
 * boundary triangles that bound nothing (degenerate ones, and the two sides
 * of a seam where cells meet without sharing point ids, as at an O-grid's
 * cut). Parts that touch along edges or at points are filled around as they
 * are. The counts say what was left out. A boundary that still intersects
 * itself (tangled or overlapping cells) bounds no volume: an error says so
 * and the output is the input, unchanged.
 *
 * A time series: an input with the geometry of the last one convexified (the
 * same points, cells, types, faces and hidden flags: ppiray::GridGeometryKey)
 * keeps its fill; only the point and cell arrays are the new input's.
 */
#ifndef vtkUnstructuredGridConvexify_h
#define vtkUnstructuredGridConvexify_h

#include "ppirayConvexifyModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <memory> // for std::unique_ptr

class PPIRAYCONVEXIFY_EXPORT vtkUnstructuredGridConvexify : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkUnstructuredGridConvexify* New();
  vtkTypeMacro(vtkUnstructuredGridConvexify, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * How far the box reaches past the mesh's bounds on every side, as a
   * fraction of the bounds' diagonal (default 0.02).
   */
  vtkSetClampMacro(Margin, double, 1e-6, 10.0);
  vtkGetMacro(Margin, double);
  ///@}

  ///@{
  /**
   * Points closer than Tolerance times the diagonal of the input's bounds
   * are taken as one for the fill (default 1e-6; 0: only points at the same
   * place): a clip computes a point where two cut edges meet once per edge,
   * a few roundings apart, and the faces between such points bound nothing.
   */
  vtkSetClampMacro(Tolerance, double, 0.0, 1e-2);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Of the last execution: imaginary tetrahedra added, Steiner points the
   * triangulation put on the mesh's boundary, points added (box corners and
   * Steiner points), and seconds taken.
   */
  vtkGetMacro(NumberOfImaginaryCells, vtkIdType);
  vtkGetMacro(NumberOfSteinerPoints, vtkIdType);
  vtkGetMacro(NumberOfAddedPoints, vtkIdType);
  /// Points within the tolerance of another (taken as that one for the fill).
  vtkGetMacro(NumberOfMergedPoints, vtkIdType);
  /// Tetrahedra of the cells' split with zero volume (once points are
  /// merged: repeated or coplanar corners), left out of the fill's boundary.
  vtkGetMacro(NumberOfFlatTetrahedra, vtkIdType);
  /// Boundary triangles that bound nothing: degenerate, or a seam's two sides.
  vtkGetMacro(NumberOfDroppedTriangles, vtkIdType);
  vtkGetMacro(ExecutionTime, double);
  ///@}

  /// Name of the 4-component cell array of input cells across imaginary faces.
  static const char* BoundaryCellArrayName();

protected:
  vtkUnstructuredGridConvexify();
  ~vtkUnstructuredGridConvexify() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Margin = 0.02;
  double Tolerance = 1e-6;
  vtkIdType NumberOfImaginaryCells = 0;
  vtkIdType NumberOfSteinerPoints = 0;
  vtkIdType NumberOfAddedPoints = 0;
  vtkIdType NumberOfMergedPoints = 0;
  vtkIdType NumberOfFlatTetrahedra = 0;
  vtkIdType NumberOfDroppedTriangles = 0;
  double ExecutionTime = 0.0;

private:
  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  vtkUnstructuredGridConvexify(const vtkUnstructuredGridConvexify&) = delete;
  void operator=(const vtkUnstructuredGridConvexify&) = delete;
};

#endif
