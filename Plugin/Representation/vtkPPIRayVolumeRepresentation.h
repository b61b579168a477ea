/**
 * @class   vtkPPIRayVolumeRepresentation
 * @brief   ParaView's unstructured-grid volume representation, rendered by
 *          vtkUnstructuredGridGPURayCastMapper ("PPIRay Volume")
 *
 * Everything a ParaView volume representation does is inherited from
 * vtkUnstructuredGridVolumeRepresentation: the colour and opacity transfer
 * functions and their scalar range, Scalar Opacity Unit Distance, block
 * selection, the translucent-surface LOD for interaction, and in parallel the
 * request for ordered compositing (the view redistributes the data into
 * visibility-sortable pieces; each rank ray casts its piece and IceT
 * composites them in order). The only volume mapper is PPIRay's: the
 * inherited mapper selection is ignored.
 *
 * Input: unstructured grids and any dataset or composite dataset (the
 * representation's preprocessor merges blocks and tetrahedralizes).
 * Hexahedral data (a structured or image grid, or an unstructured grid of
 * hexahedra and voxels only, alone or as the one block of a composite
 * dataset) is passed to the mapper as hexahedra instead, so that its
 * HexahedronMode applies (default HEXAHEDRON_ACCURATE: the trilinear field,
 * not six linear tetrahedra), when ParaView runs in one process: in parallel
 * the view redistributes the preprocessor's output and the pass-through
 * aborted the 2-rank run (Documentation/paraview.md).
 *
 * The mapper's settings are forwarded without touching the pipeline, so a
 * change re-renders without re-uploading geometry or scalars (the mapper's
 * caches and upload counters are reachable through GetPPIRayMapper()).
 * The mapper's progress while it prepares a new mesh is the
 * representation's (ProgressEvent), for ParaView's progress bar.
 */
#ifndef vtkPPIRayVolumeRepresentation_h
#define vtkPPIRayVolumeRepresentation_h

#include "ppirayParaViewModule.h" // for export macro
#include "vtkUnstructuredGridVolumeRepresentation.h"

class vtkUnstructuredGridGPURayCastMapper;

class PPIRAYPARAVIEW_EXPORT vtkPPIRayVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  static vtkPPIRayVolumeRepresentation* New();
  vtkTypeMacro(vtkPPIRayVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The mapper is always PPIRay's; other names are ignored (with a debug
   * message) so that a shared "SelectMapper" property cannot switch it.
   */
  void SetActiveVolumeMapper(const char* name) override;

  ///@{
  /** Forwarded to vtkUnstructuredGridGPURayCastMapper. */
  void SetIntegrationMode(int mode);
  void SetMaximumNumberOfPeels(int peels);
  void SetNonConvexMode(int mode);
  void SetTetrahedronLayout(int layout);
  void SetMarchStage(int stage);
  void SetPsiTableSize(int size);
  void SetPreIntegrationTableSize(int size);
  void SetTerminationOpacity(double opacity);
  // The mapper's NO_ISOSURFACES (composite), EMBEDDED_ISOSURFACES (composite
  // with the isosurfaces embedded) or ISOSURFACES_ONLY (ISOSURFACE_BLEND), or
  // MaximumIntensity, MinimumIntensity, AverageIntensity, Additive (the
  // projections).
  enum
  {
    MaximumIntensity = 3,
    MinimumIntensity = 4,
    AverageIntensity = 5,
    Additive = 6
  };
  void SetPPIRayBlendMode(int mode);
  // The scalar range the average intensity projection averages.
  void SetAverageIPScalarRange(double lo, double hi);
  // The isovalues, in the volume property (vtkImageVolumeRepresentation's
  // names, so that ParaView's isovalue widgets drive them the same way).
  void SetIsosurfaceValue(int i, double value);
  void SetNumberOfIsosurfaces(int number);
  // Lighting of the isosurfaces (the volume property's Shade).
  void SetShade(int shade);
  // Also decides whether hexahedral data bypasses the tetrahedralization.
  void SetHexahedronMode(int mode);
  // The fewest levels higher-order cells are refined by.
  void SetNonlinearSubdivisionLevel(int level);
  ///@}

  /** The mapper (for its counters, GPU memory size and peel count). */
  vtkUnstructuredGridGPURayCastMapper* GetPPIRayMapper();

  int ProcessViewRequest(
    vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

  /** Whether the last update passed the cells to the mapper unsplit. */
  bool GetPassesCellsUnsplit() const { return this->PassesCellsUnsplit; }

protected:
  vtkPPIRayVolumeRepresentation();
  ~vtkPPIRayVolumeRepresentation() override;

  /** Unstructured grids, any other dataset, composite datasets. */
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkPPIRayVolumeRepresentation(const vtkPPIRayVolumeRepresentation&) = delete;
  void operator=(const vtkPPIRayVolumeRepresentation&) = delete;

  // The mapper's ProgressEvent as this representation's progress.
  void ForwardMapperProgress(vtkObject*, unsigned long, void* progress);

  vtkUnstructuredGridGPURayCastMapper* Mapper;
  unsigned long ProgressObserver = 0;
  bool PassesCellsUnsplit = false;
};

#endif
