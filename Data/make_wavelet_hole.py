"""Make Data/wavelet_hole.vtu, the demo dataset.

VTK's wavelet (vtkRTAnalyticSource, extent [-12, 12]^3, scalar "RTData")
with the voxels inside a ball of radius 7 around (3, -2, 1) removed, split into
tetrahedra (vtkDataSetTriangleFilter): a non-convex mesh with a cavity that
rays leave and re-enter (several depth peels), 71,472 tetrahedra, 0.7 MB.

Run with VTK's Python: Module/run python Data/make_wavelet_hole.py
"""
from vtkmodules.vtkCommonDataModel import vtkSphere
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource

from carve import carve_and_write

source = vtkRTAnalyticSource()
source.SetWholeExtent(-12, 12, -12, 12, -12, 12)
ball = vtkSphere()
ball.SetCenter(3.0, -2.0, 1.0)
ball.SetRadius(7.0)
source.Update()
path, tets = carve_and_write(source.GetOutput(), ball, "wavelet_hole.vtu")
print(path, tets, "tetrahedra")
