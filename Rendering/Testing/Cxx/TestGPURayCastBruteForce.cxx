// The GPU mapper and the CPU reference renderer, each against a brute-force
// march that shares no code or assumption with either (PPIRayBruteForce.h:
// point location per sample, VTK's own transfer-function evaluation), on
// small scenes that stress what the two could get wrong together: a thin
// opacity spike, a non-convex mesh in two parts, cell scalars, ParaView's
// default Cool to Warm (Diverging) and a Lab map, inverted cells, zero-volume
// cells on interior faces (with a fourth point on the face, or a repeated
// point id), flat tetrahedra between two triangulations of a quadrilateral,
// a mesh folded back on itself (a layer of inverted cells) and two
// overlapping parts (both with a field linear in world coordinates, so that
// every cell covering a point gives it the same value and the union of the
// cells is the one right answer), scalars near 1e6, a vector array rendered
// by magnitude. Bounds per scene (every
// covered pixel, 1/255 units): p99 <= 1 for both (8-bit rounding is 0.5);
// max <= 3 against the march (its steps cut the mesh boundary and the
// cell-scalar jumps at +-Step/2: up to tau Step of a pixel's colour, about
// 0.5/255 here), max <= 2 between GPU and reference (both exact: rounding of
// each to 8 bits and the 0.1/255 transfer-function tolerance); covered pixel
// counts equal within 1 %; no NaN; where the march sees every cell the mapper
// steps through (no flat, folded or overlapping cells) and no ray becomes
// opaque, the mapper's count of cell steps (CountCellSteps) within -0.1 % and
// +1 % of the cells the march meets. Documentation/accuracy.md has the numbers.

#include "PPIRayBruteForce.h"
#include "PPIRayImageCompare.h"
#include "PPIRayTestScenes.h"
#include "vtkAppendFilter.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkUnstructuredGridReferenceRenderer.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
constexpr int Size = 96;

struct Statistics
{
  int Covered = 0;
  int NaN = 0;
  double P99 = 0, Max = 0;
};

// Whether a pixel shows anything in 8 bits.
bool Covered(const double* rgb)
{
  return std::round(255 * rgb[0]) >= 1 || std::round(255 * rgb[1]) >= 1 ||
         std::round(255 * rgb[2]) >= 1;
}

// Per-channel |a - b| * 255 over the pixels either covers.
Statistics Difference(const std::vector<double>& a, const std::vector<double>& b)
{
  Statistics s;
  std::vector<double> d;
  for (size_t p = 0; p < a.size() / 3; ++p)
  {
    bool nan = false;
    for (int c = 0; c < 3; ++c)
    {
      nan = nan || std::isnan(a[3 * p + c]) || std::isnan(b[3 * p + c]);
    }
    const bool covered = Covered(&a[3 * p]) || Covered(&b[3 * p]);
    s.NaN += nan ? 1 : 0;
    if (!covered || nan)
    {
      continue;
    }
    ++s.Covered;
    for (int c = 0; c < 3; ++c)
    {
      d.push_back(255.0 * std::abs(a[3 * p + c] - b[3 * p + c]));
    }
  }
  if (!d.empty())
  {
    std::sort(d.begin(), d.end());
    s.P99 = d[static_cast<size_t>(0.99 * (d.size() - 1))];
    s.Max = d.back();
  }
  return s;
}

int CoveredPixels(const std::vector<double>& rgb)
{
  int n = 0;
  for (size_t p = 0; p < rgb.size() / 3; ++p)
  {
    n += Covered(&rgb[3 * p]) ? 1 : 0;
  }
  return n;
}

struct SceneCase
{
  std::string Name;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  std::string Array;
  bool CellScalars = false;
  std::function<void(vtkVolumeProperty*)> TransferFunction;
  std::function<void(vtkUnstructuredGridGPURayCastMapper*)> Configure;
  std::string BruteForceArray; // if the march reads another array than the mapper
  int MaximumPeels = 0;        // if > 0, the most depth-peeling passes the geometry needs
  // Whether the march's count of cells met is the mapper's count of cell
  // steps: not where the mapper steps through cells no sample can be in
  // (flat cells, the walk back through a fold) or one sample is in two cells
  // (overlapping parts).
  bool CellStepsComparable = true;
};

