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
