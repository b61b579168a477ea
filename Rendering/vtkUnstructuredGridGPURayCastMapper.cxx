#include "vtkUnstructuredGridGPURayCastMapper.h"

#include "ppirayMapperModes.h"
#include "ppirayProgress.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPPIRayDepthPeeling.h"
#include "vtkPPIRayFrameBuilder.h"
#include "vtkPPIRayGridInput.h"
#include "vtkPPIRayIsoSurfaceUniforms.h"
#include "vtkPPIRayMarchShader.h"
#include "vtkPPIRayMeshCells.h"
#include "vtkPPIRayScalarField.h"
#include "vtkPPIRaySegmentIntegrator.h"
#include "vtkPPIRayTransferFunctionTexture.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGridAlgorithm.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkUnstructuredGridGPURayCastStatistics.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkUnstructuredGridGPURayCastMapper);

// The public enums have the values the collaborators act on
// (ppirayMapperModes.h, ppirayIsoSurfaces.h).
using Mapper = vtkUnstructuredGridGPURayCastMapper;
static_assert(int(Mapper::PARTIAL_PRE_INTEGRATION) == ppiray::PartialPreIntegration &&
                int(Mapper::EXACT_LINEAR) == ppiray::ExactLinear &&
                int(Mapper::FULL_PRE_INTEGRATION) == ppiray::FullPreIntegration &&
                int(Mapper::AVERAGE_COLOR) == ppiray::AverageColor &&
                int(Mapper::HEXAHEDRON_ACCURATE) == ppiray::HexahedronAccurate &&
                int(Mapper::HEXAHEDRON_FAST) == ppiray::HexahedronFast &&
                int(Mapper::HEXAHEDRON_SUBDIVIDE) == ppiray::HexahedronSubdivide &&
                int(Mapper::TETRAHEDRON_PLANES) == ppiray::TetrahedronPlanes &&
                int(Mapper::TETRAHEDRON_COMPACT) == ppiray::TetrahedronCompact &&
                int(Mapper::MARCH_STAGE_COMPUTE) == ppiray::MarchCompute &&
                int(Mapper::NON_CONVEX_PEEL) == ppiray::NonConvexPeel &&
                int(Mapper::NON_CONVEX_CONVEXIFY) == ppiray::NonConvexConvexify &&
                int(Mapper::NON_CONVEX_AUTOMATIC) == ppiray::NonConvexAutomatic &&
                int(Mapper::MAXIMUM_INTENSITY_BLEND) == ppiray::MaximumIntensity &&
                int(Mapper::MINIMUM_INTENSITY_BLEND) == ppiray::MinimumIntensity &&
                int(Mapper::AVERAGE_INTENSITY_BLEND) == ppiray::AverageIntensity &&
                int(Mapper::ADDITIVE_BLEND) == ppiray::Additive &&
                int(Mapper::NO_ISOSURFACES) == ppiray::NoIsoSurfaces &&
                int(Mapper::EMBEDDED_ISOSURFACES) == ppiray::EmbeddedIsoSurfaces &&
                int(Mapper::ISOSURFACES_ONLY) == ppiray::IsoSurfacesOnly,
  "one set of mode values");

//------------------------------------------------------------------------------
// The collaborators, each owning one concept and its GL objects, and what the
// cells were built from.
class vtkUnstructuredGridGPURayCastMapper::vtkInternals
{
public:
  vtkPPIRayMeshCells Mesh;
  vtkPPIRayCellBuffers* Cells = nullptr; // the mesh's buffers, for this frame
  vtkPPIRayGridInput GridInput;

  vtkPPIRayScalarField Field;
  vtkPPIRayTransferFunctionTexture TransferFunction;
  std::unique_ptr<vtkPPIRaySegmentIntegrator> Integrator;
  vtkPPIRayIsoSurfaceUniforms IsoSurfaces;
  vtkPPIRayMarchShader MarchShader;
  vtkPPIRayDepthPeeling Peeling;
  vtkPPIRayFrameBuilder FrameBuilder;
  vtkNew<vtkUnstructuredGridGPURayCastStatistics> Statistics;
  bool OverlapWarned = false; // overlapping PPIRay volumes were reported
  // The context the GL objects live in (one at a time, as VTK's own mappers
  // keep them).
  vtkWeakPointer<vtkOpenGLRenderWindow> Context;

