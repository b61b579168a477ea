// Quadratic and higher-order cells other than ten-node tetrahedra (20- and
// 27-node hexahedra, 15-node wedges, 13-node pyramids, Lagrange hexahedra
// and tetrahedra of order 3, in blocks that share every face), refined into
// ten-node tetrahedra with VTK's map and field at their nodes
// (ppirayHigherOrderPieces.h), against the CPU reference, which integrates
// each cell through VTK's own interpolation (vtkCell::EvaluatePosition,
// InterpolateFunctions):
//  1. a field quadratic in space, unrefined: exact (the pyramids, whose
//     shape functions are rational, with one level);
//  2. a field that is no polynomial, sampled at the nodes, one level: VTK's
//     interpolation of it within the bounds below;
//  3. each level closer to it, through the corners far off;
//  4. curved cells (the nodes moved by a smooth deformation): refined until
//     the pieces are within 0.4 % of an edge of straight;
//  5. a NaN at a node that is not a corner: the cells on it through their
//     corners (counted), the reference applying the same rule; at a corner:
//     those cells empty;
//  6. kinds side by side, sharing quadratic faces: one peel.

#include "PPIRayExpectNative.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkHexahedralCellTextures.h"
#include "vtkLagrangeHexahedron.h"
#include "vtkLagrangeTetra.h"
#include "vtkPointData.h"
#include "vtkQuadraticHexahedron.h"
#include "vtkQuadraticPyramid.h"
#include "vtkQuadraticWedge.h"
#include "vtkSmartPointer.h"
#include "vtkTriQuadraticHexahedron.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
constexpr int Size = 150;
using Field = ppiray_test::Field;
using Vec = std::array<double, 3>;
// The map of a cell's parametric coordinates into a unit cube.
using CellMap = std::function<Vec(const double p[3])>;

int Fail(const std::string& what)
{
  std::cerr << "FAILED: " << what << "\n";
  return 1;
}

// The parametric coordinates of the nodes of a cell type with n points.
std::vector<double> NodeParametricCoordinates(int type, int n)
{
  vtkSmartPointer<vtkCell> cell;
  switch (type)
  {
    case VTK_QUADRATIC_HEXAHEDRON:
      cell = vtkSmartPointer<vtkQuadraticHexahedron>::New();
      break;
    case VTK_TRIQUADRATIC_HEXAHEDRON:
      cell = vtkSmartPointer<vtkTriQuadraticHexahedron>::New();
      break;
    case VTK_QUADRATIC_WEDGE:
      cell = vtkSmartPointer<vtkQuadraticWedge>::New();
      break;
    case VTK_QUADRATIC_PYRAMID:
      cell = vtkSmartPointer<vtkQuadraticPyramid>::New();
      break;
    case VTK_LAGRANGE_HEXAHEDRON:
    {
      auto lagrange = vtkSmartPointer<vtkLagrangeHexahedron>::New();
      lagrange->GetPointIds()->SetNumberOfIds(n);
      lagrange->GetPoints()->SetNumberOfPoints(n);
      lagrange->SetUniformOrderFromNumPoints(n);
      cell = lagrange;
      break;
    }
    default:
    {
      auto lagrange = vtkSmartPointer<vtkLagrangeTetra>::New();
      lagrange->GetPointIds()->SetNumberOfIds(n);
      lagrange->GetPoints()->SetNumberOfPoints(n);
      lagrange->Initialize();
      cell = lagrange;
      break;
    }
  }
  const double* p = cell->GetParametricCoords();
  return std::vector<double>(p, p + 3 * n);
}

