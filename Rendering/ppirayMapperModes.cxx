#include "ppirayMapperModes.h"

#include "vtkObject.h"
#include "vtkSetGet.h"

namespace ppiray
{
namespace
{
const char* const IntegrationModes[] = { "PARTIAL_PRE_INTEGRATION", "EXACT_LINEAR",
  "FULL_PRE_INTEGRATION", "AVERAGE_COLOR" };
const char* const HexahedronModes[] = { "HEXAHEDRON_ACCURATE", "HEXAHEDRON_FAST",
  "HEXAHEDRON_SUBDIVIDE" };
const char* const TetrahedronLayouts[] = { "TETRAHEDRON_PLANES", "TETRAHEDRON_COMPACT" };
}

const ModeNames IntegrationModeNames = { "integration mode", 4, IntegrationModes };
const ModeNames HexahedronModeNames = { "hexahedron mode", 3, HexahedronModes };
const ModeNames TetrahedronLayoutNames = { "tetrahedron layout", 2, TetrahedronLayouts };

//------------------------------------------------------------------------------
const char* ModeName(const ModeNames& modes, int mode)
{
  return mode >= 0 && mode < modes.Count ? modes.Names[mode] : "unknown";
}

//------------------------------------------------------------------------------
void SetMode(vtkObject* self, int& member, int mode, const ModeNames& modes)
{
  if (mode < 0 || mode >= modes.Count)
  {
    vtkErrorWithObjectMacro(self,
      "Unknown " << modes.What << " " << mode << "; keeping " << ModeName(modes, member) << ".");
  }
  else if (mode != member)
  {
    member = mode;
    self->Modified();
  }
}
}
