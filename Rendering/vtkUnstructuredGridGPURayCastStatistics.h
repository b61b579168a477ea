/**
 * @class   vtkUnstructuredGridGPURayCastStatistics
 * @brief   what vtkUnstructuredGridGPURayCastMapper's last frame did: cells, uploads, passes
 *
 * The mapper's diagnostics in one object (vtkUnstructuredGridGPURayCastMapper::
 * GetStatistics()), refreshed at the end of every frame and when the mapper
 * releases its GL objects: how the mesh was rendered (natively or split into
 * tetrahedra, boundary faces linked in a convexified grid), how many times
 * each cache was built (tests assert that a transfer function edit did not
 * re-upload the geometry), the frame's peels, continuations and cell steps,
 * CPU and GPU time, and GPU memory.
 */
#ifndef vtkUnstructuredGridGPURayCastStatistics_h
#define vtkUnstructuredGridGPURayCastStatistics_h

#include "ppirayRenderingModule.h" // for export macro
#include "ppirayStageTimes.h"      // for ppiray::StageTimes
#include "vtkObject.h"

class vtkPPIRayPassTimes;
class vtkPPIRayStageChoice;

class PPIRAYRENDERING_EXPORT vtkUnstructuredGridGPURayCastStatistics : public vtkObject
{
public:
  static vtkUnstructuredGridGPURayCastStatistics* New();
  vtkTypeMacro(vtkUnstructuredGridGPURayCastStatistics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Tetrahedra rendered (after skipping unsupported and flat cells); 0 when
   * the mesh is marched natively.
   */
  vtkGetMacro(NumberOfTetrahedra, vtkIdType);

  /**
   * Hexahedra (and voxels) rendered natively; 0 when the mesh was split
   * into tetrahedra.
   */
  vtkGetMacro(NumberOfHexahedra, vtkIdType);

  /**
   * Cells rendered natively, without subdivision: hexahedra, voxels,
   * wedges, pyramids and, in a mesh of those, tetrahedra (0 when the mesh
   * was split into tetrahedra).
   */
  vtkGetMacro(NumberOfNativeCells, vtkIdType);

  ///@{
  /**
   * A convexified grid (cell array "ppirayBoundaryCell"): the mesh's boundary
   * faces joined to the imaginary faces on them where point ids do not join
   * them (split by Steiner points, or across a seam) — rays cross these —,
   * those of them split into several pieces, and those left open (rays
   * leave there and re-enter by depth peeling; a warning names them).
   */
  vtkGetMacro(NumberOfLinkedBoundaryFaces, vtkIdType);
  vtkGetMacro(NumberOfSplitBoundaryFaces, vtkIdType);
  vtkGetMacro(NumberOfUnlinkedBoundaryFaces, vtkIdType);
  ///@}

  ///@{
  /** How many times each cache was (re)built and uploaded. */
  vtkGetMacro(GeometryUploadCount, int);
  vtkGetMacro(FieldUploadCount, int);
  vtkGetMacro(TransferFunctionUploadCount, int);
  ///@}

  /**
   * How many times the cells were kept for a grid object, or arrays, not
   * seen before that hold the same points and cells (a time series' next
   * step): only the field was built again.
   */
  vtkGetMacro(GeometryReuseCount, int);

  /** Seconds the last FULL_PRE_INTEGRATION table build took (0 if none yet). */
  vtkGetMacro(PreIntegrationTableBuildTime, double);

  /**
   * Bytes the mapper holds on the GPU (cell textures, boundary, transfer
   * function, integration tables, render targets).
   */
  vtkGetMacro(GPUMemorySize, vtkIdType);

  ///@{
  /**
   * Bytes of the cell arrays alone (geometry, neighbours, field; without the
   * boundary, transfer function, tables and targets), and those over the
   * cells marched (GetNumberOfTetrahedra() or GetNumberOfNativeCells()):
   * what a cell costs in the layout in use. Every kind costs the same in
   * one layout (the native layout stores each cell in a hexahedron's slots);
   * lists of split faces and re-entry faces add a little
   * (Documentation/results.md, "GPU bytes per cell, by kind and layout").
   */
  vtkGetMacro(CellArrayBytes, vtkIdType);
  double GetBytesPerCell() const;
  ///@}

  /** Depth peels the last frame needed. */
  vtkGetMacro(NumberOfPeels, int);

  /**
   * Where the last frame's march ran: vtkUnstructuredGridGPURayCastMapper::
   * MARCH_STAGE_FRAGMENT or MARCH_STAGE_COMPUTE (never AUTOMATIC).
   */
  vtkGetMacro(MarchStage, int);

  /**
   * MARCH_STAGE_AUTOMATIC's choice: the stage kept after its probe (the
   * first frames of a scene alternate the stages, timed), or -1 while it
   * probes or the stage is not automatic.
   */
  vtkGetMacro(ChosenMarchStage, int);

  /**
   * The probe's best frame in `stage` (MARCH_STAGE_FRAGMENT or
   * MARCH_STAGE_COMPUTE): milliseconds from before the frame's first pass
   * to after its last, the GPU waited for; -1: not timed.
   */
  double GetMarchStageProbeTime(int stage);

  /**
   * March passes the last frame added to continue rays that needed more loop
   * iterations than one pass takes (thousands of transfer-function control
   * points crossed along a ray; some drivers end a shader's loops silently
   * past a total count, Mesa's llvmpipe at 65,535).
   */
  vtkGetMacro(NumberOfContinuations, int);

  /**
   * Cell steps the last frame's rays took, over every pixel and peel (a step
   * crosses one cell, or one piece of a folded cell); 0 unless the mapper's
   * CountCellSteps is on.
   */
  vtkGetMacro(NumberOfCellSteps, vtkIdType);

  /**
   * CPU milliseconds of the last frame before its first pass: updating what
   * changed, the near-plane sections, uniforms.
   */
  vtkGetMacro(PreparationTime, double);

  ///@{
  /**
   * The stages of the last frame's preparation, in order, with their CPU
   * milliseconds: "geometry key" (whether the points and cells changed),
   * and when the cells were built "validation" and the cell layout's stages
   * (e.g. "tetrahedra", "planes", "adjacency" — or "folds" where a
   * deforming mesh kept its faces' pairs —, "boundary"), then "field"
   * (scalars and transfer function), "upload" (cells and transfer function
   * to the GPU) and "integration tables" (the integration mode's tables).
   */
  int GetNumberOfPreparationStages();
  const char* GetPreparationStageName(int stage);
  double GetPreparationStageTime(int stage);
  ///@}

  /**
   * The kinds of pass a frame draws (the mapper's TimePasses): the opaque
   * depth copy and target clears, the near-plane sections (camera inside),
   * each layer of boundary triangles with its occlusion query, each march,
   * each check for rays left unfinished by the loop budget, the composite.
   */
  enum PassKinds
  {
    SETUP_PASS = 0,
    NEAR_PLANE_ENTRY_PASS = 1,
    ENTRY_PASS = 2,
    MARCH_PASS = 3,
    CONTINUATION_CHECK_PASS = 4,
    COMPOSITE_PASS = 5,
    NUMBER_OF_PASS_KINDS = 6
  };

  /**
   * GPU milliseconds the last frame spent in passes of `kind`, and how many
   * it drew (0 unless TimePasses and the GL has timer queries).
   */
  double GetPassTime(int kind);
  int GetNumberOfPasses(int kind);
  static const char* GetPassKindName(int kind);

protected:
  vtkUnstructuredGridGPURayCastStatistics() = default;
  ~vtkUnstructuredGridGPURayCastStatistics() override = default;

private:
  vtkUnstructuredGridGPURayCastStatistics(const vtkUnstructuredGridGPURayCastStatistics&) = delete;
  void operator=(const vtkUnstructuredGridGPURayCastStatistics&) = delete;

  // The mapper writes them (vtkUnstructuredGridGPURayCastMapper::vtkInternals).
  friend class vtkUnstructuredGridGPURayCastMapper;
  // The last frame's pass times, and the automatic stage's choice (none
  // unless `automatic`).
  void CollectTimes(
    const vtkPPIRayPassTimes& times, const vtkPPIRayStageChoice& choice, bool automatic);

  vtkIdType NumberOfTetrahedra = 0;
  vtkIdType NumberOfHexahedra = 0;
  vtkIdType NumberOfNativeCells = 0;
  vtkIdType NumberOfLinkedBoundaryFaces = 0;
  vtkIdType NumberOfSplitBoundaryFaces = 0;
  vtkIdType NumberOfUnlinkedBoundaryFaces = 0;
  int GeometryUploadCount = 0;
  int FieldUploadCount = 0;
  int TransferFunctionUploadCount = 0;
  int GeometryReuseCount = 0;
  ppiray::StageTimes PreparationStages;
  double PreIntegrationTableBuildTime = 0.0;
  vtkIdType GPUMemorySize = 0;
  vtkIdType CellArrayBytes = 0;
  int NumberOfPeels = 0;
  int MarchStage = 0;
  int ChosenMarchStage = -1;
  double MarchStageProbeTimes[2] = { -1.0, -1.0 };
  int NumberOfContinuations = 0;
  vtkIdType NumberOfCellSteps = 0;
  double PreparationTime = 0.0;
  double PassTimes[NUMBER_OF_PASS_KINDS] = {};
  int PassCounts[NUMBER_OF_PASS_KINDS] = {};
};

#endif
