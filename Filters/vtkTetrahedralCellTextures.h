/**
 * @class   vtkTetrahedralCellTextures
 * @brief   per-tetrahedron "cell textures" of a mesh, built on the CPU
 *
 * The data a cell-to-cell ray caster needs per tetrahedron (Espinha & Celes
 * 2005, Sec. 3.1; Weiler et al. 2003, Sec. 3): four outward face planes
 * (unit normal n_f and d_f = n_f . x on the face), four neighbour codes and
 * the linear scalar field s(x) = g . x + s0, i.e. 96 bytes per tetrahedron.
 *
 * Two caches with one reason each to be rebuilt:
 * - BuildGeometry(): when points or cells change. Coordinates are expressed
 *   relative to the centre of the bounds (GetOrigin()) so that meshes far from
 *   the origin keep single-precision accuracy. A zero-volume (flat)
 *   tetrahedron stays in the mesh with its four corners in place of its
 *   planes (FlatCellMarker() in each w): a ray crosses it with zero length,
 *   out through the face that contains the point where it came in.
 *   Neighbours are paired by side where more than two tetrahedra share a
 *   face, and folded faces are marked (vtkUnstructuredGridCellAdjacency).
 *   In a convexified grid the mesh's boundary faces are joined to the
 *   imaginary faces on them that point ids do not join (a face split by
 *   Steiner points, a seam; ppirayBoundaryFaceLinks.h): a split face's
 *   neighbour code names the list of its pieces.
 *   Also gives the boundary triangles, wound outward, with their points.
 * - BuildField(): when the scalars change. Point scalars give the linear
 *   interpolant's gradient; cell scalars a constant. A tetrahedron touching a
 *   NaN scalar, or of a cell the ghost array marks HIDDENCELL (read by
 *   BuildGeometry: blanked cells, convexification's imaginary cells), gets
 *   the TransparentCellOffset() marker: traversed, rendered empty.
 *
 * Two layouts (SetLayout()): PLANES stores what the march reads, face
 * planes and field per tetrahedron (96 bytes with the neighbours); COMPACT
 * stores the corners, point ids per tetrahedron and coordinates and scalar
 * per point (Maximo et al. 2008, Sec. 4.1), from which the march computes
 * the same planes and field (36 bytes per tetrahedron, 16 per point).
 *
 * No OpenGL here: the mapper uploads these arrays as buffer textures.
 */
#ifndef vtkTetrahedralCellTextures_h
#define vtkTetrahedralCellTextures_h

#include "ppirayFiltersModule.h"       // for export macro
#include "ppirayPolyhedra.h"           // for ppiray::AddedPoints
#include "ppirayStageTimes.h"          // for ppiray::StageTimes
#include "ppirayUninitializedVector.h" // for ppiray::UninitializedVector
#include "vtkNew.h"                    // for vtkNew
#include "vtkObject.h"
#include "vtkUnstructuredGridCellAdjacency.h" // for the adjacency kept between builds

#include <vector> // for std::vector

class vtkDataArray;
class vtkUnstructuredGrid;

