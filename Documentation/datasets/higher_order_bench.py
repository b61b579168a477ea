"""Higher-order cells, kind by kind: error against the CPU reference (VTK's
own interpolation of each cell), steady and first frame, GPU bytes per input
cell, for the mapper refined 0 and 1 levels (NonlinearSubdivisionLevel),
through the corners (HEXAHEDRON_SUBDIVIDE) and VTK's projected tetrahedra
on ParaView's old path (vtkDataSetTriangleFilter, which splits each
higher-order cell into linear tetrahedra over all its nodes). The mesh: an
n^3 block of unit cubes filled with cells of one kind (a hexahedron, two
wedges or six pyramids per cube, nodes at VTK's parametric coordinates,
shared by position), optionally bent (--bend: curved cells); a field that is
no polynomial at the nodes; ppiray_scene's view and transfer function.

Usage: Module/run python Documentation/datasets/higher_order_bench.py
       [--cubes 6] [--size 256] [--frames 3] [--bend 0] [--only hex20,...]
       (--only also takes hex24, wedge12, wedge18, lagrange-hex2,
       lagrange-wedge2, bezier-hex2, bezier-wedge2)
"""
import argparse
import math
import os
import sys
import time

import numpy as np
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import (
    VTK_BEZIER_HEXAHEDRON,
    VTK_BEZIER_WEDGE,
    VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON,
    VTK_BIQUADRATIC_QUADRATIC_WEDGE,
    VTK_HEXAHEDRON,
    VTK_LAGRANGE_HEXAHEDRON,
    VTK_LAGRANGE_WEDGE,
    VTK_PYRAMID,
    VTK_QUADRATIC_HEXAHEDRON,
    VTK_QUADRATIC_LINEAR_WEDGE,
    VTK_QUADRATIC_PYRAMID,
    VTK_QUADRATIC_WEDGE,
    VTK_TRIQUADRATIC_HEXAHEDRON,
    VTK_WEDGE,
    vtkBezierHexahedron,
    vtkBezierWedge,
    vtkBiQuadraticQuadraticHexahedron,
    vtkBiQuadraticQuadraticWedge,
    vtkLagrangeHexahedron,
    vtkLagrangeWedge,
    vtkQuadraticHexahedron,
    vtkQuadraticLinearWedge,
    vtkQuadraticPyramid,
    vtkQuadraticWedge,
    vtkTriQuadraticHexahedron,
    vtkUnstructuredGrid,
)
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkRenderingCore import vtkCamera
from vtkmodules.vtkRenderingVolume import vtkProjectedTetrahedraMapper

import ppiray

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Testing", "Python"))
from ppiray_scene import (  # noqa: E402
    compare_with_reference,
    reference_rgba,
    scene,
    volume_property,
    window_rgb,
)



def prototype(cls, count):
    """A Lagrange or Bezier cell class's cell of `count` nodes (order from the count)."""
    def make():
        cell = cls()
        cell.GetPointIds().SetNumberOfIds(count)
        cell.GetPoints().SetNumberOfPoints(count)
        cell.SetUniformOrderFromNumPoints(count)
        return cell
    return make


# key: (label, cell type, a cell of it, the linear shape filling the cubes)
KINDS = {
    "hex20": ("20-node hexahedra", VTK_QUADRATIC_HEXAHEDRON, vtkQuadraticHexahedron,
              VTK_HEXAHEDRON),
    "hex27": ("27-node hexahedra", VTK_TRIQUADRATIC_HEXAHEDRON, vtkTriQuadraticHexahedron,
              VTK_HEXAHEDRON),
    "wedge15": ("15-node wedges", VTK_QUADRATIC_WEDGE, vtkQuadraticWedge, VTK_WEDGE),
    "pyramid13": ("13-node pyramids", VTK_QUADRATIC_PYRAMID, vtkQuadraticPyramid, VTK_PYRAMID),
    "hex24": ("24-node hexahedra", VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON,
              vtkBiQuadraticQuadraticHexahedron, VTK_HEXAHEDRON),
    "wedge12": ("12-node wedges", VTK_QUADRATIC_LINEAR_WEDGE, vtkQuadraticLinearWedge, VTK_WEDGE),
    "wedge18": ("18-node wedges", VTK_BIQUADRATIC_QUADRATIC_WEDGE, vtkBiQuadraticQuadraticWedge,
                VTK_WEDGE),
    "lagrange-hex2": ("Lagrange hexahedra, order 2", VTK_LAGRANGE_HEXAHEDRON,
                      prototype(vtkLagrangeHexahedron, 27), VTK_HEXAHEDRON),
    "lagrange-wedge2": ("Lagrange wedges, order 2", VTK_LAGRANGE_WEDGE,
                        prototype(vtkLagrangeWedge, 18), VTK_WEDGE),
    "bezier-hex2": ("Bezier hexahedra, order 2", VTK_BEZIER_HEXAHEDRON,
                    prototype(vtkBezierHexahedron, 27), VTK_HEXAHEDRON),
    "bezier-wedge2": ("Bezier wedges, order 2", VTK_BEZIER_WEDGE, prototype(vtkBezierWedge, 18),
                      VTK_WEDGE),
}
DEFAULT_KINDS = "hex20,hex27,wedge15,pyramid13"
# Pyramid bases: each face of the cube wound so that the centre lies above it.
FACES = [((0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)), ((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)),
         ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)), ((0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)),
         ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)), ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1))]


