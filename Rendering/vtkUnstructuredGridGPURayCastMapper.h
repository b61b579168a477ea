/**
 * @class   vtkUnstructuredGridGPURayCastMapper
 * @brief   GPU ray casting of unstructured grids with partial pre-integration
 *
 * A drop-in vtkUnstructuredGridVolumeMapper: rays march from cell to cell in a
 * fragment shader (Weiler et al. 2003; Espinha & Celes 2005) and integrate the
 * volume rendering equation exactly for each cell's field and a
 * piecewise-linear transfer function: every ray segment is split at every transfer function
 * control point it crosses and integrated with Moreland and Angel's partial
 * pre-integration (Psi table). Depth peeling of the boundary re-enters
 * non-convex meshes, meshes with holes and disconnected parts.
 *
 * Semantics are those of VTK's unstructured volume mappers: attenuation
 * tau(s) = opacity(s) / ScalarOpacityUnitDistance, emission colour(s) tau(s).
 * Scalars are chosen with the vtkAbstractVolumeMapper API (SetScalarMode,
 * SelectScalarArray); point or cell data; of a multi-component array the
 * magnitude or one component (SetVectorMode, as vtkSmartVolumeMapper).
 * Transfer functions are rendered as VTK's volume mappers evaluate them
 * (vtkTransferFunctionControlPoints); infinite scalars or coordinates are
 * rejected with an error; cells listing point ids outside the points are
 * reported in one error and not rendered, the others are.
 * Opaque geometry already in the depth buffer stops the rays. A camera
 * inside the mesh: rays start at the near plane in the cell they are in.
 * Clipping planes (vtkAbstractMapper::AddClippingPlane, at most 6; each keeps
 * the side its normal points to) cut every ray piece exactly.
 *
 * Caches, each rebuilt for one reason (counted, see GetStatistics()):
 * geometry (planes, neighbours, boundary) when points or cells change; the
 * field when the scalars change; the transfer function when the volume
 * property changes; the Psi table once. The mapper coordinates collaborators
 * that each own one concept and its GL objects (Documentation/architecture.md).
 *
 * Cells: tetrahedra, hexahedra, voxels, wedges and pyramids, mixed freely,
 * marched natively, each with VTK's interpolation (see SetHexahedronMode()
 * for the exceptions); polyhedra split into conforming tetrahedra; other
 * cells are reported and skipped. Composite blending and the projections,
 * isosurfaces, perspective and parallel cameras, the integration modes of
 * SetIntegrationMode().
 */
#ifndef vtkUnstructuredGridGPURayCastMapper_h
#define vtkUnstructuredGridGPURayCastMapper_h

#include "ppirayRenderingModule.h"                   // for export macro
#include "vtkUnstructuredGridGPURayCastStatistics.h" // for GetStatistics()
#include "vtkUnstructuredGridVolumeMapper.h"

#include <memory> // for std::unique_ptr

class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkUnstructuredGridAlgorithm;
class vtkUnstructuredGridBase;
class vtkVolume;
class vtkWindow;

