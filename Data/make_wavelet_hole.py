"""Make Data/wavelet_hole.vtu, the demo dataset.

VTK's wavelet (vtkRTAnalyticSource, extent [-12, 12]^3, scalar "RTData")
with the voxels inside a ball of radius 7 around (3, -2, 1) removed, split into
tetrahedra (vtkDataSetTriangleFilter): a non-convex mesh with a cavity that
rays leave and re-enter (several depth peels), 71,472 tetrahedra, 0.7 MB.

Run with VTK's Python: Module/run python Data/make_wavelet_hole.py
"""
import os

from vtkmodules.vtkCommonDataModel import vtkSphere
from vtkmodules.vtkFiltersExtraction import vtkExtractGeometry
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

source = vtkRTAnalyticSource()
source.SetWholeExtent(-12, 12, -12, 12, -12, 12)
ball = vtkSphere()
ball.SetCenter(3.0, -2.0, 1.0)
ball.SetRadius(7.0)
outside = vtkExtractGeometry()
outside.SetInputConnection(source.GetOutputPort())
outside.SetImplicitFunction(ball)
outside.ExtractInsideOff()
outside.ExtractBoundaryCellsOff()
tetrahedralize = vtkDataSetTriangleFilter()
tetrahedralize.SetInputConnection(outside.GetOutputPort())
writer = vtkXMLUnstructuredGridWriter()
writer.SetInputConnection(tetrahedralize.GetOutputPort())
writer.SetFileName(os.path.join(os.path.dirname(os.path.abspath(__file__)), "wavelet_hole.vtu"))
writer.SetDataModeToAppended()
writer.SetCompressorTypeToZLib()
writer.Write()
print(writer.GetFileName(), tetrahedralize.GetOutput().GetNumberOfCells(), "tetrahedra")
