"""The notch tetrahedralized (#37 item 2): its cells as the file types them, and as what they are.

    Module/run python Documentation/datasets/notch_tetrahedralized.py [--size 256] [--brute-force K]

notch/notch_stress.vtk (data root) holds 20-node hexahedra and 15-node
wedges typed VTK_HEXAHEDRON and VTK_WEDGE with all their point ids (the
mapper warns: VTK's cells, and so the mapper, use the first 8 and 6).
vtkDataSetTriangleFilter hands the triangulator a parametric coordinate per
point id from the linear cell's table, which has 8 (6): the other ids get
whatever follows it in memory, and each cell becomes a tangle of
overlapping, flat and inverted tetrahedra. The same cells retyped
VTK_QUADRATIC_HEXAHEDRON and VTK_QUADRATIC_WEDGE (same ids) triangulate
into a conforming mesh. For both: the open faces linked by geometry
(ppirayNonConformingFaces.h), the peels, and the image against the CPU
reference under a field linear in the coordinates (the file's stress is
NaN at its mid-edge nodes; with a linear field the union of overlapping
cells is the one right answer), ppiray_scene's view and transfer function;
and the seconds of vtkTetrahedralCellTextures::BuildGeometry().
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Testing", "Python"))
from ppiray_datasets import legacy  # noqa: E402
from ppiray_scene import (compare_with_reference, reference_rgba, scene,  # noqa: E402
                          volume_property, window_rgb)

import numpy as np  # noqa: E402
import ppiray  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, VTK_QUADRATIC_HEXAHEDRON,  # noqa: E402
                                           VTK_QUADRATIC_WEDGE, VTK_WEDGE, vtkUnstructuredGrid)
from vtkmodules.vtkFiltersCore import vtkArrayCalculator  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter  # noqa: E402

QUADRATIC = {(VTK_HEXAHEDRON, 20): VTK_QUADRATIC_HEXAHEDRON, (VTK_WEDGE, 15): VTK_QUADRATIC_WEDGE}


def retyped(grid):
    """The same points and ids, a cell with mid-edge nodes typed as one."""
    out = vtkUnstructuredGrid()
    out.SetPoints(grid.GetPoints())
    out.GetPointData().ShallowCopy(grid.GetPointData())
    out.Allocate(grid.GetNumberOfCells())
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        key = (grid.GetCellType(c), ids.GetNumberOfIds())
        out.InsertNextCell(QUADRATIC.get(key, key[0]), ids)
    return out


def brute_force(tets, prop, renderer, image, reference, pixels):
    """Emission and absorption along the rays of the `pixels` pixels farthest
    from the reference, sampled at 4,000 points across the bounds; a sample
    counts where any tetrahedron holds it (barycentric coordinates, numpy):
    the union of the cells, independent of both renderers."""
    size = renderer.GetRenderWindow().GetSize()[0]
    points = vtk_to_numpy(tets.GetPoints().GetData()).astype(float)
    corners = points[vtk_to_numpy(tets.GetCells().GetConnectivityArray()).reshape(-1, 4)]
    edges = np.stack([corners[:, k] - corners[:, 0] for k in (1, 2, 3)], axis=2)
    solid = np.abs(np.linalg.det(edges)) > 1e-14 * np.abs(edges).max(axis=(1, 2)) ** 3
    inverse = np.zeros_like(edges)
    inverse[solid] = np.linalg.inv(edges[solid])
    colors, opacity = prop.GetRGBTransferFunction(), prop.GetScalarOpacity()
    unit = prop.GetScalarOpacityUnitDistance()
    exact = 255 * np.clip(np.nan_to_num(reference[:, :3]), 0, 1)
    b = np.array(tets.GetBounds())
    centre, radius = (b[0::2] + b[1::2]) / 2, np.linalg.norm(b[1::2] - b[0::2]) / 2

    def world(px, py, z):
        renderer.SetDisplayPoint(px + 0.5, py + 0.5, z)
        renderer.DisplayToWorld()
        w = renderer.GetWorldPoint()
        return np.array(w[:3]) / w[3]

    for i in np.argsort(-np.abs(image - exact).max(axis=1))[:pixels]:
        px, py = i % size, i // size
        origin = world(px, py, 0.0)
        direction = world(px, py, 1.0) - origin
        direction /= np.linalg.norm(direction)
        ts = np.linspace(-radius, radius, 4000) + np.dot(centre - origin, direction)
        dt = ts[1] - ts[0]
        rgb, transparency = np.zeros(3), 1.0
        for t in ts:
            x = origin + t * direction
            lam = np.einsum("tij,tj->ti", inverse, x - corners[:, 0])
            if (solid & (lam.min(axis=1) >= -1e-9) & (lam.sum(axis=1) <= 1 + 1e-9)).any():
                s = np.dot([1.0, 0.5, 0.3], x)
                a = 1 - np.exp(-opacity.GetValue(s) * dt / unit)
                rgb += transparency * a * np.array(colors.GetColor(s))
                transparency *= 1 - a
        print(f"  pixel ({px}, {py}): brute force {np.round(255 * rgb, 1)}, reference "
              f"{np.round(exact[i], 1)}, PPIRay {image[i]}")


def measure(name, grid, size, pixels=0):
    """Prints and returns (as a dict) what the module docstring lists for
    `grid` tetrahedralized."""
    split = vtkDataSetTriangleFilter()
    split.SetInputData(grid)
    split.Update()
    tets = split.GetOutput()
    tets.GetPointData().SetActiveScalars("f")
    cells = ppiray.vtkTetrahedralCellTextures()
    start = time.perf_counter()
    cells.BuildGeometry(tets)
    seconds = time.perf_counter() - start
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    prop = volume_property(tets)
    window, renderer = scene(tets, mapper, size, prop)
    window.Render()
    reference = reference_rgba(tets, prop, renderer.GetActiveCamera(), size)[0]
    image = window_rgb(window)
    check = compare_with_reference(image, reference)
    print(f"{name}: {tets.GetNumberOfCells()} tetrahedra, "
          f"{cells.GetNumberOfDegenerateTetrahedra()} flat, "
          f"{cells.GetNumberOfFoldedFaces()} folded faces; open faces linked by geometry "
          f"{cells.GetNumberOfNonConformingFaces()} (of them across a lens "
          f"{cells.GetNumberOfLensFaces()}; BuildGeometry {seconds:.2f} s); peels "
          f"{mapper.GetStatistics().GetNumberOfPeels()}; against the reference: {check}")
    if pixels:
        brute_force(tets, prop, renderer, image, reference, pixels)
    return dict(check, peels=mapper.GetStatistics().GetNumberOfPeels(),
                lenses=cells.GetNumberOfLensFaces())


def notch_with_linear_field():
    """notch_stress.vtk with f = x + 0.5 y + 0.3 z as its active point scalars."""
    calculator = vtkArrayCalculator()
    calculator.SetInputData(legacy("notch/notch_stress.vtk"))
    for k, name in enumerate("xyz"):
        calculator.AddCoordinateScalarVariable(name, k)
    calculator.SetFunction("x+0.5*y+0.3*z")
    calculator.SetResultArrayName("f")
    calculator.Update()
    return calculator.GetOutput()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--brute-force", type=int, default=0, metavar="K",
                        help="sample the union along the K pixels farthest from the reference")
    args = parser.parse_args()
    grid = notch_with_linear_field()
    measure("as typed in the file (VTK_HEXAHEDRON, 20 ids)", grid, args.size, args.brute_force)
    measure("retyped VTK_QUADRATIC_HEXAHEDRON", retyped(grid), args.size, args.brute_force)


if __name__ == "__main__":
    main()
