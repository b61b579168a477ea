"""The Kiefer bracket (56,786 quadratic tetrahedra, von Mises stress as cell data)
through ParaView's path: PPIRay Volume coloured by its cell array with ParaView's
defaults, a three-quarter view. Writes the screenshot named on the command line.

Run: Module/run pvbatch Documentation/datasets/paraview_kiefer.py OUT.png
"""
import os, sys, glob
from paraview.simple import *
root = os.environ.get("PPIRAY_DATA_ROOT", "../shared/data")
f = glob.glob(os.path.join(root, "fea_kiefer_bracket", "*.vtu"))[0]
r = XMLUnstructuredGridReader(FileName=[f])
view = CreateView("RenderView"); view.ViewSize = [500, 400]; view.Background = [0, 0, 0]
try:
    view.UseColorPaletteForBackground = 0
except Exception:
    pass
d = Show(r, view)
d.SetRepresentationType("PPIRay Volume")
arrays = r.CellData.keys() + r.PointData.keys()
print("arrays", r.PointData.keys(), r.CellData.keys())
assoc = "CELLS" if r.CellData.keys() else "POINTS"
ColorBy(d, (assoc, arrays[0]))
d.RescaleTransferFunctionToDataRange(True, False)
view.ResetCamera(); view.CameraPosition = [1, 0.7, 1.3]; view.CameraFocalPoint = [0, 0, 0]; view.ResetCamera()
Render(view)
SaveScreenshot(sys.argv[1], view)
print("saved")
