// ppiray::GridGeometryKey: a grid's geometry recognized across grid objects.
//  1. the same grid again, and a new grid object sharing its arrays: Same;
//  2. deep copies of every array: SameContent; Modified() without a change:
//     SameContent;
//  3. each array of the geometry changed, in a copy or in place (and
//     Modified()): Changed — a point coordinate, a connectivity entry, a
//     cell type, a polyhedron face's point, a hidden flag, the
//     points' data type; and the field alone changed: not a change of
//     geometry;
//  4. the digest: a single bit flipped anywhere in a string changes it, the
//     length is part of it, and a value's data type is part of an array's.

#include "ppirayGridGeometryKey.h"
#include "ppirayVTKCompatibility.h"

#include "vtkCellArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using Match = ppiray::GridGeometryKey::Match;

const char* Name(Match m)
{
  return m == Match::Same ? "Same" : (m == Match::SameContent ? "SameContent" : "Changed");
}

// Two hexahedra, a tetrahedron and a polyhedron (a cube) on 20 points, a
// point field.
vtkSmartPointer<vtkUnstructuredGrid> MakeGrid()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 5; ++i)
        points->InsertNextPoint(i, j, k);
  grid->SetPoints(points);
  auto id = [](int i, int j, int k) { return static_cast<vtkIdType>(i + 5 * (j + 2 * k)); };
  grid->Allocate(4);
  for (int i = 0; i < 2; ++i)
  {
    const vtkIdType hex[8] = { id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0), id(i, 1, 0),
      id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1) };
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  }
  const vtkIdType tet[4] = { id(2, 0, 0), id(3, 0, 0), id(2, 1, 0), id(2, 0, 1) };
  grid->InsertNextCell(VTK_TETRA, 4, tet);
  const vtkIdType c[8] = { id(3, 0, 0), id(4, 0, 0), id(4, 1, 0), id(3, 1, 0), id(3, 0, 1),
    id(4, 0, 1), id(4, 1, 1), id(3, 1, 1) };
  const int faces[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 3, 7, 6, 2 },
    { 0, 4, 7, 3 }, { 1, 2, 6, 5 } };
  vtkNew<vtkIdList> stream;
  stream->InsertNextId(6);
  for (const auto& f : faces)
  {
    stream->InsertNextId(4);
    for (int v : f)
      stream->InsertNextId(c[v]);
  }
  grid->InsertNextCell(VTK_POLYHEDRON, stream);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
    s->InsertNextValue(0.1 * p);
  grid->GetPointData()->SetScalars(s);
  return grid;
}

// A new grid object with deep copies of every array of `grid`.
vtkSmartPointer<vtkUnstructuredGrid> DeepCopyOf(vtkUnstructuredGrid* grid)
{
  auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
  copy->DeepCopy(grid);
  return copy;
}

// A new grid object sharing the arrays of `grid`.
vtkSmartPointer<vtkUnstructuredGrid> ShallowCopyOf(vtkUnstructuredGrid* grid)
{
  auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
  copy->ShallowCopy(grid);
  return copy;
}

// The array of the polyhedron faces' point ids (9.2's face stream, or the
// faces' connectivity since 9.4): the longest of them.
vtkDataArray* FaceIds(vtkUnstructuredGrid* grid)
{
  vtkDataArray* longest = nullptr;
  for (const auto& faces : ppiray::compat::PolyhedronFaceArrays(grid))
  {
    if (faces.first &&
        (!longest || faces.first->GetNumberOfValues() > longest->GetNumberOfValues()))
    {
      longest = faces.first;
    }
  }
  return longest;
}
}

