"""Scenes of Module/run bench: a mesh, a volume property and a camera each.

(a) wavelet        vtkRTAnalyticSource over [-E, E]^3, tetrahedralized (convex, smooth)
(b) graded         Data/graded_holes.vtu: holes, edge lengths varying 100x, smooth TF
(c) graded-spikes  the same mesh, 70 control points with one-value-wide spikes
(d) graded-opaque  the same mesh, nearly opaque (tau D >> 1: Psi near gamma -> 1)
(e) bluntfin       Blunt Fin (PLOT3D, Density), tetrahedralized: 187,395 tetrahedra
    loxpost        LOX Post (PLOT3D, function 110 = pressure), tetrahedralized: 513,375
(f) bluntfin-hex   Blunt Fin as it is: 37,479 hexahedra (VTK's tetrahedral mappers get
                   the vtkDataSetTriangleFilter output)
    bluntfin-hex-spikes  the same, 70 control points with one-value-wide spikes
    loxpost-hex    LOX Post as it is: 102,675 hexahedra
Non-convex scenes of the convexification comparison (ppiray_convexify_compare.py),
tetrahedralized:
    wavelet-hole   Data/wavelet_hole.vtu: one cavity
    sponge         the wavelet over [-16, 16]^3 with a 6^3 lattice of balls carved out:
                   many re-entries per ray
    disk           disk_out_ref (Exodus, Temp): the CVD reactor, a disk inside a cylinder
    unisim         UNISIM-II (corner-point reservoir, faults, inactive cells hidden; z)
"""
import os

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction, vtkUnstructuredGrid
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOParallel import vtkMultiBlockPLOT3DReader
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolumeProperty

from ppiray_scene import load, volume_property

NAMES = ["wavelet", "graded", "graded-spikes", "graded-opaque", "bluntfin", "loxpost",
         "bluntfin-hex", "bluntfin-hex-spikes", "loxpost-hex"]
HEXAHEDRAL = {"bluntfin-hex", "bluntfin-hex-spikes", "loxpost-hex"}
NON_CONVEX = ["graded", "wavelet-hole", "sponge", "loxpost", "bluntfin", "disk", "unisim"]

DERIVED = {
    "wavelet": "RTData",
    "graded": "s (analytic, see Data/make_graded_holes.py)",
    "graded-spikes": "s",
    "graded-opaque": "s",
    "bluntfin": "Density",
    "loxpost": "pressure (PLOT3D function 110)",
    "bluntfin-hex": "Density",
    "bluntfin-hex-spikes": "Density",
    "loxpost-hex": "pressure (PLOT3D function 110)",
}


def _unstructured(dataset, filter_):
    """`dataset` through `filter_` (which outputs an unstructured grid), detached."""
    filter_.SetInputData(dataset)
    filter_.Update()
    grid = vtkUnstructuredGrid()
    grid.ShallowCopy(filter_.GetOutput())
    return grid


def _tetrahedralize(dataset):
    return _unstructured(dataset, vtkDataSetTriangleFilter())


def _hexahedra(dataset):
    """A structured grid as an unstructured grid of hexahedra."""
    from vtkmodules.vtkFiltersCore import vtkAppendFilter

    return _unstructured(dataset, vtkAppendFilter())


def tetrahedralized(grid):
    """What VTK's tetrahedral mappers get of a hexahedral scene."""
    return _tetrahedralize(grid)


def _plot3d(folder, xyz, q, function, hexahedra=False):
    reader = vtkMultiBlockPLOT3DReader()
    reader.SetXYZFileName(os.path.join(folder, xyz))
    reader.SetQFileName(os.path.join(folder, q))
    reader.AutoDetectFormatOn()
    if function is not None:
        reader.SetScalarFunctionNumber(function)
    reader.Update()
    block = reader.GetOutput().GetBlock(0)
    name = "Density" if function in (None, 100) else block.GetPointData().GetArrayName(
        block.GetPointData().GetNumberOfArrays() - 1)
    grid = _hexahedra(block) if hexahedra else _tetrahedralize(block)
    grid.GetPointData().SetActiveScalars(name)
    return grid


