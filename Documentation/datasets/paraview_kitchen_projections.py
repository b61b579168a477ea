"""The kitchen (9,936 curvilinear hexahedra of room air) through ParaView's path:
ExodusII-free legacy reader, PPIRay Volume coloured by c1 with ParaView's defaults,
PPIRay Blend Mode "Average Intensity" and "Additive" from outside. Writes
kitchen_average.png, kitchen_additive.png into OUT and prints how many pixels
each lights.

Run: Module/run pvbatch Documentation/datasets/paraview_kitchen_projections.py OUT
"""
import os
import sys
from paraview.simple import ColorBy, CreateView, LegacyVTKReader, Render, SaveScreenshot, Show
out = sys.argv[1]
os.makedirs(out, exist_ok=True)
r = LegacyVTKReader(FileNames=[os.path.join(os.environ.get("PPIRAY_DATA_ROOT", "../shared/data"),
                                            "kitchen", "kitchen.vtk")])
view = CreateView("RenderView")
view.ViewSize = [400, 300]
view.Background = [0, 0, 0]
try:
    view.UseColorPaletteForBackground = 0
except Exception:
    pass
d = Show(r, view)
d.SetRepresentationType("PPIRay Volume")
ColorBy(d, ("POINTS", "c1"))
d.RescaleTransferFunctionToDataRange(True, False)
Render(view)
view.CameraPosition = [-1.0, -2.5, 2.5]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera()
for mode, name in (("Average Intensity", "kitchen_average.png"), ("Additive", "kitchen_additive.png")):
    d.PPIRayBlendMode = mode
    Render(view)
    path = os.path.join(out, name)
    SaveScreenshot(path, view, ImageResolution=[400, 300])
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    rgb = vtk_to_numpy(png.GetOutput().GetPointData().GetScalars())[:, :3]
    print("%s: %d pixels lit, brightest %d" % (mode, int((rgb.max(axis=1) > 0).sum()), rgb.max()))
