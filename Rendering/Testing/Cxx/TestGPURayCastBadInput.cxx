// Bad input gets a clear message and a defined result, never a crash:
// an empty grid (renders nothing, silently), a grid without scalars (error),
// NaN scalars (warning; the touching cells render empty, nothing else
// changes), unsupported cells only (error naming the type and count), a mix
// of tetrahedra and a 2D cell (error; the tetrahedra still render), quadratic
// cells (warning; rendered through their corners) and a zero-volume
// tetrahedron (warning; skipped), infinite scalars or coordinates (error,
// nothing drawn), a 3-component array (magnitude by default; a component
// out of range: warning, the last one), cells with point ids out of range
// (one error with their count; the other cells render as without them, in
// the mapper and in the reference renderer), a unit distance of 0 (warning;
// rendered with 1, in every blend mode), a scalar array with fewer values
// than points (error, nothing drawn), cells listing more point ids than
// their type has (warning with the count; their first ids, as in VTK).

#include "PPIRayImageCompare.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkStringOutputWindow.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkUnstructuredGridReferenceRenderer.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>

namespace
{
struct Outcome
{
  std::string Errors;
  std::string Warnings;
  std::vector<unsigned char> Image;
};

Outcome RenderGrid(vtkUnstructuredGrid* grid,
  const std::function<void(vtkUnstructuredGridGPURayCastMapper*)>& configure = nullptr,
  double unitDistance = 0.2, int frames = 1)
{
  ppiray_test::Scene scene(100, 100);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, unitDistance);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  ppiray_test::UseTetrahedronLayout(mapper);
  vtkNew<ppiray_test::MessageCollector> observer;
  mapper->AddObserver(vtkCommand::ErrorEvent, observer);
  mapper->AddObserver(vtkCommand::WarningEvent, observer);
  mapper->SetInputData(grid);
  if (configure)
  {
    configure(mapper);
  }
  scene.Volume->SetMapper(mapper);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.5, 0.5, 3.0);
  camera->SetFocalPoint(0.5, 0.5, 0.5);
  camera->SetClippingRange(0.5, 5.0);
  camera->SetViewAngle(40);
  for (int frame = 0; frame < frames; ++frame)
  {
    scene.Window->Render();
  }
  Outcome outcome;
  outcome.Errors = observer->Errors;
  outcome.Warnings = observer->Warnings;
  outcome.Image = ppiray_test::ReadRGB(scene.Window);
  return outcome;
}

int Lit(const std::vector<unsigned char>& image)
{
  int lit = 0;
  for (unsigned char c : image)
  {
    lit += c > 0 ? 1 : 0;
  }
  return lit;
}

int Expect(bool condition, const char* what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << "\n";
    return 1;
  }
  return 0;
}
}

