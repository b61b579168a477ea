// The march as a compute shader (GL 4.3): one invocation per pixel in 8 x 8
// work groups over the target, its outputs stored into the three ping-pong
// targets bound as images (the same texels the fragment stage writes).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform writeonly image2D accumulatedTarget;
layout(binding = 1, rgba32f) uniform writeonly image2D exitTarget;
layout(binding = 2, rg32f) uniform writeonly image2D continuationTarget;
uniform ivec2 targetSize;

vec2 texCoord; // pixel centre in [0, 1]^2, as the quad's interpolation gives it
vec4 fragOutput0;
vec4 fragOutput1;
vec4 fragOutput2;

ivec2 marchPixel()
{
  return ivec2(gl_GlobalInvocationID.xy);
}

void marchRay();

void main()
{
  ivec2 pixel = marchPixel();
  if (any(greaterThanEqual(pixel, targetSize)))
  {
    return;
  }
  texCoord = (vec2(pixel) + 0.5) / vec2(targetSize);
  marchRay();
  imageStore(accumulatedTarget, pixel, fragOutput0);
  imageStore(exitTarget, pixel, fragOutput1);
  imageStore(continuationTarget, pixel, fragOutput2);
}
