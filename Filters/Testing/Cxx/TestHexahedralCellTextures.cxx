// vtkHexahedralCellTextures on a 3x3x3 block of hexahedra with moved interior
// points (non-planar faces), shuffled point ids and the centre cell given
// mirrored (bottom and top swapped):
//  - 27 hexahedra, the mirrored one detected and re-ordered right-handed;
//  - neighbours symmetric, and both cells sharing a face split it along the
//    same diagonal (same two point ids);
//  - exactly the block's 108 boundary triangles, wound outward;
//  - the coefficients reproduce the corner values in the cell frame (float);
//  - a NaN scalar at an interior point marks the 8 cells around it;
//  - a left-handed pyramid written as a hexahedron (corners 0, 1, 2 on 4, 5,
//    6: no frame at corners 0 and 6) is detected mirrored too; its slanted
//    face is split along the diagonal that does not fold a triangle into the
//    base, and its six triangles with area face outward.

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkHexahedralCellTextures.h"
#include "vtkHexahedron.h"
#include "vtkHexahedronCoefficients.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numeric>
#include <set>
#include <vector>

namespace
{
// Whether triangle p faces away from `centre` (its normal, by its winding,
// points to the side `centre` is not on).
bool FacesAway(const double p[3][3], const double centre[3])
{
  double e1[3], e2[3], normal[3], out[3];
  vtkMath::Subtract(p[1], p[0], e1);
  vtkMath::Subtract(p[2], p[0], e2);
  vtkMath::Cross(e1, e2, normal);
  vtkMath::Subtract(p[0], centre, out);
  return vtkMath::Dot(normal, out) > 0;
}

int Fail(const char* what)
{
  std::cerr << "FAILED: " << what << "\n";
  return 1;
}
}

