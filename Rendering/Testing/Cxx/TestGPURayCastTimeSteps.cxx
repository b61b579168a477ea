// A time series' steps as a reader hands them over: a new grid object at
// every step. The mapper keeps its cells when the new grid has the same
// points and cells (ppiray::GridGeometryKey) and builds only the field;
// anything else that changed rebuilds them. For tetrahedra and for
// hexahedra marched natively, counted by the statistics (geometry uploads,
// field uploads, geometry reuses) and checked against a fresh mapper's image
// of the same step (equal to the last bit, over a covered view):
//  1. a new grid sharing the points and cells, new scalars: kept;
//  2. a new grid with deep copies of every array, other scalars: kept;
//  3. a copy with one point moved: rebuilt, the faces' pairs kept (only the
//     folds found again: the "folds" stage, not "adjacency");
//  4. a copy with one cell turned inside out (two point ids swapped): rebuilt,
//     faces matched again;
//  5. a copy with one cell hidden (the ghost array): rebuilt, the faces' pairs
//     kept, and the image differs from step 4's;
//  6. the field of step 5's grid as another grid shares it (same arrays):
//     nothing built, nothing uploaded.
// At every step the statistics name the preparation's stages, each timed
// (finite, not negative): the cells' stages ("validation", then "adjacency"
// or "folds") only where the cells were built, "geometry key" and "field"
// always. A
// build reports its progress (ProgressEvent): from 0 to 1, never back, one
// event per stage at least; a step that keeps the cells reports none.

#include "PPIRayImageCompare.h"
#include "PPIRayTestScenes.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <set>
#include <string>

