// Non-conforming faces crossed in one peel (ppirayNonConformingFaces.h):
// where cells meet at hanging nodes or T-junctions their faces share no
// point ids, the adjacency leaves both sides open, and the ray left the mesh
// there and came back on the next peel. Now each open face is linked to
// the open faces of other cells across it (coplanar, facing it,
// overlapping): one face directly, several through a list from which the
// exit point picks. Against the CPU reference (which integrates each cell
// on its own and knows no adjacency), a linear field (exact in every cell):
//  1. a hexahedron next to eight half-size ones (four on the shared face),
//     marched natively: one peel (two without the links);
//  2. the same cells tetrahedralized (vtkDataSetTriangleFilter: the large
//     face's two triangles against the small faces' eight), in the
//     tetrahedron layouts (the .Compact variant too): one peel;
//  3. a tetrahedral face next to four: a tetrahedron against one refined
//     into eight (red refinement), whose shared face is four triangles;
//  4. two blocks of cubes of different sizes (2 x 2 against 3 x 3 on the
//     shared face, every face met by up to four, lists of pieces), natively
//     and as tetrahedra: one peel;
//  5. partly covered faces (a slab of small cubes shifted by a quarter
//     across the large one: faces partly against cells, partly outside):
//     the exit point outside every face across ends the peel there; exact,
//     in the peels the geometry needs;
//  6. a seam: two warped blocks of hexahedra meeting through duplicated
//     points (an O-grid's cut), the quadrilaterals on the cut not planar and
//     numbered differently on the two sides: paired by their places
//     (PairCoincidentFaces), split along the same diagonal on both sides
//     (checked on the layout), one peel (two without: they are not
//     coplanar), the image of the same cells sharing their points;
//  7. a curved face split differently: two cubes of six tetrahedra whose
//     shared quadrilateral (not planar) is split along one diagonal on one
//     side and the other on the other, a lens between the two surfaces
//     that both cubes cover or neither (MatchSplitQuadrilaterals): one peel
//     (two without), exact (the apart lens integrated: p99 2.1, max 4.9);
//     and against five tetrahedra, where a ray through the covered lens
//     lands in the one around the diagonal with no face on it (without the
//     fallback to the nearest face across: max 130); and across a seam
//     (the right cube's own points, at the same places); a thin body whose
//     top and bottom have the same four corners is not a lens (linked, it
//     would have no boundary left and render nothing).

#include "PPIRayExpectNative.h"
#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "ppirayLinearCellKinds.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkHexahedralCellTextures.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkTetrahedralCellTextures.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <string>

namespace
{
constexpr int Size = 200;

// A grid built cell by cell, points merged by position (on a 1/12 lattice).
struct GridBuilder
{
  vtkNew<vtkPoints> Points;
  std::map<std::array<long, 4>, vtkIdType> Ids;
  vtkSmartPointer<vtkUnstructuredGrid> Grid = vtkSmartPointer<vtkUnstructuredGrid>::New();

