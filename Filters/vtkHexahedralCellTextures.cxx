#include "vtkHexahedralCellTextures.h"

#include "ppirayConformingTetrahedra.h"
#include "ppirayHiddenCells.h"
#include "ppirayInvertedSheets.h"
#include "ppirayMeshLocalFrame.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkHexahedron.h"
#include "vtkHexahedronCoefficients.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

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
// at corner 0 (march_hexahedra_fs.glsl).
double FrameQuality(const double* local, const vtkIdType c[8], int i)
{
  double scale;
  const double volume = CornerFrameVolume(local, c, i, scale);
  return scale > 0 ? std::abs(volume) / scale : 0.0;
}

// Negative for a left-handed (mirrored) cell: the frame volumes at its eight
// corners, summed. All eight, not two opposite ones: a collapsed corner has no
// frame, and a pyramid written as a hexahedron (4, 5, 6 on 0, 1, 2) has none
// at 0 or 6.
// Whether hexahedra a / 6 and b / 6 lie on one side of their shared face
// (face a % 6 of the first): their centroids on the same side of the plane
// through the face's centre with the normal (q2 - q0) x (q3 - q1) (the mesh
// folds back on itself there).
bool OnOneSide(const double* local, const vtkIdType* cornerIds, vtkIdType a, vtkIdType b)
{
  const vtkIdType* ca = cornerIds + 8 * (a / 6);
  const vtkIdType* cb = cornerIds + 8 * (b / 6);
  const vtkIdType* q = vtkHexahedron::GetFaceArray(static_cast<int>(a % 6));
  double centre[3] = { 0, 0, 0 }, inA[3] = { 0, 0, 0 }, inB[3] = { 0, 0, 0 };
  for (int k = 0; k < 3; ++k)
  {
    for (int v = 0; v < 4; ++v)
    {
      centre[k] += 0.25 * local[3 * ca[q[v]] + k];
    }
    for (int v = 0; v < 8; ++v)
    {
      inA[k] += 0.125 * local[3 * ca[v] + k];
      inB[k] += 0.125 * local[3 * cb[v] + k];
    }
  }
  double d02[3], d13[3], n[3];
  for (int k = 0; k < 3; ++k)
  {
    d02[k] = local[3 * ca[q[2]] + k] - local[3 * ca[q[0]] + k];
    d13[k] = local[3 * ca[q[3]] + k] - local[3 * ca[q[1]] + k];
    inA[k] -= centre[k];
    inB[k] -= centre[k];
  }
  vtkMath::Cross(d02, d13, n);
  const double sideA = vtkMath::Dot(n, inA), sideB = vtkMath::Dot(n, inB);
  return (sideA > 0 && sideB > 0) || (sideA < 0 && sideB < 0);
}

double Handedness(const double* local, const vtkIdType c[8])
{
  double sum = 0, scale;
  for (int i = 0; i < 8; ++i)
  {
    sum += CornerFrameVolume(local, c, i, scale);
  }
  return sum;
}

// Corner positions on the unit cube, bits (x, y, z), in VTK_HEXAHEDRON order.
const int CornerBits[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };

// Volume of the hexahedron as the six tetrahedra (0, a, b, 6) around its 0-6
// diagonal (a, b consecutive on the ring of the other corners).
double SignedVolume(const double* local, const vtkIdType c[8])
{
  static const int ring[7] = { 1, 2, 3, 7, 4, 5, 1 };
  auto at = [&](int i) { return local + 3 * c[i]; };
  double volume = 0;
  for (int k = 0; k < 6; ++k)
  {
    double a[3], b[3], d[3];
    for (int i = 0; i < 3; ++i)
    {
      a[i] = at(ring[k])[i] - at(0)[i];
      b[i] = at(ring[k + 1])[i] - at(0)[i];
      d[i] = at(6)[i] - at(0)[i];
    }
    double n[3];
    vtkMath::Cross(a, b, n);
    volume += vtkMath::Dot(n, d) / 6.0;
  }
  return volume;
}

