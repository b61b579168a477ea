"""pvbatch: a time series stepped through "PPIRay Volume" with ParaView's
animation scene.

Three series of four steps, each a .pvd of .vtu files read back by ParaView's
reader (new arrays at every step, as from any reader): the same mesh at
every step, the field moving (s = sin(3x + 0.4 k) cos(2y) + z^2, step k):
 1. 2,880 tetrahedra (ParaView's usual path: its preprocessor hands the
    mapper a new grid at every step);
 2. 512 hexahedra, rendered natively (passed unsplit);
 3. the tetrahedra of 1. deforming: the same cells, the points twisted about
    z by 0.25 k z radians at step k, the field moving with them.
At every step of 1. and 2.: the geometry was built and uploaded once for the whole series
(the mapper recognized the points and cells: GetGeometryReuseCount() grows
by one per step), the field once per step (counted from the first step: the
view's first render and the first step's may each read the data). In 3.
the geometry is built again at every step with its faces' pairs kept (the
preparation's stages name "folds", not "adjacency"). At every step, the screenshot against
the CPU reference renderer of that step's grid: p99 at most 1/255 and max
at most 2/255 over the covered pixels (the 8-bit rounding of the screenshot
and of the background blend, 0.5 each), at least a quarter of the view
covered; and each step's image differs from the one before (the field
moved). The representation reports the mapper's progress while it builds
the cells (ProgressEvent, for ParaView's progress bar): up to the first
step, six values or more strictly between 0 and 1 (the build's stages;
the pipeline itself reports only 0 and 1); at later steps none, but in 3.

Usage: pvbatch TestPPIRayTimeSeries.py PLUGIN TEMPORARY_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import GetAnimationScene, OpenDataFile, Render  # noqa: E402

SIZE = (200, 180)
STEPS = 4
RGB = [-1.0, 0.1, 0.1, 0.8, 0.5, 0.9, 0.9, 0.2, 2.0, 0.9, 0.1, 0.1]
OPACITY = [-1.0, 0.0, 0.5, 0.0, 2.0, 0.6, 0.5, 0.0]


def write_series(folder, hexahedra, deforming=False):
    """The series as step<k>.vtu files and a .pvd naming them; its path."""
    import math
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkCommonDataModel import vtkImageData, vtkUnstructuredGrid
    from vtkmodules.vtkFiltersCore import vtkAppendFilter
    from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
    image = vtkImageData()
    image.SetDimensions(9, 9, 9)
    image.SetOrigin(-1.0, -1.0, -1.0)
    image.SetSpacing(0.25, 0.25, 0.25)
    if hexahedra:
        cells = vtkAppendFilter()
    else:
        cells = vtkDataSetTriangleFilter()
    cells.SetInputData(image)
    cells.Update()
    grid = cells.GetOutput()
    grids = []
    material = [grid.GetPoint(p) for p in range(grid.GetNumberOfPoints())]
    for k in range(STEPS):
        if deforming:
            points = grid.GetPoints()
            for p, (x, y, z) in enumerate(material):
                a = 0.25 * k * z
                points.SetPoint(p, x * math.cos(a) - y * math.sin(a),
                                x * math.sin(a) + y * math.cos(a), z)
            points.Modified()
        values = vtkDoubleArray()
        values.SetName("s")
        for p in range(grid.GetNumberOfPoints()):
            x, y, z = material[p]
            values.InsertNextValue(math.sin(3.0 * x + 0.4 * k) * math.cos(2.0 * y) + z * z)
        grid.GetPointData().SetScalars(values)
        step = vtkUnstructuredGrid()
        step.DeepCopy(grid)
        grids.append(step)
    path = pt.write_pvd(folder, grids)
    return path, grid.GetNumberOfCells()


def stage_names(statistics):
    return [statistics.GetPreparationStageName(i)
            for i in range(statistics.GetNumberOfPreparationStages())]


def step_through(path, cells, label, temporary, failures, deforming=False):
    import numpy as np
    reader = OpenDataFile(path)
    view = pt.render_view(SIZE)
    display = pt.show_volume(reader, view, "s", rgb_points=RGB, opacity_points=OPACITY,
                             unit_distance=0.5)
    progress = []
    representation = display.GetClientSideObject().GetActiveRepresentation()
    built = []  # the stages of each build, read when its progress reaches 1

    def on_progress(caller, event):
        progress.append(caller.GetProgress())
        if progress[-1] == 1.0 and len(progress) > 2:
            built.append(stage_names(pt.mapper_of(display).GetStatistics()))
    representation.AddObserver("ProgressEvent", on_progress)
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    pt.set_camera(view, (2.5, -1.8, 2.0))
    previous = first = None
    for k in range(STEPS):
        scene.AnimationTime = float(k)
        Render(view)
        names = sum(built, [])
        built.clear()
        stages = sorted(set(v for v in progress if 0.0 < v < 1.0))
        print("%s step %d: progress between 0 and 1: %s"
              % (label, k, " ".join("%.2f" % v for v in stages)))
        rebuilds = deforming and k > 0
        if (k == 0 and (len(stages) < 6 or 1.0 not in progress)) or (k > 0 and stages and
                                                                       not rebuilds):
            failures.append("%s step %d: progress %s" % (label, k, progress))
        progress.clear()
        mapper = pt.mapper_of(display)
        s = mapper.GetStatistics()
        counts = (s.GetGeometryUploadCount(), s.GetFieldUploadCount(), s.GetGeometryReuseCount())
        image = pt.screenshot(view, os.path.join(temporary, "TestPPIRayTimeSeries%s%d.png"
                                                 % (label, k)))
        covered, p99, largest = pt.against_reference(view, display, image, "s")
        rendered = s.GetNumberOfTetrahedra() + s.GetNumberOfNativeCells()
        print("%s step %d: %d cells rendered; geometry uploads %d, field uploads %d, geometry "
              "reused %d; %d pixels covered, p99 %.2f, max %.2f /255 against the reference"
              % ((label, k, rendered) + counts + (covered, p99, largest)))
        first = first or counts
        expected = ((first[0] + k, first[1] + k, first[2]) if deforming
                    else (1, first[1] + k, first[2] + k))
        if rebuilds and (names.count("folds") != 1 or "adjacency" in names):
            failures.append("%s step %d: stages %s, expected the faces' pairs kept (folds)"
                            % (label, k, names))
        if counts != expected:
            failures.append("%s step %d: uploads and reuses %s, expected %s"
                            % (label, k, counts, expected))
        if covered < SIZE[0] * SIZE[1] // 4 or p99 > 1.0 or largest > 2.0:
            failures.append("%s step %d: %d pixels covered, p99 %.2f, max %.2f"
                            % (label, k, covered, p99, largest))
        rgb = pt.read_rgb(image).astype(np.float64)
        if previous is not None and np.abs(rgb - previous).max() < 10:
            failures.append("%s step %d: the image did not change" % (label, k))
        previous = rgb
    if label == "Hexahedra" and s.GetNumberOfNativeCells() != cells:
        failures.append("hexahedra not rendered natively (%d native cells of %d)"
                        % (s.GetNumberOfNativeCells(), cells))


def main(plugin, temporary):
    pt.load_plugin(plugin)
    failures = []
    for label, hexahedra, deforming in (("Tetrahedra", False, False), ("Hexahedra", True, False),
                                        ("Deforming", False, True)):
        path, cells = write_series(os.path.join(temporary, "TestPPIRayTimeSeries" + label),
                                   hexahedra, deforming)
        step_through(path, cells, label, temporary, failures, deforming)
    pt.finish(failures)
    return 0


if __name__ == "__main__":
    pt.run(main, __doc__, 3)