int TestGPURayCastBadInput(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  const int n[3] = { 3, 3, 3 };
  const double origin[3] = { 0, 0, 0 };
  auto good = ppiray_test::VoxelTetrahedra(
    n, 1.0 / 3, origin, [](int, int, int) { return true; }, ppiray_test::Blob);
  int errors = 0;

  const Outcome reference = RenderGrid(good);
  errors += Expect(reference.Errors.empty() && Lit(reference.Image) > 1000, "good grid renders");

  vtkNew<vtkUnstructuredGrid> empty;
  const Outcome e = RenderGrid(empty);
  errors += Expect(e.Errors.empty() && Lit(e.Image) == 0, "empty grid: nothing, no error");

  vtkNew<vtkUnstructuredGrid> noScalars;
  noScalars->DeepCopy(good);
  noScalars->GetPointData()->RemoveArray("s");
  const Outcome ns = RenderGrid(noScalars);
  std::cout << "no scalars: " << ns.Errors << "\n";
  errors += Expect(ns.Errors.find("No scalars") != std::string::npos && Lit(ns.Image) == 0,
    "no scalars: error, nothing drawn");

  vtkNew<vtkUnstructuredGrid> nan;
  nan->DeepCopy(good);
  nan->GetPointData()->GetScalars()->SetTuple1(0, std::numeric_limits<double>::quiet_NaN());
  const Outcome nn = RenderGrid(nan);
  std::cout << "NaN scalars: " << nn.Warnings << "\n";
  const auto d = ppiray_test::Compare(reference.Image, nn.Image);
  errors +=
    Expect(nn.Warnings.find("NaN") != std::string::npos && d.Max > 0 && Lit(nn.Image) > 1000,
      "NaN scalars: warning, the touching cells change, the rest renders");

  // Cells listing more point ids than their type has (each tetrahedron with
  // two more): one warning with the count; rendered through their first
  // ids, as VTK's cells are, the same image.
  {
    vtkNew<vtkUnstructuredGrid> extra;
    extra->SetPoints(good->GetPoints());
    extra->GetPointData()->ShallowCopy(good->GetPointData());
    for (vtkIdType c = 0; c < good->GetNumberOfCells(); ++c)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      good->GetCellPoints(c, npts, pts);
      const vtkIdType ids[6] = { pts[0], pts[1], pts[2], pts[3], pts[0], pts[2] };
      extra->InsertNextCell(VTK_TETRA, 6, ids);
    }
    const Outcome x = RenderGrid(extra);
    const auto diff = ppiray_test::Compare(reference.Image, x.Image);
    std::cout << "extra point ids: " << x.Warnings << "max " << diff.Max << "\n";
    errors += Expect(x.Warnings.find(std::to_string(good->GetNumberOfCells()) +
                                     " cells list more point ids than their type has (a "
                                     "vtkTetra with 6, not 4)") != std::string::npos &&
                       x.Errors.empty() && diff.Max == 0,
      "extra point ids: one warning with the count, the image of the first ids");
  }

  // Unsupported 3D cells only (a pentagonal prism: 10 corners).
  vtkNew<vtkUnstructuredGrid> prisms;
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> prismScalars;
  vtkIdType prism[10];
  for (int i = 0; i < 10; ++i)
  {
    const double angle = 2.0 * 3.141592653589793 * (i % 5) / 5.0;
    prism[i] = points->InsertNextPoint(std::cos(angle), std::sin(angle), i < 5 ? 0.0 : 1.0);
    prismScalars->InsertNextValue(0.1 * i);
  }
  prisms->SetPoints(points);
  prisms->InsertNextCell(VTK_PENTAGONAL_PRISM, 10, prism);
  prisms->GetPointData()->SetScalars(prismScalars);
  const Outcome h = RenderGrid(prisms);
  std::cout << "pentagonal prism: " << h.Errors << "\n";
  errors += Expect(h.Errors.find("1 vtkPentagonalPrism") != std::string::npos && Lit(h.Image) == 0,
    "unsupported cells only: error naming type and count, nothing drawn");

  // Point ids out of range (negative, past the last point) in two cells
  // among good ones (point and cell scalars): one error with the count, the
  // good cells render as they would alone; the reference renderer the same.
  for (const bool cellData : { false, true })
  {
    vtkNew<vtkUnstructuredGrid> clean, bad;
    clean->DeepCopy(good);
    if (cellData)
    {
      vtkNew<vtkDoubleArray> values;
      values->SetName("c");
      for (vtkIdType c = 0; c < clean->GetNumberOfCells(); ++c)
      {
        values->InsertNextValue(0.2 + 0.9 * (c % 7) / 7.0);
      }
      clean->GetCellData()->SetScalars(values);
      clean->GetPointData()->SetScalars(nullptr);
    }
    bad->DeepCopy(clean);
    const vtkIdType n = bad->GetNumberOfPoints();
    const vtkIdType negative[4] = { 0, 1, -3, 2 }, past[4] = { 0, 1, 2, n + 5 };
    // The bad cells first: every good cell's id moves by two.
    vtkNew<vtkUnstructuredGrid> shifted;
    shifted->SetPoints(bad->GetPoints());
    shifted->GetPointData()->ShallowCopy(bad->GetPointData());
    shifted->InsertNextCell(VTK_TETRA, 4, negative);
    shifted->InsertNextCell(VTK_TETRA, 4, past);
    for (vtkIdType c = 0; c < bad->GetNumberOfCells(); ++c)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      bad->GetCellPoints(c, npts, pts);
      shifted->InsertNextCell(bad->GetCellType(c), npts, pts);
    }
    if (cellData)
    {
      vtkNew<vtkDoubleArray> values;
      values->SetName("c");
      values->InsertNextValue(5.0);
      values->InsertNextValue(5.0);
      for (vtkIdType c = 0; c < clean->GetNumberOfCells(); ++c)
      {
        values->InsertNextValue(clean->GetCellData()->GetScalars()->GetTuple1(c));
      }
      shifted->GetCellData()->SetScalars(values);
    }
    const Outcome alone = RenderGrid(clean);
    const Outcome withBad = RenderGrid(shifted);
    const auto diff = ppiray_test::Compare(alone.Image, withBad.Image);
    std::cout << "ids out of range (" << (cellData ? "cell" : "point")
              << " scalars): " << withBad.Errors << "max " << diff.Max << "\n";
    errors += Expect(withBad.Errors.find("2 cells list point ids outside [0, " + std::to_string(n) +
                                         ")") != std::string::npos &&
                       diff.Max <= 1 && Lit(withBad.Image) > 1000,
      "ids out of range: one error with the count, the other cells render as alone");
    vtkNew<ppiray_test::MessageCollector> referenceMessages;
    vtkNew<vtkUnstructuredGridReferenceRenderer> reference;
    reference->AddObserver(vtkCommand::ErrorEvent, referenceMessages);
    vtkNew<vtkCamera> camera;
    camera->SetPosition(0.5, 0.5, 3.0);
    camera->SetFocalPoint(0.5, 0.5, 0.5);
    camera->SetClippingRange(0.5, 5.0);
    camera->SetViewAngle(40);
    vtkNew<vtkVolumeProperty> property;
    ppiray_test::SmoothTransferFunction(property, 0.0, 1.3, 0.8, 0.2);
    reference->SetCamera(camera);
    reference->SetVolumeProperty(property);
    reference->SetImageSize(64, 64);
    double sums[2] = { 0, 0 };
    for (int k = 0; k < 2; ++k)
    {
      reference->SetInputData(k == 0 ? clean.Get() : shifted.Get());
      reference->Update();
      vtkDataArray* rgba = reference->GetOutput()->GetPointData()->GetScalars();
      for (vtkIdType p = 0; p < rgba->GetNumberOfTuples(); ++p)
      {
        sums[k] += rgba->GetComponent(p, 3);
      }
    }
    errors += Expect(
      referenceMessages->Errors.find("2 cells list point ids outside") != std::string::npos &&
        sums[0] > 10 && std::abs(sums[0] - sums[1]) < 1e-9 * sums[0],
      "ids out of range: the reference renderer reports them and renders the other cells");
  }

  // Tetrahedra plus one triangle (a 2D cell): error, the tetrahedra still render.
  vtkNew<vtkUnstructuredGrid> mixed;
  mixed->DeepCopy(good);
  const vtkIdType triangle[3] = { 0, 1, 2 };
  mixed->InsertNextCell(VTK_TRIANGLE, 3, triangle);
  const Outcome m = RenderGrid(mixed);
  errors += Expect(m.Errors.find("1 vtkTriangle") != std::string::npos &&
                     ppiray_test::Compare(reference.Image, m.Image).Max == 0,
    "tetrahedra and a triangle: error, tetrahedra render unchanged");

  // The same tetrahedra as quadratic tetrahedra with their mid-edge nodes on
  // the corners (a map that folds, ppirayQuadraticTetrahedra.h): warning,
  // rendered through their corners, image unchanged.
  vtkNew<vtkUnstructuredGrid> quadratic;
  quadratic->SetPoints(good->GetPoints());
  quadratic->GetPointData()->ShallowCopy(good->GetPointData());
  for (vtkIdType c = 0; c < good->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    good->GetCellPoints(c, npts, pts);
    const vtkIdType ten[10] = { pts[0], pts[1], pts[2], pts[3], pts[0], pts[1], pts[2], pts[3],
      pts[0], pts[1] };
    quadratic->InsertNextCell(VTK_QUADRATIC_TETRA, 10, ten);
  }
  const Outcome q = RenderGrid(quadratic);
  std::cout << "quadratic: " << q.Warnings << "\n";
  errors += Expect(q.Warnings.find("quadratic") != std::string::npos && q.Errors.empty() &&
                     ppiray_test::Compare(reference.Image, q.Image).Max == 0,
    "quadratic tetrahedra: warning, rendered through their corners");

  // A zero-volume tetrahedron added: warning, image unchanged.
  vtkNew<vtkUnstructuredGrid> flat;
  flat->DeepCopy(good);
  vtkIdType flatIds[4];
  const double corners[4][3] = { { 0.2, 0.2, 0.5 }, { 0.8, 0.2, 0.5 }, { 0.2, 0.8, 0.5 },
    { 0.8, 0.8, 0.5 } };
  for (int v = 0; v < 4; ++v)
  {
    flatIds[v] = flat->GetPoints()->InsertNextPoint(corners[v]);
    flat->GetPointData()->GetScalars()->InsertNextTuple1(1.0);
  }
  flat->InsertNextCell(VTK_TETRA, 4, flatIds);
  const Outcome f = RenderGrid(flat);
  std::cout << "flat: " << f.Warnings << "\n";
  errors += Expect(f.Warnings.find("zero-volume") != std::string::npos &&
                     ppiray_test::Compare(reference.Image, f.Image).Max <= 1,
    "zero-volume tetrahedron: warning, image unchanged");

  // Infinite scalars and coordinates: error, nothing drawn.
  vtkNew<vtkUnstructuredGrid> infinite;
  infinite->DeepCopy(good);
  infinite->GetPointData()->GetScalars()->SetTuple1(3, std::numeric_limits<double>::infinity());
  const Outcome is = RenderGrid(infinite);
  std::cout << "infinite scalar: " << is.Errors << "\n";
  errors += Expect(is.Errors.find("infinite values") != std::string::npos && Lit(is.Image) == 0,
    "infinite scalar: error, nothing drawn");
  vtkNew<vtkUnstructuredGrid> far;
  far->DeepCopy(good);
  far->GetPoints()->SetPoint(5, 0.0, -std::numeric_limits<double>::infinity(), 0.0);
  const Outcome ic = RenderGrid(far);
  std::cout << "infinite coordinate: " << ic.Errors << "\n";
  errors += Expect(
    ic.Errors.find("infinite or NaN point coordinates") != std::string::npos && Lit(ic.Image) == 0,
    "infinite coordinate: error, nothing drawn");

  // A scalar array shorter than the point list (a reader's truncated array):
  // error naming both counts, once over three frames, nothing drawn, nothing
  // read past its end.
  vtkNew<vtkUnstructuredGrid> shortScalars;
  shortScalars->DeepCopy(good);
  shortScalars->GetPointData()->GetScalars()->SetNumberOfTuples(good->GetNumberOfPoints() - 3);
  const Outcome sh = RenderGrid(shortScalars, nullptr, 0.2, 3);
  std::cout << "short scalar array, 3 frames: " << sh.Errors << "\n";
  const std::string shortMessage = std::to_string(good->GetNumberOfPoints() - 3) + " values for " +
                                   std::to_string(good->GetNumberOfPoints()) + " points";
  const size_t first = sh.Errors.find(shortMessage);
  errors +=
    Expect(first != std::string::npos &&
             sh.Errors.find(shortMessage, first + 1) == std::string::npos && Lit(sh.Image) == 0,
      "short scalar array: one error over three frames, nothing drawn");

  // A 3-component array (s, 0, 0): magnitude |s| = s renders as the scalar;
  // component 7 of 3: warning, component 2 (zero everywhere: dark).
  vtkNew<vtkUnstructuredGrid> vectors;
  vectors->DeepCopy(good);
  vtkNew<vtkDoubleArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  vtkDataArray* scalar = good->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < scalar->GetNumberOfTuples(); ++i)
  {
    v->InsertNextTuple3(scalar->GetTuple1(i), 0.0, 0.0);
  }
  vectors->GetPointData()->SetScalars(v);
  const Outcome vm = RenderGrid(vectors);
  errors += Expect(vm.Errors.empty() && vm.Warnings.empty() &&
                     ppiray_test::Compare(reference.Image, vm.Image).Max == 0,
    "3-component array by magnitude renders as its scalar");
  const Outcome vc = RenderGrid(vectors,
    [](vtkUnstructuredGridGPURayCastMapper* mapper)
    {
      mapper->SetVectorModeToComponent();
      mapper->SetVectorComponent(7);
    });
  std::cout << "component 7 of 3: " << vc.Warnings << "\n";
  errors += Expect(vc.Warnings.find("using 2") != std::string::npos &&
                     ppiray_test::Compare(reference.Image, vc.Image).Max > 10,
    "component out of range: warning, the last component rendered");
  // ScalarOpacityUnitDistance 0 (found by the fuzz driver: a projection was
  // coloured with alpha = opacity x 0, nothing drawn): a warning, and every
  // blend mode renders as with the unit distance 1 it falls back to.
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  vtkNew<vtkStringOutputWindow> printed; // the warning comes from the transfer function
  vtkOutputWindow::SetInstance(printed);
  for (const int blend : { 0, 1, 3 })
  {
    auto withUnit = [&](double unit)
    {
      return RenderGrid(
        good, [&](vtkUnstructuredGridGPURayCastMapper* mapper) { mapper->SetBlendMode(blend); },
        unit);
    };
    const Outcome zero = withUnit(0.0), one = withUnit(1.0);
    const auto d = ppiray_test::Compare(zero.Image, one.Image);
    std::cout << "unit distance 0, blend mode " << blend << ": max " << d.Max << " against 1, "
              << Lit(zero.Image) << " lit\n";
    errors += Expect(printed->GetOutput().find("not positive") != std::string::npos && d.Max == 0 &&
                       Lit(zero.Image) > 1000,
      "unit distance 0: a warning, rendered as with unit distance 1");
  }
  vtkOutputWindow::SetInstance(previous);

  return errors == 0 ? 0 : 1;
}
