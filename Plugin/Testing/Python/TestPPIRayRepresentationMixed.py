"""pvbatch: a real FE mesh of hexahedra and wedges (notch/notch_stress.vtk:
2,188 hexahedra and 4 wedges) opened with ParaView's legacy reader and shown
as "PPIRay Volume" coloured by "Nodal Stress-normed": the cells reach the
mapper unsplit (the mapper's conforming split instead of
vtkDataSetTriangleFilter's, which leaves 6,766 zero-volume tetrahedra and
needs 49 peels there), in every Hexahedron Mode; a few peels; the image
matches its baseline and the reference renderer on the unsplit cells
(within the difference between the mapper's linear split and the reference's
trilinear hexahedra). Skipped (125) when the data root has no notch folder.

Usage: pvbatch TestPPIRayRepresentationMixed.py PLUGIN BASELINE_DIR TEMPORARY_DIR DATA_ROOT
"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import LegacyVTKReader, Render  # noqa: E402

ARRAY = "Nodal Stress-normed"


def main(plugin, baselines, temporary, data_root):
    path = os.path.join(data_root, "notch", "notch_stress.vtk")
    if not os.path.exists(path):
        print("SKIP: no %s" % path)
        return pt.SKIP
    pt.load_plugin(plugin)
    failures = []
    reader = LegacyVTKReader(FileNames=[path])
    reader.UpdatePipeline()
    lo, hi = reader.PointData[ARRAY].GetRange()
    b = reader.GetDataInformation().GetBounds()
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5
    rgb = [lo, 0.23, 0.30, 0.75, 0.5 * (lo + hi), 0.87, 0.87, 0.87, hi, 0.71, 0.02, 0.15]
    opacity = [lo, 0.2, 0.5, 0.0, hi, 1.0, 0.5, 0.0]
    view = pt.render_view((300, 300))
    display = pt.show_volume(reader, view, ARRAY, rgb, opacity, unit_distance=diagonal / 400.0)
    pt.set_camera(view, [c + d for c, d in zip(centre, (0.3, 0.4, 1.0))], centre, zoom=1.4)

    image = pt.screenshot(view, os.path.join(temporary, "TestPPIRayRepresentationMixed.png"))
    problem = pt.compare_with_baseline(
        image, os.path.join(baselines, "TestPPIRayRepresentationMixed.png"), temporary)
    if problem:
        failures.append(problem)
    covered, p99, largest = pt.against_reference(view, display, image, ARRAY)
    print("against the reference: %d pixels, p99 %.2f, max %.2f /255" % (covered, p99, largest),
          flush=True)
    # The mapper splits the mixed mesh into tetrahedra (a linear field in
    # each), the reference interpolates each hexahedron trilinearly: measured
    # p99 1.18, max 4.1 here; bounds 1.5 and 6.
    if covered < 10000 or p99 > 1.5 or largest > 6.0:
        failures.append("the notch differs from the reference: %d pixels, p99 %.2f, max %.2f /255"
                        % (covered, p99, largest))
    mapper = pt.mapper_of(display)
    for mode in ("Accurate", "Subdivide"):
        display.HexahedronMode = mode
        Render(view)
        start = time.time()
        Render(view)
        ms = 1000 * (time.time() - start)
        cells = mapper.GetInput().GetNumberOfCells()
        print("%s: %d input cells, %d tetrahedra, %d peels, %.0f ms per frame"
              % (mode, cells, mapper.GetStatistics().GetNumberOfTetrahedra(), mapper.GetStatistics().GetNumberOfPeels(), ms),
              flush=True)
        if cells != 2192:
            failures.append("%s: the mapper got %d cells, not the 2,192 hexahedra and wedges"
                            % (mode, cells))
        if mapper.GetStatistics().GetNumberOfPeels() > 4:
            failures.append("%s: %d peels" % (mode, mapper.GetStatistics().GetNumberOfPeels()))
    pt.finish(failures)
    return 0


if __name__ == "__main__":
    pt.run(main, __doc__, 5)
