"""Module/run pvbatch Plugin/Testing/Python/ppiray_pvbench_time_series.py [--steps N] [--points P] [--size S]

What stepping a time series through "PPIRay Volume" costs in ParaView:
each series is a .pvd of .vtu files (written to a temporary folder, read
back by ParaView's reader) stepped with the animation scene, in pvbatch:
  fixed     the cube [-1, 1]^3 on a P^3 point lattice split into tetrahedra
            (vtkDataSetTriangleFilter), the same at every step, the field
            moving (s = sin(3x + 0.4 k) cos(2y) + z^2, step k);
  can       the data root's crushed can (can/can.vtu) deforming: its points
            the undeformed ones (points - DISPL) plus k / (N - 1) DISPL at
            step k, split into tetrahedra, the field |DISPL| (carried along).
Per step: wall milliseconds of setting the scene's time (ParaView reads the
step, updates the representation and renders), the mapper's CPU
preparation in that render, its geometry and field upload counts, the preparation's stage that matched the faces ("adjacency", or
"folds" where a deforming mesh kept them), and the screenshot against the
CPU reference renderer of that step's grid (p99 and max over the covered
pixels, 1/255). A steady frame (the camera turned by 1 degree, median of 3)
is the yardstick. A benchmark, not a test: its numbers go in
Documentation/results.md with the command that made them.
"""
import argparse
import math
import os
import statistics
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import GetAnimationScene, OpenDataFile, Render  # noqa: E402


def fixed_series(points, steps):
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkCommonDataModel import vtkImageData, vtkUnstructuredGrid
    from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
    image = vtkImageData()
    image.SetDimensions(points, points, points)
    image.SetOrigin(-1.0, -1.0, -1.0)
    spacing = 2.0 / (points - 1)
    image.SetSpacing(spacing, spacing, spacing)
    split = vtkDataSetTriangleFilter()
    split.SetInputData(image)
    split.Update()
    grids = []
    for k in range(steps):
        grid = vtkUnstructuredGrid()
        grid.ShallowCopy(split.GetOutput())
        values = vtkDoubleArray()
        values.SetName("s")
        for p in range(grid.GetNumberOfPoints()):
            x, y, z = grid.GetPoint(p)
            values.InsertNextValue(math.sin(3.0 * x + 0.4 * k) * math.cos(2.0 * y) + z * z)
        grid.GetPointData().SetScalars(values)
        grids.append(grid)
    return grids


def can_series(steps):
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
    from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    root = os.environ.get("PPIRAY_DATA_ROOT", "")
    path = os.path.join(root, "can", "can.vtu")
    if not os.path.exists(path):
        print("no data root (PPIRAY_DATA_ROOT): the can series is left out")
        return []
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    split = vtkDataSetTriangleFilter()
    split.SetInputData(reader.GetOutput())
    split.Update()
    crushed = split.GetOutput()
    displacement = vtk_to_numpy(crushed.GetPointData().GetArray("DISPL")).astype(np.float64)
    undeformed = vtk_to_numpy(crushed.GetPoints().GetData()).astype(np.float64) - displacement
    grids = []
    for k in range(steps):
        t = k / max(1, steps - 1)
        grid = vtkUnstructuredGrid()
        grid.SetPoints(vtkPoints())
        grid.GetPoints().SetData(numpy_to_vtk(undeformed + t * displacement, deep=1))
        grid.SetCells(crushed.GetCellTypesArray(), crushed.GetCells())
        values = numpy_to_vtk(np.linalg.norm(displacement, axis=1), deep=1)
        values.SetName("s")
        grid.GetPointData().SetScalars(values)
        grids.append(grid)
    return grids


def matched_by(statistics_object):
    names = [statistics_object.GetPreparationStageName(i)
             for i in range(statistics_object.GetNumberOfPreparationStages())]
    return next((n for n in names if n in ("adjacency", "folds")), "")


def step_through(label, path, args, temporary):
    reader = OpenDataFile(path)
    view = pt.render_view((args.size, args.size))
    reader.UpdatePipeline(float(args.steps - 1))  # the transfer function over the last step's range
    low, high = reader.PointData["s"].GetRange()
    span = high - low or 1.0
    rgb = [low, 0.1, 0.1, 0.8, low + 0.5 * span, 0.9, 0.9, 0.2, high, 0.9, 0.1, 0.1]
    opacity = [low, 0.0, 0.5, 0.0, high, 0.6, 0.5, 0.0]
    bounds = reader.GetDataInformation().GetBounds()
    diagonal = math.sqrt(sum((bounds[2 * a + 1] - bounds[2 * a]) ** 2 for a in range(3)))
    display = pt.show_volume(reader, view, "s", rgb_points=rgb, opacity_points=opacity,
                             unit_distance=0.15 * diagonal)
    stages = []  # the face stage of each build, read when its progress reaches 1

    def on_progress(caller, event):
        if caller.GetProgress() == 1.0:
            stages.append(matched_by(pt.mapper_of(display).GetStatistics()))
    display.GetClientSideObject().GetActiveRepresentation().AddObserver("ProgressEvent",
                                                                        on_progress)
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Elevation(25.0)
    camera.Azimuth(30.0)
    Render(view)
    steady = []
    for _ in range(3):
        camera.Azimuth(1.0)
        start = time.perf_counter()
        Render(view)
        steady.append(1000.0 * (time.perf_counter() - start))
    mapper = pt.mapper_of(display)
    cells = mapper.GetStatistics().GetNumberOfTetrahedra()
    print("\n%s: %d tetrahedra, %dx%d; steady frame %.0f ms (median of 3)\n"
          % (label, cells, args.size, args.size, statistics.median(steady)))
    print("| step | ms | preparation ms | geometry uploads | field uploads | faces | covered | "
          "p99 | max |")
    print("|---:|---:|---:|---:|---:|:---|---:|---:|---:|")
    for k in range(args.steps):
        del stages[:]
        start = time.perf_counter()
        scene.AnimationTime = float(k)  # reads the step and renders the view (the scene's tick)
        wall = 1000.0 * (time.perf_counter() - start)
        s = mapper.GetStatistics()
        preparation = s.GetPreparationTime()
        Render(view)
        uploads = (s.GetGeometryUploadCount(), s.GetFieldUploadCount())
        image = pt.screenshot(view, os.path.join(temporary, "%s%d.png" % (label, k)))
        covered, p99, largest = pt.against_reference(view, display, image, "s")
        print("| %d | %.0f | %.0f | %d | %d | %s | %d | %.2f | %.2f |"
              % ((k, wall, preparation) + uploads
                 + (",".join(n for n in stages if n) or "kept", covered, p99, largest)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=5)
    parser.add_argument("--points", type=int, default=41, help="lattice points per axis")
    parser.add_argument("--size", type=int, default=512)
    args = parser.parse_args()
    if not os.environ.get("PV_PLUGIN_PATH"):
        pt.fail("run through Module/run pvbatch (it loads the PPIRay plugin)")
    with tempfile.TemporaryDirectory() as temporary:
        step_through("fixed", pt.write_pvd(os.path.join(temporary, "fixed"),
                                        fixed_series(args.points, args.steps)), args, temporary)
        grids = can_series(args.steps)
        if grids:
            step_through("can", pt.write_pvd(os.path.join(temporary, "can"), grids), args,
                         temporary)
    return 0


if __name__ == "__main__":
    main()  # not sys.exit(): pvbatch 5.11 tears its views down badly after it (ppiray_pvtest.fail)
