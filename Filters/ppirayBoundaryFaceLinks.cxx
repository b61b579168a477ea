#include "ppirayBoundaryFaceLinks.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace
{
using glm::dvec3;

struct Triangle
{
  dvec3 P[3];
};

Triangle FaceOf(const std::vector<vtkIdType>& tets, const double* local, vtkIdType key)
{
  Triangle tri;
  for (int v = 0; v < 3; ++v)
  {
    const vtkIdType id = tets[4 * (key / 4) + vtkUnstructuredGridCellAdjacency::FaceVertex(
                                                static_cast<int>(key % 4), v)];
    tri.P[v] = glm::make_vec3(local + 3 * id);
  }
  return tri;
}

double Area(const Triangle& t)
{
  return 0.5 * glm::length(glm::cross(t.P[1] - t.P[0], t.P[2] - t.P[0]));
}

// How far x lies from triangle t, relative to t's longest edge: the larger of
// its distance to t's plane and how far it is outside t's edges, in that
// plane (0 inside the triangle, on its plane).
double RelativeDistance(const Triangle& t, const dvec3& x)
{
  const dvec3 n = glm::cross(t.P[1] - t.P[0], t.P[2] - t.P[0]);
  const double twiceArea = glm::length(n);
  double longest = 0;
  for (int e = 0; e < 3; ++e)
  {
    longest = std::max(longest, glm::length(t.P[(e + 1) % 3] - t.P[e]));
  }
  if (!(twiceArea > 0.0) || !(longest > 0.0))
  {
    return HUGE_VAL;
  }
  const dvec3 unit = n / twiceArea;
  double outside = std::abs(glm::dot(unit, x - t.P[0]));
  for (int e = 0; e < 3; ++e)
  {
    // Signed distance into the triangle from edge e, in its plane.
    const dvec3 edge = t.P[(e + 1) % 3] - t.P[e];
    const dvec3 inward = glm::cross(unit, edge) / glm::length(edge);
    outside = std::max(outside, -glm::dot(inward, x - t.P[e]));
  }
  return outside / longest;
}
}

namespace ppiray
{
//------------------------------------------------------------------------------
void RemoveCellsLeftOutOfFill(
  vtkUnstructuredGrid* grid, std::vector<vtkIdType>& tets, std::vector<vtkIdType>& cellIds)
{
  vtkDataArray* across = grid->GetCellData()->GetArray(BoundaryCellArrayName);
  if (!across || across->GetNumberOfComponents() != 4)
  {
    return;
  }
  size_t kept = 0;
  for (size_t t = 0; t < cellIds.size(); ++t)
  {
    const vtkIdType c = cellIds[t];
    if (c < across->GetNumberOfTuples() && across->GetComponent(c, 0) == LeftOutOfFill)
    {
      continue;
    }
    std::copy_n(tets.data() + 4 * t, 4, tets.data() + 4 * kept);
    cellIds[kept++] = c;
  }
  tets.resize(4 * kept);
  cellIds.resize(kept);
}

//------------------------------------------------------------------------------
BoundaryFaceLinks LinkBoundaryFaces(vtkUnstructuredGrid* grid, const std::vector<vtkIdType>& tets,
  const std::vector<vtkIdType>& cellIds, const double* local,
  const std::vector<unsigned char>& open, const std::vector<unsigned char>& flat)
{
  BoundaryFaceLinks links;
  vtkDataArray* across = grid->GetCellData()->GetArray(BoundaryCellArrayName);
  if (!across || across->GetNumberOfComponents() != 4 || cellIds.empty() ||
      !std::is_sorted(cellIds.begin(), cellIds.end()))
  {
    return links;
  }
  // A piece lies in the face when its centroid does, to rounding of the
  // coordinates (the pieces are cut from the face exactly).
  constexpr double tolerance = 1e-7;
  const vtkIdType numberOfTets = static_cast<vtkIdType>(cellIds.size());
  std::vector<std::pair<vtkIdType, vtkIdType>> faceAndPiece;
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
    const vtkIdType c = cellIds[t];
    if (c >= across->GetNumberOfTuples())
    {
      continue;
    }
    for (int f = 0; f < 4; ++f)
    {
      const double named = across->GetComponent(c, f);
      if (!open[4 * t + f] || !(named >= 0) || named >= grid->GetNumberOfCells())
      {
        continue;
      }
      const vtkIdType b = static_cast<vtkIdType>(named);
      const Triangle piece = FaceOf(tets, local, 4 * t + f);
      const dvec3 centroid = (piece.P[0] + piece.P[1] + piece.P[2]) / 3.0;
      const auto range = std::equal_range(cellIds.begin(), cellIds.end(), b);
      vtkIdType best = -1;
      double bestDistance = tolerance;
      for (auto m = range.first; m != range.second; ++m)
      {
        const vtkIdType u = static_cast<vtkIdType>(m - cellIds.begin());
        for (int g = 0; g < 4 && !flat[u]; ++g)
        {
          const double d =
            open[4 * u + g] ? RelativeDistance(FaceOf(tets, local, 4 * u + g), centroid) : HUGE_VAL;
          if (d <= bestDistance)
          {
            bestDistance = d;
            best = 4 * u + g;
          }
        }
      }
      if (best < 0)
      {
        ++links.UnmatchedPieces;
        continue;
      }
      faceAndPiece.emplace_back(best, 4 * t + f);
    }
  }
  // Faces covered by their pieces: the areas add up.
  std::sort(faceAndPiece.begin(), faceAndPiece.end());
  for (size_t i = 0; i < faceAndPiece.size();)
  {
    size_t j = i;
    double pieces = 0;
    for (; j < faceAndPiece.size() && faceAndPiece[j].first == faceAndPiece[i].first; ++j)
    {
      pieces += Area(FaceOf(tets, local, faceAndPiece[j].second));
    }
    const double area = Area(FaceOf(tets, local, faceAndPiece[i].first));
    if (std::abs(pieces - area) <= 1e-6 * area)
    {
      links.Faces.push_back(faceAndPiece[i].first);
      for (size_t k = i; k < j; ++k)
      {
        links.Pieces.push_back(faceAndPiece[k].second);
      }
      links.Offsets.push_back(static_cast<vtkIdType>(links.Pieces.size()));
    }
    else
    {
      ++links.UncoveredFaces;
    }
    i = j;
  }
  return links;
}
}
