/**
 * @file   ppirayLinearCellKinds.h
 * @brief  the linear 3D cells marched natively: their faces, frames, mirror images
 *
 * Hexahedra, wedges, pyramids and tetrahedra as vtkHexahedralCellTextures
 * stores them: up to 8 corners in VTK's order for the type (voxels as
 * hexahedra), a kind code per cell, and for each kind
 * - its faces, corners wound outward for a right-handed cell (VTK's own
 *   orientation: positive volume, e.g. a wedge's triangle 0, 1, 2 facing
 *   3, 4, 5); a triangle's fourth corner is -1, and so are the corners of
 *   faces the kind lacks (6 face slots for every kind, so that a neighbour
 *   code is 6 cell + face);
 * - the corners that mirror it (a left-handed cell becomes right-handed with
 *   the same shape and the same field);
 * - its frame: the corner and edges the field is written in (frame
 *   coordinates (u, v, w) = [p_a - p_0, p_b - p_0, p_c - p_0]^-1 (x - p_0)),
 *   in which VTK's interpolation of a parallelepiped, an affine wedge and any
 *   tetrahedron is a polynomial; a pyramid has none (its field along a ray is
 *   rational, cell_hexahedron_fs.glsl).
 * The GPU reads the same tables (vtkPPIRayHexahedralCellBuffers writes them
 * into the march's GLSL).
 */
#ifndef ppirayLinearCellKinds_h
#define ppirayLinearCellKinds_h

#include "ppirayCellAdjacency.h" // for ppiray::CellFaceTable
#include "vtkCellType.h"         // for VTK_HEXAHEDRON ...

#include <algorithm> // for std::find

namespace ppiray
{
enum LinearCellKind
{
  HEXAHEDRON_KIND = 0,
  WEDGE_KIND = 1,
  PYRAMID_KIND = 2,
  TETRAHEDRON_KIND = 3,
  NUMBER_OF_KINDS = 4
};

/** Added to a cell's kind where the cell is flat (zero volume). */
constexpr int FLAT_KIND_BIT = 16;

struct LinearCellKindInfo : CellFaceTable // corners, faces (outward; -1: no corner)
{
  int VTKType;
  int Mirror[8]; // corner i of the mirror image is corner Mirror[i]
  int Frame[3];  // frame edges from corner 0 (-1: no frame)
};

inline const LinearCellKindInfo& LinearCellKindOf(int kind)
{
  static const LinearCellKindInfo kinds[NUMBER_OF_KINDS] = {
    { { 8, 6,
        { { 0, 4, 7, 3 }, { 1, 2, 6, 5 }, { 0, 1, 5, 4 }, { 3, 7, 6, 2 }, { 0, 3, 2, 1 },
          { 4, 5, 6, 7 } } },
      VTK_HEXAHEDRON, { 4, 5, 6, 7, 0, 1, 2, 3 }, { 1, 3, 4 } },
    { { 6, 5,
        { { 0, 2, 1, -1 }, { 3, 4, 5, -1 }, { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 2, 0, 3, 5 },
          { -1, -1, -1, -1 } } },
      VTK_WEDGE, { 3, 4, 5, 0, 1, 2, 0, 0 }, { 1, 2, 3 } },
    { { 5, 5,
        { { 0, 3, 2, 1 }, { 0, 1, 4, -1 }, { 1, 2, 4, -1 }, { 2, 3, 4, -1 }, { 3, 0, 4, -1 },
          { -1, -1, -1, -1 } } },
      VTK_PYRAMID, { 0, 3, 2, 1, 4, 0, 0, 0 }, { -1, -1, -1 } },
    { { 4, 4,
        { { 0, 1, 3, -1 }, { 1, 2, 3, -1 }, { 2, 0, 3, -1 }, { 0, 2, 1, -1 }, { -1, -1, -1, -1 },
          { -1, -1, -1, -1 } } },
      VTK_TETRA, { 0, 2, 1, 3, 0, 0, 0, 0 }, { 1, 2, 3 } },
  };
  return kinds[kind];
}

/** The kind of a linear VTK type (VTK_HEXAHEDRON, VTK_WEDGE, VTK_PYRAMID, VTK_TETRA), or -1. */
inline int LinearCellKindOfType(int vtkType)
{
  switch (vtkType)
  {
    case VTK_HEXAHEDRON:
      return HEXAHEDRON_KIND;
    case VTK_WEDGE:
      return WEDGE_KIND;
    case VTK_PYRAMID:
      return PYRAMID_KIND;
    case VTK_TETRA:
      return TETRAHEDRON_KIND;
    default:
      return -1;
  }
}

/**
 * The cells for ppiray::MatchCellFaces: `kinds` (one per cell) and
 * `cornerIds` (8 per cell) as vtkHexahedralCellTextures stores them, 6 face
 * slots per cell; `points` (3 doubles each) may be nullptr.
 */
inline CellFaceMesh LinearCellFaceMesh(vtkIdType numberOfPoints, const double* points,
  const vtkIdType* cornerIds, const unsigned char* kinds, vtkIdType numberOfCells)
{
  CellFaceMesh mesh;
  mesh.NumberOfPoints = numberOfPoints;
  mesh.NumberOfCells = numberOfCells;
  mesh.CornerIds = cornerIds;
  mesh.CornerStride = 8;
  for (int kind = 0; kind < NUMBER_OF_KINDS; ++kind)
  {
    mesh.Tables[kind] = &LinearCellKindOf(kind);
  }
  mesh.Kinds = kinds;
  mesh.FaceSlots = 6;
  mesh.Points = points;
  return mesh;
}

/** Corners of face f of a kind: 3, 4, or 0 where the kind has no face f. */
inline int FaceSize(int kind, int f)
{
  const int* q = LinearCellKindOf(kind).Face[f];
  return q[0] < 0 ? 0 : (q[3] < 0 ? 3 : 4);
}

/** The first corner of a kind's cell that is not on its face f. */
inline int CornerOffFace(int kind, int f)
{
  const LinearCellKindInfo& info = LinearCellKindOf(kind);
  for (int v = 0; v < info.Corners; ++v)
  {
    const int* face = info.Face[f];
    if (std::find(face, face + 4, v) == face + 4)
    {
      return v;
    }
  }
  return 0;
}
}

#endif