// Cells of one type filling the unit cubes of an n^3 block: a hexahedron per
// cube, two wedges, six pyramids (apex at the centre) or six tetrahedra
// (around the diagonal 0-7).
std::vector<CellMap> CubeCells(int type, const Vec& o, double h)
{
  std::vector<CellMap> maps;
  auto at = [o, h](double x, double y, double z) {
    return Vec{ o[0] + h * x, o[1] + h * y, o[2] + h * z };
  };
  if (type == VTK_QUADRATIC_HEXAHEDRON || type == VTK_TRIQUADRATIC_HEXAHEDRON ||
      type == VTK_LAGRANGE_HEXAHEDRON)
  {
    maps.push_back([at](const double p[3]) { return at(p[0], p[1], p[2]); });
  }
  else if (type == VTK_QUADRATIC_WEDGE)
  {
    maps.push_back([at](const double p[3]) { return at(p[0], p[1], p[2]); });
    maps.push_back([at](const double p[3]) { return at(1 - p[0], 1 - p[1], p[2]); });
  }
  else if (type == VTK_QUADRATIC_PYRAMID)
  {
    // Base corners of each face wound so that the centre lies above it.
    const int faces[6][4][3] = { { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 1, 0, 0 } },
      { { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } },
      { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 1 }, { 0, 0, 1 } },
      { { 0, 1, 0 }, { 0, 1, 1 }, { 1, 1, 1 }, { 1, 1, 0 } },
      { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 1 }, { 0, 1, 0 } },
      { { 1, 0, 0 }, { 1, 1, 0 }, { 1, 1, 1 }, { 1, 0, 1 } } };
    for (const auto& f : faces)
    {
      maps.push_back(
        [at, f](const double p[3])
        {
          const double r = p[0], s = p[1], t = p[2];
          const double w[4] = { (1 - r) * (1 - s), r * (1 - s), r * s, (1 - r) * s };
          Vec x = { 0.5 * t, 0.5 * t, 0.5 * t };
          for (int i = 0; i < 4; ++i)
          {
            for (int k = 0; k < 3; ++k)
            {
              x[k] += (1 - t) * w[i] * f[i][k];
            }
          }
          return at(x[0], x[1], x[2]);
        });
    }
  }
  else
  {
    const int axes[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
      { 2, 1, 0 } };
    for (const auto& a : axes)
    {
      maps.push_back(
        [at, a](const double p[3])
        {
          // Corners 0, e_a0, e_a0 + e_a1, (1, 1, 1).
          double x[3] = { 0, 0, 0 };
          x[a[0]] += p[0] + p[1] + p[2];
          x[a[1]] += p[1] + p[2];
          x[a[2]] += p[2];
          return at(x[0], x[1], x[2]);
        });
    }
  }
  return maps;
}

// Cells of `types` (one per x slab of cubes; n x n cubes each) with `points`
// nodes, points shared by position, then moved by ppiray_test::Deform(bend);
// `f` at the nodes.
vtkSmartPointer<vtkUnstructuredGrid> Block(
  const std::vector<std::pair<int, int>>& types, int n, double bend, const Field& f)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::map<std::array<long, 3>, vtkIdType> ids;
  const double h = 1.0 / n;
  for (size_t slab = 0; slab < types.size(); ++slab)
  {
    const int type = types[slab].first, count = types[slab].second;
    const std::vector<double> pcoords = NodeParametricCoordinates(type, count);
    for (int k = 0; k < n; ++k)
    {
      for (int j = 0; j < n; ++j)
      {
        const Vec o = { h * slab, h * j, h * k };
        for (const CellMap& map : CubeCells(type, o, h))
        {
          std::vector<vtkIdType> cell(count);
          for (int i = 0; i < count; ++i)
          {
            const Vec x = map(pcoords.data() + 3 * i);
            const std::array<long, 3> key = { std::lround(x[0] * 1200 * n),
              std::lround(x[1] * 1200 * n), std::lround(x[2] * 1200 * n) };
            auto it = ids.find(key);
            if (it == ids.end())
            {
              Vec y = x;
              ppiray_test::Deform(bend, y.data());
              it = ids.emplace(key, points->InsertNextPoint(y.data())).first;
            }
            cell[i] = it->second;
          }
          grid->InsertNextCell(type, count, cell.data());
        }
      }
    }
  }
  grid->SetPoints(points);
  ppiray_test::PointField(grid, f);
  return grid;
}

struct Kind
{
  const char* Name;
  int Type;
  int Points;
  bool Wavy; // checked with the wavy field too
};

