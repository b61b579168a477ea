/**
 * @class   vtkHexahedralCellTextures
 * @brief   per-cell "cell textures" for ray casting hexahedra, wedges,
 *          pyramids and tetrahedra without subdividing them, built on the CPU
 *
 * Per hexahedron, 160 bytes (Miranda 2011, Sec. 3.3 stores 248: twelve face
 * planes, six neighbours and eight world-frame coefficients):
 * - corners: the 8 corners (24 floats) relative to the centre of the mesh's
 *   bounds, in VTK_HEXAHEDRON order, right-handed (a mirrored hexahedron has
 *   its bottom and top swapped). Face planes are derived from them on the GPU;
 * - neighbours: the hexahedron through each face of vtkHexahedron::GetFaceArray
 *   (-1 on the boundary; matched, paired by side and folds marked by the
 *   stage every layout shares, ppirayCellAdjacency.h), and a 6-bit mask: bit f set when face f is
 * split into triangles along its second diagonal (q1-q3), clear along q0-q2, by the rule of
 * ppirayConformingTetrahedra.h (the diagonal through the smallest point id), so both cells sharing
 * a face see the same two triangles;
 * - coefficients: c0..c7 of the trilinear field in the cell's frame (origin
 *   corner 0, axes to corners 1, 3, 4; vtkHexahedronCoefficients); of a
 *   wedge or tetrahedron VTK's interpolation in its frame (axes to corners
 *   1, 2, 3: exact for an affine wedge and any tetrahedron); of a pyramid its
 *   five corner values (the GPU evaluates VTK's pyramid); c0 =
 *   TransparentCellOffset() for a cell touching a NaN scalar or marked
 *   HIDDENCELL in the ghost array (ppirayHiddenCells.h). In a mesh with
 *   quadratic tetrahedra a third texel per cell: c8..c10, the squares' terms
 *   of a quadratic tetrahedron's field (ppirayQuadraticTetrahedra.h; zero for
 *   every other cell).
 *
 * Also the boundary triangles (two per boundary face, split by the same rule,
 * wound outward) with their points and, per triangle, 12 h + 2 f + (0 or 1).
 *
 * Cells: VTK_HEXAHEDRON, VTK_VOXEL, VTK_WEDGE, VTK_PYRAMID, VTK_TETRA,
 * ten-node quadratic tetrahedra (VTK_QUADRATIC_TETRA, VTK_LAGRANGE_TETRAHEDRON
 * of order 2: their quadratic field, in the straight-edged tetrahedron of
 * their corners; through their corners where a mid-edge node is so far off
 * its edge's midpoint that the cell's map may fold,
 * ppirayQuadraticTetrahedra.h) and the other quadratic and higher-order
 * tetrahedra, hexahedra, wedges and pyramids (refined into ten-node
 * tetrahedra with VTK's map and field at their nodes,
 * ppirayHigherOrderPieces.h: GetRefinementLevels()), in one grid (a
 * "hexahedron" below is any of them: its kind, ppirayLinearCellKinds.h, is
 * stored with its neighbours; a kind with fewer than 8 corners repeats
 * corner 0 in the unused slots, and has fewer faces). Zero-volume ones
 * (pinched-out layers) are kept, flagged with FLAT_KIND_BIT in their kind,
 * and crossed with zero length (GetNumberOfFlatHexahedra()).
 * A grid with other cells, or of linear tetrahedra only, is only counted
 * (GetNumberOfOtherCells(); BuildGeometry() returns false and builds
 * nothing): the ray caster renders such meshes as tetrahedra. No OpenGL here.
 */
#ifndef vtkHexahedralCellTextures_h
#define vtkHexahedralCellTextures_h

#include "ppirayCellAdjacency.h"     // for ppiray::CellAdjacencyCache
#include "ppirayFiltersModule.h"     // for export macro
#include "ppirayHigherOrderPieces.h" // for ppiray::HigherOrderPieces
#include "ppirayStageTimes.h"        // for ppiray::StageTimes
#include "vtkObject.h"