// Whether the hexahedron has no volume: less than 1e-9 of its largest edge cubed.
bool IsFlat(const double* local, const vtkIdType c[8])
{
  double size = 0;
  for (int i = 0; i < 8; ++i)
  {
    for (int j = 0; j < i; ++j)
    {
      size = std::max(size, vtkMath::Distance2BetweenPoints(local + 3 * c[i], local + 3 * c[j]));
    }
  }
  size = std::sqrt(size);
  return !(std::abs(SignedVolume(local, c)) > 1e-9 * size * size * size);
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

struct FaceKey
{
  std::array<vtkIdType, 4> Ids; // sorted
  vtkIdType Owner;              // 6 h + f
  bool operator<(const FaceKey& o) const { return this->Ids < o.Ids; }
};
}

//------------------------------------------------------------------------------
int vtkHexahedralCellTextures::TriangleCorner(int f, int t, int v, bool secondDiagonal)
{
  return static_cast<int>(
    vtkHexahedron::GetFaceArray(f)[ppiray::QuadTriangleCorner(t, v, secondDiagonal)]);
}

//------------------------------------------------------------------------------
bool vtkHexahedralCellTextures::BuildGeometry(vtkUnstructuredGrid* grid)
{
  this->CellIds.clear();
  this->CornerIds.clear();
  this->Corners.clear();
  this->Neighbors.clear();
  this->Coefficients.clear();
  this->BoundaryPoints.clear();
  this->BoundaryTriangles.clear();
  this->BoundaryFaces.clear();
  this->NumberOfMirroredHexahedra = 0;
  this->NumberOfNonManifoldFaces = 0;
  this->NumberOfUnfoldedFaces = 0;
  this->NumberOfFoldedFaces = 0;
  this->NumberOfSingularFrames = 0;
  this->NumberOfFlatHexahedra = 0;
  this->NumberOfOtherCells = 0;
  this->NumberOfQuadraticCells = 0;
  if (!grid || !grid->GetPoints() || !grid->GetCells())
  {
    return false;
  }
  // Hexahedra, in VTK_HEXAHEDRON order.
  ppiray::ForEachCell(grid,
    [&](vtkIdType cellId, int type, vtkIdType npts, const vtkIdType* pts)
    {
      const ppiray::LinearShape shape = ppiray::LinearShapeOf(type);
      if (shape.Type != VTK_HEXAHEDRON || npts < 8)
      {
        ++this->NumberOfOtherCells;
        return;
      }
      this->NumberOfQuadraticCells += shape.HigherOrder ? 1 : 0;
      this->CellIds.push_back(cellId);
      for (int i = 0; i < 8; ++i)
      {
        this->CornerIds.push_back(pts[ppiray::HexahedronCorner(type, i)]);
      }
    });
  if (this->CellIds.empty() || this->NumberOfOtherCells > 0)
  {
    return false; // only counted: the textures describe meshes of hexahedra only
  }
  this->Length = ppiray::ComputeLocalPoints(grid->GetPoints(), this->Origin, this->LocalPoints);
  const double* local = this->LocalPoints.data();

  // Zero-volume hexahedra (a layer pinched out to nothing: top face on the
  // bottom face) are left out, like zero-volume tetrahedra: they hold no
  // volume, and the cells on either side share their points, so they meet
  // face to face without them. Volume: the six tetrahedra around the 0-6
  // diagonal, against the cell's size cubed.
  {
    const vtkIdType count = static_cast<vtkIdType>(this->CellIds.size());
    vtkIdType kept = 0;
    for (vtkIdType h = 0; h < count; ++h)
    {
      const vtkIdType* c = this->CornerIds.data() + 8 * h;
      if (IsFlat(local, c))
      {
        ++this->NumberOfFlatHexahedra;
        continue;
      }
      std::copy(c, c + 8, this->CornerIds.data() + 8 * kept);
      this->CellIds[kept++] = this->CellIds[h];
    }
    this->CellIds.resize(kept);
    this->CornerIds.resize(8 * kept);
  }
  const vtkIdType numberOfHexahedra = this->GetNumberOfHexahedra();
  if (numberOfHexahedra == 0)
  {
    return false;
  }
  this->Hidden = ppiray::HiddenCells(grid, this->CellIds);

  // Right-handed, with the cell frame at a corner that has one.
  for (vtkIdType h = 0; h < numberOfHexahedra; ++h)
  {
    vtkIdType* c = this->CornerIds.data() + 8 * h;
    if (Handedness(local, c) < 0)
    {
      std::rotate(c, c + 4, c + 8); // swap bottom and top
      ++this->NumberOfMirroredHexahedra;
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
    this->NumberOfSingularFrames += quality > 1e-6 ? 0 : 1;
  }

  // Corners in the local frame.
  this->Corners.resize(24 * numberOfHexahedra);
  double diameter2 = 0;
  for (vtkIdType h = 0; h < numberOfHexahedra; ++h)
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

  // Faces matched by their sorted point ids; diagonals by the smallest id,
  // except where that folds a collapsed cell (ppiray::QuadDiagonals).
  ppiray::QuadDiagonals diagonals;
  for (vtkIdType h = 0; h < numberOfHexahedra; ++h)
  {
    diagonals.AddHexahedron(this->CornerIds.data() + 8 * h);
  }
  this->NumberOfUnfoldedFaces = diagonals.GetNumberOfUnfoldedFaces();
  std::vector<FaceKey> faces(6 * numberOfHexahedra);
  this->Neighbors.assign(8 * numberOfHexahedra, -1);
  for (vtkIdType h = 0; h < numberOfHexahedra; ++h)
  {
    const vtkIdType* c = this->CornerIds.data() + 8 * h;
    int mask = 0;
    for (int f = 0; f < 6; ++f)
    {
      const vtkIdType* q = vtkHexahedron::GetFaceArray(f);
      FaceKey& key = faces[6 * h + f];
      key.Ids = { c[q[0]], c[q[1]], c[q[2]], c[q[3]] };
      mask |=
        diagonals.AlongFirstDiagonal(key.Ids[0], key.Ids[1], key.Ids[2], key.Ids[3]) ? 0 : 1 << f;
      std::sort(key.Ids.begin(), key.Ids.end());
      key.Owner = 6 * h + f;
    }
    this->Neighbors[8 * h + 6] = mask;
  }
  std::sort(faces.begin(), faces.end());
  std::vector<vtkIdType> boundary; // 6 h + f
  for (size_t i = 0; i < faces.size();)
  {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].Ids == faces[i].Ids)
    {
      ++j;
    }
    if (j - i == 2)
    {
      const vtkIdType a = faces[i].Owner, b = faces[i + 1].Owner;
      const bool folded = OnOneSide(local, this->CornerIds.data(), a, b);
      this->NumberOfFoldedFaces += folded ? 1 : 0;
      this->Neighbors[8 * (a / 6) + a % 6] = NeighborCode(b / 6, b % 6, folded, false);
      this->Neighbors[8 * (b / 6) + b % 6] = NeighborCode(a / 6, a % 6, folded, false);
    }
    else
    {
      if (j - i > 2)
      {
        ++this->NumberOfNonManifoldFaces;
      }
      for (size_t k = i; k < j; ++k)
      {
        boundary.push_back(faces[k].Owner);
      }
    }
    i = j;
  }
  std::sort(boundary.begin(), boundary.end());

  // The inverted side of each fold: there the ray turns back in the cell it
  // is in (ppirayInvertedSheets.h).
  if (this->NumberOfFoldedFaces > 0)
  {
    auto cellOf = [](int code) { return code == -1 ? -1 : (code < -1 ? -code - 2 : code) / 6; };
    auto faceOf = [](int code) { return (code < -1 ? -code - 2 : code) % 6; };
    const std::vector<unsigned char> inverted = ppiray::InvertedSheets(
      numberOfHexahedra, 6, [&](vtkIdType h, int f) { return cellOf(this->Neighbors[8 * h + f]); },
      [&](vtkIdType h, int f) { return this->Neighbors[8 * h + f] < -1; },
      [&](vtkIdType h) { return std::abs(SignedVolume(local, this->CornerIds.data() + 8 * h)); });
    for (vtkIdType h = 0; h < numberOfHexahedra; ++h)
    {
      for (int f = 0; f < 6; ++f)
      {
        int& code = this->Neighbors[8 * h + f];
        const int n = cellOf(code);
        if (code < -1 && ppiray::WalksBackInPlace(inverted, h, n))
        {
          code = NeighborCode(n, faceOf(code), true, true);
        }
      }
    }
  }

  // Boundary triangles, wound outward (VTK's hexahedron faces are outward for
  // a right-handed cell), over a compact set of points.
  std::vector<vtkIdType> pointMap(grid->GetNumberOfPoints(), -1);
  for (vtkIdType owner : boundary)
  {
    const vtkIdType h = owner / 6;
    const int f = static_cast<int>(owner % 6);
    const bool second = (this->Neighbors[8 * h + 6] >> f) & 1;
    for (int t = 0; t < 2; ++t)
    {
      for (int v = 0; v < 3; ++v)
      {
        const vtkIdType id = this->CornerIds[8 * h + TriangleCorner(f, t, v, second)];
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
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkHexahedralCellTextures::BuildField(vtkDataArray* scalars, bool cellScalars, int component)
{
  const vtkIdType numberOfHexahedra = this->GetNumberOfHexahedra();
  this->Coefficients.assign(8 * numberOfHexahedra, 0.0f);
  this->NumberOfNaNScalars = 0;
  if (!scalars || numberOfHexahedra == 0 || component < 0 ||
      component >= scalars->GetNumberOfComponents())
  {
    return false;
  }
  std::atomic<vtkIdType> nanCells(0);
#pragma omp parallel for schedule(static)
  for (vtkIdType h = 0; h < numberOfHexahedra; ++h)
  {
    float* out = this->Coefficients.data() + 8 * h;
    double s[8];
    bool hasNaN = false;
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
        s[i] = scalars->GetComponent(this->CornerIds[8 * h + i], component);
        hasNaN = hasNaN || std::isnan(s[i]);
      }
    }
    if (hasNaN || (h < static_cast<vtkIdType>(this->Hidden.size()) && this->Hidden[h]))
    {
      out[0] = TransparentCellOffset();
      nanCells += hasNaN ? 1 : 0;
      continue;
    }
    double corners[8][3], frame[12], c[8];
    for (int i = 0; i < 8; ++i)
    {
      std::copy_n(this->LocalPoints.data() + 3 * this->CornerIds[8 * h + i], 3, corners[i]);
    }
    vtkHexahedronCoefficients::FitCoefficients(corners, s, frame, c);
    for (int k = 0; k < 8; ++k)
    {
      out[k] = static_cast<float>(c[k]);
    }
  }
  this->NumberOfNaNScalars = nanCells.load();
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
  os << indent << "NumberOfNaNScalars: " << this->NumberOfNaNScalars << "\n";
  os << indent << "NumberOfSingularFrames: " << this->NumberOfSingularFrames << "\n";
  os << indent << "NumberOfFlatHexahedra: " << this->NumberOfFlatHexahedra << "\n";
  os << indent << "NumberOfOtherCells: " << this->NumberOfOtherCells << "\n";
  os << indent << "NumberOfQuadraticCells: " << this->NumberOfQuadraticCells << "\n";
}
