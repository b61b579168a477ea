"""Module/run python Testing/Python/ppiray_large_mesh.py [--voxels N] [--size S] [--check S]

A generated mesh far larger than the test meshes: the cube [-1, 1]^3 in N^3
voxels, each split into six tetrahedra around its main diagonal (6 N^3
tetrahedra: N = 189 gives 40.5 M), with the scalar
s = sin(3x) cos(2y) + z^2 at the points, rendered by
vtkUnstructuredGridGPURayCastMapper with the demo's transfer function
(ppiray_scene.volume_property) at unit distance 0.5. Prints the build and upload time (first
frame), the time of a second frame, the GPU bytes and the process's peak
memory; then checks
a small image (--check S pixels square, same camera) against the CPU
reference renderer: p99 and max per channel, pixels covered, NaN. Not a
ctest test (minutes and gigabytes); its numbers go in
Documentation/hardening.md with the command that made them.
"""
import argparse
import resource
import sys
import time

import numpy as np


def block_grid(n, cell_type, corners):
    """The unstructured grid of the cube [-1, 1]^3 on (n + 1)^3 points, cells
    of `cell_type` with point ids `corners` (cells x corners), the scalar
    s = sin(3x) cos(2y) + z^2 at the points."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid
    axis = np.linspace(-1.0, 1.0, n + 1)
    z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")
    coordinates = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(coordinates.astype(np.float64), deep=1))
    cells = vtkCellArray()
    width = corners.shape[1]
    offsets = np.arange(0, width * len(corners) + 1, width, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=1),
                  numpy_to_vtkIdTypeArray(corners.astype(np.int64).ravel(), deep=1))
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)
    grid.SetCells(cell_type, cells)
    s = np.sin(3.0 * coordinates[:, 0]) * np.cos(2.0 * coordinates[:, 1]) + coordinates[:, 2] ** 2
    array = numpy_to_vtk(s.astype(np.float64), deep=1)
    array.SetName("s")
    grid.GetPointData().SetScalars(array)
    return grid


def voxel_corners(n):
    """Point ids of the 8 corners of each of the n^3 voxels (bit 0 x, bit 1 y,
    bit 2 z), as (voxels, 8)."""
    i = np.arange(n)
    k3, j3, i3 = np.meshgrid(i, i, i, indexing="ij")
    base = ((k3 * (n + 1) + j3) * (n + 1) + i3).ravel()
    m = n + 1
    offset = [0, 1, m, m + 1, m * m, m * m + 1, m * m + m, m * m + m + 1]
    return np.stack([base + o for o in offset], axis=1)


def tetrahedral_block(n):
    """The unstructured grid of n^3 voxels in [-1, 1]^3, 6 tetrahedra each."""
    from vtkmodules.vtkCommonDataModel import VTK_TETRA
    corners = voxel_corners(n)
    # The six tetrahedra around the diagonal 0-7 walk the corners through
    # paths 0 -> a -> b -> 7; half the paths wind negatively: two corners
    # swapped there.
    paths = [(0, 1, 3, 7), (0, 5, 1, 7), (0, 3, 2, 7), (0, 2, 6, 7), (0, 4, 5, 7), (0, 6, 4, 7)]
    tets = np.stack([corners[:, list(path)] for path in paths], axis=1).reshape(-1, 4)
    return block_grid(n, VTK_TETRA, tets)


def hexahedral_block(n):
    """The unstructured grid of n^3 hexahedra in [-1, 1]^3."""
    from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON
    corners = voxel_corners(n)
    return block_grid(n, VTK_HEXAHEDRON, corners[:, [0, 1, 3, 2, 4, 5, 7, 6]])


def peak_gigabytes():
    """The process's peak resident memory so far."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--voxels", type=int, default=189, help="N: 6 N^3 tetrahedra (189: 40.5 M)")
    parser.add_argument("--size", type=int, default=512, help="image size for the timing")
    parser.add_argument("--check", type=int, default=48, help="image size checked against the reference")
    args = parser.parse_args()

    import ppiray
    from ppiray_scene import (compare_with_reference, reference_rgba, scene, volume_property,
                              window_rgb)

    start = time.perf_counter()
    grid = tetrahedral_block(args.voxels)
    print("mesh: %d tetrahedra, %d points, generated in %.1f s; peak memory so far %.1f GB"
          % (grid.GetNumberOfCells(), grid.GetNumberOfPoints(), time.perf_counter() - start,
             peak_gigabytes()), flush=True)

    prop = volume_property(grid)
    prop.SetScalarOpacityUnitDistance(0.5)

    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    window, renderer = scene(grid, mapper, args.size, prop)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(2.5, -1.8, 2.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.ResetCamera()

    start = time.perf_counter()
    window.Render()
    first = time.perf_counter() - start
    start = time.perf_counter()
    window.Render()
    second = time.perf_counter() - start
    print("%dx%d: first frame (build, upload, render) %.1f s, second frame %.2f s, %d peels, "
          "%d continuations, %.2f GB on the GPU; peak memory so far %.1f GB"
          % (args.size, args.size, first, second, mapper.GetStatistics().GetNumberOfPeels(),
             mapper.GetStatistics().GetNumberOfContinuations(), mapper.GetStatistics().GetGPUMemorySize() / 1e9,
             peak_gigabytes()), flush=True)

    window.SetSize(args.check, args.check)
    window.Render()
    image = window_rgb(window)
    # The mapper's CPU and GPU copies go before the reference builds its own.
    window.Finalize()
    renderer.RemoveAllViewProps()
    del window, renderer, mapper
    rgba, seconds = reference_rgba(grid, prop, camera, args.check)
    c = compare_with_reference(image, rgba)
    print("check %dx%d against the reference (%.0f s): %d pixels covered, p99 %.2f, max %.2f /255, "
          "%d NaN" % (args.check, args.check, seconds, c["covered"], c["p99"], c["max"], c["nan"]))
    print("peak memory of the process: %.1f GB" % peak_gigabytes())
    ok = c["covered"] > args.check ** 2 // 4 and c["p99"] <= 1.0 and c["nan"] == 0
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
