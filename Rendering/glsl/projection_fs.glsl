// Maximum and minimum intensity projection (vtkVolumeMapper's
// MAXIMUM_INTENSITY_BLEND, MINIMUM_INTENSITY_BLEND; BLEND 1 and 2, 0 is
// composite): the extreme scalar along the ray, exact per cell (a linear
// field's extreme on a segment is at an end; a cubic's at an end or at a root
// of its derivative), coloured as vtkGPUVolumeRayCastMapper colours it: the
// colour and the scalar opacity of the transfer function at the extreme,
// premultiplied. Carried across peels in the exit target: (exit, extreme,
// 1 once the ray has met the volume).
//PPIRay::Blend::Dec
uniform float opacityUnitDistance; // tau = opacity / unit distance in the control points

// The running extreme with s met.
void meetScalar(float s, inout float extreme, inout bool met)
{
  extreme = !met ? s : (BLEND == 1 ? max(extreme, s) : min(extreme, s));
  met = true;
}

// The extreme and whether the ray met the volume, as the earlier peels left them.
void previousExtreme(ivec2 pixel, out float extreme, out bool met)
{
  vec2 previous = texelFetch(previousExit, pixel, 0).gb;
  extreme = previous.x;
  met = previous.y > 0.5;
}

// The projection's premultiplied colour for the extreme scalar s.
vec4 projectionColor(float s)
{
  vec4 c = transferFunction(s, controlInterval(s, -1));
  float alpha = clamp(c.a * opacityUnitDistance, 0.0, 1.0);
  return vec4(c.rgb * alpha, alpha);
}

// A peel's outputs: composite, this peel's colour under the earlier peels';
// a projection, the colour of the extreme so far and the extreme itself.
void finishPeel(vec4 before, vec4 color, float reached, float extreme, bool met)
{
  if (BLEND == 0)
  {
    fragOutput0 = before + (1.0 - before.a) * color;
    fragOutput1 = vec4(reached);
  }
  else
  {
    fragOutput0 = met ? projectionColor(extreme) : vec4(0.0);
    fragOutput1 = vec4(reached, extreme, met ? 1.0 : 0.0, 0.0);
  }
}
