// Projections (vtkVolumeMapper's blend modes; BLEND is the mode's value,
// 0 composite): exact per cell, in the units of vtkGPUVolumeRayCastMapper.
//  1, 2 maximum and minimum intensity: the extreme scalar along the ray (a
//       linear field's extreme on a segment is at an end; a cubic's at an end
//       or at a root of its derivative), coloured with the transfer
//       function's colour and scalar opacity there, premultiplied.
//  3    average intensity: over the parts of the ray where s lies in
//       AverageIPScalarRange, A = int o(s) n(s) dt / int dt, grey A, opacity 1.
//  4    additive: S = int tau(s) n(s) dt = (1 / unit distance) int o(s) n(s) dt,
//       grey S, opacity 1 (vtkGPUVolumeRayCastMapper's sum of o n over samples
//       one unit distance apart, taken to the limit).
// o is the scalar opacity, tau = o / unit distance as in the control points,
// n(s) the scalar normalized to the field's range (n = a s + b). Both
// integrands are quadratic in s between control points, where o is linear.
// The state is carried across peels in the exit target's (g, b):
// BLEND 1, 2: (extreme, met); 3: (int tau n, int dt); 4: (int tau n, met).
//PPIRay::Blend::Dec
uniform float opacityUnitDistance;
uniform vec2 normalizedScalar; // (a, b): n(s) = a s + b
uniform vec2 averageRange;     // AverageIPScalarRange (shifted as the scalars)

// The projection's state as the earlier peels left it.
vec3 previousProjection(ivec2 pixel)
{
  return texelFetch(previousExit, pixel, 0).gba;
}

// The running extreme with s met (BLEND 1, 2).
void meetScalar(float s, inout vec3 state)
{
  bool met = state.y > 0.5;
  state.x = !met ? s : (BLEND == 1 ? max(state.x, s) : min(state.x, s));
  state.y = 1.0;
}

// int tau n dx over a piece of length len on which s, tau and n are linear
// from (sA, tauA) to (sB, tauB): Simpson's rule, exact for the quadratic.
float linearPieceMoment(float sA, float sB, float tauA, float tauB, float len)
{
  float nA = normalizedScalar.x * sA + normalizedScalar.y;
  float nB = normalizedScalar.x * sB + normalizedScalar.y;
  return len * (2.0 * (tauA * nA + tauB * nB) + tauA * nB + tauB * nA) / 6.0;
}

// The fraction [lo, hi] of a linear stretch from sFront to sBack where s lies
// in averageRange (hi <= lo: none).
vec2 averageRangeFraction(float sFront, float sBack)
{
  float ds = sBack - sFront;
  if (ds == 0.0)
  {
    bool inside = sFront >= averageRange.x && sFront <= averageRange.y;
    return inside ? vec2(0.0, 1.0) : vec2(0.0);
  }
  vec2 x = clamp((averageRange - sFront) / ds, 0.0, 1.0);
  return vec2(min(x.x, x.y), max(x.x, x.y));
}

// A stretch of length len on which s goes linearly from sFront to sBack
// (k: its control interval, kept for the next stretch). Out of loops: stops
// at a control point, cutAt that far along the stretch.
void projectLinearStretch(float sFront, float sBack, float len, inout int k, inout vec3 state)
{
  float offset = 0.0;
  if (BLEND == 1 || BLEND == 2)
  {
    meetScalar(sFront, state);
    meetScalar(sBack, state);
    return;
  }
  if (BLEND == 3)
  {
    vec2 kept = averageRangeFraction(sFront, sBack);
    if (!(kept.y > kept.x))
    {
      return;
    }
    float ds = sBack - sFront;
    sBack = sFront + kept.y * ds;
    sFront += kept.x * ds;
    offset = kept.x * len;
    len *= kept.y - kept.x;
  }
  else
  {
    state.y = 1.0;
  }
  int n = numberOfControlPoints;
  k = controlInterval(sFront, k);
  float ds = sBack - sFront;
  float sA = sFront;
  for (int i = 0; i <= n; ++i)
  {
    if (!spendLoops(1))
    {
      cutAt = offset + (ds == 0.0 ? 0.0 : len * (sA - sFront) / ds);
      return;
    }
    float sB;
    int nextK = nextControlCrossing(ds, sBack, k, sB);
    float pieceLength = ds == 0.0 ? len : len * (sB - sA) / ds;
    if (BLEND == 3)
    {
      state.y += pieceLength;
    }
    state.x += linearPieceMoment(
      sA, sB, transferFunction(sA, k).a, transferFunction(sB, k).a, pieceLength);
    if (nextK == k)
    {
      break;
    }
    k = nextK;
    sA = sB;
  }
}

// The premultiplied colour of a projection's state.
vec4 projectionColor(vec3 state)
{
  if (BLEND == 3)
  {
    float average = state.y > 0.0 ? opacityUnitDistance * state.x / state.y : 0.0;
    return state.y > 0.0 ? vec4(vec3(clamp(average, 0.0, 1.0)), 1.0) : vec4(0.0);
  }
  if (state.y < 0.5)
  {
    return vec4(0.0);
  }
  if (BLEND == 4)
  {
    return vec4(vec3(clamp(state.x, 0.0, 1.0)), 1.0);
  }
  vec4 c = transferFunction(state.x, controlInterval(state.x, -1));
  float alpha = clamp(c.a * opacityUnitDistance, 0.0, 1.0);
  return vec4(c.rgb * alpha, alpha);
}

// A peel's outputs: composite, this peel's colour under the earlier peels';
// a projection, the colour of its state so far and the state itself.
void finishPeel(vec4 before, vec4 color, float reached, vec3 state)
{
  if (BLEND == 0)
  {
    fragOutput0 = before + (1.0 - before.a) * color;
    fragOutput1 = vec4(reached);
  }
  else
  {
    fragOutput0 = projectionColor(state);
    fragOutput1 = vec4(reached, state.xy, 0.0);
  }
}
