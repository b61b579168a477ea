// Readers of the data root's PLOT3D, Exodus II and UNISIM-II files for the
// tests, in what these files need.
//
// This driver links no VTK reader of these formats
// (vtkMultiBlockPLOT3DReader is in VTK::IOParallel, vtkExodusIIReader in
// VTK::IOExodus, whose imported target needs the NetCDF and HDF5 development
// packages at configure time), so the test reads the two files itself, in
// what these files need: PLOT3D whole, big-endian, without record markers
// (what AutoDetectFormatOn() finds for them), the derived functions as
// vtkMultiBlockPLOT3DReader computes them (gamma 1.4); Exodus II stored as
// netCDF classic (coordinates, HEX8 blocks, one nodal variable, first time
// step). Checked against those VTK readers (pvpython): identical points,
// cells and values (disk_out_ref: up to the point numbering, which
// vtkExodusIIReader compacts in order of use).
#ifndef PPIRayDataReaders_h
#define PPIRayDataReaders_h

#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <string>

namespace ppiray_test
{
// PLOT3D, one 3D grid, whole (no record markers), big-endian: "ni nj nk" then
// x, y, z (an IBlank block may follow: skipped, the data's README says nothing
// is blanked); the solution "ni nj nk fsmach alpha re time" then density,
// three momentum components and stagnation energy. Cells as VTK_HEXAHEDRON in
// vtkStructuredGrid's corner order (i fastest, then j, then k).
// `function`: 100 Density, 110 Pressure, 153 VelocityMagnitude, with
// vtkMultiBlockPLOT3DReader's numbers, names and formulas.
vtkSmartPointer<vtkUnstructuredGrid> ReadPLOT3D(
  const std::string& xyzPath, const std::string& qPath, int function, std::string* error);

// An Exodus II file's element blocks (HEX8 only) as one vtkUnstructuredGrid
// over all its nodes, the nodal variable `name` of the first time step as
// point scalars: what vtkExodusIIReader with SetPointResultArrayStatus(name, 1)
// gives with its blocks appended, points merged (they share one numbering).
vtkSmartPointer<vtkUnstructuredGrid> ReadExodusHexahedra(
  const std::string& path, const std::string& name, std::string* error);

// UNISIM-II with the derived point scalars "Depth" = -z.
vtkSmartPointer<vtkUnstructuredGrid> ReadUNISIM(const std::string& path, std::string* error);
}

#endif