// The first point of `grid` within 0.2 of the block's centre line that is
// node `node` of some cell, and the number of cells that hold it.
std::pair<vtkIdType, int> InteriorNode(vtkUnstructuredGrid* grid, int node)
{
  vtkIdType id = -1;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells() && id < 0; ++c)
  {
    double x[3];
    const vtkIdType candidate = grid->GetCell(c)->GetPointId(node);
    grid->GetPoint(candidate, x);
    if (std::abs(x[1] - 0.5) < 0.2 && std::abs(x[2] - 0.5) < 0.2 && x[0] > 0.1 && x[0] < 0.9)
    {
      id = candidate;
    }
  }
  int around = 0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    around += grid->GetCell(c)->GetPointIds()->IsId(id) >= 0 ? 1 : 0;
  }
  return { id, around };
}
}

int TestGPURayCastHigherOrderCells(int, char*[])
{
  using Mapper = vtkUnstructuredGridGPURayCastMapper;
  int errors = 0;
  const Field quadratic = [](double x, double y, double z)
  { return 0.15 + 0.3 * x + 0.5 * y * y - 0.4 * x * z + 0.6 * z * z + 0.2 * x * y; };
  const Field wavy = [](double x, double y, double z)
  { return 0.65 + 0.55 * std::sin(5 * x + 0.3) * std::cos(4 * y) * std::sin(3 * z + 0.5); };
  // (The order-3 Lagrange hexahedra under the wavy field, p99 0.56, max 0.78,
  // are left out: the reference takes 30 s on them.)
  const Kind kinds[] = { { "20-node hexahedra", VTK_QUADRATIC_HEXAHEDRON, 20, true },
    { "27-node hexahedra", VTK_TRIQUADRATIC_HEXAHEDRON, 27, true },
    { "15-node wedges", VTK_QUADRATIC_WEDGE, 15, true },
    { "13-node pyramids", VTK_QUADRATIC_PYRAMID, 13, true },
    { "Lagrange hexahedra of order 3", VTK_LAGRANGE_HEXAHEDRON, 64, false },
    { "Lagrange tetrahedra of order 3", VTK_LAGRANGE_TETRAHEDRON, 20, true } };
  const auto slabs = [](const Kind& kind) {
    return std::vector<std::pair<int, int>>(3, { kind.Type, kind.Points });
  };
  const auto accurate = Mapper::HEXAHEDRON_ACCURATE;

  ppiray_test::Scene scene(Size, Size);
  vtkNew<Mapper> mapper;
  auto first = Block(slabs(kinds[0]), 3, 0.0, quadratic);
  scene.Show(mapper, first, { 2.1, 1.4, 2.5 }, { 0.5, 0.5, 0.5 });

  // 1. A field quadratic in space, unrefined: exact. VTK's 13-node pyramid
  // does not reproduce it (its shape functions are rational in space, and
  // its field along a ray is no polynomial): one level, within the rounding.
  // 2. The wavy field, one level: what is left is the pieces' quadratic
  // interpolation of VTK's field, about an eighth of the unrefined error
  // (measured at most p99 0.65, max 1.34, the pyramids).
  for (const Kind& kind : kinds)
  {
    const bool pyramid = kind.Type == VTK_QUADRATIC_PYRAMID;
    mapper->SetNonlinearSubdivisionLevel(pyramid ? 1 : 0);
    ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.15);
    errors += ppiray_test::ExpectNative((std::string(kind.Name) + ", quadratic field").c_str(),
      scene, mapper, Block(slabs(kind), 3, 0.0, quadratic), accurate, Size, 1.0, 1.0);
    if (kind.Wavy)
    {
      mapper->SetNonlinearSubdivisionLevel(1);
      ppiray_test::SmoothTransferFunction(scene.Property, 0.1, 1.2, 0.4, 0.5);
      errors += ppiray_test::ExpectNative((std::string(kind.Name) + ", wavy field").c_str(), scene,
        mapper, Block(slabs(kind), 3, 0.0, wavy), accurate, Size, 1.0, 1.5);
    }
  }

  // 3. Each level closer to VTK's field; through the corners far off.
  ppiray_test::PixelCheck levels[2], corners;
  auto hexahedra = Block(slabs(kinds[0]), 3, 0.0, wavy);
  for (int level = 0; level <= 1; ++level)
  {
    mapper->SetNonlinearSubdivisionLevel(level);
    errors += ppiray_test::ExpectNative(
      ("20-node hexahedra, wavy field, level " + std::to_string(level)).c_str(), scene, mapper,
      hexahedra, accurate, Size, 255.0, 255.0, &levels[level]);
  }
  errors += ppiray_test::ExpectNative("20-node hexahedra, wavy field, through the corners", scene,
    mapper, hexahedra, Mapper::HEXAHEDRON_SUBDIVIDE, Size, 255.0, 255.0, &corners);
  if (!(levels[0].P99 > levels[1].P99 + 0.5 &&
        levels[0].MaxDifference > levels[1].MaxDifference + 1.0 &&
        corners.P99 > levels[0].P99 + 1.0))
  {
    errors += Fail("a level does not bring the image closer to VTK's field");
  }

  // 4. Curved cells (nodes moved by up to 0.06): refined until the pieces are
  // within 0.4 % of an edge of straight.
  vtkNew<vtkHexahedralCellTextures> textures;
  for (const Kind& kind : { kinds[0], kinds[2] })
  {
    mapper->SetNonlinearSubdivisionLevel(1);
    auto curved = Block(slabs(kind), 3, 0.06, wavy);
    textures->SetMinimumRefinementLevel(1);
    textures->BuildGeometry(curved);
    std::cout << kind.Name << ", curved: refined " << textures->GetRefinementLevels()
              << " levels into " << textures->GetNumberOfHexahedra() << " pieces\n";
    if (textures->GetRefinementLevels() < 2)
    {
      errors += Fail("curved cells not refined further");
    }
    errors += ppiray_test::ExpectNative((std::string(kind.Name) + ", curved").c_str(), scene,
      mapper, curved, accurate, Size, 1.0, 1.5);
  }

  // 5. A NaN at an interior mid-edge node: the cells on it through their
  // corners, counted, as the reference does; at a corner: those cells empty.
  for (const int node : { 8, 0 })
  {
    auto withNaN = Block(slabs(kinds[0]), 3, 0.0, wavy);
    const auto [id, around] = InteriorNode(withNaN, node);
    withNaN->GetPointData()->GetScalars()->SetComponent(id, 0, std::nan(""));
    errors += ppiray_test::ExpectNative(node ? "NaN at a mid-edge node" : "NaN at a corner", scene,
      mapper, withNaN, accurate, Size, 1.0, 1.5);
    textures->BuildGeometry(withNaN);
    textures->BuildField(withNaN->GetPointData()->GetScalars(), false, 0);
    const vtkIdType linearized = textures->GetNumberOfLinearizedCells();
    const vtkIdType empty = textures->GetNumberOfNaNScalars();
    std::cout << "through their corners " << linearized << ", empty " << empty
              << " (cells on the node: " << around << ")\n";
    if (around < 2 || linearized != (node ? around : 0) || (empty > 0) != (node == 0))
    {
      errors += Fail("the cells on a NaN node are not the ones through their corners or empty");
    }
  }

  // 6. Kinds side by side, sharing quadratic faces: one peel.
  mapper->SetNonlinearSubdivisionLevel(1);
  auto mixed = Block({ { VTK_QUADRATIC_HEXAHEDRON, 20 }, { VTK_QUADRATIC_WEDGE, 15 },
                       { VTK_QUADRATIC_PYRAMID, 13 }, { VTK_QUADRATIC_HEXAHEDRON, 20 } },
    3, 0.0, wavy);
  errors +=
    ppiray_test::ExpectNative("mixed kinds", scene, mapper, mixed, accurate, Size, 1.0, 1.5);
  return errors == 0 ? 0 : 1;
}
