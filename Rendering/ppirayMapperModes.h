// The mapper's modes, for the collaborators that act on them: they include
// this header, not the mapper's. vtkUnstructuredGridGPURayCastMapper's public
// enums have these values (static_assert in its .cxx).
#ifndef ppirayMapperModes_h
#define ppirayMapperModes_h

class vtkObject;

namespace ppiray
{
// A family of modes: what it is, and its values' names (value i: Names[i]).
struct ModeNames
{
  const char* What;
  int Count;
  const char* const* Names;
};

// How a ray segment is integrated (vtkUnstructuredGridGPURayCastMapper::IntegrationModes).
enum IntegrationMode
{
  PartialPreIntegration = 0,
  ExactLinear = 1,
  FullPreIntegration = 2,
  AverageColor = 3
};

// How hexahedra are rendered (vtkUnstructuredGridGPURayCastMapper::HexahedronModes).
enum HexahedronMode
{
  HexahedronAccurate = 0,
  HexahedronFast = 1,
  HexahedronSubdivide = 2
};

// How tetrahedra are laid out (vtkUnstructuredGridGPURayCastMapper::TetrahedronLayouts).
enum TetrahedronLayout
{
  TetrahedronPlanes = 0,
  TetrahedronCompact = 1
};

// Where the march runs (vtkUnstructuredGridGPURayCastMapper::MarchStages).
enum MarchStage
{
  MarchFragment = 0,
  MarchCompute = 1,
  MarchAutomatic = 2
};

// How rays that leave a non-convex mesh and enter it again are followed.
enum NonConvexMode
{
  NonConvexPeel = 0,
  NonConvexConvexify = 1,
  NonConvexAutomatic = 2
};

// What a ray accumulates: composite, or a projection (the blend mode's
// value, vtkVolumeMapper's: maximum, minimum, average intensity, additive).
enum Projection
{
  Composite = 0,
  MaximumIntensity = 1,
  MinimumIntensity = 2,
  AverageIntensity = 3,
  Additive = 4
};

extern const ModeNames IntegrationModeNames;
extern const ModeNames HexahedronModeNames;
extern const ModeNames TetrahedronLayoutNames;

// The name of `mode` in `modes`, "unknown" if none.
const char* ModeName(const ModeNames& modes, int mode);

// member <- mode (`self` Modified) when mode is one of `modes`; else an
// error through `self` and member kept.
void SetMode(vtkObject* self, int& member, int mode, const ModeNames& modes);
}

#endif
