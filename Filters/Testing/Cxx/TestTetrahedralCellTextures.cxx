// Cell textures of a tetrahedralized box far from the origin, with a linear
// field: every gradient is exact, each face plane passes through its three
// points with the fourth inside, neighbours are mutual, boundary triangles
// wound outward; a flat tetrahedron is skipped and NaN scalars marked empty.
// The COMPACT layout's arrays against the grid (CheckCompactLayout).

#include "vtkCellArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTetrahedralCellTextures.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>

namespace
{
double LinearField(const double x[3])
{
  return 2.0 * x[0] - 3.0 * x[1] + 0.5 * x[2] + 7.0;
}

// COMPACT layout of three separate tetrahedra, positive, inverted (two ids
// swapped) and flat, against the grid itself: corner ids and flags (the
// signed volume here in double), point texels (x - origin, s; 0 for NaN),
// cell values (point data: 0, or transparent beside a NaN; cell data: the
// value, transparent for NaN); no planes or field stored.
int CheckCompactLayout()
{
  const double corners[12][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 3, 0, 0 },
    { 4, 0, 0 }, { 3, 1, 0 }, { 3, 0, 1 }, { 6, 0, 0 }, { 7, 0, 0 }, { 6, 1, 0 }, { 7, 1, 0 } };
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> pointScalars;
  for (int p = 0; p < 12; ++p)
  {
    points->InsertNextPoint(corners[p]);
    pointScalars->InsertNextValue(p == 5 ? std::numeric_limits<double>::quiet_NaN() : 0.25 * p);
  }
  grid->SetPoints(points);
  const vtkIdType cells[3][4] = { { 0, 1, 2, 3 }, { 5, 4, 6, 7 }, { 8, 9, 10, 11 } };
  for (const auto& ids : cells)
  {
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  vtkNew<vtkTetrahedralCellTextures> compact;
  compact->SetLayout(vtkTetrahedralCellTextures::COMPACT);
  int errors = 0;
  auto fail = [&errors](const std::string& what)
  {
    std::cerr << "compact layout: " << what << "\n";
    ++errors;
  };
  if (!compact->BuildGeometry(grid) || !compact->BuildField(pointScalars, false, 0))
  {
    fail("build failed");
    return errors;
  }
  if (!compact->GetFacePlanes().empty() || !compact->GetField().empty())
  {
    fail("planes or field stored");
  }
  const vtkIdType n = compact->GetNumberOfTetrahedra();
  const auto& ids = compact->GetCellCorners();
  const auto& texels = compact->GetPointTexels();
  const auto& values = compact->GetCellValues();
  if (ids.size() != static_cast<size_t>(4 * n) || values.size() != static_cast<size_t>(n) ||
      texels.size() != 4 * 12)
  {
    fail("array sizes");
    return errors;
  }
  const int flags =
    vtkTetrahedralCellTextures::InvertedCorners() | vtkTetrahedralCellTextures::FlatCorners();
  const double* origin = compact->GetOrigin();
  for (vtkIdType t = 0; t < n; ++t)
  {
    const vtkIdType cell = compact->GetCellIds()[t];
    const vtkIdType* pts = cells[cell];
    for (int v = 0; v < 4; ++v)
    {
      if ((v < 3 ? ids[4 * t + v] : ids[4 * t + 3] & ~flags) != pts[v])
      {
        fail("cell " + std::to_string(cell) + " corner " + std::to_string(v));
      }
    }
    double e[3][3];
    for (int v = 0; v < 3; ++v)
    {
      for (int i = 0; i < 3; ++i)
      {
        e[v][i] = corners[pts[v + 1]][i] - corners[pts[0]][i];
      }
    }
    const double volume6 = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    const bool inverted = (ids[4 * t + 3] & vtkTetrahedralCellTextures::InvertedCorners()) != 0;
    const bool flat = (ids[4 * t + 3] & vtkTetrahedralCellTextures::FlatCorners()) != 0;
    if (flat != (volume6 == 0.0) || (!flat && inverted != (volume6 < 0.0)))
    {
      fail("flags of cell " + std::to_string(cell));
    }
    const bool nearNaN = cell == 1;
    const float expected =
      flat || nearNaN ? vtkTetrahedralCellTextures::TransparentCellOffset() : 0.0f;
    if (values[t] != expected)
    {
      fail("point-data value of cell " + std::to_string(cell));
    }
  }
  for (int p = 0; p < 12; ++p)
  {
    for (int i = 0; i < 3; ++i)
    {
      if (std::abs(texels[4 * p + i] - (corners[p][i] - origin[i])) > 1e-6)
      {
        fail("point " + std::to_string(p) + " coordinates");
      }
    }
    if (texels[4 * p + 3] != (p == 5 ? 0.0f : static_cast<float>(0.25 * p)))
    {
      fail("point " + std::to_string(p) + " scalar");
    }
  }
  vtkNew<vtkDoubleArray> cellScalars;
  cellScalars->InsertNextValue(1.5);
  cellScalars->InsertNextValue(std::numeric_limits<double>::quiet_NaN());
  cellScalars->InsertNextValue(2.5);
  compact->BuildField(cellScalars, true, 0);
  for (vtkIdType t = 0; t < n; ++t)
  {
    const vtkIdType cell = compact->GetCellIds()[t];
    const bool flat = (ids[4 * t + 3] & vtkTetrahedralCellTextures::FlatCorners()) != 0;
    const float expected = flat || cell == 1 ? vtkTetrahedralCellTextures::TransparentCellOffset()
                                             : static_cast<float>(cellScalars->GetValue(cell));
    if (compact->GetCellValues()[t] != expected)
    {
      fail("cell-data value of cell " + std::to_string(cell));
    }
  }
  // Cell data: the points carry no scalar (the march reads the cell value).
  for (size_t p = 0; p < compact->GetPointTexels().size() / 4; ++p)
  {
    if (compact->GetPointTexels()[4 * p + 3] != 0.0f)
    {
      fail("point " + std::to_string(p) + " scalar under cell data");
    }
  }
  std::cout << "compact layout: " << n << " tetrahedra checked\n";
  return errors;
}
}

