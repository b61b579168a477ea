// The march as a fragment shader: one fragment per pixel of a full-screen
// quad (vtkOpenGLQuadHelper), its outputs the three ping-pong targets of the
// framebuffer.
in vec2 texCoord; // pixel centre in [0, 1]^2

out vec4 fragOutput0;
out vec4 fragOutput1;
out vec4 fragOutput2;

ivec2 marchPixel()
{
  return ivec2(gl_FragCoord.xy);
}

void marchRay();

void main()
{
  marchRay();
}
