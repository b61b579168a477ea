#version 430 core
// Ray queue (compute stage): before a march pass, the pixels whose ray it
// takes (march_pixels_fs.glsl) are appended to one list, so that the
// march's invocations, and the SIMD lanes and warps that run them
// together, hold rays only; this pass writes every other pixel's targets.
//
// Each work group counts its rays in shared memory and takes its slots with
// one atomic, so the counter is contended once per group, not once per ray.
layout(local_size_x = 8, local_size_y = 8) in;
//PPIRay::MarchQueue::Dec
//PPIRay::MarchPixels::Impl

shared uint groupRays;
shared uint groupFirst;

// The number of multiples of n in [first, last).
uint multiplesIn(uint first, uint last, uint n)
{
  return (last + n - 1u) / n - (first + n - 1u) / n;
}

void main()
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  bool inside = all(lessThan(pixel, targetSize));
  bool live = inside && hasRay(pixel);
  if (gl_LocalInvocationIndex == 0u)
  {
    groupRays = 0u;
  }
  barrier();
  uint slot = live ? atomicAdd(groupRays, 1u) : 0u;
  barrier();
  if (gl_LocalInvocationIndex == 0u && groupRays > 0u)
  {
    groupFirst = atomicAdd(rays, groupRays);
    atomicAdd(groups[0], multiplesIn(groupFirst, groupFirst + groupRays, MARCH_GROUP_SIZE));
  }
  barrier();
  if (live)
  {
    pixels[groupFirst + slot] = uint(pixel.x) + 65536u * uint(pixel.y);
  }
  else if (inside)
  {
    vec4 accumulated, exit, continuation;
    targetsWithoutRay(pixel, accumulated, exit, continuation);
    imageStore(accumulatedTarget, pixel, accumulated);
    imageStore(exitTarget, pixel, exit);
    imageStore(continuationTarget, pixel, continuation);
  }
}
