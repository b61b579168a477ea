/**
 * @file   ppirayCellAdjacency.h
 * @brief  face neighbours, boundary and folds of a mesh of cells of any kind with up to 6 faces
 *
 * The one adjacency stage of every cell layout (tetrahedra,
 * vtkTetrahedralCellTextures through vtkUnstructuredGridCellAdjacency;
 * hexahedra, wedges, pyramids and tetrahedra together,
 * vtkHexahedralCellTextures). A cell kind supplies only its face table
 * (CellFaceTable); the rules below are the same for every kind.
 *
 * Faces are matched by their point ids: a triangle with a triangle, a
 * quadrilateral with a quadrilateral. Point-to-cell links are built by a
 * counting sort; a face is matched by the first of its cell faces (by
 * cell, then face), which merges the cells around its two points with the
 * fewest of them and writes every cell face on it; the others, once
 * written, are skipped. O(cells) for bounded vertex degree, parallel over
 * cells with OpenMP. A cell is on a face where it holds each of the face's
 * point ids; which of its faces, by the bits of its corners on them.
 *
 * Real meshes share a face between more than two cells (zero-volume cells
 * between two triangulations of a quadrilateral or on a face, a hexahedron
 * collapsed into tetrahedra with repeated point ids, tangled regions).
 * Given the coordinates, the cell faces on one face are paired by the side
 * of the face their cell lies on (SideOfFace: the centre of the cell's
 * corners off the face): positive with negative; a face with cells on one
 * side only goes on through a flat (zero-volume) cell if one is there, else
 * its same-side cells pair up (folded); flat cells on a face that non-flat
 * cells close are left out (none of their faces is paired through it or a
 * boundary); flat faces alone pair with each other. Two faces of one cell
 * never pair; a face left without a partner is a boundary face. Faces with
 * fewer than three distinct point ids (zero area) are neither paired nor
 * boundary.
 *
 * A pair whose two cells lie on the same side of their face is folded (the
 * mesh turns back on itself there: an inverted cell in a tangled region);
 * Folded and Inverted (ppirayInvertedSheets.h) tell the ray caster how to
 * walk through it.
 */
#ifndef ppirayCellAdjacency_h
#define ppirayCellAdjacency_h

#include "ppirayFiltersModule.h"   // for export macro
#include "ppirayGridGeometryKey.h" // for ppiray::ContentDigest
#include "vtkType.h"

#include <vector> // for std::vector

