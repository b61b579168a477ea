// Boundary faces of a mesh joined to the imaginary cells on them
// (ppirayBoundaryFaceLinks.h, through vtkTetrahedralCellTextures): one mesh
// tetrahedron whose top face ABC is met by imaginary tetrahedra from an apex
// E above it, built by hand, each imaginary face on ABC named in
// "ppirayBoundaryCell":
//  1. ABC split at its centroid S into 3 pieces: one split face, its list
//     (3, the pieces' codes), each piece's code back to ABC, 6 boundary
//     triangles left (the mesh's 3 others, the 3 around E);
//  2. two of the 3 pieces: they do not cover ABC, nothing joined through the
//     array, one face left open by it; then joined by geometry
//     (ppirayNonConformingFaces.h), ABC partly covered: a list, and still a
//     boundary face;
//  3. one piece, ABC through other point ids at the same places (a seam):
//     joined directly (no list);
//  4. the pieces naming a cell they do not lie on: not joined through the
//     array, 3 left open by it, then joined by geometry (they lie on ABC:
//     ppirayNonConformingFaces.h);
//  5. no cell array: nothing counted, joined by geometry as in 4.

#include "ppirayBoundaryFaceLinks.h"
#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTetrahedralCellTextures.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
// Points: A B C D (the mesh tetrahedron, D below ABC), S (ABC's centroid),
// E (above), A' B' C' (copies of A B C), F (far away, for a wrong name).
vtkNew<vtkUnstructuredGrid> Scene(int scene)
{
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  const double x[10][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.2, 0.2, -1 },
    { 1.0 / 3, 1.0 / 3, 0 }, { 0.3, 0.3, 1 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 5, 5, 5 } };
  for (const auto& p : x)
  {
    points->InsertNextPoint(p);
  }
  grid->SetPoints(points);
  grid->AllocateEstimate(8, 4);
  const vtkIdType mesh[4] = { 0, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, mesh);
  std::vector<std::vector<vtkIdType>> imaginary;
  if (scene == 3)
  {
    imaginary = { { 6, 7, 8, 5 } };
  }
  else
  {
    imaginary = { { 0, 1, 4, 5 }, { 1, 2, 4, 5 }, { 2, 0, 4, 5 } };
  }
  if (scene == 2)
  {
    imaginary.pop_back();
  }
  for (const auto& t : imaginary)
  {
    grid->InsertNextCell(VTK_TETRA, 4, t.data());
  }
  if (scene == 4)
  {
    const vtkIdType far[4] = { 9, 1, 2, 3 }; // a second mesh cell, away from E
    grid->InsertNextCell(VTK_TETRA, 4, far);
  }
  if (scene != 5)
  {
    vtkNew<vtkIdTypeArray> across;
    across->SetName(ppiray::BoundaryCellArrayName);
    across->SetNumberOfComponents(4);
    across->SetNumberOfTuples(grid->GetNumberOfCells());
    across->Fill(-1);
    for (vtkIdType c = 1; c <= static_cast<vtkIdType>(imaginary.size()); ++c)
    {
      across->SetTypedComponent(c, 3, scene == 4 ? 4 : 0); // face opposite E
    }
    grid->GetCellData()->AddArray(across);
  }
  return grid;
}
}

int TestBoundaryFaceLinks(int, char*[])
{
  using Cells = vtkTetrahedralCellTextures;
  int errors = 0;
  auto expect = [&errors](bool ok, int scene, const std::string& what)
  {
    if (!ok)
    {
      std::cerr << "FAILED: scene " << scene << ": " << what << "\n";
      ++errors;
    }
  };
  for (int scene = 1; scene <= 5; ++scene)
  {
    auto grid = Scene(scene);
    vtkNew<Cells> cells;
    cells->BuildGeometry(grid);
    const std::vector<int>& nb = cells->GetNeighbors();
    const int meshFace = 3; // face ABC of tetrahedron 0, opposite D
    std::cout << "scene " << scene << ": linked " << cells->GetNumberOfLinkedFaces() << ", split "
              << cells->GetNumberOfSplitFaces() << ", most pieces "
              << cells->GetMaximumPiecesPerFace() << ", open " << cells->GetNumberOfUnlinkedFaces()
              << ", boundary triangles " << cells->GetBoundaryFaces().size() << ", neighbour ints "
              << nb.size() << ", by geometry " << cells->GetNumberOfNonConformingFaces()
              << ", ABC code " << nb[meshFace] << "\n";
    const vtkIdType imaginary = scene == 2 ? 2 : scene == 3 ? 1 : 3;
    if (scene == 1)
    {
      expect(cells->GetNumberOfLinkedFaces() == 1 && cells->GetNumberOfSplitFaces() == 1 &&
               cells->GetMaximumPiecesPerFace() == 3 && cells->GetNumberOfUnlinkedFaces() == 0,
        scene, "one split face of 3 pieces");
      const int list = nb[meshFace] - Cells::SplitFace();
      const bool listed = list == 4 && nb.size() == 4 * 4 + 4 && nb[4 * list] == 3 &&
                          nb[4 * list + 1] == 4 * 1 + 3 && nb[4 * list + 2] == 4 * 2 + 3 &&
                          nb[4 * list + 3] == 4 * 3 + 3;
      expect(listed, scene, "the list after the 4 tetrahedra's texels: 3, codes of the pieces");
      for (vtkIdType t = 1; t <= imaginary; ++t)
      {
        expect(nb[4 * t + 3] == meshFace, scene, "a piece's code back to the mesh face");
      }
      expect(cells->GetBoundaryFaces().size() == 6, scene, "6 boundary triangles");
    }
    else if (scene == 3)
    {
      expect(cells->GetNumberOfLinkedFaces() == 1 && cells->GetNumberOfSplitFaces() == 0 &&
               nb[meshFace] == 4 * 1 + 3 && nb[4 * 1 + 3] == meshFace && nb.size() == 8 &&
               cells->GetBoundaryFaces().size() == 6,
        scene, "the seam face joined directly both ways");
    }
    else if (scene == 2)
    {
      // Not covered by the array's pieces: not joined through the array;
      // joined by geometry (ABC to its 2 pieces by a list, still a boundary
      // face where it is exposed; each piece to ABC directly).
      expect(cells->GetNumberOfLinkedFaces() == 0 && cells->GetNumberOfSplitFaces() == 0 &&
               cells->GetNumberOfNonConformingFaces() == 3 && nb[meshFace] >= Cells::SplitFace() &&
               nb[meshFace] < Cells::ReentryFace(),
        scene, "nothing joined through the array, joined by geometry");
    }
    if (scene >= 4)
    {
      // Not joined through the cell array, but the pieces lie on ABC: joined
      // by geometry (ppirayNonConformingFaces.h), ABC to its 3 pieces by a
      // list, each piece to ABC directly.
      expect(cells->GetNumberOfLinkedFaces() == 0 && cells->GetNumberOfSplitFaces() == 0 &&
               cells->GetNumberOfNonConformingFaces() == 4 && nb[meshFace] >= Cells::SplitFace() &&
               nb[meshFace] < Cells::ReentryFace() &&
               cells->GetBoundaryFaces().size() == (scene == 4 ? 8u : 6u),
        scene, "joined by geometry only");
    }
    if (scene != 1 && scene != 3)
    {
      const vtkIdType open = scene == 2 ? 1 : scene == 4 ? 3 : 0;
      expect(
        cells->GetNumberOfUnlinkedFaces() == open, scene, "left open: " + std::to_string(open));
    }
  }
  return errors == 0 ? 0 : 1;
}
