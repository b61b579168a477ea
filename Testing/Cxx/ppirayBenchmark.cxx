// ppirayBenchmark: frame time of vtkUnstructuredGridGPURayCastMapper against
// VTK's own unstructured volume mappers on the same scene, same machine, same
// run. Prints one row per mapper: median ms per frame over an orbit of views
// (after a warm-up frame; every frame ends with WaitForCompletion), tetrahedra
// per second, GPU bytes per tetrahedron, the speed-up of PPIRay and, for
// PPIRay, the cell steps its rays take per frame (counted on a second,
// untimed pass over the orbit) and per second (at the median frame time).
//
//   ppirayBenchmark [--file MESH.vtu] [--wavelet HALF_EXTENT] [--hexahedra] [--size WxH[,WxH..]]
//                   [--views N] [--peer-views N] [--inside] [--check N]
//                   [--march-stage fragment,compute,automatic]
//                   [--transfer-function ramp|realistic|cutoff|detailed] [--breakdown]
//                   [--mappers ppiray,ppiray-exact,ppiray-full,ppiray-average,ppiray-compact,
//                              ppiray-subdivide,ppiray-fast,pt,raycast,zsweep]
//
// --check N: after its frames, each PPIRay mapper renders the last view at
// N x N and every pixel is compared with the CPU reference renderer (p99 and
// max per channel, pixels covered, NaN); the exit status is 1 when p99 or
// max exceeds 1/255 or a pixel is NaN (the bound of the test suite).
//
// --transfer-function realistic: 14 colour and 22 opacity nodes (RealisticFunction);
// cutoff: its colours, the opacity zero on the lower 45 % of the range
// (CutoffFunction); detailed: 128 colour and 127 opacity nodes, 255 control
// points (DetailedFunction); ramp (default): 3 colour nodes, a 2-node opacity
// ramp.
// --breakdown: a third untimed orbit with the mapper's TimePasses on prints
// the GPU milliseconds per kind of pass and frame, and the CPU preparation.
//
// Default scene: vtkRTAnalyticSource over [-32, 32]^3 split into 1.31 M
// tetrahedra (vtkDataSetTriangleFilter), 512x512, 8 views. --inside: the
// camera at the mesh's centre (a 60 degree view turning about itself, the
// near plane inside the mesh: PPIRay's rays start in the cells it cuts).

#include "vtkAppendFilter.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include "ppirayPlaneSection.h"

#include "PPIRayPixelCheck.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Options
{
  std::string File;
  int Wavelet = 32;
  std::vector<std::pair<int, int>> Sizes; // window sizes, measured in turn (default 512x512)
  int Views = 8;
  int PeerViews = 2;
  std::string Mappers = "ppiray,pt,raycast";
  bool Inside = false;
  bool Hexahedra = false; // the wavelet's voxels as they are, not split
  int Check = 0;
  std::string TransferFunction = "ramp";
  bool Breakdown = false;
  std::vector<int> MarchStages; // each PPIRay mapper once per stage (default: its default)
};

struct Row
{
  std::string Name;
  std::string Size;
  double Ms = 0;
  int Frames = 0;
  double GPUBytes = -1;
  double CellStepsPerFrame = -1; // mean over the orbit (PPIRay only)
  bool CheckFailed = false;
};

// A transfer function as users set them: 14 colour nodes (a desaturated
// rainbow, RGB space) and 22 opacity nodes (three humps rising with the
// scalar), smooth, no spikes, over [lo, hi].
void RealisticFunction(
  double lo, double hi, vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity)
{
  static const double rgb[14][3] = { { 0.28, 0.28, 0.86 }, { 0.00, 0.00, 0.36 },
    { 0.00, 1.00, 1.00 }, { 0.00, 0.50, 0.00 }, { 1.00, 1.00, 0.00 }, { 1.00, 0.38, 0.00 },
    { 0.42, 0.00, 0.00 }, { 0.88, 0.30, 0.30 }, { 0.60, 0.40, 0.80 }, { 0.95, 0.95, 0.95 },
    { 0.20, 0.60, 0.40 }, { 0.75, 0.55, 0.20 }, { 0.90, 0.75, 0.55 }, { 0.50, 0.10, 0.20 } };
  for (int i = 0; i < 14; ++i)
  {
    color->AddRGBPoint(lo + (hi - lo) * i / 13.0, rgb[i][0], rgb[i][1], rgb[i][2]);
  }
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < 22; ++i)
  {
    const double x = i / 21.0;
    const double hump = 0.5 - 0.5 * std::cos(6.0 * pi * x);
    opacity->AddPoint(lo + (hi - lo) * x, 0.02 + 0.48 * x * hump * hump);
  }
}

