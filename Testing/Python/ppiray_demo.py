"""Module/run demo [FILE.vtu] [--out demo.png] [--size N] [--frames N]

Renders a tetrahedral .vtu (default: Data/wavelet_hole.vtu) with
vtkUnstructuredGridGPURayCastMapper, writes the image, prints the frame time,
the error against VTK's CPU ray caster (vtkUnstructuredGridVolumeRayCastMapper,
image sample distance 1) rendering the same view in a subprocess, and the
error against the exact CPU reference (vtkUnstructuredGridReferenceRenderer).
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingVolume import vtkUnstructuredGridVolumeRayCastMapper

from ppiray_scene import load, read_png, save, scene

ROOT = os.environ.get("PPIRAY_ROOT", os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))


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

    reference = ppiray.vtkUnstructuredGridReferenceRenderer()
    reference.SetInputData(grid)
    reference.SetVolumeProperty(renderer.GetVolumes().GetLastProp().GetProperty())
    reference.SetCamera(renderer.GetActiveCamera())
    reference.SetImageSize(args.size, args.size)
    start = time.perf_counter()
    reference.Update()
    exact = 255.0 * vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars())[:, :3]
    diff = np.abs(read_png(args.out) - np.clip(np.rint(exact), 0, 255))
    print("error     vs the exact CPU reference (%.1f s), per channel in 1/255: mean %.3f, "
          "p99 %.1f, max %.0f" % (time.perf_counter() - start, diff.mean(),
                                  np.percentile(diff, 99), diff.max()))

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
