// vtkHexahedronCoefficients: exact where the field is trilinear in the cell's
// frame, whatever the rotation and shear, and honest flags elsewhere.
//  1. A unit cube turned 45 degrees about z (Miranda's world-coordinate fit is
//     singular there: checked) and a rotated, sheared, scaled parallelepiped:
//     with corner values of a trilinear field, the coefficients equal the
//     unit-cube formulas and reproduce the isoparametric field at interior
//     points to 1e-12.
//  2. A distorted hexahedron: the polynomial takes the corner values
//     (1e-12); NON_PLANAR_FACE set, unset on the parallelepipeds.
//  3. A collapsed hexahedron (pinch-out: top face collapsed onto an edge)
//     gets COLLAPSED_EDGE; a mirrored one INVERTED.
//  4. The filter on a grid of hexahedra, voxels and a tetrahedron: voxels give
//     the same coefficients as the same cells as hexahedra, the tetrahedron is
//     NOT_A_HEXAHEDRON, progress events arrive, the arrays are cell data.

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkHexahedronCoefficients.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>

namespace
{
const double Unit[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
  { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
// A trilinear field of the reference coordinates.
const double Field[8] = { 0.3, -1.2, 0.7, 2.1, -0.4, 1.5, -2.2, 0.9 };

double Trilinear(const double c[8], double u, double v, double w)
{
  const double uvw[3] = { u, v, w };
  return vtkHexahedronCoefficients::EvaluateField(c, uvw);
}

// x = M r + t for reference point r.
void Affine(const double m[3][3], const double t[3], const double r[3], double x[3])
{
  for (int i = 0; i < 3; ++i)
  {
    x[i] = m[i][0] * r[0] + m[i][1] * r[1] + m[i][2] * r[2] + t[i];
  }
}

int Fail(const char* what)
{
  std::cerr << "FAILED: " << what << "\n";
  return 1;
}

// Case 1 for one affine map: returns the number of failures.
int CheckParallelepiped(const char* name, const double m[3][3], const double t[3])
{
  int errors = 0;
  double corners[8][3], values[8];
  for (int i = 0; i < 8; ++i)
  {
    Affine(m, t, Unit[i], corners[i]);
    values[i] = Trilinear(Field, Unit[i][0], Unit[i][1], Unit[i][2]);
  }
  double frame[12], c[8], deviation;
  const int flags =
    vtkHexahedronCoefficients::ComputeCell(corners, values, 1e-3, 1e-6, frame, c, &deviation);
  double worst = 0;
  for (int k = 0; k < 8; ++k)
  {
    worst = std::max(worst, std::abs(c[k] - Field[k]));
  }
  // Interior points: the isoparametric field at reference r is Field(r).
  for (int n = 0; n < 27; ++n)
  {
    const double r[3] = { 0.1 + 0.4 * (n % 3), 0.1 + 0.4 * ((n / 3) % 3), 0.1 + 0.4 * (n / 9) };
    double x[3], uvw[3];
    Affine(m, t, r, x);
    vtkHexahedronCoefficients::ToFrame(frame, x, uvw);
    worst = std::max(worst, std::abs(vtkHexahedronCoefficients::EvaluateField(c, uvw) -
                                     Trilinear(Field, r[0], r[1], r[2])));
  }
  std::cout << name << ": flags " << flags << ", worst coefficient/field error " << worst
            << ", non-planarity " << deviation << "\n";
  if (flags != 0 || worst > 1e-12)
  {
    errors += Fail(name);
  }
  return errors;
}
}

int TestHexahedronCoefficients(int, char*[])
{
  int errors = 0;
  const double origin[3] = { 10.0, -3.0, 2.5 };

  // 1a. Unit cube turned 45 degrees about z.
  const double r45 = std::sqrt(0.5);
  const double rotation[3][3] = { { r45, -r45, 0 }, { r45, r45, 0 }, { 0, 0, 1 } };
  errors += CheckParallelepiped("cube turned 45 degrees about z", rotation, origin);
  {
    // Miranda's world fit: rows (1, x, y, z, xy, yz, xz, xyz) at the corners of
    // the turned cube centred at the origin; singular (xy and xyz vanish).
    const double centre[3] = { 0, 0, 0 };
    double a[8][8];
    for (int i = 0; i < 8; ++i)
    {
      const double r[3] = { Unit[i][0] - 0.5, Unit[i][1] - 0.5, Unit[i][2] - 0.5 };
      double x[3];
      Affine(rotation, centre, r, x);
      const double row[8] = { 1, x[0], x[1], x[2], x[0] * x[1], x[1] * x[2], x[0] * x[2],
        x[0] * x[1] * x[2] };
      std::copy(row, row + 8, a[i]);
    }
    bool xyVanishes = true;
    for (int i = 0; i < 8; ++i)
    {
      xyVanishes = xyVanishes && std::abs(a[i][4]) < 1e-12 && std::abs(a[i][7]) < 1e-12;
    }
    std::cout << "world-frame fit of the turned cube: xy and xyz columns vanish: " << xyVanishes
              << "\n";
    if (!xyVanishes)
    {
      errors += Fail("expected the world-frame system of the turned cube to be singular");
    }
  }

  // 1b. Rotated, sheared and scaled.
  const double general[3][3] = { { 2.0, 0.7, -0.3 }, { -0.4, 1.3, 0.5 }, { 0.2, -0.6, 0.8 } };
  errors += CheckParallelepiped("rotated, sheared, scaled parallelepiped", general, origin);

  // 2. Distorted: corner 6 pulled out, corner 2 pushed in.
  double corners[8][3], values[8];
  for (int i = 0; i < 8; ++i)
  {
    std::copy(Unit[i], Unit[i] + 3, corners[i]);
    values[i] = 1.0 + 0.5 * i - 0.1 * i * i;
  }
  corners[6][0] += 0.3;
  corners[6][2] += 0.2;
  corners[2][1] -= 0.15;
  double frame[12], c[8], deviation;
  int flags =
    vtkHexahedronCoefficients::ComputeCell(corners, values, 1e-3, 1e-6, frame, c, &deviation);
  double worst = 0;
  for (int i = 0; i < 8; ++i)
  {
    double uvw[3];
    vtkHexahedronCoefficients::ToFrame(frame, corners[i], uvw);
    worst = std::max(worst, std::abs(vtkHexahedronCoefficients::EvaluateField(c, uvw) - values[i]));
  }
  std::cout << "distorted: flags " << flags << ", corner error " << worst << ", non-planarity "
            << deviation << "\n";
  if (worst > 1e-12 || !(flags & vtkHexahedronCoefficients::NON_PLANAR_FACE) ||
      (flags & ~vtkHexahedronCoefficients::NON_PLANAR_FACE))
  {
    errors += Fail("distorted hexahedron: corners not interpolated or wrong flags");
  }

  // 3. Collapsed: the top face's back edge onto its front edge (7 -> 4, 6 -> 5).
  for (int i = 0; i < 8; ++i)
  {
    std::copy(Unit[i], Unit[i] + 3, corners[i]);
  }
  std::copy(corners[4], corners[4] + 3, corners[7]);
  std::copy(corners[5], corners[5] + 3, corners[6]);
  flags = vtkHexahedronCoefficients::ComputeCell(corners, values, 1e-3, 1e-6, frame, c, &deviation);
  std::cout << "collapsed: flags " << flags << "\n";
  if (!(flags & vtkHexahedronCoefficients::COLLAPSED_EDGE) ||
      (flags & vtkHexahedronCoefficients::INVERTED))
  {
    errors += Fail("collapsed hexahedron not flagged COLLAPSED_EDGE only");
  }
  // Mirrored: bottom and top swapped.
  for (int i = 0; i < 8; ++i)
  {
    std::copy(Unit[(i + 4) % 8], Unit[(i + 4) % 8] + 3, corners[i]);
  }
  flags = vtkHexahedronCoefficients::ComputeCell(corners, values, 1e-3, 1e-6, frame, c, &deviation);
  std::cout << "mirrored: flags " << flags << "\n";
  if (!(flags & vtkHexahedronCoefficients::INVERTED))
  {
    errors += Fail("mirrored hexahedron not flagged INVERTED");
  }

  // 4. The filter: 2 hexahedra, the same 2 cells as voxels, one tetrahedron.
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
      {
        points->InsertNextPoint(0.5 * i, 0.7 * j, 0.9 * k);
        scalars->InsertNextValue(std::sin(1.0 + i + 2.0 * j + 3.0 * k));
      }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(scalars);
  auto id = [](int i, int j, int k) { return static_cast<vtkIdType>(i + 3 * (j + 2 * k)); };
  for (int i = 0; i < 2; ++i)
  {
    const vtkIdType hex[8] = { id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0),
      id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1) };
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  }
  for (int i = 0; i < 2; ++i)
  {
    const vtkIdType voxel[8] = { id(i, 0, 0), id(i + 1, 0, 0), id(i, 1, 0), id(i + 1, 1, 0),
      id(i, 0, 1), id(i + 1, 0, 1), id(i, 1, 1), id(i + 1, 1, 1) };
    grid->InsertNextCell(VTK_VOXEL, 8, voxel);
  }
  const vtkIdType tet[4] = { 0, 1, 3, 6 };
  grid->InsertNextCell(VTK_TETRA, 4, tet);

