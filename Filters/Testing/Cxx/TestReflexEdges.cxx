// Boundary triangles facing each other across reflex edges
// (ppirayReflexEdges.h), on voxel blocks split into tetrahedra
// (vtkDataSetTriangleFilter) whose boundary vtkTetrahedralCellTextures
// builds:
//  1. a 2x2x2 block (convex): no partners;
//  2. an L (the block without the column x > 1, y > 1): the inner corner
//     line x = y = 1 is reflex (90 degrees empty): its 2 segments each join
//     a triangle of the face x = 1 to one of the face y = 1, both ways;
//  3. two voxels meeting along one edge (x = y = 1, z in [0, 1]): two empty
//     wedges of 90 degrees, each joining a triangle of one voxel to one of
//     the other, both ways (4 triangles);
//  4. a 2x1x1 block with a crack: the two voxels' facing sides apart by
//     1e-3 except along one edge, where they meet: a zero wedge, joined.
// Also: each face with a partner gets a re-entry list in the neighbour codes.

#include "ppirayReflexEdges.h"
#include "vtkCellArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTetrahedralCellTextures.h"
#include "vtkUnstructuredGrid.h"

#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// Voxels (i, j, k) of an n^3 unit lattice where keep(i, j, k), in tetrahedra;
// `move` may displace the points.
vtkNew<vtkUnstructuredGrid> Voxels(const int n[3], const std::function<bool(int, int, int)>& keep,
  const std::function<void(double*)>& move = nullptr)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n[0] + 1, n[1] + 1, n[2] + 1);
  vtkNew<vtkDataSetTriangleFilter> split;
  split->SetInputData(image);
  split->Update();
  vtkUnstructuredGrid* all = split->GetOutput();
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->DeepCopy(all->GetPoints());
  for (vtkIdType p = 0; move && p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    move(x);
    points->SetPoint(p, x);
  }
  grid->SetPoints(points);
  grid->AllocateEstimate(all->GetNumberOfCells(), 4);
  for (vtkIdType c = 0; c < all->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    all->GetCellPoints(c, npts, pts);
    double centre[3] = { 0, 0, 0 };
    for (vtkIdType v = 0; v < npts; ++v)
    {
      for (int a = 0; a < 3; ++a)
      {
        centre[a] += all->GetPoint(pts[v])[a] / npts;
      }
    }
    if (keep(static_cast<int>(centre[0]), static_cast<int>(centre[1]), static_cast<int>(centre[2])))
    {
      grid->InsertNextCell(VTK_TETRA, npts, pts);
    }
  }
  return grid;
}
}

int TestReflexEdges(int, char*[])
{
  int errors = 0;
  const int two[3] = { 2, 2, 2 }, flat[3] = { 2, 2, 1 }, pair[3] = { 2, 1, 1 };
  std::vector<std::pair<std::string, int>> names; // and the triangles with a partner
  std::vector<vtkSmartPointer<vtkUnstructuredGrid>> grids;
  auto add = [&](const std::string& name, vtkUnstructuredGrid* grid, int expected)
  {
    names.emplace_back(name, expected);
    grids.emplace_back(grid);
  };
  auto block = Voxels(two, [](int, int, int) { return true; });
  add("2x2x2 block", block, 0);
  auto l = Voxels(two, [](int i, int j, int) { return !(i == 1 && j == 1); });
  add("L", l, 4);
  auto touching = Voxels(flat, [](int i, int j, int) { return i == j; });
  add("two voxels along an edge", touching, 4);
  // The crack: the right voxel from its own points, those with x = 1 and
  // y > 0 moved right by 1e-3; along y = 0 it takes the left voxel's points.
  auto left = Voxels(pair, [](int i, int, int) { return i == 0; });
  auto right = Voxels(
    pair, [](int i, int, int) { return i == 1; },
    [](double* x) { x[0] += (x[0] == 1.0 && x[1] > 0.0) ? 1e-3 : 0.0; });
  vtkNew<vtkUnstructuredGrid> crack;
  {
    vtkNew<vtkPoints> points;
    const vtkIdType offset = left->GetNumberOfPoints();
    for (vtkIdType p = 0; p < offset; ++p)
    {
      points->InsertNextPoint(left->GetPoint(p));
    }
    for (vtkIdType p = 0; p < right->GetNumberOfPoints(); ++p)
    {
      points->InsertNextPoint(right->GetPoint(p));
    }
    crack->SetPoints(points);
    crack->AllocateEstimate(12, 4);
    for (vtkIdType c = 0; c < left->GetNumberOfCells(); ++c)
    {
      crack->InsertNextCell(VTK_TETRA, left->GetCell(c)->GetPointIds());
    }
    for (vtkIdType c = 0; c < right->GetNumberOfCells(); ++c)
    {
      vtkIdType ids[4];
      for (int v = 0; v < 4; ++v)
      {
        // The edge y = 0, x = 1 is where the sides meet: the left voxel's points there.
        const vtkIdType id = right->GetCell(c)->GetPointId(v);
        const double* x = right->GetPoint(id);
        ids[v] =
          (x[0] == 1.0 && x[1] == 0.0) ? left->FindPoint(const_cast<double*>(x)) : id + offset;
      }
      crack->InsertNextCell(VTK_TETRA, 4, ids);
    }
  }
  add("crack closed along one edge", crack, 2);

  for (size_t c = 0; c < grids.size(); ++c)
  {
    vtkNew<vtkTetrahedralCellTextures> cells;
    cells->BuildGeometry(grids[c]);
    const std::vector<int> partners =
      ppiray::ReflexEdgePartners(cells->GetBoundaryPoints(), cells->GetBoundaryTriangles());
    int with = 0;
    bool mutual = true;
    const size_t n = partners.size() / 3;
    for (size_t k = 0; k < n; ++k)
    {
      bool any = false;
      for (int e = 0; e < 3; ++e)
      {
        const int p = partners[3 * k + e];
        if (p < 0)
        {
          continue;
        }
        any = true;
        bool back = false;
        for (int f = 0; f < 3; ++f)
        {
          back = back || partners[3 * p + f] == static_cast<int>(k);
        }
        mutual = mutual && back;
      }
      with += any ? 1 : 0;
    }
    std::cout << names[c].first << ": " << n << " boundary triangles, " << with
              << " with a partner across a reflex edge, " << cells->GetNumberOfReentryFaces()
              << " re-entry faces" << (mutual ? "" : ", NOT MUTUAL") << "\n";
    const int expected = names[c].second;
    if (with != expected || !mutual || cells->GetNumberOfReentryFaces() != with)
    {
      std::cerr << "FAILED: " << names[c].first << "\n";
      ++errors;
    }
  }
  return errors == 0 ? 0 : 1;
}
