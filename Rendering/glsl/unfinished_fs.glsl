//VTK::System::Dec
// Unfinished rays: a fragment (counted by an occlusion query) wherever the
// last march ran out of its loop budget and left a continuation
// (march_common_fs.glsl); discarded elsewhere.

in vec2 texCoord; // pixel centre in [0, 1]^2
uniform sampler2D continuation;

out vec4 fragOutput0;

void main()
{
  if (!(texture(continuation, texCoord).r > 0.0))
  {
    discard;
  }
  fragOutput0 = vec4(0.0);
}
