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
// Every segment is integrated by integrateSegment(), the integration mode,
// substituted below with the transfer function lookup.

uniform samplerBuffer facePlanes;
uniform isamplerBuffer neighbors;
uniform samplerBuffer field;

//PPIRay::MarchCommon::Impl

//PPIRay::TransferFunction::Impl

//PPIRay::IsoSurface::Impl

//PPIRay::Integrate::Impl

// One cell's stretch of the ray, x in [0, len] past `entry`, on which s goes
// linearly from sFront to sBack (gradient g): the volume integrated up to
// each isosurface crossed (at x = len (v - sFront) / (sBack - sFront)), unless
// ISO_MODE is 2, each surface composited there, and on to the exit.
int integrateTetrahedronSegment(float sFront, float sBack, float len, vec3 g, vec3 entry,
  vec3 direction, int k, inout int j, inout vec4 color)
{
  if (ISO_MODE == 0)
  {
    return integrateSegment(sFront, sBack, len, k, color);
  }
  j = j < 0 ? isoInterval(sFront, 0) : j;
  int surface = -1;
  // Surfaces the scalar jumped across at the entry face (cell data).
  for (int i = 0; i < MAXIMUM_ISO_VALUES; ++i)
  {
    int next = nextIsoCrossing(sFront, j, surface);
    if (surface < 0)
    {
      break;
    }
    compositeIsoSurface(surface, entry, g, direction, color);
    j = next;
  }
  float x = 0.0;
  float sA = sFront;
  float ds = sBack - sFront;
  for (int i = 0; i < MAXIMUM_ISO_VALUES; ++i)
  {
    int next = nextIsoCrossing(sBack, j, surface);
    if (surface < 0)
    {
      break;
    }
    float v = isoValues[surface];
    float xv = ds == 0.0 ? x : clamp(len * (v - sFront) / ds, x, len);
    if (ISO_MODE == 1 && xv > x)
    {
      k = integrateSegment(sA, v, xv - x, k, color);
    }
    compositeIsoSurface(surface, entry + xv * direction, g, direction, color);
    x = xv;
    sA = v;
    j = next;
  }
  if (ISO_MODE != 2 && len > x)
  {
    k = integrateSegment(sA, sBack, len - x, k, color);
  }
  return k;
}

//PPIRay::Ray::Impl

// Plane of face f of cell t.
vec4 facePlane(int t, int f)
{
  return texelFetch(facePlanes, 4 * t + f);
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 before;
  float resume;
  int cellFace = enterPeel(pixel, before, resume);
  if (cellFace < 0)
  {
    return;
  }
  int cell = cellFace / 4;
  int entryFace = cellFace - 4 * cell;

  // The ray through the pixel centre, in the local frame.
  vec2 ndc = 2.0 * texCoord - 1.0;
  vec3 origin, direction;
  pixelRay(ndc, origin, direction);

  // Opaque geometry stops the ray at its depth.
  float tStop = opaqueStop(opaqueDepth, pixel, ndc, origin, direction);

  vec4 plane = facePlane(cell, entryFace);
  float t = max((plane.w - dot(plane.xyz, origin)) / min(dot(plane.xyz, direction), -1.0e-30), resume);
  int k = -1;
  int j = -1; // isovalue interval, set at the first cell
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
      k = integrateTetrahedronSegment(sFront, sBack, tEnd - t, g.xyz, origin + t * direction,
        direction, k, j, color);
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