class PPIRAYFILTERS_EXPORT vtkTetrahedralCellTextures : public vtkObject
{
public:
  static vtkTetrahedralCellTextures* New();
  vtkTypeMacro(vtkTetrahedralCellTextures, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Layouts
  {
    PLANES = 0, // GetFacePlanes(), GetField()
    COMPACT = 1 // GetCellCorners(), GetPointTexels(), GetCellValues()
  };
  ///@{
  /** The arrays BuildGeometry() and BuildField() make (Layouts), default PLANES. */
  vtkSetClampMacro(Layout, int, PLANES, COMPACT);
  int GetLayout() const { return this->Layout; }
  ///@}

  /**
   * Planes, neighbours and boundary of the tetrahedra of `grid`: its
   * tetrahedra, and its hexahedra, voxels, wedges and pyramids (linear, or
   * quadratic through their corners) split into tetrahedra that conform
   * across shared faces (ppirayConformingTetrahedra.h). Other cell types are
   * left out and counted (GetUnsupportedCellTypes()). Returns false when no
   * tetrahedron is left.
   */
  bool BuildGeometry(vtkUnstructuredGrid* grid);

  /** Wall time of each stage of the last BuildGeometry(), in order. */
  const ppiray::StageTimes& GetStageTimes() const { return this->Stages; }

  /**
   * Linear field per tetrahedron from `scalars` (point data when `cellScalars`
   * is false, else cell data), using `component`. Call after BuildGeometry().
   */
  bool BuildField(vtkDataArray* scalars, bool cellScalars, int component);

  /**
   * Value stored as s0 of a tetrahedron that must render empty (NaN scalar).
   */
  static constexpr float TransparentCellOffset() { return -3.0e38f; }

  /** The w of a flat tetrahedron's four texels in GetFacePlanes(). */
  static constexpr float FlatCellMarker() { return 3.0e38f; }

  ///@{
  /**
   * Neighbour codes: 4 * tetrahedron + its face; where the face is folded
   * (both tetrahedra on the same side of it), -(code + 2) if the ray walks
   * back through the neighbour (it is inverted), -(code + 2 + TurnBack())
   * if it walks back through the cell it is in (that one is inverted, the
   * neighbour not); NoNeighbor() on the boundary; SplitFace() + i for a
   * boundary face split into pieces (convexification), whose list starts
   * at texel i of GetNeighbors(): (n, code_1, code_2, ...), the codes of the
   * n imaginary faces on it or faces across it (n plus
   * ppiray::LensList() across a lens), in texels of 4 (at most
   * MaximumPieces());
   * ReentryFace() + i for a boundary face with a reflex edge
   * (ppirayReflexEdges.h), texel i holding the codes of the boundary faces
   * across its edges (-1: none left).
   */
  static constexpr int NoNeighbor() { return -1; }
  static constexpr int TurnBack() { return 1 << 29; }
  static constexpr int SplitFace() { return 1 << 30; }
  static constexpr int ReentryFace() { return (1 << 30) + (1 << 29); }
  static constexpr int MaximumPieces() { return 1024; }
  ///@}

  ///@{
  /**
   * COMPACT layout: added to the fourth point id of a tetrahedron in
   * GetCellCorners() when it is inverted (its faces wound inward) and when it
   * is flat (zero volume); point ids stay below InvertedCorners().
   */
  static constexpr int InvertedCorners() { return 1 << 29; }
  static constexpr int FlatCorners() { return 1 << 30; }
  static int NeighborCode(vtkIdType tet, int face, bool folded, bool turnBack)
  {
    const int code = static_cast<int>(4 * tet + face);
    return folded ? -(code + 2 + (turnBack ? TurnBack() : 0)) : code;
  }
  ///@}

  vtkIdType GetNumberOfTetrahedra() const { return static_cast<vtkIdType>(this->CellIds.size()); }
  /** Point ids of the tetrahedra, 4 each (into the grid's points). */
  const std::vector<vtkIdType>& GetTetrahedra() const { return this->Tets; }
  /** The grid's points relative to GetOrigin(), 3 each, in double. */
  const std::vector<double>& GetLocalPoints() const { return this->LocalPoints; }
  /** Whether tetrahedron t is flat (zero volume; kept, crossed with zero length). */
  bool IsFlat(vtkIdType t) const { return this->Degenerate[t] != 0; }
  /** Cell id in the input grid of each tetrahedron. */
  const std::vector<vtkIdType>& GetCellIds() const { return this->CellIds; }
  /** Centre of the bounds: all coordinates below are relative to it. */
  const double* GetOrigin() const { return this->Origin; }
  /** Length of the diagonal of the bounds. */
  double GetLength() const { return this->Length; }
  /** Longest edge of a rendered tetrahedron: no ray segment in a cell is longer. */
  double GetMaximumEdgeLength() const { return this->MaximumEdgeLength; }
  /**
   * 16 floats per tetrahedron: (n_f, d_f) for faces f = 0..3; a flat
   * tetrahedron's corners (x_v, FlatCellMarker()) for v = 0..3.
   */
  const ppiray::UninitializedVector<float>& GetFacePlanes() const { return this->FacePlanes; }
  /**
   * 4 ints per tetrahedron: the neighbour code through face f (NeighborCode());
   * then the lists of split faces' pieces.
   */
  const std::vector<int>& GetNeighbors() const { return this->Neighbors; }
  /** 4 floats per tetrahedron: (g, s0) with s(x) = g . x + s0. */
  const std::vector<float>& GetField() const { return this->Field; }
  ///@{
  /**
   * COMPACT layout: 4 ints per tetrahedron, its point ids (the fourth plus
   * InvertedCorners(), FlatCorners() as they apply); 4 floats per grid
   * point, (x, s) with x relative to GetOrigin() and s its scalar (0 for
   * cell scalars and for NaN); 1 float per tetrahedron, added to the linear
   * interpolant of the points' s: the cell scalar, 0 for point scalars, or
   * TransparentCellOffset().
   */
  const std::vector<int>& GetCellCorners() const { return this->CellCorners; }
  const std::vector<float>& GetPointTexels() const { return this->PointTexels; }
  const std::vector<float>& GetCellValues() const { return this->CellValues; }
  ///@}
  /** Boundary points, 3 floats each (relative to GetOrigin()). */
  const std::vector<float>& GetBoundaryPoints() const { return this->BoundaryPoints; }
  /** Boundary triangles, 3 indices into GetBoundaryPoints(), wound outward. */
  const std::vector<unsigned int>& GetBoundaryTriangles() const { return this->BoundaryTriangles; }
  /** Per boundary triangle: 4 * tetrahedron + local face. */
  const std::vector<int>& GetBoundaryFaces() const { return this->BoundaryFaces; }

  vtkGetMacro(NumberOfDegenerateTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfInvertedTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldFaces, vtkIdType);
  vtkGetMacro(NumberOfFoldedFaces, vtkIdType);
  vtkGetMacro(NumberOfNaNScalars, vtkIdType);
  /** Tetrahedra of cells marked HIDDENCELL (traversed, rendered empty). */
  vtkGetMacro(NumberOfHiddenTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfUnsupportedCells, vtkIdType);
  ///@{
  /**
   * Convexified grids: boundary faces joined to imaginary faces that point
   * ids do not join (linked), those of them split into several pieces, the
   * most pieces on one face, and faces left open (pieces that do not cover
   * them, or more than MaximumPieces(); imaginary faces on no open face).
   */
  vtkGetMacro(NumberOfLinkedFaces, vtkIdType);
  vtkGetMacro(NumberOfSplitFaces, vtkIdType);
  /**
   * Open faces linked to the open faces of other cells that meet them
   * geometrically, not by point ids (hanging nodes, T-junctions:
   * ppirayNonConformingFaces.h); a list where more than one meets a face.
   */
  vtkGetMacro(NumberOfNonConformingFaces, vtkIdType);
  /**
   * Of those, faces of a quadrilateral split along other diagonals on its
   * two sides (a lens between them: ppiray::MatchSplitQuadrilaterals).
   */
  vtkGetMacro(NumberOfLensFaces, vtkIdType);
  /**
   * Polyhedra split into tetrahedra (ppirayPolyhedra.h: a cone from an added
   * point at their centre; faces of five or more corners fanned from an added
   * point), counted in GetNumberOfSplitCells() too.
   */
  vtkGetMacro(NumberOfPolyhedra, vtkIdType);
  vtkGetMacro(MaximumPiecesPerFace, int);
  vtkGetMacro(NumberOfUnlinkedFaces, vtkIdType);
  ///@}

  /** Boundary faces with a reflex edge (a re-entry across it is checked). */
  vtkGetMacro(NumberOfReentryFaces, vtkIdType);
  /** Hexahedra, voxels, wedges and pyramids split into tetrahedra. */
  vtkGetMacro(NumberOfSplitCells, vtkIdType);
  /** Quadratic (or higher-order) cells, split through their linear corners. */
  vtkGetMacro(NumberOfQuadraticCells, vtkIdType);
  /** Pairs (VTK cell type, count) of the cells left out. */
  const std::vector<vtkIdType>& GetUnsupportedCellTypes() const { return this->Unsupported; }

  ///@{
  /**
   * The layout: texels (4 values each) per tetrahedron in GetFacePlanes(),
   * GetNeighbors() and GetField(), read by the GPU march with these counts
   * (vtkPPIRayTetrahedralCellBuffers); bytes of the three arrays.
   */
  static constexpr int FacePlaneTexels() { return 4; }
  static constexpr int NeighborTexels() { return 1; }
  static constexpr int FieldTexels() { return 1; }
  static constexpr int BytesPerTetrahedron()
  {
    return 16 * (FacePlaneTexels() + NeighborTexels() + FieldTexels());
  }
  /** COMPACT layout: bytes per tetrahedron (corners, neighbours, value) and per point. */
  static constexpr int CompactBytesPerTetrahedron() { return 16 + 16 * NeighborTexels() + 4; }
  static constexpr int CompactBytesPerPoint() { return 16; }
  ///@}

protected:
  vtkTetrahedralCellTextures() = default;
  ~vtkTetrahedralCellTextures() override = default;

  // Joins boundary faces (pairs tetrahedron, face) to the imaginary faces
  // on them (convexified grids): neighbour codes both ways, lists of pieces
  // appended to Neighbors; returns which faces (4 t + f) are joined.
  std::vector<unsigned char> LinkBoundaryFaces(
    vtkUnstructuredGrid* grid, const std::vector<vtkIdType>& boundary);

  // Links the open faces left after LinkBoundaryFaces() (`linked`) to the
  // open faces across them (ppiray::LinkNonConformingFaces); marks those
  // covered as linked.
  void LinkNonConformingFaces(const std::vector<vtkIdType>& boundary,
    const std::vector<signed char>& orientation, std::vector<unsigned char>& linked);

  // Whether the triangle of flat tetrahedron t's corners (local indices,
  // counter-clockwise) faces the first non-flat cell reached from t through
  // flat ones (ppiray::NearestSolidCell).
  bool FacesTowards(vtkIdType t, const int corner[3], const std::vector<int>& neighbors) const;

  int Layout = PLANES;
  double Origin[3] = { 0, 0, 0 };
  double Length = 0;
  double MaximumEdgeLength = 0;
  std::vector<vtkIdType> Tets; // 4 point ids per tetrahedron
  std::vector<vtkIdType> CellIds;
  std::vector<unsigned char> Degenerate;
  std::vector<unsigned char> Hidden;
  ppiray::UninitializedVector<float> FacePlanes; // filled whole by the planes' parallel loop
  std::vector<int> Neighbors;
  std::vector<float> Field;
  std::vector<int> CellCorners;
  std::vector<float> PointTexels;
  std::vector<float> CellValues;
  std::vector<float> BoundaryPoints;
  std::vector<unsigned int> BoundaryTriangles;
  std::vector<int> BoundaryFaces;
  std::vector<vtkIdType> Unsupported;
  std::vector<double> LocalPoints;  // 3 per grid point and added point, relative to Origin
  ppiray::AddedPoints Added;        // points the split of polyhedra adds
  vtkIdType NumberOfGridPoints = 0; // added points are numbered from here
  vtkIdType NumberOfPolyhedra = 0;
  // The value at point `id`: a grid point's, or an added point's interpolation.
  double PointValue(vtkDataArray* values, vtkIdType id, int component) const;
  vtkIdType NumberOfDegenerateTetrahedra = 0;
  vtkIdType NumberOfInvertedTetrahedra = 0;
  vtkIdType NumberOfNonManifoldFaces = 0;
  vtkIdType NumberOfFoldedFaces = 0;
  vtkIdType NumberOfNaNScalars = 0;
  vtkIdType NumberOfHiddenTetrahedra = 0;
  vtkIdType NumberOfUnsupportedCells = 0;
  vtkIdType NumberOfLinkedFaces = 0;
  vtkIdType NumberOfSplitFaces = 0;
  int MaximumPiecesPerFace = 0;
  vtkIdType NumberOfUnlinkedFaces = 0;
  vtkIdType NumberOfReentryFaces = 0;
  vtkIdType NumberOfNonConformingFaces = 0;
  vtkIdType NumberOfLensFaces = 0;
  vtkIdType NumberOfSplitCells = 0;
  vtkIdType NumberOfQuadraticCells = 0;

private:
  ppiray::StageTimes Stages; // of the last BuildGeometry()
  // Kept between builds: the same tetrahedra find only their folds again.
  vtkNew<vtkUnstructuredGridCellAdjacency> Adjacency;
  vtkTetrahedralCellTextures(const vtkTetrahedralCellTextures&) = delete;
  void operator=(const vtkTetrahedralCellTextures&) = delete;
};

#endif
