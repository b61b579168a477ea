// The reference renderer's path for hexahedra (and the other linear 3D cells):
// 1. a sheared grid of hexahedra with a linear scalar field (trilinear
//    interpolation of a linear field is the same field; planar faces) renders
//    like the same grid split into tetrahedra: the two exact paths agree to 1e-7;
// 2. one hexahedron with non-planar faces and a trilinear field
//    (s = 2 x y z + x): every pixel against a brute-force march of 20,000
//    steps with the cell's own interpolation. The march converges to the
//    reference (measured 1.75e-4 at 20,000 steps, 1.04e-4 at 40,000); bound
//    3e-4, while a wrong interval or field shows as 1e-2 to 0.5;
// 3. a voxel (vtkImageData's cell type, other point order) like a hexahedron;
// 4. a NaN point scalar: the cells touching it are empty and the rest renders
//    as the grid without them (the linearization of a NaN field never
//    converged and bisected every ray piece 24 levels deep: a real FE result
//    with NaN in a normalized stress never finished);
// 5. hexahedra listing 20 point ids (a serendipity hexahedron written as
//    VTK_HEXAHEDRON, mid-edge values NaN) render from their 8 corners;
// 6. progress events go from 0 to 1 in order;
// 7. a constant field renders as the same cells as tetrahedra, quickly;
// 8. Lagrange hexahedra of order 3 (64 nodes), Lagrange and Bezier wedges of
//    order 2 (18 nodes; VTK 9.2's Lagrange wedge takes points with r + s > 1
//    for inside, its Bezier wedge fails from two threads) with the linear
//    field of 1. render like the same cells as hexahedra.

#include "vtkBezierWedge.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkLagrangeHexahedron.h"
#include "vtkLagrangeWedge.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReferenceRenderer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace
{
constexpr int Size = 24;

vtkSmartPointer<vtkFloatArray> Render(
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera)
{
  vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetVolumeProperty(property);
  reference->SetCamera(camera);
  reference->SetImageSize(Size, Size);
  reference->Update();
  return vtkFloatArray::SafeDownCast(reference->GetOutput()->GetPointData()->GetScalars());
}

double MaxDifference(vtkFloatArray* a, vtkFloatArray* b)
{
  double worst = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    worst = std::max(worst, std::abs(double(a->GetValue(i)) - b->GetValue(i)));
  }
  return worst;
}

// Cells of an n^3 grid over [0, 1]^3 moved by `map`, field f(x); `type`
// VTK_HEXAHEDRON or VTK_VOXEL (point orders differ).
vtkSmartPointer<vtkUnstructuredGrid> Grid(int n, int type, const std::function<void(double*)>& map,
  const std::function<double(const double*)>& f)
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
        double x[3] = { double(i) / n, double(j) / n, double(k) / n };
        map(x);
        points->InsertNextPoint(x);
        s->InsertNextValue(f(x));
      }
    }
  }
  grid->SetPoints(points);
  auto id = [n](int i, int j, int k) { return vtkIdType((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        const vtkIdType voxel[8] = { hex[0], hex[1], hex[3], hex[2], hex[4], hex[5], hex[7],
          hex[6] };
        grid->InsertNextCell(type, 8, type == VTK_VOXEL ? voxel : hex);
      }
    }
  }
  grid->GetPointData()->SetScalars(s);
  return grid;
}
// A higher-order cell of `count` nodes (its order set from the count).
template<class Cell>
vtkSmartPointer<Cell> Prototype(int count)
{
  auto cell = vtkSmartPointer<Cell>::New();
  cell->GetPointIds()->SetNumberOfIds(count);
  cell->GetPoints()->SetNumberOfPoints(count);
  cell->SetUniformOrderFromNumPoints(count);
  return cell;
}

