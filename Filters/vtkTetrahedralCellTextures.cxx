#include "vtkTetrahedralCellTextures.h"

#include "ppirayBoundaryFaceLinks.h"
#include "ppirayCellAdjacency.h"
#include "ppirayConformingTetrahedra.h"
#include "ppirayHiddenCells.h"
#include "ppirayMeshLocalFrame.h"
#include "ppirayNonConformingFaces.h"
#include "ppirayReflexEdges.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkTetrahedralCellTextures);

namespace
{
using glm::dvec3;
using glm::make_vec3;

// A tetrahedron is treated as flat when |6V| <= eps * L^3, L its longest edge:
// its face planes are then not a partition of space a ray can march through.
constexpr double FlatVolumeRatio = 1e-12;

double LongestEdge(const double* p[4])
{
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      longest = std::max(longest, glm::length(make_vec3(p[j]) - make_vec3(p[i])));
    }
  }
  return longest;
}
}

//------------------------------------------------------------------------------
bool vtkTetrahedralCellTextures::BuildGeometry(vtkUnstructuredGrid* grid)
{
  this->Stages.Clear();
  ppiray::StageTimes::Laps laps(this->Stages, ppiray::ProgressEvents(this, 6));
  ppiray::TetrahedralSplit split;
  split.Tets.swap(this->Tets); // the last build's storage, reused (no fresh pages)
  split.CellIds.swap(this->CellIds);
  ppiray::SplitIntoTetrahedra(grid, /*tetrahedraOnly=*/false, split);
  ppiray::RemoveCellsLeftOutOfFill(grid, split.Tets, split.CellIds);
  this->NumberOfUnsupportedCells = split.GetNumberOfUnsupportedCells();
  this->NumberOfSplitCells = split.NumberOfSplitCells;
  this->NumberOfQuadraticCells = split.NumberOfQuadraticCells;
  this->Tets = std::move(split.Tets);
  this->CellIds = std::move(split.CellIds);
  this->Added = std::move(split.Added);
  this->NumberOfPolyhedra = split.NumberOfPolyhedra;
  this->Unsupported = std::move(split.Unsupported);
  this->Hidden = ppiray::HiddenCells(grid, this->CellIds);
  this->NumberOfHiddenTetrahedra = std::count(this->Hidden.begin(), this->Hidden.end(), 1);
  this->FacePlanes.clear();
  this->Neighbors.clear();
  this->Field.clear();
  this->CellCorners.clear();
  this->PointTexels.clear();
  this->CellValues.clear();
  this->BoundaryPoints.clear();
  this->BoundaryTriangles.clear();
  this->BoundaryFaces.clear();
  this->NumberOfDegenerateTetrahedra = 0;
  this->NumberOfInvertedTetrahedra = 0;
  this->NumberOfNonManifoldFaces = 0;
  this->NumberOfFoldedFaces = 0;
  this->NumberOfLinkedFaces = this->NumberOfSplitFaces = this->NumberOfUnlinkedFaces = 0;
  this->MaximumPiecesPerFace = 0;
  this->NumberOfReentryFaces = 0;
  this->NumberOfNonConformingFaces = 0;
  this->NumberOfLensFaces = 0;
  const vtkIdType numberOfTets = this->GetNumberOfTetrahedra();
  if (numberOfTets == 0 || !grid->GetPoints())
  {
    return false;
  }
  if (numberOfTets > ppiray::MaximumAdjacencyCells)
  {
    vtkErrorMacro("Mesh too large: " << numberOfTets << " tetrahedra (at most "
                                     << ppiray::MaximumAdjacencyCells << ").");
    return false;
  }

  laps.End("tetrahedra");
  this->Length = ppiray::ComputeLocalPoints(grid->GetPoints(), this->Origin, this->LocalPoints);
  for (size_t i = 0; i < this->Added.Points.size(); ++i)
  {
    // Added points (polyhedra) lie inside the cells, within the bounds.
    this->LocalPoints.push_back(this->Added.Points[i] - this->Origin[i % 3]);
  }
  this->NumberOfGridPoints = grid->GetNumberOfPoints();
  const vtkIdType numberOfPoints = this->NumberOfGridPoints + this->Added.GetNumberOfPoints();

  const bool compact = this->Layout == COMPACT;
  if (compact && numberOfPoints > InvertedCorners())
  {
    vtkErrorMacro("The compact layout holds at most " << InvertedCorners() << " points, not "
                                                      << numberOfPoints << ".");
    return false;
  }
  if (compact)
  {
    // Corners: point ids and flags; points: (x, s), s set by BuildField().
    this->CellCorners.resize(4 * numberOfTets);
    std::transform(this->Tets.begin(), this->Tets.end(), this->CellCorners.begin(),
      [](vtkIdType id) { return static_cast<int>(id); });
    this->PointTexels.assign(4 * numberOfPoints, 0.0f);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      std::copy_n(this->LocalPoints.data() + 3 * i, 3, this->PointTexels.data() + 4 * i);
    }
  }

  laps.End("points");
  // Face planes: n_f outward unit normal, d_f = n_f . (face centroid).
  this->Degenerate.assign(numberOfTets, 0);
  this->FacePlanes.resize(compact ? 0 : 16 * numberOfTets); // every texel set below
  std::vector<signed char> orientation(numberOfTets, 1);
  std::atomic<vtkIdType> degenerate(0), inverted(0);
  double maximumEdge = 0.0;
  const double* local = this->LocalPoints.data();
  const vtkIdType* tets = this->Tets.data();
