"""Module/run demo [FILE] [options]: render a mesh with PPIRay, print the time

Reads FILE (default: the bundled Data/wavelet_hole.vtu): XML (.vtu .vts .vtr
.vti .vtm .pvtu .pvd), legacy .vtk, Exodus (.e .ex2 .exo), PLOT3D (xyz file
with --q). Renders its 3D cells with vtkUnstructuredGridGPURayCastMapper as
ParaView shows a new volume (Cool to Warm, opacity ramp 0 to 1, unit
distance about one cell), writes the image and prints the frame time, the cells rendered (tetrahedra,
native hexahedra) and the GPU memory. --compare adds the error against the
exact CPU reference (vtkUnstructuredGridReferenceRenderer) and/or the time
and error of VTK's CPU ray caster (vtkUnstructuredGridVolumeRayCastMapper).
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
from vtkmodules.vtkRenderingVolume import vtkUnstructuredGridVolumeRayCastMapper

from ppiray_readers import ReadError, read, three_d_cells
from ppiray_scene import load, paraview_property, read_png, save, scene

ROOT = os.environ.get("PPIRAY_ROOT", os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
BUNDLED = os.path.join(ROOT, "Data", "wavelet_hole.vtu")
# Arrays that number things rather than measure them.
NOT_A_FIELD = re.compile(r"(ids?|ghosttype|validpointmask|blockid|objectid)$", re.IGNORECASE)


def render_cpu_peer(path, out, size, unit_distance):
    grid = load(path)
    mapper = vtkUnstructuredGridVolumeRayCastMapper()
    mapper.SetImageSampleDistance(1.0)
    mapper.AutoAdjustSampleDistancesOff()
    window, _ = scene(grid, mapper, size, paraview_property(grid, unit_distance))
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    print("%.1f" % (1000 * (time.perf_counter() - start)))
    save(window, out)


def choose_array(grid, name):
    """(point or cell data, array) to render: `name`, else the first
    one-component array that is not an id (point data first), else the first
    multi-component one."""
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
        raise ReadError("no point or cell array to render")
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


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.splitlines()[0], epilog="\n".join(__doc__.splitlines()[2:]),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", nargs="?", default=BUNDLED,
                        help="the mesh (default: the bundled Data/wavelet_hole.vtu)")
    parser.add_argument("--q", help="PLOT3D solution file for an xyz FILE")
    parser.add_argument("--time-step", type=int, default=0,
                        help="time step index of a .pvd or Exodus file (default 0)")
    parser.add_argument("--array", help="point or cell array to render (default: the first "
                        "one-component array that is not an id, point data first)")
    parser.add_argument("--component", type=int,
                        help="component of a vector array (default: its magnitude)")
    parser.add_argument("--unit-distance", type=float,
                        help="the opacity's unit distance (default: about one cell, as ParaView "
                        "sets it: the bounds' diagonal over the cube root of the cell count)")
    parser.add_argument("--out", default="demo.png", help="image written (default demo.png)")
    parser.add_argument("--size", type=int, default=512, help="window side in pixels (512)")
    parser.add_argument("--frames", type=int, default=10,
                        help="frames timed after a warm-up, median printed (10)")
    parser.add_argument("--compare", choices=("none", "reference", "vtk", "all"),
                        help="also render with the exact CPU reference and/or VTK's CPU ray "
                        "caster (slow on large meshes; default: all for the bundled mesh, none "
                        "for your files)")
    parser.add_argument("--cpu-peer", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.cpu_peer:
        render_cpu_peer(args.file, args.cpu_peer, args.size, args.unit_distance)
        return 0
    compare = args.compare or ("all" if os.path.abspath(args.file) == BUNDLED else "none")

    import ppiray

    try:
        grid = read(args.file, args.q, args.time_step)
        cells3d = three_d_cells(grid)
        if cells3d == 0:
            raise ReadError("%s has no 3D cells (%d cells of lower dimension): nothing to "
                            "render as a volume" % (args.file, grid.GetNumberOfCells()))
        field = rendered_scalars(grid, args.array, args.component)
    except ReadError as error:
        print("error     %s" % error, file=sys.stderr)
        return 1

    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    prop = paraview_property(grid, args.unit_distance)
    window, renderer = scene(grid, mapper, args.size, prop)
    window.Render()  # warm-up: builds cell textures, compiles shaders
    window.WaitForCompletion()
    times = []
    for _ in range(args.frames):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(time.perf_counter() - start)
    save(window, args.out)
    ms = 1000 * float(np.median(times))
    tets, hexes = mapper.GetNumberOfTetrahedra(), mapper.GetNumberOfHexahedra()
    rendered = ("%d hexahedra natively" % hexes) if hexes else ("%d tetrahedra" % tets)
    if tets + hexes == 0:
        print("error     nothing was rendered (see the messages above)", file=sys.stderr)
        return 1
    print("dataset   %s: %d cells (%d 3D), %s, rendered as %s" % (
        os.path.basename(args.file), grid.GetNumberOfCells(), cells3d, field, rendered))
    print("PPIRay    %.1f ms/frame at %dx%d (median of %d), %d peels, %.1f MB on the GPU" % (
        ms, args.size, args.size, args.frames, mapper.GetNumberOfPeels(),
        mapper.GetGPUMemorySize() / 2**20))
    print("image     %s" % os.path.abspath(args.out))
    ours = read_png(args.out)
    if not (ours.max(axis=1) > 0).any():
        print("warning   the image is empty: try --array, or another transfer function")

    if compare in ("reference", "all"):
        reference = ppiray.vtkUnstructuredGridReferenceRenderer()
        reference.SetInputData(grid)
        reference.SetVolumeProperty(renderer.GetVolumes().GetLastProp().GetProperty())
        reference.SetCamera(renderer.GetActiveCamera())
        reference.SetImageSize(args.size, args.size)
        start = time.perf_counter()
        reference.Update()
        exact = 255.0 * vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars())[:, :3]
        diff = np.abs(ours - np.clip(np.rint(exact), 0, 255))
        print("error     vs the exact CPU reference (%.1f s), per channel in 1/255: mean %.3f, "
              "p99 %.1f, max %.0f" % (time.perf_counter() - start, diff.mean(),
                                      np.percentile(diff, 99), diff.max()))

    if compare in ("vtk", "all"):
        with tempfile.TemporaryDirectory() as tmp:
            prepared, peer = os.path.join(tmp, "grid.vtu"), os.path.join(tmp, "cpu.png")
            writer = vtkXMLUnstructuredGridWriter()
            writer.SetFileName(prepared)
            writer.SetInputData(grid)
            writer.Write()
            run = subprocess.run([sys.executable, __file__, prepared, "--size", str(args.size),
                                  "--unit-distance", repr(prop.GetScalarOpacityUnitDistance()),
                                  "--cpu-peer", peer], capture_output=True, text=True)
            if run.returncode != 0 or not os.path.exists(peer):
                print("error     VTK's CPU ray caster failed (exit %d): %s" % (
                    run.returncode, run.stderr.strip().splitlines()[-1:] or ""), file=sys.stderr)
                return 1
            cpu_ms = float(run.stdout.strip().splitlines()[-1])
            diff = np.abs(ours - read_png(peer))
            print("VTK CPU   %.1f ms/frame (vtkUnstructuredGridVolumeRayCastMapper): PPIRay is "
                  "%.1fx faster" % (cpu_ms, cpu_ms / ms))
            print("error     vs VTK's CPU ray caster, per channel in 1/255: mean %.2f, p99 %.1f, "
                  "max %.0f" % (diff.mean(), np.percentile(diff, 99), diff.max()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
