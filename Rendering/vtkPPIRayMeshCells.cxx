#include "vtkPPIRayMeshCells.h"

#include "ppirayLinearCellKinds.h"
#include "ppirayMapperModes.h"
#include "ppirayProgress.h"
#include "vtkPPIRayGridInput.h"
#include "vtkUnstructuredGrid.h"

//------------------------------------------------------------------------------
vtkPPIRayMeshCells::Status vtkPPIRayMeshCells::Update(vtkUnstructuredGridBase* input,
  const Modes& modes, vtkPPIRayGridInput& grid, vtkWindow* window, vtkObject* reporter)
{
  this->Stages.Clear();
  this->Rebuilt = false;
  ppiray::StageTimes::Laps laps(this->Stages);
  const ppiray::GridGeometryKey::Match match = this->Key.Update(input);
  laps.End("geometry key");
  const bool sameModes = this->Built == modes;
  if (match != ppiray::GridGeometryKey::Match::Changed && sameModes)
  {
    if (this->Input != input || match == ppiray::GridGeometryKey::Match::SameContent)
    {
      ++this->ReuseCount; // a grid object or arrays seen for the first time, same geometry
    }
    this->Input = input;
    return this->Valid ? Status::Current : Status::Failed;
  }
  this->Input = input;
  this->Rebuilt = true;
  ppiray::ReportProgress(reporter, 0.0);
  this->Built = modes;
  this->Time.Modified();
  this->Valid = false;
  vtkUnstructuredGrid* valid = grid.Validated(input, reporter);
  laps.End("validation");
  if (!valid)
  {
    return Status::Failed;
  }
  // Natively when the mode asks for it and the mesh allows it, else tetrahedra.
  using Result = vtkPPIRayCellBuffers::BuildResult;
  vtkPPIRayCellBuffers* buffers = &this->Native;
  // The layouts' stages are the rebuild's progress in CellsProgress.
  const ppiray::ProgressForwarding nativeProgress(this->Native.GetGeometryBuilder(), reporter,
    ppiray::CellsProgress[0], ppiray::CellsProgress[1]);
  const ppiray::ProgressForwarding tetrahedraProgress(this->Tetrahedra.GetGeometryBuilder(),
    reporter, ppiray::CellsProgress[0], ppiray::CellsProgress[1]);
  this->Native.SetSubdivisionLevel(modes.SubdivisionLevel);
  Result result = modes.Native ? this->Native.BuildGeometry(valid, reporter) : Result::Declined;
  if (result == Result::Declined)
  {
    buffers = &this->Tetrahedra;
    this->Tetrahedra.SetLayout(modes.Layout == ppiray::TetrahedronCompact
                                 ? vtkTetrahedralCellTextures::COMPACT
                                 : vtkTetrahedralCellTextures::PLANES);
    result = this->Tetrahedra.BuildGeometry(valid, reporter);
  }
  if (this->Buffers && this->Buffers != buffers)
  {
    this->Buffers->ReleaseGraphicsResources(window);
  }
  this->Buffers = buffers;
  this->Stages.Add(buffers->GetGeometryStageTimes());
  this->Valid = result == Result::Built;
  return this->Valid ? Status::Rebuilt : Status::Failed;
}

//------------------------------------------------------------------------------
vtkTetrahedralCellTextures* vtkPPIRayMeshCells::GetTetrahedralTextures()
{
  return this->Buffers == &this->Tetrahedra ? this->Tetrahedra.GetTextures() : nullptr;
}

//------------------------------------------------------------------------------
vtkIdType vtkPPIRayMeshCells::GetNumberOfTetrahedra() const
{
  return this->Buffers == &this->Tetrahedra ? this->Tetrahedra.GetNumberOfTetrahedra() : 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkPPIRayMeshCells::GetNumberOfHexahedra() const
{
  return this->Buffers == &this->Native
           ? this->Native.GetNumberOfCellsOfKind(ppiray::HEXAHEDRON_KIND)
           : 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkPPIRayMeshCells::GetNumberOfNativeCells() const
{
  return this->Buffers == &this->Native ? this->Native.GetNumberOfCells() : 0;
}

//------------------------------------------------------------------------------
int vtkPPIRayMeshCells::GetGeometryUploadCount() const
{
  return this->Tetrahedra.GetGeometryUploadCount() + this->Native.GetGeometryUploadCount();
}

//------------------------------------------------------------------------------
int vtkPPIRayMeshCells::GetFieldUploadCount() const
{
  return this->Tetrahedra.GetFieldUploadCount() + this->Native.GetFieldUploadCount();
}

//------------------------------------------------------------------------------
void vtkPPIRayMeshCells::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Tetrahedra.ReleaseGraphicsResources(window);
  this->Native.ReleaseGraphicsResources(window);
}
