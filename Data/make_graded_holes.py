"""Make Data/graded_holes.vtu: the benchmark's non-convex scene.

A rectilinear grid whose spacing grows geometrically along every axis, from
0.002 at x = 0 to 0.2 at x = 1 and from 0.005 to 0.1 along y and z (edge
lengths varying 100x, cell volumes 10^5 x over the mesh), three
spherical holes carved out (one reaching the surface, so the boundary is
non-convex), split into tetrahedra by vtkDataSetTriangleFilter. Point scalar
"s": a smooth field with a sharp front near the fine end,
s = exp(-((y-0.5)^2 + (z-0.5)^2) / 0.08) + 0.5 tanh((x - 0.05) / 0.01).

Run with VTK's Python: Module/run python Data/make_graded_holes.py
"""
import math

from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkImplicitBoolean, vtkRectilinearGrid, vtkSphere

from carve import carve_and_write


def geometric(first, last, total):
    """Coordinates from 0 to `total` with spacing growing from `first` to about `last`."""
    ratio = 1.0
    n = 2
    while True:  # smallest n whose geometric series with the end spacings covers `total`
        ratio = (last / first) ** (1.0 / (n - 1))
        if first * (ratio ** n - 1) / (ratio - 1) >= total:
            break
        n += 1
    coords = [0.0]
    step = first
    while coords[-1] < total - 1e-12:
        coords.append(min(total, coords[-1] + step))
        step *= ratio
    return coords


def array(values):
    a = vtkDoubleArray()
    for v in values:
        a.InsertNextValue(v)
    return a


x = geometric(0.002, 0.2, 1.0)
y = geometric(0.005, 0.1, 1.0)
grid = vtkRectilinearGrid()
grid.SetDimensions(len(x), len(y), len(y))
grid.SetXCoordinates(array(x))
grid.SetYCoordinates(array(y))
grid.SetZCoordinates(array(y))
s = vtkDoubleArray()
s.SetName("s")
for k in range(len(y)):
    for j in range(len(y)):
        for i in range(len(x)):
            r2 = (y[j] - 0.5) ** 2 + (y[k] - 0.5) ** 2
            s.InsertNextValue(math.exp(-r2 / 0.08) + 0.5 * math.tanh((x[i] - 0.05) / 0.01))
grid.GetPointData().SetScalars(s)

holes = vtkImplicitBoolean()
holes.SetOperationTypeToUnion()
for centre, radius in (((0.3, 0.5, 0.5), 0.18), ((0.7, 0.25, 0.7), 0.15), ((0.6, 0.85, 0.2), 0.2)):
    ball = vtkSphere()
    ball.SetCenter(centre)
    ball.SetRadius(radius)
    holes.AddFunction(ball)
path, tets = carve_and_write(grid, holes, "graded_holes.vtu")
print(path, tets, "tetrahedra,", len(x) - 1, "x", len(y) - 1, "x", len(y) - 1,
      "voxels before the holes")
