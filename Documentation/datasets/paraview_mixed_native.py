"""AngularSector (7,632 hexahedra and 144 pyramids, no field: a Calculator
adds one, z x y) through ParaView's path as PPIRay Volume, the mixed mesh
marched natively (Hexahedron Mode Accurate) and split into tetrahedra
(Subdivide); prints the cells each path rendered, its peels, the lit
pixels, each image against the CPU reference renderer (ppiray_pvtest's
against_reference: ParaView's own lookup table and opacity function) and the
difference between the two images. Writes the screenshots into the folder
named on the command line.

Run: Module/run pvbatch Documentation/datasets/paraview_mixed_native.py OUTDIR
"""
import os
import sys

from paraview.simple import (Calculator, CreateView, GetColorTransferFunction, LegacyVTKReader,
                             Show)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Plugin",
                                "Testing", "Python"))
from ppiray_pvtest import native_and_split  # noqa: E402

root = os.environ.get("PPIRAY_DATA_ROOT", "../shared/data")
reader = LegacyVTKReader(FileNames=[os.path.join(root, "angularsector", "AngularSector.vtk")])
field = Calculator(Input=reader, ResultArrayName="zy", Function="coordsZ * coordsY")
view = CreateView("RenderView")
view.ViewSize = [400, 400]
view.Background = [0, 0, 0]
view.UseColorPaletteForBackground = 0
display = Show(field, view)
display.SetRepresentationType("PPIRay Volume")
display.ColorArrayName = ["POINTS", "zy"]
display.RescaleTransferFunctionToDataRange(True, False)
view.ResetCamera()
view.CameraPosition = [2.0, -1.5, 1.2]
view.CameraFocalPoint = [0, 0, 0]
view.ResetCamera()
native_and_split(view, display, sys.argv[1], "angularsector", "zy", background=[0, 0, 0])
