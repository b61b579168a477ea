/**
 * @class   vtkUnstructuredGridReferenceRenderer
 * @brief   ground-truth volume rendering of a tetrahedral grid on the CPU, in double
 *
 * Produces the image a volume renderer should produce: float RGBA
 * (premultiplied, the volume alone over a transparent background) for a
 * vtkUnstructuredGrid, a vtkVolumeProperty, a vtkCamera and an image size,
 * with VTK's unstructured semantics (attenuation = opacity / unit distance,
 * emission = colour * attenuation) and the mapper's pixel convention (rays
 * through pixel centres of the camera's composite projection).
 *
 * Exact for linear tetrahedra and a piecewise-linear transfer function: each
 * ray collects its pieces in every tetrahedron by clipping the ray against the
 * cell (barycentric coordinates, no adjacency: non-convex meshes, holes and
 * separate parts need nothing special), splits them at every colour and
 * opacity node value, and integrates each piece in closed form
 * (ppirayVolumeIntegrals.h). The transfer function is VTK's own evaluation
 * (vtkColorTransferFunction::GetTable, vtkPiecewiseFunction::GetValue), split
 * between nodes by bisection until linear within TransferFunctionTolerance.
 * No early termination. Deterministic; OpenMP over screen tiles.
 *
 * Independent of the GPU path by construction (no shared traversal, transfer
 * function or integration code), so that each checks the other.
 *
 * Hexahedra, voxels, wedges, pyramids, polyhedra and the quadratic,
 * Lagrange and Bezier 3D cells take a general path with the cell's own
 * (isoparametric) interpolation, vtkCell::EvaluatePosition: the ray is cut
 * at its crossings with every face (triangles, quadrilaterals as the
 * bilinear patches the interpolation spans, planar or not, and a nonlinear
 * face as the triangles vtkCell::Triangulate makes of its nodes: exact for
 * straight edges, a polyline through the nodes for curved ones), the
 * intervals whose midpoint the cell contains are split until the
 * interpolated scalar is linear along the ray within QuadratureTolerance
 * (relative to the scalar range), and each piece is integrated exactly.
 * Other cell types are skipped with a warning.
 *
 * Isosurfaces (SetBlendMode(ISOSURFACE_BLEND), or embedded in the composite
 * volume with EmbedIsoSurfaces): the isovalues of the property's
 * GetIsoSurfaceValues(), where the piecewise-linear scalar along the ray
 * crosses them (in a tetrahedron exactly; in a general cell within
 * QuadratureTolerance), coloured and made opaque by the transfer function
 * at the isovalue, and, with the property's Shade on, Phong-lit with its
 * ambient, diffuse, specular and specular power and the lights of SetLights()
 * (normal: the interpolated field's gradient, turned towards the viewer;
 * positional lights as point lights). The same definition as
 * vtkUnstructuredGridGPURayCastMapper's, evaluated independently.
 *
 * Work per ray is bounded: a piece of a general cell is split at most 24
 * levels deep and into at most 4,096 pieces per cell (the tolerance of a
 * constant field is relative to its values); pieces accepted there without
 * meeting QuadratureTolerance are counted and reported in one warning. Progress events per finished
 * tile (from the calling thread); SetAbortExecute(1) (from a progress observer, say) starts no
 * further tile: the image is unfinished (tiles left transparent) and GetAbortExecute() stays 1
 * until the next update.
 *
 * Cells listing point ids outside the grid's points are reported in one
 * error and not rendered (ppirayValidPointIds.h), as by the mapper.
 *
 * Scalars: SetInputArrayToProcess(0, 0, 0, association, name); default the
 * active point scalars, else the active cell scalars; first component.
 */
#ifndef vtkUnstructuredGridReferenceRenderer_h
#define vtkUnstructuredGridReferenceRenderer_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class vtkCamera;
class vtkLightCollection;
class vtkPlaneCollection;
class vtkVolumeProperty;

