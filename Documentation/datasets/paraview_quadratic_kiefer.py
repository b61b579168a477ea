"""The Kiefer bracket's quadratic tetrahedra through ParaView's path.

    Module/run pvbatch Documentation/datasets/paraview_quadratic_kiefer.py [OUT.png]

The data root's fea_kiefer_bracket/dataset.vtu (56,786 ten-node tetrahedra,
many with curved edges) read by ParaView, a point field made by a
Calculator over every node (a smooth function of the coordinates, so the
mid-edge nodes carry values the corners alone do not give; a
PythonCalculator: the Calculator's parser has no coordinates here), shown as
"PPIRay Volume" (300 x 300): the cells the mapper marched (refined pieces)
and the screenshot against the CPU reference renderer, which integrates
each cell through vtkQuadraticTetra (covered pixels, p99, max in 1/255).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Plugin", "Testing", "Python"))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import OpenDataFile, PythonCalculator, Render  # noqa: E402


def main():
    root = os.environ.get("PPIRAY_DATA_ROOT", "")
    reader = OpenDataFile(os.path.join(root, "fea_kiefer_bracket", "dataset.vtu"))
    reader.UpdatePipeline()
    b = reader.GetDataInformation().GetBounds()
    scale = [6.0 / max(b[2 * i + 1] - b[2 * i], 1e-30) for i in range(3)]
    field = PythonCalculator(Input=reader)
    field.ArrayName = "wave"
    x = "inputs[0].Points[:, %d]"
    field.Expression = ("sin(%.6f * (%s - %.6f)) * cos(%.6f * (%s - %.6f)) + %.6f * (%s - %.6f)"
                        % (scale[0], x % 0, b[0], scale[1], x % 1, b[2], scale[2] / 6.0,
                           x % 2, b[4]))
    field.UpdatePipeline()
    lo, hi = field.PointData["wave"].GetRange()
    view = pt.render_view((300, 300))
    display = pt.show_volume(
        field, view, "wave",
        rgb_points=[lo, 0.1, 0.1, 0.9, (lo + hi) / 2, 0.9, 0.9, 0.2, hi, 0.9, 0.1, 0.1],
        opacity_points=[lo, 0.0, 0.5, 0.0, hi, 0.8, 0.5, 0.0],
        unit_distance=0.05 * max(b[1] - b[0], b[3] - b[2], b[5] - b[4]))
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Azimuth(30)
    camera.Elevation(25)
    Render(view)
    Render(view)
    mapper = pt.mapper_of(display)
    s = mapper.GetStatistics()
    print("mapper input: %d cells" % mapper.GetInput().GetNumberOfCells())
    print("%d cells marched natively, %d peels, %.0f GPU bytes per cell"
          % (s.GetNumberOfNativeCells(), s.GetNumberOfPeels(), s.GetBytesPerCell()))
    out = sys.argv[1] if len(sys.argv) > 1 else "kiefer_quadratic.png"
    image = pt.screenshot(view, os.path.abspath(out))
    covered, p99, largest = pt.against_reference(view, display, image, "wave")
    print("against the reference: %d pixels covered, p99 %.2f, max %.2f /255"
          % (covered, p99, largest))


main()  # not sys.exit(): pvbatch 5.11 tears its views down badly after it
