"""VTK's combustor (PLOT3D, 43,008 curvilinear hexahedra, Density at the
points) through ParaView's path as PPIRay Volume: the PLOT3D reader, Merge
Blocks, the hexahedra marched natively (Hexahedron Mode Accurate) and split
into tetrahedra (Subdivide); prints the cells each path rendered, its peels,
the lit pixels, each image against the CPU reference renderer (ppiray_pvtest's
against_reference: covered pixels, p99, max) and the difference between the
two images. Writes the screenshots into the folder named on the command line.

Run: Module/run pvbatch Documentation/datasets/paraview_combustor.py OUTDIR
"""
import os
import sys

import numpy as np
from paraview.simple import (CreateView, MergeBlocks, PLOT3DReader, Render, SaveScreenshot,
                             Show)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Plugin",
                                "Testing", "Python"))
from ppiray_pvtest import against_reference  # noqa: E402

root = os.environ.get("PPIRAY_DATA_ROOT", "../shared/data")
reader = PLOT3DReader(FileName=os.path.join(root, "combustor", "combxyz.bin"),
                      QFileName=[os.path.join(root, "combustor", "combq.bin")])
reader.Functions = []
merged = MergeBlocks(Input=reader)
view = CreateView("RenderView")
view.ViewSize = [400, 400]
view.Background = [0, 0, 0]
view.UseColorPaletteForBackground = 0
display = Show(merged, view)
display.SetRepresentationType("PPIRay Volume")
display.ColorArrayName = ["POINTS", "Density"]
display.RescaleTransferFunctionToDataRange(True, False)
view.ResetCamera()
focal = list(view.CameraFocalPoint)
view.CameraPosition = [focal[0] + 20, focal[1] - 25, focal[2] + 30]
view.ResetCamera()
out = sys.argv[1]
images = {}
for mode in ("Accurate", "Subdivide"):
    display.HexahedronMode = mode
    Render(view)
    path = os.path.join(out, "combustor_%s.png" % mode)
    SaveScreenshot(path, view)
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    images[mode] = vtk_to_numpy(png.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)
    import ppiray  # noqa: F401  (the mapper's Python class, for its counters)
    mapper = display.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper()
    print(mode, "native cells", mapper.GetStatistics().GetNumberOfNativeCells(), "tetrahedra",
          mapper.GetStatistics().GetNumberOfTetrahedra(), "peels",
          mapper.GetStatistics().GetNumberOfPeels(), "lit pixels",
          int((images[mode].max(axis=1) > 0).sum()), "against the reference (covered, p99, max)",
          against_reference(view, display, path, "Density", background=[0, 0, 0]))
diff = np.abs(images["Accurate"] - images["Subdivide"])
print("native against split: max %.0f, p99 %.1f, pixels > 8: %d"
      % (diff.max(), np.percentile(diff, 99), int((diff.max(axis=1) > 8).sum())))
