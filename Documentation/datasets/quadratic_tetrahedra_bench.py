"""Frame time and GPU bytes per cell of ten-node tetrahedra rendered with
their quadratic field against the same cells through their corners
(HEXAHEDRON_SUBDIVIDE), in one process, alternating, steady frames (the
first frame of each mode not counted). The mesh: an n^3 lattice of cubes,
six tetrahedra each, mid-edge nodes at the midpoints, or every node moved
by a smooth deformation (--bend: curved cells, refined by the mapper); a
smooth field at the nodes.

Usage: Module/run python Documentation/datasets/quadratic_tetrahedra_bench.py
       [--cubes 20] [--bend 0.06] [--size 512] [--frames 5] [--rounds 2]
"""
import argparse
import math
import os
import sys
import time

import ppiray
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_QUADRATIC_TETRA, vtkUnstructuredGrid

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Testing", "Python"))
from ppiray_scene import scene, volume_property  # noqa: E402

EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
PATHS = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]


def quadratic_block(cubes, bend):
    points = vtkPoints()
    points.SetDataTypeToDouble()
    ids, mids = {}, {}

    def point(i, j, k):
        if (i, j, k) not in ids:
            ids[(i, j, k)] = points.InsertNextPoint(i / cubes, j / cubes, k / cubes)
        return ids[(i, j, k)]

    grid = vtkUnstructuredGrid()
    for k in range(cubes):
        for j in range(cubes):
            for i in range(cubes):
                for path in PATHS:
                    c = [i, j, k]
                    tet = [point(*c)]
                    for axis in path:
                        c[axis] += 1
                        tet.append(point(*c))
                    nodes = list(tet)
                    for a, b in EDGES:
                        key = (min(tet[a], tet[b]), max(tet[a], tet[b]))
                        if key not in mids:
                            x, y = points.GetPoint(key[0]), points.GetPoint(key[1])
                            mids[key] = points.InsertNextPoint(
                                [(x[m] + y[m]) / 2 for m in range(3)])
                        nodes.append(mids[key])
                    idlist = vtkIdList()
                    for n in nodes:
                        idlist.InsertNextId(n)
                    grid.InsertNextCell(VTK_QUADRATIC_TETRA, idlist)
    scalars = vtkDoubleArray()
    scalars.SetName("s")
    for p in range(points.GetNumberOfPoints()):
        x, y, z = points.GetPoint(p)
        if bend:
            x, y, z = (x + bend * math.sin(4 * y), y + bend * math.cos(4 * z),
                       z + bend * math.sin(4 * x))
            points.SetPoint(p, x, y, z)
        scalars.InsertNextValue(0.65 + 0.55 * math.sin(5 * x + 0.3) * math.cos(4 * y)
                                * math.sin(3 * z + 0.5))
    grid.SetPoints(points)
    grid.GetPointData().SetScalars(scalars)
    return grid


def window(grid, size):
    """ppiray_scene's window and transfer function, translucent (unit distance 0.5)."""
    prop = volume_property(grid)
    prop.SetScalarOpacityUnitDistance(0.5)
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    win, _ = scene(grid, mapper, size, prop)
    win.SetOffScreenRendering(1)
    return win, mapper


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cubes", type=int, default=20)
    parser.add_argument("--bend", type=float, default=0.0)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--rounds", type=int, default=2)
    args = parser.parse_args()
    grid = quadratic_block(args.cubes, args.bend)
    win, mapper = window(grid, args.size)
    modes = [("quadratic field", mapper.HEXAHEDRON_ACCURATE),
             ("through the corners", mapper.HEXAHEDRON_SUBDIVIDE)]
    print("%d quadratic tetrahedra, bend %g, %d^2" % (grid.GetNumberOfCells(), args.bend,
                                                      args.size))
    for round_ in range(args.rounds):
        for name, mode in modes:
            mapper.SetHexahedronMode(mode)
            start = time.perf_counter()
            win.Render()
            first = 1000 * (time.perf_counter() - start)
            times = []
            for _ in range(args.frames):
                start = time.perf_counter()
                win.Render()
                times.append(1000 * (time.perf_counter() - start))
            stats = mapper.GetStatistics()
            cells = stats.GetNumberOfNativeCells() or stats.GetNumberOfTetrahedra()
            print("round %d, %s: first frame %.0f ms, steady %.0f ms (median of %d), "
                  "%d cells marched, %.0f GPU bytes per cell, %.1f MB"
                  % (round_ + 1, name, first, sorted(times)[len(times) // 2], args.frames,
                     cells, stats.GetBytesPerCell(), stats.GetCellArrayBytes() / 1e6))


if __name__ == "__main__":
    main()
