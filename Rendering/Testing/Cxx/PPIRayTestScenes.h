// Scenes shared by the Rendering tests: meshes built from voxels split into
// six tetrahedra (Kuhn split: consistent across shared faces), scalar fields,
// transfer functions, and a window set up for headless regression testing.
#ifndef PPIRayTestScenes_h
#define PPIRayTestScenes_h

#include "PPIRayTestDisplay.h"
#include "vtkAppendFilter.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <map>
#include <string>

namespace ppiray_test
{
// The tetrahedron layout and march stage a test runs with:
// TETRAHEDRON_COMPACT when its arguments hold "--tetrahedron-layout compact"
// (the ".Compact" variants), MARCH_STAGE_COMPUTE with "--march-stage
// compute" (the ".Compute" variants; ctest runs both of the tests that read
// them, PPIRayTesting.cmake), else the default layout and the fragment
// stage; every PPIRay mapper a test shows (Scene::Show) or passes to
// UseTetrahedronLayout() gets them. Not the automatic stage: its probe
// alternates the stages over a mapper's first frames, and a test that
// compares frames compares one stage (TestGPURayCastMarchStageChoice
// tests the automatic stage).
inline int& TetrahedronLayout()
{
  static int layout = vtkUnstructuredGridGPURayCastMapper::TETRAHEDRON_PLANES;
  return layout;
}

inline int& MarchStage()
{
  static int stage = vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_FRAGMENT;
  return stage;
}

inline void ReadTetrahedronLayout(int argc, char* argv[])
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    const bool layout = std::strcmp(argv[i], "--tetrahedron-layout") == 0;
    const bool stage = std::strcmp(argv[i], "--march-stage") == 0;
    if (layout && std::strcmp(argv[i + 1], "compact") == 0)
    {
      TetrahedronLayout() = vtkUnstructuredGridGPURayCastMapper::TETRAHEDRON_COMPACT;
    }
    else if (stage && std::strcmp(argv[i + 1], "compute") == 0)
    {
      MarchStage() = vtkUnstructuredGridGPURayCastMapper::MARCH_STAGE_COMPUTE;
    }
    else if ((layout && std::strcmp(argv[i + 1], "planes") != 0) ||
             (stage && std::strcmp(argv[i + 1], "fragment") != 0))
    {
      // A misspelt option would silently test the default.
      std::cout << "FAILED: unknown " << argv[i] << " " << argv[i + 1] << "\n";
      std::exit(EXIT_FAILURE);
    }
  }
}

inline void UseTetrahedronLayout(vtkAbstractVolumeMapper* mapper)
{
  if (auto* ours = vtkUnstructuredGridGPURayCastMapper::SafeDownCast(mapper))
  {
    ours->SetTetrahedronLayout(TetrahedronLayout());
    ours->SetMarchStage(MarchStage());
  }
}

using Field = std::function<double(double, double, double)>;
using Keep = std::function<bool(int, int, int)>;

// Voxels (i, j, k) in [0, n)^3 of size h where keep(i, j, k), each split into
// six tetrahedra around its main diagonal, or each a VTK_HEXAHEDRON; points
// shared; scalar "s" = f(x).
inline vtkSmartPointer<vtkUnstructuredGrid> VoxelTetrahedra(const int n[3], double h,
  const double origin[3], const Keep& keep, const Field& f, bool hexahedra = false)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  std::map<std::array<int, 3>, vtkIdType> ids;
  auto point = [&](int i, int j, int k)
  {
    auto it = ids.find({ i, j, k });
    if (it != ids.end())
    {
      return it->second;
    }
    const double x = origin[0] + h * i, y = origin[1] + h * j, z = origin[2] + h * k;
    const vtkIdType id = points->InsertNextPoint(x, y, z);
    scalars->InsertNextValue(f(x, y, z));
    ids[{ i, j, k }] = id;
    return id;
  };
  // Kuhn split: the six paths from corner 000 to 111 along the axes.
  const int paths[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  vtkNew<vtkCellArray> cells;
  for (int k = 0; k < n[2]; ++k)
  {
    for (int j = 0; j < n[1]; ++j)
    {
      for (int i = 0; i < n[0]; ++i)
      {
        if (!keep(i, j, k))
        {
          continue;
        }
        if (hexahedra)
        {
          const vtkIdType hex[8] = { point(i, j, k), point(i + 1, j, k), point(i + 1, j + 1, k),
            point(i, j + 1, k), point(i, j, k + 1), point(i + 1, j, k + 1),
            point(i + 1, j + 1, k + 1), point(i, j + 1, k + 1) };
          cells->InsertNextCell(8, hex);
          continue;
        }
        for (const auto& path : paths)
        {
          int c[3] = { i, j, k };
          vtkIdType tet[4];
          tet[0] = point(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s)
          {
            ++c[path[s]];
            tet[s + 1] = point(c[0], c[1], c[2]);
          }
          cells->InsertNextCell(4, tet);
        }
      }
    }
  }
  grid->SetPoints(points);
  grid->SetCells(hexahedra ? VTK_HEXAHEDRON : VTK_TETRA, cells);
  grid->GetPointData()->SetScalars(scalars);
  return grid;
}