def _spiky_property(lo, hi):
    """70 control points: 10 colour nodes, 60 opacity nodes; 12 spikes, each
    (hi - lo) / 200 wide, 0 -> 0.9 -> 0 over a faint ramp."""
    color = vtkColorTransferFunction()
    for i in range(10):
        u = i / 9.0
        color.AddRGBPoint(lo + u * (hi - lo), 0.2 + 0.8 * u, 0.9 - 0.7 * u * u, 1.0 - u)
    opacity = vtkPiecewiseFunction()
    width = (hi - lo) / 200.0
    opacity.AddPoint(lo, 0.0)
    for i in range(12):
        centre = lo + (i + 1) * (hi - lo) / 13.0
        opacity.AddPoint(centre - 2.0 * width, 0.02)
        opacity.AddPoint(centre - 0.5 * width, 0.0)
        opacity.AddPoint(centre, 0.9)
        opacity.AddPoint(centre + 0.5 * width, 0.0)
        opacity.AddPoint(centre + 2.0 * width, 0.02)
    opacity.AddPoint(hi, 0.05)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(0.05)
    return prop


def _opaque_property(lo, hi):
    prop = volume_property_for_range(lo, hi)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(lo + 0.3 * (hi - lo), 1.0)
    opacity.AddPoint(hi, 1.0)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(0.002)  # tau D reaches ~100 in the coarse cells
    return prop


def volume_property_for_range(lo, hi):
    color = vtkColorTransferFunction()
    for u, rgb in ((0.0, (0.23, 0.30, 0.75)), (0.5, (0.87, 0.87, 0.87)), (1.0, (0.71, 0.02, 0.15))):
        color.AddRGBPoint(lo + u * (hi - lo), *rgb)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    return prop


def _sponge():
    """The wavelet over [-16, 16]^3 without the voxels inside balls of radius
    2 centred on a 6^3 lattice (spacing 32/6), tetrahedralized."""
    from vtkmodules.vtkCommonDataModel import vtkImplicitBoolean, vtkSphere
    from vtkmodules.vtkFiltersExtraction import vtkExtractGeometry
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-16, 16, -16, 16, -16, 16)
    source.Update()
    balls = vtkImplicitBoolean()
    balls.SetOperationTypeToUnion()
    step = 32.0 / 6
    for i in range(6):
        for j in range(6):
            for k in range(6):
                ball = vtkSphere()
                ball.SetCenter(-16 + step * (i + 0.5), -16 + step * (j + 0.5),
                               -16 + step * (k + 0.5))
                ball.SetRadius(2.0)
                balls.AddFunction(ball)
    outside = vtkExtractGeometry()
    outside.SetImplicitFunction(balls)
    outside.ExtractInsideOff()
    outside.ExtractBoundaryCellsOff()
    outside.SetInputData(source.GetOutput())
    outside.Update()
    grid = _tetrahedralize(outside.GetOutput())
    return grid, volume_property(grid)


def build(name, root, data_root, wavelet_extent=16):
    """(grid, vtkVolumeProperty) of scene `name`; None if its data is missing."""
    if name == "wavelet":
        source = vtkRTAnalyticSource()
        e = wavelet_extent
        source.SetWholeExtent(-e, e, -e, e, -e, e)
        source.Update()
        grid = _tetrahedralize(source.GetOutput())
        return grid, volume_property(grid)
    if name == "wavelet-hole":
        grid = load(os.path.join(root, "Data", "wavelet_hole.vtu"))
        return grid, volume_property(grid)
    if name == "sponge":
        return _sponge()
    if name in ("disk", "unisim"):
        import ppiray_datasets
        loader, array, points = ppiray_datasets.DATASETS[
            "disk_out_ref" if name == "disk" else "unisim2"]
        if not os.path.isdir(os.path.join(data_root, "disk_out_ref" if name == "disk"
                                          else "unisim2")):
            return None
        grid = _tetrahedralize(loader())
        ppiray_datasets.select(grid, array, points)
        return grid, volume_property(grid)
    if name.startswith("graded"):
        grid = load(os.path.join(root, "Data", "graded_holes.vtu"))
        lo, hi = grid.GetPointData().GetScalars().GetRange()
        if name == "graded-spikes":
            return grid, _spiky_property(lo, hi)
        if name == "graded-opaque":
            return grid, _opaque_property(lo, hi)
        return grid, volume_property(grid)
    hexahedra = name in HEXAHEDRAL
    path = os.path.join(data_root, "bluntfin" if name.startswith("bluntfin") else "lox_post")
    if not os.path.isdir(path):
        return None
    if name.startswith("bluntfin"):
        grid = _plot3d(path, "bluntfinxyz.bin", "bluntfinq.bin", None, hexahedra)
    else:
        grid = _plot3d(path, "postxyz.bin", "postq.bin", 110, hexahedra)
    if name.endswith("-spikes"):
        lo, hi = grid.GetPointData().GetScalars().GetRange()
        return grid, _spiky_property(lo, hi)
    return grid, volume_property(grid)
