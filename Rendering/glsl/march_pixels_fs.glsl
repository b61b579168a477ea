// Which pixels a march pass takes, for the passes that spare the march the
// others (march_queue_cs.glsl in the compute stage, march_mask_fs.glsl in
// the fragment stage): those with an entry code (entry and section passes)
// or a continuation the last pass left. Every other pixel's targets are
// what the march writes where no ray starts (march_common_fs.glsl,
// enterPeel()): the earlier peels' colour and exit passed through, no
// continuation.
uniform sampler2D entryTriangle;
uniform sampler2D previousAccumulated;
uniform sampler2D previousExit;
uniform sampler2D previousContinuation;

bool hasRay(ivec2 pixel)
{
  return texelFetch(entryTriangle, pixel, 0).r > 0.0 ||
    texelFetch(previousContinuation, pixel, 0).r > 0.0;
}

void targetsWithoutRay(ivec2 pixel, out vec4 accumulated, out vec4 exit, out vec4 continuation)
{
  accumulated = texelFetch(previousAccumulated, pixel, 0);
  exit = texelFetch(previousExit, pixel, 0);
  continuation = vec4(0.0);
}