// Tangled: the points of a mesh over [0, 1]^3 with z levels of 1/6 moved so
// that levels 3 and 4 swap over (z 0.62 and 0.45, bent by 0.04 sin 6x): the
// layer between them is inverted, the mesh folds back on itself twice.
inline void FoldLayers(vtkUnstructuredGrid* grid)
{
  const double levels[7] = { 0.0, 1.0 / 6, 2.0 / 6, 0.62, 0.45, 0.75, 1.0 };
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    const int level = static_cast<int>(std::lround(6 * x[2]));
    x[2] = levels[level] + ((level == 3 || level == 4) ? 0.04 * std::sin(6.0 * x[0]) : 0.0);
    grid->GetPoints()->SetPoint(i, x);
  }
}

// Point scalars "s" = f(x, y, z) at every point of `grid`.
inline void PointField(vtkUnstructuredGrid* grid, const Field& f)
{
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    s->InsertNextValue(f(x[0], x[1], x[2]));
  }
  grid->GetPointData()->SetScalars(s);
}

// Point scalars "s" = 0.5 x + 0.4 y + 0.4 z (0 to 1.3 over the unit cube):
// linear in world coordinates, so every cell covering a point (overlapping
// or folded cells) gives it the same value, and a trilinear (isoparametric)
// cell reproduces it exactly.
inline void WorldLinearField(vtkUnstructuredGrid* grid)
{
  PointField(grid, [](double x, double y, double z) { return 0.5 * x + 0.4 * y + 0.4 * z; });
}

// A smooth deformation of space: x + a (sin 4y, cos 4z, sin 4x), one-to-one
// for a < 1/4.
inline void Deform(double a, double x[3])
{
  const double d[3] = { std::sin(4 * x[1]), std::cos(4 * x[2]), std::sin(4 * x[0]) };
  for (int i = 0; i < 3; ++i)
  {
    x[i] += a * d[i];
  }
}

// A smooth field on [0, 1]^3-ish coordinates.
inline double Blob(double x, double y, double z)
{
  return std::exp(
           -((x - 0.5) * (x - 0.5) + (y - 0.45) * (y - 0.45) + (z - 0.55) * (z - 0.55)) / 0.12) +
         0.3 * x;
}

// The blob on an n x n x n block of voxels over [0, 1]^3 (vtkImageData through
// vtkAppendFilter, VTK_VOXEL cells) and the same cells as VTK_HEXAHEDRON.
struct VoxelBlock
{
  vtkSmartPointer<vtkImageData> Image; // the same points and scalars
  vtkSmartPointer<vtkUnstructuredGrid> Voxels;
  vtkSmartPointer<vtkUnstructuredGrid> Hexahedra;
};

// The same cells and point data with each voxel as a VTK_HEXAHEDRON (voxel
// corners 2, 3 and 6, 7 swapped).
inline vtkSmartPointer<vtkUnstructuredGrid> VoxelsAsHexahedra(vtkUnstructuredGrid* voxels)
{
  auto hexahedra = vtkSmartPointer<vtkUnstructuredGrid>::New();
  hexahedra->SetPoints(voxels->GetPoints());
  hexahedra->GetPointData()->ShallowCopy(voxels->GetPointData());
  for (vtkIdType c = 0; c < voxels->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* v;
    voxels->GetCellPoints(c, npts, v);
    const vtkIdType hex[8] = { v[0], v[1], v[3], v[2], v[4], v[5], v[7], v[6] };
    hexahedra->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  }
  return hexahedra;
}

