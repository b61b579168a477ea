// The march as a fragment shader: one fragment per pixel of a full-screen
// quad (vtkOpenGLQuadHelper), its outputs the three ping-pong targets of the
// framebuffer.
in vec2 texCoord; // pixel centre in [0, 1]^2, interpolated (to a rounding)
uniform ivec2 targetSize;

out vec4 fragOutput0;
out vec4 fragOutput1;
out vec4 fragOutput2;

// The pixel: the interpolated centre scaled to the target, rounded down.
ivec2 marchPixel()
{
  return ivec2(texCoord * vec2(targetSize));
}

// The pixel's centre in [0, 1]^2, from its index: the same value as the
// compute stage's, so both cast the same ray.
vec2 pixelCentre()
{
  return (vec2(marchPixel()) + 0.5) / vec2(targetSize);
}

void marchRay();

void main()
{
  marchRay();
}
