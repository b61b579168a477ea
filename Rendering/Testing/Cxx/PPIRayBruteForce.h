// A third check that shares nothing with the GPU path or with the reference
// renderer: a brute-force march. Each pixel's ray goes from the camera
// through the pixel centre (VTK's own view transform,
// vtkRenderer::DisplayToWorld); it is sampled at the midpoints of fixed steps
// of length Step; the cell holding each sample is found by point location
// (the previous sample's cell, else vtkStaticCellLocator), the scalar
// interpolated with that cell's own weights (vtkCell::EvaluatePosition), and
// colour and opacity come from VTK (vtkColorTransferFunction::GetTable,
// vtkPiecewiseFunction::GetValue). Front-to-back compositing of the
// emission-absorption model of VTK's unstructured mappers (emission
// colour * tau, tau = opacity / unit distance), constant per step:
//   C += T c (1 - exp(-tau Step)),  T *= exp(-tau Step)
// (midpoint rule: error O(Step^2) where the field is smooth, O(tau Step) at
// the mesh boundary and at cell-scalar jumps). It also counts the cells each
// ray meets (a sample in another cell than the last sample's: crossings
// shorter than Step can be missed) and the rays that become opaque (below a
// transmittance of 0.001, where a renderer's early termination stops).
#ifndef PPIRayBruteForce_h
#define PPIRayBruteForce_h

#include "vtkCamera.h"
#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLocator.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ppiray_test
{
// Premultiplied RGB in [0, 1] per pixel (row-major from the bottom) and the
// number of samples taken. `array`: point scalars by that name, else cell
// scalars by that name.
struct BruteForceImage
{
  std::vector<double> RGB;
  long long Samples = 0;
  long long CellsMet = 0;
  int OpaqueRays = 0;
};

inline BruteForceImage BruteForceMarch(vtkRenderer* ren, vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, const char* array, bool cellScalars, int w, int h, double step)
{
  vtkDataArray* scalars =
    cellScalars ? grid->GetCellData()->GetArray(array) : grid->GetPointData()->GetArray(array);
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(grid);
  locator->BuildLocator();
  vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const double unitDistance = property->GetScalarOpacityUnitDistance(0);
  double bounds[6];
  grid->GetBounds(bounds);

  // Rays in world coordinates: near and far points of each pixel centre.
  std::vector<std::array<double, 6>> rays(static_cast<size_t>(w) * h);
  for (int py = 0; py < h; ++py)
  {
    for (int px = 0; px < w; ++px)
    {
      auto& ray = rays[py * w + px];
      for (int z = 0; z < 2; ++z)
      {
        ren->SetDisplayPoint(px + 0.5, py + 0.5, z);
        ren->DisplayToWorld();
        const double* p = ren->GetWorldPoint();
        for (int i = 0; i < 3; ++i)
        {
          ray[3 * z + i] = p[i] / p[3];
        }
      }
    }
  }
  BruteForceImage image;
  image.RGB.assign(3 * rays.size(), 0.0);
  std::vector<long long> samples(rays.size(), 0), cellsMet(rays.size(), 0);
  std::vector<char> opaque(rays.size(), 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(rays.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkNew<vtkGenericCell> cell;
      std::vector<double> weights(64);
      for (vtkIdType r = begin; r < end; ++r)
      {
        const auto& ray = rays[r];
        double d[3] = { ray[3] - ray[0], ray[4] - ray[1], ray[5] - ray[2] };
        // The part of the ray inside the bounds (slab clipping).
        double t0 = 0.0, t1 = 1.0;
        for (int i = 0; i < 3; ++i)
        {
          if (d[i] == 0.0)
          {
            if (ray[i] < bounds[2 * i] || ray[i] > bounds[2 * i + 1])
            {
              t1 = -1.0;
            }
            continue;
          }
          double a = (bounds[2 * i] - ray[i]) / d[i], b = (bounds[2 * i + 1] - ray[i]) / d[i];
          t0 = std::max(t0, std::min(a, b));
          t1 = std::min(t1, std::max(a, b));
        }
        if (!(t1 > t0))
        {
          continue;
        }
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double dt = step / length;
        double rgb[3] = { 0, 0, 0 }, transmittance = 1.0;
        vtkIdType current = -1;
        for (double t = t0 + 0.5 * dt; t < t1; t += dt)
        {
          double x[3] = { ray[0] + t * d[0], ray[1] + t * d[1], ray[2] + t * d[2] };
          double pcoords[3], dist2;
          int subId;
          bool inside = false;
          if (current >= 0)
          {
            grid->GetCell(current, cell);
            double closest[3];
            inside = cell->EvaluatePosition(x, closest, subId, pcoords, dist2, weights.data()) == 1;
          }
          if (!inside)
          {
            current = locator->FindCell(x, 0.0, cell, subId, pcoords, weights.data());
            inside = current >= 0;
            cellsMet[r] += inside ? 1 : 0;
          }
          ++samples[r];
          if (!inside)
          {
            continue;
          }
          double s = 0.0;
          if (cellScalars)
          {
            s = scalars->GetComponent(current, 0);
          }
          else
          {
            for (vtkIdType v = 0; v < cell->GetNumberOfPoints(); ++v)
            {
              s += weights[v] * scalars->GetComponent(cell->GetPointId(v), 0);
            }
          }
          double c[3];
          color->GetTable(s, s, 1, c);
          const double alpha = 1.0 - std::exp(-opacity->GetValue(s) / unitDistance * step);
          for (int i = 0; i < 3; ++i)
          {
            rgb[i] += transmittance * alpha * c[i];
          }
          transmittance *= 1.0 - alpha;
        }
        for (int i = 0; i < 3; ++i)
        {
          image.RGB[3 * r + i] = rgb[i];
        }
        opaque[r] = transmittance < 0.001;
      }
    });
  for (size_t r = 0; r < rays.size(); ++r)
  {
    image.Samples += samples[r];
    image.CellsMet += cellsMet[r];
    image.OpaqueRays += opaque[r];
  }
  return image;
}
}

#endif
