#include "vtkHexahedralCellTextures.h"

#include "ppirayCellAdjacency.h"
#include "ppirayConformingTetrahedra.h"
#include "ppirayHiddenCells.h"
#include "ppirayHigherOrderPieces.h"
#include "ppirayInvertedSheets.h"
#include "ppirayLinearCellKinds.h"
#include "ppirayMeshLocalFrame.h"
#include "ppirayNonConformingFaces.h"
#include "ppirayQuadraticTetrahedra.h"
#include "ppirayReflexEdges.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkHexahedron.h"
#include "vtkHexahedronCoefficients.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

vtkStandardNewMacro(vtkHexahedralCellTextures);

namespace
{
// det[a b c] of the frame at corner i (its edges to
// vtkHexahedronCoefficients::CornerNeighbor), and |a| |b| |c| in `scale`.
double CornerFrameVolume(const double* local, const vtkIdType c[8], int i, double& scale)
{
  double e[3][3];
  for (int k = 0; k < 3; ++k)
  {
    vtkMath::Subtract(
      local + 3 * c[vtkHexahedronCoefficients::CornerNeighbor(i, k)], local + 3 * c[i], e[k]);
  }
  scale = vtkMath::Norm(e[0]) * vtkMath::Norm(e[1]) * vtkMath::Norm(e[2]);
  return vtkMath::Determinant3x3(e[0], e[1], e[2]);
}

// |det[a b c]| / (|a| |b| |c|) at corner i: 1 for a right-angled corner, 0 for
// a collapsed or flat one. The shader renders a cell when this exceeds 1e-6
// at corner 0 (cell_hexahedron_fs.glsl).
double FrameQuality(const double* local, const vtkIdType c[8], int i)
{
  double scale;
  const double volume = CornerFrameVolume(local, c, i, scale);
  return scale > 0 ? std::abs(volume) / scale : 0.0;
}

// Signed volume of a cell (ppiray::CellVolume6).
double SignedVolume(const double* local, const vtkIdType c[8], int kind)
{
  return ppiray::CellVolume6(ppiray::LinearCellKindOf(kind), c, local) / 6.0;
}

// Negative for a left-handed (mirrored) hexahedron: the frame volumes at its
// eight corners, summed. All eight, not two opposite ones: a collapsed corner
// has no frame, and a pyramid written as a hexahedron (4, 5, 6 on 0, 1, 2)
// has none at 0 or 6. Other kinds: their signed volume.
double Handedness(const double* local, const vtkIdType c[8], int kind)
{
  if (kind != ppiray::HEXAHEDRON_KIND)
  {
    return SignedVolume(local, c, kind);
  }
  double sum = 0, scale;
  for (int i = 0; i < 8; ++i)
  {
    sum += CornerFrameVolume(local, c, i, scale);
  }
  return sum;
}

// Corner positions on the unit cube, bits (x, y, z), in VTK_HEXAHEDRON order.
const int CornerBits[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };

// Whether the cell has no volume: less than 1e-9 of its largest edge cubed.
bool IsFlat(const double* local, const vtkIdType c[8], int kind)
{
  const int n = ppiray::LinearCellKindOf(kind).Corners;
  double size = 0;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < i; ++j)
    {
      size = std::max(size, vtkMath::Distance2BetweenPoints(local + 3 * c[i], local + 3 * c[j]));
    }
  }
  size = std::sqrt(size);
  return !(std::abs(SignedVolume(local, c, kind)) > 1e-9 * size * size * size);
}

// Renumbers the corners by the rotation of the cube that takes corner `i` to
// corner 0 and its frame (CornerNeighbor(i, 0..2)) to the axes: the same cell, still
// right-handed, with its frame at corner i.
void MoveFrameToCorner(vtkIdType c[8], int i)
{
  int index[8]; // corner of a cube position
  for (int q = 0; q < 8; ++q)
  {
    index[CornerBits[q]] = q;
  }
  const int origin = CornerBits[i];
  int axis[3];
  for (int k = 0; k < 3; ++k)
  {
    axis[k] = CornerBits[vtkHexahedronCoefficients::CornerNeighbor(i, k)] ^ origin;
  }
  vtkIdType moved[8];
  for (int q = 0; q < 8; ++q)
  {
    const int b = CornerBits[q];
    const int position =
      origin ^ ((b & 1) ? axis[0] : 0) ^ ((b & 2) ? axis[1] : 0) ^ ((b & 4) ? axis[2] : 0);
    moved[q] = c[index[position]];
  }
  std::copy(moved, moved + 8, c);
}

// The field of a cell of `kind` from its corner values s (cell_hexahedron_fs.glsl
// reads it): a hexahedron's trilinear fit in its frame
// (vtkHexahedronCoefficients); a wedge's and a tetrahedron's VTK
// interpolation in the frame (u, v, w) of edges 0-1, 0-2, 0-3, where VTK's
// parametric coordinates are the frame coordinates when the cell is affine:
//   wedge  f = s0 + (s1 - s0) u + (s2 - s0) v + (s3 - s0) w
//              + (s0 - s2 - s3 + s5) v w + (s0 - s1 - s3 + s4) u w,
//   tetrahedron the same without the products (barycentric);
// a pyramid's corner values themselves.
void CellCoefficients(
  int kind, const double* local, const vtkIdType* ids, const double s[8], float out[8])
{
  double c[8] = { s[0], 0, 0, 0, 0, 0, 0, 0 };
  if (kind == ppiray::HEXAHEDRON_KIND)
  {
    double corners[8][3], frame[12];
    for (int i = 0; i < 8; ++i)
    {
      std::copy_n(local + 3 * ids[i], 3, corners[i]);
    }
    vtkHexahedronCoefficients::FitCoefficients(corners, s, frame, c);
  }
  else if (kind == ppiray::PYRAMID_KIND)
  {
    std::copy_n(s, 5, c);
  }
  else
  {
    c[1] = s[1] - s[0];
    c[2] = s[2] - s[0];
    c[3] = s[3] - s[0];
    if (kind == ppiray::WEDGE_KIND)
    {
      c[5] = s[0] - s[2] - s[3] + s[5];
      c[6] = s[0] - s[1] - s[3] + s[4];
    }
  }
  for (int k = 0; k < 8; ++k)
  {
    out[k] = static_cast<float>(c[k]);
  }
}

