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
#include "PPIRayMixedBlock.h"
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
constexpr int N = 4; // cells per axis

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
  ppiray_test::MixedBlock block(N);
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
  std::cout << "peels " << mapper->GetStatistics()->GetNumberOfPeels() << "\n";
  if (mapper->GetStatistics()->GetNumberOfPeels() != 1)
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
  const vtkIdType voxelTets = mapper->GetStatistics()->GetNumberOfTetrahedra();
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