// The realistic function's colours with the low values hidden, as users
// clear a background: opacity zero on the lower 45 % of [lo, hi], above it
// 16 nodes of humps rising from zero.
void CutoffFunction(
  double lo, double hi, vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity)
{
  RealisticFunction(lo, hi, color, opacity);
  opacity->RemoveAllPoints();
  const double pi = 3.14159265358979323846;
  const double cut = 0.45;
  opacity->AddPoint(lo, 0.0);
  for (int i = 0; i < 16; ++i)
  {
    const double u = i / 15.0;
    const double hump = 0.5 - 0.5 * std::cos(6.0 * pi * u);
    opacity->AddPoint(lo + (hi - lo) * (cut + (1.0 - cut) * u), 0.5 * u * hump * hump);
  }
}

// A detailed function: 128 colour nodes (three turns of a smooth hue
// cycle) and 127 opacity nodes between them (five humps rising with the
// scalar), 255 control points in all, no spikes.
void DetailedFunction(
  double lo, double hi, vtkColorTransferFunction* color, vtkPiecewiseFunction* opacity)
{
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < 128; ++i)
  {
    const double x = i / 127.0;
    color->AddRGBPoint(lo + (hi - lo) * x, 0.5 + 0.5 * std::sin(6.0 * pi * x),
      0.5 + 0.5 * std::sin(6.0 * pi * x + 2.0 * pi / 3.0),
      0.5 + 0.5 * std::sin(6.0 * pi * x + 4.0 * pi / 3.0));
  }
  for (int i = 0; i < 127; ++i)
  {
    const double x = (i + 0.5) / 127.0;
    const double hump = 0.5 - 0.5 * std::cos(10.0 * pi * x);
    opacity->AddPoint(lo + (hi - lo) * x, 0.02 + 0.48 * x * hump * hump);
  }
}

// Milliseconds of one frame, ended with WaitForCompletion.
double FrameMilliseconds(vtkRenderWindow* window)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  window->Render();
  window->WaitForCompletion();
  timer->StopTimer();
  return 1000.0 * timer->GetElapsedTime();
}

// The mean GPU milliseconds per kind of pass and frame over `views` frames of
// the orbit, the passes drawn, the CPU preparation and the frame's wall time.
void PrintBreakdown(const std::string& name, const std::string& size, vtkRenderWindow* window,
  vtkUnstructuredGridGPURayCastMapper* mapper, const std::function<void()>& nextView, int views)
{
  const int kinds = vtkUnstructuredGridGPURayCastStatistics::NUMBER_OF_PASS_KINDS;
  std::vector<double> ms(kinds, 0.0), passes(kinds, 0.0);
  double preparation = 0.0, wall = 0.0;
  mapper->TimePassesOn();
  for (int v = 0; v < views; ++v)
  {
    nextView();
    wall += FrameMilliseconds(window);
    preparation += mapper->GetStatistics()->GetPreparationTime();
    for (int k = 0; k < kinds; ++k)
    {
      ms[k] += mapper->GetStatistics()->GetPassTime(k);
      passes[k] += mapper->GetStatistics()->GetNumberOfPasses(k);
    }
  }
  mapper->TimePassesOff();
  double gpu = 0.0;
  std::printf("\nbreakdown %s %s (mean of %d frames, GPU timer queries):\n", name.c_str(),
    size.c_str(), views);
  std::printf("| pass | ms/frame | passes/frame | share of frame |\n|---|---:|---:|---:|\n");
  std::printf(
    "| CPU preparation | %.2f | | %.1f %% |\n", preparation / views, 100.0 * preparation / wall);
  for (int k = 0; k < kinds; ++k)
  {
    gpu += ms[k];
    std::printf("| %s | %.2f | %.2f | %.1f %% |\n",
      vtkUnstructuredGridGPURayCastStatistics::GetPassKindName(k), ms[k] / views, passes[k] / views,
      100.0 * ms[k] / wall);
  }
  std::printf("| all passes | %.2f | | %.1f %% |\n| frame (wall) | %.2f | | |\n", gpu / views,
    100.0 * gpu / wall, wall / views);
}

