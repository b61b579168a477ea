#include "vtkUnstructuredGridReferenceRenderer.h"

#include "ppirayIsoSurfaces.h"
#include "ppirayReferenceTile.h"
#include "ppirayValidPointIds.h"
#include "vtkCamera.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <thread>

vtkStandardNewMacro(vtkUnstructuredGridReferenceRenderer);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, VolumeProperty, vtkVolumeProperty);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, Lights, vtkLightCollection);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, ClippingPlanes, vtkPlaneCollection);

using namespace ppiray::reference;

namespace
{
// The output: a width x height image of float RGBA, zero (transparent) until drawn.
vtkFloatArray* AllocateImage(vtkImageData* output, int width, int height)
{
  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  vtkNew<vtkFloatArray> rgba;
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  rgba->Fill(0.0);
  output->GetPointData()->SetScalars(rgba);
  return rgba;
}

// The input, or its copy with the cells that list point ids outside its
// points emptied (reported).
vtkSmartPointer<vtkUnstructuredGrid> WithValidPointIds(
  vtkAlgorithm* self, vtkUnstructuredGrid* input)
{
  vtkIdType invalidCells = 0;
  const vtkSmartPointer<vtkUnstructuredGrid> validCells =
    ppiray::EmptyCellsWithInvalidPointIds(input, invalidCells);
  if (!validCells)
  {
    return input;
  }
  vtkErrorWithObjectMacro(self, << invalidCells << " cells list point ids outside [0, "
                                << input->GetNumberOfPoints() << "): they are not rendered.");
  return validCells;
}

// The cells not integrated as themselves (reported).
void ReportCellsNotIntegrated(vtkAlgorithm* self, const ReferenceCells& cells)
{
  if (cells.Skipped)
  {
    vtkWarningWithObjectMacro(
      self, << cells.Skipped << " cells of other types than 3D cells skipped.");
  }
}

// QuadratureTolerance relative to the range; for a (nearly) constant field, to
// the values' magnitude (the interpolation's own rounding is not a deviation).
double LinearTolerance(double quadratureTolerance, const double scalarRange[2])
{
  return quadratureTolerance *
         std::max({ scalarRange[1] - scalarRange[0],
           1e-9 * std::max(std::abs(scalarRange[0]), std::abs(scalarRange[1])), 1e-300 });
}

// A projection's blend mode and inputs; n(s) = (s - min) / (max - min) over the
// scalar range (1 for a constant field).
Projection ProjectionOf(int blendMode, const double scalarRange[2], const double averageRange[2])
{
  Projection how;
  how.Blend = blendMode;
  const double scalarWidth = scalarRange[1] - scalarRange[0];
  how.Normalize[0] = scalarWidth > 0 ? 1.0 / scalarWidth : 0.0;
  how.Normalize[1] = scalarWidth > 0 ? -scalarRange[0] / scalarWidth : 1.0;
  std::copy_n(averageRange, 2, how.AverageRange);
  return how;
}

// Every tile of the scene (OpenMP, dynamic schedule); returns the unresolved
// ray pieces. Progress after each tile, no tile started once aborted.
long long RenderTiles(vtkAlgorithm* self, const Scene& scene, float* rgba)
{
  const int numberOfTiles = scene.Tiles.TilesX * scene.Tiles.TilesY;
  // VTK's Bezier wedge shares state between its instances (VTK 9.2:
  // InterpolateFunctions fails from two threads): one thread for a grid with any.
  bool parallel = true;
  for (vtkIdType c = 0; c < scene.Grid->GetNumberOfCells() && parallel; ++c)
  {
    parallel = scene.Grid->GetCellType(c) != VTK_BEZIER_WEDGE;
  }
  std::atomic<int> tilesDone(0);
  std::atomic<long long> unresolvedPieces(0);
  const std::thread::id caller = std::this_thread::get_id();
  self->UpdateProgress(0.0);
#pragma omp parallel for schedule(dynamic) if (parallel)
  for (int tile = 0; tile < numberOfTiles; ++tile)
  {
    if (self->GetAbortExecute())
    {
      continue; // aborted (e.g. by a progress observer): no tile is started
    }
    unresolvedPieces += RenderTile(scene, tile, rgba);
    const int done = ++tilesDone;
    if (std::this_thread::get_id() == caller) // observers run on the calling thread only
    {
      self->UpdateProgress(static_cast<double>(done) / numberOfTiles);
    }
  }
  self->UpdateProgress(1.0);
  return unresolvedPieces;
}
}

