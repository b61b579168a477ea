// Polyhedra (VTK_POLYHEDRON, what OpenFOAM, Fluent and STAR-CCM+ meshes
// are) split into conforming tetrahedra (ppirayPolyhedra.h: a cone from an
// added centre point, faces of five or more corners fanned from an added
// point shared by both cells on them, quadrilaterals by the diagonal rule),
// against the CPU reference, which integrates each polyhedron through VTK's
// own interpolation (mean value coordinates, vtkPolyhedron):
//  1. polyhedra shaped as hexahedra (a 4 x 4 x 4 block of cubes), a field
//     linear in space: exact (mean value coordinates reproduce it); one peel
//     (the split conforms); the cell textures count the polyhedra;
//  2. the same block under a smooth field that is not linear: VTK's field at
//     the cells' points and the added points, linear between them; bounded
//     as measured (below);
//  3. hexagonal prisms (a honeycomb, two layers: hexagons shared between
//     layers, each fanned from one added point for both cells), linear
//     field: exact; conforming (the boundary triangles are exactly those of
//     the faces of one cell);
//  4. polyhedra next to hexahedra (half the block each): the grid is split
//     into tetrahedra (with the warning that names the polyhedra), the
//     shared quadrilaterals split alike on both sides: one peel, exact for
//     the linear field.

#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkGenericCell.h"
#include "vtkHexahedron.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTetrahedralCellTextures.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
constexpr int Size = 150;

using Face = std::vector<vtkIdType>;

void AddPolyhedron(vtkUnstructuredGrid* grid, const std::vector<Face>& faces)
{
  vtkNew<vtkIdList> stream;
  stream->InsertNextId(static_cast<vtkIdType>(faces.size()));
  for (const Face& face : faces)
  {
    stream->InsertNextId(static_cast<vtkIdType>(face.size()));
    for (vtkIdType id : face)
    {
      stream->InsertNextId(id);
    }
  }
  grid->InsertNextCell(VTK_POLYHEDRON, stream);
}

double Linear(const double x[3])
{
  return 0.2 + 0.45 * x[0] + 0.35 * x[1] + 0.5 * x[2];
}

// A point field: linear, or ppiray_test::Blob (smooth, not linear).
void SetField(vtkUnstructuredGrid* grid, bool blob)
{
  vtkNew<vtkDoubleArray> values;
  values->SetName(blob ? "blob" : "linear");
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    double x[3];
    grid->GetPoint(p, x);
    values->InsertNextValue(blob ? ppiray_test::Blob(x[0], x[1], x[2]) : Linear(x));
  }
  grid->GetPointData()->SetScalars(values);
}

// Triangles on the boundary of the polyhedra of `grid` if their split
// conforms: faces of one cell only (by sorted point ids), m - 2 triangles
// for a face of 3 or 4 corners, m for one fanned from an added point.
size_t ExpectedBoundaryTriangles(vtkUnstructuredGrid* grid)
{
  std::map<std::vector<vtkIdType>, int> count;
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCell(c, cell);
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkIdList* ids = cell->GetFace(f)->GetPointIds();
      std::vector<vtkIdType> key(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  }
  size_t triangles = 0;
  for (const auto& face : count)
  {
    const size_t m = face.first.size();
    triangles += face.second == 1 ? (m <= 4 ? m - 2 : m) : 0;
  }
  return triangles;
}

// n x n x n unit-block cubes; those with i < hexahedraBelow as VTK_HEXAHEDRON,
// the others as polyhedra with the hexahedron's faces.
vtkSmartPointer<vtkUnstructuredGrid> CubeBlock(int n, int hexahedraBelow = 0)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
      {
        points->InsertNextPoint(
          static_cast<double>(i) / n, static_cast<double>(j) / n, static_cast<double>(k) / n);
      }
  grid->SetPoints(points);
  auto id = [n](int i, int j, int k)
  { return static_cast<vtkIdType>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType c[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
          id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) };
        if (i < hexahedraBelow)
        {
          grid->InsertNextCell(VTK_HEXAHEDRON, 8, c);
          continue;
        }
        std::vector<Face> faces;
        for (int f = 0; f < 6; ++f)
        {
          const vtkIdType* q = vtkHexahedron::GetFaceArray(f);
          faces.push_back({ c[q[0]], c[q[1]], c[q[2]], c[q[3]] });
        }
        AddPolyhedron(grid, faces);
      }
  return grid;
}

// Hexagonal prisms of side a in `rows` x `columns` (a honeycomb), `layers`
// high, each hexagon shared by the prisms above and below it.
vtkSmartPointer<vtkUnstructuredGrid> Honeycomb(int rows, int columns, int layers)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  std::map<std::array<long long, 3>, vtkIdType> ids;
  const double a = 0.12, pi = std::acos(-1.0);
  auto point = [&](double x, double y, double z)
  {
    const std::array<long long, 3> key = { std::llround(x * 1e6), std::llround(y * 1e6),
      std::llround(z * 1e6) };
    auto it = ids.find(key);
    if (it == ids.end())
    {
      it = ids.emplace(key, points->InsertNextPoint(x, y, z)).first;
    }
    return it->second;
  };
  const double height = 0.25;
  for (int l = 0; l < layers; ++l)
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < columns; ++c)
      {
        const double cx = 1.5 * a * c, cy = std::sqrt(3.0) * a * (r + 0.5 * (c % 2));
        Face bottom, top;
        for (int k = 0; k < 6; ++k)
        {
          const double x = cx + a * std::cos(k * pi / 3), y = cy + a * std::sin(k * pi / 3);
          bottom.push_back(point(x, y, l * height));
          top.push_back(point(x, y, (l + 1) * height));
        }
        std::vector<Face> faces = { Face(bottom.rbegin(), bottom.rend()), top };
        for (int k = 0; k < 6; ++k)
        {
          faces.push_back({ bottom[k], bottom[(k + 1) % 6], top[(k + 1) % 6], top[k] });
        }
        AddPolyhedron(grid, faces);
      }
  grid->SetPoints(points);
  return grid;
}