vtkSmartPointer<vtkUnstructuredGrid> LoadScene(const Options& o)
{
  if (!o.File.empty())
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(o.File.c_str());
    reader->Update();
    vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
    if (!grid->GetPointData()->GetScalars() && grid->GetPointData()->GetNumberOfArrays())
    {
      grid->GetPointData()->SetActiveScalars(grid->GetPointData()->GetArrayName(0));
    }
    if (!grid->GetPointData()->GetScalars())
    {
      std::cerr << o.File << ": no point scalars to render (or not a mesh the reader can read)\n";
      return nullptr;
    }
    return grid;
  }
  vtkNew<vtkRTAnalyticSource> source;
  const int e = o.Wavelet;
  source->SetWholeExtent(-e, e, -e, e, -e, e);
  if (o.Hexahedra)
  {
    vtkNew<vtkAppendFilter> voxels; // the image's voxels as an unstructured grid
    voxels->SetInputConnection(source->GetOutputPort());
    voxels->Update();
    return voxels->GetOutput();
  }
  vtkNew<vtkDataSetTriangleFilter> tetrahedralize;
  tetrahedralize->SetInputConnection(source->GetOutputPort());
  tetrahedralize->Update();
  return tetrahedralize->GetOutput();
}

// The frames of one orbit at the window's current size (after a warm-up
// frame); for PPIRay also its cell steps and, with `check`, the last view
// against the reference at --check's size.
Row MeasureOrbit(const std::string& name, vtkRenderWindow* window,
  vtkUnstructuredGridVolumeMapper* mapper, vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  const Options& o, int views, bool check)
{
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  vtkCamera* camera = renderer->GetActiveCamera();
  window->Render(); // warm-up: uploads, shader compilation, sorting structures
  auto* automatic = vtkUnstructuredGridGPURayCastMapper::SafeDownCast(mapper);
  for (int frame = 0;
       automatic && automatic->GetStatistics()->GetChosenMarchStage() < 0 &&
       automatic->GetMarchStage() == vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_AUTOMATIC &&
       frame < 12;
       ++frame)
  {
    window->Render(); // the automatic stage's probe, until it has chosen
  }
  window->WaitForCompletion();
  static bool reported = false;
  if (!reported)
  {
    // The OpenGL the numbers were taken on: vendor, renderer, version.
    std::istringstream capabilities(window->ReportCapabilities());
    std::string line;
    while (std::getline(capabilities, line))
    {
      if (line.rfind("OpenGL ", 0) == 0 && line.find("extensions") == std::string::npos)
      {
        std::cout << line << "\n";
      }
    }
    reported = true;
  }
  // The next view of the orbit: turning about the centre, or about itself.
  auto nextView = [&]() { o.Inside ? camera->Yaw(360.0 / views) : camera->Azimuth(360.0 / views); };
  std::vector<double> times;
  for (int v = 0; v < views; ++v)
  {
    nextView();
    times.push_back(FrameMilliseconds(window));
  }
  std::sort(times.begin(), times.end());
  if (automatic &&
      automatic->GetMarchStage() == vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_AUTOMATIC)
  {
    auto* statistics = automatic->GetStatistics();
    std::printf("(automatic stage: chose %d, ran %d in the last view; the probe's best frames: "
                "fragment %.2f ms, compute %.2f ms)\n",
      statistics->GetChosenMarchStage(), statistics->GetMarchStage(),
      statistics->GetMarchStageProbeTime(0), statistics->GetMarchStageProbeTime(1));
  }
  Row row;
  row.Name = name;
  row.Ms = times[times.size() / 2];
  row.Frames = views;
  if (auto* ours = vtkUnstructuredGridGPURayCastMapper::SafeDownCast(mapper))
  {
    row.GPUBytes = static_cast<double>(ours->GetStatistics()->GetGPUMemorySize());
    // The same orbit again, untimed, counting the march's cell steps (a
    // read-back per pass).
    ours->CountCellStepsOn();
    double steps = 0;
    for (int v = 0; v < views; ++v)
    {
      nextView();
      window->Render();
      steps += static_cast<double>(ours->GetStatistics()->GetNumberOfCellSteps());
    }
    ours->CountCellStepsOff();
    row.CellStepsPerFrame = steps / views;
    if (o.Breakdown)
    {
      int* size = window->GetSize();
      PrintBreakdown(name, std::to_string(size[0]) + "x" + std::to_string(size[1]), window, ours,
        nextView, views);
    }
    if (check)
    {
      window->SetSize(o.Check, o.Check);
      window->Render();
      const auto pixels = ppiray_test::CheckPixels(
        renderer, grid, property, ppiray_test::ReadRGB(window), o.Check, o.Check);
      row.CheckFailed = pixels.NaNPixels > 0 || pixels.P99 > 1.0 || pixels.MaxDifference > 1.0 ||
                        pixels.Pixels == 0;
      std::printf("pixel check %s %dx%d against the reference: %d pixels covered, p99 %.2f, max "
                  "%.2f /255, %d NaN: %s\n",
        name.c_str(), o.Check, o.Check, pixels.Pixels, pixels.P99, pixels.MaxDifference,
        pixels.NaNPixels, row.CheckFailed ? "FAILED" : "passed");
    }
  }
  return row;
}