namespace
{
using GridPtr = vtkSmartPointer<vtkUnstructuredGrid>;

// The grid's point scalars replaced by a new array, v -> a + b v.
void NewScalars(vtkUnstructuredGrid* grid, double a, double b)
{
  vtkDataArray* old = grid->GetPointData()->GetScalars();
  vtkNew<vtkDoubleArray> values;
  values->SetName(old->GetName());
  for (vtkIdType p = 0; p < old->GetNumberOfTuples(); ++p)
  {
    values->InsertNextValue(a + b * old->GetTuple1(p));
  }
  auto data = vtkSmartPointer<vtkPointData>::New();
  data->SetScalars(values);
  grid->GetPointData()->ShallowCopy(data);
}

GridPtr SharedCopy(vtkUnstructuredGrid* grid)
{
  auto copy = GridPtr::New();
  copy->ShallowCopy(grid);
  return copy;
}

GridPtr DeepCopy(vtkUnstructuredGrid* grid)
{
  auto copy = GridPtr::New();
  copy->DeepCopy(grid);
  return copy;
}

// Renders `grid` with `mapper`, then with a fresh mapper; the number of
// errors (images not equal, or an empty view), and the image.
int RenderAgainstFresh(ppiray_test::Scene& scene, vtkUnstructuredGridGPURayCastMapper* mapper,
  vtkUnstructuredGrid* grid, const std::string& step, std::vector<unsigned char>& image,
  std::vector<double>& progress)
{
  mapper->SetInputData(grid);
  progress.clear();
  scene.Window->Render();
  image = ppiray_test::ReadRGB(scene.Window);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> fresh;
  fresh->SetHexahedronMode(mapper->GetHexahedronMode());
  fresh->SetInputData(grid);
  scene.Volume->SetMapper(fresh);
  scene.Window->Render();
  const auto expected = ppiray_test::ReadRGB(scene.Window);
  fresh->ReleaseGraphicsResources(scene.Window);
  scene.Volume->SetMapper(mapper);
  int covered = 0;
  for (size_t i = 0; i < expected.size(); i += 3)
  {
    covered += expected[i] + expected[i + 1] + expected[i + 2] > 0 ? 1 : 0;
  }
  const auto d = ppiray_test::Compare(image, expected);
  std::cout << step << ": against a fresh mapper max " << d.Max << ", " << covered
            << " pixels covered\n";
  if (d.Max != 0 || covered < 2000)
  {
    std::cerr << "FAILED: " << step << " differs from a fresh mapper's image (max " << d.Max
              << ") or covers " << covered << " pixels (at least 2000)\n";
    return 1;
  }
  return 0;
}

// The number of errors in the statistics' stages of the last frame: each
// timed, finite and not negative; "validation" there exactly when the cells
// were built, with `adjacency` ("adjacency": faces matched, "folds": the
// same cells' pairs kept) and not the other; neither where nullptr (kept).
int CheckStages(
  vtkUnstructuredGridGPURayCastStatistics* s, const char* adjacency, const std::string& step)
{
  int errors = 0;
  std::set<std::string> names;
  std::cout << "  stages:";
  for (int i = 0; i < s->GetNumberOfPreparationStages(); ++i)
  {
    const double ms = s->GetPreparationStageTime(i);
    names.insert(s->GetPreparationStageName(i));
    std::cout << " " << s->GetPreparationStageName(i) << " " << ms << " ms;";
    if (!std::isfinite(ms) || ms < 0.0)
    {
      std::cerr << "FAILED: " << step << ": stage " << i << " took " << ms << " ms\n";
      ++errors;
    }
  }
  std::cout << "\n";
  for (const char* always : { "geometry key", "field", "upload" })
  {
    errors += names.count(always) == 1 ? 0 : 1;
  }
  const bool built = adjacency != nullptr;
  errors += (names.count("validation") == 1) == built ? 0 : 1;
  for (const char* stage : { "adjacency", "folds" })
  {
    errors += (names.count(stage) == 1) == (built && std::string(stage) == adjacency) ? 0 : 1;
  }
  if (errors != 0)
  {
    std::cerr << "FAILED: " << step << ": the stages do not match a "
              << (built ? std::string("rebuild with ") + adjacency : std::string("reuse")) << "\n";
  }
  return errors;
}

// The number of errors in the progress reported by one frame (`values`),
// after the pipeline's own (0, 1) where a new input made it execute the
// mapper (vtkDemandDrivenPipeline reports both around RequestData).
int CheckProgress(std::vector<double> values, bool built, const std::string& step)
{
  if (values.size() >= 2 && values[0] == 0.0 && values[1] == 1.0)
  {
    values.erase(values.begin(), values.begin() + 2);
  }
  std::cout << "  progress:";
  for (double v : values)
  {
    std::cout << " " << v;
  }
  std::cout << "\n";
  const bool rises = std::is_sorted(values.begin(), values.end());
  const bool ok = built
                    ? values.size() >= 8 && values.front() == 0.0 && values.back() == 1.0 && rises
                    : values.empty();
  if (!ok)
  {
    std::cerr << "FAILED: " << step << ": progress does not match a "
              << (built ? "rebuild (0 to 1, rising, 8 events at least)" : "reuse (none)") << "\n";
  }
  return ok ? 0 : 1;
}

int RunSeries(bool hexahedra)
{
  const int n[3] = { 5, 5, 5 };
  const double origin[3] = { 0, 0, 0 };
  GridPtr grid = ppiray_test::VoxelTetrahedra(
    n, 0.2, origin, [](int, int, int) { return true; }, ppiray_test::Blob, hexahedra);
  ppiray_test::Scene scene(120, 120);
  ppiray_test::SmoothTransferFunction(scene.Property, 0.0, 1.3, 0.8, 0.2);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  scene.Show(mapper, grid, { 2.2, 1.4, 2.6 }, { 0.5, 0.5, 0.5 });
  const char* kind = hexahedra ? "hexahedra" : "tetrahedra";
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* values, void* fraction)
    { static_cast<std::vector<double>*>(values)->push_back(*static_cast<double*>(fraction)); });
  mapper->AddObserver(vtkCommand::ProgressEvent, onProgress);

  int errors = 0;
  int built = 0;
  auto expect =
    [&](int geometry, int field, int reused, const std::string& step, const char* adjacency)
  {
    vtkUnstructuredGridGPURayCastStatistics* s = mapper->GetStatistics();
    errors += CheckStages(s, adjacency, std::string(kind) + ", " + step);
    errors += CheckProgress(progress, geometry != built, std::string(kind) + ", " + step);
    built = geometry;
    std::cout << kind << ", " << step << ": geometry uploads " << s->GetGeometryUploadCount()
              << ", field uploads " << s->GetFieldUploadCount() << ", geometry reused "
              << s->GetGeometryReuseCount() << "\n";
    if (s->GetGeometryUploadCount() != geometry || s->GetFieldUploadCount() != field ||
        s->GetGeometryReuseCount() != reused)
    {
      std::cerr << "FAILED: " << kind << ", " << step << ": expected " << geometry << " " << field
                << " " << reused << "\n";
      ++errors;
    }
  };
  std::vector<unsigned char> image;
  errors += RenderAgainstFresh(scene, mapper, grid, "first step", image, progress);
  expect(1, 1, 0, "first step", "adjacency");
  if (hexahedra && mapper->GetStatistics()->GetNumberOfHexahedra() != 125)
  {
    std::cerr << "FAILED: hexahedra not marched natively\n";
    ++errors;
  }

  // 1.
  GridPtr step = SharedCopy(grid);
  NewScalars(step, 1.3, -1.0);
  errors += RenderAgainstFresh(scene, mapper, step, "shared arrays, new scalars", image, progress);
  expect(1, 2, 1, "shared arrays, new scalars", nullptr);
  // 2.
  step = DeepCopy(step);
  NewScalars(step, 0.1, 0.9);
  errors +=
    RenderAgainstFresh(scene, mapper, step, "copied arrays, other scalars", image, progress);
  expect(1, 3, 2, "copied arrays, other scalars", nullptr);
  // 3.
  step = DeepCopy(step);
  double x[3];
  step->GetPoints()->GetPoint(7, x);
  step->GetPoints()->SetPoint(7, x[0] + 0.05, x[1], x[2]);
  errors += RenderAgainstFresh(scene, mapper, step, "a point moved", image, progress);
  expect(2, 4, 2, "a point moved", "folds");
  // 4.
  step = DeepCopy(step);
  vtkDataArray* connectivity = step->GetCells()->GetConnectivityArray();
  const double a = connectivity->GetTuple1(0), b = connectivity->GetTuple1(1);
  connectivity->SetTuple1(0, b);
  connectivity->SetTuple1(1, a);
  errors += RenderAgainstFresh(scene, mapper, step, "a cell inside out", image, progress);
  expect(3, 5, 2, "a cell inside out", "adjacency");
  const auto insideOut = image;
  // 5.
  step = DeepCopy(step);
  step->AllocateCellGhostArray();
  for (vtkIdType c = 0; c < step->GetNumberOfCells(); c += 3)
  {
    step->GetCellGhostArray()->SetValue(c, vtkDataSetAttributes::HIDDENCELL);
  }
  errors += RenderAgainstFresh(scene, mapper, step, "cells hidden", image, progress);
  expect(4, 6, 2, "cells hidden", "folds");
  if (ppiray_test::Compare(image, insideOut).Max < 10)
  {
    std::cerr << "FAILED: hiding cells did not change the image\n";
    ++errors;
  }
  // 6.
  errors +=
    RenderAgainstFresh(scene, mapper, SharedCopy(step), "all arrays shared", image, progress);
  expect(4, 6, 3, "all arrays shared", nullptr);
  return errors;
}
}

int TestGPURayCastTimeSteps(int, char*[])
{
  const int errors = RunSeries(false) + RunSeries(true);
  return errors == 0 ? 0 : 1;
}
