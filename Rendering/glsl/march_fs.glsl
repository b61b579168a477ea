//VTK::System::Dec
// March pass: per pixel, from the cell a ray enters through (entry pass) to
// the cell it leaves the mesh from, one tetrahedron at a time.
//
// Cell textures (Espinha & Celes 2005, Sec. 3.1), all in the mesh's local frame:
//   facePlanes[4 t + f] = (n_f, d_f), outward unit normal, n_f . x = d_f on face f
//   neighbors[t]        = cell through face f (-1: boundary)
//   field[t]            = (g, s0): s(x) = g . x + s0 (s0 = -3e38: render empty)
// The exit face is the nearest face plane the ray is heading out of
// (Weiler et al. 2003, Sec. 3.2): t_f = (d_f - n_f . o) / (n_f . r), n_f . r > 0.
// Every segment is integrated by integrateSegment(), split at each transfer
// function control point it crosses; each piece by integratePiece(), the
// integration mode, substituted below.

uniform samplerBuffer facePlanes;
uniform isamplerBuffer neighbors;
uniform samplerBuffer field;
uniform isamplerBuffer boundaryFaces; // boundary triangle -> 4 t + f
uniform samplerBuffer controlPoints;  // 2 texels per point: (s, tau), (r, g, b)
uniform int numberOfControlPoints;
uniform sampler2D entryTriangle;      // boundary triangle id + 1 per pixel
uniform sampler2D opaqueDepth;
uniform sampler2D previousAccumulated; // colour of the earlier peels
uniform sampler2D previousExit;        // where the earlier peel stopped
uniform int maximumSteps;
uniform float terminationAlpha;

in vec2 texCoord; // pixel centre in [0, 1]^2

// Ping-pong targets: the accumulated premultiplied colour, this peel's
// colour composited under the earlier peels', and the ray parameter where
// this peel's march stopped (for the next entry pass).
out vec4 fragOutput0;
out vec4 fragOutput1;

const float INFINITY = 3.0e38;

// Transfer function: piecewise linear between control points, constant outside.
float controlPointValue(int i)
{
  return texelFetch(controlPoints, 2 * i).x;
}

// (r, g, b, tau) of the transfer function at scalar s, with s in the control
// interval [s_k, s_k+1] (k = -1 or n - 1: clamped to the end points).
vec4 transferFunction(float s, int k)
{
  int n = numberOfControlPoints;
  int lo = clamp(k, 0, n - 1);
  int hi = clamp(k + 1, 0, n - 1);
  vec4 a = texelFetch(controlPoints, 2 * lo);
  vec4 b = texelFetch(controlPoints, 2 * hi);
  vec4 ca = vec4(texelFetch(controlPoints, 2 * lo + 1).rgb, a.y);
  vec4 cb = vec4(texelFetch(controlPoints, 2 * hi + 1).rgb, b.y);
  float w = (hi == lo || b.x <= a.x) ? 0.0 : clamp((s - a.x) / (b.x - a.x), 0.0, 1.0);
  return mix(ca, cb, w);
}

// Index k with s_k <= s < s_k+1 (-1 below the first point), moved from the
// previous cell's index: the scalar is continuous along a ray for point data,
// so this is usually zero or one step. Bounded by the number of points.
int controlInterval(float s, int k)
{
  int n = numberOfControlPoints;
  k = clamp(k, -1, n - 1);
  for (int i = 0; i < n && k + 1 < n && controlPointValue(k + 1) <= s; ++i)
  {
    ++k;
  }
  for (int i = 0; i < n && k >= 0 && controlPointValue(k) > s; ++i)
  {
    --k;
  }
  return k;
}

void compositeFrontToBack(inout vec4 color, vec3 emitted, float alpha)
{
  color.rgb += (1.0 - color.a) * emitted;
  color.a += (1.0 - color.a) * alpha;
}

//PPIRay::Integrate::Impl

//PPIRay::Ray::Impl

