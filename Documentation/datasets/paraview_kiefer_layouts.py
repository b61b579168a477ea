"""The Kiefer bracket (quadratic tetrahedra, von Mises stress as cell data)
through ParaView's path, PPIRay Volume in both tetrahedron layouts (Planes,
Compact), with ParaView's default map and with 40 random colour nodes in the
Lab/CIEDE2000 space (thousands of control points, which cell data jumps
across at every face); prints the lit pixels and the difference between the
layouts. Writes the four screenshots into the folder named on the command line.

Run: Module/run pvbatch Documentation/datasets/paraview_kiefer_layouts.py OUTDIR
"""
import os, sys, glob
import numpy as np
from paraview.simple import *

root = os.environ.get("PPIRAY_DATA_ROOT", "../shared/data")
f = glob.glob(os.path.join(root, "fea_kiefer_bracket", "*.vtu"))[0]
r = XMLUnstructuredGridReader(FileName=[f])
view = CreateView("RenderView"); view.ViewSize = [400, 320]; view.Background = [0, 0, 0]
view.UseColorPaletteForBackground = 0
d = Show(r, view)
d.SetRepresentationType("PPIRay Volume")
name = r.CellData.keys()[0]
ColorBy(d, ("CELLS", name))
d.RescaleTransferFunctionToDataRange(True, False)
view.ResetCamera(); view.CameraPosition = [1, 0.7, 1.3]; view.CameraFocalPoint = [0, 0, 0]; view.ResetCamera()
out = sys.argv[1]
images = {}
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy
def grab(tag):
    Render(view)
    path = os.path.join(out, tag + ".png")
    SaveScreenshot(path, view)
    rd = vtkPNGReader(); rd.SetFileName(path); rd.Update()
    a = vtk_to_numpy(rd.GetOutput().GetPointData().GetScalars()).astype(float)
    images[tag] = a
    print(tag, "lit pixels", int((a[:, :3].max(axis=1) > 0).sum()))
for layout in ("Planes", "Compact"):
    d.TetrahedronLayout = layout
    grab("default_" + layout)
lut = GetColorTransferFunction(name)
lo, hi = r.CellData[name].GetRange()
rng = np.random.default_rng(5)
pts = []
for x in np.linspace(lo, hi, 40):
    pts += [x] + list(rng.uniform(0, 1, 3))
lut.RGBPoints = pts
lut.ColorSpace = "Lab/CIEDE2000"
for layout in ("Planes", "Compact"):
    d.TetrahedronLayout = layout
    grab("ciede_" + layout)
for k in ("default", "ciede"):
    diff = np.abs(images[k + "_Planes"] - images[k + "_Compact"])[:, :3]
    print(k, "planes vs compact: max %.0f, p99 %.1f, pixels > 8: %d" % (diff.max(), np.percentile(diff, 99), int((diff.max(axis=1) > 8).sum())))
