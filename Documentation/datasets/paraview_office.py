"""The office (a room of air, 7,220 hexahedra) through ParaView's path: PPIRay Volume
coloured by its scalars with ParaView's defaults, the camera inside the room, composite
and Maximum Intensity, and MIP from outside. Writes office_inside.png,
office_inside_mip.png, office_outside_mip.png into OUT.

Run: Module/run pvbatch Documentation/datasets/paraview_office.py OUT
"""
import os
import sys
from paraview.simple import *
out = sys.argv[1]
r = LegacyVTKReader(FileNames=[os.path.join(os.environ.get("PPIRAY_DATA_ROOT", "../shared/data"), "office", "office.binary.vtk")])
view = CreateView("RenderView"); view.ViewSize = [400, 300]; view.Background = [0, 0, 0]
try:
    view.UseColorPaletteForBackground = 0
except Exception:
    pass
d = Show(r, view)
d.SetRepresentationType("PPIRay Volume")
ColorBy(d, ("POINTS", "scalars"))
d.RescaleTransferFunctionToDataRange(True, False)
b = r.GetDataInformation().GetBounds()
print("bounds", b)
# inside the room, looking along +y
cx, cz = 0.5 * (b[0] + b[1]), 0.5 * (b[4] + b[5])
view.CameraPosition = [cx, b[2] + 0.1 * (b[3] - b[2]), cz]
view.CameraFocalPoint = [cx, b[3], cz]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 70
Render(view)
SaveScreenshot(out + "/office_inside.png", view, ImageResolution=[400, 300])
d.PPIRayBlendMode = "Maximum Intensity"
Render(view)
SaveScreenshot(out + "/office_inside_mip.png", view, ImageResolution=[400, 300])
view.CameraPosition = [b[1] + 2 * (b[1] - b[0]), b[2] - 1.5 * (b[3] - b[2]), b[5] + (b[5] - b[4])]
view.CameraFocalPoint = [cx, 0.5 * (b[2] + b[3]), cz]
view.ResetCamera()
Render(view)
SaveScreenshot(out + "/office_outside_mip.png", view, ImageResolution=[400, 300])
print("done")
