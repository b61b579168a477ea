// Boundary faces of a tetrahedralized box: the right count, wound outward
// (divergence theorem gives the box volume), owning cell and local face
// consistent with the cell's points, also with half the tetrahedra inverted.

#include "ppirayConformingTetrahedra.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridBoundaryFaces.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <cmath>
#include <iostream>

namespace
{
// Volume enclosed by a closed, consistently wound triangle surface:
// V = (1/6) sum over triangles of p0 . (p1 x p2).
double EnclosedVolume(vtkPolyData* surface)
{
  double volume = 0.0;
  vtkIdType npts;
  const vtkIdType* pts;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    double p[3][3];
    for (int v = 0; v < 3; ++v)
    {
      surface->GetPoint(pts[v], p[v]);
    }
    const double cross[3] = { p[1][1] * p[2][2] - p[1][2] * p[2][1],
      p[1][2] * p[2][0] - p[1][0] * p[2][2], p[1][0] * p[2][1] - p[1][1] * p[2][0] };
    volume += (p[0][0] * cross[0] + p[0][1] * cross[1] + p[0][2] * cross[2]) / 6.0;
  }
  return volume;
}

int Check(vtkUnstructuredGrid* grid, const char* label)
{
  vtkNew<vtkUnstructuredGridBoundaryFaces> boundary;
  boundary->SetInputData(grid);
  boundary->Update();
  vtkPolyData* surface = boundary->GetOutput();
  int errors = 0;
  // 3x3x3 voxels: 6 sides x 9 squares x 2 triangles.
  if (surface->GetNumberOfPolys() != 108)
  {
    std::cerr << label << ": expected 108 boundary triangles, got " << surface->GetNumberOfPolys()
              << "\n";
    ++errors;
  }
  const double volume = EnclosedVolume(surface);
  if (std::abs(volume - 27.0) > 1e-9)
  {
    std::cerr << label << ": boundary encloses volume " << volume << ", expected +27\n";
    ++errors;
  }
  auto* owner = vtkIdTypeArray::SafeDownCast(surface->GetCellData()->GetArray("CellId"));
  auto* face = vtkUnsignedCharArray::SafeDownCast(surface->GetCellData()->GetArray("FaceIndex"));
  if (!owner || !face)
  {
    std::cerr << label << ": missing CellId or FaceIndex\n";
    return errors + 1;
  }
  vtkIdType npts;
  const vtkIdType* pts;
  vtkIdType k = 0;
  vtkCellArray* polys = surface->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts); ++k)
  {
    vtkIdType cellSize;
    const vtkIdType* cellPoints;
    grid->GetCellPoints(owner->GetValue(k), cellSize, cellPoints);
    const int f = face->GetValue(k);
    for (int v = 0; v < 3; ++v)
    {
      bool found = false;
      for (int c = 0; c < 4; ++c)
      {
        found = found || (c != f && cellPoints[c] == pts[v]);
      }
      if (!found)
      {
        std::cerr << label << ": triangle " << k << " is not face " << f << " of its cell\n";
        ++errors;
        break;
      }
    }
  }
  return errors;
}
}

int TestUnstructuredGridBoundaryFaces(int, char*[])
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 4);
  vtkNew<vtkDataSetTriangleFilter> tetrahedralize;
  tetrahedralize->SetInputData(image);
  tetrahedralize->Update();
  vtkUnstructuredGrid* grid = tetrahedralize->GetOutput();

  int errors = Check(grid, "box");

  // Invert every other tetrahedron (swap two points): still wound outward.
  vtkNew<vtkUnstructuredGrid> inverted;
  inverted->DeepCopy(grid);
  vtkNew<vtkCellArray> cells;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    grid->GetCellPoints(c, npts, pts);
    vtkIdType p[4] = { pts[0], pts[1], pts[2], pts[3] };
    if (c % 2)
    {
      std::swap(p[1], p[2]);
    }
    cells->InsertNextCell(4, p);
  }
  inverted->SetCells(VTK_TETRA, cells);
  errors += Check(inverted, "inverted");

  // Adjacency is symmetric: t's neighbour through f has t as a neighbour.
  std::vector<vtkIdType> tets, ids, unsupported;
  ppiray::ExtractTetrahedra(grid, tets, ids, unsupported);
  vtkNew<vtkUnstructuredGridCellAdjacency> adjacency;
  adjacency->Build(grid->GetNumberOfPoints(), tets.data(), static_cast<vtkIdType>(ids.size()));
  const auto& neighbors = adjacency->GetNeighbors();
  for (size_t t = 0; t < ids.size(); ++t)
  {
    for (int f = 0; f < 4; ++f)
    {
      const vtkIdType n = neighbors[4 * t + f];
      if (n >= 0 && neighbors[4 * n] != vtkIdType(t) && neighbors[4 * n + 1] != vtkIdType(t) &&
          neighbors[4 * n + 2] != vtkIdType(t) && neighbors[4 * n + 3] != vtkIdType(t))
      {
        std::cerr << "adjacency not symmetric at tetrahedron " << t << "\n";
        ++errors;
      }
    }
  }
  if (adjacency->GetNumberOfBoundaryFaces() != 108 || adjacency->GetNumberOfNonManifoldFaces())
  {
    std::cerr << "adjacency: " << adjacency->GetNumberOfBoundaryFaces()
              << " boundary faces (expected 108)\n";
    ++errors;
  }
  return errors == 0 ? 0 : 1;
}
