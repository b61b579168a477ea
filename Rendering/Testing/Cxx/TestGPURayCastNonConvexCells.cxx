// Hexahedra so distorted that a line leaves one, comes back in and leaves
// again, marched natively. Each face is the two triangles the mapper splits
// it into (the diagonal through the face's smallest point id,
// algorithms.md), so the cell is the region that closed triangulated
// surface bounds. With a constant colour and opacity the exact pixel is
//   C = c (1 - exp(-tau L)),  tau = opacity / unit distance,
// L the length of the pixel's ray inside that surface, computed here in
// double from the ray's crossings with the twelve triangles alone (no
// adjacency, no exit rule):  L = sum over crossings of +t heading out,
// -t heading in. Nothing is shared with the march's exit rule, whose rare
// cases these cells reach: a concave fold's far triangle crossed only after
// the line left by another face (cellExit's other-face guard), and the
// nearest of several crossed faces (cellExitSearch). The shapes and view
// directions are where those rules decide many rays, from a random search
// over distorted hexahedra (Documentation/datasets/nonconvex_cells_search.py);
// each rule broken alone fails here.

#include "PPIRayImageCompare.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
using Vec = std::array<double, 3>;

// vtkMath's vector operations on values.
Vec Sub(const Vec& a, const Vec& b)
{
  Vec d;
  vtkMath::Subtract(a.data(), b.data(), d.data());
  return d;
}

double Dot(const Vec& a, const Vec& b)
{
  return vtkMath::Dot(a.data(), b.data());
}

Vec Cross(const Vec& a, const Vec& b)
{
  Vec c;
  vtkMath::Cross(a.data(), b.data(), c.data());
  return c;
}

Vec Normalized(Vec a)
{
  vtkMath::Normalize(a.data());
  return a;
}

// A distorted hexahedron (VTK's corner order, every corner's Jacobian
// positive) and the direction of the rays that test it.
struct Shape
{
  std::array<Vec, 8> Corners;
  Vec Direction;
};

// Many rays where cellExit's other-face guard decides, and many where the
// first face in order with a crossed triangle is not the nearest.
const Shape Shapes[2] = {
  { { { { 0.392, 0.115, -0.07 }, { 1.224, -0.65, 0.207 }, { 0.653, 1.154, 0.201 },
      { -0.033, 0.655, 0.012 }, { -0.348, 0.397, 0.829 }, { 0.821, 0.738, 1.234 },
      { 0.821, 1.101, 1.223 }, { 0.309, 0.977, 1.037 } } },
    { -0.013, -0.79, 0.613 } },
  { { { { -0.171, 0.203, 0.394 }, { 0.635, -0.342, -0.213 }, { 1.112, 0.977, 0.421 },
      { -0.339, 1.002, -0.22 }, { 0.112, -0.266, 0.62 }, { 1.009, 0.236, 1.127 },
      { 1.295, 1.312, 1.228 }, { 0.126, 0.534, 0.733 } } },
    { 0.433, -0.895, -0.104 } },
};

// The triangles of a hexahedron with point ids 0..7 (faces wound outward,
// ppirayLinearCellKinds.h), each quadrilateral split along the diagonal
// through its smallest id.
std::vector<std::array<int, 3>> HexahedronTriangles()
{
  const int faces[6][4] = { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 }, { 3, 7, 6, 2 },
    { 0, 3, 2, 1 }, { 4, 5, 6, 7 } };
  std::vector<std::array<int, 3>> triangles;
  for (const auto& q : faces)
  {
    const int smallest = static_cast<int>(std::min_element(q, q + 4) - q);
    if (smallest % 2 == 0)
    {
      triangles.push_back({ q[0], q[1], q[2] });
      triangles.push_back({ q[0], q[2], q[3] });
    }
    else
    {
      triangles.push_back({ q[1], q[2], q[3] });
      triangles.push_back({ q[1], q[3], q[0] });
    }
  }
  return triangles;
}

// The shapes turned so that each one's direction is -z (the view
// direction), side by side along x; a constant point scalar.
vtkSmartPointer<vtkUnstructuredGrid> ShapesGrid(std::vector<Vec>& points)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> vtkpoints;
  vtkNew<vtkCellArray> cells;
  for (int s = 0; s < 2; ++s)
  {
    const Vec w =
      Normalized({ -Shapes[s].Direction[0], -Shapes[s].Direction[1], -Shapes[s].Direction[2] });
    const Vec u = Normalized(Cross({ 0.3, 0.5, 0.8 }, w));
    const Vec v = Cross(w, u);
    vtkIdType ids[8];
    for (int i = 0; i < 8; ++i)
    {
      const Vec& p = Shapes[s].Corners[i];
      points.push_back({ Dot(u, p) + 2.5 * s, Dot(v, p), Dot(w, p) });
      ids[i] = vtkpoints->InsertNextPoint(points.back().data());
    }
    cells->InsertNextCell(8, ids);
  }
  grid->SetPoints(vtkpoints);
  grid->SetCells(VTK_HEXAHEDRON, cells);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  scalars->SetNumberOfValues(grid->GetNumberOfPoints());
  scalars->Fill(1.0);
  grid->GetPointData()->SetScalars(scalars);
  return grid;
}