#pragma omp parallel for schedule(static) reduction(max : maximumEdge)
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
    const double* p[4];
    for (int v = 0; v < 4; ++v)
    {
      p[v] = local + 3 * tets[4 * t + v];
    }
    const double volume6 = vtkUnstructuredGridCellAdjacency::SignedVolume6(p[0], p[1], p[2], p[3]);
    const double edge = LongestEdge(p);
    if (!(std::abs(volume6) > FlatVolumeRatio * edge * edge * edge))
    {
      // A flat tetrahedron keeps its corners, for the ray to pass through it.
      this->Degenerate[t] = 1;
      ++degenerate;
      if (compact)
      {
        this->CellCorners[4 * t + 3] += FlatCorners();
        continue;
      }
      for (int v = 0; v < 4; ++v)
      {
        float* corner = this->FacePlanes.data() + 16 * t + 4 * v;
        for (int i = 0; i < 3; ++i)
        {
          corner[i] = static_cast<float>(p[v][i]);
        }
        corner[3] = FlatCellMarker();
      }
      continue;
    }
    maximumEdge = std::max(maximumEdge, edge);
    const double sign = volume6 > 0 ? 1.0 : -1.0;
    if (sign < 0)
    {
      orientation[t] = -1;
      ++inverted;
    }
    if (compact)
    {
      this->CellCorners[4 * t + 3] += sign < 0 ? InvertedCorners() : 0;
      continue;
    }
    for (int f = 0; f < 4; ++f)
    {
      // Outward unit normal n and d = n . x on the face (at its centroid).
      const dvec3 a = make_vec3(p[vtkUnstructuredGridCellAdjacency::FaceVertex(f, 0)]);
      const dvec3 b = make_vec3(p[vtkUnstructuredGridCellAdjacency::FaceVertex(f, 1)]);
      const dvec3 c = make_vec3(p[vtkUnstructuredGridCellAdjacency::FaceVertex(f, 2)]);
      const dvec3 n = sign * glm::normalize(glm::cross(b - a, c - a));
      float* plane = this->FacePlanes.data() + 16 * t + 4 * f;
      plane[0] = static_cast<float>(n.x);
      plane[1] = static_cast<float>(n.y);
      plane[2] = static_cast<float>(n.z);
      plane[3] = static_cast<float>(glm::dot(n, (a + b + c) / 3.0));
    }
  }
  this->NumberOfDegenerateTetrahedra = degenerate.load();
  this->MaximumEdgeLength = maximumEdge;
  this->NumberOfInvertedTetrahedra = inverted.load();
  laps.End("planes");

  // Neighbours: the flat tetrahedra between the others, folded faces marked.
  vtkUnstructuredGridCellAdjacency* adjacency = this->Adjacency;
  adjacency->Build(numberOfPoints, tets, numberOfTets, local, this->Degenerate.data());
  this->NumberOfNonManifoldFaces = adjacency->GetNumberOfNonManifoldFaces();
  this->NumberOfFoldedFaces = adjacency->GetNumberOfFoldedFaces();
  const std::vector<int>& neighbors = adjacency->GetNeighbors();
  const std::vector<signed char>& neighborFaces = adjacency->GetNeighborFaces();
  this->Neighbors.resize(neighbors.size());
  const vtkIdType slots = static_cast<vtkIdType>(neighbors.size());
