// What both march passes (tetrahedra, hexahedra) share: the per-pixel inputs
// of a peel and its two outputs.
uniform isamplerBuffer boundaryFaces; // boundary triangle -> the cell and face it enters
uniform sampler2D entryTriangle;      // boundary triangle id + 1 per pixel (entry pass)
uniform sampler2D opaqueDepth;
uniform sampler2D previousAccumulated; // colour of the earlier peels
uniform sampler2D previousExit;        // where the earlier peel stopped
uniform int maximumSteps;

// The cell layout: GEOMETRY_TEXELS, NEIGHBOR_TEXELS, FIELD_TEXELS per cell,
// neighbour code = FACES cell + face, TURN_BACK, the FLAT_CELL and EMPTY_CELL
// thresholds (written by vtkPPIRayCellBuffers); FLAT_CELLS, FOLDS: whether the
// mesh has flat cells to cross and folds to walk back (the march leaves out
// what it does not need).
//PPIRay::Cells::Dec
uniform float terminationAlpha;

in vec2 texCoord; // pixel centre in [0, 1]^2

// Ping-pong targets: the accumulated premultiplied colour, this peel's
// colour composited under the earlier peels', and the ray parameter where
// this peel's march stopped (for the next entry pass).
out vec4 fragOutput0;
out vec4 fragOutput1;

const float INFINITY = 3.0e38;

// Passes the earlier peels' colour and exit through (in case this pixel has no
// entry) and returns the boundary face code of the triangle the ray enters by
// in this peel, or -1. `resume`: where the earlier peel left the mesh; the
// march starts no earlier than that (entry_fs.glsl says why). `startCell`:
// the cell the ray starts in at the near plane (section_fs.glsl), or -1.
int enterPeel(ivec2 pixel, out vec4 before, out float resume, out int startCell)
{
  before = texelFetch(previousAccumulated, pixel, 0);
  float entry = texelFetch(entryTriangle, pixel, 0).r;
  fragOutput0 = before;
  fragOutput1 = texelFetch(previousExit, pixel, 0);
  resume = fragOutput1.r;
  startCell = entry < -0.5 ? int(-entry) - 1 : -1;
  return entry < 0.5 ? -1 : texelFetch(boundaryFaces, int(entry) - 1).r;
}
