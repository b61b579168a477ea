#include "vtkPPIRayVolumeRepresentation.h"

#include "ppirayConformingTetrahedra.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkAppendFilter.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkContourValues.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"
#include "vtkRectilinearGrid.h"
#include "vtkScalarsToColors.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumeRepresentationPreprocessor.h"

#include <cstring>

#include <algorithm>

namespace
{
// The name the mapper is registered under with AddVolumeMapper().
constexpr const char* PPIRayMapperName = "PPIRay";

// Whether the grid's ghost array marks any cell HIDDENCELL.
bool HasHiddenCells(vtkUnstructuredGrid* grid)
{
  vtkUnsignedCharArray* ghosts = grid->GetCellGhostArray();
  for (vtkIdType c = 0; ghosts && c < ghosts->GetNumberOfValues(); ++c)
  {
    if (ghosts->GetValue(c) & vtkDataSetAttributes::HIDDENCELL)
    {
      return true;
    }
  }
  return false;
}

// Whether every cell of `data` is a hexahedron or a voxel (`mixed` false), or
// one of the 3D cells the mapper renders itself: tetrahedra, hexahedra,
// voxels, wedges and pyramids, linear, quadratic or of higher order, split
// conformingly by the mapper where it does not render them natively (`mixed`
// true). Linear tetrahedra alone keep ParaView's usual path, unless some
// are hidden.
bool RenderedUnsplit(vtkDataSet* data, bool mixed)
{
  if (vtkStructuredGrid::SafeDownCast(data) || vtkImageData::SafeDownCast(data) ||
      vtkRectilinearGrid::SafeDownCast(data))
  {
    return data->GetNumberOfCells() > 0 && data->GetCell(0)->GetCellDimension() == 3;
  }
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    return false;
  }
  bool tetrahedraOnly = true;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const int type = grid->GetCellType(c);
    tetrahedraOnly = tetrahedraOnly && type == VTK_TETRA;
    const bool hexahedral = type == VTK_HEXAHEDRON || type == VTK_VOXEL;
    // Higher-order cells carry their field to the mapper
    // (vtkDataSetTriangleFilter would split them into linear tetrahedra).
    if (!hexahedral && !(mixed && ppiray::LinearShapeOf(type).Type != 0))
    {
      return false;
    }
  }
  // Tetrahedra take ParaView's usual path, which drops hidden cells: a grid
  // with hidden cells (a convexified grid's imaginary cells) keeps them.
  return !tetrahedraOnly || HasHiddenCells(grid);
}

// `output` made to hold the cells of `data` as they are (structured cells as
// hexahedra or voxels).
void CopyCells(vtkDataSet* data, vtkUnstructuredGrid* output)
{
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    output->ShallowCopy(grid);
    return;
  }
  vtkNew<vtkAppendFilter> append;
  append->AddInputData(data);
  append->Update();
  output->ShallowCopy(append->GetOutput());
}

// The one non-empty dataset of `input` (itself, or the only non-empty leaf
// of a composite dataset); null if there are several or none.
vtkDataSet* SingleDataSet(vtkDataObject* input)
{
  if (auto* data = vtkDataSet::SafeDownCast(input))
  {
    return data;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (!composite)
  {
    return nullptr;
  }
  vtkDataSet* found = nullptr;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    if (leaf && leaf->GetNumberOfCells() > 0)
    {
      if (found)
      {
        return nullptr;
      }
      found = leaf;
    }
  }
  return found;
}
}

vtkStandardNewMacro(vtkPPIRayVolumeRepresentation);

