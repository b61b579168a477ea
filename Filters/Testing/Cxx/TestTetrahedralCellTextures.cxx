// Cell textures of a tetrahedralized box far from the origin, with a linear
// field: every gradient is exact, each face plane passes through its three
// points with the fourth inside, neighbours are mutual, boundary triangles
// wound outward; a flat tetrahedron is skipped and NaN scalars marked empty.

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

namespace
{
double LinearField(const double x[3])
{
  return 2.0 * x[0] - 3.0 * x[1] + 0.5 * x[2] + 7.0;
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
  return errors == 0 ? 0 : 1;
}
