// The differences between the VTK versions PPIRay builds against (9.2,
// ParaView 5.11's, with GLEW; 9.6, the headless build of Module/vtk, with glad
// and the 9.4 polyhedron storage), in one place.
#ifndef ppirayVTKCompatibility_h
#define ppirayVTKCompatibility_h

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVersionMacros.h"

#include <utility>
#include <vector>

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
#define PPIRAY_VTK_HAS_GLAD 1
#include "vtkCellTypeUtilities.h"
#else
#define PPIRAY_VTK_HAS_GLAD 0
#include "vtkCellTypes.h"
#endif

// The header that declares OpenGL through VTK's loader:
// #include PPIRAY_VTK_OPENGL_HEADER
#if PPIRAY_VTK_HAS_GLAD
#define PPIRAY_VTK_OPENGL_HEADER "vtk_glad.h"
#else
#define PPIRAY_VTK_OPENGL_HEADER "vtk_glew.h"
#endif

namespace ppiray
{
namespace compat
{
/// "vtkTetra" for VTK_TETRA.
inline const char* CellClassName(int cellType)
{
#if PPIRAY_VTK_HAS_GLAD
  return vtkCellTypeUtilities::GetClassNameFromTypeId(cellType);
#else
  return vtkCellTypes::GetClassNameFromTypeId(cellType);
#endif
}

/// The arrays holding a grid's polyhedron faces, each with the object whose
/// modification time covers it (null arrays where the grid has none; always
/// as many).
inline std::vector<std::pair<vtkDataArray*, vtkObject*>> PolyhedronFaceArrays(
  vtkUnstructuredGrid* grid)
{
  std::vector<std::pair<vtkDataArray*, vtkObject*>> arrays;
#if PPIRAY_VTK_HAS_GLAD
  for (vtkCellArray* cells : { grid->GetPolyhedronFaces(), grid->GetPolyhedronFaceLocations() })
  {
    arrays.emplace_back(cells ? cells->GetOffsetsArray() : nullptr, cells);
    arrays.emplace_back(cells ? cells->GetConnectivityArray() : nullptr, cells);
  }
#else
  arrays.emplace_back(grid->GetFaces(), grid->GetFaces());
  arrays.emplace_back(grid->GetFaceLocations(), grid->GetFaceLocations());
#endif
  return arrays;
}

/// `output` takes `types` and `cells` and keeps the polyhedron faces of
/// `input`, except for the cells flagged in `emptied`, which keep none.
inline void SetCellsKeepingPolyhedra(vtkUnstructuredGrid* output, vtkUnstructuredGrid* input,
  vtkUnsignedCharArray* types, vtkCellArray* cells, const std::vector<bool>& emptied)
{
#if PPIRAY_VTK_HAS_GLAD
  vtkCellArray* faceLocations = input->GetPolyhedronFaceLocations();
  if (!faceLocations || faceLocations->GetNumberOfCells() == 0)
  {
    output->SetCells(types, cells);
    return;
  }
  // One "cell" of face ids per grid cell; an emptied polyhedron lists none.
  vtkNew<vtkCellArray> keptLocations;
  for (vtkIdType c = 0; c < faceLocations->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* faceIds;
    faceLocations->GetCellAtId(c, n, faceIds);
    const bool drop = c < static_cast<vtkIdType>(emptied.size()) && emptied[c];
    keptLocations->InsertNextCell(drop ? 0 : n, faceIds);
  }
  output->SetPolyhedralCells(types, cells, keptLocations, input->GetPolyhedronFaces());
#else
  vtkSmartPointer<vtkIdTypeArray> faceLocations;
  if (input->GetFaceLocations())
  {
    faceLocations = vtkSmartPointer<vtkIdTypeArray>::New();
    faceLocations->DeepCopy(input->GetFaceLocations());
    for (vtkIdType c = 0; c < faceLocations->GetNumberOfValues(); ++c)
    {
      if (c < static_cast<vtkIdType>(emptied.size()) && emptied[c])
      {
        faceLocations->SetValue(c, -1);
      }
    }
  }
  output->SetCells(types, cells, faceLocations, input->GetFaces());
#endif
}
}
}

#endif