#include <vector> // for std::vector

namespace ppiray
{
struct CellFaceMesh;
}

class vtkDataArray;
class vtkUnstructuredGrid;

class PPIRAYFILTERS_EXPORT vtkHexahedralCellTextures : public vtkObject
{
public:
  static vtkHexahedralCellTextures* New();
  vtkTypeMacro(vtkHexahedralCellTextures, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Corners, neighbours, diagonals and boundary. False if there is no
   * hexahedron or there are other cells.
   */
  bool BuildGeometry(vtkUnstructuredGrid* grid);

  /** Wall time of each stage of the last BuildGeometry(), in order. */
  const ppiray::StageTimes& GetStageTimes() const { return this->Stages; }

  /**
   * Coefficients from `scalars` (point data, or cell data when `cellScalars`:
   * a constant c0), `component`. Call after BuildGeometry().
   */
  bool BuildField(vtkDataArray* scalars, bool cellScalars, int component);

  /** Value stored as c0 of a hexahedron that must render empty (NaN scalar). */
  static constexpr float TransparentCellOffset() { return -3.0e38f; }

  /**
   * Neighbour code: 6 * hexahedron + its face; across a folded face (both
   * cells on one side of it) -(code + 2) if the ray walks back through the
   * neighbour, -(code + 2 + TurnBack()) if it walks back through the cell it
   * is in (that one is inverted, the neighbour not: ppirayInvertedSheets.h);
   * -1 on the boundary.
   */
  static constexpr int TurnBack() { return 1 << 29; }
  /**
   * SplitFace() + i: a face met by faces of other cells, its list at
   * neighbour texel i: their number n (plus ppiray::LensList() across a
   * lens), then their codes (ppiray::AppendFaceList).
   */
  static constexpr int SplitFace() { return 1 << 30; }
  /** The most faces a list names (a face met by more is left open). */
  static constexpr int MaximumPieces() { return 1024; }
  /**
   * ReentryFace() + i: a boundary face with a reflex edge
   * (ppirayReflexEdges.h), texel i holding the codes of the boundary faces
   * across its edges (-1: none left).
   */
  static constexpr int ReentryFace() { return (1 << 30) + (1 << 29); }
  static int NeighborCode(vtkIdType hexahedron, int face, bool folded, bool turnBack)
  {
    const int code = static_cast<int>(6 * hexahedron + face);
    return folded ? -(code + 2 + (turnBack ? TurnBack() : 0)) : code;
  }

  vtkIdType GetNumberOfHexahedra() const { return static_cast<vtkIdType>(this->CellIds.size()); }
  const double* GetOrigin() const { return this->Origin; }
  double GetLength() const { return this->Length; }
  /** The largest distance between two corners of one hexahedron. */
  double GetMaximumCellDiameter() const { return this->MaximumCellDiameter; }
  /** Input cell id of each hexahedron. */
  /** The kind of each cell (ppiray::LinearCellKind). */
  const std::vector<unsigned char>& GetKinds() const { return this->Kinds; }
  /** Cells of a kind (ppiray::LinearCellKind) kept. */
  vtkIdType GetNumberOfCellsOfKind(int kind) const { return this->NumberOfCellsOfKind[kind]; }
  const std::vector<vtkIdType>& GetCellIds() const { return this->CellIds; }
  /** Point ids, 8 per hexahedron, in the (right-handed) order of the corners. */
  const std::vector<vtkIdType>& GetCornerIds() const { return this->CornerIds; }
  /** 24 floats per hexahedron (6 RGBA texels). */
  const std::vector<float>& GetCorners() const { return this->Corners; }
  /**
   * 8 ints per hexahedron (2 RGBA texels): 6 neighbour codes (NeighborCode():
   * the neighbour and the face it is entered by), the diagonal mask, the kind.
   */
  const std::vector<int>& GetNeighbors() const { return this->Neighbors; }
  /** 4 GetCoefficientTexels() floats per hexahedron. */
  const std::vector<float>& GetCoefficients() const { return this->Coefficients; }
  const std::vector<float>& GetBoundaryPoints() const { return this->BoundaryPoints; }
  const std::vector<unsigned int>& GetBoundaryTriangles() const { return this->BoundaryTriangles; }
  /** Per boundary triangle: 12 h + 2 f + t (t: first or second triangle of face f). */
  const std::vector<int>& GetBoundaryFaces() const { return this->BoundaryFaces; }

  vtkGetMacro(NumberOfMirroredHexahedra, vtkIdType);
  /**
   * Cell faces on a face that more than two cell faces share (paired by side,
   * ppirayCellAdjacency.h).
   */
  vtkGetMacro(NumberOfNonManifoldFaces, vtkIdType);
  /**
   * Faces split along the diagonal that does not go through their smallest
   * point id, because that split folds a triangle of a collapsed hexahedron
   * (repeated corner ids: a pyramid or wedge written as a hexahedron) onto
   * another of its faces. Both cells sharing such a face split it the same way.
   */
  vtkGetMacro(NumberOfUnfoldedFaces, vtkIdType);
  /** Shared faces whose two hexahedra lie on one side of them (a tangled mesh). */
  vtkGetMacro(NumberOfFoldedFaces, vtkIdType);
  /** Quadrilaterals met by two triangles of other cells (SplitFace()). */
  vtkGetMacro(NumberOfSplitQuadrilaterals, vtkIdType);
  /**
   * Open faces linked to the open faces of other cells that meet them
   * geometrically, not by point ids (hanging nodes, T-junctions:
   * ppirayNonConformingFaces.h), and the longest list of a face (these and
   * the split quadrilaterals').
   */
  vtkGetMacro(NumberOfNonConformingFaces, vtkIdType);
  /**
   * Of those, faces of a quadrilateral split along other diagonals on its
   * two sides (a lens between them: ppiray::MatchSplitQuadrilaterals).
   */
  vtkGetMacro(NumberOfLensFaces, vtkIdType);
  vtkGetMacro(MaximumPiecesPerFace, int);
  /** Boundary faces with a reflex edge (ReentryFace()). */
  vtkGetMacro(NumberOfReentryFaces, vtkIdType);
  /** Input cells rendered empty for a NaN scalar (a refined cell counts once). */
  vtkGetMacro(NumberOfNaNScalars, vtkIdType);
  /**
   * Hexahedra whose frame is singular, |det M| <= 1e-6 |a| |b| |c|, at every
   * corner (flat cells): the field cannot be expressed in a cell frame
   * (BuildGeometry()). When only corner 0 is collapsed or flat (pinch-outs),
   * the corners are renumbered (a rotation of the cube, still right-handed)
   * so that the best-shaped corner becomes corner 0.
   */
  vtkGetMacro(NumberOfSingularFrames, vtkIdType);
  /** Zero-volume cells (in GetNumberOfHexahedra(): crossed with zero length). */
  vtkGetMacro(NumberOfFlatHexahedra, vtkIdType);
  vtkGetMacro(NumberOfOtherCells, vtkIdType);
  /**
   * Quadratic tetrahedra rendered through their linear corners (a mid-edge
   * node beyond FoldingDeviation: the cell's map may fold).
   */
  vtkGetMacro(NumberOfQuadraticCells, vtkIdType);
  /**
   * Quadratic and higher-order cells other than ten-node tetrahedra: always
   * refined (GetRefinementLevels()).
   */
  vtkGetMacro(NumberOfHigherOrderCells, vtkIdType);
  /** Whether some cells carry a quadratic field (ten-node tetrahedra). */
  bool HasQuadraticField() const { return !this->EdgeNodeIds.empty(); }
  /**
   * Quadratic tetrahedra with a mid-edge node more than CurvedEdgeTolerance()
   * of its edge's length from the edge's midpoint (GetRefinementLevels()).
   */
  vtkGetMacro(NumberOfCurvedCells, vtkIdType);
  vtkGetMacro(MaximumMidEdgeDeviation, double);
  static constexpr double CurvedEdgeTolerance() { return 4e-3; }
  /**
   * Levels the higher-order cells are refined by (ppirayHigherOrderPieces.h),
   * all by the same so that their pieces conform: the fewest that bring the
   * largest mid-edge offset of a piece below CurvedEdgeTolerance() of an edge
   * (it shrinks fourfold per level), at least GetMinimumRefinementLevel()
   * when there are higher-order cells other than ten-node tetrahedra, at
   * most 3, and at most MaximumRefinedPieces() pieces in all or one level if
   * that is more. Ten-node tetrahedra are refined only with 1 level or more
   * (they are exact unrefined). The pieces are rendered with straight edges.
   */
  vtkGetMacro(RefinementLevels, int);
  /**
   * The fewest levels cells other than ten-node tetrahedra are refined by
   * (like ParaView's Nonlinear Subdivision Level): each level cuts the
   * interpolation error of a smooth field about eightfold and multiplies the
   * pieces by 8. Default 0; at most 3.
   */
  vtkSetClampMacro(MinimumRefinementLevel, int, 0, 3);
  vtkGetMacro(MinimumRefinementLevel, int);
  static constexpr vtkIdType MaximumRefinedPieces() { return vtkIdType(1) << 20; }
  /**
   * Quadratic and higher-order cells with a NaN at a node other than a
   * corner (none at a corner): rendered through their corners.
   */
  vtkGetMacro(NumberOfLinearizedCells, vtkIdType);

  ///@{
  /**
   * The layout: texels (4 values each) per hexahedron in GetCorners(),
   * GetNeighbors() and GetCoefficients(), read by the GPU march with these
   * counts (vtkPPIRayHexahedralCellBuffers).
   */
  static constexpr int CornerTexels() { return 6; }
  static constexpr int NeighborTexels() { return 2; }
  static constexpr int CoefficientTexels() { return 2; }
  static constexpr int BytesPerHexahedron()
  {
    return 16 * (CornerTexels() + NeighborTexels() + CoefficientTexels());
  }
  /** Coefficient texels per cell of this mesh: one more with a quadratic field. */
  int GetCoefficientTexels() const
  {
    return CoefficientTexels() + (this->HasQuadraticField() ? 1 : 0);
  }
  ///@}

  /**
   * Corner v (0..2) of triangle t (0, 1; a triangular face has only 0) of
   * face f of a cell of kind `kind`, given the face's diagonal bit.
   */
  static int TriangleCorner(int kind, int f, int t, int v, bool secondDiagonal);

protected:
  vtkHexahedralCellTextures() = default;
  ~vtkHexahedralCellTextures() override = default;

  // The steps of BuildGeometry().
  void Clear();
  bool CollectCells(vtkUnstructuredGrid* grid); // false: not for these textures
  void AddEdgeNodes(const vtkIdType* mids);     // a collected cell's (nullptr: none)
  bool HasEdgeNodes(vtkIdType h) const;
  void MarkFlatCells();
  // Links the open faces left in `boundary` (6 h + f, sorted) to the open
  // faces across them (ppiray::LinkNonConformingFaces); removes those
  // covered.
  void LinkNonConformingFaces(std::vector<vtkIdType>& boundary);
  // Quadrilateral a (6 h + f), linked to quadrilateral b whose corners are
  // at the same places (a seam's duplicated points), split along the same
  // diagonal as b where a > b: both sides then march through the same two
  // triangles, as faces paired by point ids do.
  void SplitAlongLinkedDiagonal(vtkIdType a, vtkIdType b);
  // Whether face f of flat cell h, wound as its kind winds it, faces the
  // first non-flat cell reached from h: a boundary face of a flat cell is
  // wound away from the cells it lies on.
  bool FacesSolidNeighbor(vtkIdType h, int f) const;
  void OrientCells();
  void RefineHigherOrderCells(vtkUnstructuredGrid* grid);
  void ReplaceByPieces(const std::vector<vtkIdType>& refined);
  // Per refined cell: THROUGH_CORNERS (a NaN at a node other than a corner),
  // EMPTY (a NaN at a corner) or 0.
  enum RefinedField
  {
    THROUGH_CORNERS = 1,
    EMPTY = 2
  };
  std::vector<unsigned char> RefinedFields(vtkDataArray* scalars, int component) const;
  void StoreCorners();
  ppiray::CellFaceMesh FaceMesh() const; // the cells for ppiray::MatchCellFaces
  std::vector<vtkIdType> MatchFaces();   // the boundary faces, 6 h + f
  void LinkSplitQuadrilaterals(std::vector<vtkIdType>& boundary);
  void ExtractBoundary(const std::vector<vtkIdType>& boundary, vtkIdType numberOfPoints);

  double Origin[3] = { 0, 0, 0 };
  double Length = 0;
  double MaximumCellDiameter = 0;
  std::vector<vtkIdType> CellIds;
  std::vector<unsigned char> Kinds;
  vtkIdType NumberOfCellsOfKind[4] = { 0, 0, 0, 0 };
  std::vector<unsigned char> Hidden; // ppirayHiddenCells.h
  std::vector<unsigned char> Flat;   // zero volume
  std::vector<vtkIdType> CornerIds;
  std::vector<vtkIdType> EdgeNodeIds; // 6 per cell, renumbered with the corners (-1: none)
  std::vector<float> Corners;
  std::vector<int> Neighbors;
  std::vector<float> Coefficients;
  std::vector<float> BoundaryPoints;
  std::vector<unsigned int> BoundaryTriangles;
  std::vector<int> BoundaryFaces;
  std::vector<double> LocalPoints;
  vtkIdType NumberOfMirroredHexahedra = 0;
  vtkIdType NumberOfNonManifoldFaces = 0;
  vtkIdType NumberOfUnfoldedFaces = 0;
  vtkIdType NumberOfFoldedFaces = 0;
  vtkIdType NumberOfSplitQuadrilaterals = 0;
  vtkIdType NumberOfReentryFaces = 0;
  vtkIdType NumberOfNaNScalars = 0;
  vtkIdType NumberOfSingularFrames = 0;
  vtkIdType NumberOfFlatHexahedra = 0;
  vtkIdType NumberOfNonConformingFaces = 0;
  vtkIdType NumberOfLensFaces = 0;
  int MaximumPiecesPerFace = 0;
  vtkIdType NumberOfOtherCells = 0;
  vtkIdType NumberOfQuadraticCells = 0;
  vtkIdType NumberOfHigherOrderCells = 0;
  vtkIdType NumberOfCurvedCells = 0;
  double MaximumMidEdgeDeviation = 0;
  vtkIdType NumberOfLinearizedCells = 0;
  int RefinementLevels = 0;
  int MinimumRefinementLevel = 0;
  vtkIdType NumberOfGridPoints = 0;
  ppiray::HigherOrderPieces Refinement;
  std::vector<vtkIdType> RefinedPointOffsets; // per refined cell: its range in RefinedPointIds
  std::vector<vtkIdType> RefinedPointIds;     // its points, corners first
  std::vector<unsigned char> RefinedCorners;  // per refined cell: its number of corners
  std::vector<vtkIdType> PieceCell;           // per cell: its refined cell (-1: not a piece)

private:
  ppiray::StageTimes Stages; // of the last BuildGeometry()
  // Kept between builds: the same cells find only their folds again.
  ppiray::CellAdjacencyCache Adjacency;
  vtkHexahedralCellTextures(const vtkHexahedralCellTextures&) = delete;
  void operator=(const vtkHexahedralCellTextures&) = delete;
};

#endif