// The cells of Grid(3, ...) as cells of the type of `prototype`, their nodes
// at its parametric coordinates: one per cube for a hexahedron, (r, s, t) and
// (1 - r, 1 - s, t) for a wedge; nodes not shared.
vtkSmartPointer<vtkUnstructuredGrid> HigherOrderCells(vtkCell* prototype,
  const std::function<void(double*)>& map, const std::function<double(const double*)>& f)
{
  const int count = static_cast<int>(prototype->GetNumberOfPoints());
  const int type = prototype->GetCellType();
  const double* nodes = prototype->GetParametricCoords();
  const bool wedge = prototype->GetNumberOfFaces() == 5;
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> values;
  values->SetName("s");
  for (int c = 0; c < 27 * (wedge ? 2 : 1); ++c)
  {
    const int cube = wedge ? c / 2 : c;
    const bool flip = wedge && c % 2 == 1;
    std::vector<vtkIdType> ids(count);
    for (int i = 0; i < count; ++i)
    {
      const double* p = nodes + 3 * i;
      double x[3] = { (cube % 3 + (flip ? 1 - p[0] : p[0])) / 3,
        (cube / 3 % 3 + (flip ? 1 - p[1] : p[1])) / 3, (cube / 9 + p[2]) / 3 };
      map(x);
      ids[i] = points->InsertNextPoint(x);
      values->InsertNextValue(f(x));
    }
    grid->InsertNextCell(type, count, ids.data());
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(values);
  return grid;
}
}