// One orbit of `views` frames per window size; the window and the mapper are
// kept from one size to the next (the mapper's GPU data is built once).
std::vector<Row> Measure(const std::string& name, vtkUnstructuredGridVolumeMapper* mapper,
  vtkUnstructuredGrid* grid, const Options& o, int views)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  if (o.TransferFunction == "realistic")
  {
    RealisticFunction(range[0], range[1], color, opacity);
  }
  else if (o.TransferFunction == "cutoff")
  {
    CutoffFunction(range[0], range[1], color, opacity);
  }
  else if (o.TransferFunction == "detailed")
  {
    DetailedFunction(range[0], range[1], color, opacity);
  }
  else
  {
    color->AddRGBPoint(range[0], 0.23, 0.30, 0.75);
    color->AddRGBPoint(0.5 * (range[0] + range[1]), 0.87, 0.87, 0.87);
    color->AddRGBPoint(range[1], 0.71, 0.02, 0.15);
    opacity->AddPoint(range[0], 0.0);
    opacity->AddPoint(range[1], 0.5);
  }
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  double b[6];
  grid->GetBounds(b);
  property->SetScalarOpacityUnitDistance((b[1] - b[0]) / 20.0);

  mapper->SetInputData(grid);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(o.Sizes[0].first, o.Sizes[0].second);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  if (o.Inside)
  {
    const double centre[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
    camera->SetPosition(centre);
    camera->SetFocalPoint(centre[0] + 1.0, centre[1] + 0.3, centre[2] + 0.2);
    camera->SetViewAngle(60.0);
  }
  else
  {
    camera->SetPosition(1.0, 0.6, 1.4);
    renderer->ResetCamera();
  }

  std::vector<Row> rows;
  for (const auto& size : o.Sizes)
  {
    window->SetSize(size.first, size.second);
    const bool check = o.Check > 0 && &size == &o.Sizes.back();
    rows.push_back(MeasureOrbit(name, window, mapper, grid, property, o, views, check));
    rows.back().Size = std::to_string(size.first) + "x" + std::to_string(size.second);
  }
  return rows;
}

void Append(std::vector<Row>& rows, const std::vector<Row>& more)
{
  rows.insert(rows.end(), more.begin(), more.end());
}

// The stages of a --march-stage list ("fragment,compute"); empty on a bad name.
std::vector<int> MarchStages(const std::string& list)
{
  std::vector<int> stages;
  std::stringstream names(list);
  std::string name;
  while (std::getline(names, name, ','))
  {
    const int stage = name == "fragment" ? vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_FRAGMENT
                      : name == "compute" ? vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_COMPUTE
                      : name == "automatic"
                        ? vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_AUTOMATIC
                        : -1;
    if (stage < 0)
    {
      return {};
    }
    stages.push_back(stage);
  }
  return stages;
}

