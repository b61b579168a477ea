// What the ray queue pass (march_queue_cs.glsl) and the march's compute
// stage (march_compute_stage_cs.glsl) share: the list of rays, the three
// ping-pong targets as images and the target's size.
//
// The list: `rays` entries of `pixels` (x + 65536 y), and `groups`, the
// indirect dispatch of the march: MARCH_GROUP_SIZE invocations per group,
// ceil(rays / MARCH_GROUP_SIZE) groups, then 1, 1 (vtkPPIRayMarchQueue).
layout(std430, binding = 0) buffer RayQueue
{
  uint rays;
  uint groups[3];
  uint pixels[];
};
layout(binding = 0, rgba32f) uniform writeonly image2D accumulatedTarget;
layout(binding = 1, rgba32f) uniform writeonly image2D exitTarget;
layout(binding = 2, rg32f) uniform writeonly image2D continuationTarget;
uniform ivec2 targetSize;
