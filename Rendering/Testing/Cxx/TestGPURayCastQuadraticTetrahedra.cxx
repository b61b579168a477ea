// Ten-node quadratic tetrahedra with their own field (ppirayQuadraticTetrahedra.h),
// against the CPU reference, which integrates each cell through VTK's own
// interpolation (vtkQuadraticTetra::EvaluatePosition, its nodes' faces):
//  0. the frame polynomial (FrameCoefficients) against
//     vtkQuadraticTetra::InterpolationFunctions at random parametric points;
//  1. a block of straight-edged quadratic tetrahedra (half of them
//     left-handed: the Kuhn split alternates) under a quadratic field, which
//     VTK's interpolation reproduces exactly: every cell native, one peel,
//     within the suite's bound; the same cells through their corners
//     (HEXAHEDRON_SUBDIVIDE: split as linear tetrahedra) are further off;
//  2. a field that is no polynomial (sampled at the nodes): VTK's quadratic
//     interpolation of it, within the suite's bound;
//  3. the same cells as VTK_LAGRANGE_TETRAHEDRON of order 2: the same image;
//  4. a NaN at one mid-edge node: the cells around that edge through their
//     corners (counted, warned), no NaN, the reference applying the same rule;
//  5. curved edges (mid-edge nodes moved off the midpoints by up to 3 % of an
//     edge): refined (ppirayHigherOrderPieces.h) into pieces rendered with
//     straight edges (warned), against VTK's curved cells: the pieces'
//     geometric error within the bounds below; 6. with the NaN of 4.;
//  7. curved, with cell data.

#include "PPIRayExpectNative.h"
#include "PPIRayImageCompare.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "ppirayQuadraticTetrahedra.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkHexahedralCellTextures.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkPointData.h"
#include "vtkQuadraticTetra.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <utility>

namespace
{
constexpr int Size = 200;
using Field = ppiray_test::Field;

int Fail(const char* what)
{
  std::cerr << "FAILED: " << what << "\n";
  return 1;
}

// 0. The polynomial of FrameCoefficients against VTK's shape functions.
int CheckFramePolynomial()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  auto next = [&]()
  {
    random->Next();
    return random->GetValue();
  };
  double worst = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    double s[4], m[6], c[11];
    for (double& v : s)
    {
      v = 2 * next() - 1;
    }
    for (double& v : m)
    {
      v = 2 * next() - 1;
    }
    ppiray::quadratic_tetrahedron::FrameCoefficients(s, m, c);
    double p[3] = { next(), next(), next() };
    double weights[10];
    vtkQuadraticTetra::InterpolationFunctions(p, weights);
    double vtk = 0;
    for (int i = 0; i < 10; ++i)
    {
      vtk += weights[i] * (i < 4 ? s[i] : m[i - 4]);
    }
    const double u = p[0], v = p[1], w = p[2];
    const double ours = c[0] + c[1] * u + c[2] * v + c[3] * w + c[4] * u * v + c[5] * v * w +
                        c[6] * u * w + c[8] * u * u + c[9] * v * v + c[10] * w * w;
    worst = std::max(worst, std::abs(ours - vtk));
  }
  std::cout << "frame polynomial against vtkQuadraticTetra: max difference " << worst << "\n";
  return worst < 1e-12 ? 0 : Fail("the frame polynomial is not VTK's quadratic field");
}

// The block's linear tetrahedra made quadratic: one mid-edge node per edge
// (shared) at its midpoint, then every node moved by Deform(bend) (0:
// straight edges; else the cells are curved, as a mesh of curved geometry
// is); `f` at every node.
vtkSmartPointer<vtkUnstructuredGrid> Quadratic(
  vtkUnstructuredGrid* linear, int type, double bend, const Field& f)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(linear->GetPoints());
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> mids;
  for (vtkIdType c = 0; c < linear->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    linear->GetCellPoints(c, npts, pts);
    vtkIdType ids[10];
    std::copy_n(pts, 4, ids);
    for (int k = 0; k < 6; ++k)
    {
      const vtkIdType a = pts[ppiray::quadratic_tetrahedron::Edge[k][0]];
      const vtkIdType b = pts[ppiray::quadratic_tetrahedron::Edge[k][1]];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mids.find(key);
      if (it == mids.end())
      {
        double x[3], y[3], m[3];
        points->GetPoint(key.first, x);
        points->GetPoint(key.second, y);
        for (int i = 0; i < 3; ++i)
        {
          m[i] = 0.5 * (x[i] + y[i]);
        }
        it = mids.emplace(key, points->InsertNextPoint(m)).first;
      }
      ids[4 + k] = it->second;
    }
    grid->InsertNextCell(type, 10, ids);
  }
  for (vtkIdType p = 0; p < points->GetNumberOfPoints() && bend != 0; ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    ppiray_test::Deform(bend, x);
    points->SetPoint(p, x);
  }
  grid->SetPoints(points);
  ppiray_test::PointField(grid, f);
  return grid;
}

}