// PPIRay as `name` (ppiray, ppiray-exact, ...) in march stage `stage` (-1:
// the mapper's default).
std::vector<Row> MeasurePPIRay(
  const std::string& name, int stage, vtkUnstructuredGrid* grid, const Options& o)
{
  vtkNew<vtkUnstructuredGridGPURayCastMapper> m;
  if (name == "ppiray-subdivide")
  {
    m->SetHexahedronModeToSubdivide();
  }
  else if (name == "ppiray-fast")
  {
    m->SetHexahedronModeToFast();
  }
  if (stage >= 0)
  {
    m->SetMarchStage(stage);
  }
  m->SetTetrahedronLayout(name == "ppiray-compact"
                            ? vtkUnstructuredGridGPURayCastMapper::TETRAHEDRON_COMPACT
                            : vtkUnstructuredGridGPURayCastMapper::TETRAHEDRON_PLANES);
  m->SetIntegrationMode(
    name == "ppiray-exact"     ? vtkUnstructuredGridGPURayCastMapper::EXACT_LINEAR
    : name == "ppiray-average" ? vtkUnstructuredGridGPURayCastMapper::AVERAGE_COLOR
    : name == "ppiray-full"    ? vtkUnstructuredGridGPURayCastMapper::FULL_PRE_INTEGRATION
                               : vtkUnstructuredGridGPURayCastMapper::PARTIAL_PRE_INTEGRATION);
  const std::string stageName =
    stage == vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_COMPUTE     ? " [compute]"
    : stage == vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_FRAGMENT  ? " [fragment]"
    : stage == vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_AUTOMATIC ? " [automatic]"
                                                                          : "";
  std::vector<Row> rows = Measure(std::string("PPIRay ") + m->GetIntegrationModeAsString() +
                                    (name == "ppiray-compact"      ? " (compact)"
                                      : name == "ppiray-subdivide" ? " (subdivided)"
                                      : name == "ppiray-fast"      ? " (fast)"
                                                                   : "") +
                                    stageName,
    m, grid, o, o.Views);
  if (stage == vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_COMPUTE &&
      m->GetStatistics()->GetMarchStage() != stage)
  {
    std::cout << "(the compute stage was not available: measured in the fragment stage)\n";
  }

  if (name == "ppiray-full")
  {
    std::printf("FULL_PRE_INTEGRATION table %d^3 built in %.3f s\n",
      m->GetPreIntegrationTableSize(), m->GetStatistics()->GetPreIntegrationTableBuildTime());
  }
  return rows;
}
}

