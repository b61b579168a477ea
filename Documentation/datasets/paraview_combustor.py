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

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Plugin",
                                "Testing", "Python"))
from ppiray_pvtest import combustor_view, native_and_split  # noqa: E402

view, display = combustor_view()
focal = list(view.CameraFocalPoint)
view.CameraPosition = [focal[0] + 20, focal[1] - 25, focal[2] + 30]
view.ResetCamera()
native_and_split(view, display, sys.argv[1], "combustor", "Density", background=[0, 0, 0])
