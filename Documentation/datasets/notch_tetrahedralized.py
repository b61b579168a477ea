"""The notch tetrahedralized, a non-conforming and tangled mesh (#37 item 2).

    Module/run python Documentation/datasets/notch_tetrahedralized.py [--size 256]

notch/notch_stress.vtk (data root) holds 20-node hexahedra written with all
20 nodes; vtkDataSetTriangleFilter splits each into tetrahedra over all its
nodes, each cell on its own, so that neighbours triangulate their shared
curved faces differently. Prints the open faces linked by geometry
(ppirayNonConformingFaces.h), the peels, and the image against the CPU
reference under a field linear in the coordinates (the file's stress is
NaN at its mid-edge nodes), ppiray_scene's view and transfer function; and
the seconds of vtkTetrahedralCellTextures::BuildGeometry().
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

import ppiray  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkArrayCalculator  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--size", type=int, default=256)
    args = parser.parse_args()
    calculator = vtkArrayCalculator()
    calculator.SetInputData(legacy("notch/notch_stress.vtk"))
    for k, name in enumerate("xyz"):
        calculator.AddCoordinateScalarVariable(name, k)
    calculator.SetFunction("x+0.5*y+0.3*z")
    calculator.SetResultArrayName("f")
    split = vtkDataSetTriangleFilter()
    split.SetInputConnection(calculator.GetOutputPort())
    split.Update()
    grid = split.GetOutput()
    grid.GetPointData().SetActiveScalars("f")
    cells = ppiray.vtkTetrahedralCellTextures()
    start = time.perf_counter()
    cells.BuildGeometry(grid)
    seconds = time.perf_counter() - start
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    prop = volume_property(grid)
    window, renderer = scene(grid, mapper, args.size, prop)
    window.Render()
    reference = reference_rgba(grid, prop, renderer.GetActiveCamera(), args.size)[0]
    check = compare_with_reference(window_rgb(window), reference)
    print(f"{grid.GetNumberOfCells()} tetrahedra, {cells.GetNumberOfDegenerateTetrahedra()} flat, "
          f"{cells.GetNumberOfFoldedFaces()} folded faces; open faces linked by geometry "
          f"{cells.GetNumberOfNonConformingFaces()} (BuildGeometry {seconds:.2f} s); peels "
          f"{mapper.GetStatistics().GetNumberOfPeels()}; against the reference: {check}")


if __name__ == "__main__":
    main()