  // Releases the GL objects in the context they live in (made current for
  // it, then restored), else in `window`'s.
  void ReleaseInTheirContext(vtkWindow* window)
  {
    if (vtkOpenGLRenderWindow* context = this->Context)
    {
      context->PushContext();
      this->ReleaseGraphicsResources(context);
      context->PopContext();
      this->Context = nullptr;
      // PopContext restores the earlier context only for X windows (VTK's
      // default PushContext just makes the window current): `window`, where
      // the caller renders next, is made current again.
      if (auto* next = vtkOpenGLRenderWindow::SafeDownCast(window))
      {
        next->MakeCurrent();
      }
    }
    else
    {
      this->ReleaseGraphicsResources(window);
    }
  }

  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Mesh.ReleaseGraphicsResources(window);
    this->TransferFunction.ReleaseGraphicsResources(window);
    if (this->Integrator)
    {
      this->Integrator->ReleaseGraphicsResources(window);
    }
    this->MarchShader.ReleaseGraphicsResources(window);
    this->Peeling.ReleaseGraphicsResources(window);
  }
};

//------------------------------------------------------------------------------
vtkUnstructuredGridGPURayCastMapper::vtkUnstructuredGridGPURayCastMapper()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkUnstructuredGridGPURayCastMapper::~vtkUnstructuredGridGPURayCastMapper()
{
  if (this->Internals->Context)
  {
    this->Internals->ReleaseInTheirContext(nullptr);
  }
  this->SetConvexifier(nullptr);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(
  vtkUnstructuredGridGPURayCastMapper, Convexifier, vtkUnstructuredGridAlgorithm);

//------------------------------------------------------------------------------
vtkUnstructuredGridBase* vtkUnstructuredGridGPURayCastMapper::RenderedGrid(
  vtkUnstructuredGridBase* input)
{
  if (this->NonConvexMode != NON_CONVEX_PEEL && !this->Convexifier)
  {
    // One registered with VTK's object factory (by PPIRay::Convexify, not linked here).
    auto made = vtkSmartPointer<vtkObject>::Take(
      vtkObjectFactory::CreateInstance("vtkUnstructuredGridConvexify"));
    this->SetConvexifier(vtkUnstructuredGridAlgorithm::SafeDownCast(made));
  }
  return this->Internals->GridInput.Rendered(input, this->NonConvexMode, this->Convexifier, this);
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridGPURayCastMapper::GetNonConvexChoice()
{
  return this->Internals->GridInput.GetNonConvexChoice();
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::SetIntegrationMode(int mode)
{
  ppiray::SetMode(this, this->IntegrationMode, mode, ppiray::IntegrationModeNames);
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastMapper::GetIntegrationModeAsString()
{
  return ppiray::ModeName(ppiray::IntegrationModeNames, this->IntegrationMode);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::SetHexahedronMode(int mode)
{
  ppiray::SetMode(this, this->HexahedronMode, mode, ppiray::HexahedronModeNames);
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastMapper::GetHexahedronModeAsString()
{
  return ppiray::ModeName(ppiray::HexahedronModeNames, this->HexahedronMode);
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastMapper::GetTetrahedronLayoutAsString()
{
  return ppiray::ModeName(ppiray::TetrahedronLayoutNames, this->TetrahedronLayout);
}

//------------------------------------------------------------------------------
vtkUnstructuredGridGPURayCastStatistics* vtkUnstructuredGridGPURayCastMapper::GetStatistics()
{
  return this->Internals->Statistics;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::CollectStatistics()
{
  vtkInternals& in = *this->Internals;
  vtkUnstructuredGridGPURayCastStatistics& out = *in.Statistics;
  vtkTetrahedralCellTextures* split = in.Mesh.GetTetrahedralTextures();
  out.NumberOfTetrahedra = in.Mesh.GetNumberOfTetrahedra();
  out.NumberOfHexahedra = in.Mesh.GetNumberOfHexahedra();
  out.NumberOfNativeCells = in.Mesh.GetNumberOfNativeCells();
  out.NumberOfLinkedBoundaryFaces = split ? split->GetNumberOfLinkedFaces() : 0;
  out.NumberOfSplitBoundaryFaces = split ? split->GetNumberOfSplitFaces() : 0;
  out.NumberOfUnlinkedBoundaryFaces = split ? split->GetNumberOfUnlinkedFaces() : 0;
  out.GeometryUploadCount = in.Mesh.GetGeometryUploadCount();
  out.FieldUploadCount = in.Mesh.GetFieldUploadCount();
  out.GeometryReuseCount = in.Mesh.GetGeometryReuseCount();
  out.TransferFunctionUploadCount = in.TransferFunction.GetUploadCount();
  out.PreIntegrationTableBuildTime = in.Integrator ? in.Integrator->GetTableBuildTime() : 0.0;
  out.GPUMemorySize = static_cast<vtkIdType>(
    (in.Mesh.GetBuffers() ? in.Mesh.GetBuffers()->GetGPUBytes() : 0) +
    in.TransferFunction.GetGPUBytes() + (in.Integrator ? in.Integrator->GetGPUBytes() : 0) +
    in.Peeling.GetGPUBytes() + in.MarchShader.GetGPUBytes());
  out.CellArrayBytes =
    static_cast<vtkIdType>(in.Mesh.GetBuffers() ? in.Mesh.GetBuffers()->GetCellArrayBytes() : 0);
  out.CollectTimes(in.Peeling.GetPassTimes(), in.MarchShader.GetChoice(),
    this->MarchStage == MARCH_STAGE_AUTOMATIC);
  out.Modified();
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  // Deleted in their own context, whichever window asks (or closes).
  this->Internals->ReleaseInTheirContext(window);
  this->CollectStatistics();
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateCells(
  vtkUnstructuredGridBase* input, vtkOpenGLRenderWindow* context)
{
  vtkInternals& in = *this->Internals;
  const vtkPPIRayMeshCells::Modes modes = { this->HexahedronMode != HEXAHEDRON_SUBDIVIDE,
    this->TetrahedronLayout, this->NonlinearSubdivisionLevel };
  const auto status = in.Mesh.Update(input, modes, in.GridInput, context, this);
  if (status != vtkPPIRayMeshCells::Status::Current)
  {
    in.Field.Invalidate(); // the field follows the cells
  }
  in.Cells = in.Mesh.GetBuffers();
  return status != vtkPPIRayMeshCells::Status::Failed;
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateField(vtkUnstructuredGridBase* input)
{
  vtkInternals& in = *this->Internals;
  vtkPPIRayScalarField::Selection selection = { this->ScalarMode, this->ArrayAccessMode,
    this->ArrayId, this->ArrayName, this->VectorMode == MAGNITUDE, this->VectorComponent };
  switch (in.Field.Update(input, selection, this))
  {
    case vtkPPIRayScalarField::Status::Failed:
      return false;
    case vtkPPIRayScalarField::Status::Changed:
      in.Cells->BuildField(in.Field.GetValues(), in.Field.IsCellData(), this);
      return true;
    default:
      return true;
  }
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateIntegrator(vtkOpenGLRenderWindow* context)
{
  vtkInternals& in = *this->Internals;
  if (!in.Integrator || in.Integrator->GetIntegrationMode() != this->IntegrationMode)
  {
    if (in.Integrator)
    {
      in.Integrator->ReleaseGraphicsResources(context);
    }
    in.Integrator = vtkPPIRaySegmentIntegrator::New(this->IntegrationMode);
  }
  const double* range = in.Field.GetRange();
  const vtkPPIRaySegmentIntegrator::Inputs inputs = { in.TransferFunction.GetControlPoints(),
    { range[0], range[1] }, in.Field.GetShift(), in.Cells->GetMaximumSegmentLength(),
    std::max({ in.TransferFunction.GetMTime(), in.Field.GetMTime(), in.Mesh.GetMTime() }),
    this->PsiTableSize, this->PreIntegrationTableSize };
  return in.Integrator->Update(context, inputs, this);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::WarnAboutOverlappingVolumes(
  vtkRenderer* ren, vtkVolume* vol)
{
  // Each PPIRay volume composites its whole image over what was drawn before
  // it: overlapping ones are not interleaved per pixel.
  const int overlapping = vtkPPIRayFrameBuilder::CountOverlappingVolumes(ren, vol);
  vtkInternals& in = *this->Internals;
  if (overlapping > 0 && !in.OverlapWarned)
  {
    vtkWarningMacro(<< overlapping
                    << " other PPIRay volumes overlap this one: each is composited whole over "
                       "what was rendered before it, in the renderer's order, not interleaved "
                       "per pixel.");
  }
  in.OverlapWarned = overlapping > 0;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  // The frame's wall time, for AutoAdjustSampleDistances.
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->RenderFrame(ren, vol);
  this->CollectStatistics();
  timer->StopTimer();
  this->TimeToDraw = timer->GetElapsedTime();
}

//------------------------------------------------------------------------------
vtkUnstructuredGridBase* vtkUnstructuredGridGPURayCastMapper::FrameInput(
  vtkRenderer* ren, vtkVolume* vol)
{
  if (this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  vtkUnstructuredGridBase* input = this->GetInput();
  if (!input || !vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) || !vol ||
      !vol->GetProperty())
  {
    vtkErrorMacro("Nothing to render: " << (!input ? "no input" : "no OpenGL window or property"));
    return nullptr;
  }
  if (input->GetNumberOfCells() == 0 || input->GetNumberOfPoints() == 0)
  {
    return nullptr; // an empty grid is a valid scene: nothing to draw
  }
  return this->RenderedGrid(input);
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateCollaborators(
  vtkUnstructuredGridBase* input, vtkVolume* vol, vtkOpenGLRenderWindow* context)
{
  // GL objects made in another context (a second window) are released there
  // first and made again in this one.
  vtkInternals& in = *this->Internals;
  if (in.Context != context)
  {
    in.ReleaseInTheirContext(context);
    in.Context = context;
  }
  const bool cells = this->UpdateCells(input, context);
  in.Statistics->PreparationStages.Add(in.Mesh.GetStageTimes());
  // A rebuild's progress: the cells' stages, then these three to 1.
  ppiray::StageTimes::Laps laps(in.Statistics->PreparationStages,
    [this, rebuilt = in.Mesh.WasRebuilt()](int lap)
    {
      if (rebuilt)
      {
        ppiray::ReportProgress(
          this, ppiray::CellsProgress[1] + (1 - ppiray::CellsProgress[1]) * lap / 3);
      }
    });
  if (!cells || !this->UpdateField(input) ||
      !in.TransferFunction.Update(vol->GetProperty(), in.Field.GetShift(), this))
  {
    return false;
  }
  laps.End("field");
  in.Cells->SetMaximumBufferTexels(static_cast<size_t>(this->MaximumBufferTexels));
  const bool uploaded =
    in.Cells->Upload(context, this) && in.TransferFunction.Upload(context, this);
  laps.End("upload");
  const bool integrator = uploaded && this->UpdateIntegrator(context);
  laps.End("integration tables");
  return integrator;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::RenderFrame(vtkRenderer* ren, vtkVolume* vol)
{
  vtkNew<vtkTimerLog> preparation;
  preparation->StartTimer();
  vtkInternals& in = *this->Internals;
  vtkUnstructuredGridGPURayCastStatistics& statistics = *in.Statistics;
  statistics.NumberOfPeels = statistics.NumberOfContinuations = 0;
  statistics.NumberOfCellSteps = 0;
  statistics.PreparationTime = 0.0;
  statistics.PreparationStages.Clear();
  vtkUnstructuredGridBase* input = this->FrameInput(ren, vol);
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!input)
  {
    return;
  }

  // Find what is stale and update the collaborators, on the CPU, then the GPU.
  this->WarnAboutOverlappingVolumes(ren, vol);
  const ppiray::IsoSurfaceMode isoMode =
    in.IsoSurfaces.Update(ren, vol, this->BlendMode, this->EmbedIsoSurfaces != 0, this);
  if (!this->UpdateCollaborators(input, vol, context))
  {
    return;
  }
  if (this->AutoAdjustSampleDistances)
  {
    this->ImageSampleDistance = static_cast<float>(vtkPPIRayFrameBuilder::AdjustedSampleDistance(
      this->ImageSampleDistance, this->TimeToDraw, vol->GetAllocatedRenderTime(),
      this->MinimumImageSampleDistance, this->MaximumImageSampleDistance));
  }
  vtkPPIRayFrameBuilder::Settings settings;
  const bool projects =
    this->BlendMode >= MAXIMUM_INTENSITY_BLEND && this->BlendMode <= ADDITIVE_BLEND;
  settings.Projection = projects ? this->BlendMode : ppiray::Composite;
  settings.TerminationOpacity = this->TerminationOpacity;
  settings.MaximumPeels = this->MaximumNumberOfPeels;
  settings.MaximumSteps = this->MaximumNumberOfSteps;
  settings.CountCellSteps = this->CountCellSteps != 0;
  settings.TimePasses = this->TimePasses != 0;
  settings.TimeFrame = in.MarchShader.Probing(this->MarchStage);
  settings.ImageSampleDistance = this->ImageSampleDistance;
  settings.ClippingPlanes = this->ClippingPlanes;
  if (!in.MarchShader.Ready(context,
        in.Cells->GetMarchShader(this->HexahedronMode == HEXAHEDRON_ACCURATE),
        in.Integrator->GetShaderCode(), vtkPPIRayIsoSurfaceUniforms::Declarations(isoMode),
        settings.Projection, this->MarchStage, this) ||
      !in.FrameBuilder.Build(ren, vol, *in.Cells, settings, this))
  {
    return;
  }

  // Peel: each march reads the cells, the transfer function, the integrator's
  // tables and the isosurfaces.
  const vtkPPIRayDepthPeeling::Frame& frame = in.FrameBuilder.GetFrame();
  auto marchInputs = [&](vtkShaderProgram* program, std::vector<vtkTextureObject*>& textures)
  {
    in.Cells->Bind(program, textures);
    in.TransferFunction.Bind(program, textures);
    in.Integrator->Bind(program, textures);
    program->SetUniformi("maximumSteps", in.FrameBuilder.GetMaximumSteps());
    program->SetUniformf("terminationAlpha", frame.TerminationAlpha);
    program->SetUniformf("opacityUnitDistance",
      static_cast<float>(in.TransferFunction.GetControlPoints()->GetUnitDistance()));
    if (settings.Projection >= ppiray::AverageIntensity)
    {
      in.Field.BindProjection(program, this->AverageIPScalarRange);
    }
    if (isoMode != ppiray::NoIsoSurfaces)
    {
      in.IsoSurfaces.Bind(program, in.FrameBuilder.GetLocalToWorld(), in.Field.GetShift());
    }
  };
  bool cut = false;
  preparation->StopTimer();
  statistics.PreparationTime = 1000.0 * preparation->GetElapsedTime();
  statistics.NumberOfPeels = std::max(
    0, in.Peeling.Render(context, frame, *in.Cells, in.MarchShader, marchInputs, cut, this));
  statistics.MarchStage = in.MarchShader.GetStage();
  in.MarchShader.ObserveFrame(
    in.Peeling, in.Mesh.GetNumberOfTetrahedra(), in.Mesh.GetNumberOfNativeCells());
  statistics.NumberOfContinuations = in.Peeling.GetNumberOfContinuations();
  statistics.NumberOfCellSteps = static_cast<vtkIdType>(in.Peeling.GetNumberOfCellSteps());
  in.GridInput.ObserveFrame(statistics.NumberOfPeels, in.Mesh.GetNumberOfHexahedra() > 0);
  if (cut)
  {
    vtkWarningMacro(
      "Stopped after MaximumNumberOfPeels = " << this->MaximumNumberOfPeels
                                              << " depth peels; parts of the mesh may be missing.");
  }
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegrationMode: " << this->GetIntegrationModeAsString() << "\n";
  os << indent << "HexahedronMode: " << this->GetHexahedronModeAsString()
     << ", NonlinearSubdivisionLevel: " << this->NonlinearSubdivisionLevel << "\n";
  os << indent << "TetrahedronLayout: " << this->GetTetrahedronLayoutAsString()
     << ", MarchStage: " << this->MarchStage << "\n";
  os << indent << "EmbedIsoSurfaces: " << this->EmbedIsoSurfaces << ", AverageIPScalarRange: ("
     << this->AverageIPScalarRange[0] << ", " << this->AverageIPScalarRange[1] << ")\n";
  os << indent << "VectorMode: " << (this->VectorMode == MAGNITUDE ? "MAGNITUDE" : "COMPONENT")
     << ", VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "MaximumNumberOfPeels: " << this->MaximumNumberOfPeels
     << ", NonConvexMode: " << this->NonConvexMode << "\n";
  os << indent << "Convexifier: " << this->Convexifier << "\n";
  os << indent << "MaximumNumberOfSteps: " << this->MaximumNumberOfSteps << "\n";
  os << indent << "PsiTableSize: " << this->PsiTableSize
     << ", PreIntegrationTableSize: " << this->PreIntegrationTableSize << "\n";
  os << indent << "TerminationOpacity: " << this->TerminationOpacity << "\n";
  os << indent << "CountCellSteps: " << this->CountCellSteps << ", TimePasses: " << this->TimePasses
     << "\n";
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "MinimumImageSampleDistance: " << this->MinimumImageSampleDistance
     << ", MaximumImageSampleDistance: " << this->MaximumImageSampleDistance << "\n";
  os << indent << "AutoAdjustSampleDistances: " << this->AutoAdjustSampleDistances << "\n";
  os << indent << "MaximumBufferTexels: " << this->MaximumBufferTexels << "\n";
  os << indent << "Statistics:\n";
  this->Internals->Statistics->PrintSelf(os, indent.GetNextIndent());
}
