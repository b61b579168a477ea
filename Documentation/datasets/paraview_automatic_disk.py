"""disk_out_ref through ParaView's path with Non-Convex Mode "Automatic".

    Module/run pvbatch Documentation/datasets/paraview_automatic_disk.py [OUT.png]

The data root's disk_out_ref.ex2 (7,472 hexahedra, point array Temp) read by
ParaView, shown as "PPIRay Volume" (400 x 400, a three-quarter view), three
frames: peels, the automatic choice (0 peel, 1 convexify) and the cells
rendered natively; then the screenshot against the CPU reference renderer
(covered pixels, p99, max in 1/255).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Plugin", "Testing", "Python"))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import OpenDataFile, Render  # noqa: E402


def main():
    root = os.environ.get("PPIRAY_DATA_ROOT", "")
    reader = OpenDataFile(os.path.join(root, "disk_out_ref", "disk_out_ref.ex2"))
    reader.UpdatePipeline()
    lo, hi = reader.PointData["Temp"].GetRange()
    view = pt.render_view((400, 400))
    display = pt.show_volume(
        reader, view, "Temp",
        rgb_points=[lo, 0.1, 0.1, 0.9, (lo + hi) / 2, 0.9, 0.9, 0.2, hi, 0.9, 0.1, 0.1],
        opacity_points=[lo, 0.0, 0.5, 0.0, hi, 0.8, 0.5, 0.0], unit_distance=1.0)
    display.NonConvexMode = "Automatic"
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Azimuth(40)
    camera.Elevation(20)
    camera.Dolly(1.6)
    mapper = pt.mapper_of(display)
    for frame in range(3):
        Render(view)
        s = mapper.GetStatistics()
        print("frame %d: %d peels, choice %d, %d cells natively"
              % (frame, s.GetNumberOfPeels(), mapper.GetNonConvexChoice(),
                 s.GetNumberOfNativeCells()))
    out = sys.argv[1] if len(sys.argv) > 1 else "disk_out_ref_automatic.png"
    image = pt.screenshot(view, os.path.abspath(out))
    covered, p99, largest = pt.against_reference(view, display, image, "Temp")
    print("against the reference: %d pixels covered, p99 %.2f, max %.2f /255"
          % (covered, p99, largest))


main()  # not sys.exit(): pvbatch 5.11 tears its views down badly after it