int TestTetrahedralCellTextures(int, char*[])
{
  const double offset = 1.0e6;
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 5, 6);
  image->SetOrigin(offset, -offset, offset);
  image->SetSpacing(0.5, 0.25, 1.0);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    image->GetPoint(p, x);
    double local[3] = { x[0] - offset, x[1] + offset, x[2] - offset };
    scalars->InsertNextValue(LinearField(local));
  }
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkDataSetTriangleFilter> tetrahedralize;
  tetrahedralize->SetInputData(image);
  tetrahedralize->Update();
  vtkUnstructuredGrid* grid = tetrahedralize->GetOutput();

  vtkNew<vtkTetrahedralCellTextures> cells;
  int errors = 0;
  if (!cells->BuildGeometry(grid) ||
      !cells->BuildField(grid->GetPointData()->GetScalars(), false, 0))
  {
    std::cerr << "build failed\n";
    return 1;
  }
  const vtkIdType n = cells->GetNumberOfTetrahedra();
  const double* origin = cells->GetOrigin();
  const auto& planes = cells->GetFacePlanes();
  const auto& field = cells->GetField();
  const auto& neighbors = cells->GetNeighbors();
  for (vtkIdType t = 0; t < n; ++t)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    grid->GetCellPoints(cells->GetCellIds()[t], npts, pts);
    double local[4][3];
    for (int v = 0; v < 4; ++v)
    {
      grid->GetPoint(pts[v], local[v]);
      for (int i = 0; i < 3; ++i)
      {
        local[v][i] -= origin[i];
      }
    }
    // Field: s(x) = g . (x - origin) + s0 reproduces the point scalars.
    for (int v = 0; v < 4; ++v)
    {
      const float* g = field.data() + 4 * t;
      const double s = g[0] * local[v][0] + g[1] * local[v][1] + g[2] * local[v][2] + g[3];
      if (std::abs(s - scalars->GetValue(pts[v])) > 1e-4)
      {
        std::cerr << "tet " << t << " field off at vertex " << v << ": " << s << "\n";
        ++errors;
      }
    }
    if (std::abs(field[4 * t] - 2.0) > 1e-4 || std::abs(field[4 * t + 1] + 3.0) > 1e-4)
    {
      std::cerr << "tet " << t << " gradient off\n";
      ++errors;
    }
    // Planes: face f holds the points other than f; point f is strictly inside.
    for (int f = 0; f < 4; ++f)
    {
      const float* p = planes.data() + 16 * t + 4 * f;
      for (int v = 0; v < 4; ++v)
      {
        const double d = p[0] * local[v][0] + p[1] * local[v][1] + p[2] * local[v][2] - p[3];
        if ((v != f && std::abs(d) > 1e-5) || (v == f && !(d < -1e-3)))
        {
          std::cerr << "tet " << t << " face " << f << " vertex " << v << " distance " << d << "\n";
          ++errors;
        }
      }
      // Neighbour codes 4 t' + f' point back at 4 t + f (none folded here).
      const int nb = neighbors[4 * t + f];
      if (nb < -1 || (nb >= 0 && neighbors[nb] != 4 * t + f))
      {
        std::cerr << "neighbours not mutual at " << t << " face " << f << "\n";
        ++errors;
      }
    }
  }
  // 3x4x5 voxels: boundary 2 (3*4 + 4*5 + 3*5) squares, 2 triangles each.
  if (cells->GetBoundaryFaces().size() != 188 || cells->GetBoundaryTriangles().size() != 3 * 188)
  {
    std::cerr << "boundary faces: " << cells->GetBoundaryFaces().size() << " (expected 188)\n";
    ++errors;
  }

  // A flat tetrahedron and a NaN scalar.
  vtkNew<vtkUnstructuredGrid> extra;
  extra->DeepCopy(grid);
  const vtkIdType base = extra->GetNumberOfPoints();
  const double flat[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } };
  vtkNew<vtkDoubleArray> s2;
  s2->DeepCopy(scalars);
  for (const auto& p : flat)
  {
    extra->GetPoints()->InsertNextPoint(p);
    s2->InsertNextValue(1.0);
  }
  const vtkIdType flatIds[4] = { base, base + 1, base + 2, base + 3 };
  extra->InsertNextCell(VTK_TETRA, 4, flatIds);
  s2->SetValue(0, std::numeric_limits<double>::quiet_NaN());
  extra->GetPointData()->SetScalars(s2);
  cells->BuildGeometry(extra);
  cells->BuildField(s2, false, 0);
  if (cells->GetNumberOfDegenerateTetrahedra() != 1)
  {
    std::cerr << "degenerate count " << cells->GetNumberOfDegenerateTetrahedra() << "\n";
    ++errors;
  }
  if (cells->GetNumberOfNaNScalars() < 1)
  {
    std::cerr << "NaN scalar not detected\n";
    ++errors;
  }
  for (vtkIdType t = 0; t < cells->GetNumberOfTetrahedra(); ++t)
  {
    if (std::isnan(cells->GetField()[4 * t + 3]))
    {
      std::cerr << "NaN leaked into the field of tet " << t << "\n";
      ++errors;
    }
  }
  errors += CheckCompactLayout();
  return errors == 0 ? 0 : 1;
}