def cube_maps(shape):
    """Maps of a cell's parametric coordinates into the unit cube."""
    if shape == VTK_WEDGE:
        return [lambda p: p, lambda p: (1 - p[0], 1 - p[1], p[2])]
    if shape == VTK_PYRAMID:
        def pyramid(face):
            def map_(p):
                r, s, t = p
                w = ((1 - r) * (1 - s), r * (1 - s), r * s, (1 - r) * s)
                return tuple(0.5 * t + (1 - t) * sum(w[i] * face[i][k] for i in range(4))
                             for k in range(3))
            return map_
        return [pyramid(face) for face in FACES]
    return [lambda p: p]


def block(type_, cell_class, shape, cubes, bend):
    cell = cell_class()
    n = cell.GetNumberOfPoints()
    pcoords = cell.GetParametricCoords()
    nodes = [tuple(pcoords[3 * i:3 * i + 3]) for i in range(n)]
    points = vtkPoints()
    points.SetDataTypeToDouble()
    ids = {}
    grid = vtkUnstructuredGrid()
    for k in range(cubes):
        for j in range(cubes):
            for i in range(cubes):
                for map_ in cube_maps(shape):
                    idlist = vtkIdList()
                    for p in nodes:
                        x = [(c + u) / cubes for c, u in zip((i, j, k), map_(p))]
                        key = tuple(round(v * 1200 * cubes) for v in x)
                        if key not in ids:
                            ids[key] = points.InsertNextPoint(
                                x[0] + bend * math.sin(4 * x[1]), x[1] + bend * math.cos(4 * x[2]),
                                x[2] + bend * math.sin(4 * x[0]))
                        idlist.InsertNextId(ids[key])
                    grid.InsertNextCell(type_, idlist)
    grid.SetPoints(points)
    scalars = vtkDoubleArray()
    scalars.SetName("s")
    for p in range(points.GetNumberOfPoints()):
        x, y, z = points.GetPoint(p)
        scalars.InsertNextValue(0.65 + 0.55 * math.sin(5 * x + 0.3) * math.cos(4 * y)
                                * math.sin(3 * z + 0.5))
    grid.GetPointData().SetScalars(scalars)
    return grid


def frames(window, count):
    """(first frame ms, median steady frame ms)."""
    start = time.perf_counter()
    window.Render()
    window.WaitForCompletion()
    first = 1000 * (time.perf_counter() - start)
    times = []
    for _ in range(count):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(1000 * (time.perf_counter() - start))
    return first, float(np.median(times))


def measure(grid, prop, size, count, camera):
    """Rows (rendering, first ms, steady ms, GPU bytes per cell, RGB image),
    all in one window; `camera` set to its (ppiray_scene's view)."""
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    window, renderer = scene(grid, mapper, size, prop)
    camera.DeepCopy(renderer.GetActiveCamera())
    rows = []
    for name, level, mode in (("level 0", 0, "ACCURATE"), ("level 1", 1, "ACCURATE"),
                              ("through the corners", 0, "SUBDIVIDE")):
        mapper.SetNonlinearSubdivisionLevel(level)
        mapper.SetHexahedronMode(getattr(mapper, "HEXAHEDRON_" + mode))
        first, steady = frames(window, count)
        stats = mapper.GetStatistics()
        rows.append((name, first, steady, stats.GetCellArrayBytes() / grid.GetNumberOfCells(),
                     window_rgb(window)))
    split = vtkDataSetTriangleFilter()
    split.SetInputData(grid)
    split.Update()
    projected = vtkProjectedTetrahedraMapper()
    projected.SetInputData(split.GetOutput())
    renderer.GetVolumes().GetLastProp().SetMapper(projected)
    first, steady = frames(window, count)
    rows.append(("projected tetrahedra (%d)" % split.GetOutput().GetNumberOfCells(), first,
                 steady, float("nan"), window_rgb(window)))
    window.Finalize()
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cubes", type=int, default=6)
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--bend", type=float, default=0.0)
    parser.add_argument("--only", default=DEFAULT_KINDS, help="of: " + ", ".join(KINDS))
    args = parser.parse_args()
    print("| kind | rendering | first frame ms | steady ms | GPU bytes per cell | p99 | max |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for key in args.only.split(","):
        label, type_, cell_class, shape = KINDS[key]
        grid = block(type_, cell_class, shape, args.cubes, args.bend)
        prop = volume_property(grid)
        camera = vtkCamera()
        rows = measure(grid, prop, args.size, args.frames, camera)
        # The reference last: no window is opened after its threads ran.
        rgba, seconds = reference_rgba(grid, prop, camera, args.size)
        for name, first, steady, bytes_, image in rows:
            e = compare_with_reference(image, rgba)
            print("| %s (%d) | %s | %.0f | %.0f | %s | %.2f | %.2f |"
                  % (label, grid.GetNumberOfCells(), name, first, steady,
                     "" if math.isnan(bytes_) else "%.0f" % bytes_, e["p99"], e["max"]),
                  flush=True)
        print("(reference: %.1f s, %d pixels covered)" % (seconds, e["covered"]), file=sys.stderr)


if __name__ == "__main__":
    main()
