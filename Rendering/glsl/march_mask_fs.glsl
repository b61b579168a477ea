//VTK::System::Dec
// Ray mask (fragment stage): before a march pass, the depth of each pixel
// says whether the pass takes its ray (0) or not (1), so that the march's
// quad, drawn at depth 0.5 and tested against it, is shaded where a ray is
// only; this pass writes every other pixel's targets (march_pixels_fs.glsl).
// The compute stage's ray queue (march_queue_cs.glsl) lists the same pixels.
in vec2 texCoord; // pixel centre in [0, 1]^2

out vec4 fragOutput0;
out vec4 fragOutput1;
out vec4 fragOutput2;

//PPIRay::MarchPixels::Impl

void main()
{
  ivec2 pixel = ivec2(texCoord * vec2(textureSize(entryTriangle, 0)));
  gl_FragDepth = hasRay(pixel) ? 0.0 : 1.0;
  targetsWithoutRay(pixel, fragOutput0, fragOutput1, fragOutput2);
}
