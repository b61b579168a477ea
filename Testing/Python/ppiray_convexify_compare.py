"""Module/run python Testing/Python/ppiray_convexify_compare.py [--scenes L] [--size N] [--views N]

Depth peeling against convexification on the same scenes (Module/run bench's
scenes, ppiray_bench_scenes.py): the mesh as it is, and the output of
vtkUnstructuredGridConvexify (imaginary cells, hidden) rendered by the same
mapper. Per scene: the filter's time, added cells and Steiner points; per
method, the median ms per frame over an orbit of views (after a warm-up
frame), the largest number of peels, the GPU bytes; the largest difference
between the two methods' images over all views (1/255) and, for the first
view, both against the CPU reference of the original mesh (p99, max).
Prints a Markdown table; --plot FILE also draws the ratio (convexified over
peeled ms per frame) against the peels the mesh needs, each scene labelled
with its imaginary cells per mesh cell. Not a test (speed); the
convexification's tests are in Convexify/Testing/Cxx.
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
ROOT = os.environ.get("PPIRAY_ROOT", os.path.dirname(os.path.dirname(HERE)))
DATA_ROOT = os.environ.get("PPIRAY_DATA_ROOT", os.path.join(ROOT, "..", "shared", "data"))


def orbit(grid, prop, size, views, check, start_camera=None):
    """Frames of vtkUnstructuredGridGPURayCastMapper around `grid`: median ms,
    largest peel count, GPU bytes, the images, the first view's comparison
    with the reference of `check` (a grid) or None, and the first camera.
    `start_camera` (else the scene's view of `grid`) starts the orbit."""
    from vtkmodules.vtkRenderingCore import vtkCamera
    import ppiray
    from ppiray_scene import compare_with_reference, reference_rgba, scene, window_rgb
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    window, renderer = scene(grid, mapper, size, prop)
    camera = renderer.GetActiveCamera()
    if start_camera is not None:
        camera.DeepCopy(start_camera)
    first_camera = vtkCamera()
    first_camera.DeepCopy(camera)
    window.Render()  # warm-up: build, upload, compile
    times, peels, images = [], 0, []
    for v in range(views):
        camera.Azimuth(0.0 if v == 0 else 360.0 / views)
        renderer.ResetCameraClippingRange()
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(1000.0 * (time.perf_counter() - start))
        peels = max(peels, mapper.GetStatistics().GetNumberOfPeels())
        images.append(window_rgb(window))
        if v == 0 and check is not None:
            rgba, _ = reference_rgba(check, prop, camera, size)
            first = compare_with_reference(images[0], rgba)
    gpu = mapper.GetStatistics().GetGPUMemorySize()
    open_faces = mapper.GetStatistics().GetNumberOfUnlinkedBoundaryFaces()
    window.Finalize()
    return (float(np.median(times)), peels, gpu, images,
            first if check is not None else None, first_camera, open_faces)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", default=None,
                        help="comma-separated scenes of ppiray_bench_scenes.py (default: its "
                             "NON_CONVEX list)")
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--views", type=int, default=8)
    parser.add_argument("--check", action="store_true",
                        help="compare the first view with the CPU reference (slow on large meshes)")
    parser.add_argument("--plot", help="write the ratio against the peels to this PNG")
    args = parser.parse_args()

    import ppiray
    import ppiray_bench_scenes
    scenes = args.scenes.split(",") if args.scenes else ppiray_bench_scenes.NON_CONVEX
    print("| scene | cells | convexify (s) | imaginary cells | Steiner points | merged points, "
          "dropped triangles | peels: ms/frame, peels, GPU MB | convexified: ms/frame, peels, "
          "GPU MB, faces left open | ratio | max diff (1/255) | vs reference p99/max (peeled; "
          "convexified) |")
    print("|---|---:|---:|---:|---:|---|---|---|---:|---:|---|")
    points = []
    for name in scenes:
        built = ppiray_bench_scenes.build(name, ROOT, DATA_ROOT)
        if built is None:
            print("| %s | no data under %s |" % (name, DATA_ROOT))
            continue
        grid, prop = built
        convexify = ppiray.vtkUnstructuredGridConvexify()
        convexify.SetInputData(grid)
        start = time.perf_counter()
        convexify.Update()
        seconds = time.perf_counter() - start
        convex = convexify.GetOutput()
        check = grid if args.check else None
        a = orbit(grid, prop, args.size, args.views, check)
        b = orbit(convex, prop, args.size, args.views, check, a[5])
        diff = max(float(np.abs(x - y).max()) for x, y in zip(a[3], b[3]))
        if convexify.GetNumberOfImaginaryCells() > 0:
            points.append((name, a[1], b[0] / a[0],
                           convexify.GetNumberOfImaginaryCells() / grid.GetNumberOfCells()))
        vs = ("%.2f/%.2f; %.2f/%.2f" % (a[4]["p99"], a[4]["max"], b[4]["p99"], b[4]["max"])
              if args.check else "not checked")
        print("| %s | %d | %.2f | %d | %d | %d, %d | %.1f, %d, %.1f | %.1f, %d, %.1f, %d | %.2f "
              "| %.0f | %s |" % (
                  name, grid.GetNumberOfCells(), seconds, convexify.GetNumberOfImaginaryCells(),
                  convexify.GetNumberOfSteinerPoints(), convexify.GetNumberOfMergedPoints(),
                  convexify.GetNumberOfDroppedTriangles(), a[0], a[1], a[2] / 1e6, b[0], b[1],
                  b[2] / 1e6, b[6], b[0] / a[0], diff, vs), flush=True)

    if args.plot:
        plot(points, args.plot, args.size, args.views)


def plot(points, path, size, views):
    """Ratio (log) against peels, one labelled point per scene."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for name, peels, ratio, imaginary in points:
        ax.plot(peels, ratio, "o", color="tab:blue" if ratio < 1 else "tab:red")
        ax.annotate("%s (%.2f)" % (name, imaginary), (peels, ratio), textcoords="offset points",
                    xytext=(5, 4), fontsize=8)
    ax.axhline(1.0, color="gray", lw=0.8)
    ax.set_yscale("log")
    ax.set_xlabel("peels the mesh needs (largest over the orbit)")
    ax.set_ylabel("convexified / peeled, ms per frame")
    ax.set_title("Convexification against depth peeling (%dx%d, %d views, llvmpipe)\n"
                 "(imaginary cells per mesh cell)" % (size, size, views), fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()
