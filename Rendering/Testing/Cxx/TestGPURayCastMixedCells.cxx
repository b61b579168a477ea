// A mixed mesh rendered without tetrahedralizing it first: a block of 4x4x4
// cells, one layer each of hexahedra, wedges (two per cell), pyramids (six
// per cell, apex at the cell centre) and tetrahedra (twelve per cell),
// interior points moved so that shared quadrilaterals are not planar, point
// ids shuffled so that every diagonal configuration occurs. The mapper splits
// each cell along the diagonal through the smallest point id of each face, so
// the pieces must meet face to face:
//   - cell textures: no face left unmatched inside (exactly the 192 boundary
//     triangles of the block's 96 boundary quads), no non-manifold face, no
//     flat tetrahedron, tetrahedron volumes adding up to the block's;
//   - one peel (a gap inside would show as a second boundary layer);
//   - pixels against the CPU reference renderer given the same tetrahedra;
//   - voxels (vtkImageData through vtkAppendFilter) render exactly like the
//     same cells given as hexahedra;
//   - a baseline image.

#include "PPIRayBaseline.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "ppirayConformingTetrahedra.h"
#include "vtkAppendFilter.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkTetrahedralCellTextures.h"
#include "vtkUnstructuredGridCellAdjacency.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <numeric>
#include <vector>

namespace
{
constexpr int N = 4;                    // cells per axis
constexpr int PyramidAsTetrahedra = -1; // a cell type of this test only

// Deterministic value in [-1, 1] for an integer triple.
double Hash(int i, int j, int k)
{
  unsigned h = 2166136261u;
  for (int v : { i, j, k })
  {
    h = (h ^ static_cast<unsigned>(v + 17)) * 16777619u;
  }
  return (h % 20001u) / 10000.0 - 1.0;
}

struct MixedBlock
{
  vtkNew<vtkUnstructuredGrid> Grid;
  std::vector<vtkIdType> Permutation; // logical point -> stored point id
  std::vector<std::array<double, 3>> Logical;

  vtkIdType Add(const std::array<double, 3>& x)
  {
    this->Logical.push_back(x);
    return static_cast<vtkIdType>(this->Logical.size() - 1);
  }
  vtkIdType Corner(int i, int j, int k) const { return (k * (N + 1) + j) * (N + 1) + i; }