#pragma omp parallel for schedule(static)
  for (vtkIdType k = 0; k < slots; ++k)
  {
    const vtkIdType t = k / 4;
    const vtkIdType n = neighbors[k];
    const bool folded = n >= 0 && adjacency->IsFolded(t, k % 4);
    const bool inPlace = folded && adjacency->WalksBackInPlace(t, n);
    this->Neighbors[k] = n < 0 ? NoNeighbor() : NeighborCode(n, neighborFaces[k], folded, inPlace);
  }

  laps.End(adjacency->WasKept() ? "folds" : "adjacency");

  // Boundary triangles wound outward, over a compact set of points, but for
  // those joined to the imaginary cells on them.
  const std::vector<vtkIdType>& boundary = adjacency->GetBoundaryFaces();
  std::vector<unsigned char> linked = this->LinkBoundaryFaces(grid, boundary);
  this->LinkNonConformingFaces(boundary, orientation, linked);
  std::vector<vtkIdType> pointMap(numberOfPoints, -1);
  for (size_t k = 0; k < boundary.size(); k += 2)
  {
    const vtkIdType t = boundary[k];
    const int f = static_cast<int>(boundary[k + 1]);
    if (linked[4 * t + f])
    {
      continue; // crossed into the imaginary cells on it
    }
    int corner[3] = { vtkUnstructuredGridCellAdjacency::FaceVertex(f, 0),
      vtkUnstructuredGridCellAdjacency::FaceVertex(f, 1),
      vtkUnstructuredGridCellAdjacency::FaceVertex(f, 2) };
    if (orientation[t] < 0 || (this->Degenerate[t] && this->FacesTowards(t, corner, neighbors)))
    {
      std::swap(corner[1], corner[2]);
    }
    for (int v : corner)
    {
      const vtkIdType id = tets[4 * t + v];
      if (pointMap[id] < 0)
      {
        pointMap[id] = static_cast<vtkIdType>(this->BoundaryPoints.size() / 3);
        for (int i = 0; i < 3; ++i)
        {
          this->BoundaryPoints.push_back(static_cast<float>(local[3 * id + i]));
        }
      }
      this->BoundaryTriangles.push_back(static_cast<unsigned int>(pointMap[id]));
    }
    this->BoundaryFaces.push_back(static_cast<int>(4 * t + f));
  }

  laps.End("boundary");

  // Faces with reflex edges: the faces across them, for the march to enter
  // again where it leaves next to one.
  this->NumberOfReentryFaces = ppiray::ListReentryFaces(
    this->BoundaryPoints, this->BoundaryTriangles, this->BoundaryFaces,
    [](int face) { return static_cast<size_t>(face); }, ReentryFace(), this->Neighbors);
  laps.End("re-entry faces");
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
std::vector<unsigned char> vtkTetrahedralCellTextures::LinkBoundaryFaces(
  vtkUnstructuredGrid* grid, const std::vector<vtkIdType>& boundary)
{
  this->NumberOfLinkedFaces = this->NumberOfSplitFaces = this->NumberOfUnlinkedFaces = 0;
  this->MaximumPiecesPerFace = 0;
  std::vector<unsigned char> linked(this->Neighbors.size(), 0);
  if (!grid->GetCellData()->GetArray(ppiray::BoundaryCellArrayName))
  {
    return linked;
  }
  std::vector<unsigned char> open(this->Neighbors.size(), 0);
  for (size_t k = 0; k < boundary.size(); k += 2)
  {
    open[4 * boundary[k] + boundary[k + 1]] = 1;
  }
  const ppiray::BoundaryFaceLinks links = ppiray::LinkBoundaryFaces(
    grid, this->Tets, this->CellIds, this->LocalPoints.data(), open, this->Degenerate);
  this->NumberOfUnlinkedFaces = links.UncoveredFaces + links.UnmatchedPieces;
  auto code = [](vtkIdType key)
  { return NeighborCode(key / 4, static_cast<int>(key % 4), false, false); };
  for (size_t i = 0; i < links.Faces.size(); ++i)
  {
    const vtkIdType face = links.Faces[i];
    const vtkIdType first = links.Offsets[i], n = links.Offsets[i + 1] - first;
    if (n > MaximumPieces())
    {
      ++this->NumberOfUnlinkedFaces;
      continue;
    }
    for (vtkIdType p = first; p < first + n; ++p)
    {
      this->Neighbors[links.Pieces[p]] = code(face);
      linked[links.Pieces[p]] = 1;
    }
    linked[face] = 1;
    ++this->NumberOfLinkedFaces;
    if (n == 1)
    {
      this->Neighbors[face] = code(links.Pieces[first]);
      continue;
    }
    std::vector<int> codes;
    for (vtkIdType p = first; p < first + n; ++p)
    {
      codes.push_back(code(links.Pieces[p]));
    }
    this->Neighbors[face] = ppiray::AppendFaceList(this->Neighbors, codes, SplitFace());
    ++this->NumberOfSplitFaces;
    this->MaximumPiecesPerFace = std::max(this->MaximumPiecesPerFace, static_cast<int>(n));
  }
  return linked;
}