int TestGPURayCastQuadraticTetrahedra(int, char*[])
{
  using Mapper = vtkUnstructuredGridGPURayCastMapper;
  int errors = CheckFramePolynomial();

  // A block of 4^3 cubes, six tetrahedra each, points moved off the lattice
  // (the tetrahedra stay straight: their edges are segments).
  const int n[3] = { 4, 4, 4 };
  const double origin[3] = { 0, 0, 0 };
  auto linear = ppiray_test::VoxelTetrahedra(
    n, 0.25, origin, [](int, int, int) { return true; },
    [](double, double, double) { return 0.0; });
  auto lattice = vtkSmartPointer<vtkUnstructuredGrid>::New(); // before the points move
  lattice->DeepCopy(linear);
  for (vtkIdType p = 0; p < linear->GetNumberOfPoints(); ++p)
  {
    double x[3];
    linear->GetPoints()->GetPoint(p, x);
    const double interior = x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1 && x[2] > 0 && x[2] < 1;
    x[0] += interior * 0.04 * std::sin(11 * x[1] + 3 * x[2]);
    x[1] += interior * 0.04 * std::cos(9 * x[2] + 2 * x[0]);
    x[2] += interior * 0.04 * std::sin(13 * x[0] + x[1]);
    linear->GetPoints()->SetPoint(p, x);
  }
  const Field quadratic = [](double x, double y, double z)
  { return 0.15 + 0.3 * x + 0.5 * y * y - 0.4 * x * z + 0.6 * z * z + 0.2 * x * y; };
  const Field wavy = [](double x, double y, double z)
  { return 0.65 + 0.55 * std::sin(5 * x + 0.3) * std::cos(4 * y) * std::sin(3 * z + 0.5); };
  auto straight = Quadratic(linear, VTK_QUADRATIC_TETRA, 0.0, quadratic);

  vtkNew<vtkHexahedralCellTextures> textures;
  textures->BuildGeometry(straight);
  std::cout << "cells " << textures->GetNumberOfHexahedra() << " of "
            << straight->GetNumberOfCells() << ", mirrored "
            << textures->GetNumberOfMirroredHexahedra() << ", curved "
            << textures->GetNumberOfCurvedCells() << ", coefficient texels "
            << textures->GetCoefficientTexels() << "\n";
  if (textures->GetNumberOfHexahedra() != straight->GetNumberOfCells() ||
      textures->GetNumberOfMirroredHexahedra() == 0 || textures->GetNumberOfCurvedCells() != 0 ||
      textures->GetCoefficientTexels() != 3)
  {
    errors += Fail("quadratic tetrahedra not laid out natively with their field");
  }

  ppiray_test::Scene scene(Size, Size);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.15);
  vtkNew<Mapper> mapper;
  scene.Show(mapper, straight, { 2.1, 1.4, 2.5 }, { 0.5, 0.5, 0.5 });

  // 1. The quadratic field exactly; through the corners further off.
  ppiray_test::PixelCheck native, corners;
  std::vector<unsigned char> quadraticImage;
  errors += ppiray_test::ExpectNative("quadratic field", scene, mapper, straight,
    Mapper::HEXAHEDRON_ACCURATE, Size, 1.0, 1.0, &native, nullptr, &quadraticImage);
  errors += ppiray_test::ExpectNative("quadratic field, through the corners", scene, mapper,
    straight, Mapper::HEXAHEDRON_SUBDIVIDE, Size, 255.0, 255.0, &corners);
  if (!(corners.P99 > native.P99 + 1.0 && corners.MaxDifference > native.MaxDifference + 2.0))
  {
    errors += Fail("through the corners is not further from VTK's field than natively");
  }

  // 2. A field that is no polynomial, sampled at the nodes.
  ppiray_test::SmoothTransferFunction(scene.Property, 0.1, 1.2, 0.4, 0.5); // the inside shows
  auto wavyGrid = Quadratic(linear, VTK_QUADRATIC_TETRA, 0.0, wavy);
  errors += ppiray_test::ExpectNative(
    "wavy field", scene, mapper, wavyGrid, Mapper::HEXAHEDRON_ACCURATE, Size, 1.0, 1.0);

  // 3. Lagrange tetrahedra of order 2: the same cells, the same image.
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.15);
  auto lagrange = Quadratic(linear, VTK_LAGRANGE_TETRAHEDRON, 0.0, quadratic);
  std::vector<unsigned char> lagrangeImage;
  errors += ppiray_test::ExpectNative("Lagrange tetrahedra", scene, mapper, lagrange,
    Mapper::HEXAHEDRON_ACCURATE, Size, 1.0, 1.0, nullptr, nullptr, &lagrangeImage);
  if (ppiray_test::Compare(lagrangeImage, quadraticImage).Max > 0)
  {
    errors += Fail("Lagrange tetrahedra of order 2 differ from quadratic tetrahedra");
  }

  // 4. A NaN at an interior mid-edge node: the cells around that edge
  // through their corners, once warned.
  auto withNaN = Quadratic(linear, VTK_QUADRATIC_TETRA, 0.0, wavy);
  vtkIdType nanNode = -1, around = 0;
  for (vtkIdType c = 0; c < withNaN->GetNumberOfCells() && nanNode < 0; ++c)
  {
    double x[3];
    withNaN->GetPoint(withNaN->GetCell(c)->GetPointId(9), x);
    nanNode = std::abs(x[0] - 0.5) < 0.2 && std::abs(x[1] - 0.5) < 0.2 && x[2] > 0.1 && x[2] < 0.9
                ? withNaN->GetCell(c)->GetPointId(9)
                : -1;
  }
  for (vtkIdType c = 0; c < withNaN->GetNumberOfCells(); ++c)
  {
    around += withNaN->GetCell(c)->GetPointIds()->IsId(nanNode) >= 0 ? 1 : 0;
  }
  withNaN->GetPointData()->GetScalars()->SetComponent(nanNode, 0, std::nan(""));
  ppiray_test::SmoothTransferFunction(scene.Property, 0.1, 1.2, 0.4, 0.5); // the inside shows
  errors += ppiray_test::ExpectNative(
    "NaN at a mid-edge node", scene, mapper, withNaN, Mapper::HEXAHEDRON_ACCURATE, Size, 1.0, 1.0);
  textures->BuildGeometry(withNaN);
  textures->BuildField(withNaN->GetPointData()->GetScalars(), false, 0);
  std::cout << "cells through their corners " << textures->GetNumberOfLinearizedCells()
            << " (around the edge: " << around << "), empty " << textures->GetNumberOfNaNScalars()
            << "\n";
  if (around < 3 || textures->GetNumberOfLinearizedCells() != around ||
      textures->GetNumberOfNaNScalars() != 0)
  {
    errors += Fail("the cells around a NaN mid-edge value are not the ones through their corners");
  }

  // 5. Curved cells (the lattice deformed: mid-edge nodes up to 2.9 % of an
  // edge off the midpoint): every cell refined twice (64 pieces), the
  // pieces within 0.4 % of an edge of straight.
  auto curved = Quadratic(lattice, VTK_QUADRATIC_TETRA, 0.06, wavy);
  textures->BuildGeometry(curved);
  std::cout << "curved cells " << textures->GetNumberOfCurvedCells() << ", deviation up to "
            << textures->GetMaximumMidEdgeDeviation() << ", refined "
            << textures->GetRefinementLevels() << " levels into "
            << textures->GetNumberOfHexahedra() << " pieces\n";
  if (textures->GetNumberOfCurvedCells() < curved->GetNumberOfCells() * 9 / 10 ||
      textures->GetRefinementLevels() != 2 ||
      textures->GetNumberOfHexahedra() != 64 * curved->GetNumberOfCells())
  {
    errors += Fail("curved cells not counted, or not refined twice");
  }
  errors += ppiray_test::ExpectNative(
    "curved edges", scene, mapper, curved, Mapper::HEXAHEDRON_ACCURATE, Size, 1.0, 3.0);
  if (mapper->GetStatistics()->GetNumberOfNativeCells() != 64 * curved->GetNumberOfCells())
  {
    errors += Fail("the refined pieces are not what the mapper marched");
  }

  // 6. Curved, with the NaN of 4.: the cells around that edge through their
  // corners in every piece (RefinedTetrahedra::Linear), as the reference.
  curved->GetPointData()->GetScalars()->SetComponent(nanNode, 0, std::nan(""));
  curved->GetPointData()->GetScalars()->Modified();
  errors += ppiray_test::ExpectNative("curved, NaN at a mid-edge node", scene, mapper, curved,
    Mapper::HEXAHEDRON_ACCURATE, Size, 1.0, 1.0);

  // 7. Curved, cell data (constant per cell): each piece takes its cell's
  // value. The jumps lie on the pieces' straight faces, within 0.4 % of an
  // edge of VTK's curved ones: where a ray runs nearly along a face that
  // moves a long stretch from one cell to the other (measured p99 0.67,
  // max 9.4 at a few pixels); bounds a fifth above.
  vtkNew<vtkDoubleArray> cellValues;
  cellValues->SetName("cellWave");
  for (vtkIdType c = 0; c < curved->GetNumberOfCells(); ++c)
  {
    cellValues->InsertNextValue(0.1 + 1.1 * ((c * 7919) % 101) / 100.0);
  }
  curved->GetCellData()->AddArray(cellValues);
  mapper->SelectScalarArray("cellWave");
  mapper->SetScalarModeToUseCellFieldData();
  errors += ppiray_test::ExpectNative("curved, cell data", scene, mapper, curved,
    Mapper::HEXAHEDRON_ACCURATE, Size, 1.0, 11.5, nullptr, "cellWave");
  return errors == 0 ? 0 : 1;
}