int TestReferenceRendererGeneralCells(int, char*[])
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.1, 0.3, 0.9);
  color->AddRGBPoint(1.0, 0.9, 0.8, 0.1);
  color->AddRGBPoint(2.0, 0.8, 0.1, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.8, 0.6);
  opacity->AddPoint(0.9, 0.0);
  opacity->AddPoint(2.0, 0.4);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.3);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(2.0, 1.6, 2.4);
  camera->SetFocalPoint(0.5, 0.5, 0.5);
  camera->SetViewAngle(40);
  camera->SetClippingRange(0.5, 10);
  int errors = 0;

  // 1. Linear field, affine (sheared) grid: hexahedra against tetrahedra.
  auto shear = [](double* x)
  {
    x[0] += 0.3 * x[1];
    x[2] += 0.2 * x[0];
  };
  auto linear = [](const double* x) { return 1.2 * x[0] + 0.7 * x[1] - 0.4 * x[2] + 0.3; };
  auto hexes = Grid(3, VTK_HEXAHEDRON, shear, linear);
  vtkNew<vtkDataSetTriangleFilter> tetrahedralize;
  tetrahedralize->SetInputData(hexes);
  tetrahedralize->Update();
  auto a = Render(hexes, property, camera);
  auto b = Render(tetrahedralize->GetOutput(), property, camera);
  double brightest = 0;
  for (vtkIdType i = 0; i < b->GetNumberOfValues(); ++i)
  {
    brightest = std::max(brightest, double(b->GetValue(i)));
  }
  double worst = MaxDifference(a, b);
  std::printf("linear field, hexahedra vs tetrahedra: max difference %.2e (max value %.2f)\n",
    worst, brightest);
  if (!(worst < 1e-7) || brightest < 0.1)
  {
    std::printf("FAILED: the general-cell path disagrees with the tetrahedral one\n");
    ++errors;
  }

  // 3. Voxels: the same cells in vtkVoxel order (axis-aligned grid).
  auto none = [](double*) {};
  auto asHexes = Grid(2, VTK_HEXAHEDRON, none, linear);
  auto asVoxels = Grid(2, VTK_VOXEL, none, linear);
  worst = MaxDifference(Render(asHexes, property, camera), Render(asVoxels, property, camera));
  std::printf("voxels vs hexahedra: max difference %.2e\n", worst);
  if (!(worst < 1e-7))
  {
    std::printf("FAILED: voxels render differently from the same hexahedra\n");
    ++errors;
  }

  // 2. Trilinear field in one hexahedron with non-planar faces.
  auto twist = [](double* x)
  {
    x[2] += 0.25 * x[0] * x[1]; // bilinear bulge: faces no longer planar
    x[0] += 0.3 * x[1];
  };
  auto trilinear = [](const double* x) { return 2.0 * x[0] * x[1] * x[2] + x[0]; };
  auto one = Grid(1, VTK_HEXAHEDRON, twist, trilinear);
  auto c = Render(one, property, camera);
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(camera->GetCompositeProjectionTransformMatrix(1.0, -1, 1), inverse);
  vtkNew<vtkGenericCell> cell;
  one->GetCell(0, cell);
  double values[8];
  for (int v = 0; v < 8; ++v)
  {
    values[v] = one->GetPointData()->GetScalars()->GetTuple1(cell->GetPointId(v));
  }
  worst = 0;
  for (int py = 0; py < Size; ++py)
  {
    for (int px = 0; px < Size; ++px)
    {
      double nearP[4] = { 2.0 * (px + 0.5) / Size - 1, 2.0 * (py + 0.5) / Size - 1, -1, 1 };
      double farP[4] = { nearP[0], nearP[1], 1, 1 };
      inverse->MultiplyPoint(nearP, nearP);
      inverse->MultiplyPoint(farP, farP);
      double o[3], d[3], length = 0;
      for (int i = 0; i < 3; ++i)
      {
        o[i] = nearP[i] / nearP[3];
        d[i] = farP[i] / farP[3] - o[i];
        length += d[i] * d[i];
      }
      length = std::sqrt(length);
      // March t in [0, 6]: the cell lies within 6 of the near plane.
      const int steps = 20000;
      const double dt = 6.0 / steps;
      double rgb[3] = { 0, 0, 0 }, transmittance = 1.0;
      for (int k = 0; k < steps; ++k)
      {
        const double t = (k + 0.5) * dt;
        double x[3], pcoords[3], dist2, weights[8];
        int subId;
        for (int i = 0; i < 3; ++i)
        {
          x[i] = o[i] + t * d[i] / length;
        }
        if (cell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, weights) == -1 ||
            cell->GetParametricDistance(pcoords) > 0)
        {
          continue;
        }
        double s = 0;
        for (int v = 0; v < 8; ++v)
        {
          s += weights[v] * values[v];
        }
        double col[3];
        color->GetColor(s, col);
        const double alpha = 1.0 - std::exp(-opacity->GetValue(s) / 0.3 * dt);
        for (int i = 0; i < 3; ++i)
        {
          rgb[i] += transmittance * col[i] * alpha;
        }
        transmittance *= 1.0 - alpha;
      }
      for (int i = 0; i < 3; ++i)
      {
        worst = std::max(worst, std::abs(rgb[i] - c->GetComponent(py * Size + px, i)));
      }
    }
  }
  std::printf("trilinear field, one hexahedron vs 20000-step march: max difference %.2e\n", worst);
  if (!(worst < 3e-4))
  {
    std::printf("FAILED: the general-cell path is off the brute-force march\n");
    ++errors;
  }

  // 4. A NaN at the middle point of a 3^3 grid of hexahedra.
  auto withNaN = Grid(3, VTK_HEXAHEDRON, shear, linear);
  const vtkIdType middle = (1 * 4 + 1) * 4 + 1;
  withNaN->GetPointData()->GetScalars()->SetTuple1(middle, std::nan(""));
  vtkNew<vtkUnstructuredGrid> without;
  without->SetPoints(withNaN->GetPoints());
  without->GetPointData()->ShallowCopy(withNaN->GetPointData());
  for (vtkIdType c = 0; c < withNaN->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    withNaN->GetCellPoints(c, npts, pts);
    if (std::find(pts, pts + npts, middle) == pts + npts)
    {
      without->InsertNextCell(VTK_HEXAHEDRON, npts, pts);
    }
  }
  const double nanDifference =
    MaxDifference(Render(withNaN, property, camera), Render(without, property, camera));
  std::printf("NaN point scalar: %lld cells without it, max difference %.2e\n",
    static_cast<long long>(without->GetNumberOfCells()), nanDifference);
  if (without->GetNumberOfCells() != 19 || !(nanDifference <= 1e-7))
  {
    std::printf("FAILED: cells touching a NaN scalar are not simply empty\n");
    ++errors;
  }

  // 5. The same 27 hexahedra with 12 extra ids each, at new NaN points.
  auto plain = Grid(3, VTK_HEXAHEDRON, shear, linear);
  vtkNew<vtkUnstructuredGrid> twenty;
  vtkNew<vtkPoints> points;
  points->DeepCopy(plain->GetPoints());
  vtkNew<vtkDoubleArray> twentyValues;
  twentyValues->DeepCopy(plain->GetPointData()->GetScalars());
  for (vtkIdType c = 0; c < plain->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    plain->GetCellPoints(c, npts, pts);
    vtkIdType ids[20];
    std::copy(pts, pts + 8, ids);
    for (int k = 8; k < 20; ++k)
    {
      ids[k] = points->InsertNextPoint(0.5, 0.5, 0.5);
      twentyValues->InsertNextValue(std::nan(""));
    }
    twenty->InsertNextCell(VTK_HEXAHEDRON, 20, ids);
  }
  twenty->SetPoints(points);
  twenty->GetPointData()->SetScalars(twentyValues);
  const double twentyDifference =
    MaxDifference(Render(twenty, property, camera), Render(plain, property, camera));
  std::printf("hexahedra with 20 ids: max difference %.2e\n", twentyDifference);
  if (!(twentyDifference <= 1e-7))
  {
    std::printf("FAILED: a hexahedron with extra ids is not rendered from its corners\n");
    ++errors;
  }

  // 6. Progress: events from 0 to 1, one per tile at most, never backwards.
  {
    vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
    reference->SetInputData(plain);
    reference->SetVolumeProperty(property);
    reference->SetCamera(camera);
    reference->SetImageSize(Size, Size);
    std::vector<double> progress;
    vtkNew<vtkCallbackCommand> observer;
    observer->SetClientData(&progress);
    observer->SetCallback([](vtkObject*, unsigned long, void* client, void* data)
      { static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(data)); });
    reference->AddObserver(vtkCommand::ProgressEvent, observer);
    reference->Update();
    const bool ordered = std::is_sorted(progress.begin(), progress.end());
    std::printf("progress: %zu events, last %.2f\n", progress.size(),
      progress.empty() ? -1.0 : progress.back());
    if (progress.size() < 3 || !ordered || progress.front() != 0.0 || progress.back() != 1.0)
    {
      std::printf("FAILED: progress events do not go from 0 to 1\n");
      ++errors;
    }
  }
  // 7. A constant field (found by the fuzz driver, seed 1 case 3: the
  // tolerance relative to a zero range made the rounding of the
  // interpolation a deviation, and every ray split 2^24 times: hours, past
  // the test's time limit): equal to the same cells as tetrahedra.
  {
    auto constant = Grid(2, VTK_HEXAHEDRON, shear, [](const double*) { return 0.85; });
    vtkNew<vtkDataSetTriangleFilter> split;
    split->SetInputData(constant);
    split->Update();
    const auto start = std::chrono::steady_clock::now();
    auto c = Render(constant, property, camera);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double apart = MaxDifference(c, Render(split->GetOutput(), property, camera));
    std::printf("constant field: %.3f s, max difference to tetrahedra %.2e\n", seconds, apart);
    if (!(apart < 1e-7))
    {
      std::printf("FAILED: a constant field in general cells\n");
      ++errors;
    }
  }
  // 8. Lagrange hexahedra of order 3, Lagrange and Bezier wedges of order 2
  // (two per cube) over the sheared cells of 1.
  const std::pair<const char*, vtkSmartPointer<vtkCell>> higherOrder[] = {
    { "Lagrange hexahedra of order 3", Prototype<vtkLagrangeHexahedron>(64) },
    { "Lagrange wedges of order 2", Prototype<vtkLagrangeWedge>(18) },
    { "Bezier wedges of order 2", Prototype<vtkBezierWedge>(18) }
  };
  for (const auto& kind : higherOrder)
  {
    auto cells = HigherOrderCells(kind.second, shear, linear);
    const double apart = MaxDifference(Render(cells, property, camera), a);
    std::printf("%s vs hexahedra: max difference %.2e\n", kind.first, apart);
    if (!(apart < 1e-6))
    {
      std::printf("FAILED: %s render differently from the same hexahedra\n", kind.first);
      ++errors;
    }
  }
  return errors == 0 ? 0 : 1;
}