int CellStepScenes = 0; // scenes whose cell steps were compared

// Scalars "s" = 100 Blob / 1.3 on n^3 voxels over [0, 1]^3 split into tetrahedra.
vtkSmartPointer<vtkUnstructuredGrid> Block(
  int n, const ppiray_test::Keep& keep, double scale = 1.0, double offset = 0.0)
{
  const int cells[3] = { n, n, n };
  const double origin[3] = { 0, 0, 0 };
  return ppiray_test::VoxelTetrahedra(cells, 1.0 / n, origin, keep,
    [=](double x, double y, double z) { return offset + scale * ppiray_test::Blob(x, y, z); });
}

bool All(int, int, int)
{
  return true;
}

// n^3 voxels over [0, 1]^3 split into six tetrahedra around a main diagonal,
// the voxels with i + j + k odd mirrored in x: neighbours along y and z split
// their shared face along different diagonals, and a flat tetrahedron of the
// face's four corners fills the gap between the two triangulations (what
// vtkDataSetTriangleFilter leaves between differently split hexahedra).
vtkSmartPointer<vtkUnstructuredGrid> MismatchedVoxels(int n)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        const double x = double(i) / n, y = double(j) / n, z = double(k) / n;
        points->InsertNextPoint(x, y, z);
        s->InsertNextValue(ppiray_test::Blob(x, y, z));
      }
    }
  }
  auto id = [n](int i, int j, int k) { return vtkIdType(i + (n + 1) * (j + (n + 1) * k)); };
  auto mirrored = [](int i, int j, int k) { return (i + j + k) % 2 == 1; };
  const int paths[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  vtkNew<vtkCellArray> cells;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const bool m = mirrored(i, j, k);
        for (const auto& path : paths)
        {
          int c[3] = { m ? 1 : 0, 0, 0 };
          vtkIdType tet[4] = { id(i + c[0], j, k), 0, 0, 0 };
          for (int step = 0; step < 3; ++step)
          {
            c[path[step]] += (path[step] == 0 && m) ? -1 : 1;
            tet[step + 1] = id(i + c[0], j + c[1], k + c[2]);
          }
          cells->InsertNextCell(4, tet);
        }
        if (j + 1 < n && m != mirrored(i, j + 1, k))
        {
          const vtkIdType flat[4] = { id(i, j + 1, k), id(i + 1, j + 1, k), id(i + 1, j + 1, k + 1),
            id(i, j + 1, k + 1) };
          cells->InsertNextCell(4, flat);
        }
        if (k + 1 < n && m != mirrored(i, j, k + 1))
        {
          const vtkIdType flat[4] = { id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
            id(i, j + 1, k + 1) };
          cells->InsertNextCell(4, flat);
        }
      }
    }
  }
  grid->SetPoints(points);
  grid->SetCells(VTK_TETRA, cells);
  grid->GetPointData()->SetScalars(s);
  return grid;
}

void CoolToWarm(vtkVolumeProperty* property, double lo, double hi, double maxOpacity)
{
  vtkNew<vtkColorTransferFunction> color;
  color->SetColorSpaceToDiverging();
  color->AddRGBPoint(lo, 0.231373, 0.298039, 0.752941);
  color->AddRGBPoint(hi, 0.705882, 0.0156863, 0.14902);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(hi, maxOpacity);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.25);
}

