#include "vtkUnstructuredGridBoundaryFaces.h"

#include "ppirayConformingTetrahedra.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridCellAdjacency.h"

#include <vector>

vtkStandardNewMacro(vtkUnstructuredGridBoundaryFaces);

//------------------------------------------------------------------------------
int vtkUnstructuredGridBoundaryFaces::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridBoundaryFaces::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }

  std::vector<vtkIdType> tets, cellIds, unsupported;
  ppiray::ExtractTetrahedra(input, tets, cellIds, unsupported);
  vtkIdType ignored = 0;
  for (size_t i = 1; i < unsupported.size(); i += 2)
  {
    ignored += unsupported[i];
  }
  if (ignored > 0)
  {
    vtkWarningMacro(<< ignored << " non-tetrahedral cells ignored.");
  }
  const vtkIdType numberOfTets = static_cast<vtkIdType>(cellIds.size());
  if (numberOfTets == 0 || !input->GetPoints())
  {
    return 1;
  }

  vtkNew<vtkUnstructuredGridCellAdjacency> adjacency;
  adjacency->Build(input->GetNumberOfPoints(), tets.data(), numberOfTets);
  const std::vector<vtkIdType>& boundary = adjacency->GetBoundaryFaces();
  const vtkIdType numberOfFaces = adjacency->GetNumberOfBoundaryFaces();

  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(numberOfFaces, 3 * numberOfFaces);
  vtkNew<vtkIdTypeArray> owner;
  owner->SetName("CellId");
  owner->SetNumberOfTuples(numberOfFaces);
  vtkNew<vtkUnsignedCharArray> faceIndex;
  faceIndex->SetName("FaceIndex");
  faceIndex->SetNumberOfTuples(numberOfFaces);

  vtkPoints* points = input->GetPoints();
  for (vtkIdType k = 0; k < numberOfFaces; ++k)
  {
    const vtkIdType t = boundary[2 * k];
    const int f = static_cast<int>(boundary[2 * k + 1]);
    const vtkIdType* tet = tets.data() + 4 * t;
    double p[4][3];
    for (int v = 0; v < 4; ++v)
    {
      points->GetPoint(tet[v], p[v]);
    }
    vtkIdType face[3];
    for (int v = 0; v < 3; ++v)
    {
      face[v] = tet[vtkUnstructuredGridCellAdjacency::FaceVertex(f, v)];
    }
    if (vtkUnstructuredGridCellAdjacency::SignedVolume6(p[0], p[1], p[2], p[3]) < 0)
    {
      std::swap(face[1], face[2]);
    }
    triangles->InsertNextCell(3, face);
    owner->SetValue(k, cellIds[t]);
    faceIndex->SetValue(k, static_cast<unsigned char>(f));
  }

  output->SetPoints(points);
  output->SetPolys(triangles);
  output->GetCellData()->AddArray(owner);
  output->GetCellData()->AddArray(faceIndex);
  return 1;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridBoundaryFaces::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
