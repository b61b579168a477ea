#include "vtkPPIRayVolumeRepresentation.h"

#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkContourValues.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"
#include "vtkVolumeProperty.h"

#include <cstring>

namespace
{
// The name the mapper is registered under with AddVolumeMapper().
constexpr const char* PPIRayMapperName = "PPIRay";
}

vtkStandardNewMacro(vtkPPIRayVolumeRepresentation);

//------------------------------------------------------------------------------
vtkPPIRayVolumeRepresentation::vtkPPIRayVolumeRepresentation()
  : Mapper(vtkUnstructuredGridGPURayCastMapper::New())
{
  this->AddVolumeMapper(PPIRayMapperName, this->Mapper);
  this->Superclass::SetActiveVolumeMapper(PPIRayMapperName);
}

//------------------------------------------------------------------------------
vtkPPIRayVolumeRepresentation::~vtkPPIRayVolumeRepresentation()
{
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
  this->Mapper->SetBlendMode(mode == 1 ? vtkUnstructuredGridGPURayCastMapper::ISOSURFACE_BLEND
                                       : vtkUnstructuredGridGPURayCastMapper::COMPOSITE_BLEND);
  this->Mapper->SetEmbedIsoSurfaces(mode == 2);
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
  os << indent << "Mapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