int TestGridGeometryKey(int, char*[])
{
  int errors = 0;
  auto expect = [&](Match got, Match want, const std::string& what)
  {
    std::cout << what << ": " << Name(got) << "\n";
    if (got != want)
    {
      std::cerr << "FAILED: " << what << " gave " << Name(got) << ", expected " << Name(want)
                << "\n";
      ++errors;
    }
  };

  // 1, 2.
  auto grid = MakeGrid();
  ppiray::GridGeometryKey key;
  expect(key.Update(grid), Match::Changed, "first grid");
  expect(key.Update(grid), Match::Same, "the same grid again");
  expect(key.Update(ShallowCopyOf(grid)), Match::Same, "a new grid sharing the arrays");
  auto copy = DeepCopyOf(grid);
  expect(key.Update(copy), Match::SameContent, "deep copies of the arrays");
  expect(key.Update(copy), Match::Same, "the copy again");
  copy->GetPoints()->Modified();
  expect(key.Update(copy), Match::SameContent, "points Modified() unchanged");
  copy->GetPointData()->GetScalars()->SetTuple1(0, 7.0);
  copy->GetPointData()->GetScalars()->Modified();
  expect(key.Update(copy), Match::Same, "the field changed");

  // 3. Each array of the geometry changed in a deep copy, then the key back
  // on the original.
  using Edit = std::function<void(vtkUnstructuredGrid*)>;
  const std::vector<std::pair<std::string, Edit>> edits = {
    { "a point moved",
      [](vtkUnstructuredGrid* g)
      {
        g->GetPoints()->SetPoint(7, 1.0, 1.0, 1e-7);
        g->GetPoints()->Modified();
      } },
    { "a connectivity entry",
      [](vtkUnstructuredGrid* g)
      {
        g->GetCells()->GetConnectivityArray()->SetTuple1(1, 3);
        g->GetCells()->Modified();
      } },
    { "a cell type",
      [](vtkUnstructuredGrid* g)
      {
        g->GetCellTypesArray()->SetValue(0, VTK_VOXEL);
        g->GetCellTypesArray()->Modified();
      } },
    { "a hidden flag",
      [](vtkUnstructuredGrid* g)
      {
        g->AllocateCellGhostArray();
        g->GetCellGhostArray()->SetValue(2, vtkDataSetAttributes::HIDDENCELL);
      } },
    { "points as double (the same values)",
      [](vtkUnstructuredGrid* g)
      {
        vtkNew<vtkPoints> points;
        points->SetDataTypeToDouble();
        for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p)
          points->InsertNextPoint(g->GetPoint(p));
        g->SetPoints(points);
      } },
    { "a polyhedron face's point",
      [](vtkUnstructuredGrid* g)
      {
        vtkDataArray* faces = FaceIds(g);
        faces->SetTuple1(faces->GetNumberOfTuples() - 1, 0);
        faces->Modified();
      } },
  };
  for (const auto& edit : edits)
  {
    auto changed = DeepCopyOf(grid);
    edit.second(changed);
    expect(key.Update(changed), Match::Changed, edit.first + " (a copy)");
    expect(key.Update(grid), Match::Changed, "the original after " + edit.first);
  }
  // In place, the same arrays: the point moved, then back.
  double x[3];
  grid->GetPoints()->GetPoint(3, x);
  grid->GetPoints()->SetPoint(3, x[0], x[1], x[2] + 0.25);
  grid->GetPoints()->Modified();
  expect(key.Update(grid), Match::Changed, "a point moved in place");
  grid->GetPoints()->SetPoint(3, x);
  grid->GetPoints()->Modified();
  expect(key.Update(grid), Match::Changed, "moved back in place");
  expect(key.Update(DeepCopyOf(grid)), Match::SameContent, "a copy after moving back");

  // 4. The digest itself.
  std::vector<unsigned char> bytes(1000);
  for (size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<unsigned char>((i * 131 + 7) & 255);
  const ppiray::ContentDigest d = ppiray::DigestBytes(bytes.data(), bytes.size());
  int unchanged = 0;
  for (size_t i = 0; i < bytes.size(); ++i)
  {
    for (int b = 0; b < 8; ++b)
    {
      bytes[i] ^= static_cast<unsigned char>(1 << b);
      unchanged += ppiray::DigestBytes(bytes.data(), bytes.size()) == d ? 1 : 0;
      bytes[i] ^= static_cast<unsigned char>(1 << b);
    }
  }
  const bool lengthCounts =
    ppiray::DigestBytes(bytes.data(), 999) != ppiray::DigestBytes(bytes.data(), 998);
  vtkNew<vtkFloatArray> f;
  vtkNew<vtkIdTypeArray> ids; // 4 bytes of float zero and of half an id zero alike
  f->SetNumberOfValues(2);
  f->FillValue(0.0f);
  ids->SetNumberOfValues(1);
  ids->FillValue(0);
  const bool typeCounts = ppiray::DigestArray(f) != ppiray::DigestArray(ids);
  std::cout << "digest: " << unchanged << " of 8000 single-bit flips unseen; length "
            << (lengthCounts ? "counts" : "ignored") << "; type "
            << (typeCounts ? "counts" : "ignored") << "\n";
  if (unchanged != 0 || !lengthCounts || !typeCounts)
  {
    std::cerr << "FAILED: the digest missed a change\n";
    ++errors;
  }
  return errors == 0 ? 0 : 1;
}
