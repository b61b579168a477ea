"""Module/run demo [FILE.vtu] [--out demo.png] [--size N] [--frames N]

Renders a tetrahedral .vtu (default: Data/wavelet_hole.vtu) with
vtkUnstructuredGridGPURayCastMapper, writes the image, prints the frame time,
and the error against VTK's CPU ray caster (vtkUnstructuredGridVolumeRayCastMapper,
image sample distance 1) rendering the same view in a subprocess.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)
from vtkmodules.vtkRenderingVolume import vtkUnstructuredGridVolumeRayCastMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

ROOT = os.environ.get("PPIRAY_ROOT", os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))


def load(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetPointData().GetScalars() is None and grid.GetPointData().GetNumberOfArrays():
        grid.GetPointData().SetActiveScalars(grid.GetPointData().GetArrayName(0))
    return grid


def scene(grid, mapper, size):
    scalars = grid.GetPointData().GetScalars() or grid.GetCellData().GetScalars()
    if scalars is None:
        sys.exit("no point or cell scalars in the dataset")
    lo, hi = scalars.GetRange()
    color = vtkColorTransferFunction()
    for u, rgb in ((0.0, (0.23, 0.30, 0.75)), (0.5, (0.87, 0.87, 0.87)), (1.0, (0.71, 0.02, 0.15))):
        color.AddRGBPoint(lo + u * (hi - lo), *rgb)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(lo + 0.5 * (hi - lo), 0.05)
    opacity.AddPoint(hi, 0.6)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    b = grid.GetBounds()
    diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5
    prop.SetScalarOpacityUnitDistance(diagonal / 20.0)
    mapper.SetInputData(grid)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(0, 0, 0)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(1.0, 0.7, 1.3)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCamera()
    camera.SetFocalPoint([(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2])
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetMultiSamples(0)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    return window, renderer


def save(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    return vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(float)


def render_cpu_peer(path, out, size):
    grid = load(path)
    mapper = vtkUnstructuredGridVolumeRayCastMapper()
    mapper.SetImageSampleDistance(1.0)
    mapper.AutoAdjustSampleDistancesOff()
    window, _ = scene(grid, mapper, size)
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    print("%.1f" % (1000 * (time.perf_counter() - start)))
    save(window, out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", nargs="?", default=os.path.join(ROOT, "Data", "wavelet_hole.vtu"))
    parser.add_argument("--out", default="demo.png")
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--frames", type=int, default=10)
    parser.add_argument("--cpu-peer", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.cpu_peer:
        render_cpu_peer(args.file, args.cpu_peer, args.size)
        return 0

    import ppiray

    grid = load(args.file)
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    window, renderer = scene(grid, mapper, args.size)
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
    tets = mapper.GetNumberOfTetrahedra()
    print("dataset   %s: %d cells, %d tetrahedra rendered" % (
        os.path.basename(args.file), grid.GetNumberOfCells(), tets))
    print("PPIRay    %.1f ms/frame at %dx%d (median of %d), %.2f M tetrahedra/s, %d peels, "
          "%.1f MB on the GPU" % (ms, args.size, args.size, args.frames, tets / ms / 1000.0,
                                  mapper.GetNumberOfPeels(), mapper.GetGPUMemorySize() / 2**20))
    print("image     %s" % os.path.abspath(args.out))

    with tempfile.TemporaryDirectory() as tmp:
        peer = os.path.join(tmp, "cpu.png")
        run = subprocess.run([sys.executable, __file__, args.file, "--size", str(args.size),
                              "--cpu-peer", peer], capture_output=True, text=True)
        if run.returncode != 0 or not os.path.exists(peer):
            print("error     VTK CPU ray caster failed (exit %d): %s" % (
                run.returncode, run.stderr.strip().splitlines()[-1:] or ""))
            return 0
        cpu_ms = float(run.stdout.strip().splitlines()[-1])
        diff = np.abs(read_png(args.out) - read_png(peer))
        print("VTK CPU   %.1f ms/frame (vtkUnstructuredGridVolumeRayCastMapper): PPIRay is %.1fx "
              "faster" % (cpu_ms, cpu_ms / ms))
        print("error     vs VTK CPU ray caster, per channel in 1/255: mean %.2f, p99 %.1f, max %.0f"
              % (diff.mean(), np.percentile(diff, 99), diff.max()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