//------------------------------------------------------------------------------
vtkUnstructuredGridReferenceRenderer::vtkUnstructuredGridReferenceRenderer()
{
  this->SetNumberOfInputPorts(1);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkUnstructuredGridReferenceRenderer::~vtkUnstructuredGridReferenceRenderer()
{
  this->SetVolumeProperty(nullptr);
  this->SetCamera(nullptr);
  this->SetLights(nullptr);
  this->SetClippingPlanes(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkUnstructuredGridReferenceRenderer::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->VolumeProperty)
  {
    time = std::max(time, this->VolumeProperty->GetMTime());
  }
  if (this->Camera)
  {
    time = std::max(time, this->Camera->GetMTime());
  }
  if (this->ClippingPlanes)
  {
    time = std::max(time, this->ClippingPlanes->GetMTime());
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridReferenceRenderer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridReferenceRenderer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->ImageSize[0] - 1, 0, this->ImageSize[1] - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 4);
  return 1;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridReferenceRenderer::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0]);
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  vtkFloatArray* rgba = AllocateImage(vtkImageData::GetData(outputVector), width, height);
  if (!this->VolumeProperty || !this->Camera || !this->VolumeProperty->GetScalarOpacity(0))
  {
    vtkErrorMacro("A volume property with a scalar opacity function and a camera are required.");
    return 1;
  }
  if (!input || input->GetNumberOfCells() == 0)
  {
    return 1;
  }
  Scene scene;
  int association = 0;
  scene.Scalars = this->GetInputArrayToProcess(0, input, association);
  if (!scene.Scalars)
  {
    vtkErrorMacro("No scalars to render.");
    return 1;
  }
  scene.CellScalars = association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
  const vtkSmartPointer<vtkUnstructuredGrid> grid = WithValidPointIds(this, input);
  scene.Grid = grid;
  scene.Cells = CollectCells(grid);
  ReportCellsNotIntegrated(this, scene.Cells);
  double scalarRange[2];
  scene.Scalars->GetRange(scalarRange, 0);
  scene.LinearTolerance = LinearTolerance(this->QuadratureTolerance, scalarRange);

  scene.TF.Build(this->VolumeProperty, this->TransferFunctionTolerance);
  std::string isoWarning;
  scene.Iso = ppiray::ReadIsoSurfaces(this->VolumeProperty,
    ppiray::ChooseIsoSurfaceMode(this->BlendMode, this->EmbedIsoSurfaces != 0,
      this->VolumeProperty->GetIsoSurfaceValues()->GetNumberOfContours(), isoWarning),
    this->Lights);
  if (!isoWarning.empty())
  {
    vtkWarningMacro(<< isoWarning);
  }
  scene.IsProjection =
    this->BlendMode >= MAXIMUM_INTENSITY_BLEND && this->BlendMode <= ADDITIVE_BLEND;
  scene.How = ProjectionOf(this->BlendMode, scalarRange, this->AverageIPScalarRange);

  double bounds[6];
  grid->GetBounds(bounds);
  scene.View.Build(this->Camera, bounds, this->ClippingPlanes, width, height);
  scene.Tiles.Build(grid, scene.Cells, scene.View.WorldToClip, width, height);
  const long long unresolvedPieces = RenderTiles(this, scene, rgba->GetPointer(0));
  if (unresolvedPieces > 0)
  {
    vtkWarningMacro(<< unresolvedPieces << " ray pieces in general cells were split "
                    << MaximumSplitDepth << " levels deep or into " << MaximumPiecesPerCell
                    << " pieces and still not linear within "
                    << "QuadratureTolerance: the image may be off by more there.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "TransferFunctionTolerance: " << this->TransferFunctionTolerance << "\n";
  os << indent << "QuadratureTolerance: " << this->QuadratureTolerance << "\n";
  os << indent << "BlendMode: " << this->BlendMode << "\n";
  os << indent << "AverageIPScalarRange: (" << this->AverageIPScalarRange[0] << ", "
     << this->AverageIPScalarRange[1] << ")\n";
  os << indent << "EmbedIsoSurfaces: " << this->EmbedIsoSurfaces << "\n";
  os << indent << "Lights: " << this->Lights << "\n";
  os << indent << "ClippingPlanes: " << this->ClippingPlanes << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "Camera: " << this->Camera << "\n";
}
