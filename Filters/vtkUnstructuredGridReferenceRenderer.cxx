#include "vtkUnstructuredGridReferenceRenderer.h"

#include "ppirayConformingTetrahedra.h"
#include "ppirayIsoSurfaces.h"
#include "ppirayRayIntegrator.h"
#include "ppirayRaySegments.h"
#include "ppirayReferenceCells.h"
#include "ppirayReferenceTransferFunction.h"
#include "ppirayValidPointIds.h"
#include "ppirayVolumeIntegrals.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"
#include "vtkVolumeProperty.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

vtkStandardNewMacro(vtkUnstructuredGridReferenceRenderer);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, VolumeProperty, vtkVolumeProperty);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, Lights, vtkLightCollection);
vtkCxxSetObjectMacro(vtkUnstructuredGridReferenceRenderer, ClippingPlanes, vtkPlaneCollection);

using namespace ppiray::reference;

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
  vtkImageData* output = vtkImageData::GetData(outputVector);
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  vtkNew<vtkFloatArray> rgba;
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  rgba->Fill(0.0);
  output->GetPointData()->SetScalars(rgba);
  if (!this->VolumeProperty || !this->Camera || !this->VolumeProperty->GetScalarOpacity(0))
  {
    vtkErrorMacro("A volume property with a scalar opacity function and a camera are required.");
    return 1;
  }
  if (!input || input->GetNumberOfCells() == 0)
  {
    return 1;
  }
  int association = 0;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, input, association);
  if (!scalars)
  {
    vtkErrorMacro("No scalars to render.");
    return 1;
  }
  const bool cellScalars = association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
  vtkIdType invalidCells = 0;
  const vtkSmartPointer<vtkUnstructuredGrid> validCells =
    ppiray::EmptyCellsWithInvalidPointIds(input, invalidCells);
  if (validCells)
  {
    vtkErrorMacro(<< invalidCells << " cells list point ids outside [0, "
                  << input->GetNumberOfPoints() << "): they are not rendered.");
    input = validCells;
  }

  const ReferenceCells cells = CollectCells(input);
  if (cells.CornerTetrahedra)
  {
    vtkWarningMacro(<< cells.CornerTetrahedra
                    << " higher-order tetrahedra rendered through their corners.");
  }
  if (cells.Skipped)
  {
    vtkWarningMacro(<< cells.Skipped << " cells of other types than linear 3D cells skipped.");
  }
  const vtkIdType numberOfTets = cells.NumberOfTetrahedra();
  double scalarRange[2];
  scalars->GetRange(scalarRange, 0);
  // Relative to the range; for a (nearly) constant field, to the values'
  // magnitude (the interpolation's own rounding is not a deviation).
  const double linearTolerance =
    this->QuadratureTolerance *
    std::max({ scalarRange[1] - scalarRange[0],
      1e-9 * std::max(std::abs(scalarRange[0]), std::abs(scalarRange[1])), 1e-300 });

  TransferFunction tf;
  tf.Build(this->VolumeProperty, this->TransferFunctionTolerance);
  std::string isoWarning;
  const ppiray::IsoSurfaces iso = ppiray::ReadIsoSurfaces(this->VolumeProperty,
    ppiray::ChooseIsoSurfaceMode(this->BlendMode, this->EmbedIsoSurfaces != 0,
      this->VolumeProperty->GetIsoSurfaceValues()->GetNumberOfContours(), isoWarning),
    this->Lights);
  if (!isoWarning.empty())
  {
    vtkWarningMacro(<< isoWarning);
  }

  // Camera: clip <-> world, with world shifted to the centre of the bounds.
  double bounds[6];
  input->GetBounds(bounds);
  const Vec3 centre = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  vtkNew<vtkMatrix4x4> worldToClip, clipToWorld;
  worldToClip->DeepCopy(this->Camera->GetCompositeProjectionTransformMatrix(
    static_cast<double>(width) / height, -1, 1));
  vtkMatrix4x4::Invert(worldToClip, clipToWorld);

  // Clipping planes in the frame centred on the bounds: n . y + (d + n . centre) >= 0.
  std::vector<glm::dvec4> clippingPlanes;
  const int planes = this->ClippingPlanes ? this->ClippingPlanes->GetNumberOfItems() : 0;
  for (int i = 0; i < std::min(planes, 6); ++i)
  {
    vtkPlane* plane = this->ClippingPlanes->GetItem(i);
    const Vec3 n = glm::make_vec3(plane->GetNormal()), o = glm::make_vec3(plane->GetOrigin());
    clippingPlanes.emplace_back(n, glm::dot(n, centre - o));
  }

  const bool projection =
    this->BlendMode >= MAXIMUM_INTENSITY_BLEND && this->BlendMode <= ADDITIVE_BLEND;
  Projection how;
  how.Blend = this->BlendMode;
  const double scalarWidth = scalarRange[1] - scalarRange[0];
  how.Normalize[0] = scalarWidth > 0 ? 1.0 / scalarWidth : 0.0;
  how.Normalize[1] = scalarWidth > 0 ? -scalarRange[0] / scalarWidth : 1.0;
  std::copy_n(this->AverageIPScalarRange, 2, how.AverageRange);
  ScreenTiles tiles;
  tiles.Build(input, cells, worldToClip, width, height);
  const int tilesX = tiles.TilesX, TileSize = ScreenTiles::Size;

  float* out = rgba->GetPointer(0);
  const int numberOfTiles = tiles.TilesX * tiles.TilesY;
  std::atomic<int> tilesDone(0);
  std::atomic<long long> unresolvedPieces(0);
  const std::thread::id caller = std::this_thread::get_id();
  this->UpdateProgress(0.0);