// A segment of length `len` on which s goes linearly from sFront to sBack:
// split at every control point value strictly between them, each piece
// integrated by integratePiece(). Walks the control points in the direction
// s moves (index arithmetic, no re-lookup: a value landing exactly on a
// control point cannot loop, the role of next_s_iso in Espinha & Celes,
// Sec. 3.2). Returns the control interval at sBack.
int integrateSegment(float sFront, float sBack, float len, int k, inout vec4 color)
{
  int n = numberOfControlPoints;
  k = controlInterval(sFront, k);
  float ds = sBack - sFront;
  float sA = sFront;
  vec4 tfA = transferFunction(sA, k);
  for (int i = 0; i <= n; ++i)
  {
    float sB;
    int nextK;
    if (ds > 0.0 && k + 1 < n && controlPointValue(k + 1) < sBack)
    {
      sB = controlPointValue(k + 1);
      nextK = k + 1;
    }
    else if (ds < 0.0 && k >= 0 && controlPointValue(k) > sBack)
    {
      sB = controlPointValue(k);
      nextK = k - 1;
    }
    else
    {
      sB = sBack;
      nextK = k;
    }
    vec4 tfB = transferFunction(sB, k);
    float pieceLength = ds == 0.0 ? len : len * (sB - sA) / ds;
    integratePiece(tfA, tfB, pieceLength, color);
    if (nextK == k)
    {
      break;
    }
    k = nextK;
    sA = sB;
    tfA = transferFunction(sA, k);
  }
  return k;
}

// Plane of face f of cell t.
vec4 facePlane(int t, int f)
{
  return texelFetch(facePlanes, 4 * t + f);
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 before = texelFetch(previousAccumulated, pixel, 0);
  float entry = texelFetch(entryTriangle, pixel, 0).r;
  fragOutput0 = before;
  fragOutput1 = texelFetch(previousExit, pixel, 0);
  if (entry < 0.5)
  {
    return;
  }
  int cellFace = texelFetch(boundaryFaces, int(entry) - 1).r;
  int cell = cellFace / 4;
  int entryFace = cellFace - 4 * cell;

  // The ray through the pixel centre, in the local frame.
  vec2 ndc = 2.0 * texCoord - 1.0;
  vec3 origin, direction;
  pixelRay(ndc, origin, direction);

  // Opaque geometry stops the ray at its depth.
  float tStop = INFINITY;
  float zOpaque = texelFetch(opaqueDepth, pixel, 0).r;
  if (zOpaque < 1.0)
  {
    vec4 hit = clipToLocal * vec4(ndc, 2.0 * zOpaque - 1.0, 1.0);
    tStop = dot(hit.xyz / hit.w - origin, direction);
  }

  vec4 plane = facePlane(cell, entryFace);
  float t = (plane.w - dot(plane.xyz, origin)) / min(dot(plane.xyz, direction), -1.0e-30);
  int k = -1;
  vec4 color = vec4(0.0);
  float reached = t;
  for (int step = 0; step < maximumSteps; ++step)
  {
    float tExit = INFINITY;
    int exitFace = -1;
    for (int f = 0; f < 4; ++f)
    {
      vec4 p = facePlane(cell, f);
      float along = dot(p.xyz, direction);
      if (f != entryFace && along > 0.0)
      {
        float tf = (p.w - dot(p.xyz, origin)) / along;
        if (tf < tExit)
        {
          tExit = tf;
          exitFace = f;
        }
      }
    }
    if (exitFace < 0)
    {
      break;
    }
    tExit = max(tExit, t);
    float tEnd = min(tExit, tStop);
    reached = tEnd;
    vec4 g = texelFetch(field, cell);
    if (g.w > -1.0e38 && tEnd > t)
    {
      float sFront = dot(g.xyz, origin + t * direction) + g.w;
      float sBack = dot(g.xyz, origin + tEnd * direction) + g.w;
      k = integrateSegment(sFront, sBack, tEnd - t, k, color);
    }
    if (tExit >= tStop || before.a + (1.0 - before.a) * color.a >= terminationAlpha)
    {
      break;
    }
    int next = texelFetch(neighbors, cell)[exitFace];
    if (next < 0)
    {
      break;
    }
    ivec4 back = texelFetch(neighbors, next);
    entryFace = back.x == cell ? 0 : (back.y == cell ? 1 : (back.z == cell ? 2 : 3));
    cell = next;
    t = tExit;
  }
  fragOutput0 = before + (1.0 - before.a) * color;
  fragOutput1 = vec4(reached);
}
