/**
 * @file   PPIRayMixedBlock.h
 * @brief  a test mesh of every linear kind: hexahedra, wedges, pyramids, tetrahedra
 *
 * A unit block of n x n x n cells in four layers of z: hexahedra, wedges (two
 * per cell, split by the plane through the edges (x0, z0) and (x1, z1),
 * triangles facing -y and +y: every x and z face stays a whole quad),
 * pyramids (six per cell, apex at the cell centre, each base a whole face of
 * the cell) and tetrahedra (twelve per cell: each face's pyramid as two,
 * split along the diagonal through the base's smallest stored id, as a
 * conforming neighbour splits the same quadrilateral). Interior points moved
 * by up to `perturbation` of a cell (0: every hexahedron a cube, every wedge
 * a right prism), point ids shuffled so that every diagonal configuration
 * occurs, the point field ppiray_test::Blob ("blob").
 */
#ifndef PPIRayMixedBlock_h
#define PPIRayMixedBlock_h

#include "PPIRayTestScenes.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

namespace ppiray_test
{
// Deterministic value in [-1, 1] for an integer triple.
inline double MixedBlockHash(int i, int j, int k)
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
  int N;

  vtkIdType Add(const std::array<double, 3>& x)
  {
    this->Logical.push_back(x);
    return static_cast<vtkIdType>(this->Logical.size() - 1);
  }
  vtkIdType Corner(int i, int j, int k) const { return (k * (N + 1) + j) * (N + 1) + i; }

  explicit MixedBlock(int cellsPerAxis = 4, double perturbation = 0.25);
};

inline MixedBlock::MixedBlock(int cellsPerAxis, double perturbation)
  : N(cellsPerAxis)
{
  constexpr int PyramidAsTetrahedra = -1; // a cell type of this block only
  const double h = 1.0 / N;
  for (int k = 0; k <= N; ++k)
    for (int j = 0; j <= N; ++j)
      for (int i = 0; i <= N; ++i)
      {
        const bool interior = i > 0 && i < N && j > 0 && j < N && k > 0 && k < N;
        const double s = interior ? perturbation * h : 0.0;
        this->Add({ i * h + s * MixedBlockHash(i, j, k), j * h + s * MixedBlockHash(j, k, i),
          k * h + s * MixedBlockHash(k, i, j) });
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
          const int faces[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 3, 7, 6, 2 },
            { 0, 4, 7, 3 }, { 1, 2, 6, 5 } };
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
}

#endif