int Run(const SceneCase& scene)
{
  ppiray_test::Scene window(Size, Size);
  scene.TransferFunction(window.Property);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  mapper->SetScalarModeToUsePointFieldData();
  if (scene.CellScalars)
  {
    mapper->SetScalarModeToUseCellFieldData();
  }
  mapper->SelectScalarArray(scene.Array.c_str());
  mapper->CountCellStepsOn();
  if (scene.Configure)
  {
    scene.Configure(mapper);
  }
  window.Show(mapper, scene.Grid, { 2.2, 1.4, 2.6 }, { 0.5, 0.5, 0.5 });
  window.Window->Render();
  const auto bytes = ppiray_test::ReadRGB(window.Window);
  std::vector<double> gpu(bytes.begin(), bytes.end());
  for (double& v : gpu)
  {
    v /= 255.0;
  }

  vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
  reference->SetInputData(scene.Grid);
  reference->SetVolumeProperty(window.Property);
  reference->SetCamera(window.Renderer->GetActiveCamera());
  reference->SetImageSize(Size, Size);
  reference->SetInputArrayToProcess(0, 0, 0,
    scene.CellScalars ? vtkDataObject::FIELD_ASSOCIATION_CELLS
                      : vtkDataObject::FIELD_ASSOCIATION_POINTS,
    (scene.BruteForceArray.empty() ? scene.Array : scene.BruteForceArray).c_str());
  reference->Update();
  auto* rgba = vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetScalars());
  std::vector<double> exact(3 * Size * Size);
  for (int p = 0; p < Size * Size; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      // as 8 bits over black, like the window
      exact[3 * p + c] = std::round(255.0 * std::min(1.0, double(rgba->GetComponent(p, c)))) / 255;
    }
  }

  const double step = 1.0 / 2048; // the mesh is the unit cube
  const auto march = ppiray_test::BruteForceMarch(window.Renderer, scene.Grid, window.Property,
    (scene.BruteForceArray.empty() ? scene.Array : scene.BruteForceArray).c_str(),
    scene.CellScalars, Size, Size, step);

  const Statistics gpuMarch = Difference(gpu, march.RGB);
  const Statistics refMarch = Difference(exact, march.RGB);
  const Statistics gpuRef = Difference(gpu, exact);
  const int coveredGPU = CoveredPixels(gpu), coveredMarch = CoveredPixels(march.RGB);
  std::printf("%-24s covered %4d (march %4d, %.1f M samples) | GPU-march p99 %.2f max %.2f | "
              "reference-march p99 %.2f max %.2f | GPU-reference p99 %.2f max %.2f\n",
    scene.Name.c_str(), coveredGPU, coveredMarch, 1e-6 * march.Samples, gpuMarch.P99, gpuMarch.Max,
    refMarch.P99, refMarch.Max, gpuRef.P99, gpuRef.Max);
  std::fflush(stdout);
  int errors = 0;
  auto fail = [&](bool bad, const char* what)
  {
    if (bad)
    {
      std::printf("FAILED: %s: %s\n", scene.Name.c_str(), what);
      ++errors;
    }
  };
  fail(coveredMarch < Size * Size / 20, "the scene covers too few pixels to test anything");
  fail(std::abs(coveredGPU - coveredMarch) > 0.01 * coveredMarch,
    "GPU and march cover different pixel counts");
  fail(gpuMarch.NaN + refMarch.NaN > 0, "NaN pixels");
  fail(gpuMarch.P99 > 1.0 || gpuMarch.Max > 3.0, "GPU against the march");
  fail(refMarch.P99 > 1.0 || refMarch.Max > 3.0, "reference against the march");
  fail(gpuRef.P99 > 1.0 || gpuRef.Max > 2.0, "GPU against the reference");
  if (scene.CellStepsComparable && march.OpaqueRays == 0)
  {
    // The same rays: every cell the march meets the mapper steps through;
    // the march misses crossings shorter than its step and those within
    // vtkCell::EvaluatePosition's parametric tolerance (0.001) of the last
    // sample's cell (Documentation/accuracy.md: +0.6 % here, +1.4 % with a
    // step 4 times longer). A count one cell short per ray is 10-13 % low.
    const double steps = static_cast<double>(mapper->GetStatistics()->GetNumberOfCellSteps());
    const double met = static_cast<double>(march.CellsMet);
    std::printf("%-24s cell steps %.0f, cells met by the march %.0f (%+.3f %%)\n",
      scene.Name.c_str(), steps, met, 100.0 * (steps - met) / met);
    fail(!(steps >= 0.999 * met && steps <= 1.01 * met), "cell steps against the march");
    ++CellStepScenes;
  }
  if (scene.MaximumPeels > 0)
  {
    std::printf("%-24s peels %d (at most %d)\n", scene.Name.c_str(),
      mapper->GetStatistics()->GetNumberOfPeels(), scene.MaximumPeels);
    fail(mapper->GetStatistics()->GetNumberOfPeels() > scene.MaximumPeels,
      "more peels than the geometry needs");
  }
  return errors;
}
}