//------------------------------------------------------------------------------
vtkPPIRayVolumeRepresentation::vtkPPIRayVolumeRepresentation()
  : Mapper(vtkUnstructuredGridGPURayCastMapper::New())
{
  this->AddVolumeMapper(PPIRayMapperName, this->Mapper);
  this->Superclass::SetActiveVolumeMapper(PPIRayMapperName);
  this->ProgressObserver = this->Mapper->AddObserver(
    vtkCommand::ProgressEvent, this, &vtkPPIRayVolumeRepresentation::ForwardMapperProgress);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::ForwardMapperProgress(vtkObject*, unsigned long, void* progress)
{
  this->UpdateProgress(*static_cast<double*>(progress));
}

//------------------------------------------------------------------------------
vtkPPIRayVolumeRepresentation::~vtkPPIRayVolumeRepresentation()
{
  // The superclass holds the mapper a little longer: nothing may call back here.
  this->Mapper->RemoveObserver(this->ProgressObserver);
  this->Mapper->Delete();
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetActiveVolumeMapper(const char* name)
{
  if (name && std::strcmp(name, PPIRayMapperName) != 0)
  {
    vtkDebugMacro("Ignoring volume mapper \"" << name << "\": this representation renders with "
                                              << PPIRayMapperName);
  }
}

//------------------------------------------------------------------------------
vtkUnstructuredGridGPURayCastMapper* vtkPPIRayVolumeRepresentation::GetPPIRayMapper()
{
  return this->Mapper;
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetIntegrationMode(int mode)
{
  this->Mapper->SetIntegrationMode(mode);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetMaximumNumberOfPeels(int peels)
{
  this->Mapper->SetMaximumNumberOfPeels(peels);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetNonConvexMode(int mode)
{
  this->Mapper->SetNonConvexMode(mode);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetTetrahedronLayout(int layout)
{
  this->Mapper->SetTetrahedronLayout(layout);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetMarchStage(int stage)
{
  this->Mapper->SetMarchStage(stage);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetPsiTableSize(int size)
{
  this->Mapper->SetPsiTableSize(size);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetPreIntegrationTableSize(int size)
{
  this->Mapper->SetPreIntegrationTableSize(size);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetTerminationOpacity(double opacity)
{
  this->Mapper->SetTerminationOpacity(opacity);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetPPIRayBlendMode(int mode)
{
  using Mapper = vtkUnstructuredGridGPURayCastMapper;
  const int blend = mode == Mapper::ISOSURFACES_ONLY ? static_cast<int>(Mapper::ISOSURFACE_BLEND)
                    : mode == MaximumIntensity ? static_cast<int>(Mapper::MAXIMUM_INTENSITY_BLEND)
                    : mode == MinimumIntensity ? static_cast<int>(Mapper::MINIMUM_INTENSITY_BLEND)
                    : mode == AverageIntensity ? static_cast<int>(Mapper::AVERAGE_INTENSITY_BLEND)
                    : mode == Additive         ? static_cast<int>(Mapper::ADDITIVE_BLEND)
                                               : static_cast<int>(Mapper::COMPOSITE_BLEND);
  this->Mapper->SetBlendMode(blend);
  this->Mapper->SetEmbedIsoSurfaces(mode == Mapper::EMBEDDED_ISOSURFACES);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetAverageIPScalarRange(double lo, double hi)
{
  this->Mapper->SetAverageIPScalarRange(lo, hi);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetIsosurfaceValue(int i, double value)
{
  this->Property->GetIsoSurfaceValues()->SetValue(i, value);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetNumberOfIsosurfaces(int number)
{
  this->Property->GetIsoSurfaceValues()->SetNumberOfContours(number);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetShade(int shade)
{
  this->Property->SetShade(shade);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetNonlinearSubdivisionLevel(int level)
{
  this->Mapper->SetNonlinearSubdivisionLevel(level);
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::SetHexahedronMode(int mode)
{
  if (mode != this->Mapper->GetHexahedronMode())
  {
    this->Mapper->SetHexahedronMode(mode);
    this->MarkModified(); // may switch between passing hexahedra and the preprocessor
  }
}

//------------------------------------------------------------------------------
int vtkPPIRayVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The cells reach the mapper as they are, in one process and on each rank
  // in parallel (the view then redistributes whole cells for ordered
  // compositing): hexahedra when the mapper renders them natively, and
  // meshes of tetrahedra, hexahedra, wedges and pyramids (linear, quadratic
  // or of higher order) in any mode (the mapper's conforming split, with shared
  // diagonals, instead of vtkDataSetTriangleFilter's, which leaves
  // zero-volume and non-manifold tetrahedra on real FE meshes and can take
  // minutes on their non-planar faces, and splits higher-order cells into
  // linear tetrahedra).
  this->PassesCellsUnsplit = false;
  vtkDataObject* input = inputVector[0]->GetNumberOfInformationObjects() == 1
                           ? vtkDataObject::GetData(inputVector[0], 0)
                           : nullptr;
  vtkDataSet* data = input ? SingleDataSet(input) : nullptr;
  const bool subdivide =
    this->Mapper->GetHexahedronMode() == vtkUnstructuredGridGPURayCastMapper::HEXAHEDRON_SUBDIVIDE;
  const bool unsplit =
    data && RenderedUnsplit(data, true) && !(subdivide && RenderedUnsplit(data, false));

  // The view delivers the preprocessor's output (vtkPVRenderView::SetPiece in
  // the superclass): it is made to hold the cells. A single dataset skips the
  // preprocessor altogether (nothing to extract, nothing to split).
  if (unsplit && vtkDataSet::SafeDownCast(input) && !this->UseSeparateOpacityArray)
  {
    auto* output = vtkUnstructuredGrid::SafeDownCast(this->Preprocessor->GetOutputDataObject(0));
    if (output)
    {
      CopyCells(data, output);
      vtkMath::UninitializeBounds(this->DataBounds);
      output->GetBounds(this->DataBounds);
      this->PassesCellsUnsplit = true;
      return this->vtkVolumeRepresentation::RequestData(request, inputVector, outputVector);
    }
  }
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  // A composite dataset: the preprocessor ran (block selection); its output,
  // if it kept the block, is replaced by the cells as they are.
  auto* preprocessed =
    vtkUnstructuredGrid::SafeDownCast(this->Preprocessor->GetOutputDataObject(0));
  if (unsplit && preprocessed && preprocessed->GetNumberOfCells() > 0)
  {
    CopyCells(data, preprocessed);
    this->PassesCellsUnsplit = true;
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPPIRayVolumeRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPPIRayVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo))
  {
    return 0;
  }
  if (request == vtkPVView::REQUEST_RENDER())
  {
    // A multi-component array is rendered as the colour map shows it:
    // ParaView's "colour by" menu sets the lookup table's vector mode.
    if (vtkColorTransferFunction* lut = this->Property->GetRGBTransferFunction(0))
    {
      if (lut->GetVectorMode() == vtkScalarsToColors::COMPONENT)
      {
        this->Mapper->SetVectorModeToComponent();
        this->Mapper->SetVectorComponent(std::max(0, lut->GetVectorComponent()));
      }
      else
      {
        this->Mapper->SetVectorModeToMagnitude();
      }
    }
    // In parallel a rank may hold no cells after redistribution: an empty
    // piece is normal there, not the user error the mapper reports.
    vtkAlgorithmOutput* port = vtkPVRenderView::GetPieceProducer(inInfo, this);
    vtkDataSet* piece =
      port ? vtkDataSet::SafeDownCast(port->GetProducer()->GetOutputDataObject(0)) : nullptr;
    if (!piece || piece->GetNumberOfCells() == 0)
    {
      this->Actor->SetMapper(nullptr);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkPPIRayVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PassesCellsUnsplit: " << this->PassesCellsUnsplit << "\n";
  os << indent << "Mapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
