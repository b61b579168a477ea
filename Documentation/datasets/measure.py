"""Every dataset in the data root, rendered by the mapper and by the CPU
reference renderer, as it comes (hexahedra, wedges, pyramids, quadratic
cells...) and after vtkDataSetTriangleFilter (the tetrahedra ParaView's volume
preprocessor makes): peels, ms per frame, and the per-channel difference to
the reference over the covered pixels (p99, max, 1/255). Prints a Markdown
table.

Run: Module/run python Documentation/datasets/measure.py [--size N] [--only NAME,...]
"""
import argparse
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter

import ppiray

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Testing", "Python"))
from ppiray_datasets import DATASETS, select  # noqa: E402
from ppiray_scene import scene, window_rgb  # noqa: E402


def measure(grid, size):
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    window, renderer = scene(grid, mapper, size)
    window.Render()
    times = []
    for _ in range(3):
        start = time.perf_counter()
        window.Render()
        times.append(1000 * (time.perf_counter() - start))
    gpu = window_rgb(window)
    cells = mapper.GetStatistics().GetNumberOfTetrahedra() or mapper.GetStatistics().GetNumberOfNativeCells()
    kind = ("tetrahedra" if mapper.GetStatistics().GetNumberOfTetrahedra() else
            "hexahedra" if mapper.GetStatistics().GetNumberOfHexahedra() == cells else "cells natively")
    peels = mapper.GetStatistics().GetNumberOfPeels()
    window.Finalize()  # one X connection at a time
    reference = ppiray.vtkUnstructuredGridReferenceRenderer()
    reference.SetInputData(grid)
    reference.SetVolumeProperty(renderer.GetVolumes().GetLastProp().GetProperty())
    reference.SetCamera(renderer.GetActiveCamera())
    reference.SetImageSize(size, size)
    start = time.perf_counter()
    reference.Update()
    seconds = time.perf_counter() - start
    exact = vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars())[:, :3]
    exact = np.clip(exact, 0, 1) * 255.0
    covered = (np.rint(exact) >= 1).any(axis=1) | (gpu >= 1).any(axis=1)
    nan = int(np.isnan(exact).any(axis=1).sum())
    d = np.abs(gpu - exact)[covered & ~np.isnan(exact).any(axis=1)]
    return dict(cells="%d %s" % (cells, kind), peels=peels,
                ms=float(np.median(times)), ref_s=seconds, covered=int(covered.sum()), nan=nan,
                p99=float(np.percentile(d, 99)) if d.size else 0.0,
                max=float(d.max()) if d.size else 0.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--only", default="")
    args = parser.parse_args()
    names = [n for n in DATASETS if not args.only or n in args.only.split(",")]
    print("| dataset | array | as | cells rendered | peels | ms/frame | reference s | "
          "covered px | p99 | max |")
    print("|---|---|---|---|---:|---:|---:|---:|---:|---:|")
    for name in names:
        loader, array, points = DATASETS[name]
        try:
            grid = loader()
        except Exception as error:  # a reader the build lacks
            print("| %s | | | failed to read: %s | | | | | | |" % (name, error), flush=True)
            continue
        array = select(grid, array, points)
        if array is None:
            print("| %s | (none) | | | | | | | | |" % name, flush=True)
            continue
        tetra = vtkDataSetTriangleFilter()
        tetra.SetInputData(grid)
        tetra.Update()
        for label, g in (("given", grid), ("vtkDataSetTriangleFilter", tetra.GetOutput())):
            select(g, array, points)
            m = measure(g, args.size)
            print("| %s | %s | %s | %s | %d | %.0f | %.1f | %d | %.2f | %.1f |"
                  % (name, array, label, m["cells"], m["peels"], m["ms"], m["ref_s"],
                     m["covered"], m["p99"], m["max"]), flush=True)


if __name__ == "__main__":
    main()