namespace ppiray
{
/**
 * The faces of a cell kind: corner indices of each face, wound outward for a
 * positively oriented cell; a triangle's fourth entry is -1.
 */
struct CellFaceTable
{
  int Corners;
  int Faces;
  int Face[6][4];
};

/** The cells whose faces MatchCellFaces() matches. */
struct CellFaceMesh
{
  vtkIdType NumberOfPoints = 0;
  vtkIdType NumberOfCells = 0;
  /** CornerStride point ids per cell. */
  const vtkIdType* CornerIds = nullptr;
  int CornerStride = 4;
  /** Face table of each kind; Kinds (one per cell) indexes it, or nullptr: kind 0. */
  const CellFaceTable* Tables[4] = { nullptr, nullptr, nullptr, nullptr };
  const unsigned char* Kinds = nullptr;
  /** Entries per cell in CellAdjacency's face arrays (at least every table's Faces). */
  int FaceSlots = 4;
  /** 3 doubles per point, or nullptr: faces are not ordered by side, nothing is folded. */
  const double* Points = nullptr;
  /** One per cell, or nullptr: zero-volume cells (they lie on neither side). */
  const unsigned char* Flat = nullptr;
};

/**
 * The most cells MatchCellFaces() takes: cells are numbered in int (4 bytes
 * per face and per point-to-cell link; the GPU layouts number them in int too).
 */
constexpr vtkIdType MaximumAdjacencyCells = VTK_INT_MAX;

/** What MatchCellFaces() finds: FaceSlots entries per cell in the face arrays. */
struct CellAdjacency
{
  std::vector<int> Neighbors;             // the cell across the face, -1: none
  std::vector<signed char> NeighborFaces; // its face, -1: none
  std::vector<unsigned char> Folded;      // both cells on one side of the face
  std::vector<unsigned char> Inverted;    // one per cell (ppirayInvertedSheets.h)
  std::vector<vtkIdType> BoundaryFaces;   // (cell, face) pairs, in cell order
  /** Cell faces on a face that more than two cell faces share. */
  vtkIdType NumberOfNonManifoldFaces = 0;
  /** Folded pairs of cell faces. */
  vtkIdType NumberOfFoldedFaces = 0;
  /**
   * Neighbors, NeighborFaces and BoundaryFaces follow from the point ids
   * alone (no flat cell, no face shared by more than two cell faces), so
   * RefoldCellFaces() can keep them for other coordinates.
   */
  bool ByIds = false;
};

/** Empty (no face arrays) for more than MaximumAdjacencyCells cells: the caller says so. */
PPIRAYFILTERS_EXPORT CellAdjacency MatchCellFaces(const CellFaceMesh& mesh);

/**
 * `adjacency`, which MatchCellFaces() found for the same cells (corner ids)
 * with other coordinates, made `mesh`'s: the folds (Folded,
 * NumberOfFoldedFaces, Inverted) found again from its coordinates, the
 * rest kept, as MatchCellFaces() would find them. False (`adjacency`
 * untouched) where that does not hold: not ByIds, or a cell of `mesh` is
 * flat.
 */
PPIRAYFILTERS_EXPORT bool RefoldCellFaces(const CellFaceMesh& mesh, CellAdjacency& adjacency);

/**
 * The adjacency of the last cells seen, kept for the next build: a
 * deforming mesh (the same cells, points moved) finds only its folds again
 * (RefoldCellFaces()), any other change matches its faces again
 * (MatchCellFaces()). The cells are recognized by a digest of their corner
 * ids, kinds and face tables and the number of points
 * (ppirayGridGeometryKey.h's DigestBytes).
 */
class PPIRAYFILTERS_EXPORT CellAdjacencyCache
{
public:
  const CellAdjacency& Update(const CellFaceMesh& mesh);
  /** The adjacency of the last Update(). */
  const CellAdjacency& Get() const { return this->Adjacency; }
  /** Whether the last Update() kept the faces' pairs (only the folds found again). */
  bool WasKept() const { return this->Kept; }

private:
  CellAdjacency Adjacency;
  ContentDigest Cells;
  bool Valid = false;
  bool Kept = false;
};

/**
 * The side of face `face` of `cell` that the cell lies on: the sign (+1, -1,
 * 0) of its off-face centre q (the mean of its corners not on the face; a
 * tetrahedron's opposite corner) against the plane of the face with point
 * ids `faceIds` (`size` 3 or 4, in either winding, from any corner): a
 * triangle (a, b, c) by ascending id, det[b - a, c - a, q - a]; a
 * quadrilateral by its cycle c0..c3 that is smallest by ids,
 * ((c2 - c0) x (c3 - c1)) . (q - centre). Both cells sharing a face measure
 * against the same plane.
 */
PPIRAYFILTERS_EXPORT int SideOfFace(
  const CellFaceMesh& mesh, vtkIdType cell, int face, const vtkIdType* faceIds, int size);

/**
 * The first cell that is not flat reached from flat cell `cell` through
 * neighbours (`slots` entries per cell, -1: none), breadth first over at most
 * 64 cells (flat cells come in small clusters); -1: none. A boundary face of
 * a flat cell is wound away from that cell (the cells it lies on).
 */
PPIRAYFILTERS_EXPORT vtkIdType NearestSolidCell(
  vtkIdType cell, const int* neighbors, int slots, const unsigned char* flat);

/**
 * Six times the signed volume of a cell (`corners`: its point ids, `points`:
 * 3 doubles per point) by the divergence theorem: the sum of
 * det[a - p0, b - p0, c - p0] over its faces fanned from their first corner,
 * p0 its corner 0.
 */
PPIRAYFILTERS_EXPORT double CellVolume6(
  const CellFaceTable& table, const vtkIdType* corners, const double* points);
}

#endif
