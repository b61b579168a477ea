// The viewing ray through a pixel, in the mesh's local frame: from the
// pixel's point on the near plane, unprojected, along d = D (x, y, 1), the
// far point minus the near one, affine in the pixel's NDC (x, y) and made in
// double (NdcToDirection in vtkUnstructuredGridGPURayCastMapper.cxx: the far
// point unprojected in float loses its digits when the near plane is close).
// Perspective and parallel cameras alike.
uniform mat4 clipToLocal;
uniform mat3 ndcToDirection;

void pixelRay(vec2 ndc, out vec3 origin, out vec3 direction)
{
  vec4 nearPoint = clipToLocal * vec4(ndc, -1.0, 1.0);
  origin = nearPoint.xyz / nearPoint.w;
  direction = normalize(ndcToDirection * vec3(ndc, 1.0));
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

// Clipping planes (vtkAbstractMapper's, at most 6) in the local frame: the
// side n . x + d >= 0 of each is kept, as VTK's mappers keep the side a
// vtkPlane's normal points to.
uniform int numberOfClippingPlanes;
uniform vec4 clippingPlanes[6];

// The part [lo, hi] of the ray origin + t direction, t >= 0, that every
// clipping plane keeps (lo > hi: none): on plane i, n . (origin + t direction)
// + d = b + a t >= 0 bounds t from below where a > 0, from above where a < 0.
vec2 keptRange(vec3 origin, vec3 direction)
{
  vec2 range = vec2(0.0, 3.0e38);
  for (int i = 0; i < min(numberOfClippingPlanes, 6); ++i)
  {
    float a = dot(clippingPlanes[i].xyz, direction);
    float b = dot(clippingPlanes[i].xyz, origin) + clippingPlanes[i].w;
    if (a > 0.0)
    {
      range.x = max(range.x, -b / a);
    }
    else if (a < 0.0)
    {
      range.y = min(range.y, -b / a);
    }
    else if (b < 0.0)
    {
      range.y = -1.0; // along a plane, on its clipped side
    }
  }
  return range;
}
