// A ray that leaves the mesh next to a reflex edge enters it again at once
// through the face across the edge; depth peeling must not lose that entry.
// Mesh: a block of voxels (tetrahedra) over x in [0, 1], y in [-1, 1],
// z in [0, 2] without the quarter y > 0, z > 1: an L in the y-z plane whose
// inner corner E (y = 0, z = 1) is a reflex edge between the step F1 (y = 0,
// normal +y) and the lower top F2 (z = 1, normal +z). A parallel camera
// looks along (0, sin a, -cos a): rays through the tall part leave it
// through F1 and enter the low part through F2, the closer to E the nearer
// the two crossings; on screen both faces lie on one side of E (F1 faces
// away), below it with view-up -(0, cos a, sin a). The centres of image row
// size / 2 lie a thousandth of a pixel below E on screen: each of their rays
// leaves through F1 and enters through F2 within that distance of E, while
// the rasterizer, which snaps vertices to a fraction of a pixel, puts the
// centres on F2's edge and leaves them to the other side (Mesa's llvmpipe:
// that row loses the low part, 24 % of its brightness, without the march's
// own re-entry, reentryAcrossEdge). The same block of hexahedra, marched
// natively, re-enters through the same listed faces. Checked: the image against the CPU
// reference pixel by pixel (p99, max at most 1/255), and the row on E at
// least 97 % of the darker of its two neighbours (the image varies
// smoothly across E: the low part continues the tall one).

#include "PPIRayPixelCheck.h"
#include "PPIRayTestScenes.h"
#include "vtkCamera.h"
#include "vtkUnstructuredGridGPURayCastMapper.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{
// The L-shaped block of tetrahedra, or of hexahedra marched natively.
int CheckReflexEdge(bool hexahedra)
{
  const int size = 64;
  const int n[3] = { 2, 4, 4 };
  const double origin[3] = { 0.0, -1.0, 0.0 };
  auto grid = ppiray_test::VoxelTetrahedra(
    n, 0.5, origin, [](int, int j, int k) { return !(j >= 2 && k >= 2); },
    [](double x, double y, double z) { return x + y + z; }, hexahedra);

  ppiray_test::Scene scene(size, size);
  ppiray_test::SmoothTransferFunction(scene.Property, -1.0, 4.0, 0.8, 0.5);
  vtkNew<vtkUnstructuredGridGPURayCastMapper> mapper;
  scene.Show(mapper, grid, { 0.5, -3.0, 3.0 }, { 0.5, 0.0, 1.0 });
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const double a = 30.0 * 3.14159265358979323846 / 180.0;
  const double d[3] = { 0.0, std::sin(a), -std::cos(a) },
               up[3] = { 0.0, -std::cos(a), -std::sin(a) };
  const double scale = 1.6; // half the view's height
  const double pixel = 2.0 * scale / size;
  // E on screen at row size / 2 + 0.5 + 0.001 (window rows upwards): the
  // centres of row size / 2 lie 0.001 pixel below it, on F2's side.
  const double shift = (0.5 + 0.001) * pixel;
  const double focal[3] = { 0.5, -shift * up[1], 1.0 - shift * up[2] };
  camera->ParallelProjectionOn();
  camera->SetParallelScale(scale);
  camera->SetFocalPoint(focal);
  camera->SetPosition(focal[0] - 10.0 * d[0], focal[1] - 10.0 * d[1], focal[2] - 10.0 * d[2]);
  camera->SetViewUp(up);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  const auto image = ppiray_test::ReadRGB(scene.Window);

  const char* what = hexahedra ? "L-shaped block of hexahedra, rays grazing its reflex edge"
                               : "L-shaped block, rays grazing its reflex edge";
  int errors = ppiray_test::ExpectReference(what,
    ppiray_test::CheckPixels(scene.Renderer, grid, scene.Property, image, size, size),
    size * size / 8);
  const vtkIdType native = mapper->GetStatistics()->GetNumberOfHexahedra();
  if (hexahedra != (native == grid->GetNumberOfCells()))
  {
    std::printf("FAILED: %lld of %lld cells marched as hexahedra\n", static_cast<long long>(native),
      static_cast<long long>(grid->GetNumberOfCells()));
    ++errors;
  }
  // The row on E against its neighbours.
  auto sum = [&](int row)
  {
    long total = 0;
    for (int x = 0; x < size; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        total += image[3 * (row * size + x) + c];
      }
    }
    return total;
  };
  const long onEdge = sum(size / 2);
  const long darker = std::min(sum(size / 2 - 1), sum(size / 2 + 1));
  std::printf("%s: row on the edge: %ld, darker neighbour: %ld (sums of channels); %d peels\n",
    hexahedra ? "hexahedra" : "tetrahedra", onEdge, darker,
    mapper->GetStatistics()->GetNumberOfPeels());
  if (!(onEdge >= 0.97 * darker) || darker == 0)
  {
    std::printf("FAILED: the row on the reflex edge lost the part behind it\n");
    ++errors;
  }
  return errors;
}
}

int TestGPURayCastReflexEdge(int argc, char* argv[])
{
  ppiray_test::ReadTetrahedronLayout(argc, argv);
  const int errors = CheckReflexEdge(false) + CheckReflexEdge(true);
  return errors == 0 ? 0 : 1;
}