int TestHexahedralCellTextures(int, char*[])
{
  const int n = 3;
  const int m = n + 1;
  // Shuffled ids: logical point l is stored at id perm[l].
  std::vector<vtkIdType> perm(m * m * m);
  std::iota(perm.begin(), perm.end(), 0);
  unsigned state = 777u;
  for (size_t i = perm.size() - 1; i > 0; --i)
  {
    state = state * 1664525u + 1013904223u;
    std::swap(perm[i], perm[state % (i + 1)]);
  }
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(m * m * m);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetNumberOfTuples(m * m * m);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
      {
        const bool interior = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        const double d = interior ? 0.12 : 0.0;
        const double x[3] = { i + d * std::sin(3.0 * j + k), j + d * std::cos(2.0 * k + i),
          k + d * std::sin(i + 5.0 * j) };
        const vtkIdType id = perm[(k * m + j) * m + i];
        points->SetPoint(id, x);
        scalars->SetValue(id, std::cos(0.7 * x[0]) + 0.3 * x[1] * x[2]);
      }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(scalars);
  auto id = [&](int i, int j, int k) { return perm[(k * m + j) * m + i]; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
          id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) };
        if (i == 1 && j == 1 && k == 1)
        {
          std::rotate(hex, hex + 4, hex + 8); // mirrored
        }
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }

  int errors = 0;
  vtkNew<vtkHexahedralCellTextures> textures;
  if (!textures->BuildGeometry(grid) || !textures->BuildField(scalars, false, 0))
  {
    return Fail("build");
  }
  const vtkIdType hexes = textures->GetNumberOfHexahedra();
  std::cout << hexes << " hexahedra, mirrored " << textures->GetNumberOfMirroredHexahedra()
            << ", boundary triangles " << textures->GetBoundaryFaces().size() << ", non-manifold "
            << textures->GetNumberOfNonManifoldFaces() << "\n";
  if (hexes != 27 || textures->GetNumberOfMirroredHexahedra() != 1 ||
      textures->GetBoundaryFaces().size() != 108 || textures->GetNumberOfNonManifoldFaces() != 0)
  {
    errors += Fail("counts");
  }

  const std::vector<int>& nb = textures->GetNeighbors();
  const std::vector<vtkIdType>& ids = textures->GetCornerIds();
  // The diagonal of face f of cell h, as a sorted pair of point ids.
  auto diagonal = [&](vtkIdType h, int f)
  {
    const bool second = (nb[8 * h + 6] >> f) & 1;
    const vtkIdType* q = vtkHexahedron::GetFaceArray(f);
    vtkIdType a = ids[8 * h + q[second ? 1 : 0]], b = ids[8 * h + q[second ? 3 : 2]];
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  int asymmetric = 0, crossed = 0;
  for (vtkIdType h = 0; h < hexes; ++h)
  {
    for (int f = 0; f < 6; ++f)
    {
      // Neighbour codes 6 h' + f' point back at 6 h + f (none folded here).
      const int code = nb[8 * h + f];
      if (code == -1)
      {
        continue;
      }
      const int other = code / 6, back = code % 6;
      if (code < -1 || nb[8 * other + back] != 6 * h + f)
      {
        ++asymmetric;
        continue;
      }
      crossed += diagonal(h, f) != diagonal(other, back) ? 1 : 0;
    }
  }
  std::cout << "asymmetric neighbours " << asymmetric << ", faces split differently " << crossed
            << "\n";
  if (asymmetric || crossed)
  {
    errors += Fail("neighbours or shared diagonals");
  }

  // Boundary triangles face away from their cell.
  const std::vector<float>& bp = textures->GetBoundaryPoints();
  const std::vector<unsigned int>& tri = textures->GetBoundaryTriangles();
  const std::vector<float>& corners = textures->GetCorners();
  int inward = 0;
  for (size_t t = 0; t < textures->GetBoundaryFaces().size(); ++t)
  {
    const vtkIdType h = textures->GetBoundaryFaces()[t] / 12;
    double p[3][3], centre[3] = { 0, 0, 0 };
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k)
        p[v][k] = bp[3 * tri[3 * t + v] + k];
    for (int i = 0; i < 8; ++i)
      for (int k = 0; k < 3; ++k)
        centre[k] += corners[24 * h + 3 * i + k] / 8.0;
    inward += FacesAway(p, centre) ? 0 : 1;
  }
  std::cout << "inward boundary triangles " << inward << "\n";
  if (inward)
  {
    errors += Fail("boundary triangles not wound outward");
  }

  // Coefficients against the corner values.
  double worst = 0;
  for (vtkIdType h = 0; h < hexes; ++h)
  {
    double frame[12], c[8];
    for (int k = 0; k < 3; ++k)
    {
      frame[k] = corners[24 * h + k];
      frame[3 + k] = corners[24 * h + 3 + k] - frame[k];
      frame[6 + k] = corners[24 * h + 9 + k] - frame[k];
      frame[9 + k] = corners[24 * h + 12 + k] - frame[k];
    }
    std::copy_n(textures->GetCoefficients().data() + 8 * h, 8, c);
    for (int i = 0; i < 8; ++i)
    {
      double x[3], uvw[3];
      for (int k = 0; k < 3; ++k)
        x[k] = corners[24 * h + 3 * i + k];
      vtkHexahedronCoefficients::ToFrame(frame, x, uvw);
      worst = std::max(worst, std::abs(vtkHexahedronCoefficients::EvaluateField(c, uvw) -
                                       scalars->GetValue(ids[8 * h + i])));
    }
  }
  std::cout << "coefficients at the corners: worst error " << worst << "\n";
  if (worst > 1e-5)
  {
    errors += Fail("coefficients do not reproduce the corner values");
  }

  // NaN at an interior point.
  scalars->SetValue(id(1, 2, 1), std::numeric_limits<double>::quiet_NaN());
  textures->BuildField(scalars, false, 0);
  int marked = 0;
  for (vtkIdType h = 0; h < hexes; ++h)
  {
    marked +=
      textures->GetCoefficients()[8 * h] == vtkHexahedralCellTextures::TransparentCellOffset();
  }
  std::cout << "NaN: " << textures->GetNumberOfNaNScalars() << " cells, " << marked << " marked\n";
  if (textures->GetNumberOfNaNScalars() != 8 || marked != 8)
  {
    errors += Fail("NaN scalar");
  }
  std::cout << "bytes per hexahedron " << vtkHexahedralCellTextures::BytesPerHexahedron() << "\n";

  // A left-handed pyramid as a hexahedron: base (0, 0, 0), (1, 0, 0),
  // (1, 1, 0), (0, 1, 0), apex (0, 1, 1); corners 0-3 = 0, 1, 2, apex and
  // 4-7 = 0, 1, 2, 3. Every boundary triangle with area must face away from
  // the pyramid's centroid.
  {
    vtkNew<vtkUnstructuredGrid> pyramid;
    vtkNew<vtkPoints> points;
    const double x[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 1, 1 } };
    for (const auto& p : x)
    {
      points->InsertNextPoint(p);
    }
    pyramid->SetPoints(points);
    const vtkIdType cell[8] = { 0, 1, 2, 4, 0, 1, 2, 3 };
    pyramid->InsertNextCell(VTK_HEXAHEDRON, 8, cell);
    vtkNew<vtkHexahedralCellTextures> one;
    one->BuildGeometry(pyramid);
    // (base corners + apex) / 5, in the local frame of the boundary points.
    double centroid[3] = { 0.4, 0.6, 0.2 };
    vtkMath::Subtract(centroid, one->GetOrigin(), centroid);
    const std::vector<float>& q = one->GetBoundaryPoints();
    const std::vector<unsigned int>& t = one->GetBoundaryTriangles();
    int facing[2] = { 0, 0 }; // outward, inward
    for (size_t i = 0; i < t.size() / 3; ++i)
    {
      double p[3][3];
      for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k)
          p[v][k] = q[3 * t[3 * i + v] + k];
      double e1[3], e2[3], normal[3];
      vtkMath::Subtract(p[1], p[0], e1);
      vtkMath::Subtract(p[2], p[0], e2);
      vtkMath::Cross(e1, e2, normal);
      if (vtkMath::Norm(normal) > 1e-9) // triangles with area
      {
        ++facing[FacesAway(p, centroid) ? 0 : 1];
      }
    }
    std::cout << "left-handed pyramid: mirrored " << one->GetNumberOfMirroredHexahedra()
              << ", unfolded faces " << one->GetNumberOfUnfoldedFaces() << ", triangles outward "
              << facing[0] << ", inward " << facing[1] << "\n";
    if (one->GetNumberOfMirroredHexahedra() != 1 || one->GetNumberOfUnfoldedFaces() < 1 ||
        facing[0] != 6 || facing[1] != 0)
    {
      errors += Fail("left-handed pyramid as a hexahedron");
    }
  }
  return errors == 0 ? 0 : 1;
}
