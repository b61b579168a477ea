//VTK::System::Dec
// Final pass: the volume's premultiplied colour over VTK's framebuffer
// (blending ONE, ONE_MINUS_SRC_ALPHA). Opaque geometry nearer than the volume
// already stopped the rays, so the volume lands over it where it is in front
// and is hidden where it is behind.

in vec2 texCoord;
uniform sampler2D accumulated;

out vec4 fragOutput0;

void main()
{
  fragOutput0 = texture(accumulated, texCoord);
}