// Where the line o + t d crosses triangle (a, b, c): t, and n . d (> 0
// heading out of an outward-wound triangle); false where it misses.
bool CrossTriangle(
  const Vec& o, const Vec& d, const Vec& a, const Vec& b, const Vec& c, double& t, double& along)
{
  const Vec n = Cross(Sub(b, a), Sub(c, a));
  along = Dot(n, d);
  if (along == 0.0)
  {
    return false;
  }
  t = Dot(n, Sub(a, o)) / along;
  const Vec x = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
  return Dot(Cross(Sub(b, a), Sub(x, a)), n) >= 0.0 && Dot(Cross(Sub(c, b), Sub(x, b)), n) >= 0.0 &&
         Dot(Cross(Sub(a, c), Sub(x, c)), n) >= 0.0;
}

// The length of the line inside the cells' triangulated surfaces, and the
// number of times it crosses them.
double InsideLength(const Vec& o, const Vec& d, const std::vector<Vec>& points, int& crossings)
{
  static const auto triangles = HexahedronTriangles();
  double length = 0.0;
  crossings = 0;
  for (size_t cell = 0; 8 * cell < points.size(); ++cell)
  {
    for (const auto& tri : triangles)
    {
      double t, along;
      if (CrossTriangle(o, d, points[8 * cell + tri[0]], points[8 * cell + tri[1]],
            points[8 * cell + tri[2]], t, along))
      {
        length += along > 0.0 ? t : -t;
        ++crossings;
      }
    }
  }
  return length * std::sqrt(Dot(d, d));
}
}

int TestGPURayCastNonConvexCells(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  std::vector<Vec> points;
  auto grid = ShapesGrid(points);
  const int size = 400;
  ppiray_test::Scene scene(size, size);
  const double color[3] = { 1.0, 0.6, 0.2 };
  const double opacity = 0.9;
  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0.0, color[0], color[1], color[2]);
  colors->AddRGBPoint(2.0, color[0], color[1], color[2]);
  vtkNew<vtkPiecewiseFunction> opacities;
  opacities->AddPoint(0.0, opacity);
  opacities->AddPoint(2.0, opacity);
  scene.Property->SetColor(colors);
  scene.Property->SetScalarOpacity(opacities);
  scene.Property->SetScalarOpacityUnitDistance(0.5);
  const double tau = opacity / 0.5;

  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  double bounds[6];
  grid->GetBounds(bounds);
  const double cx = 0.5 * (bounds[0] + bounds[1]), cy = 0.5 * (bounds[2] + bounds[3]);
  scene.Show(mapper, grid, { cx, cy, bounds[5] + 10.0 }, { cx, cy, bounds[4] });
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(0.55 * (bounds[1] - bounds[0]));
  scene.Window->Render();
  const auto image = ppiray_test::ReadRGB(scene.Window);

  // Each pixel's ray through its centre (vtkRenderer::DisplayToWorld).
  std::vector<double> differences;
  int reentering = 0, nan = 0;
  for (int py = 0; py < size; ++py)
  {
    for (int px = 0; px < size; ++px)
    {
      Vec ends[2];
      for (int z = 0; z < 2; ++z)
      {
        scene.Renderer->SetDisplayPoint(px + 0.5, py + 0.5, z);
        scene.Renderer->DisplayToWorld();
        const double* p = scene.Renderer->GetWorldPoint();
        ends[z] = { p[0] / p[3], p[1] / p[3], p[2] / p[3] };
      }
      int crossings;
      const double length = InsideLength(ends[0], Sub(ends[1], ends[0]), points, crossings);
      reentering += crossings >= 4 ? 1 : 0;
      const double shade = 1.0 - std::exp(-tau * length);
      const unsigned char* rgb = &image[3 * (py * size + px)];
      const bool covered = crossings > 0 || rgb[0] + rgb[1] + rgb[2] > 0;
      for (int c = 0; c < 3 && covered; ++c)
      {
        const double difference = std::abs(255.0 * color[c] * shade - rgb[c]);
        nan += std::isnan(difference) ? 1 : 0;
        differences.push_back(difference);
      }
    }
  }
  std::sort(differences.begin(), differences.end());
  const double max = differences.empty() ? 0.0 : differences.back();
  const double p99 = differences.empty() ? 0.0 : differences[differences.size() * 99 / 100];
  const int pixels = static_cast<int>(differences.size() / 3);
  std::cout << "pixels " << pixels << ", rays leaving and re-entering a cell " << reentering
            << ", p99 " << p99 << ", max " << max << " /255, NaN " << nan << ", peels "
            << mapper->GetStatistics()->GetNumberOfPeels() << "\n";
  int errors = 0;
  // 8-bit rounding 0.5 and float ray parameters (t within 1e-6 relative).
  if (max > 1.0 || p99 > 1.0 || nan > 0)
  {
    std::cerr << "pixels differ from the exact length inside the cells\n";
    ++errors;
  }
  if (pixels < 20000 || reentering < 4000)
  {
    std::cerr << "too few pixels covered, or too few rays that leave a cell and come back\n";
    ++errors;
  }
  return errors == 0 ? 0 : 1;
}
