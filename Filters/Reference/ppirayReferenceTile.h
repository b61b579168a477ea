/**
 * @file   ppirayReferenceTile.h
 * @brief  the reference renderer's scene, and one screen tile of its image
 *
 * For vtkUnstructuredGridReferenceRenderer only: what every pixel reads
 * (Scene), and the pixels of one tile of ScreenTiles (ppirayReferenceCells.h):
 * the tile's cells, each pixel's ray (ppirayReferenceView.h), its segments
 * in them (ppirayRaySegments.h), kept by the clipping planes, and their
 * integral or projection (ppirayRayIntegrator.h).
 */
#ifndef ppirayReferenceTile_h
#define ppirayReferenceTile_h

#include "ppirayIsoSurfaces.h"               // for ppiray::IsoSurfaces
#include "ppirayRayIntegrator.h"             // for Projection
#include "ppirayReferenceCells.h"            // for ReferenceCells, ScreenTiles
#include "ppirayReferenceTransferFunction.h" // for TransferFunction
#include "ppirayReferenceView.h"             // for ReferenceView

class vtkDataArray;
class vtkUnstructuredGrid;

namespace ppiray
{
namespace reference
{
struct Scene
{
  vtkUnstructuredGrid* Grid = nullptr;
  vtkDataArray* Scalars = nullptr; // first component rendered
  bool CellScalars = false;
  ReferenceCells Cells;
  double LinearTolerance = 0; // of a general cell's pieces (GeneralCellSegments)
  TransferFunction TF;
  IsoSurfaces Iso;
  bool IsProjection = false; // ProjectRay with How, else IntegrateRay
  Projection How;
  ReferenceView View;
  ScreenTiles Tiles;
};

/**
 * The pixels of tile `tile` of scene.Tiles written to `rgba` (the image,
 * scene.View.Width x scene.View.Height RGBA, rows from the bottom); returns
 * the general cells' ray pieces left unresolved (GeneralCellSegments).
 */
long long RenderTile(const Scene& scene, int tile, float* rgba);
}
}

#endif