int main(int argc, char* argv[])
{
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (arg == "--file")
    {
      o.File = next();
    }
    else if (arg == "--wavelet")
    {
      o.Wavelet = std::stoi(next());
    }
    else if (arg == "--size")
    {
      std::stringstream sizes(next());
      std::string size;
      while (std::getline(sizes, size, ','))
      {
        int w = 0, h = 0;
        if (std::sscanf(size.c_str(), "%dx%d", &w, &h) == 2 && w > 0 && h > 0)
        {
          o.Sizes.emplace_back(w, h);
        }
      }
    }
    else if (arg == "--views")
    {
      o.Views = std::stoi(next());
    }
    else if (arg == "--peer-views")
    {
      o.PeerViews = std::stoi(next());
    }
    else if (arg == "--hexahedra")
    {
      o.Hexahedra = true;
    }
    else if (arg == "--inside")
    {
      o.Inside = true;
    }
    else if (arg == "--check")
    {
      o.Check = std::stoi(next());
    }
    else if (arg == "--mappers")
    {
      o.Mappers = next();
    }
    else if (arg == "--transfer-function")
    {
      o.TransferFunction = next();
      if (o.TransferFunction != "ramp" && o.TransferFunction != "realistic" &&
          o.TransferFunction != "cutoff" && o.TransferFunction != "detailed")
      {
        std::cerr << "--transfer-function: ramp, realistic, cutoff or detailed\n";
        return 2;
      }
    }
    else if (arg == "--breakdown")
    {
      o.Breakdown = true;
    }
    else if (arg == "--march-stage")
    {
      o.MarchStages = MarchStages(next());
      if (o.MarchStages.empty())
      {
        std::cerr << "--march-stage: a list of fragment, compute, automatic\n";
        return 2;
      }
    }
    else
    {
      std::cout
        << "usage: ppirayBenchmark [--file MESH.vtu] [--wavelet HALF_EXTENT] [--hexahedra] "
           "[--size WxH[,WxH..]]"
           " [--views N] [--peer-views N] [--inside] [--check N]"
           " [--transfer-function ramp|realistic|cutoff|detailed] [--breakdown]"
           " [--march-stage fragment,compute,automatic]"
           " [--mappers ppiray,ppiray-exact,ppiray-full,ppiray-average,ppiray-compact,"
           "ppiray-subdivide,ppiray-fast,pt,raycast,zsweep]\n\n"
           "Frame time of PPIRay against VTK's unstructured volume mappers on one scene, same\n"
           "run: median ms per frame over an orbit of views after a warm-up frame.\n"
           "  --file MESH.vtu     a tetrahedral mesh and its point scalars (default: the wavelet)\n"
           "  --wavelet N         vtkRTAnalyticSource over [-N, N]^3 split into tetrahedra\n"
           "  --hexahedra         the wavelet's voxels as they are (hexahedra for PPIRay)\n"
           "                      (default 32: 1.31 M tetrahedra)\n"
           "  --size WxH[,WxH..]  window sizes, measured in turn with the same window and\n"
           "                      mapper (default 512x512)\n"
           "  --views N           views on the orbit for PPIRay and PT (default 8)\n"
           "  --peer-views N      views for the CPU mappers raycast, zsweep (default 2)\n"
           "  --inside            camera at the mesh's centre, turning about itself (default "
           "outside)\n"
           "  --check N           PPIRay's last view at NxN against the CPU reference; exit 1\n"
           "                      past 1/255 (p99 or max) or with NaN\n"
           "  --transfer-function ramp (default: 3 colour nodes, 2-node opacity ramp) or\n"
           "                      realistic (14 colour and 22 opacity nodes, smooth),\n"
           "                      cutoff (realistic colours, opacity zero on the lower 45 %)\n"
           "                      or detailed (128 colour and 127 opacity nodes)\n"
           "  --breakdown         GPU time per kind of pass (a third, untimed orbit)\n"
           "  --march-stage LIST  each PPIRay mapper once per march stage listed\n"
           "                      (fragment, compute, automatic; default: the mapper's)\n"
           "  --mappers LIST      comma-separated (default ppiray,pt,raycast): ppiray (partial\n"
           "                      pre-integration), ppiray-exact, ppiray-full, ppiray-average,\n"
           "                      ppiray-compact (partial, TETRAHEDRON_COMPACT layout),\n"
           "                      ppiray-subdivide (partial, HEXAHEDRON_SUBDIVIDE: every\n"
           "                      cell split into tetrahedra), ppiray-fast (partial,\n"
           "                      HEXAHEDRON_FAST),\n"
           "                      pt (vtkProjectedTetrahedraMapper), raycast\n"
           "                      (vtkUnstructuredGridVolumeRayCastMapper), zsweep\n"
           "                      (vtkUnstructuredGridVolumeZSweepMapper)\n";
      return arg == "--help" ? 0 : 2;
    }
  }

  if (o.Sizes.empty())
  {
    o.Sizes.emplace_back(512, 512);
  }
  std::string sizes;
  for (const auto& size : o.Sizes)
  {
    sizes +=
      (sizes.empty() ? "" : ", ") + std::to_string(size.first) + "x" + std::to_string(size.second);
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = LoadScene(o);
  if (!grid)
  {
    return EXIT_FAILURE;
  }
  const double tets = static_cast<double>(grid->GetNumberOfCells());
  std::cout << "scene: "
            << (o.File.empty()
                   ? "wavelet [-" + std::to_string(o.Wavelet) + ", " + std::to_string(o.Wavelet) +
                       "]^3 " + (o.Hexahedra ? "as voxels" : "tetrahedralized")
                   : o.File)
            << ", " << grid->GetNumberOfCells() << " cells, " << sizes
            << (o.Inside ? ", camera inside" : "") << ", transfer function " << o.TransferFunction
            << "\n";

  std::vector<Row> rows;
  std::stringstream list(o.Mappers);
  std::string name;
  while (std::getline(list, name, ','))
  {
    std::cerr << "measuring " << name << " ..." << std::endl;
    if (name == "ppiray" || name == "ppiray-exact" || name == "ppiray-average" ||
        name == "ppiray-full" || name == "ppiray-compact" || name == "ppiray-subdivide" ||
        name == "ppiray-fast")
    {
      for (int stage : o.MarchStages.empty() ? std::vector<int>{ -1 } : o.MarchStages)
      {
        Append(rows, MeasurePPIRay(name, stage, grid, o));
      }
    }
    else if (name == "pt")
    {
      vtkNew<vtkProjectedTetrahedraMapper> m;
      Append(rows, Measure("vtkProjectedTetrahedraMapper", m, grid, o, o.Views));
    }
    else if (name == "raycast")
    {
      vtkNew<vtkUnstructuredGridVolumeRayCastMapper> m;
      m->SetImageSampleDistance(1.0);
      m->AutoAdjustSampleDistancesOff();
      Append(rows, Measure("vtkUnstructuredGridVolumeRayCastMapper", m, grid, o, o.PeerViews));
    }
    else if (name == "zsweep")
    {
      vtkNew<vtkUnstructuredGridVolumeZSweepMapper> m;
      m->SetImageSampleDistance(1.0);
      m->AutoAdjustSampleDistancesOff();
      Append(rows, Measure("vtkUnstructuredGridVolumeZSweepMapper", m, grid, o, o.PeerViews));
    }
  }

  if (o.Inside)
  {
    // The CPU part of starting rays inside: the cells cut by the near plane
    // as polygons (what the mapper computes per frame, timed alone here for a
    // plane through the centre).
    double b[6];
    grid->GetBounds(b);
    const glm::dvec3 centre(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
    const glm::dvec3 n = glm::normalize(glm::dvec3(1.0, 0.3, 0.2));
    const glm::dvec4 plane(n, glm::dot(n, centre));
    // Corners in one array first, as the mapper keeps them (not timed).
    std::vector<glm::dvec3> corners;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      const vtkIdType* ids;
      vtkIdType size;
      grid->GetCellPoints(c, size, ids);
      for (int v = 0; v < 4 && size == 4; ++v)
      {
        corners.emplace_back();
        grid->GetPoint(ids[v], &corners.back().x);
      }
    }
    std::vector<glm::dvec3> triangles;
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    for (size_t t = 0; t + 3 < corners.size(); t += 4)
    {
      ppiray::TetrahedronSection(&corners[t], plane, triangles);
    }
    timer->StopTimer();
    std::printf("near-plane section through the centre (ppiray::TetrahedronSection, every cell): "
                "%.1f ms, %zu triangles\n",
      1000.0 * timer->GetElapsedTime(), triangles.size() / 3);
  }

  std::map<std::string, double> ours; // PPIRay's default mode, per window size
  bool checkFailed = false;
  for (const Row& r : rows)
  {
    if (r.Name == "PPIRay PARTIAL_PRE_INTEGRATION")
    {
      ours[r.Size] = r.Ms;
    }
    checkFailed = checkFailed || r.CheckFailed;
  }
  std::printf(
    "\n| mapper | ms/frame (median) | frames | M tets/s | GPU B/tet | M cell steps/frame | M cell "
    "steps/s | PPIRay speed-up | size |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for (const Row& r : rows)
  {
    char gpu[32] = "n/a";
    if (r.GPUBytes >= 0)
    {
      std::snprintf(gpu, sizeof(gpu), "%.1f", r.GPUBytes / tets);
    }
    char speedup[32] = "";
    if (ours.count(r.Size))
    {
      std::snprintf(speedup, sizeof(speedup), "%.2fx", r.Ms / ours[r.Size]);
    }
    char steps[32] = "n/a";
    char stepRate[32] = "n/a";
    if (r.CellStepsPerFrame >= 0)
    {
      std::snprintf(steps, sizeof(steps), "%.2f", r.CellStepsPerFrame / 1.0e6);
      std::snprintf(stepRate, sizeof(stepRate), "%.1f", r.CellStepsPerFrame / r.Ms / 1000.0);
    }
    std::printf("| %s | %.1f | %d | %.2f | %s | %s | %s | %s | %s |\n", r.Name.c_str(), r.Ms,
      r.Frames, tets / r.Ms / 1000.0, gpu, steps, stepRate, speedup, r.Size.c_str());
  }
  return checkFailed ? 1 : 0;
}