class PPIRAYRENDERING_EXPORT vtkUnstructuredGridGPURayCastMapper
  : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkUnstructuredGridGPURayCastMapper* New();
  vtkTypeMacro(vtkUnstructuredGridGPURayCastMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * How each ray segment is integrated; all modes share the traversal.
   * - PARTIAL_PRE_INTEGRATION (default): stops at every transfer-function
   *   control point, each piece by Moreland and Angel's Psi table.
   * - EXACT_LINEAR: the same stops, Psi in closed form in the shader (no table).
   * - FULL_PRE_INTEGRATION: the whole cell segment by one lookup in the 3D
   *   table over (s_front, s_back, length) of Röttger et al., built with
   *   Weiler's incremental method, rebuilt on every transfer-function change.
   * - AVERAGE_COLOR: the whole cell segment with the mean of its end colours
   *   and linear attenuation (Shirley-Tuchman; what projected tetrahedra do),
   *   no stops: cheap, misses transfer-function features inside a cell.
   * See Documentation/algorithms.md for the formulas and their sources.
   */
  enum IntegrationModes
  {
    PARTIAL_PRE_INTEGRATION = 0,
    EXACT_LINEAR = 1,
    FULL_PRE_INTEGRATION = 2,
    AVERAGE_COLOR = 3
  };

  ///@{
  /**
   * The integration mode (IntegrationModes), default PARTIAL_PRE_INTEGRATION.
   */
  virtual void SetIntegrationMode(int mode);
  vtkGetMacro(IntegrationMode, int);
  void SetIntegrationModeToPartialPreIntegration()
  {
    this->SetIntegrationMode(PARTIAL_PRE_INTEGRATION);
  }
  void SetIntegrationModeToExactLinear() { this->SetIntegrationMode(EXACT_LINEAR); }
  void SetIntegrationModeToFullPreIntegration() { this->SetIntegrationMode(FULL_PRE_INTEGRATION); }
  void SetIntegrationModeToAverageColor() { this->SetIntegrationMode(AVERAGE_COLOR); }
  const char* GetIntegrationModeAsString();
  ///@}

  /**
   * How hexahedra (also voxels and the corners of quadratic hexahedra) are
   * rendered; see Documentation/algorithms.md.
   * - HEXAHEDRON_ACCURATE: natively, with the trilinear field: along a ray a
   *   cubic, split at its extrema and at every control point crossing (found
   *   by safeguarded Newton), each piece integrated by Gauss-Legendre
   *   quadrature with the exact attenuation integral (Miranda 2011, Ch. 3);
   * - HEXAHEDRON_FAST: natively, the cubic split at its extrema, each
   *   monotonic piece integrated as linear by the integration mode
   *   (Miranda 2011, Ch. 4);
   * - HEXAHEDRON_SUBDIVIDE: split into 6 tetrahedra that conform across
   *   shared faces (ppirayConformingTetrahedra.h).
   * Default HEXAHEDRON_ACCURATE: exact to the transfer function like the
   * tetrahedral path (Documentation/results.md: on llvmpipe it takes about
   * twice the time of SUBDIVIDE, with a tenth of its error and 160 instead of
   * 576 bytes per hexahedron).
   * In a mesh of hexahedra, voxels, wedges, pyramids and tetrahedra, the
   * native modes march every cell natively (wedges and tetrahedra with their
   * affine field; pyramids with the cubic through VTK's field at four points
   * of the ray, Documentation/algorithms.md "Cell kinds"); SUBDIVIDE, or a
   * mesh with other cells (polyhedra, quadratic cells), splits every cell
   * into tetrahedra.
   */
  enum HexahedronModes
  {
    HEXAHEDRON_ACCURATE = 0,
    HEXAHEDRON_FAST = 1,
    HEXAHEDRON_SUBDIVIDE = 2
  };

  ///@{
  /** The hexahedron mode (HexahedronModes), default HEXAHEDRON_ACCURATE. */
  virtual void SetHexahedronMode(int mode);
  vtkGetMacro(HexahedronMode, int);
  void SetHexahedronModeToAccurate() { this->SetHexahedronMode(HEXAHEDRON_ACCURATE); }
  void SetHexahedronModeToFast() { this->SetHexahedronMode(HEXAHEDRON_FAST); }
  void SetHexahedronModeToSubdivide() { this->SetHexahedronMode(HEXAHEDRON_SUBDIVIDE); }
  const char* GetHexahedronModeAsString();
  ///@}

  ///@{
  /**
   * The fewest levels quadratic and higher-order cells other than ten-node
   * tetrahedra are refined by (like ParaView's Nonlinear Subdivision Level;
   * vtkHexahedralCellTextures::SetMinimumRefinementLevel(): each level cuts
   * the interpolation error of a smooth field about eightfold and makes 8
   * times the pieces). Default 1, at most 3.
   */
  vtkSetClampMacro(NonlinearSubdivisionLevel, int, 0, 3);
  vtkGetMacro(NonlinearSubdivisionLevel, int);
  ///@}

  /**
   * How tetrahedra (and the cells split into them) are laid out in GPU
   * memory; see Documentation/algorithms.md, "Cell layouts".
   * - TETRAHEDRON_PLANES: each tetrahedron's four face planes and linear
   *   field stored (Espinha & Celes 2005), 96 bytes per tetrahedron;
   * - TETRAHEDRON_COMPACT: point ids per tetrahedron and coordinates and
   *   scalar per point, the planes and field computed in the march (Maximo
   *   et al. 2008), 36 bytes per tetrahedron and 16 per point (about 40 per
   *   tetrahedron in a typical mesh).
   * Default TETRAHEDRON_PLANES. Images agree to float rounding.
   */
  enum TetrahedronLayouts
  {
    TETRAHEDRON_PLANES = 0,
    TETRAHEDRON_COMPACT = 1
  };

  ///@{
  /** The tetrahedron layout (TetrahedronLayouts), default TETRAHEDRON_PLANES. */
  vtkSetClampMacro(TetrahedronLayout, int, TETRAHEDRON_PLANES, TETRAHEDRON_COMPACT);
  vtkGetMacro(TetrahedronLayout, int);
  void SetTetrahedronLayoutToPlanes() { this->SetTetrahedronLayout(TETRAHEDRON_PLANES); }
  void SetTetrahedronLayoutToCompact() { this->SetTetrahedronLayout(TETRAHEDRON_COMPACT); }
  const char* GetTetrahedronLayoutAsString();
  ///@}

  /**
   * Where the march runs (Documentation/algorithms.md, "March stages"):
   * - MARCH_STAGE_FRAGMENT: a fragment shader over a full-screen quad, one
   *   fragment per pixel (every OpenGL 3.2 context);
   * - MARCH_STAGE_COMPUTE: the same march as a compute shader (OpenGL 4.3),
   *   one invocation per pixel in 8 x 8 work groups, storing into the same
   *   targets; where the context has no compute shaders or the shader does
   *   not build, one warning and the fragment stage;
   * - MARCH_STAGE_AUTOMATIC (default): the stage measured faster where the
   *   mapper runs, for the scene on screen: the first six frames of a scene
   *   alternate the stages, each frame's passes timed between two waits for
   *   the GPU, and the stage of the faster best frame is kept; a new march
   *   program, a mesh with other numbers of cells, or rays marched per pixel
   *   that change by more than a factor of two, measure again. The fragment
   *   stage, without a probe, where the context has no compute shaders.
   *   GetStatistics()->GetChosenMarchStage() and GetMarchStageProbeTime()
   *   report the choice.
   * GetStatistics()->GetMarchStage() says which ran. Both stages cast the
   * same rays: images agree to float rounding (identical on llvmpipe).
   */
  enum MarchStages
  {
    MARCH_STAGE_FRAGMENT = 0,
    MARCH_STAGE_COMPUTE = 1,
    MARCH_STAGE_AUTOMATIC = 2
  };

  ///@{
  /** The march stage (MarchStages), default MARCH_STAGE_AUTOMATIC. */
  vtkSetClampMacro(MarchStage, int, MARCH_STAGE_FRAGMENT, MARCH_STAGE_AUTOMATIC);
  vtkGetMacro(MarchStage, int);
  void SetMarchStageToFragment() { this->SetMarchStage(MARCH_STAGE_FRAGMENT); }
  void SetMarchStageToCompute() { this->SetMarchStage(MARCH_STAGE_COMPUTE); }
  void SetMarchStageToAutomatic() { this->SetMarchStage(MARCH_STAGE_AUTOMATIC); }
  ///@}

  /**
   * Blend modes: COMPOSITE_BLEND (vtkUnstructuredGridVolumeMapper) and VTK's
   * ISOSURFACE_BLEND (the value of vtkVolumeMapper::ISOSURFACE_BLEND): the
   * isosurfaces of vtkVolumeProperty::GetIsoSurfaceValues() (at most 16),
   * found exactly in each cell (the root of the linear field in a
   * tetrahedron, of the cubic along the ray in a hexahedron), coloured by
   * the colour transfer function and with the scalar opacity at the
   * isovalue as their opacity (1: opaque), lit with the renderer's lights and
   * the property's ambient, diffuse, specular and specular power when its
   * Shade is on (normal: the field gradient; trilinear in a hexahedron).
   * MAXIMUM_INTENSITY_BLEND (vtkUnstructuredGridVolumeMapper) and
   * MINIMUM_INTENSITY_BLEND (vtkVolumeMapper's value): the largest or
   * smallest scalar along the ray, exact per cell (at a segment's end, or at
   * an extremum of the cubic in a hexahedron), with the transfer function's
   * colour and scalar opacity there, as vtkGPUVolumeRayCastMapper colours
   * it. AVERAGE_INTENSITY_BLEND: over the parts of the ray where the scalar
   * lies in AverageIPScalarRange, the length-weighted average of scalar
   * opacity x scalar normalized to the array's range, as grey with opacity 1
   * (nothing where no part is in the range). ADDITIVE_BLEND: the integral
   * of scalar opacity x normalized scalar along the ray, per unit distance
   * (ScalarOpacityUnitDistance), as grey clamped to 1 with opacity 1: what
   * vtkGPUVolumeRayCastMapper sums over samples one unit distance apart,
   * independent of sampling. Both exact per cell (the integrand is quadratic
   * in the scalar between control points). Other blend modes render
   * composite, with a warning.
   */
  enum
  {
    MINIMUM_INTENSITY_BLEND = 2,
    AVERAGE_INTENSITY_BLEND = 3,
    ADDITIVE_BLEND = 4,
    ISOSURFACE_BLEND = 5
  };
  void SetBlendModeToIsoSurface() { this->SetBlendMode(ISOSURFACE_BLEND); }
  void SetBlendModeToMinimumIntensity() { this->SetBlendMode(MINIMUM_INTENSITY_BLEND); }
  void SetBlendModeToAverageIntensity() { this->SetBlendMode(AVERAGE_INTENSITY_BLEND); }
  void SetBlendModeToAdditive() { this->SetBlendMode(ADDITIVE_BLEND); }

  ///@{
  /**
   * The scalar range AVERAGE_INTENSITY_BLEND averages over, in the array's
   * units (vtkVolumeMapper's; default: every value).
   */
  vtkSetVector2Macro(AverageIPScalarRange, double);
  vtkGetVectorMacro(AverageIPScalarRange, double, 2);
  ///@}

  /**
   * What a frame draws of the isosurfaces (from the blend mode,
   * EmbedIsoSurfaces and the isovalues): none, embedded in the composite
   * volume, or the surfaces only. The shaders' ISO_MODE and the ParaView
   * representation's PPIRayBlendMode use these values.
   */
  enum
  {
    NO_ISOSURFACES = 0,
    EMBEDDED_ISOSURFACES = 1,
    ISOSURFACES_ONLY = 2
  };

  ///@{
  /**
   * In COMPOSITE_BLEND, also draw the isosurfaces of the property's
   * isovalues, embedded in the volume (Weiler et al. 2003, Fig. 1): the
   * volume is integrated up to each surface, the surface composited, and on.
   * Default off (VTK's composite mode ignores isovalues).
   */
  vtkSetMacro(EmbedIsoSurfaces, vtkTypeBool);
  vtkGetMacro(EmbedIsoSurfaces, vtkTypeBool);
  vtkBooleanMacro(EmbedIsoSurfaces, vtkTypeBool);
  ///@}

  /**
   * What a multi-component scalar array contributes (as vtkSmartVolumeMapper
   * and ParaView's "colour by" menu): MAGNITUDE (default) or the COMPONENT
   * VectorComponent. One-component arrays are rendered as they are.
   */
  enum VectorModes
  {
    MAGNITUDE = 0,
    COMPONENT = 1
  };

  ///@{
  /** Magnitude or one component of multi-component scalars (default MAGNITUDE). */
  vtkSetClampMacro(VectorMode, int, MAGNITUDE, COMPONENT);
  vtkGetMacro(VectorMode, int);
  void SetVectorModeToMagnitude() { this->SetVectorMode(MAGNITUDE); }
  void SetVectorModeToComponent() { this->SetVectorMode(COMPONENT); }
  ///@}

  ///@{
  /** The component rendered in COMPONENT mode (default 0). */
  vtkSetClampMacro(VectorComponent, int, 0, VTK_INT_MAX);
  vtkGetMacro(VectorComponent, int);
  ///@}

  ///@{
  /**
   * Upper bound on depth-peeling passes per frame (default 64). A mesh that
   * needs more is cut there, with a warning.
   */
  vtkSetClampMacro(MaximumNumberOfPeels, int, 1, 4096);
  vtkGetMacro(MaximumNumberOfPeels, int);
  ///@}

  ///@{
  /**
   * How rays that leave a non-convex mesh and enter it again are followed.
   * NON_CONVEX_PEEL (default): depth peeling, one pass per re-entry.
   * NON_CONVEX_CONVEXIFY: the Convexifier's output is rendered instead of the
   * input (run again when the input or the Convexifier changes): imaginary
   * cells marked HIDDENCELL fill the space around the mesh, so rays enter it
   * once — one peel where no boundary face is split by Steiner points
   * (Documentation/convexification.md). Without a Convexifier, or for an
   * input that is not a vtkUnstructuredGrid, it warns once and peels.
   * NON_CONVEX_AUTOMATIC: peels, and from what the first frame of a geometry
   * measured (peels; then the fill's size and the peels convexified)
   * chooses one of the two for it (ppirayNonConvexChoice.h states the rule);
   * GetNonConvexChoice() says which.
   */
  enum NonConvexModes
  {
    NON_CONVEX_PEEL = 0,
    NON_CONVEX_CONVEXIFY = 1,
    NON_CONVEX_AUTOMATIC = 2
  };
  vtkSetClampMacro(NonConvexMode, int, NON_CONVEX_PEEL, NON_CONVEX_AUTOMATIC);
  vtkGetMacro(NonConvexMode, int);
  void SetNonConvexModeToPeel() { this->SetNonConvexMode(NON_CONVEX_PEEL); }
  void SetNonConvexModeToConvexify() { this->SetNonConvexMode(NON_CONVEX_CONVEXIFY); }
  void SetNonConvexModeToAutomatic() { this->SetNonConvexMode(NON_CONVEX_AUTOMATIC); }
  /** How the last frame followed the mesh: NON_CONVEX_PEEL or NON_CONVEX_CONVEXIFY. */
  int GetNonConvexChoice();
  ///@}

  ///@{
  /**
   * The filter NON_CONVEX_CONVEXIFY runs on the input, pluggable like
   * vtkUnstructuredGridVolumeRayCastMapper's ray integrator: PPIRay's is
   * vtkUnstructuredGridConvexify (module PPIRay::Convexify, GPL through
   * CGAL, which this module does not depend on). When none is set,
   * NON_CONVEX_CONVEXIFY makes one with vtkObjectFactory::CreateInstance(
   * "vtkUnstructuredGridConvexify"): loading PPIRay::Convexify (its library,
   * its Python module or the PPIRayConvexify ParaView plugin) registers it.
   */
  virtual void SetConvexifier(vtkUnstructuredGridAlgorithm* convexifier);
  vtkGetObjectMacro(Convexifier, vtkUnstructuredGridAlgorithm);
  ///@}

  ///@{
  /**
   * Upper bound on cells one ray visits per peel; 0 (default) chooses
   * max(1024, 64 * cbrt(number of tetrahedra)). Keeps every shader loop bounded.
   */
  vtkSetClampMacro(MaximumNumberOfSteps, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfSteps, int);
  ///@}

  ///@{
  /**
   * Texels per buffer texture at most; 0 (default): the OpenGL limit,
   * GL_MAX_TEXTURE_BUFFER_SIZE (commonly 2^27: 33.5 M tetrahedra or 22 M
   * hexahedra per buffer). A mesh whose cell textures exceed it is stored in
   * up to 6 buffer textures per array. Lower values are for testing the
   * split and for drivers whose limit is wrong.
   */
  vtkSetClampMacro(MaximumBufferTexels, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumBufferTexels, vtkIdType);
  ///@}

  ///@{
  /**
   * Resolution of the Psi table (default 512: bilinear lookup error at most
   * 2.3e-4 in Psi, i.e. below 0.06/255 in colour; 1 MB of GPU memory; see
   * Documentation/algorithms.md and TestPsiTable).
   */
  vtkSetClampMacro(PsiTableSize, int, 16, 4096);
  vtkGetMacro(PsiTableSize, int);
  ///@}

  ///@{
  /**
   * Resolution N of the FULL_PRE_INTEGRATION table, N x N x N texels over
   * (s_front, s_back, length) (default 64: 4 MB).
   */
  vtkSetClampMacro(PreIntegrationTableSize, int, 4, 512);
  vtkGetMacro(PreIntegrationTableSize, int);
  ///@}

  ///@{
  /**
   * Opacity at which a ray stops (early ray termination, default 0.999).
   */
  vtkSetClampMacro(TerminationOpacity, double, 0.5, 1.0);
  vtkGetMacro(TerminationOpacity, double);
  ///@}

  ///@{
  /**
   * Level of detail, as vtkUnstructuredGridVolumeRayCastMapper has it: rays
   * are cast for one pixel in ImageSampleDistance x ImageSampleDistance
   * (default 1: every pixel; at least 1) and the image is scaled up
   * bilinearly. With AutoAdjustSampleDistances (default on) the distance is
   * chosen each frame from the time the last frame took and the time the
   * renderer allocates the volume (vtkRenderWindow::SetDesiredUpdateRate:
   * interactors ask for a high rate while the user interacts), within
   * [MinimumImageSampleDistance, MaximumImageSampleDistance]:
   *   d <- d sqrt(last frame's time / allocated time)
   * (VTK's CPU ray caster's rule): coarser while interacting, every pixel
   * again on the first frame with time to spare.
   */
  vtkSetClampMacro(ImageSampleDistance, float, 1.0f, 100.0f);
  vtkGetMacro(ImageSampleDistance, float);
  vtkSetClampMacro(MinimumImageSampleDistance, float, 1.0f, 100.0f);
  vtkGetMacro(MinimumImageSampleDistance, float);
  vtkSetClampMacro(MaximumImageSampleDistance, float, 1.0f, 100.0f);
  vtkGetMacro(MaximumImageSampleDistance, float);
  vtkSetClampMacro(AutoAdjustSampleDistances, vtkTypeBool, 0, 1);
  vtkGetMacro(AutoAdjustSampleDistances, vtkTypeBool);
  vtkBooleanMacro(AutoAdjustSampleDistances, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Count the cell steps of every ray (default off): each march pass's step
   * counts are read back from the GPU, which stalls the frame. For
   * benchmarks (cell steps per second), not for interactive use.
   */
  vtkSetMacro(CountCellSteps, vtkTypeBool);
  vtkGetMacro(CountCellSteps, vtkTypeBool);
  vtkBooleanMacro(CountCellSteps, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Time every pass of a frame on the GPU (default off): GL timer queries
   * around each pass, read at the end of the frame, which waits for the GPU.
   * For benchmarks (where the time goes), not for interactive use.
   */
  vtkSetMacro(TimePasses, vtkTypeBool);
  vtkGetMacro(TimePasses, vtkTypeBool);
  vtkBooleanMacro(TimePasses, vtkTypeBool);
  ///@}

  /**
   * What the last frame did: cells rendered natively or as tetrahedra,
   * caches rebuilt, peels, continuations, cell steps, pass times, GPU
   * memory. Refreshed at the end of every frame.
   */
  vtkUnstructuredGridGPURayCastStatistics* GetStatistics();

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow*) override;

protected:
  vtkUnstructuredGridGPURayCastMapper();
  ~vtkUnstructuredGridGPURayCastMapper() override;

  int IntegrationMode = PARTIAL_PRE_INTEGRATION;
  int HexahedronMode = HEXAHEDRON_ACCURATE;
  int TetrahedronLayout = TETRAHEDRON_PLANES;
  int MarchStage = MARCH_STAGE_AUTOMATIC;
  int NonlinearSubdivisionLevel = 1;
  vtkTypeBool EmbedIsoSurfaces = 0;
  double AverageIPScalarRange[2] = { VTK_FLOAT_MIN, VTK_FLOAT_MAX };
  int VectorMode = MAGNITUDE;
  int VectorComponent = 0;
  int MaximumNumberOfPeels = 64;
  int NonConvexMode = NON_CONVEX_PEEL;
  vtkUnstructuredGridAlgorithm* Convexifier = nullptr;
  int MaximumNumberOfSteps = 0;
  vtkIdType MaximumBufferTexels = 0;
  int PsiTableSize = 512;
  int PreIntegrationTableSize = 64;
  double TerminationOpacity = 0.999;
  vtkTypeBool CountCellSteps = 0;
  vtkTypeBool TimePasses = 0;
  float ImageSampleDistance = 1.0f;
  float MinimumImageSampleDistance = 1.0f;
  float MaximumImageSampleDistance = 10.0f;
  vtkTypeBool AutoAdjustSampleDistances = 1;

  // Stages of Render(), each refreshing a collaborator when its source
  // changed: the cells (tetrahedra or hexahedra), the scalar field in them,
  // the integration mode's tables.
  // The grid rendered: the input, or its convexified copy (NonConvexMode).
  vtkUnstructuredGridBase* RenderedGrid(vtkUnstructuredGridBase* input);
  // The grid a frame renders, updated; null (reported unless empty) for none.
  vtkUnstructuredGridBase* FrameInput(vtkRenderer* ren, vtkVolume* vol);
  // Render() without its timing (TimeToDraw).
  void RenderFrame(vtkRenderer* ren, vtkVolume* vol);
  // The cells, field, transfer function and integrator current and uploaded.
  bool UpdateCollaborators(
    vtkUnstructuredGridBase* input, vtkVolume* vol, vtkOpenGLRenderWindow* context);
  bool UpdateCells(vtkUnstructuredGridBase* input, vtkOpenGLRenderWindow* context);
  bool UpdateField(vtkUnstructuredGridBase* input);
  bool UpdateIntegrator(vtkOpenGLRenderWindow* context);
  // Warns once when other PPIRay volumes of the renderer overlap `vol`.
  void WarnAboutOverlappingVolumes(vtkRenderer* ren, vtkVolume* vol);
  // GetStatistics() from the collaborators, after a frame or a release.
  void CollectStatistics();

private:
  vtkUnstructuredGridGPURayCastMapper(const vtkUnstructuredGridGPURayCastMapper&) = delete;
  void operator=(const vtkUnstructuredGridGPURayCastMapper&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
