"""Module/run demo [FILE] [options]: render a mesh with PPIRay, print the time

Reads FILE (default: the bundled Data/wavelet_hole.vtu): XML (.vtu .vts .vtr
.vti .vtm .pvtu .pvd), legacy .vtk, Exodus (.e .ex2 .exo), PLOT3D (xyz file
with --q). Renders its 3D cells with vtkUnstructuredGridGPURayCastMapper as
ParaView shows a new volume (Cool to Warm, opacity ramp 0 to 1, unit
distance about one cell), or with the colour map, opacity, unit distance,
view, integration mode, blend mode and hexahedron mode given; writes the
image and prints the frame time, the cells rendered (tetrahedra, native
hexahedra, split cells) and the GPU memory. --compare adds the error
against the exact CPU reference (vtkUnstructuredGridReferenceRenderer)
and/or the time and error of VTK's CPU ray caster
(vtkUnstructuredGridVolumeRayCastMapper), each within --budget seconds.
Exits non-zero on any failure.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkRenderingVolume import (
    vtkProjectedTetrahedraMapper,
    vtkUnstructuredGridVolumeRayCastMapper,
)

from ppiray_readers import ReadError, read, three_d_cells
from ppiray_scene import colormap_names, load, paraview_property, read_png, save, scene

ROOT = os.environ.get("PPIRAY_ROOT", os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
BUNDLED = os.path.join(ROOT, "Data", "wavelet_hole.vtu")
# Arrays that number things rather than measure them.
NOT_A_FIELD = re.compile(r"(ids?|ghosttype|validpointmask|blockid|objectid|_[ijk])$",
                         re.IGNORECASE)


# Choices of the command line, as the mapper's values.
MODES = {"partial": "PARTIAL_PRE_INTEGRATION", "exact": "EXACT_LINEAR",
         "full": "FULL_PRE_INTEGRATION", "average": "AVERAGE_COLOR"}
BLENDS = {"composite": 0, "maximum": 1, "minimum": 2, "average": 3, "additive": 4}
HEXAHEDRA = {"accurate": "HEXAHEDRON_ACCURATE", "fast": "HEXAHEDRON_FAST",
             "subdivide": "HEXAHEDRON_SUBDIVIDE"}


def opacity_points(text):
    """--opacity: 'ramp' (None: ParaView's 0 to 1) or 'u:o,...' pairs."""
    if text == "ramp":
        return None
    try:
        points = [tuple(float(x) for x in pair.split(":")) for pair in text.split(",")]
    except ValueError:
        points = []
    if not points or any(len(p) != 2 or not 0.0 <= p[1] <= 1.0 for p in points):
        raise argparse.ArgumentTypeError("'ramp' or 'u:o,u:o,...' with opacities in [0, 1] "
                                         "expected, not %r" % text)
    return sorted(points)


def view_angles(text):
    """--view: (azimuth, elevation, zoom)."""
    try:
        values = [float(x) for x in text.split(",")]
    except ValueError:
        values = []
    if len(values) not in (2, 3) or (len(values) == 3 and values[2] <= 0):
        raise argparse.ArgumentTypeError("'AZIMUTH,ELEVATION[,ZOOM]' expected (zoom > 0), not %r"
                                         % text)
    return tuple(values) + ((1.0,) if len(values) == 2 else ())


def image_size(text):
    """--size: 'N' or 'WxH' -> (width, height)."""
    try:
        values = [int(x) for x in text.lower().split("x")]
    except ValueError:
        values = []
    if len(values) == 1:
        values *= 2
    if len(values) != 2 or min(values) < 1:
        raise argparse.ArgumentTypeError("'N' or 'WxH' pixels expected, not %r" % text)
    return tuple(values)


def demo_scene(grid, mapper, size, unit_distance, colormap_name, opacity, view):
    """The window and renderer the demo renders in: ParaView's defaults with
    the command line's colour map, opacity, unit distance and view."""
    prop = paraview_property(grid, unit_distance, colormap_name, opacity)
    window, renderer = scene(grid, mapper, size, prop)
    camera = renderer.GetActiveCamera()
    camera.Azimuth(view[0])
    camera.Elevation(view[1])
    camera.OrthogonalizeViewUp()
    camera.Zoom(view[2])
    renderer.ResetCameraClippingRange()
    return window, renderer


def render_cpu_peer(path, out, size, unit_distance, colormap_name, opacity, view):
    grid = load(path)
    mapper = vtkUnstructuredGridVolumeRayCastMapper()
    mapper.SetImageSampleDistance(1.0)
    mapper.AutoAdjustSampleDistancesOff()
    window, _ = demo_scene(grid, mapper, size, unit_distance, colormap_name, opacity, view)
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    print("%.1f" % (1000 * (time.perf_counter() - start)))
    save(window, out)


def choose_array(grid, name):
    """(point or cell data, array) to render: `name`, else the first
    one-component array that is not an id (point data first), else the first
    multi-component one, else the z coordinate."""
    candidates = []
    for data in (grid.GetPointData(), grid.GetCellData()):
        for i in range(data.GetNumberOfArrays()):
            array = data.GetArray(i)
            if array is None:
                continue
            if name is not None:
                if array.GetName() == name:
                    return data, array
                continue
            if not NOT_A_FIELD.search(array.GetName() or ""):
                candidates.append((array.GetNumberOfComponents() > 1, data, array))
    if name is not None:
        raise ReadError("no point or cell array named %s" % name)
    if not candidates:
        # No field (a bare mesh, or ids only): its z coordinate.
        z = numpy_to_vtk(vtk_to_numpy(grid.GetPoints().GetData())[:, 2].copy(), deep=True)
        z.SetName("z (no field in the file)")
        grid.GetPointData().AddArray(z)
        return grid.GetPointData(), z
    candidates.sort(key=lambda c: c[0])  # stable: one-component arrays first
    return candidates[0][1], candidates[0][2]


def rendered_scalars(grid, name, component):
    """Makes the chosen array's magnitude or component the active scalars of
    its point or cell data (the other's active scalars unset); returns a
    description."""
    data, array = choose_array(grid, name)
    values = vtk_to_numpy(array).astype(float)
    label = array.GetName()
    if values.ndim > 1:
        if component is None:
            values = np.linalg.norm(values, axis=1)
            label += " (magnitude)"
        elif 0 <= component < values.shape[1]:
            values = values[:, component]
            label += " (component %d)" % component
        else:
            raise ReadError("%s has %d components; --component %d is not one" % (
                array.GetName(), values.shape[1], component))
    scalars = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
    scalars.SetName("rendered")
    data.AddArray(scalars)
    data.SetActiveScalars("rendered")
    other = grid.GetCellData() if data is grid.GetPointData() else grid.GetPointData()
    other.SetActiveScalars(None)
    return "%s %s" % ("point" if data is grid.GetPointData() else "cell", label)


def speed_sentence(ours_ms, theirs_ms, theirs_are):
    """Which of PPIRay and the other ("projected tetrahedra are") is faster on
    this mesh, and by how much (a ratio of at least 1)."""
    if theirs_ms >= ours_ms:
        return "PPIRay is %.1fx faster on this mesh here" % (theirs_ms / ours_ms)
    return "%s %.1fx faster on this mesh here" % (theirs_are, ours_ms / theirs_ms)


def timed_first_frame(window):
    """Milliseconds of a window's first render (preparation, upload, shader
    compilation and the frame)."""
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    return 1000 * (time.perf_counter() - start)


def compare_projected_tetrahedra(grid, prop, camera, args, ours, ms):
    """VTK's projected tetrahedra on the same view (its tetrahedra as
    ParaView's volume preprocessor makes them): frame time, image beside
    --out, difference to PPIRay's."""
    only_tetrahedra = set(vtk_to_numpy(grid.GetCellTypesArray())) <= {10}
    tetrahedra = grid
    if not only_tetrahedra:
        split = vtkDataSetTriangleFilter()
        split.SetInputData(grid)
        split.Update()
        tetrahedra = split.GetOutput()
    mapper = vtkProjectedTetrahedraMapper()
    window, renderer = scene(tetrahedra, mapper, args.size, prop)
    renderer.GetActiveCamera().DeepCopy(camera)
    start = time.perf_counter()
    first_ms = timed_first_frame(window)
    times = []
    for _ in range(args.frames):
        if time.perf_counter() - start > args.budget:
            break
        begin = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - begin)
    if not times:
        print("VTK PT    stopped after the %g s budget (--budget): no comparison" % args.budget)
        return
    out = os.path.splitext(args.out)[0] + "_pt.png"
    save(window, out)
    pt_ms = 1000 * float(np.median(times))
    diff = np.abs(ours - read_png(out))
    print("VTK PT    %.1f ms/frame (vtkProjectedTetrahedraMapper, %d tetrahedra, median of %d; "
          "first frame %.0f ms): %s; image %s"
          % (pt_ms, tetrahedra.GetNumberOfCells(), len(times), first_ms,
             speed_sentence(ms, pt_ms, "projected tetrahedra are"), os.path.abspath(out)))
    print("differ    PT from PPIRay, per channel in 1/255: mean %.2f, p99 %.1f, max %.0f" % (
        diff.mean(), np.percentile(diff, 99), diff.max()))


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.splitlines()[0], epilog="\n".join(__doc__.splitlines()[2:]),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", nargs="?", default=BUNDLED,
                        help="the mesh (default: the bundled Data/wavelet_hole.vtu)")
    parser.add_argument("--q", help="PLOT3D solution file for an xyz FILE")
    parser.add_argument("--function", type=int,
                        help="PLOT3D: also derive this function (vtkMultiBlockPLOT3DReader "
                        "numbers: 110 pressure, 153 velocity magnitude, ...)")
    parser.add_argument("--raw", help="FILE is a raw brick 'NXxNYxNZ[:TYPE]' (TYPE uint8 "
                        "(default), int8, uint16, int16, int32, float32, float64; little-endian)")
    parser.add_argument("--time-step", type=int, default=0,
                        help="time step index of a .pvd or Exodus file (default 0)")
    parser.add_argument("--array", help="point or cell array to render (default: the first "
                        "one-component array that is not an id, point data first)")
    parser.add_argument("--component", type=int,
                        help="component of a vector array (default: its magnitude)")
    parser.add_argument("--colormap", default="Cool to Warm",
                        help="a ParaView colour map preset by name, in its colour space "
                        "(default 'Cool to Warm'; 'list' prints the names)")
    parser.add_argument("--opacity", type=opacity_points, default=None,
                        help="the opacity over the scalar range: 'ramp' (0 to 1, ParaView's "
                        "default) or points 'u:o,u:o,...' with u the fraction of the range "
                        "(0 to 1) and o the opacity, e.g. '0:0,0.5:0.05,1:0.6'")
    parser.add_argument("--unit-distance", type=float,
                        help="the opacity's unit distance (default: about one cell, as ParaView "
                        "sets it: the bounds' diagonal over the cube root of the cell count)")
    parser.add_argument("--view", type=view_angles, default=(0.0, 0.0, 1.0),
                        help="'AZIMUTH,ELEVATION[,ZOOM]': degrees about the default "
                        "three-quarter view, and a zoom factor (default 0,0,1)")
    parser.add_argument("--mode", choices=sorted(MODES), default="partial",
                        help="integration: partial pre-integration (default), exact linear, "
                        "full pre-integration table, average colour")
    parser.add_argument("--blend", choices=sorted(BLENDS), default="composite",
                        help="composite (default) or a projection: maximum, minimum, average "
                        "intensity, additive")
    parser.add_argument("--hexahedra", choices=sorted(HEXAHEDRA), default="accurate",
                        help="meshes of hexahedra only: rendered natively, 'accurate' (default) "
                        "or 'fast', or split into tetrahedra ('subdivide')")
    parser.add_argument("--out", default="demo.png", help="image written (default demo.png)")
    parser.add_argument("--size", type=image_size, default=(512, 512),
                        help="image size, 'N' or 'WxH' pixels (default 512)")
    parser.add_argument("--frames", type=int, default=10,
                        help="frames timed after a warm-up, median printed (10)")
    parser.add_argument("--compare", choices=("none", "reference", "vtk", "pt", "all"),
                        help="also render with the exact CPU reference, VTK's CPU ray caster "
                        "(vtk) or VTK's projected tetrahedra (pt, image written beside --out), "
                        "or all three (slow on large meshes; default: all for the bundled mesh, "
                        "none for your files)")
    parser.add_argument("--budget", type=float, default=120.0,
                        help="seconds each comparison may take; past it, it stops and no error "
                        "is printed for it (default 120)")
    parser.add_argument("--cpu-peer", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.colormap == "list":
        print("\n".join(colormap_names()))
        return 0
    if args.cpu_peer:
        render_cpu_peer(args.file, args.cpu_peer, args.size, args.unit_distance, args.colormap,
                        args.opacity, args.view)
        return 0
    compare = args.compare or ("all" if os.path.abspath(args.file) == BUNDLED else "none")
    if compare in ("vtk", "pt", "all") and args.blend != "composite":
        print("note      VTK's unstructured mappers draw composite only: not compared in "
              "--blend %s" % args.blend)
        compare = "reference" if compare == "all" else "none"

    import ppiray

    try:
        grid = read(args.file, args.q, args.time_step, args.raw, args.function)
        cells3d = three_d_cells(grid)
        if cells3d == 0:
            raise ReadError("%s has no 3D cells (%d cells of lower dimension): nothing to "
                            "render as a volume" % (args.file, grid.GetNumberOfCells()))
        field = rendered_scalars(grid, args.array, args.component)
    except ReadError as error:
        print("error     %s" % error, file=sys.stderr)
        return 1

    Mapper = ppiray.vtkUnstructuredGridGPURayCastMapper
    mapper = Mapper()
    mapper.SetIntegrationMode(getattr(Mapper, MODES[args.mode]))
    mapper.SetBlendMode(BLENDS[args.blend])
    mapper.SetHexahedronMode(getattr(Mapper, HEXAHEDRA[args.hexahedra]))
    try:
        window, renderer = demo_scene(grid, mapper, args.size, args.unit_distance, args.colormap,
                                      args.opacity, args.view)
    except KeyError:
        print("error     no colour map named %r (--colormap list prints them)" % args.colormap,
              file=sys.stderr)
        return 1
    prop = renderer.GetVolumes().GetLastProp().GetProperty()
    width, height = args.size
    first_ms = timed_first_frame(window)  # builds cell textures, compiles shaders
    preparation_ms = mapper.GetStatistics().GetPreparationTime()
    times = []
    for _ in range(args.frames):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - start)
    save(window, args.out)
    ms = 1000 * float(np.median(times))
    tets, native = mapper.GetStatistics().GetNumberOfTetrahedra(), mapper.GetStatistics().GetNumberOfNativeCells()
    # VTK_TETRA 10; quadratic, Lagrange and Bezier tetrahedra (24, 71, 78) are
    # rendered through their corners; other cells as the tetrahedra they split into.
    types = set(vtk_to_numpy(grid.GetCellTypesArray()))
    how = ("" if types <= {10} else " (higher-order ones by their corners)"
           if types <= {10, 24, 71, 78} else " (cells split)")
    kind = "hexahedra" if mapper.GetStatistics().GetNumberOfHexahedra() == native else "cells"
    rendered = "%d %s natively" % (native, kind) if native else "%d tetrahedra%s" % (tets, how)
    if tets + native == 0:
        print("error     nothing was rendered (see the messages above)", file=sys.stderr)
        return 1
    print("dataset   %s: %d cells (%d 3D), %s, rendered as %s" % (
        os.path.basename(args.file), grid.GetNumberOfCells(), cells3d, field, rendered))
    print("transfer  %s, opacity %s over [%.4g, %.4g], unit distance %.4g; %s, %s" % (
        args.colormap, "ramp 0 to 1" if not args.opacity else
        " ".join("%g:%g" % p for p in args.opacity), *prop.GetRGBTransferFunction().GetRange(),
        prop.GetScalarOpacityUnitDistance(), args.mode, args.blend))
    print("PPIRay    %.1f ms/frame at %dx%d (median of %d), %d peels, %.1f MB on the GPU" % (
        ms, width, height, args.frames, mapper.GetStatistics().GetNumberOfPeels(),
        mapper.GetStatistics().GetGPUMemorySize() / 2**20))
    print("first     %.0f ms for the first frame: %.0f ms preparing the cells on the CPU, then "
          "upload, shader compilation and the frame" % (first_ms, preparation_ms))
    print("image     %s" % os.path.abspath(args.out))
    ours = read_png(args.out)
    if not (ours.max(axis=1) > 0).any():
        print("warning   the image is empty: try --array, or another transfer function")

    if compare in ("reference", "all"):
        reference = ppiray.vtkUnstructuredGridReferenceRenderer()
        reference.SetInputData(grid)
        reference.SetVolumeProperty(prop)
        reference.SetCamera(renderer.GetActiveCamera())
        reference.SetImageSize(width, height)
        reference.SetBlendMode(BLENDS[args.blend])
        start = time.perf_counter()
        shown = [0.0]

        def progress(algorithm, event):
            # Progress lines every 10 %; past the budget, stop the reference.
            done, elapsed = algorithm.GetProgress(), time.perf_counter() - start
            if done >= shown[0] + 0.1 and done < 1.0:
                shown[0] = done
                print("reference %3.0f %% after %.0f s" % (100 * done, elapsed), flush=True)
            if elapsed > args.budget:
                algorithm.SetAbortExecute(1)

        reference.AddObserver("ProgressEvent", progress)
        reference.Update()
        seconds = time.perf_counter() - start
        if reference.GetAbortExecute():
            print("reference stopped at %.0f %% after %.0f s (--budget %g): no comparison" % (
                100 * reference.GetProgress(), seconds, args.budget))
        else:
            exact = 255.0 * vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars())[:, :3]
            diff = np.abs(ours - np.clip(np.rint(exact), 0, 255))
            print("error     vs the exact CPU reference (%.1f s), per channel in 1/255: mean "
                  "%.3f, p99 %.1f, max %.0f; %d pixels off by more than 2" % (
                      seconds, diff.mean(), np.percentile(diff, 99), diff.max(),
                      int((diff.max(axis=1) > 2).sum())))

    if compare in ("pt", "all"):
        compare_projected_tetrahedra(grid, prop, renderer.GetActiveCamera(), args, ours, ms)

    if compare in ("vtk", "all"):
        with tempfile.TemporaryDirectory() as tmp:
            prepared, peer = os.path.join(tmp, "grid.vtu"), os.path.join(tmp, "cpu.png")
            writer = vtkXMLUnstructuredGridWriter()
            writer.SetFileName(prepared)
            writer.SetInputData(grid)
            writer.Write()
            command = [sys.executable, __file__, prepared, "--size", "%dx%d" % args.size,
                       "--unit-distance", repr(prop.GetScalarOpacityUnitDistance()),
                       "--colormap", args.colormap, "--view", "%r,%r,%r" % args.view,
                       "--cpu-peer", peer]
            if args.opacity:
                command += ["--opacity", ",".join("%r:%r" % p for p in args.opacity)]
            try:
                run = subprocess.run(command, capture_output=True, text=True,
                                     timeout=args.budget)
            except subprocess.TimeoutExpired:
                print("VTK CPU   stopped after the %g s budget (--budget): no comparison"
                      % args.budget)
                return 0
            if run.returncode != 0 or not os.path.exists(peer):
                print("error     VTK's CPU ray caster failed (exit %d): %s" % (
                    run.returncode, run.stderr.strip().splitlines()[-1:] or ""), file=sys.stderr)
                return 1
            cpu_ms = float(run.stdout.strip().splitlines()[-1])
            diff = np.abs(ours - read_png(peer))
            print("VTK CPU   %.1f ms/frame (vtkUnstructuredGridVolumeRayCastMapper): %s"
                  % (cpu_ms, speed_sentence(ms, cpu_ms, "VTK's CPU ray caster is")))
            print("error     vs VTK's CPU ray caster, per channel in 1/255: mean %.2f, p99 %.1f, "
                  "max %.0f" % (diff.mean(), np.percentile(diff, 99), diff.max()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