// The unit cube in n^3 voxels with point scalars `name` = f(x).
inline VoxelBlock FieldVoxelBlock(int n, const Field& f, const char* name)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n + 1, n + 1, n + 1);
  image->SetSpacing(1.0 / n, 1.0 / n, 1.0 / n);
  vtkNew<vtkDoubleArray> values;
  values->SetName(name);
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    image->GetPoint(p, x);
    values->InsertNextValue(f(x[0], x[1], x[2]));
  }
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkAppendFilter> append;
  append->AddInputData(image);
  append->Update();
  VoxelBlock block;
  block.Image = image;
  block.Voxels = append->GetOutput();
  block.Hexahedra = VoxelsAsHexahedra(block.Voxels);
  return block;
}

inline VoxelBlock BlobVoxelBlock(int n)
{
  return FieldVoxelBlock(n, Blob, "blob");
}

// A block with a square tunnel through it beside a second, separate block
// (10 x 6 x 6 voxels of 0.1, split into tetrahedra; the blob field): rays
// leave and re-enter it several times.
inline vtkSmartPointer<vtkUnstructuredGrid> TunnelAndBlock()
{
  const int n[3] = { 10, 6, 6 };
  const double origin[3] = { 0, 0, 0 };
  auto keep = [](int i, int j, int k)
  {
    const bool tunnel = j >= 2 && j < 4 && k >= 2 && k < 4 && i < 6;
    const bool gap = i == 6 || i == 7;
    return !tunnel && !gap;
  };
  return VoxelTetrahedra(
    n, 0.1, origin, keep, [](double x, double y, double z) { return Blob(x, y / 0.6, z / 0.6); });
}

// A smooth rainbow with smooth opacity over [lo, hi].
inline void SmoothTransferFunction(vtkVolumeProperty* property, double lo, double hi,
  double maxOpacity = 0.6, double unitDistance = 0.25)
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.1, 0.2, 0.9);
  color->AddRGBPoint(lo + 0.5 * (hi - lo), 0.2, 0.9, 0.3);
  color->AddRGBPoint(hi, 0.95, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(hi, maxOpacity);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
}

// 41 control points on a 0..100 scalar range: a smooth colour ramp (9 nodes),
// a low wavy opacity ramp (28 nodes) and a one-value-wide opacity spike
// 0 -> 1 -> 0 at 70, which sampling-based mappers miss.
inline void SpikeTransferFunction(vtkVolumeProperty* property)
{
  vtkNew<vtkColorTransferFunction> color;
  for (int i = 0; i <= 8; ++i)
  {
    const double u = i / 8.0;
    color->AddRGBPoint(100.0 * u, 0.2 + 0.8 * u, 0.9 - 0.7 * u * u, 1.0 - u);
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  for (int i = 0; i < 28; ++i)
  {
    opacity->AddPoint(2.0 + 1.9 * i, 0.02 + 0.02 * (i % 3));
  }
  opacity->AddPoint(69.5, 0.0);
  opacity->AddPoint(70.0, 1.0);
  opacity->AddPoint(70.5, 0.0);
  opacity->AddPoint(100.0, 0.05);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.05);
}

// Collects the error and warning messages of the objects it observes
// (AddObserver(vtkCommand::ErrorEvent / WarningEvent, collector)).
class MessageCollector : public vtkCommand
{
public:
  static MessageCollector* New() { return new MessageCollector; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings) +=
      static_cast<const char*>(data) + std::string("\n");
  }
  std::string Errors;
  std::string Warnings;
};

// Window + renderer for a regression test: fixed size, no multisampling.
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkVolumeProperty> Property;
  Scene(int width = 300, int height = 300)
  {
    // Only an X window takes an X connection (EGL and OSMesa windows have
    // their own display handles).
    void* display = this->Window->IsA("vtkXOpenGLRenderWindow") ? SharedDisplay() : nullptr;
    if (display)
    {
      this->Window->SetDisplayId(display);
    }
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
  }

  // Show `grid` with `mapper`, the camera at `eye` looking at `focal`, then
  // fit to the volume (not rendered yet).
  void Show(vtkAbstractVolumeMapper* mapper, vtkDataSet* grid, const std::array<double, 3>& eye,
    const std::array<double, 3>& focal)
  {
    vtkUnstructuredGridVolumeMapper::SafeDownCast(mapper)->SetInputData(grid);
    UseTetrahedronLayout(mapper);
    this->Volume->SetMapper(mapper);
    this->Renderer->GetActiveCamera()->SetPosition(eye.data());
    this->Renderer->GetActiveCamera()->SetFocalPoint(focal.data());
    this->Renderer->ResetCamera();
  }
};
}

#endif
