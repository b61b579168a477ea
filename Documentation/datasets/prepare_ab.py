"""Preparation of a conforming tetrahedral mesh, for A/B between builds.

    PYTHONPATH=A/lib/python3.11/site-packages LD_LIBRARY_PATH=A/lib \\
      /usr/bin/python3 Documentation/datasets/prepare_ab.py [N]

vtkRTAnalyticSource over [-N, N]^3 (default 24: 552,960 tetrahedra) through
vtkDataSetTriangleFilter; prints the seconds of two
vtkTetrahedralCellTextures::BuildGeometry() calls of the build on the path.
"""
import sys
import time

import ppiray
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource

n = int(sys.argv[1]) if len(sys.argv) > 1 else 24
source = vtkRTAnalyticSource()
source.SetWholeExtent(-n, n, -n, n, -n, n)
split = vtkDataSetTriangleFilter()
split.SetInputConnection(source.GetOutputPort())
split.Update()
grid = split.GetOutput()
for attempt in range(2):
    cells = ppiray.vtkTetrahedralCellTextures()
    start = time.perf_counter()
    cells.BuildGeometry(grid)
    print(f"{grid.GetNumberOfCells()} tetrahedra: BuildGeometry {time.perf_counter() - start:.3f} s")
