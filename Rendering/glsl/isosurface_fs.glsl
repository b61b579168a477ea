// Isosurfaces (vtkVolumeProperty::GetIsoSurfaceValues()): found exactly
// inside each cell by the march (a linear root in a tetrahedron, a cubic root
// in a hexahedron), shaded with the renderer's lights, composited front to
// back. ISO_MODE: 0 none; 1 embedded in the composite volume (Weiler et al.
// 2003, Fig. 1 left); 2 surfaces only (VTK's ISOSURFACE_BLEND);
// MAXIMUM_ISO_VALUES, MAXIMUM_LIGHTS: sizes of the uniform arrays (ISO_MODE
// and both written by vtkPPIRayIsoSurfaceUniforms).
//
// Which side of the surfaces a ray is on is carried along it as an index j =
// the number of isovalues <= s (like the control interval k): a surface is
// crossed exactly when j changes, also where the scalar jumps between cells
// (cell data), so a surface through a shared face is counted once. Where the
// ray crosses a stretch without a field (a hidden cell, a NaN scalar, an
// imaginary cell of a convexified grid) j is forgotten: the field resumes
// behind it as if the ray entered the mesh there, with no surface at the
// resumption (isoIntervalAfterEmpty).
//PPIRay::IsoSurface::Dec

uniform int numberOfIsoValues;
uniform float isoValues[MAXIMUM_ISO_VALUES]; // ascending
uniform vec4 isoColors[MAXIMUM_ISO_VALUES];  // colour and opacity at the isovalue

// Phong lighting as VTK's volume mappers do it (vtkVolumeProperty's ambient,
// diffuse, specular, specular power; the renderer's lights), in world space.
uniform int shade;
uniform vec4 material; // (ambient, diffuse, specular, specular power)
uniform int numberOfLights;
uniform vec3 lightVector[MAXIMUM_LIGHTS]; // directional: towards the light; positional: position
uniform int lightPositional[MAXIMUM_LIGHTS];
uniform vec3 lightDiffuse[MAXIMUM_LIGHTS];  // colour times intensity
uniform vec3 lightSpecular[MAXIMUM_LIGHTS];
uniform mat4 localToWorld;
uniform mat3 normalToWorld; // inverse transpose of localToWorld's linear part

// j after a stretch of length len, ending at t, through a cell with no field:
// unset (-1) unless the stretch is empty to float precision (a flat cell).
int isoIntervalAfterEmpty(int j, float len, float t)
{
  return len > 1.0e-5 * abs(t) ? -1 : j;
}

// The isovalue interval of s (number of isovalues <= s), walked from j.
int isoInterval(float s, int j)
{
  int n = numberOfIsoValues;
  j = clamp(j, 0, n);
  for (int i = 0; i < n && j < n && isoValues[j] <= s; ++i)
  {
    ++j;
  }
  for (int i = 0; i < n && j > 0 && isoValues[j - 1] > s; ++i)
  {
    --j;
  }
  return j;
}

// The next surface crossed from interval j on the way to s (monotonic), in
// `surface`, and the interval beyond it; surface = -1 when none is left.
int nextIsoCrossing(float s, int j, out int surface)
{
  if (j < numberOfIsoValues && isoValues[j] <= s)
  {
    surface = j;
    return j + 1;
  }
  if (j > 0 && isoValues[j - 1] > s)
  {
    surface = j - 1;
    return j - 1;
  }
  surface = -1;
  return j;
}

// Phong shading of a surface point x (local frame) with the field gradient g
// there, seen along `direction`: C (Ka + sum_l Kd max(n.l, 0) D_l) +
// Ks sum_l max(n.h, 0)^P S_l, with n turned towards the viewer (both sides of
// an isosurface are lit). Without a gradient (cell data) the surface faces
// the viewer.
vec3 shadeIsoSurface(vec3 rgb, vec3 x, vec3 g, vec3 direction)
{
  if (shade == 0)
  {
    return rgb;
  }
  vec3 view = -normalize(mat3(localToWorld) * direction);
  vec3 n = normalToWorld * g;
  float length2 = dot(n, n);
  n = length2 > 1.0e-30 ? n * inversesqrt(length2) : view;
  n = dot(n, view) < 0.0 ? -n : n;
  vec3 position = (localToWorld * vec4(x, 1.0)).xyz;
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
  for (int i = 0; i < MAXIMUM_LIGHTS && i < numberOfLights; ++i)
  {
    vec3 l = lightPositional[i] == 1 ? normalize(lightVector[i] - position) : lightVector[i];
    float nl = dot(n, l);
    if (nl > 0.0)
    {
      diffuse += nl * lightDiffuse[i];
      float nh = max(dot(n, normalize(l + view)), 0.0);
      specular += pow(nh, material.w) * lightSpecular[i];
    }
  }
  return rgb * (material.x + material.y * diffuse) + material.z * specular;
}

// Surface `surface` at x, composited under what the ray has gathered.
void compositeIsoSurface(int surface, vec3 x, vec3 g, vec3 direction, inout vec4 color)
{
  vec4 c = isoColors[surface];
  compositeFrontToBack(color, c.a * shadeIsoSurface(c.rgb, x, g, direction), c.a);
}
