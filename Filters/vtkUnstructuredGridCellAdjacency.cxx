#include "vtkUnstructuredGridCellAdjacency.h"

#include "ppirayCellAdjacency.h"
#include "ppirayInvertedSheets.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkUnstructuredGridCellAdjacency);

namespace
{
// Face f is opposite vertex f, wound counter-clockwise seen from outside a
// positively oriented tetrahedron.
constexpr ppiray::CellFaceTable Tetrahedron = { 4, 4,
  { { 1, 2, 3, -1 }, { 0, 3, 2, -1 }, { 0, 1, 3, -1 }, { 0, 2, 1, -1 }, { -1, -1, -1, -1 },
    { -1, -1, -1, -1 } } };
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridCellAdjacency::FaceVertex(int f, int v)
{
  return Tetrahedron.Face[f][v];
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridCellAdjacency::SignedVolume6(
  const double p0[3], const double p1[3], const double p2[3], const double p3[3])
{
  const double a[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  const double b[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
  const double c[3] = { p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2] };
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridCellAdjacency::Build(vtkIdType numberOfPoints, const vtkIdType* tets,
  vtkIdType numberOfTets, const double* points, const unsigned char* flat)
{
  ppiray::CellFaceMesh mesh;
  mesh.NumberOfPoints = numberOfPoints;
  mesh.NumberOfCells = numberOfTets;
  mesh.CornerIds = tets;
  mesh.Tables[0] = &Tetrahedron;
  mesh.Points = points;
  mesh.Flat = flat;
  this->Cache.Update(mesh);
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridCellAdjacency::WalksBackInPlace(vtkIdType t, vtkIdType n) const
{
  return ppiray::WalksBackInPlace(this->Get().Inverted, t, n);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridCellAdjacency::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTetrahedra: " << this->Get().Neighbors.size() / 4 << "\n";
  os << indent << "NumberOfBoundaryFaces: " << this->GetNumberOfBoundaryFaces() << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->GetNumberOfNonManifoldFaces() << "\n";
  os << indent << "NumberOfFoldedFaces: " << this->GetNumberOfFoldedFaces() << "\n";
}
