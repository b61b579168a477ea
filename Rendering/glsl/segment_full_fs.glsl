// Full pre-integration of a whole cell segment (Röttger et al.; Weiler et al.
// 2003, Sec. 3.3 and 4): one lookup in the 3D table of premultiplied colour
// and opacity over (s_front, s_back, length), built on the CPU for the current
// transfer function (vtkPreIntegrationTable). No stops at control points: the
// table resolution in s decides how thin a feature survives.
uniform sampler3D preIntegrationTable;
uniform vec2 tableScalarRange;   // s at the first and last texel
uniform float tableMaximumLength; // length at the last slice
uniform vec3 tableSize;

int integrateSegment(float sFront, float sBack, float len, int k, inout vec4 color)
{
  vec3 x = vec3((vec2(sFront, sBack) - tableScalarRange.x) /
      (tableScalarRange.y - tableScalarRange.x), len / tableMaximumLength);
  // Texel centres sit at x = i / (size - 1).
  vec3 uvw = (clamp(x, 0.0, 1.0) * (tableSize - 1.0) + 0.5) / tableSize;
  vec4 segment = texture(preIntegrationTable, uvw);
  color.rgb += (1.0 - color.a) * segment.rgb;
  color.a += (1.0 - color.a) * segment.a;
  return k;
}