// A quadratic tetrahedron's field (ppirayQuadraticTetrahedra.h) from its
// corner values s and the values at its mid-edge nodes `mids`: c0..c7 into
// out[0..7], c8..c10 into out[8..10]. False, and out left linear, when a
// mid-edge value is NaN (the cell through its corners).
template<typename PointValues>
bool QuadraticCoefficients(
  const PointValues& values, const vtkIdType mids[6], const double s[8], float out[12])
{
  double m[6], c[ppiray::quadratic_tetrahedron::Coefficients];
  for (int k = 0; k < 6; ++k)
  {
    m[k] = values(mids[k]);
    if (std::isnan(m[k]))
    {
      return false;
    }
  }
  ppiray::quadratic_tetrahedron::FrameCoefficients(s, m, c);
  for (int k = 0; k < ppiray::quadratic_tetrahedron::Coefficients; ++k)
  {
    out[k] = static_cast<float>(c[k]);
  }
  return true;
}

// MidEdgeDeviation of a quadratic tetrahedron with point ids `pts`.
double MidEdgeDeviation(vtkPoints* points, const vtkIdType* pts)
{
  double x[10][3];
  for (int i = 0; i < 10; ++i)
  {
    points->GetPoint(pts[i], x[i]);
  }
  return ppiray::quadratic_tetrahedron::MidEdgeDeviation(x);
}

struct FaceKey
{
  std::array<vtkIdType, 4> Ids; // sorted
  vtkIdType Owner;              // 6 h + f
  bool operator<(const FaceKey& o) const { return this->Ids < o.Ids; }
};
}

//------------------------------------------------------------------------------
int vtkHexahedralCellTextures::TriangleCorner(int kind, int f, int t, int v, bool secondDiagonal)
{
  const int* q = ppiray::LinearCellKindOf(kind).Face[f];
  return ppiray::FaceSize(kind, f) == 3 ? q[v]
                                        : q[ppiray::QuadTriangleCorner(t, v, secondDiagonal)];
}

