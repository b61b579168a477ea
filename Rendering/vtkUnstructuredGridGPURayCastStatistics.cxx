#include "vtkUnstructuredGridGPURayCastStatistics.h"

#include "vtkObjectFactory.h"
#include "vtkPPIRayPassTimes.h"
#include "vtkPPIRayStageChoice.h"

vtkStandardNewMacro(vtkUnstructuredGridGPURayCastStatistics);

static_assert(
  int(vtkUnstructuredGridGPURayCastStatistics::SETUP_PASS) == vtkPPIRayPassTimes::Setup &&
    int(vtkUnstructuredGridGPURayCastStatistics::NEAR_PLANE_ENTRY_PASS) ==
      vtkPPIRayPassTimes::NearPlaneEntry &&
    int(vtkUnstructuredGridGPURayCastStatistics::ENTRY_PASS) == vtkPPIRayPassTimes::Entry &&
    int(vtkUnstructuredGridGPURayCastStatistics::MARCH_PASS) == vtkPPIRayPassTimes::March &&
    int(vtkUnstructuredGridGPURayCastStatistics::CONTINUATION_CHECK_PASS) ==
      vtkPPIRayPassTimes::ContinuationCheck &&
    int(vtkUnstructuredGridGPURayCastStatistics::COMPOSITE_PASS) == vtkPPIRayPassTimes::Composite &&
    int(vtkUnstructuredGridGPURayCastStatistics::NUMBER_OF_PASS_KINDS) ==
      vtkPPIRayPassTimes::NumberOfPasses,
  "one set of pass kinds");

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastStatistics::CollectTimes(
  const vtkPPIRayPassTimes& times, const vtkPPIRayStageChoice& choice, bool automatic)
{
  for (int kind = 0; kind < NUMBER_OF_PASS_KINDS; ++kind)
  {
    this->PassTimes[kind] = times.GetMilliseconds(kind);
    this->PassCounts[kind] = times.GetCount(kind);
  }
  this->ChosenMarchStage = automatic ? choice.GetChosen() : -1;
  for (int stage = 0; stage < 2; ++stage)
  {
    this->MarchStageProbeTimes[stage] = automatic ? choice.GetProbeMilliseconds(stage) : -1.0;
  }
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridGPURayCastStatistics::GetMarchStageProbeTime(int stage)
{
  return stage == 0 || stage == 1 ? this->MarchStageProbeTimes[stage] : -1.0;
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridGPURayCastStatistics::GetPassTime(int kind)
{
  return kind >= 0 && kind < NUMBER_OF_PASS_KINDS ? this->PassTimes[kind] : 0.0;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridGPURayCastStatistics::GetNumberOfPasses(int kind)
{
  return kind >= 0 && kind < NUMBER_OF_PASS_KINDS ? this->PassCounts[kind] : 0;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridGPURayCastStatistics::GetNumberOfPreparationStages()
{
  return static_cast<int>(this->PreparationStages.Get().size());
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastStatistics::GetPreparationStageName(int stage)
{
  return stage >= 0 && stage < this->GetNumberOfPreparationStages()
           ? this->PreparationStages.Get()[stage].Name.c_str()
           : nullptr;
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridGPURayCastStatistics::GetPreparationStageTime(int stage)
{
  return stage >= 0 && stage < this->GetNumberOfPreparationStages()
           ? this->PreparationStages.Get()[stage].Milliseconds
           : 0.0;
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastStatistics::GetPassKindName(int kind)
{
  return vtkPPIRayPassTimes::GetName(kind);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastStatistics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "NumberOfHexahedra: " << this->NumberOfHexahedra << "\n";
  os << indent << "NumberOfNativeCells: " << this->NumberOfNativeCells << "\n";
  os << indent << "NumberOfLinkedBoundaryFaces: " << this->NumberOfLinkedBoundaryFaces << "\n";
  os << indent << "NumberOfSplitBoundaryFaces: " << this->NumberOfSplitBoundaryFaces << "\n";
  os << indent << "NumberOfUnlinkedBoundaryFaces: " << this->NumberOfUnlinkedBoundaryFaces << "\n";
  os << indent << "GeometryUploadCount: " << this->GeometryUploadCount << "\n";
  os << indent << "GeometryReuseCount: " << this->GeometryReuseCount << "\n";
  os << indent << "FieldUploadCount: " << this->FieldUploadCount << "\n";
  os << indent << "TransferFunctionUploadCount: " << this->TransferFunctionUploadCount << "\n";
  os << indent << "PreIntegrationTableBuildTime: " << this->PreIntegrationTableBuildTime << "\n";
  os << indent << "GPUMemorySize: " << this->GPUMemorySize << "\n";
  os << indent << "CellArrayBytes: " << this->CellArrayBytes << "\n";
  os << indent << "NumberOfPeels: " << this->NumberOfPeels << "\n";
  os << indent << "MarchStage: " << this->MarchStage
     << ", ChosenMarchStage: " << this->ChosenMarchStage << " (probe: fragment "
     << this->MarchStageProbeTimes[0] << " ms, compute " << this->MarchStageProbeTimes[1]
     << " ms)\n";
  os << indent << "NumberOfContinuations: " << this->NumberOfContinuations << "\n";
  os << indent << "NumberOfCellSteps: " << this->NumberOfCellSteps << "\n";
  os << indent << "PreparationTime: " << this->PreparationTime << "\n";
  for (int kind = 0; kind < NUMBER_OF_PASS_KINDS; ++kind)
  {
    os << indent << GetPassKindName(kind) << ": " << this->PassCounts[kind] << " passes, "
       << this->PassTimes[kind] << " ms\n";
  }
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridGPURayCastStatistics::GetBytesPerCell() const
{
  const vtkIdType cells = this->NumberOfTetrahedra + this->NumberOfNativeCells;
  return cells > 0 ? static_cast<double>(this->CellArrayBytes) / cells : 0.0;
}