int Fail(const char* what)
{
  std::cerr << "FAILED: " << what << "\n";
  return 1;
}

// Renders `grid` and checks it against the reference (p99, max bounds), at
// most `peels` peels, some tetrahedra rendered.
int Expect(const char* what, ppiray_test::Scene& scene, vtkUnstructuredGridGPURayCastMapper* mapper,
  vtkUnstructuredGrid* grid, double p99Bound, double maxBound, int peels = 1, int size = Size)
{
  mapper->SetInputData(grid);
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  const auto image = ppiray_test::ReadRGB(scene.Window);
  const auto check =
    ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, size, size);
  std::cout << what << ": tetrahedra " << mapper->GetStatistics()->GetNumberOfTetrahedra()
            << ", peels " << mapper->GetStatistics()->GetNumberOfPeels() << ", ";
  int errors = ppiray_test::ExpectCoverage(check, size * size / 6);
  if (mapper->GetStatistics()->GetNumberOfPeels() > peels ||
      mapper->GetStatistics()->GetNumberOfTetrahedra() == 0)
  {
    errors += Fail("more peels than the boundary needs (the split does not conform), or nothing "
                   "rendered");
  }
  if (check.P99 > p99Bound || check.MaxDifference > maxBound)
  {
    std::cerr << "bounds: p99 " << p99Bound << ", max " << maxBound << "\n";
    errors += Fail(what);
  }
  return errors;
}
}

int TestGPURayCastPolyhedra(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  int errors = 0;
  auto cubes = CubeBlock(4);
  SetField(cubes, false);

  // 1. The split.
  vtkNew<vtkTetrahedralCellTextures> textures;
  textures->BuildGeometry(cubes);
  std::cout << "cubes: polyhedra " << textures->GetNumberOfPolyhedra() << ", tetrahedra "
            << textures->GetNumberOfTetrahedra() << ", boundary triangles "
            << textures->GetBoundaryFaces().size() << ", unsupported "
            << textures->GetNumberOfUnsupportedCells() << "\n";
  if (textures->GetNumberOfPolyhedra() != 64 || textures->GetNumberOfTetrahedra() != 64 * 12 ||
      textures->GetBoundaryFaces().size() != 2u * 6 * 16 || textures->GetNumberOfUnsupportedCells())
  {
    errors += Fail("the polyhedra are not split into 12 conforming tetrahedra each");
  }

  ppiray_test::Scene scene(Size, Size);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.1, 1.4, 1.0, 0.05);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  scene.Show(mapper, cubes, { 2.0, 1.3, 2.4 }, { 0.5, 0.5, 0.5 });
  errors += Expect("cubes, linear field", scene, mapper, cubes, 1.0, 1.0);

  // 2. A smooth field that is not linear: VTK's at the points, linear between
  // them. At 64 x 64: the reference subdivides each polyhedron's stretch
  // until VTK's field is linear along it, and vtkPolyhedron evaluates it
  // slowly. Measured p99 6.5, max 21.9; bounds about a seventh above.
  {
    ppiray_test::Scene small(64, 64);
    ppiray_test::SmoothTransferFunction(small.Property, 0.1, 1.4, 1.0, 0.05);
    vtkNew<vtkUnstructuredGridGPURayCastMapper> smallMapper;
    SetField(cubes, true);
    small.Show(smallMapper, cubes, { 2.0, 1.3, 2.4 }, { 0.5, 0.5, 0.5 });
    errors += Expect("cubes, smooth field", small, smallMapper, cubes, 7.5, 25.0, 1, 64);
  }

  // 3. Hexagonal prisms.
  auto prisms = Honeycomb(4, 5, 2);
  SetField(prisms, false);
  textures->BuildGeometry(prisms);
  std::cout << "prisms: polyhedra " << textures->GetNumberOfPolyhedra() << ", tetrahedra "
            << textures->GetNumberOfTetrahedra() << "\n";
  // Per prism: 2 hexagons x 6 + 6 quadrilaterals x 2 tetrahedra; the
  // honeycomb's jagged sides are concave (two peels).
  const size_t expected = ExpectedBoundaryTriangles(prisms);
  std::cout << "prisms: boundary triangles " << textures->GetBoundaryFaces().size()
            << " (faces of one cell: " << expected << ")\n";
  if (textures->GetNumberOfPolyhedra() != 40 || textures->GetNumberOfTetrahedra() != 40 * 24 ||
      textures->GetBoundaryFaces().size() != expected)
  {
    errors += Fail("the prisms are not split into conforming tetrahedra");
  }
  errors += Expect("hexagonal prisms, linear field", scene, mapper, prisms, 1.0, 1.0, 2);

  // 4. Polyhedra next to hexahedra.
  auto both = CubeBlock(4, 2);
  SetField(both, false);
  vtkNew<ppiray_test::MessageCollector> messages;
  mapper->AddObserver(vtkCommand::WarningEvent, messages);
  errors += Expect("polyhedra next to hexahedra, linear field", scene, mapper, both, 1.0, 1.0);
  std::cout << "warnings: " << messages->Warnings << "\n";
  if (messages->Warnings.find("32 other cells") == std::string::npos)
  {
    errors += Fail("no warning names the polyhedra that make the grid split");
  }
  return errors == 0 ? 0 : 1;
}