  int Part = 0; // points of different parts are never merged
  vtkIdType Point(double x, double y, double z)
  {
    const std::array<long, 4> key = { std::lround(12 * x), std::lround(12 * y), std::lround(12 * z),
      this->Part };
    auto found = this->Ids.find(key);
    if (found != this->Ids.end())
    {
      return found->second;
    }
    return this->Ids[key] = this->Points->InsertNextPoint(x, y, z);
  }
  void Cube(double x, double y, double z, double h)
  {
    const int corner[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
      { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
    vtkIdType ids[8];
    for (int v = 0; v < 8; ++v)
    {
      ids[v] = this->Point(x + h * corner[v][0], y + h * corner[v][1], z + h * corner[v][2]);
    }
    this->Grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
  }
  void Tetra(const std::array<double, 3> (&x)[4])
  {
    vtkIdType ids[4];
    for (int v = 0; v < 4; ++v)
    {
      ids[v] = this->Point(x[v][0], x[v][1], x[v][2]);
    }
    this->Grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  // The cube of size h at (x, y, z) as six tetrahedra around its diagonal
  // (0, 0, 0) - (1, 1, 1), or, `mirrored`, the same six mirrored in y
  // (around (0, 1, 0) - (1, 0, 1)): every face is split along a diagonal,
  // the other one on the mirrored cube.
  void SixTetrahedra(double x, double y, double z, double h, bool mirrored)
  {
    const int tets[6][4] = { { 0, 1, 2, 6 }, { 0, 2, 3, 6 }, { 0, 3, 7, 6 }, { 0, 7, 4, 6 },
      { 0, 4, 5, 6 }, { 0, 5, 1, 6 } };
    this->Tetrahedra(x, y, z, h, mirrored, tets);
  }
  // The cube as five tetrahedra: four corners cut off, (1, 3, 4, 6) left in
  // the middle (its +x face split along (1, 0, 0) - (1, 1, 1) as above, the
  // diagonal an edge of three tetrahedra).
  void FiveTetrahedra(double x, double y, double z, double h)
  {
    const int tets[5][4] = { { 0, 1, 3, 4 }, { 2, 3, 1, 6 }, { 5, 4, 6, 1 }, { 7, 6, 4, 3 },
      { 1, 3, 4, 6 } };
    this->Tetrahedra(x, y, z, h, false, tets);
  }
  template<size_t N>
  void Tetrahedra(double x, double y, double z, double h, bool mirrored, const int (&tets)[N][4])
  {
    const int corner[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
      { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
    for (const auto& tet : tets)
    {
      vtkIdType ids[4];
      for (int v = 0; v < 4; ++v)
      {
        const int* c = corner[tet[v]];
        ids[v] = this->Point(x + h * c[0], y + h * (mirrored ? 1 - c[1] : c[1]), z + h * c[2]);
      }
      this->Grid->InsertNextCell(VTK_TETRA, 4, ids);
    }
  }
  // The grid with the linear field s = 0.2 + 0.3 x + 0.2 y + 0.1 z.
  vtkSmartPointer<vtkUnstructuredGrid> Done()
  {
    this->Grid->SetPoints(this->Points);
    vtkNew<vtkDoubleArray> s;
    s->SetName("s");
    for (vtkIdType p = 0; p < this->Points->GetNumberOfPoints(); ++p)
    {
      double x[3];
      this->Points->GetPoint(p, x);
      s->InsertNextValue(0.2 + 0.3 * x[0] + 0.2 * x[1] + 0.1 * x[2]);
    }
    this->Grid->GetPointData()->SetScalars(s);
    return this->Grid;
  }
};

// The unit cube at the origin filled with cubes of size 1 / left and, on
// its +x face, `layers` of cubes of size 1 / right (right x right on the
// face), shifted by `shift` along y.
vtkSmartPointer<vtkUnstructuredGrid> Blocks(int left, int right, int layers, double shift)
{
  GridBuilder b;
  for (int i = 0; i < left; ++i)
    for (int j = 0; j < left; ++j)
      for (int k = 0; k < left; ++k)
        b.Cube(i / double(left), j / double(left), k / double(left), 1.0 / left);
  for (int i = 0; i < layers; ++i)
    for (int j = 0; j < right; ++j)
      for (int k = 0; k < right; ++k)
        b.Cube(1 + i / double(right), shift + j / double(right), k / double(right), 1.0 / right);
  return b.Done();
}

// Two blocks of 2 x 2 x 2 cubes of size 1/2, [0, 1]^3 and [1, 2] x [0, 1]^2,
// the second numbered in reverse, with their own points each (a seam at x =
// 1) or sharing them; then every point moved by x += 0.12 y z (the seam's
// quadrilaterals warp).
vtkSmartPointer<vtkUnstructuredGrid> Seam(bool seam)
{
  GridBuilder b;
  for (int part = 0; part < 2; ++part)
  {
    b.Part = seam ? part : 0;
    for (int c = 0; c < 8; ++c)
    {
      const int n = part == 0 ? c : 7 - c;
      b.Cube(part + 0.5 * (n % 2), 0.5 * ((n / 2) % 2), 0.5 * (n / 4), 0.5);
    }
  }
  vtkPoints* points = b.Points;
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    points->SetPoint(p, x[0] + 0.12 * x[1] * x[2], x[1], x[2]);
  }
  return b.Done();
}

// Of the faces of `grid`'s hexahedra (vtkHexahedralCellTextures built) at
// the same places as another's: how many, and how many of those pairs are
// split along different diagonals (their corners' places) on the two sides.
std::array<int, 2> SeamDiagonals(vtkUnstructuredGrid* grid, vtkHexahedralCellTextures* hexes)
{
  using Place = std::array<double, 3>;
  const std::vector<vtkIdType>& ids = hexes->GetCornerIds();
  const std::vector<int>& neighbors = hexes->GetNeighbors();
  std::map<std::array<Place, 4>, std::vector<std::array<Place, 2>>> sides;
  for (vtkIdType h = 0; h < hexes->GetNumberOfHexahedra(); ++h)
  {
    for (int f = 0; f < 6; ++f)
    {
      const int* q = ppiray::LinearCellKindOf(ppiray::HEXAHEDRON_KIND).Face[f];
      std::array<Place, 4> corners;
      for (int v = 0; v < 4; ++v)
      {
        grid->GetPoint(ids[8 * h + q[v]], corners[v].data());
      }
      const int second = (neighbors[8 * h + 6] >> f) & 1;
      std::array<Place, 2> diagonal = { corners[second], corners[second + 2] };
      std::sort(diagonal.begin(), diagonal.end());
      std::sort(corners.begin(), corners.end());
      sides[corners].push_back(diagonal);
    }
  }
  std::array<int, 2> count = { 0, 0 };
  for (const auto& face : sides)
  {
    count[0] += face.second.size() == 2 ? 1 : 0;
    count[1] += face.second.size() == 2 && face.second[0] != face.second[1] ? 1 : 0;
  }
  return count;
}

vtkSmartPointer<vtkUnstructuredGrid> Tetrahedralized(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkDataSetTriangleFilter> split;
  split->SetInputData(grid);
  split->Update();
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->DeepCopy(split->GetOutput());
  return out;
}

// A tetrahedron and, across its face (1,0,0), (0,1,0), (0,0,1), one refined
// into eight (red refinement: four corner tetrahedra, the octahedron left
// split around the diagonal m02 - m13).
vtkSmartPointer<vtkUnstructuredGrid> FaceNextToFour()
{
  using P = std::array<double, 3>;
  GridBuilder b;
  const P v0 = { 1, 0, 0 }, v1 = { 0, 1, 0 }, v2 = { 0, 0, 1 }, v3 = { 1, 1, 1 };
  b.Tetra({ v0, v1, v2, P{ 0, 0, 0 } });
  auto mid = [](const P& a, const P& c) {
    return P{ (a[0] + c[0]) / 2, (a[1] + c[1]) / 2, (a[2] + c[2]) / 2 };
  };
  const P m01 = mid(v0, v1), m02 = mid(v0, v2), m03 = mid(v0, v3), m12 = mid(v1, v2),
          m13 = mid(v1, v3), m23 = mid(v2, v3);
  b.Tetra({ v0, m01, m02, m03 });
  b.Tetra({ v1, m01, m12, m13 });
  b.Tetra({ v2, m02, m12, m23 });
  b.Tetra({ v3, m03, m13, m23 });
  b.Tetra({ m02, m13, m01, m12 });
  b.Tetra({ m02, m13, m12, m23 });
  b.Tetra({ m02, m13, m23, m03 });
  b.Tetra({ m02, m13, m03, m01 });
  return b.Done();
}

// Two unit cubes side by side along x, each as six tetrahedra
// (SixTetrahedra), their shared face split along different diagonals, its
// corner (1, 1, 1) moved to (1 + bulge, 1, 1): the face is not planar and
// its two sides are different surfaces, a thin lens between them that both
// cells cover (bulge > 0: the left cube's triangles bulge into the right
// cube) or neither (bulge < 0). `five`: the left cube as five tetrahedra,
// so that a ray out of the right cube may land in the one of the three
// around the diagonal that has no face on the quadrilateral. `seam`: the
// right cube with its own points.
vtkSmartPointer<vtkUnstructuredGrid> CurvedFace(double bulge, bool five = false, bool seam = false)
{
  GridBuilder b;
  if (five)
  {
    b.FiveTetrahedra(0, 0, 0, 1);
  }
  else
  {
    b.SixTetrahedra(0, 0, 0, 1, false);
  }
  b.Part = seam ? 1 : 0;
  b.SixTetrahedra(1, 0, 0, 1, true);
  for (const int part : { 0, seam ? 1 : 0 })
  {
    b.Part = part;
    b.Points->SetPoint(b.Point(1, 1, 1), 1 + bulge, 1, 1);
  }
  return b.Done();
}

// A thin body: the tetrahedron (0, 0, 0), (2, 0, 0.7), (2, 2, 0),
// (0, 2, 0.7) split into four from its centre. Its top and bottom are two
// pairs of triangles with the same four corners facing away from each
// other: not a lens (each side's cells lie inside, not beyond the other).
vtkSmartPointer<vtkUnstructuredGrid> ThinBody()
{
  using P = std::array<double, 3>;
  GridBuilder b;
  const P a = { 0, 0, 0 }, c = { 2, 0, 0.7 }, d = { 2, 2, 0 }, e = { 0, 2, 0.7 },
          m = { 1, 1, 0.35 };
  b.Tetra({ m, a, c, e });
  b.Tetra({ m, c, d, e });
  b.Tetra({ m, a, c, d });
  b.Tetra({ m, a, d, e });
  return b.Done();
}

int Fail(const std::string& what)
{
  std::cerr << "FAILED: " << what << "\n";
  return 1;
}

// The open faces the layout of `grid` links geometrically.
vtkIdType NonConformingFaces(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkHexahedralCellTextures> hexes;
  if (hexes->BuildGeometry(grid))
  {
    return hexes->GetNumberOfNonConformingFaces();
  }
  vtkNew<vtkTetrahedralCellTextures> tets;
  tets->BuildGeometry(grid);
  return tets->GetNumberOfNonConformingFaces();
}
}

int TestGPURayCastNonConforming(int argc, char* argv[])
{
  using Mapper = vtkUnstructuredGridGPURayCastMapper;
  int errors = 0;
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  ppiray_test::Scene scene(Size, Size);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.0, 0.8, 0.15);
  vtkNew<Mapper> mapper;

  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
    vtkIdType Linked; // open faces linked geometrically
  };
  const auto hanging = Blocks(1, 2, 2, 0.0);
  const auto sizes = Blocks(2, 3, 2, 0.0);
  const Case cases[] = {
    { "a hexahedron next to eight", hanging, 1 + 4 },
    { "a hexahedron next to eight, tetrahedralized", Tetrahedralized(hanging), 2 + 8 },
    { "a tetrahedral face next to four", FaceNextToFour(), 1 + 4 },
    { "2 x 2 cubes against 3 x 3", sizes, 4 + 9 },
    { "2 x 2 cubes against 3 x 3, tetrahedralized", Tetrahedralized(sizes), 8 + 18 },
    { "a curved face split differently, overlapping", CurvedFace(0.25), 4 },
    { "a curved face split differently, apart", CurvedFace(-0.25), 4 },
    { "a curved face split differently, overlapping, five tetrahedra", CurvedFace(0.25, true), 4 },
    { "a curved face split differently, apart, a seam", CurvedFace(-0.25, false, true), 4 },
    { "a thin body (top and bottom with the same corners, not a lens)", ThinBody(), 0 },
  };
  for (const Case& c : cases)
  {
    const vtkIdType linked = NonConformingFaces(c.Grid);
    std::cout << c.Name << ": " << c.Grid->GetNumberOfCells() << " cells, " << linked
              << " faces linked\n";
    if (linked != c.Linked)
    {
      errors += Fail(std::string(c.Name) + ": expected " + std::to_string(c.Linked));
    }
    scene.Show(mapper, c.Grid, { 3.5, 2.6, 2.2 }, { 0.8, 0.5, 0.5 });
    scene.Renderer->GetActiveCamera()->Zoom(1.2);
    const bool tetrahedra = c.Grid->GetCellType(0) == VTK_TETRA;
    errors += ppiray_test::ExpectNative(c.Name, scene, mapper, c.Grid,
      tetrahedra ? Mapper::HEXAHEDRON_SUBDIVIDE : Mapper::HEXAHEDRON_ACCURATE, Size, 1.0, 1.0);
  }

  // 6. A seam through non-planar quadrilaterals numbered differently: the
  // image of the same cells sharing their points, within 1/255, one peel.
  // (Both against the reference: p99 3.0, max 5.9, the quadrilaterals split
  // into two triangles where VTK's hexahedron has bilinear faces.)
  {
    auto seam = Seam(true);
    vtkNew<vtkHexahedralCellTextures> hexes;
    hexes->BuildGeometry(seam);
    const std::array<int, 2> faces = SeamDiagonals(seam, hexes);
    std::cout << "a seam: " << hexes->GetNumberOfNonConformingFaces()
              << " faces linked, faces with two sides " << faces[0] << ", split differently "
              << faces[1] << "\n";
    // 12 faces inside each block, paired by ids; the seam's 4 on each side.
    if (hexes->GetNumberOfNonConformingFaces() != 8 || faces[0] != 2 * 12 + 4 || faces[1] != 0)
    {
      errors += Fail("a seam: expected its 8 faces linked, each pair split alike");
    }
    mapper->SetHexahedronModeToAccurate();
    scene.Show(mapper, Seam(false), { 3.5, 2.6, 2.2 }, { 1.0, 0.5, 0.5 });
    scene.Window->Render();
    const auto shared = ppiray_test::ReadRGB(scene.Window);
    mapper->SetInputData(seam);
    scene.Window->Render();
    const auto image = ppiray_test::ReadRGB(scene.Window);
    int largest = 0, covered = 0;
    for (size_t i = 0; i < image.size(); ++i)
    {
      largest = std::max(largest, std::abs(int(image[i]) - int(shared[i])));
      covered += shared[i] > 0 ? 1 : 0;
    }
    std::cout << "a seam: peels " << mapper->GetStatistics()->GetNumberOfPeels() << ", native "
              << mapper->GetStatistics()->GetNumberOfNativeCells() << ", against the shared "
              << "points' image max " << largest << "/255 over " << covered << " channels\n";
    if (mapper->GetStatistics()->GetNumberOfPeels() != 1 || largest > 1 || covered < 10000 ||
        mapper->GetStatistics()->GetNumberOfNativeCells() != 16)
    {
      errors += Fail("a seam: expected one peel, natively, the shared points' image");
    }
  }

  // 5. Partly covered faces: exact, in as many peels as the geometry needs.
  for (const bool tetrahedra : { false, true })
  {
    auto grid = Blocks(1, 2, 1, 0.25);
    grid = tetrahedra ? Tetrahedralized(grid) : grid;
    const std::string name = tetrahedra ? "shifted slab, tetrahedralized" : "shifted slab";
    scene.Show(mapper, grid, { 3.5, 2.6, 2.2 }, { 0.8, 0.5, 0.5 });
    mapper->SetHexahedronModeToAccurate();
    scene.Window->Render();
    const auto check = ppiray_test::CheckPixels(
      scene.Renderer, grid, scene.Property, ppiray_test::ReadRGB(scene.Window), Size, Size);
    std::cout << name << ": " << NonConformingFaces(grid) << " faces linked, peels "
              << mapper->GetStatistics()->GetNumberOfPeels() << ", ";
    errors += ppiray_test::ExpectReference(name.c_str(), check, 10000);
  }
  return errors == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