int TestGPURayCastBruteForce(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  std::vector<SceneCase> scenes;
  const double toPercent = 100.0 / 1.3; // Blob spans about [0, 1.3]
  scenes.push_back({ "thin opacity spike", Block(6, All, toPercent), "s", false,
    [](vtkVolumeProperty* p) { ppiray_test::SpikeTransferFunction(p); } });
  // Two parts (a gap at i = 2) and a hole through the larger one.
  scenes.push_back({ "non-convex, two parts",
    Block(
      8, [](int i, int j, int k) { return i != 2 && !(i >= 4 && i <= 5 && j >= 3 && j <= 4); },
      toPercent),
    "s", false,
    [](vtkVolumeProperty* p) { ppiray_test::SmoothTransferFunction(p, 0, 100, 0.8, 0.2); } });
  {
    auto grid = Block(6, All);
    vtkNew<vtkDoubleArray> centroid;
    centroid->SetName("centroid");
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      double x[3] = { 0, 0, 0 }, p[3];
      for (int v = 0; v < 4; ++v)
      {
        grid->GetPoint(grid->GetCell(c)->GetPointId(v), p);
        for (int i = 0; i < 3; ++i)
        {
          x[i] += 0.25 * p[i];
        }
      }
      centroid->InsertNextValue(ppiray_test::Blob(x[0], x[1], x[2]));
    }
    grid->GetCellData()->AddArray(centroid);
    scenes.push_back({ "cell scalars", grid, "centroid", true,
      [](vtkVolumeProperty* p) { ppiray_test::SmoothTransferFunction(p, 0.0, 1.3, 0.8, 0.2); } });
  }
  scenes.push_back({ "Cool to Warm (Diverging)", Block(6, All), "s", false,
    [](vtkVolumeProperty* p) { CoolToWarm(p, 0.0, 1.3, 0.9); } });
  scenes.push_back({ "Lab, three nodes", Block(6, All), "s", false,
    [](vtkVolumeProperty* p)
    {
      vtkNew<vtkColorTransferFunction> color;
      color->SetColorSpaceToLab();
      color->AddRGBPoint(0.0, 0.05, 0.1, 0.9);
      color->AddRGBPoint(0.7, 0.95, 0.95, 0.2);
      color->AddRGBPoint(1.3, 0.9, 0.05, 0.05);
      vtkNew<vtkPiecewiseFunction> opacity;
      opacity->AddPoint(0.2, 0.0);
      opacity->AddPoint(0.8, 0.3);
      opacity->AddPoint(1.3, 0.9);
      p->SetColor(color);
      p->SetScalarOpacity(opacity);
      p->SetScalarOpacityUnitDistance(0.2);
    } });
  {
    // Every other tetrahedron with two corners swapped (negative orientation).
    auto grid = Block(6, All);
    vtkNew<vtkCellArray> cells;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      grid->GetCellPoints(c, npts, pts);
      vtkIdType tet[4] = { pts[0], pts[1], pts[2], pts[3] };
      if (c % 2)
      {
        std::swap(tet[1], tet[2]);
      }
      cells->InsertNextCell(4, tet);
    }
    grid->SetCells(VTK_TETRA, cells);
    scenes.push_back({ "inverted cells", grid, "s", false,
      [](vtkVolumeProperty* p) { CoolToWarm(p, 0.0, 1.3, 0.9); } });
  }
  {
    // Zero-volume tetrahedra on interior faces: a face's three corners and
    // its centroid (a new point with the interpolated scalar), or, every
    // other one, a corner twice (a collapsed cell).
    auto grid = Block(6, All);
    vtkDataArray* s = grid->GetPointData()->GetArray("s");
    const vtkIdType cells = grid->GetNumberOfCells();
    for (vtkIdType c = 0; c < cells; c += 7)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      grid->GetCellPoints(c, npts, pts);
      const vtkIdType face[3] = { pts[0], pts[1], pts[2] };
      double centroid[3] = { 0, 0, 0 }, value = 0;
      for (vtkIdType id : face)
      {
        double p[3];
        grid->GetPoint(id, p);
        for (int i = 0; i < 3; ++i)
        {
          centroid[i] += p[i] / 3;
        }
        value += s->GetComponent(id, 0) / 3;
      }
      if (c % 2)
      {
        const vtkIdType collapsed[4] = { face[0], face[0], face[1], face[2] };
        grid->InsertNextCell(VTK_TETRA, 4, collapsed);
        continue;
      }
      const vtkIdType m = grid->GetPoints()->InsertNextPoint(centroid);
      s->InsertNextTuple1(value);
      const vtkIdType flat[4] = { face[0], face[1], face[2], m };
      grid->InsertNextCell(VTK_TETRA, 4, flat);
    }
    scenes.push_back({ "zero-volume cells", grid, "s", false,
      [](vtkVolumeProperty* p) { CoolToWarm(p, 0.0, 1.3, 0.9); }, nullptr, "", 1, false });
  }
  scenes.push_back({ "quadrilateral slivers", MismatchedVoxels(6), "s", false,
    [](vtkVolumeProperty* p) { CoolToWarm(p, 0.0, 1.3, 0.9); }, nullptr, "", 1, false });
  {
    // A layer of inverted cells: the mesh folds back on itself.
    auto grid = Block(6, All);
    ppiray_test::FoldLayers(grid);
    ppiray_test::WorldLinearField(grid);
    scenes.push_back({ "folded layer", grid, "s", false,
      [](vtkVolumeProperty* p) { CoolToWarm(p, 0.0, 1.3, 0.9); }, nullptr, "", 0, false });
  }
  {
    // A second block (half the size) overlapping the first, unconnected.
    vtkNew<vtkAppendFilter> append;
    auto second = Block(3, All);
    for (vtkIdType i = 0; i < second->GetNumberOfPoints(); ++i)
    {
      double x[3];
      second->GetPoint(i, x);
      second->GetPoints()->SetPoint(i, 0.45 + 0.6 * x[0], 0.3 + 0.6 * x[1], 0.2 + 0.6 * x[2]);
    }
    append->AddInputData(Block(6, All));
    append->AddInputData(second);
    append->Update();
    vtkSmartPointer<vtkUnstructuredGrid> grid = append->GetOutput();
    ppiray_test::WorldLinearField(grid);
    scenes.push_back({ "overlapping parts", grid, "s", false,
      [](vtkVolumeProperty* p) { CoolToWarm(p, 0.0, 1.3, 0.9); }, nullptr, "", 0, false });
  }
  scenes.push_back({ "scalars near 1e6", Block(6, All, 1.0, 1e6), "s", false,
    [](vtkVolumeProperty* p) { CoolToWarm(p, 1e6, 1e6 + 1.3, 0.9); } });
  {
    // A vector whose magnitude is the blob; the march reads the blob.
    auto grid = Block(6, All);
    vtkDataArray* s = grid->GetPointData()->GetArray("s");
    vtkNew<vtkDoubleArray> vectors;
    vectors->SetName("v");
    vectors->SetNumberOfComponents(3);
    for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
    {
      const double v = s->GetComponent(i, 0);
      vectors->InsertNextTuple3(0.6 * v, -0.8 * v, 0.0);
    }
    grid->GetPointData()->AddArray(vectors);
    scenes.push_back({ "vector magnitude", grid, "v", false,
      [](vtkVolumeProperty* p) { CoolToWarm(p, 0.0, 1.3, 0.9); }, nullptr, "s" });
  }

  int errors = 0;
  for (const auto& scene : scenes)
  {
    errors += Run(scene);
  }
  if (CellStepScenes < 5)
  {
    std::printf("FAILED: cell steps compared in %d scenes, expected at least 5\n", CellStepScenes);
    ++errors;
  }
  return errors == 0 ? 0 : 1;
}
