/**
 * @file   ppirayIsoSurfaces.h
 * @brief  the isosurfaces a frame draws, read once from a vtkVolumeProperty
 *
 * One reading of the property for the GPU mapper and the reference renderer:
 * the isovalues (ascending, NaN and repeats dropped), the transfer
 * function's colour (vtkColorTransferFunction::GetTable, or the grey
 * function) and scalar opacity (clamped to [0, 1]) at each, the property's
 * Phong coefficients and the renderer's switched-on lights in world
 * coordinates (positional lights as point lights: no cone, no attenuation).
 */
#ifndef ppirayIsoSurfaces_h
#define ppirayIsoSurfaces_h

#include "ppirayFiltersModule.h" // for export macro

#include <glm/vec3.hpp> // for glm::dvec3
#include <glm/vec4.hpp> // for glm::dvec4
#include <string>       // for std::string
#include <vector>       // for std::vector

class vtkLightCollection;
class vtkVolumeProperty;

namespace ppiray
{
/**
 * What a frame draws of the isosurfaces; the values of
 * vtkUnstructuredGridGPURayCastMapper's NO_ISOSURFACES, EMBEDDED_ISOSURFACES
 * and ISOSURFACES_ONLY, and of the shaders' ISO_MODE.
 */
enum IsoSurfaceMode
{
  NoIsoSurfaces = 0,
  EmbeddedIsoSurfaces = 1,
  IsoSurfacesOnly = 2
};

/**
 * The mode of a blend mode (VTK's COMPOSITE_BLEND 0, MAXIMUM_ and
 * MINIMUM_INTENSITY_BLEND 1 and 2, ISOSURFACE_BLEND 5), EmbedIsoSurfaces and
 * the number of isovalues: isosurfaces only in ISOSURFACE_BLEND (nothing
 * drawn without isovalues), embedded in composite when asked for and there
 * are values, else none. `warning` says what is not drawn as asked ("" when
 * all is; other blend modes render composite).
 */
PPIRAYFILTERS_EXPORT IsoSurfaceMode ChooseIsoSurfaceMode(
  int blendMode, bool embed, int numberOfValues, std::string& warning);

struct PPIRAYFILTERS_EXPORT IsoSurfaces
{
  IsoSurfaceMode Mode = NoIsoSurfaces;
  std::vector<double> Values;     // ascending
  std::vector<glm::dvec4> Colors; // colour and opacity at each value
  bool Shade = false;
  double Ambient = 0, Diffuse = 1, Specular = 0, SpecularPower = 1;
  struct Light
  {
    bool Positional;
    glm::dvec3 Vector;        // towards the light (directional), or its position
    glm::dvec3 DiffuseColor;  // times intensity
    glm::dvec3 SpecularColor; // times intensity
  };
  std::vector<Light> Lights;

  /**
   * The next surface crossed from interval j (number of values <= s) on the
   * way to s, or -1; j moves past it.
   */
  int NextCrossing(double s, int& j) const;

  /**
   * Phong shading of surface i at x seen along `direction`, field gradient g:
   * C (Ka + Kd sum_l max(n.l, 0) D_l) + Ks sum_l [n.l > 0] max(n.h, 0)^P S_l,
   * n the normalized gradient turned towards the viewer, h = l + v
   * normalized; the colour C itself when Shade is off.
   */
  glm::dvec3 Shaded(
    int i, const glm::dvec3& x, const glm::dvec3& g, const glm::dvec3& direction) const;
};

/**
 * The isosurfaces of `property` in `mode`, lit by `lights` (may be null).
 * Values and colours are read only when the mode draws surfaces.
 */
PPIRAYFILTERS_EXPORT IsoSurfaces ReadIsoSurfaces(
  vtkVolumeProperty* property, IsoSurfaceMode mode, vtkLightCollection* lights);
}

#endif
