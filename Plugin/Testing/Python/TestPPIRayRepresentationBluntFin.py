"""pvbatch: Blunt Fin (NASA, PLOT3D) opened with ParaView's PLOT3D reader,
a multiblock of one curvilinear grid, shown as "PPIRay Volume" coloured by
Density: by default its 37,479 hexahedra reach the mapper as they are
(Hexahedron Mode "Accurate", rendered natively); with "Subdivide" the
representation's preprocessor tetrahedralizes them. Each compared with its
baseline. Skipped (125) when the data root has no bluntfin folder.

Usage: pvbatch TestPPIRayRepresentationBluntFin.py PLUGIN BASELINE_DIR TEMPORARY_DIR DATA_ROOT
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import PLOT3DReader  # noqa: E402

# ParaView's volume preprocessor splits each of the 37,479 hexahedra into 6
# tetrahedra (224,874); the mapper drops the 116 that are flat (collapsed
# cells at the fin).
EXPECTED_TETRAHEDRA = 224758


def main(plugin, baselines, temporary, data_root):
    folder = os.path.join(data_root, "bluntfin")
    if not os.path.isdir(folder):
        print("SKIP: no %s" % folder)
        return pt.SKIP
    pt.load_plugin(plugin)
    failures = []

    reader = PLOT3DReader(FileName=os.path.join(folder, "bluntfinxyz.bin"),
                          QFileName=[os.path.join(folder, "bluntfinq.bin")])
    reader.UpdatePipeline()
    lo, hi = reader.PointData["Density"].GetRange()
    b = reader.GetDataInformation().GetBounds()
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5
    # Cool-warm colours over the range; opacity only above the free-stream
    # density (~0.9, the median): the compressed air ahead of the fin and
    # along the plate.
    rgb = [lo, 0.23, 0.30, 0.75, 0.5 * (lo + hi), 0.87, 0.87, 0.87, hi, 0.71, 0.02, 0.15]
    opacity = [lo, 0.0, 0.5, 0.0, 0.9, 0.0, 0.5, 0.0, 1.3, 0.15, 0.5, 0.0,
               3.2, 0.5, 0.5, 0.0, hi, 0.8, 0.5, 0.0]
    view = pt.render_view((400, 300))
    display = pt.show_volume(reader, view, "Density", rgb, opacity, unit_distance=diagonal / 20.0)
    if display.GetXMLName() != "StructuredGridRepresentation":
        failures.append("PLOT3D output shown as %s" % display.GetXMLName())
    pt.set_camera(view, [c + d for c, d in zip(centre, (1.0, 0.7, 1.3))], centre, zoom=1.3)

    def check_image(name):
        image = pt.screenshot(view, os.path.join(temporary, name + ".png"))
        problem = pt.compare_with_baseline(image, os.path.join(baselines, name + ".png"), temporary)
        if problem:
            failures.append(problem)

    check_image("TestPPIRayRepresentationBluntFin")
    mapper = pt.mapper_of(display)
    if mapper.GetStatistics().GetNumberOfHexahedra() != 37479 or mapper.GetStatistics().GetNumberOfTetrahedra() != 0:
        failures.append("natively: %d hexahedra, %d tetrahedra, expected 37479 and 0"
                        % (mapper.GetStatistics().GetNumberOfHexahedra(), mapper.GetStatistics().GetNumberOfTetrahedra()))

    display.HexahedronMode = "Subdivide"
    check_image("TestPPIRayRepresentationBluntFinSubdivide")
    if mapper.GetStatistics().GetNumberOfTetrahedra() != EXPECTED_TETRAHEDRA or mapper.GetStatistics().GetNumberOfHexahedra():
        failures.append("Subdivide: %d tetrahedra, %d hexahedra, expected %d and 0"
                        % (mapper.GetStatistics().GetNumberOfTetrahedra(), mapper.GetStatistics().GetNumberOfHexahedra(),
                           EXPECTED_TETRAHEDRA))
    pt.finish(failures)
    return 0


if __name__ == "__main__":
    pt.run(main, __doc__, 5)
