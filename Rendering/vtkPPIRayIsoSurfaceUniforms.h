/**
 * @class   vtkPPIRayIsoSurfaceUniforms
 * @brief   the isosurfaces of a frame as the march shader reads them
 *
 * ppiray::IsoSurfaces (read from the volume property, as the reference
 * renderer reads them) as glsl/isosurface_fs.glsl's declarations and
 * uniforms: at most MaximumValues isovalues (the lowest) with their colour
 * and opacity, stored minus the field's shift; the material; at most
 * MaximumLights lights; the local frame to world and its normal matrix.
 * Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayIsoSurfaceUniforms_h
#define vtkPPIRayIsoSurfaceUniforms_h

#include "ppirayIsoSurfaces.h" // for ppiray::IsoSurfaces

#include <string> // for std::string

class vtkMatrix4x4;
class vtkObject;
class vtkRenderer;
class vtkShaderProgram;
class vtkVolume;

class vtkPPIRayIsoSurfaceUniforms
{
public:
  static constexpr int MaximumValues = 16;
  static constexpr int MaximumLights = 8;

  /**
   * This frame's isosurfaces of `volume`'s property (mode from the blend
   * mode and EmbedIsoSurfaces); a warning about what is not drawn as asked
   * is given once, until it changes. Returns the mode.
   */
  ppiray::IsoSurfaceMode Update(
    vtkRenderer* renderer, vtkVolume* volume, int blendMode, bool embed, vtkObject* reporter);
  ppiray::IsoSurfaceMode GetMode() const { return this->Surfaces.Mode; }

  /** GLSL constants: ISO_MODE, MAXIMUM_ISO_VALUES, MAXIMUM_LIGHTS. */
  static std::string Declarations(ppiray::IsoSurfaceMode mode);

  /**
   * Sets the uniforms; `localToWorld`: the mesh's local frame (coordinates
   * minus its origin) to world; the field stored minus `fieldShift`.
   */
  void Bind(vtkShaderProgram* program, vtkMatrix4x4* localToWorld, double fieldShift) const;

private:
  ppiray::IsoSurfaces Surfaces;
  std::string Warning; // the last warning given
};

#endif
