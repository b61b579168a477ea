// What both march passes (tetrahedra, hexahedra) share: the per-pixel inputs
// of a peel and its two outputs.
uniform isamplerBuffer boundaryFaces; // boundary triangle -> the cell and face it enters
uniform sampler2D opaqueDepth;
// entryTriangle: the entry code per pixel (entry and section passes);
// previousAccumulated: the colour of the earlier peels; previousExit: where
// the earlier peel stopped; previousContinuation: where the last pass ran
// out of loops; and the targets of a pixel without a ray.
//PPIRay::MarchPixels::Impl
uniform int maximumSteps;

// The cell layout: GEOMETRY_TEXELS, NEIGHBOR_TEXELS, FIELD_TEXELS per cell,
// neighbour code = FACES cell + face, TURN_BACK, the FLAT_CELL and EMPTY_CELL
// thresholds, SPLIT_FACE + list: a boundary face split into MAXIMUM_SPLIT_PIECES
// or fewer pieces, REENTRY_FACE + list: a boundary face with reflex edges
// (written by vtkPPIRayCellBuffers); FLAT_CELLS, FOLDS, SPLIT_FACES,
// REENTRY_EDGES: whether the mesh has flat cells to cross, folds to walk
// back, split faces to cross, reflex edges to re-enter across (the march
// leaves out what it does not need).
//PPIRay::Cells::Dec
uniform float terminationAlpha;

// The stage the march runs in (march_fragment_stage_fs.glsl,
// march_compute_stage_cs.glsl): pixelCentre(), the pixel centre in [0, 1]^2,
// the same in both stages;
// marchPixel(), the pixel; the ping-pong targets fragOutput0..2: the
// accumulated premultiplied colour, this peel's colour composited under the
// earlier peels'; the ray parameter where this peel's march stopped (for the
// next entry pass); a continuation and the steps this peel has taken
// (below); and main(), which runs marchRay() (march_fs.glsl).
//PPIRay::MarchStage::Dec

const float INFINITY = 3.0e38;

// Loop budget. A driver may end a shader invocation's loops silently past a
// total count (Mesa's llvmpipe: 65,535 iterations of all loops together,
// counted for the SIMD group of pixels that run together, whose loops go on
// while any of its lanes needs them), so a ray that needs more work
// (thousands of control points crossed, long rays) would end early and dark.
// The march spends at most LOOP_BUDGET iterations in a pass, counted
// conservatively: STEP_LOOPS per cell step (declared by the march),
// PIECE_LOOPS per piece between control points (the integration mode's worst
// case), the control-interval searches as they go; LOOP_RESERVE, above every
// count taken after the fact (two searches, the search at a listed exit
// face), keeps the total under the driver's. Where the budget runs out the
// ray stops at a cell and a ray parameter and the next pass continues it
// there (continuation: its code and the steps taken so far in this peel,
// which MaximumNumberOfSteps bounds across passes, in the third target).
// The margin between the budget and the driver's limit is for the lanes of
// a group that take different numbers of iterations in the same step.
const int CONTROL_SEARCH_LOOPS = 32; // a control-interval search at most
const int LOOP_BUDGET = 40960;
const int LOOP_RESERVE = 2 * CONTROL_SEARCH_LOOPS + 64 + EXIT_LOOPS;
int loopsLeft = LOOP_BUDGET;
bool outOfLoops = false;   // the work stopped for the budget ...
float cutAt = 0.0;         // ... this far into the stretch it was given
bool loopsWaived = false;  // a step that must finish in this pass

// Takes n iterations from the budget; false (and nothing taken) when they
// would leave less than the reserve.
bool spendLoops(int n)
{
  if (!loopsWaived && loopsLeft - n < LOOP_RESERVE)
  {
    outOfLoops = true;
    return false;
  }
  loopsLeft -= n;
  return true;
}

// A continuation as a positive normal float: code = 2 (cell (FACES + 1) +
// entry face + 1) + backwards, stored as the bits code + 2^23 (exponent
// field never 0 or 255, so no render target flushes or rewrites it); 0: none.
float continuationCode(int cell, int entryFace, bool backwards)
{
  uint code = uint(2 * (cell * (FACES + 1) + entryFace + 1) + (backwards ? 1 : 0));
  return uintBitsToFloat(code + 0x00800000u);
}

void continuationCell(float code, out int cell, out int entryFace, out bool backwards)
{
  int c = int(floatBitsToUint(code) - 0x00800000u);
  backwards = (c & 1) == 1;
  int cellFace = c / 2;
  cell = cellFace / (FACES + 1);
  entryFace = cellFace - cell * (FACES + 1) - 1;
}

// The third output at the end of a march: the continuation (0: none) and the
// steps taken in this peel. A ray that finished inside the loop broke before
// counting the cell it stopped in: counted here, so that the steps of the
// finished rays of every pass sum to the cells the rays visited (what
// vtkUnstructuredGridGPURayCastMapper::CountCellSteps reads).
void writeContinuation(float continuation, int step)
{
  bool finished = continuation == 0.0 && step < maximumSteps;
  fragOutput2 = vec4(continuation, float(finished ? step + 1 : step), 0.0, 0.0);
}

// Passes the earlier peels' colour and exit through (in case this pixel has no
// entry) and returns the boundary face code of the triangle the ray enters by
// in this peel, or -1. `resume`: where the earlier peel left the mesh; the
// march starts no earlier than that (entry_fs.glsl says why). `startCell`:
// the cell the ray starts in at the near plane (section_fs.glsl), or where
// the previous pass ran out of its loop budget (then with `startFace`, the
// face it entered that cell by, `backwards`, and `steps` taken before), or -1.
int enterPeel(ivec2 pixel, out vec4 before, out float resume, out int startCell,
  out int startFace, out bool backwards, out int steps)
{
  targetsWithoutRay(pixel, fragOutput0, fragOutput1, fragOutput2);
  before = fragOutput0;
  resume = fragOutput1.r;
  // Entry code: 0 none, else the bits 2 id + cell + 2^23 of a positive
  // normal float (exact for any id): a boundary triangle (entry_fs.glsl) or
  // the cell the ray starts in (cell = 1; section_fs.glsl).
  float entry = texelFetch(entryTriangle, pixel, 0).r;
  startFace = -1;
  backwards = false;
  steps = 0;
  vec2 continuation = texelFetch(previousContinuation, pixel, 0).rg;
  if (continuation.r > 0.0)
  {
    continuationCell(continuation.r, startCell, startFace, backwards);
    steps = int(continuation.g);
    return -1;
  }
  int code = entry > 0.0 ? int(floatBitsToUint(entry) - 0x00800000u) : -1;
  startCell = code >= 0 && (code & 1) == 1 ? code >> 1 : -1;
  return code >= 0 && (code & 1) == 0 ? texelFetch(boundaryFaces, code >> 1).r : -1;
}