//------------------------------------------------------------------------------
void vtkTetrahedralCellTextures::LinkNonConformingFaces(const std::vector<vtkIdType>& boundary,
  const std::vector<signed char>& orientation, std::vector<unsigned char>& linked)
{
  // The open faces left (of tetrahedra with volume), wound outward, linked
  // to the open faces across them (ppirayNonConformingFaces.h).
  std::vector<ppiray::OpenFace> faces;
  std::vector<vtkIdType> keys; // 4 t + f
  for (size_t k = 0; k < boundary.size(); k += 2)
  {
    const vtkIdType t = boundary[k];
    const int f = static_cast<int>(boundary[k + 1]);
    if (linked[4 * t + f] || this->Degenerate[t])
    {
      continue;
    }
    int corner[3] = { vtkUnstructuredGridCellAdjacency::FaceVertex(f, 0),
      vtkUnstructuredGridCellAdjacency::FaceVertex(f, 1),
      vtkUnstructuredGridCellAdjacency::FaceVertex(f, 2) };
    if (orientation[t] < 0)
    {
      std::swap(corner[1], corner[2]);
    }
    ppiray::OpenFace face{ t, 1, {} };
    for (int v = 0; v < 3; ++v)
    {
      face.Points[v] = this->Tets[4 * t + corner[v]];
    }
    face.Apex = this->Tets[4 * t + f]; // face f is opposite corner f
    faces.push_back(face);
    keys.push_back(4 * t + f);
  }
  const ppiray::NonConformingLinks links = ppiray::LinkNonConformingFaces(
    this->LocalPoints.data(), faces,
    [&](vtkIdType i)
    { return NeighborCode(keys[i] / 4, static_cast<int>(keys[i] % 4), false, false); },
    [&](vtkIdType i) { return static_cast<size_t>(keys[i]); },
    [](vtkIdType, vtkIdType) {}, // triangles: nothing to align
    SplitFace(), MaximumPieces(), this->Neighbors);
  for (size_t i = 0; i < faces.size(); ++i)
  {
    linked[keys[i]] = linked[keys[i]] || links.Covered[i];
  }
  this->NumberOfNonConformingFaces = links.Faces;
  this->NumberOfLensFaces = links.Lenses;
  this->MaximumPiecesPerFace = std::max(this->MaximumPiecesPerFace, links.MaximumPieces);
}

//------------------------------------------------------------------------------
bool vtkTetrahedralCellTextures::FacesTowards(
  vtkIdType t, const int corner[3], const std::vector<int>& neighbors) const
{
  // The first non-flat cell's centre on the triangle's positive side.
  const vtkIdType n = ppiray::NearestSolidCell(t, neighbors.data(), 4, this->Degenerate.data());
  if (n < 0)
  {
    return false;
  }
  const double* local = this->LocalPoints.data();
  const vtkIdType* tet = this->Tets.data() + 4 * t;
  double centre[3] = { 0, 0, 0 };
  for (int v = 0; v < 4; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += 0.25 * local[3 * this->Tets[4 * n + v] + k];
    }
  }
  return vtkUnstructuredGridCellAdjacency::SignedVolume6(local + 3 * tet[corner[0]],
           local + 3 * tet[corner[1]], local + 3 * tet[corner[2]], centre) > 0;
}

//------------------------------------------------------------------------------
double vtkTetrahedralCellTextures::PointValue(
  vtkDataArray* values, vtkIdType id, int component) const
{
  return id < this->NumberOfGridPoints
           ? values->GetComponent(id, component)
           : this->Added.Value(id - this->NumberOfGridPoints, values, component);
}

//------------------------------------------------------------------------------
bool vtkTetrahedralCellTextures::BuildField(vtkDataArray* scalars, bool cellScalars, int component)
{
  const vtkIdType numberOfTets = this->GetNumberOfTetrahedra();
  const bool compact = this->Layout == COMPACT;
  this->Field.assign(compact ? 0 : 4 * numberOfTets, 0.0f);
  this->CellValues.assign(compact ? numberOfTets : 0, 0.0f);
  this->NumberOfNaNScalars = 0;
  if (!scalars || numberOfTets == 0 || component < 0 ||
      component >= scalars->GetNumberOfComponents())
  {
    return false;
  }
  const double* local = this->LocalPoints.data();
  const vtkIdType* tets = this->Tets.data();
  std::atomic<vtkIdType> nanCells(0);
  if (compact)
  {
    // The points' scalars, interpolated by the march (cell scalars: 0).
    const vtkIdType numberOfPoints = static_cast<vtkIdType>(this->PointTexels.size() / 4);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      const double s = cellScalars ? 0.0 : this->PointValue(scalars, i, component);
      this->PointTexels[4 * i + 3] = std::isnan(s) ? 0.0f : static_cast<float>(s);
    }
  }

