"""AngularSector (7,632 hexahedra and 144 pyramids, no field: a Calculator
adds one, z x y) through ParaView's path as PPIRay Volume, the mixed mesh
marched natively (Hexahedron Mode Accurate) and split into tetrahedra
(Subdivide); prints the cells each path rendered, the lit pixels and the
difference between the two images. Writes the screenshots into the folder
named on the command line.

Run: Module/run pvbatch Documentation/datasets/paraview_mixed_native.py OUTDIR
"""
import os
import sys

import numpy as np
from paraview.simple import (Calculator, CreateView, GetColorTransferFunction, LegacyVTKReader,
                             Render, SaveScreenshot, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

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
out = sys.argv[1]
images = {}
for mode in ("Accurate", "Subdivide"):
    display.HexahedronMode = mode
    Render(view)
    path = os.path.join(out, "angularsector_%s.png" % mode)
    SaveScreenshot(path, view)
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    images[mode] = vtk_to_numpy(png.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)
    import ppiray  # noqa: F401  (the mapper's Python class, for its counters)
    mapper = display.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper()
    print(mode, "native cells", mapper.GetStatistics().GetNumberOfNativeCells(), "tetrahedra",
          mapper.GetStatistics().GetNumberOfTetrahedra(), "lit pixels", int((images[mode].max(axis=1) > 0).sum()))
diff = np.abs(images["Accurate"] - images["Subdivide"])
print("native against split: max %.0f, p99 %.1f, pixels > 8: %d"
      % (diff.max(), np.percentile(diff, 99), int((diff.max(axis=1) > 8).sum())))
