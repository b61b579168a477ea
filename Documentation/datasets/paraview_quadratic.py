"""A mesh of quadratic cells through ParaView's path, against the reference.

    Module/run pvbatch Documentation/datasets/paraview_quadratic.py \
        [FILE (under the data root)] [POINT ARRAY] [OUT.png]

Default: the data root's quadratic/CylinderQuadratic.vtk (1,522 ten-node
tetrahedra, the flow past a cylinder's "pressure"), opened with
OpenDataFile and shown as "PPIRay Volume" (300 x 300, a three-quarter
view): the cells the mapper marched and the screenshot against the CPU
reference renderer, which integrates each cell through VTK's own
interpolation (covered pixels, p99, max in 1/255). The Kiefer bracket with a
field over every node is TestPPIRayRepresentationQuadratic.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Plugin", "Testing", "Python"))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import OpenDataFile, Render  # noqa: E402


def main():
    args = sys.argv[1:] + [None] * 3
    path = os.path.join(os.environ.get("PPIRAY_DATA_ROOT", ""),
                        args[0] or os.path.join("quadratic", "CylinderQuadratic.vtk"))
    array = args[1] or "pressure"
    reader = OpenDataFile(path)
    reader.UpdatePipeline()
    lo, hi = reader.PointData[array].GetRange()
    b = reader.GetDataInformation().GetBounds()
    view = pt.render_view((300, 300))
    display = pt.show_volume(
        reader, view, array,
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
    print("mapper input: %d cells; %d marched natively, %d tetrahedra, %d peels"
          % (mapper.GetInput().GetNumberOfCells(), s.GetNumberOfNativeCells(),
             s.GetNumberOfTetrahedra(), s.GetNumberOfPeels()))
    image = pt.screenshot(view, os.path.abspath(args[2] or "quadratic.png"))
    covered, p99, largest = pt.against_reference(view, display, image, array)
    print("against the reference: %d pixels covered, p99 %.2f, max %.2f /255"
          % (covered, p99, largest))


main()  # not sys.exit(): pvbatch 5.11 tears its views down badly after it
