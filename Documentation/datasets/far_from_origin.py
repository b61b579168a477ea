"""A mesh far from the origin against the same mesh at the origin (#37).

    Module/run python Documentation/datasets/far_from_origin.py

For Data/'s carved meshes (centred, then translated by (1e6, -2e6, 3e6)),
300 x 300, llvmpipe: the images at the origin and far away compared pixel by
pixel (p99 and max over the covered pixels, 1/255) and their peels, with
  outside   the camera outside, looking at the centre;
  inside    the camera inside the mesh, perspective (near-plane sections);
  float32   the points stored as float32 (0.25 apart at 3e6), and that image
            against the reference renderer of the same float32 grid.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Testing", "Python"))
from ppiray_scene import (compare_with_reference, load, reference_rgba, scene,  # noqa: E402
                          volume_property, window_rgb)

import ppiray  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid  # noqa: E402

FAR = np.array([1e6, -2e6, 3e6])
SIZE = 300


def translated(grid, xyz, offset, dtype):
    moved = vtkUnstructuredGrid()
    moved.ShallowCopy(grid)
    points = vtkPoints()
    points.SetData(numpy_to_vtk((xyz + offset).astype(dtype), deep=1))
    moved.SetPoints(points)
    return moved


def render(grid, prop, offset, extent, inside):
    """The image (pixels x 3), peels and camera of `grid` seen from the view."""
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    window, renderer = scene(grid, mapper, SIZE, prop)
    camera = renderer.GetActiveCamera()
    camera.SetViewUp(0, 1, 0)
    if inside:
        camera.SetPosition(*(offset + np.array([0.05, 0.1, 0.02]) * extent))
        camera.SetFocalPoint(*(offset + np.array([0.3, -0.2, 0.4]) * extent))
        camera.SetClippingRange(0.01 * extent, 3 * extent)
    else:
        camera.SetFocalPoint(*offset)
        camera.SetPosition(*(offset + np.array([1.0, 0.7, 1.3]) * 2.5 * extent))
        renderer.ResetCameraClippingRange()
    window.Render()
    image = window_rgb(window).astype(np.int64).reshape(-1, 3)
    peels = mapper.GetStatistics().GetNumberOfPeels()
    window.Finalize()  # one X connection at a time
    return image, peels, camera


def compare(a, b):
    d = np.abs(a - b).max(axis=1)
    covered = (a.sum(axis=1) > 0) | (b.sum(axis=1) > 0)
    return covered.sum(), np.percentile(d[covered], 99), d.max()


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data")
    for name in ("wavelet_hole.vtu", "graded_holes.vtu"):
        grid = load(os.path.join(root, name))
        prop = volume_property(grid)
        xyz = vtk_to_numpy(grid.GetPoints().GetData()).astype(np.float64)
        xyz -= xyz.mean(axis=0)
        extent = np.ptp(xyz, axis=0).max()
        for view in ("outside", "inside", "float32"):
            dtype = np.float32 if view == "float32" else np.float64
            inside = view == "inside"
            near, peels_near, _ = render(translated(grid, xyz, 0.0, dtype), prop, 0.0 * FAR,
                                         extent, inside)
            far_grid = translated(grid, xyz, FAR, dtype)
            far, peels_far, camera = render(far_grid, prop, FAR, extent, inside)
            covered, p99, largest = compare(near, far)
            line = ("%s, %s: peels %d and %d, %d pixels covered, far against origin p99 %.2f "
                    "max %d" % (name, view, peels_near, peels_far, covered, p99, largest))
            if view == "float32":
                rgba, _ = reference_rgba(far_grid, prop, camera, SIZE)
                r = compare_with_reference(far.astype(np.float64), rgba)
                line += "; far against the reference of the same grid p99 %.2f max %.2f" % (
                    r["p99"], r["max"])
            print(line, flush=True)


if __name__ == "__main__":
    main()
