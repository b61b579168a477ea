// The viewing ray through a pixel, in the mesh's local frame: the pixel's
// points on the near and far planes, unprojected. Works for perspective and
// parallel cameras alike.
uniform mat4 clipToLocal;

void pixelRay(vec2 ndc, out vec3 origin, out vec3 direction)
{
  vec4 nearPoint = clipToLocal * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = clipToLocal * vec4(ndc, 1.0, 1.0);
  origin = nearPoint.xyz / nearPoint.w;
  direction = normalize(farPoint.xyz / farPoint.w - origin);
}

// Ray parameter where opaque geometry (VTK's depth buffer, copied to `depth`)
// stops the ray through `pixel`; 3e38 where there is none.
float opaqueStop(sampler2D depth, ivec2 pixel, vec2 ndc, vec3 origin, vec3 direction)
{
  float z = texelFetch(depth, pixel, 0).r;
  if (z >= 1.0)
  {
    return 3.0e38;
  }
  vec4 hit = clipToLocal * vec4(ndc, 2.0 * z - 1.0, 1.0);
  return dot(hit.xyz / hit.w - origin, direction);
}