//------------------------------------------------------------------------------
bool vtkHexahedralCellTextures::BuildGeometry(vtkUnstructuredGrid* grid)
{
  this->Clear();
  ppiray::StageTimes::Laps laps(this->Stages, ppiray::ProgressEvents(this, 5));
  if (!grid || !grid->GetPoints() || !grid->GetCells() || !this->CollectCells(grid))
  {
    return false; // only counted: a grid of tetrahedra only, or with other cells
  }
  this->Length = ppiray::ComputeLocalPoints(grid->GetPoints(), this->Origin, this->LocalPoints);
  this->RefineHigherOrderCells(grid);
  if (this->GetNumberOfHexahedra() == 0)
  {
    return false;
  }
  if (this->GetNumberOfHexahedra() > ppiray::MaximumAdjacencyCells)
  {
    vtkErrorMacro("Mesh too large: " << this->GetNumberOfHexahedra() << " cells (at most "
                                     << ppiray::MaximumAdjacencyCells << ").");
    return false;
  }
  this->MarkFlatCells();
  laps.End("cells");
  this->Hidden = ppiray::HiddenCells(grid, this->CellIds);
  this->OrientCells();
  this->StoreCorners();
  laps.End("corners");
  std::vector<vtkIdType> boundary = this->MatchFaces();
  laps.End(this->Adjacency.WasKept() ? "folds" : "adjacency");
  this->LinkSplitQuadrilaterals(boundary);
  this->LinkNonConformingFaces(boundary);
  this->ExtractBoundary(boundary, static_cast<vtkIdType>(this->LocalPoints.size() / 3));
  laps.End("boundary");
  // Faces with reflex edges: the faces across them, for the march to enter
  // again where it leaves next to one (boundary triangle codes 12 h + 2 f + t).
  std::vector<int> faceOf(this->BoundaryFaces.size());
  std::transform(this->BoundaryFaces.begin(), this->BoundaryFaces.end(), faceOf.begin(),
    [](int triangle) { return triangle / 2; });
  this->NumberOfReentryFaces = ppiray::ListReentryFaces(
    this->BoundaryPoints, this->BoundaryTriangles, faceOf,
    [](int face) { return static_cast<size_t>(8 * (face / 6) + face % 6); }, ReentryFace(),
    this->Neighbors);
  laps.End("re-entry faces");
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::Clear()
{
  this->Stages.Clear();
  this->CellIds.clear();
  this->Kinds.clear();
  this->Flat.clear();
  this->CornerIds.clear();
  this->EdgeNodeIds.clear();
  this->Corners.clear();
  this->Neighbors.clear();
  this->Coefficients.clear();
  this->BoundaryPoints.clear();
  this->BoundaryTriangles.clear();
  this->BoundaryFaces.clear();
  std::fill(std::begin(this->NumberOfCellsOfKind), std::end(this->NumberOfCellsOfKind), 0);
  this->NumberOfMirroredHexahedra = 0;
  this->NumberOfNonManifoldFaces = 0;
  this->NumberOfUnfoldedFaces = 0;
  this->NumberOfFoldedFaces = 0;
  this->NumberOfSplitQuadrilaterals = 0;
  this->NumberOfReentryFaces = 0;
  this->NumberOfNonConformingFaces = 0;
  this->NumberOfLensFaces = 0;
  this->MaximumPiecesPerFace = 0;
  this->NumberOfSingularFrames = 0;
  this->NumberOfFlatHexahedra = 0;
  this->NumberOfOtherCells = 0;
  this->NumberOfQuadraticCells = 0;
  this->NumberOfHigherOrderCells = 0;
  this->NumberOfCurvedCells = 0;
  this->MaximumMidEdgeDeviation = 0;
  this->RefinementLevels = 0;
  this->Refinement = ppiray::HigherOrderPieces();
  this->RefinedPointOffsets.clear();
  this->RefinedPointIds.clear();
  this->RefinedCorners.clear();
  this->PieceCell.clear();
}

//------------------------------------------------------------------------------
bool vtkHexahedralCellTextures::CollectCells(vtkUnstructuredGrid* grid)
{
  const size_t cells = static_cast<size_t>(grid->GetNumberOfCells());
  this->CellIds.reserve(cells);
  this->Kinds.reserve(cells);
  this->CornerIds.reserve(8 * cells);
  ppiray::ForEachCell(grid,
    [&](vtkIdType cellId, int type, vtkIdType npts, const vtkIdType* pts)
    {
      const ppiray::LinearShape shape = ppiray::LinearShapeOf(type);
      const int kind = ppiray::LinearCellKindOfType(shape.Type);
      if (kind < 0 || npts < shape.Corners)
      {
        ++this->NumberOfOtherCells;
        return;
      }
      // A ten-node tetrahedron's field, unless its map folds; how curved it is.
      const double deviation = ppiray::quadratic_tetrahedron::IsQuadraticTetrahedron(type, npts)
                                 ? MidEdgeDeviation(grid->GetPoints(), pts)
                                 : -1.0;
      const bool quadraticField =
        deviation >= 0 && deviation <= ppiray::quadratic_tetrahedron::FoldingDeviation;
      this->MaximumMidEdgeDeviation =
        std::max(this->MaximumMidEdgeDeviation, quadraticField ? deviation : 0.0);
      this->NumberOfCurvedCells += quadraticField && deviation > CurvedEdgeTolerance() ? 1 : 0;
      this->NumberOfQuadraticCells += deviation >= 0 && !quadraticField ? 1 : 0;
      this->NumberOfHigherOrderCells += shape.HigherOrder && deviation < 0 ? 1 : 0;
      this->AddEdgeNodes(quadraticField ? pts + 4 : nullptr);
      ++this->NumberOfCellsOfKind[kind];
      this->CellIds.push_back(cellId);
      this->Kinds.push_back(static_cast<unsigned char>(kind));
      for (int i = 0; i < 8; ++i)
      {
        const int corner = i < shape.Corners ? i : 0; // unused slots repeat corner 0
        this->CornerIds.push_back(
          pts[kind == ppiray::HEXAHEDRON_KIND ? ppiray::HexahedronCorner(type, corner) : corner]);
      }
    });
  const vtkIdType all = static_cast<vtkIdType>(this->CellIds.size());
  if (this->NumberOfCellsOfKind[ppiray::TETRAHEDRON_KIND] == all && this->EdgeNodeIds.empty() &&
      this->NumberOfHigherOrderCells == 0)
  {
    // Linear tetrahedra only (or nothing): the tetrahedral textures' mesh.
    this->CellIds.clear();
    this->Kinds.clear();
    this->CornerIds.clear();
    this->NumberOfCellsOfKind[ppiray::TETRAHEDRON_KIND] = 0;
    return false;
  }
  return this->NumberOfOtherCells == 0;
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::AddEdgeNodes(const vtkIdType* mids)
{
  // Six per cell from the first quadratic tetrahedron on (-1: a cell
  // without them); none in a mesh of linear cells.
  if (mids && this->EdgeNodeIds.empty())
  {
    this->EdgeNodeIds.assign(6 * this->CellIds.size(), -1);
  }
  if (mids || !this->EdgeNodeIds.empty())
  {
    for (int k = 0; k < 6; ++k)
    {
      this->EdgeNodeIds.push_back(mids ? mids[k] : -1);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkHexahedralCellTextures::HasEdgeNodes(vtkIdType h) const
{
  return !this->EdgeNodeIds.empty() && this->EdgeNodeIds[6 * h] >= 0;
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::RefineHigherOrderCells(vtkUnstructuredGrid* grid)
{
  // The higher-order cells other than ten-node tetrahedra always, those too
  // when the levels are 1 or more, all by the same levels (their pieces
  // conform across faces: ppirayHigherOrderPieces.h).
  this->NumberOfGridPoints = static_cast<vtkIdType>(this->LocalPoints.size() / 3);
  std::vector<vtkIdType> others, quadratic; // indices of cells kept so far
  for (vtkIdType h = 0; h < this->GetNumberOfHexahedra(); ++h)
  {
    const int type = grid->GetCellType(this->CellIds[h]);
    if (this->HasEdgeNodes(h))
    {
      quadratic.push_back(h);
    }
    else if (ppiray::LinearShapeOf(type).HigherOrder &&
             !ppiray::quadratic_tetrahedron::IsQuadraticTetrahedron(
               type, grid->GetCellSize(this->CellIds[h])))
    {
      others.push_back(h);
    }
  }
  const auto inputIds = [&](const std::vector<vtkIdType>& cells)
  {
    std::vector<vtkIdType> ids(cells.size());
    std::transform(
      cells.begin(), cells.end(), ids.begin(), [&](vtkIdType h) { return this->CellIds[h]; });
    return ids;
  };
  // Unrefined, the other cells' pieces: how curved they are.
  double deviation = this->MaximumMidEdgeDeviation;
  vtkIdType pieces = static_cast<vtkIdType>(quadratic.size());
  if (!others.empty())
  {
    ppiray::RefineHigherOrderCells(
      grid, this->LocalPoints.data(), inputIds(others), 0, this->Refinement);
    deviation = std::max(deviation, this->Refinement.MaximumMidEdgeDeviation);
    pieces += static_cast<vtkIdType>(this->Refinement.Pieces.size());
  }
  this->RefinementLevels = ppiray::RefinementLevels(deviation, CurvedEdgeTolerance(), pieces,
    others.empty() ? 0 : this->MinimumRefinementLevel, 3,
    std::max(8 * pieces, MaximumRefinedPieces()));
  this->MaximumMidEdgeDeviation = deviation;
  if (this->RefinementLevels == 0 && others.empty())
  {
    return;
  }
  std::vector<vtkIdType> refined(others);
  if (this->RefinementLevels > 0)
  {
    refined.insert(refined.end(), quadratic.begin(), quadratic.end());
    ppiray::RefineHigherOrderCells(
      grid, this->LocalPoints.data(), inputIds(refined), this->RefinementLevels, this->Refinement);
  }
  this->RefinedPointOffsets.assign(1, 0);
  for (const vtkIdType h : refined)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    grid->GetCellPoints(this->CellIds[h], npts, pts);
    this->RefinedPointIds.insert(this->RefinedPointIds.end(), pts, pts + npts);
    this->RefinedPointOffsets.push_back(static_cast<vtkIdType>(this->RefinedPointIds.size()));
    this->RefinedCorners.push_back(static_cast<unsigned char>(
      ppiray::LinearShapeOf(grid->GetCellType(this->CellIds[h])).Corners));
  }
  this->ReplaceByPieces(refined);
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::ReplaceByPieces(const std::vector<vtkIdType>& refined)
{
  // The cells kept in place, the pieces after them.
  const auto& added = this->Refinement.Added.Points;
  this->LocalPoints.insert(this->LocalPoints.end(), added.begin(), added.end());
  const vtkIdType count = this->GetNumberOfHexahedra();
  if (this->EdgeNodeIds.empty())
  {
    this->EdgeNodeIds.assign(6 * count, -1);
  }
  std::vector<unsigned char> isRefined(count, 0);
  for (const vtkIdType h : refined)
  {
    isRefined[h] = 1;
    --this->NumberOfCellsOfKind[this->Kinds[h]];
  }
  const std::vector<vtkIdType> cellIds(this->CellIds);
  vtkIdType kept = 0;
  for (vtkIdType h = 0; h < count; ++h)
  {
    if (!isRefined[h])
    {
      std::copy_n(this->CornerIds.data() + 8 * h, 8, this->CornerIds.data() + 8 * kept);
      std::copy_n(this->EdgeNodeIds.data() + 6 * h, 6, this->EdgeNodeIds.data() + 6 * kept);
      this->CellIds[kept] = this->CellIds[h];
      this->Kinds[kept++] = this->Kinds[h];
    }
  }
  this->PieceCell.assign(kept, -1);
  this->PieceCell.insert(
    this->PieceCell.end(), this->Refinement.Cell.begin(), this->Refinement.Cell.end());
  this->CellIds.resize(kept);
  this->Kinds.resize(kept);
  this->CornerIds.resize(8 * kept);
  this->EdgeNodeIds.resize(6 * kept);
  for (size_t p = 0; p < this->Refinement.Pieces.size(); ++p)
  {
    const auto& nodes = this->Refinement.Pieces[p];
    this->CellIds.push_back(cellIds[refined[this->Refinement.Cell[p]]]);
    this->Kinds.push_back(ppiray::TETRAHEDRON_KIND);
    for (int i = 0; i < 8; ++i)
    {
      this->CornerIds.push_back(nodes[i < 4 ? i : 0]);
    }
    this->EdgeNodeIds.insert(this->EdgeNodeIds.end(), nodes.begin() + 4, nodes.end());
  }
  this->NumberOfCellsOfKind[ppiray::TETRAHEDRON_KIND] +=
    static_cast<vtkIdType>(this->Refinement.Pieces.size());
}

//------------------------------------------------------------------------------
std::vector<unsigned char> vtkHexahedralCellTextures::RefinedFields(
  vtkDataArray* scalars, int component) const
{
  // A refined cell is empty when a corner value is NaN, and taken through
  // its corners, as an unrefined one is, when only another node's is.
  const size_t cells = this->RefinedCorners.size();
  std::vector<unsigned char> fields(cells, 0);
  for (size_t c = 0; c < cells; ++c)
  {
    bool corners = true, others = true;
    for (vtkIdType k = this->RefinedPointOffsets[c]; k < this->RefinedPointOffsets[c + 1]; ++k)
    {
      const bool finite = !std::isnan(scalars->GetComponent(this->RefinedPointIds[k], component));
      const bool corner = k - this->RefinedPointOffsets[c] < this->RefinedCorners[c];
      (corner ? corners : others) = (corner ? corners : others) && finite;
    }
    fields[c] = !corners ? EMPTY : (!others ? THROUGH_CORNERS : 0);
  }
  return fields;
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::MarkFlatCells()
{
  // Zero-volume cells (a layer pinched out to nothing: top face on the
  // bottom face) are kept and crossed with zero length, like zero-volume
  // tetrahedra: the cells on either side meet through them.
  const double* local = this->LocalPoints.data();
  const vtkIdType count = this->GetNumberOfHexahedra();
  this->Flat.assign(count, 0);
  vtkIdType flatCells = 0;
#pragma omp parallel for schedule(static) reduction(+ : flatCells)
  for (vtkIdType h = 0; h < count; ++h)
  {
    this->Flat[h] = IsFlat(local, this->CornerIds.data() + 8 * h, this->Kinds[h]) ? 1 : 0;
    flatCells += this->Flat[h];
  }
  this->NumberOfFlatHexahedra = flatCells;
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::OrientCells()
{
  // Right-handed (mirrored by the kind's permutation), a hexahedron with its
  // cell frame at a corner that has one.
  const double* local = this->LocalPoints.data();
  const vtkIdType count = this->GetNumberOfHexahedra();
  vtkIdType mirroredCells = 0, singularFrames = 0;
#pragma omp parallel for schedule(static) reduction(+ : mirroredCells, singularFrames)
  for (vtkIdType h = 0; h < count; ++h)
  {
    vtkIdType* c = this->CornerIds.data() + 8 * h;
    const int kind = this->Kinds[h];
    if (this->Flat[h])
    {
      continue; // no handedness, no frame: crossed with zero length
    }
    if (Handedness(local, c, kind) < 0)
    {
      const int* mirror = ppiray::LinearCellKindOf(kind).Mirror;
      vtkIdType mirrored[8];
      for (int i = 0; i < 8; ++i)
      {
        mirrored[i] = c[mirror[i]];
      }
      std::copy(mirrored, mirrored + 8, c);
      if (this->HasEdgeNodes(h))
      {
        vtkIdType* mids = this->EdgeNodeIds.data() + 6 * h;
        vtkIdType renumbered[6];
        ppiray::quadratic_tetrahedron::RenumberEdgeNodes(mirror, mids, renumbered);
        std::copy_n(renumbered, 6, mids);
      }
      ++mirroredCells;
    }
    if (kind != ppiray::HEXAHEDRON_KIND)
    {
      continue;
    }
    // The cell frame at the best-shaped corner when corner 0 is collapsed or
    // flat (pinch-outs): a rotation of the corner numbering.
    double quality = FrameQuality(local, c, 0);
    if (quality < 1e-3)
    {
      int best = 0;
      for (int i = 1; i < 8; ++i)
      {
        const double q = FrameQuality(local, c, i);
        best = q > quality ? i : best;
        quality = std::max(quality, q);
      }
      MoveFrameToCorner(c, best);
    }
    singularFrames += quality > 1e-6 ? 0 : 1;
  }
  this->NumberOfMirroredHexahedra += mirroredCells;
  this->NumberOfSingularFrames += singularFrames;
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::StoreCorners()
{
  const double* local = this->LocalPoints.data();
  const vtkIdType count = this->GetNumberOfHexahedra();
  this->Corners.resize(24 * count);
  double diameter2 = 0;
#pragma omp parallel for schedule(static) reduction(max : diameter2)
  for (vtkIdType h = 0; h < count; ++h)
  {
    const vtkIdType* c = this->CornerIds.data() + 8 * h;
    for (int i = 0; i < 8; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        this->Corners[24 * h + 3 * i + k] = static_cast<float>(local[3 * c[i] + k]);
      }
      for (int j = 0; j < i; ++j)
      {
        diameter2 =
          std::max(diameter2, vtkMath::Distance2BetweenPoints(local + 3 * c[i], local + 3 * c[j]));
      }
    }
  }
  this->MaximumCellDiameter = std::sqrt(diameter2);
}

//------------------------------------------------------------------------------
ppiray::CellFaceMesh vtkHexahedralCellTextures::FaceMesh() const
{
  ppiray::CellFaceMesh mesh = ppiray::LinearCellFaceMesh(
    static_cast<vtkIdType>(this->LocalPoints.size() / 3), this->LocalPoints.data(),
    this->CornerIds.data(), this->Kinds.data(), this->GetNumberOfHexahedra());
  mesh.Flat = this->NumberOfFlatHexahedra > 0 ? this->Flat.data() : nullptr;
  return mesh;
}

//------------------------------------------------------------------------------
std::vector<vtkIdType> vtkHexahedralCellTextures::MatchFaces()
{
  // A quadrilateral's diagonal by the smallest id, except where that folds a
  // collapsed hexahedron (ppiray::QuadDiagonals); the neighbours, folds and
  // boundary by the stage every layout shares (ppirayCellAdjacency.h).
  const vtkIdType count = this->GetNumberOfHexahedra();
  ppiray::QuadDiagonals diagonals;
  for (vtkIdType h = 0; h < count; ++h)
  {
    if (this->Kinds[h] == ppiray::HEXAHEDRON_KIND)
    {
      diagonals.AddHexahedron(this->CornerIds.data() + 8 * h);
    }
  }
  this->NumberOfUnfoldedFaces = diagonals.GetNumberOfUnfoldedFaces();
  const ppiray::CellAdjacency& adjacency = this->Adjacency.Update(this->FaceMesh());
  this->NumberOfNonManifoldFaces = adjacency.NumberOfNonManifoldFaces;
  this->NumberOfFoldedFaces = adjacency.NumberOfFoldedFaces;
  this->Neighbors.assign(8 * count, -1);
  for (vtkIdType h = 0; h < count; ++h)
  {
    const vtkIdType* c = this->CornerIds.data() + 8 * h;
    const int kind = this->Kinds[h];
    int mask = 0;
    for (int f = 0; f < ppiray::LinearCellKindOf(kind).Faces; ++f)
    {
      const int* q = ppiray::LinearCellKindOf(kind).Face[f];
      if (ppiray::FaceSize(kind, f) == 4)
      {
        mask |= diagonals.AlongFirstDiagonal(c[q[0]], c[q[1]], c[q[2]], c[q[3]]) ? 0 : 1 << f;
      }
      const vtkIdType n = adjacency.Neighbors[6 * h + f];
      const bool folded = adjacency.Folded[6 * h + f] != 0;
      if (n >= 0)
      {
        this->Neighbors[8 * h + f] = NeighborCode(n, adjacency.NeighborFaces[6 * h + f], folded,
          folded && ppiray::WalksBackInPlace(adjacency.Inverted, h, n));
      }
    }
    this->Neighbors[8 * h + 6] = mask;
    this->Neighbors[8 * h + 7] = kind | (this->Flat[h] ? ppiray::FLAT_KIND_BIT : 0);
  }
  std::vector<vtkIdType> boundary; // 6 h + f
  for (size_t k = 0; k < adjacency.BoundaryFaces.size(); k += 2)
  {
    boundary.push_back(6 * adjacency.BoundaryFaces[k] + adjacency.BoundaryFaces[k + 1]);
  }
  return boundary;
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::LinkSplitQuadrilaterals(std::vector<vtkIdType>& boundary)
{
  // A quadrilateral left unmatched whose two triangles (split by its
  // diagonal) are each an unmatched triangular face of another cell (a
  // hexahedron, wedge or pyramid next to two tetrahedra, or two wedges'
  // triangles): each triangle's cell enters the quadrilateral's, and the
  // quadrilateral lists the two (SplitFace(): the march takes the one its
  // exit point lies in, listed_faces_fs.glsl).
  std::vector<FaceKey> triangles;
  for (vtkIdType owner : boundary)
  {
    const vtkIdType h = owner / 6;
    const int f = static_cast<int>(owner % 6);
    if (ppiray::FaceSize(this->Kinds[h], f) == 3)
    {
      const int* q = ppiray::LinearCellKindOf(this->Kinds[h]).Face[f];
      const vtkIdType* c = this->CornerIds.data() + 8 * h;
      FaceKey key{ { -1, c[q[0]], c[q[1]], c[q[2]] }, owner };
      std::sort(key.Ids.begin(), key.Ids.end());
      triangles.push_back(key);
    }
  }
  if (triangles.empty())
  {
    return;
  }
  std::sort(triangles.begin(), triangles.end());
  auto findTriangle = [&](std::array<vtkIdType, 4> ids) -> vtkIdType
  {
    std::sort(ids.begin(), ids.end());
    const FaceKey probe{ ids, 0 };
    auto range = std::equal_range(triangles.begin(), triangles.end(), probe);
    return range.second - range.first == 1 ? range.first->Owner : -1;
  };
  // Whether the piece's cell lies across the quadrilateral from cell h (not
  // folded onto its side).
  const ppiray::CellFaceMesh mesh = this->FaceMesh();
  auto acrossFace = [&](vtkIdType h, int f, vtkIdType piece)
  {
    vtkIdType ids[4];
    const int* q = ppiray::LinearCellKindOf(this->Kinds[h]).Face[f];
    for (int v = 0; v < 4; ++v)
    {
      ids[v] = this->CornerIds[8 * h + q[v]];
    }
    const int side = ppiray::SideOfFace(mesh, h, f, ids, 4);
    const int pieceSide = ppiray::SideOfFace(mesh, piece / 6, static_cast<int>(piece % 6), ids, 4);
    return side == 0 || side != pieceSide;
  };
  std::vector<unsigned char> linked(6 * this->GetNumberOfHexahedra(), 0);
  for (vtkIdType owner : boundary)
  {
    const vtkIdType h = owner / 6;
    const int f = static_cast<int>(owner % 6);
    const int kind = this->Kinds[h];
    if (ppiray::FaceSize(kind, f) != 4 || linked[owner])
    {
      continue;
    }
    const bool second = (this->Neighbors[8 * h + 6] >> f) & 1;
    vtkIdType pieces[2];
    for (int t = 0; t < 2; ++t)
    {
      std::array<vtkIdType, 4> ids = { -1, 0, 0, 0 };
      for (int v = 0; v < 3; ++v)
      {
        ids[v + 1] = this->CornerIds[8 * h + TriangleCorner(kind, f, t, v, second)];
      }
      pieces[t] = findTriangle(ids);
    }
    if (pieces[0] < 0 || pieces[1] < 0 || pieces[0] / 6 == h || pieces[1] / 6 == h ||
        linked[pieces[0]] || linked[pieces[1]] || !acrossFace(h, f, pieces[0]) ||
        !acrossFace(h, f, pieces[1]))
    {
      continue;
    }
    this->Neighbors[8 * h + f] = ppiray::AppendFaceList(this->Neighbors,
      { NeighborCode(pieces[0] / 6, static_cast<int>(pieces[0] % 6), false, false),
        NeighborCode(pieces[1] / 6, static_cast<int>(pieces[1] % 6), false, false) },
      SplitFace());
    this->MaximumPiecesPerFace = 2;
    for (vtkIdType piece : pieces)
    {
      this->Neighbors[8 * (piece / 6) + piece % 6] = NeighborCode(h, f, false, false);
      linked[piece] = 1;
    }
    linked[owner] = 1;
    ++this->NumberOfSplitQuadrilaterals;
  }
  boundary.erase(std::remove_if(boundary.begin(), boundary.end(),
                   [&](vtkIdType owner) { return linked[owner] != 0; }),
    boundary.end());
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::LinkNonConformingFaces(std::vector<vtkIdType>& boundary)
{
  // The open faces left (of cells with volume), as the march splits them,
  // wound outward, linked to the open faces across them
  // (ppirayNonConformingFaces.h); those covered are no boundary faces.
  std::vector<ppiray::OpenFace> faces;
  std::vector<vtkIdType> owners; // 6 h + f
  for (vtkIdType owner : boundary)
  {
    const vtkIdType h = owner / 6;
    const int f = static_cast<int>(owner % 6);
    if (this->Flat[h])
    {
      continue;
    }
    const int kind = this->Kinds[h];
    const bool second = (this->Neighbors[8 * h + 6] >> f) & 1;
    ppiray::OpenFace face{ h, ppiray::FaceSize(kind, f) - 2, {} };
    for (int t = 0; t < face.Triangles; ++t)
    {
      for (int v = 0; v < 3; ++v)
      {
        face.Points[3 * t + v] = this->CornerIds[8 * h + TriangleCorner(kind, f, t, v, second)];
      }
    }
    face.Apex = this->CornerIds[8 * h + ppiray::CornerOffFace(kind, f)];
    faces.push_back(face);
    owners.push_back(owner);
  }
  const ppiray::NonConformingLinks links = ppiray::LinkNonConformingFaces(
    this->LocalPoints.data(), faces,
    [&](vtkIdType i)
    { return NeighborCode(owners[i] / 6, static_cast<int>(owners[i] % 6), false, false); },
    [&](vtkIdType i) { return static_cast<size_t>(8 * (owners[i] / 6) + owners[i] % 6); },
    [&](vtkIdType i, vtkIdType j) { this->SplitAlongLinkedDiagonal(owners[i], owners[j]); },
    SplitFace(), MaximumPieces(), this->Neighbors);
  std::vector<vtkIdType> covered;
  for (size_t i = 0; i < faces.size(); ++i)
  {
    if (links.Covered[i])
    {
      covered.push_back(owners[i]);
    }
  }
  boundary.erase(
    std::remove_if(boundary.begin(), boundary.end(),
      [&](vtkIdType owner) { return std::binary_search(covered.begin(), covered.end(), owner); }),
    boundary.end());
  this->NumberOfNonConformingFaces = links.Faces;
  this->NumberOfLensFaces = links.Lenses;
  this->MaximumPiecesPerFace = std::max(this->MaximumPiecesPerFace, links.MaximumPieces);
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::SplitAlongLinkedDiagonal(vtkIdType a, vtkIdType b)
{
  const vtkIdType ha = a / 6, hb = b / 6;
  const int fa = static_cast<int>(a % 6), fb = static_cast<int>(b % 6);
  if (a < b || ppiray::FaceSize(this->Kinds[ha], fa) != 4 ||
      ppiray::FaceSize(this->Kinds[hb], fb) != 4)
  {
    return;
  }
  auto corner = [this](vtkIdType h, int f, int v)
  {
    const int* q = ppiray::LinearCellKindOf(this->Kinds[h]).Face[f];
    return glm::make_vec3(this->LocalPoints.data() + 3 * this->CornerIds[8 * h + q[v]]);
  };
  // b's diagonal: corners 0-2, or 1-3 where its bit is set; a's corners at
  // its two ends are a's diagonal.
  const int bSecond = (this->Neighbors[8 * hb + 6] >> fb) & 1;
  int at[2] = { -1, -1 };
  for (int e = 0; e < 2; ++e)
  {
    for (int v = 0; v < 4; ++v)
    {
      at[e] = corner(ha, fa, v) == corner(hb, fb, bSecond + 2 * e) ? v : at[e];
    }
  }
  if (at[0] >= 0 && at[1] >= 0 && (at[0] - at[1] + 4) % 4 == 2)
  {
    this->Neighbors[8 * ha + 6] = (this->Neighbors[8 * ha + 6] & ~(1 << fa)) | ((at[0] % 2) << fa);
  }
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::ExtractBoundary(
  const std::vector<vtkIdType>& boundary, vtkIdType numberOfPoints)
{
  // Boundary triangles, wound outward (the kinds' faces are outward for a
  // right-handed cell), over a compact set of points.
  const double* local = this->LocalPoints.data();
  std::vector<vtkIdType> pointMap(numberOfPoints, -1);
  for (vtkIdType owner : boundary)
  {
    const vtkIdType h = owner / 6;
    const int f = static_cast<int>(owner % 6);
    const int kind = this->Kinds[h];
    const bool second = (this->Neighbors[8 * h + 6] >> f) & 1;
    const bool reversed = this->Flat[h] && this->FacesSolidNeighbor(h, f);
    for (int t = 0; t < ppiray::FaceSize(kind, f) - 2; ++t)
    {
      for (int v = 0; v < 3; ++v)
      {
        const int w = reversed && v > 0 ? 3 - v : v;
        const vtkIdType id = this->CornerIds[8 * h + TriangleCorner(kind, f, t, w, second)];
        if (pointMap[id] < 0)
        {
          pointMap[id] = static_cast<vtkIdType>(this->BoundaryPoints.size() / 3);
          for (int k = 0; k < 3; ++k)
          {
            this->BoundaryPoints.push_back(static_cast<float>(local[3 * id + k]));
          }
        }
        this->BoundaryTriangles.push_back(static_cast<unsigned int>(pointMap[id]));
      }
      this->BoundaryFaces.push_back(static_cast<int>(12 * h + 2 * f + t));
    }
  }
}

//------------------------------------------------------------------------------
bool vtkHexahedralCellTextures::FacesSolidNeighbor(vtkIdType h, int f) const
{
  // Face f's outward normal (as the kind winds it) against the centre of
  // the first non-flat cell reached from h (ppiray::NearestSolidCell).
  const ppiray::CellAdjacency& adjacency = this->Adjacency.Get();
  const vtkIdType n = ppiray::NearestSolidCell(h, adjacency.Neighbors.data(), 6, this->Flat.data());
  if (n < 0)
  {
    return false;
  }
  const double* local = this->LocalPoints.data();
  const int corners = ppiray::LinearCellKindOf(this->Kinds[n]).Corners;
  double centre[3] = { 0, 0, 0 };
  for (int v = 0; v < corners; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += local[3 * this->CornerIds[8 * n + v] + k] / corners;
    }
  }
  const int* q = ppiray::LinearCellKindOf(this->Kinds[h]).Face[f];
  const vtkIdType* c = this->CornerIds.data() + 8 * h;
  double volume6 = 0;
  for (int t = 0; t + 2 < ppiray::FaceSize(this->Kinds[h], f); ++t)
  {
    volume6 += vtkUnstructuredGridCellAdjacency::SignedVolume6(
      local + 3 * c[q[0]], local + 3 * c[q[t + 1]], local + 3 * c[q[t + 2]], centre);
  }
  return volume6 > 0;
}

//------------------------------------------------------------------------------
bool vtkHexahedralCellTextures::BuildField(vtkDataArray* scalars, bool cellScalars, int component)
{
  const vtkIdType numberOfHexahedra = this->GetNumberOfHexahedra();
  const int stride = 4 * this->GetCoefficientTexels();
  this->Coefficients.assign(stride * numberOfHexahedra, 0.0f);
  this->NumberOfNaNScalars = 0;
  this->NumberOfLinearizedCells = 0;
  if (!scalars || numberOfHexahedra == 0 || component < 0 ||
      component >= scalars->GetNumberOfComponents())
  {
    return false;
  }
  // The refinement's added points: VTK's field of their cell, or through
  // its corners where that is NaN (ppirayHigherOrderPieces.h).
  // (Point scalars only: cell scalars are read per cell.)
  const ppiray::HigherOrderPieces& pieces = this->Refinement;
  const vtkIdType added = cellScalars ? 0 : pieces.Added.GetNumberOfPoints();
  std::vector<double> addedValues(added);
#pragma omp parallel for schedule(static)
  for (vtkIdType i = 0; i < added; ++i)
  {
    const double v = pieces.Added.Value(i, scalars, component);
    addedValues[i] = std::isnan(v) ? pieces.Linear.Value(i, scalars, component) : v;
  }
  const vtkIdType gridPoints = this->NumberOfGridPoints;
  const auto value = [&](vtkIdType id)
  { return id < gridPoints ? scalars->GetComponent(id, component) : addedValues[id - gridPoints]; };
  const auto linearValue = [&](vtkIdType id)
  {
    return id < gridPoints ? scalars->GetComponent(id, component)
                           : pieces.Linear.Value(id - gridPoints, scalars, component);
  };
  const std::vector<unsigned char> fields =
    cellScalars ? std::vector<unsigned char>() : this->RefinedFields(scalars, component);
  const auto fieldOf = [&](vtkIdType h)
  {
    const vtkIdType cell = this->PieceCell.empty() ? -1 : this->PieceCell[h];
    return cellScalars || cell < 0 ? 0 : fields[cell];
  };
  vtkIdType nanCells = 0, linearized = 0;
#pragma omp parallel for schedule(static) reduction(+ : nanCells, linearized)
  for (vtkIdType h = 0; h < numberOfHexahedra; ++h)
  {
    float* out = this->Coefficients.data() + stride * h;
    const int field = fieldOf(h);
    double s[8];
    bool hasNaN = field == EMPTY;
    if (cellScalars)
    {
      s[0] = scalars->GetComponent(this->CellIds[h], component);
      std::fill(s + 1, s + 8, s[0]);
      hasNaN = std::isnan(s[0]);
    }
    else
    {
      for (int i = 0; i < 8; ++i)
      {
        const vtkIdType id = this->CornerIds[8 * h + i];
        s[i] = field == THROUGH_CORNERS ? linearValue(id) : value(id);
        hasNaN = hasNaN || std::isnan(s[i]);
      }
    }
    if (hasNaN || (h < static_cast<vtkIdType>(this->Hidden.size()) && this->Hidden[h]) ||
        this->Flat[h])
    {
      out[0] = TransparentCellOffset();
      const vtkIdType cell = this->PieceCell.empty() ? -1 : this->PieceCell[h];
      const bool firstPiece = cell < 0 || h == 0 || this->PieceCell[h - 1] != cell;
      nanCells += hasNaN && firstPiece ? 1 : 0; // counted per input cell
      continue;
    }
    CellCoefficients(
      this->Kinds[h], this->LocalPoints.data(), this->CornerIds.data() + 8 * h, s, out);
    if (!cellScalars && field == THROUGH_CORNERS)
    {
      QuadraticCoefficients(linearValue, this->EdgeNodeIds.data() + 6 * h, s, out);
    }
    else if (!cellScalars && this->HasEdgeNodes(h))
    {
      linearized += QuadraticCoefficients(value, this->EdgeNodeIds.data() + 6 * h, s, out) ? 0 : 1;
    }
  }
  this->NumberOfNaNScalars = nanCells;
  this->NumberOfLinearizedCells = linearized + std::count(fields.begin(), fields.end(),
                                                 static_cast<unsigned char>(THROUGH_CORNERS));
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkHexahedralCellTextures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfHexahedra: " << this->GetNumberOfHexahedra() << "\n";
  os << indent << "NumberOfMirroredHexahedra: " << this->NumberOfMirroredHexahedra << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
  os << indent << "NumberOfUnfoldedFaces: " << this->NumberOfUnfoldedFaces << "\n";
  os << indent << "NumberOfFoldedFaces: " << this->NumberOfFoldedFaces << "\n";
  os << indent << "NumberOfSplitQuadrilaterals: " << this->NumberOfSplitQuadrilaterals << "\n";
  os << indent << "NumberOfReentryFaces: " << this->NumberOfReentryFaces << "\n";
  os << indent << "NumberOfNaNScalars: " << this->NumberOfNaNScalars << "\n";
  os << indent << "NumberOfSingularFrames: " << this->NumberOfSingularFrames << "\n";
  os << indent << "NumberOfFlatHexahedra: " << this->NumberOfFlatHexahedra << "\n";
  os << indent << "NumberOfOtherCells: " << this->NumberOfOtherCells << "\n";
  os << indent << "NumberOfQuadraticCells: " << this->NumberOfQuadraticCells << "\n";
  os << indent << "NumberOfHigherOrderCells: " << this->NumberOfHigherOrderCells << "\n";
  os << indent << "MinimumRefinementLevel: " << this->MinimumRefinementLevel << "\n";
  os << indent << "NumberOfCurvedCells: " << this->NumberOfCurvedCells << "\n";
  os << indent << "MaximumMidEdgeDeviation: " << this->MaximumMidEdgeDeviation << "\n";
  os << indent << "NumberOfLinearizedCells: " << this->NumberOfLinearizedCells << "\n";
}
