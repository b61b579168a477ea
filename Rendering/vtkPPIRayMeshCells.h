/**
 * @class   vtkPPIRayMeshCells
 * @brief   the cells a mesh is rendered as: natively, or split into tetrahedra
 *
 * Chooses and keeps the cell buffers of a grid: its linear cells marched
 * natively when the mode asks for it and the mesh allows it
 * (vtkPPIRayHexahedralCellBuffers), else every cell split into tetrahedra
 * in the chosen layout (vtkPPIRayTetrahedralCellBuffers). Rebuilt when the
 * grid's points or cells, or the modes, change; kept for a new grid object
 * with the same points and cells (ppiray::GridGeometryKey: the same arrays,
 * or arrays with the same values), as a time series hands over at every
 * step. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayMeshCells_h
#define vtkPPIRayMeshCells_h

#include "ppirayGridGeometryKey.h" // for ppiray::GridGeometryKey
#include "vtkPPIRayHexahedralCellBuffers.h"
#include "vtkPPIRayTetrahedralCellBuffers.h"
#include "vtkTimeStamp.h" // for vtkTimeStamp

class vtkObject;
class vtkPPIRayGridInput;
class vtkUnstructuredGridBase;
class vtkWindow;

class vtkPPIRayMeshCells
{
public:
  vtkPPIRayMeshCells() = default;

  enum class Status
  {
    Current, // as last built (and valid)
    Rebuilt, // built anew from the grid
    Failed   // nothing to render (reported)
  };
  /** How the cells are built; a change rebuilds them. */
  struct Modes
  {
    bool Native;          // natively where the mesh allows it
    int Layout;           // else as tetrahedra in this layout (ppiray::TetrahedronLayout)
    int SubdivisionLevel; // vtkHexahedralCellTextures::SetMinimumRefinementLevel()
    bool operator==(const Modes& o) const
    {
      return this->Native == o.Native && this->Layout == o.Layout &&
             this->SubdivisionLevel == o.SubdivisionLevel;
    }
  };
  /**
   * The cells of `input` (validated by `grid`) built in `modes`. The buffers
   * no longer used release their GL objects in `window`.
   */
  Status Update(vtkUnstructuredGridBase* input, const Modes& modes, vtkPPIRayGridInput& grid,
    vtkWindow* window, vtkObject* reporter);

  /** The buffers the mesh is rendered with (null before the first Update()). */
  vtkPPIRayCellBuffers* GetBuffers() const { return this->Buffers; }
  /**
   * Wall time of each stage of the last Update(): the geometry key, and when
   * the cells were built, the validation and the build's stages.
   */
  const ppiray::StageTimes& GetStageTimes() const { return this->Stages; }
  /** When the cells were last built. */
  vtkMTimeType GetMTime() const { return this->Time.GetMTime(); }
  /** Whether the last Update() built the cells (its progress reported from 0). */
  bool WasRebuilt() const { return this->Rebuilt; }

  ///@{
  /** What the last build made, for the mapper's statistics. */
  vtkIdType GetNumberOfTetrahedra() const;
  vtkIdType GetNumberOfHexahedra() const;
  vtkIdType GetNumberOfNativeCells() const;
  // The split cells' textures (boundary face links), or null when native.
  vtkTetrahedralCellTextures* GetTetrahedralTextures();
  int GetGeometryUploadCount() const;
  int GetFieldUploadCount() const;
  // Updates that kept the cells for a grid object or arrays not seen before.
  int GetGeometryReuseCount() const { return this->ReuseCount; }
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPPIRayMeshCells(const vtkPPIRayMeshCells&) = delete;
  void operator=(const vtkPPIRayMeshCells&) = delete;

  vtkPPIRayTetrahedralCellBuffers Tetrahedra;
  vtkPPIRayHexahedralCellBuffers Native;
  vtkPPIRayCellBuffers* Buffers = nullptr; // the kind the mesh is rendered as
  vtkUnstructuredGridBase* Input = nullptr;
  ppiray::GridGeometryKey Key; // the geometry the cells were built from
  ppiray::StageTimes Stages;   // of the last Update()
  int ReuseCount = 0;
  vtkTimeStamp Time;
  Modes Built = { false, 0, 0 }; // the modes built with
  bool Valid = false;
  bool Rebuilt = false; // by the last Update()
};

#endif