class PPIRAYFILTERS_EXPORT vtkUnstructuredGridReferenceRenderer : public vtkImageAlgorithm
{
public:
  static vtkUnstructuredGridReferenceRenderer* New();
  vtkTypeMacro(vtkUnstructuredGridReferenceRenderer, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The transfer function and unit distance. */
  virtual void SetVolumeProperty(vtkVolumeProperty*);
  vtkGetObjectMacro(VolumeProperty, vtkVolumeProperty);
  ///@}

  ///@{
  /** The view: rays through pixel centres of its composite projection. */
  virtual void SetCamera(vtkCamera*);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /** Image width and height in pixels (default 256 x 256). */
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  ///@}

  ///@{
  /**
   * Largest deviation of colour (in [0, 1]) and opacity from linear on a
   * transfer-function piece (default 1e-5, 1/400 of 1/255).
   */
  vtkSetClampMacro(TransferFunctionTolerance, double, 1e-9, 0.1);
  vtkGetMacro(TransferFunctionTolerance, double);
  ///@}

  ///@{
  /**
   * Largest deviation of the scalar from linear along a ray piece in a
   * non-tetrahedral cell, relative to the scalar range (default 1e-6).
   */
  vtkSetClampMacro(QuadratureTolerance, double, 1e-12, 0.1);
  vtkGetMacro(QuadratureTolerance, double);
  ///@}

  /**
   * Blend modes, with vtkVolumeMapper's names and values: composite
   * (default), maximum or minimum intensity projection (the extreme scalar
   * along the ray with the transfer function's colour and scalar opacity
   * there, premultiplied), average intensity (over the parts of the ray with
   * the scalar in AverageIPScalarRange, the length-weighted mean of scalar
   * opacity x the scalar normalized to its range; grey, opacity 1), additive
   * (the integral of scalar opacity x normalized scalar per unit distance;
   * grey clamped to 1, opacity 1), or isosurfaces only.
   */
  enum
  {
    COMPOSITE_BLEND = 0,
    MAXIMUM_INTENSITY_BLEND = 1,
    MINIMUM_INTENSITY_BLEND = 2,
    AVERAGE_INTENSITY_BLEND = 3,
    ADDITIVE_BLEND = 4,
    ISOSURFACE_BLEND = 5
  };
  vtkSetMacro(BlendMode, int);
  vtkGetMacro(BlendMode, int);
  void SetBlendModeToIsoSurface() { this->SetBlendMode(ISOSURFACE_BLEND); }
  void SetBlendModeToMaximumIntensity() { this->SetBlendMode(MAXIMUM_INTENSITY_BLEND); }
  void SetBlendModeToMinimumIntensity() { this->SetBlendMode(MINIMUM_INTENSITY_BLEND); }
  void SetBlendModeToAverageIntensity() { this->SetBlendMode(AVERAGE_INTENSITY_BLEND); }
  void SetBlendModeToAdditive() { this->SetBlendMode(ADDITIVE_BLEND); }
  ///@{
  /** AVERAGE_INTENSITY_BLEND's scalar range (default: every value). */
  vtkSetVector2Macro(AverageIPScalarRange, double);
  vtkGetVectorMacro(AverageIPScalarRange, double, 2);
  ///@}

  ///@{
  /** In composite mode, also draw the isosurfaces embedded in the volume (default off). */
  vtkSetMacro(EmbedIsoSurfaces, vtkTypeBool);
  vtkGetMacro(EmbedIsoSurfaces, vtkTypeBool);
  vtkBooleanMacro(EmbedIsoSurfaces, vtkTypeBool);
  ///@}

  ///@{
  /** The lights that shade isosurfaces (e.g. a renderer's GetLights() after it rendered). */
  virtual void SetLights(vtkLightCollection*);
  vtkGetObjectMacro(Lights, vtkLightCollection);
  ///@}

  ///@{
  /**
   * Clipping planes (world coordinates, at most 6 used, as the GPU mapper):
   * each keeps the side its normal points to, n . (x - origin) >= 0; every
   * ray piece is cut exactly where a plane crosses it.
   */
  virtual void SetClippingPlanes(vtkPlaneCollection*);
  vtkGetObjectMacro(ClippingPlanes, vtkPlaneCollection);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkUnstructuredGridReferenceRenderer();
  ~vtkUnstructuredGridReferenceRenderer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkVolumeProperty* VolumeProperty = nullptr;
  vtkCamera* Camera = nullptr;
  int ImageSize[2] = { 256, 256 };
  double TransferFunctionTolerance = 1e-5;
  double QuadratureTolerance = 1e-6;
  int BlendMode = COMPOSITE_BLEND;
  double AverageIPScalarRange[2] = { VTK_FLOAT_MIN, VTK_FLOAT_MAX };
  vtkTypeBool EmbedIsoSurfaces = 0;
  vtkLightCollection* Lights = nullptr;
  vtkPlaneCollection* ClippingPlanes = nullptr;

private:
  vtkUnstructuredGridReferenceRenderer(const vtkUnstructuredGridReferenceRenderer&) = delete;
  void operator=(const vtkUnstructuredGridReferenceRenderer&) = delete;
};

#endif