  MixedBlock()
  {
    const double h = 1.0 / N;
    for (int k = 0; k <= N; ++k)
      for (int j = 0; j <= N; ++j)
        for (int i = 0; i <= N; ++i)
        {
          const bool interior = i > 0 && i < N && j > 0 && j < N && k > 0 && k < N;
          const double s = interior ? 0.25 * h : 0.0;
          this->Add(
            { i * h + s * Hash(i, j, k), j * h + s * Hash(j, k, i), k * h + s * Hash(k, i, j) });
        }
    struct Cell
    {
      int Type;
      std::vector<vtkIdType> Points; // logical ids
    };
    std::vector<Cell> cells;
    for (int k = 0; k < N; ++k)
      for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i)
        {
          // Hexahedron corners in VTK order.
          const vtkIdType c[8] = { this->Corner(i, j, k), this->Corner(i + 1, j, k),
            this->Corner(i + 1, j + 1, k), this->Corner(i, j + 1, k), this->Corner(i, j, k + 1),
            this->Corner(i + 1, j, k + 1), this->Corner(i + 1, j + 1, k + 1),
            this->Corner(i, j + 1, k + 1) };
          if (k == 0)
          {
            cells.push_back({ VTK_HEXAHEDRON, { c, c + 8 } });
          }
          else if (k == 1)
          {
            // Two wedges split by the plane through the edges (x0,z0) and (x1,z1),
            // triangles facing -y and +y: every x and z face stays a whole quad.
            cells.push_back({ VTK_WEDGE, { c[0], c[1], c[5], c[3], c[2], c[6] } });
            cells.push_back({ VTK_WEDGE, { c[0], c[5], c[4], c[3], c[6], c[7] } });
          }
          else
          {
            std::array<double, 3> centre = { 0, 0, 0 };
            for (vtkIdType p : c)
              for (int a = 0; a < 3; ++a)
                centre[a] += this->Logical[p][a] / 8.0;
            const vtkIdType apex = this->Add(centre);
            const int faces[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 },
              { 3, 7, 6, 2 }, { 0, 4, 7, 3 }, { 1, 2, 6, 5 } };
            for (const auto& f : faces)
            {
              if (k == 2) // six pyramids, each base a whole face of the cell
              {
                cells.push_back({ VTK_PYRAMID, { c[f[0]], c[f[1]], c[f[2]], c[f[3]], apex } });
              }
              else // two tetrahedra per face: resolved once the ids are shuffled
              {
                cells.push_back(
                  { PyramidAsTetrahedra, { c[f[0]], c[f[1]], c[f[2]], c[f[3]], apex } });
              }
            }
          }
        }
    // Shuffle point ids (deterministic Fisher-Yates with an LCG).
    const vtkIdType n = static_cast<vtkIdType>(this->Logical.size());
    this->Permutation.resize(n);
    std::iota(this->Permutation.begin(), this->Permutation.end(), 0);
    unsigned state = 12345u;
    for (vtkIdType p = n - 1; p > 0; --p)
    {
      state = state * 1664525u + 1013904223u;
      std::swap(this->Permutation[p], this->Permutation[state % (p + 1)]);
    }
    vtkNew<vtkPoints> points;
    points->SetNumberOfPoints(n);
    vtkNew<vtkDoubleArray> scalars;
    scalars->SetName("blob");
    scalars->SetNumberOfTuples(n);
    for (vtkIdType p = 0; p < n; ++p)
    {
      const auto& x = this->Logical[p];
      points->SetPoint(this->Permutation[p], x.data());
      scalars->SetValue(this->Permutation[p], ppiray_test::Blob(x[0], x[1], x[2]));
    }
    this->Grid->SetPoints(points);
    this->Grid->GetPointData()->SetScalars(scalars);
    // The top layer's pyramids as two tetrahedra each, the base split along
    // the diagonal through its smallest stored id, as a conforming neighbour
    // splits the same quadrilateral.
    for (const Cell& cell : cells)
    {
      std::vector<vtkIdType> ids;
      for (vtkIdType p : cell.Points)
      {
        ids.push_back(this->Permutation[p]);
      }
      if (cell.Type != PyramidAsTetrahedra)
      {
        this->Grid->InsertNextCell(cell.Type, static_cast<vtkIdType>(ids.size()), ids.data());
        continue;
      }
      const vtkIdType a = ids[0], b = ids[1], c = ids[2], d = ids[3], apex = ids[4];
      const bool throughA = std::min(a, c) < std::min(b, d);
      const vtkIdType first[4] = { a, b, c, apex }, second[4] = { a, c, d, apex };
      const vtkIdType third[4] = { b, c, d, apex }, fourth[4] = { b, d, a, apex };
      this->Grid->InsertNextCell(VTK_TETRA, 4, throughA ? first : third);
      this->Grid->InsertNextCell(VTK_TETRA, 4, throughA ? second : fourth);
    }
  }
};

// The tetrahedra the mapper renders, as a grid for the reference renderer.
vtkSmartPointer<vtkUnstructuredGrid> AsTetrahedra(vtkUnstructuredGrid* grid)
{
  ppiray::TetrahedralSplit split;
  ppiray::SplitIntoTetrahedra(grid, false, split);
  auto tets = vtkSmartPointer<vtkUnstructuredGrid>::New();
  tets->SetPoints(grid->GetPoints());
  tets->GetPointData()->ShallowCopy(grid->GetPointData());
  for (size_t t = 0; t < split.CellIds.size(); ++t)
  {
    tets->InsertNextCell(VTK_TETRA, 4, split.Tets.data() + 4 * t);
  }
  return tets;
}

int Fail(const char* what)
{
  std::cerr << "FAILED: " << what << "\n";
  return 1;
}
}

