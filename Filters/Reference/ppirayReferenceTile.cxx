#include "ppirayReferenceTile.h"

#include "vtkDataArray.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ppiray
{
namespace reference
{
namespace
{
// The items of one tile: its tetrahedra and its general cells.
struct TileCells
{
  std::vector<Tetrahedron> Tetrahedra; // flat ones and those with a NaN scalar left out
  std::vector<size_t> General;         // indices into ReferenceCells::General
};

// The tetrahedra in the renderer's frame, with their barycentric inverses.
TileCells CellsOfTile(const Scene& scene, int tile)
{
  TileCells cells;
  const vtkIdType numberOfTets = scene.Cells.NumberOfTetrahedra();
  for (vtkIdType k = scene.Tiles.Offsets[tile]; k < scene.Tiles.Offsets[tile + 1]; ++k)
  {
    const vtkIdType t = scene.Tiles.Items[k];
    if (t >= numberOfTets)
    {
      cells.General.push_back(static_cast<size_t>(t - numberOfTets));
      continue;
    }
    Vec3 p[4];
    Tetrahedron tet;
    for (int v = 0; v < 4; ++v)
    {
      const vtkIdType id = scene.Cells.Tetrahedra[4 * t + v];
      double x[3];
      scene.Grid->GetPoints()->GetPoint(id, x);
      p[v] = Vec3(x[0], x[1], x[2]) - scene.View.Centre;
      tet.S[v] = scene.CellScalars ? scene.Scalars->GetComponent(scene.Cells.TetrahedronCell[t], 0)
                                   : scene.Scalars->GetComponent(id, 0);
    }
    if (std::isnan(tet.S[0] + tet.S[1] + tet.S[2] + tet.S[3]) || !InvertEdges(p, tet.Inverse))
    {
      continue;
    }
    tet.P0 = p[0];
    cells.Tetrahedra.push_back(tet);
  }
  return cells;
}

// The interpolated field's gradient in general cell c at the ray's t (the
// cell's own derivatives at its parametric coordinates there); zero for cell
// scalars.
class GeneralCellGradient
{
public:
  GeneralCellGradient(const Scene& scene, const Vec3& origin, const Vec3& direction)
    : S(scene)
    , Origin(origin)
    , Direction(direction)
  {
  }

  Vec3 operator()(vtkIdType c, double t)
  {
    if (this->S.CellScalars)
    {
      return { 0, 0, 0 };
    }
    this->S.Grid->GetCell(c, this->Cell);
    const int n = InterpolatedPoints(this->Cell);
    this->Values.resize(n);
    this->Weights.resize(std::max(n, 8));
    for (int v = 0; v < n; ++v)
    {
      this->Values[v] = this->S.Scalars->GetComponent(this->Cell->GetPointId(v), 0);
    }
    double x[3], pcoords[3], dist2, g[3] = { 0, 0, 0 };
    for (int i = 0; i < 3; ++i)
    {
      x[i] = this->Origin[i] + t * this->Direction[i] + this->S.View.Centre[i];
    }
    int subId = 0;
    this->Cell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, this->Weights.data());
    this->Cell->Derivatives(subId, pcoords, this->Values.data(), 1, g);
    return { g[0], g[1], g[2] };
  }

private:
  const Scene& S;
  const Vec3& Origin; // the current pixel's ray
  const Vec3& Direction;
  vtkNew<vtkGenericCell> Cell;
  std::vector<double> Values, Weights;
};

// The ray's segments in the tile's cells (a general cell only where its
// pixel box holds the pixel), unsorted.
void RaySegments(const Scene& scene, const TileCells& cells, int px, int py, const Vec3& origin,
  const Vec3& direction, vtkGenericCell* cell, std::vector<Segment>& segments,
  long long& unresolved)
{
  segments.clear();
  for (const Tetrahedron& tet : cells.Tetrahedra)
  {
    Segment seg;
    if (ClipRay(tet, origin, direction, seg))
    {
      segments.push_back(seg);
    }
  }
  for (size_t g : cells.General)
  {
    const auto& box = scene.Tiles.GeneralBox[g];
    if (px < box[0] || px > box[1] || py < box[2] || py > box[3]) // pixel centres at integers
    {
      continue;
    }
    const vtkIdType c = scene.Cells.General[g];
    scene.Grid->GetCell(c, cell);
    GeneralCellSegments(c, cell, scene.Scalars, scene.CellScalars ? c : -1, origin, direction,
      scene.View.Centre, scene.LinearTolerance, segments, unresolved);
  }
}
}

//------------------------------------------------------------------------------
long long RenderTile(const Scene& scene, int tile, float* rgba)
{
  const int tx = tile % scene.Tiles.TilesX, ty = tile / scene.Tiles.TilesX;
  const int width = scene.View.Width, height = scene.View.Height, size = ScreenTiles::Size;
  const TileCells cells = CellsOfTile(scene, tile);
  long long unresolved = 0;
  vtkNew<vtkGenericCell> cell;
  std::vector<Segment> segments;
  Vec3 origin, direction;
  GeneralCellGradient gradient(scene, origin, direction);
  const GradientAt gradientAt = [&gradient](vtkIdType c, double t) { return gradient(c, t); };
  for (int py = ty * size; py < std::min(height, (ty + 1) * size); ++py)
  {
    for (int px = tx * size; px < std::min(width, (tx + 1) * size); ++px)
    {
      scene.View.PixelRay(px, py, origin, direction);
      RaySegments(scene, cells, px, py, origin, direction, cell, segments, unresolved);
      ClipSegments(segments, KeptRange(scene.View.ClippingPlanes, origin, direction));
      float* pixel = rgba + 4 * (static_cast<size_t>(py) * width + px);
      if (scene.IsProjection)
      {
        ProjectRay(segments, scene.TF, scene.How, pixel);
      }
      else
      {
        IntegrateRay(
          segments, scene.TF, scene.Iso, origin, direction, scene.View.Centre, gradientAt, pixel);
      }
    }
  }
  return unresolved;
}
}
}
