#include "vtkPPIRayIsoSurfaceUniforms.h"

#include "vtkContourValues.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObject.h"
#include "vtkRenderer.h"
#include "vtkSetGet.h"
#include "vtkShaderProgram.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

//------------------------------------------------------------------------------
ppiray::IsoSurfaceMode vtkPPIRayIsoSurfaceUniforms::Update(
  vtkRenderer* renderer, vtkVolume* volume, int blendMode, bool embed, vtkObject* reporter)
{
  vtkVolumeProperty* property = volume->GetProperty();
  const int count = property->GetIsoSurfaceValues()->GetNumberOfContours();
  std::string warning;
  const ppiray::IsoSurfaceMode mode =
    ppiray::ChooseIsoSurfaceMode(blendMode, embed, count, warning);
  if (mode != ppiray::NoIsoSurfaces && count > MaximumValues)
  {
    warning = std::to_string(count) + " isovalues; only the lowest " +
              std::to_string(MaximumValues) + " are drawn.";
  }
  if (warning != this->Warning)
  {
    this->Warning = warning;
    if (!warning.empty())
    {
      vtkWarningWithObjectMacro(reporter, << warning);
    }
  }
  this->Surfaces = ppiray::ReadIsoSurfaces(property, mode, renderer->GetLights());
  return mode;
}

//------------------------------------------------------------------------------
std::string vtkPPIRayIsoSurfaceUniforms::Declarations(ppiray::IsoSurfaceMode mode)
{
  return "const int ISO_MODE = " + std::to_string(static_cast<int>(mode)) +
         ";\nconst int MAXIMUM_ISO_VALUES = " + std::to_string(MaximumValues) +
         ";\nconst int MAXIMUM_LIGHTS = " + std::to_string(MaximumLights) + ";";
}

//------------------------------------------------------------------------------
void vtkPPIRayIsoSurfaceUniforms::Bind(
  vtkShaderProgram* program, vtkMatrix4x4* localToWorld, double fieldShift) const
{
  const ppiray::IsoSurfaces& iso = this->Surfaces;
  const int values = static_cast<int>(std::min<size_t>(iso.Values.size(), MaximumValues));
  float isoValues[MaximumValues] = {};
  float isoColors[MaximumValues][4] = {};
  for (int i = 0; i < values; ++i)
  {
    isoValues[i] = static_cast<float>(iso.Values[i] - fieldShift);
    for (int c = 0; c < 4; ++c)
    {
      isoColors[i][c] = static_cast<float>(iso.Colors[i][c]);
    }
  }
  program->SetUniformi("numberOfIsoValues", values);
  program->SetUniform1fv("isoValues", MaximumValues, isoValues);
  program->SetUniform4fv("isoColors", MaximumValues, isoColors);

  const float material[4] = { static_cast<float>(iso.Ambient), static_cast<float>(iso.Diffuse),
    static_cast<float>(iso.Specular), static_cast<float>(iso.SpecularPower) };
  program->SetUniformi("shade", iso.Shade ? 1 : 0);
  program->SetUniform4f("material", material);
  float lightVector[MaximumLights][3] = {}, lightDiffuse[MaximumLights][3] = {},
        lightSpecular[MaximumLights][3] = {};
  int lightPositional[MaximumLights] = {};
  const int lights = static_cast<int>(std::min<size_t>(iso.Lights.size(), MaximumLights));
  for (int l = 0; l < lights; ++l)
  {
    const ppiray::IsoSurfaces::Light& light = iso.Lights[l];
    lightPositional[l] = light.Positional ? 1 : 0;
    for (int c = 0; c < 3; ++c)
    {
      lightVector[l][c] = static_cast<float>(light.Vector[c]);
      lightDiffuse[l][c] = static_cast<float>(light.DiffuseColor[c]);
      lightSpecular[l][c] = static_cast<float>(light.SpecularColor[c]);
    }
  }
  program->SetUniformi("numberOfLights", lights);
  program->SetUniform3fv("lightVector", MaximumLights, lightVector);
  program->SetUniform3fv("lightDiffuse", MaximumLights, lightDiffuse);
  program->SetUniform3fv("lightSpecular", MaximumLights, lightSpecular);
  program->SetUniform1iv("lightPositional", MaximumLights, lightPositional);

  // Column-major localToWorld, and its normal matrix (inverse transpose of
  // the linear part): column-major element (r, c) = inverse[c][r].
  float localToWorldF[16];
  double linear[3][3], inverse[3][3];
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      localToWorldF[4 * c + r] = static_cast<float>(localToWorld->GetElement(r, c));
      if (r < 3 && c < 3)
      {
        linear[r][c] = localToWorld->GetElement(r, c);
      }
    }
  }
  program->SetUniformMatrix4x4("localToWorld", localToWorldF);
  vtkMath::Invert3x3(linear, inverse);
  float normalToWorld[9];
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      normalToWorld[3 * c + r] = static_cast<float>(inverse[c][r]);
    }
  }
  program->SetUniformMatrix3x3("normalToWorld", normalToWorld);
}