int TestGPURayCastMixedCells(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  MixedBlock block;
  vtkUnstructuredGrid* grid = block.Grid;
  int errors = 0;

  // Conformity, from the cell textures.
  vtkNew<vtkTetrahedralCellTextures> textures;
  textures->BuildGeometry(grid);
  const vtkIdType expectedTets = N * N * (6 + 2 * 3 + 6 * 2 + 12);
  std::cout << "cells " << grid->GetNumberOfCells() << ", split "
            << textures->GetNumberOfSplitCells() << ", tetrahedra "
            << textures->GetNumberOfTetrahedra() << ", boundary triangles "
            << textures->GetBoundaryFaces().size() << ", degenerate "
            << textures->GetNumberOfDegenerateTetrahedra() << ", non-manifold "
            << textures->GetNumberOfNonManifoldFaces() << "\n";
  if (textures->GetNumberOfTetrahedra() != expectedTets ||
      textures->GetNumberOfSplitCells() != N * N * (1 + 2 + 6))
  {
    errors += Fail("unexpected number of tetrahedra or split cells");
  }
  if (textures->GetBoundaryFaces().size() != 6u * N * N * 2 ||
      textures->GetNumberOfNonManifoldFaces() != 0 ||
      textures->GetNumberOfDegenerateTetrahedra() != 0)
  {
    errors += Fail("the split does not conform: faces left unmatched inside the block");
  }
  ppiray::TetrahedralSplit split;
  ppiray::SplitIntoTetrahedra(grid, false, split);
  double volume = 0;
  for (size_t t = 0; t < split.CellIds.size(); ++t)
  {
    double p[4][3];
    for (int v = 0; v < 4; ++v)
    {
      grid->GetPoint(split.Tets[4 * t + v], p[v]);
    }
    volume += std::abs(vtkUnstructuredGridCellAdjacency::SignedVolume6(p[0], p[1], p[2], p[3])) / 6;
  }
  std::cout << "volume of the tetrahedra " << volume << "\n";
  if (std::abs(volume - 1.0) > 1e-12)
  {
    errors += Fail("tetrahedra overlap or leave holes (volume is not the block's)");
  }

  // Rendering.
  ppiray_test::Scene scene(300, 300);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.15);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  mapper->SetHexahedronModeToSubdivide(); // the split path, also for the voxels below
  scene.Show(mapper, grid, { 2.0, 1.3, 2.4 }, { 0.5, 0.5, 0.5 });
  scene.Window->Render();
  std::cout << "peels " << mapper->GetNumberOfPeels() << "\n";
  if (mapper->GetNumberOfPeels() != 1)
  {
    errors += Fail("a convex block needed more than one peel");
  }
  const auto image = ppiray_test::ReadRGB(scene.Window);
  auto tets = AsTetrahedra(grid);
  const auto check =
    ppiray_test::CheckPixels(scene.Renderer, tets, scene.Property, image, 300, 300);
  std::cout << "pixels checked " << check.Pixels << ", max difference " << check.MaxDifference
            << "/255 against the reference on the same tetrahedra\n";
  // 8-bit rounding 0.5, float and the 0.1/255 transfer-function tolerance
  if (check.MaxDifference > 1.0)
  {
    errors += Fail("pixels differ from the reference renderer");
  }
  errors += ppiray_test::ExpectCoverage(check, 5000);
  const int result = ppiray_test::BaselineTest(argc, argv, scene.Window);

  // Voxels from image data against the same cells as hexahedra.
  const auto block3d = ppiray_test::BlobVoxelBlock(N);
  vtkUnstructuredGrid* voxels = block3d.Voxels;
  vtkUnstructuredGrid* hexahedra = block3d.Hexahedra;
  if (voxels->GetCellType(0) != VTK_VOXEL)
  {
    errors += Fail("vtkAppendFilter did not produce voxels");
  }
  mapper->SetInputData(voxels);
  scene.Window->Render();
  const auto voxelImage = ppiray_test::ReadRGB(scene.Window);
  const vtkIdType voxelTets = mapper->GetNumberOfTetrahedra();
  mapper->SetInputData(hexahedra);
  scene.Window->Render();
  const auto hexImage = ppiray_test::ReadRGB(scene.Window);
  const auto same = ppiray_test::Compare(voxelImage, hexImage);
  std::cout << "voxels: " << voxelTets << " tetrahedra, image against hexahedra max " << same.Max
            << "/255\n";
  if (voxelTets != 6 * N * N * N || same.Max > 0 ||
      ppiray_test::Compare(voxelImage, image).Max == 0)
  {
    errors += Fail("voxels do not render as the same hexahedra");
  }
  return (errors == 0 && result == 0) ? 0 : 1;
}