#pragma omp parallel for schedule(static)
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
    float* field = compact ? nullptr : this->Field.data() + 4 * t;
    float& value = compact ? this->CellValues[t] : field[3];
    if (this->Degenerate[t] || (t < static_cast<vtkIdType>(this->Hidden.size()) && this->Hidden[t]))
    {
      value = TransparentCellOffset();
      continue;
    }
    if (cellScalars)
    {
      const double s = scalars->GetComponent(this->CellIds[t], component);
      value = std::isnan(s) ? TransparentCellOffset() : static_cast<float>(s);
      nanCells += std::isnan(s) ? 1 : 0;
      continue;
    }
    const double* p[4];
    double s[4];
    bool hasNaN = false;
    for (int v = 0; v < 4; ++v)
    {
      p[v] = local + 3 * tets[4 * t + v];
      s[v] = this->PointValue(scalars, tets[4 * t + v], component);
      hasNaN = hasNaN || std::isnan(s[v]);
    }
    if (hasNaN)
    {
      value = TransparentCellOffset();
      ++nanCells;
      continue;
    }
    if (compact)
    {
      continue; // the points' scalars, interpolated
    }
    // Gradient of the linear interpolant: M g = ds with rows r_i = p_i - p_0,
    // solved by Cramer's rule, g = (ds1 r2 x r3 + ds2 r3 x r1 + ds3 r1 x r2) / det M.
    const dvec3 p0 = make_vec3(p[0]);
    const dvec3 r1 = make_vec3(p[1]) - p0, r2 = make_vec3(p[2]) - p0, r3 = make_vec3(p[3]) - p0;
    const dvec3 c23 = glm::cross(r2, r3), c31 = glm::cross(r3, r1), c12 = glm::cross(r1, r2);
    const dvec3 g =
      ((s[1] - s[0]) * c23 + (s[2] - s[0]) * c31 + (s[3] - s[0]) * c12) / glm::dot(r1, c23);
    const double s0 = s[0] - glm::dot(g, p0);
    field[0] = static_cast<float>(g.x);
    field[1] = static_cast<float>(g.y);
    field[2] = static_cast<float>(g.z);
    field[3] = static_cast<float>(s0);
  }
  this->NumberOfNaNScalars = nanCells.load();
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkTetrahedralCellTextures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Layout: " << (this->Layout == COMPACT ? "COMPACT" : "PLANES") << "\n";
  os << indent << "NumberOfTetrahedra: " << this->GetNumberOfTetrahedra() << "\n";
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "NumberOfBoundaryFaces: " << this->BoundaryFaces.size() << "\n";
  os << indent << "NumberOfDegenerateTetrahedra: " << this->NumberOfDegenerateTetrahedra << "\n";
  os << indent << "NumberOfInvertedTetrahedra: " << this->NumberOfInvertedTetrahedra << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
  os << indent << "NumberOfFoldedFaces: " << this->NumberOfFoldedFaces << "\n";
  os << indent << "NumberOfNaNScalars: " << this->NumberOfNaNScalars << "\n";
  os << indent << "NumberOfUnsupportedCells: " << this->NumberOfUnsupportedCells << "\n";
  os << indent << "NumberOfSplitCells: " << this->NumberOfSplitCells << "\n";
  os << indent << "NumberOfQuadraticCells: " << this->NumberOfQuadraticCells << "\n";
  os << indent << "NumberOfLinkedFaces: " << this->NumberOfLinkedFaces << "\n";
  os << indent << "NumberOfPolyhedra: " << this->NumberOfPolyhedra << "\n";
  os << indent << "NumberOfSplitFaces: " << this->NumberOfSplitFaces << "\n";
  os << indent << "MaximumPiecesPerFace: " << this->MaximumPiecesPerFace << "\n";
  os << indent << "NumberOfUnlinkedFaces: " << this->NumberOfUnlinkedFaces << "\n";
  os << indent << "NumberOfReentryFaces: " << this->NumberOfReentryFaces << "\n";
}
