"""An image clipped and tetrahedralized, convexified (#37 item 1).

    Module/run python Documentation/datasets/clipped_convexify.py [--extents 6 8 12] [--size 256]

What ParaView's Clip and Tetrahedralize make of an image, built as
Convexify/Testing/Cxx/PPIRayClippedImage.h builds it (VTK's wavelet over
[-n, n]^3 cut by a sphere, a slanted plane and a thin gap, then
vtkDataSetTriangleFilter), at larger extents than the test's. Prints, per
extent, the convexifier's counts (points merged, flat tetrahedra left out,
imaginary cells, Steiner points, seconds), whether it refuses the mesh with
Tolerance 0, and for ppiray_scene's view and transfer function the peels
as it is and convexified, the largest difference between the two images
and the convexified image against the CPU reference of the mesh.
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Testing", "Python"))
from ppiray_scene import (compare_with_reference, reference_rgba, scene,  # noqa: E402
                          volume_property, window_rgb)

import ppiray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImplicitBoolean, vtkPlane, vtkSphere  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkClipDataSet, vtkDataSetTriangleFilter  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402


def clipped_image(n):
    """The wavelet over [-n, n]^3 clipped and tetrahedralized."""
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-n, n, -n, n, -n, n)
    sphere = vtkSphere()
    sphere.SetRadius(0.55 * n)
    sphere.SetCenter(0.3 * n, 0.2 * n, 0.0)
    slant = vtkPlane()
    slant.SetNormal(1.0, 0.4, 0.3)
    slant.SetOrigin(-0.4 * n, 0.0, 0.0)
    below, above = vtkPlane(), vtkPlane()
    below.SetNormal(0.0, 1.0, 0.2)
    below.SetOrigin(0.0, -0.05 * n, 0.0)
    above.SetNormal(0.0, -1.0, -0.2)
    above.SetOrigin(0.0, 0.05 * n, 0.0)
    gap = vtkImplicitBoolean()
    gap.SetOperationTypeToIntersection()
    gap.AddFunction(below)
    gap.AddFunction(above)
    clips = [vtkClipDataSet() for _ in range(3)]  # held: a port does not hold its filter
    for k, function in enumerate((sphere, slant, gap)):
        clips[k].SetInputConnection((clips[k - 1] if k else wavelet).GetOutputPort())
        clips[k].SetClipFunction(function)
    split = vtkDataSetTriangleFilter()
    split.SetInputConnection(clips[-1].GetOutputPort())
    split.Update()
    return split.GetOutput()


def render(grid, prop, size, camera=None):
    """The image, peels and camera of `grid` (from `camera`, else the scene's)."""
    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    window, renderer = scene(grid, mapper, size, prop)
    if camera is not None:
        renderer.GetActiveCamera().DeepCopy(camera)
        renderer.ResetCameraClippingRange()
    window.Render()
    image = window_rgb(window)
    camera = renderer.GetActiveCamera()
    peels = mapper.GetStatistics().GetNumberOfPeels()
    window.Finalize()
    return image, peels, camera


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--extents", type=int, nargs="+", default=[6, 8, 12])
    parser.add_argument("--size", type=int, default=256)
    args = parser.parse_args()
    for n in args.extents:
        grid = clipped_image(n)
        exact = ppiray.vtkUnstructuredGridConvexify()
        exact.SetTolerance(0.0)
        exact.GlobalWarningDisplayOff()
        exact.SetInputData(grid)
        exact.Update()
        convexify = ppiray.vtkUnstructuredGridConvexify()
        convexify.SetInputData(grid)
        start = time.perf_counter()
        convexify.Update()
        seconds = time.perf_counter() - start
        prop = volume_property(grid)
        peeled, peels, camera = render(grid, prop, args.size)
        convex, convex_peels, _ = render(convexify.GetOutput(), prop, args.size, camera)
        largest = int(np.abs(peeled.astype(int) - convex.astype(int)).max())
        reference = reference_rgba(grid, prop, camera, args.size)[0]
        print(f"[-{n}, {n}]^3: {grid.GetNumberOfCells()} tetrahedra; merged "
              f"{convexify.GetNumberOfMergedPoints()} points, left out "
              f"{convexify.GetNumberOfFlatTetrahedra()} flat tetrahedra; "
              f"{convexify.GetNumberOfImaginaryCells()} imaginary, "
              f"{convexify.GetNumberOfSteinerPoints()} Steiner points, {seconds:.2f} s; "
              f"Tolerance 0: {exact.GetNumberOfImaginaryCells()} imaginary; peels "
              f"{peels} as it is, {convex_peels} convexified; max {largest}/255 between them; "
              f"convexified against the reference: "
              f"{compare_with_reference(convex, reference)}")


if __name__ == "__main__":
    main()
