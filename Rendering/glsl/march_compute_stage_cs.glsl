// The march as a compute shader (GL 4.3): one invocation per ray of the ray
// queue (march_queue_cs.glsl: the pixels with an entry or a continuation,
// in groups of MARCH_GROUP_SIZE, dispatched indirectly), its outputs stored
// into the three ping-pong targets bound as images (the same texels the
// fragment stage writes; the queue pass wrote every other pixel's).
//PPIRay::MarchQueue::Dec
layout(local_size_x = MARCH_GROUP_SIZE) in;

vec4 fragOutput0;
vec4 fragOutput1;
vec4 fragOutput2;
ivec2 queuedPixel;

ivec2 marchPixel()
{
  return queuedPixel;
}

// The pixel's centre in [0, 1]^2, computed as the fragment stage computes it.
vec2 pixelCentre()
{
  return (vec2(queuedPixel) + 0.5) / vec2(targetSize);
}

void marchRay();

void main()
{
  if (gl_GlobalInvocationID.x >= rays)
  {
    return;
  }
  uint code = pixels[gl_GlobalInvocationID.x];
  queuedPixel = ivec2(code % 65536u, code / 65536u);
  marchRay();
  imageStore(accumulatedTarget, queuedPixel, fragOutput0);
  imageStore(exitTarget, queuedPixel, fragOutput1);
  imageStore(continuationTarget, queuedPixel, fragOutput2);
}
