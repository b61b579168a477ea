"""Shared last step of the Data/ scripts: remove the cells inside an implicit
function, split the rest into tetrahedra, write a compressed .vtu next to
these scripts."""
import os

from vtkmodules.vtkFiltersExtraction import vtkExtractGeometry
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter


def carve_and_write(dataset, holes, name):
    """Cells of `dataset` outside `holes`, tetrahedralized, written to
    Data/<name>; returns (path, number of tetrahedra)."""
    outside = vtkExtractGeometry()
    outside.SetInputData(dataset)
    outside.SetImplicitFunction(holes)
    outside.ExtractInsideOff()
    outside.ExtractBoundaryCellsOff()
    tetrahedralize = vtkDataSetTriangleFilter()
    tetrahedralize.SetInputConnection(outside.GetOutputPort())
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetInputConnection(tetrahedralize.GetOutputPort())
    writer.SetFileName(os.path.join(os.path.dirname(os.path.abspath(__file__)), name))
    writer.SetDataModeToAppended()
    writer.SetCompressorTypeToZLib()
    writer.Write()
    return writer.GetFileName(), tetrahedralize.GetOutput().GetNumberOfCells()
