#include "ppirayIsoSurfaces.h"

#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace ppiray
{
//------------------------------------------------------------------------------
IsoSurfaceMode ChooseIsoSurfaceMode(
  int blendMode, bool embed, int numberOfValues, std::string& warning)
{
  constexpr int compositeBlend = 0;  // vtkVolumeMapper::COMPOSITE_BLEND
  constexpr int maximumBlend = 1;    // vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND
  constexpr int additiveBlend = 4;   // vtkVolumeMapper::ADDITIVE_BLEND
  constexpr int isoSurfaceBlend = 5; // vtkVolumeMapper::ISOSURFACE_BLEND
  warning.clear();
  if (blendMode == isoSurfaceBlend)
  {
    if (numberOfValues == 0)
    {
      warning = "ISOSURFACE_BLEND without isovalues (vtkVolumeProperty::GetIsoSurfaceValues()): "
                "nothing is drawn.";
    }
    return IsoSurfacesOnly;
  }
  if (blendMode >= maximumBlend && blendMode <= additiveBlend)
  {
    return NoIsoSurfaces; // projections draw no surfaces
  }
  if (blendMode != compositeBlend)
  {
    warning = "Blend mode " + std::to_string(blendMode) +
              " is not supported (composite, maximum, minimum and average intensity, additive, "
              "isosurface); rendering "
              "composite.";
    return NoIsoSurfaces;
  }
  return embed && numberOfValues > 0 ? EmbeddedIsoSurfaces : NoIsoSurfaces;
}

//------------------------------------------------------------------------------
int IsoSurfaces::NextCrossing(double s, int& j) const
{
  if (j < static_cast<int>(this->Values.size()) && this->Values[j] <= s)
  {
    return j++;
  }
  if (j > 0 && this->Values[j - 1] > s)
  {
    return --j;
  }
  return -1;
}

//------------------------------------------------------------------------------
glm::dvec3 IsoSurfaces::Shaded(
  int i, const glm::dvec3& x, const glm::dvec3& g, const glm::dvec3& direction) const
{
  const glm::dvec3 color(this->Colors[i]);
  if (!this->Shade)
  {
    return color;
  }
  const glm::dvec3 view = -direction;
  const double norm = glm::length(g);
  glm::dvec3 n = norm > 0 ? g / norm : view;
  if (glm::dot(n, view) < 0)
  {
    n = -n;
  }
  glm::dvec3 diffuse(0.0), specular(0.0);
  for (const Light& light : this->Lights)
  {
    const glm::dvec3 l = light.Positional ? glm::normalize(light.Vector - x) : light.Vector;
    const double nl = glm::dot(n, l);
    if (nl <= 0)
    {
      continue;
    }
    const glm::dvec3 h = l + view;
    const double hn = glm::length(h);
    const double nh = hn > 0 ? std::max(0.0, glm::dot(n, h) / hn) : 0.0;
    diffuse += nl * light.DiffuseColor;
    specular += std::pow(nh, this->SpecularPower) * light.SpecularColor;
  }
  return color * (this->Ambient + this->Diffuse * diffuse) + this->Specular * specular;
}

//------------------------------------------------------------------------------
IsoSurfaces ReadIsoSurfaces(
  vtkVolumeProperty* property, IsoSurfaceMode mode, vtkLightCollection* lights)
{
  IsoSurfaces iso;
  iso.Mode = mode;
  if (mode == NoIsoSurfaces)
  {
    return iso;
  }
  vtkContourValues* contours = property->GetIsoSurfaceValues();
  for (int i = 0; i < contours->GetNumberOfContours(); ++i)
  {
    if (!std::isnan(contours->GetValue(i)))
    {
      iso.Values.push_back(contours->GetValue(i));
    }
  }
  std::sort(iso.Values.begin(), iso.Values.end());
  iso.Values.erase(std::unique(iso.Values.begin(), iso.Values.end()), iso.Values.end());
  for (double v : iso.Values)
  {
    glm::dvec4 c(1.0);
    if (property->GetColorChannels(0) == 3)
    {
      double rgb[3];
      property->GetRGBTransferFunction(0)->GetTable(v, v, 1, rgb);
      c = glm::dvec4(rgb[0], rgb[1], rgb[2], 1.0);
    }
    else
    {
      c = glm::dvec4(glm::dvec3(property->GetGrayTransferFunction(0)->GetValue(v)), 1.0);
    }
    c.a = std::min(1.0, std::max(0.0, property->GetScalarOpacity(0)->GetValue(v)));
    iso.Colors.push_back(c);
  }
  iso.Shade = property->GetShade(0) != 0;
  iso.Ambient = property->GetAmbient(0);
  iso.Diffuse = property->GetDiffuse(0);
  iso.Specular = property->GetSpecular(0);
  iso.SpecularPower = property->GetSpecularPower(0);
  if (!lights)
  {
    return iso;
  }
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    glm::dvec3 position, focalPoint;
    light->GetTransformedPosition(glm::value_ptr(position));
    light->GetTransformedFocalPoint(glm::value_ptr(focalPoint));
    IsoSurfaces::Light l;
    l.Positional = light->GetPositional() != 0;
    const glm::dvec3 towards = position - focalPoint;
    l.Vector = l.Positional ? position : towards / std::max(glm::length(towards), 1e-300);
    const double* diffuse = light->GetDiffuseColor();
    const double* specular = light->GetSpecularColor();
    l.DiffuseColor = light->GetIntensity() * glm::dvec3(diffuse[0], diffuse[1], diffuse[2]);
    l.SpecularColor = light->GetIntensity() * glm::dvec3(specular[0], specular[1], specular[2]);
    iso.Lights.push_back(l);
  }
  return iso;
}
}
