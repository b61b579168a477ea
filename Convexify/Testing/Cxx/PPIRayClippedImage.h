// What ParaView's Clip and Tetrahedralize make of an image: VTK's wavelet
// (RTData at the points) over [-n, n]^3 cut by a sphere, a slanted plane and
// a thin gap (vtkClipDataSet), then split into tetrahedra
// (vtkDataSetTriangleFilter). The clips leave zero-volume tetrahedra, faces
// shared by three cells and points a few roundings apart where cut edges
// meet; the gap leaves two parts.
#ifndef PPIRayClippedImage_h
#define PPIRayClippedImage_h

#include "vtkClipDataSet.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkImplicitBoolean.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSmartPointer.h"
#include "vtkSphere.h"
#include "vtkUnstructuredGrid.h"

namespace ppiray_test
{
inline vtkSmartPointer<vtkUnstructuredGrid> ClippedImage(int n)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-n, n, -n, n, -n, n);
  vtkNew<vtkSphere> sphere;
  sphere->SetRadius(0.55 * n);
  sphere->SetCenter(0.3 * n, 0.2 * n, 0.0);
  vtkNew<vtkPlane> slant;
  slant->SetNormal(1.0, 0.4, 0.3);
  slant->SetOrigin(-0.4 * n, 0.0, 0.0);
  vtkNew<vtkPlane> below, above;
  below->SetNormal(0.0, 1.0, 0.2);
  below->SetOrigin(0.0, -0.05 * n, 0.0);
  above->SetNormal(0.0, -1.0, -0.2);
  above->SetOrigin(0.0, 0.05 * n, 0.0);
  vtkNew<vtkImplicitBoolean> gap; // outside the slab between the two planes
  gap->SetOperationTypeToIntersection();
  gap->AddFunction(below);
  gap->AddFunction(above);
  vtkNew<vtkClipDataSet> bySphere, bySlant, byGap;
  bySphere->SetInputConnection(wavelet->GetOutputPort());
  bySphere->SetClipFunction(sphere);
  bySlant->SetInputConnection(bySphere->GetOutputPort());
  bySlant->SetClipFunction(slant);
  byGap->SetInputConnection(bySlant->GetOutputPort());
  byGap->SetClipFunction(gap);
  vtkNew<vtkDataSetTriangleFilter> tetrahedralize;
  tetrahedralize->SetInputConnection(byGap->GetOutputPort());
  tetrahedralize->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = tetrahedralize->GetOutput();
  return grid;
}
}

#endif