  vtkNew<vtkHexahedronCoefficients> filter;
  filter->SetInputData(grid);
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progressEvents);
  onProgress->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  filter->Update();
  vtkCellData* cd = filter->GetOutput()->GetCellData();
  auto* coefficients = vtkDoubleArray::SafeDownCast(cd->GetArray("HexahedronCoefficients"));
  auto* quality = vtkUnsignedCharArray::SafeDownCast(cd->GetArray("HexahedronQuality"));
  if (!coefficients || !quality || !cd->GetArray("HexahedronFrame") ||
      !cd->GetArray("FaceNonPlanarity"))
  {
    return Fail("filter output lacks its cell arrays");
  }
  double same = 0;
  for (int cell = 0; cell < 2; ++cell)
  {
    for (int k = 0; k < 8; ++k)
    {
      same = std::max(same,
        std::abs(coefficients->GetComponent(cell, k) - coefficients->GetComponent(cell + 2, k)));
    }
  }
  std::cout << "filter: voxel vs hexahedron coefficients " << same << ", flags "
            << int(quality->GetValue(0)) << " " << int(quality->GetValue(2)) << " "
            << int(quality->GetValue(4)) << ", progress events " << progressEvents << "\n";
  if (same > 1e-12 || quality->GetValue(0) != 0 || quality->GetValue(2) != 0 ||
      quality->GetValue(4) != vtkHexahedronCoefficients::NOT_A_HEXAHEDRON || progressEvents < 1)
  {
    errors += Fail("filter on hexahedra, voxels and a tetrahedron");
  }
  return errors == 0 ? 0 : 1;
}