#pragma omp parallel for schedule(dynamic)
  for (int tile = 0; tile < numberOfTiles; ++tile)
  {
    if (this->GetAbortExecute())
    {
      continue; // aborted (e.g. by a progress observer): no tile is started
    }
    const int tx = tile % tilesX, ty = tile / tilesX;
    long long unresolved = 0;
    std::vector<Tetrahedron> local;
    std::vector<size_t> localGeneral; // indices into generalCells
    vtkNew<vtkGenericCell> cell;
    vtkNew<vtkGenericCell> gradientCell;
    std::vector<double> values, weights, derivatives;
    Vec3 origin, direction;
    // The interpolated field's gradient in general cell c at the ray's t.
    auto gradientAt = [&](vtkIdType c, double t) -> Vec3
    {
      if (cellScalars)
      {
        return { 0, 0, 0 };
      }
      input->GetCell(c, gradientCell);
      const int n = InterpolatedPoints(gradientCell);
      values.resize(n);
      weights.resize(std::max(n, 8));
      for (int v = 0; v < n; ++v)
      {
        values[v] = scalars->GetComponent(gradientCell->GetPointId(v), 0);
      }
      double x[3], pcoords[3], dist2, g[3] = { 0, 0, 0 };
      for (int i = 0; i < 3; ++i)
      {
        x[i] = origin[i] + t * direction[i] + centre[i];
      }
      int subId = 0;
      gradientCell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, weights.data());
      gradientCell->Derivatives(subId, pcoords, values.data(), 1, g);
      return { g[0], g[1], g[2] };
    };
    for (vtkIdType k = tiles.Offsets[tile]; k < tiles.Offsets[tile + 1]; ++k)
    {
      const vtkIdType t = tiles.Items[k];
      if (t >= numberOfTets)
      {
        localGeneral.push_back(static_cast<size_t>(t - numberOfTets));
        continue;
      }
      Vec3 p[4];
      Tetrahedron tet;
      for (int v = 0; v < 4; ++v)
      {
        const vtkIdType id = cells.Tetrahedra[4 * t + v];
        double x[3];
        input->GetPoints()->GetPoint(id, x);
        p[v] = Vec3(x[0], x[1], x[2]) - centre;
        tet.S[v] = cellScalars ? scalars->GetComponent(cells.TetrahedronCell[t], 0)
                               : scalars->GetComponent(id, 0);
      }
      if (std::isnan(tet.S[0] + tet.S[1] + tet.S[2] + tet.S[3]) || !InvertEdges(p, tet.Inverse))
      {
        continue;
      }
      tet.P0 = p[0];
      local.push_back(tet);
    }
    std::vector<Segment> segments;
    for (int py = ty * TileSize; py < std::min(height, (ty + 1) * TileSize); ++py)
    {
      for (int px = tx * TileSize; px < std::min(width, (tx + 1) * TileSize); ++px)
      {
        double ndcNear[4] = { 2.0 * (px + 0.5) / width - 1.0, 2.0 * (py + 0.5) / height - 1.0, -1.0,
          1.0 };
        double ndcFar[4] = { ndcNear[0], ndcNear[1], 1.0, 1.0 };
        double nearPoint[4], farPoint[4];
        clipToWorld->MultiplyPoint(ndcNear, nearPoint);
        clipToWorld->MultiplyPoint(ndcFar, farPoint);
        origin = Vec3(nearPoint[0], nearPoint[1], nearPoint[2]) / nearPoint[3] - centre;
        direction = glm::normalize(
          Vec3(farPoint[0], farPoint[1], farPoint[2]) / farPoint[3] - centre - origin);
        segments.clear();
        for (const Tetrahedron& tet : local)
        {
          Segment seg;
          if (ClipRay(tet, origin, direction, seg))
          {
            segments.push_back(seg);
          }
        }
        for (size_t g : localGeneral)
        {
          const auto& box = tiles.GeneralBox[g];
          if (px < box[0] || px > box[1] || py < box[2] || py > box[3]) // pixel centres at integers
          {
            continue;
          }
          const vtkIdType c = cells.General[g];
          input->GetCell(c, cell);
          GeneralCellSegments(c, cell, scalars, cellScalars ? c : -1, origin, direction, centre,
            linearTolerance, segments, unresolved);
        }
        ClipSegments(segments, KeptRange(clippingPlanes, origin, direction));
        float* pixel = out + 4 * (static_cast<size_t>(py) * width + px);
        if (projection)
        {
          ProjectRay(segments, tf, how, pixel);
        }
        else
        {
          IntegrateRay(segments, tf, iso, origin, direction, centre, gradientAt, pixel);
        }
      }
    }
    unresolvedPieces += unresolved;
    const int done = ++tilesDone;
    if (std::this_thread::get_id() == caller) // observers run on the calling thread only
    {
      this->UpdateProgress(static_cast<double>(done) / numberOfTiles);
    }
  }
  this->UpdateProgress(1.0);
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
