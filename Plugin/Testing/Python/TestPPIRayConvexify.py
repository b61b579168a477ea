"""pvbatch: the PPIRayConvexify plugin (GPL) and PPIRay Volume's Non-Convex Mode.

On Data/graded_holes.vtu (a carved wavelet that needs several peels):
- shown as PPIRay Volume (Peel): more than one peel; against the CPU
  reference p99 <= 1, max <= 2 (1/255 units, every covered pixel);
- Non-Convex Mode = Convexify (the plugin registers the filter with VTK's
  object factory): one peel, the same image (every channel within 1/255);
- the "PPIRay Convexify" filter, its output shown as PPIRay Volume (Peel):
  more cells than the input, hidden imaginary cells, one peel, the same image.

Usage: pvbatch TestPPIRayConvexify.py PLUGIN CONVEXIFY_PLUGIN TEMPORARY DATA
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import Hide, XMLUnstructuredGridReader  # noqa: E402


def main(plugin, convexify_plugin, temporary, data):
    pt.load_plugin(plugin)
    pt.load_plugin(convexify_plugin)
    # LoadPlugin defines the plugin's filters in the namespace it is given
    # (ppiray_pvtest's).
    PPIRayConvexify = getattr(pt, "PPIRayConvexify")
    import numpy as np

    reader = XMLUnstructuredGridReader(FileName=[os.path.join(data, "graded_holes.vtu")])
    view = pt.render_view((200, 200))
    rgb = [-0.5, 0.23, 0.30, 0.75, 0.5, 0.87, 0.87, 0.87, 1.49, 0.71, 0.02, 0.15]
    opacity = [-0.5, 0.0, 0.5, 0.0, 1.49, 0.6, 0.5, 0.0]
    display = pt.show_volume(reader, view, "s", rgb, opacity, unit_distance=0.1)
    pt.set_camera(view, (1.0, 0.6, 1.4), (0.866, 0.866, 0.866))
    failures = []

    def shot(name):
        path = pt.screenshot(view, os.path.join(temporary, "TestPPIRayConvexify_%s.png" % name))
        return pt.read_rgb(path).astype(int)

    peeled = shot("peeled")
    peels = pt.mapper_of(display).GetStatistics().GetNumberOfPeels()
    covered, p99, largest = pt.against_reference(
        view, display, os.path.join(temporary, "TestPPIRayConvexify_peeled.png"), "s")
    print("peeled: %d peels, %d pixels against the reference: p99 %.2f, max %.2f"
          % (peels, covered, p99, largest))
    if peels < 2:
        failures.append("the scene needs %d peel(s), expected several" % peels)
    if covered < 4000 or p99 > 1.0 or largest > 2.0:
        failures.append("peeled image against the reference")

    display.NonConvexMode = "Convexify"
    by_mode = shot("mode")
    mapper = pt.mapper_of(display)
    made = mapper.GetConvexifier()
    print("Non-Convex Mode = Convexify: %d peels, convexifier %s, max difference %d"
          % (mapper.GetStatistics().GetNumberOfPeels(), made.GetClassName() if made else None,
             np.abs(by_mode - peeled).max()))
    if made is None or mapper.GetStatistics().GetNumberOfPeels() != 1:
        failures.append("Non-Convex Mode = Convexify did not render in one peel")
    if np.abs(by_mode - peeled).max() > 1:
        failures.append("Non-Convex Mode = Convexify changed the image")

    convexified = PPIRayConvexify(Input=reader)
    convexified.UpdatePipeline()
    cells_in = reader.GetDataInformation().GetNumberOfCells()
    cells_out = convexified.GetDataInformation().GetNumberOfCells()
    hidden = convexified.CellData.GetArray("vtkGhostType")
    Hide(reader, view)
    filtered = pt.show_volume(convexified, view, "s", rgb, opacity, unit_distance=0.1)
    by_filter = shot("filter")
    filter_peels = pt.mapper_of(filtered).GetStatistics().GetNumberOfPeels()
    got = pt.mapper_of(filtered).GetInput()
    print("PPIRay Convexify: %d -> %d cells, vtkGhostType %s, %d peels, max difference %d"
          % (cells_in, cells_out, hidden.GetRange() if hidden else None, filter_peels,
             np.abs(by_filter - peeled).max()))
    if cells_out <= cells_in or hidden is None or filter_peels != 1:
        failures.append("the filter's output is not a convexified grid rendering in one peel")
    if np.abs(by_filter - peeled).max() > 1:
        failures.append("the filter's output renders differently")
    pt.finish(failures)


pt.run(main, __doc__, 5)
