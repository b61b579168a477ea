"""The scene the demo, the reference command and the benchmarks share: a
tetrahedral .vtu, a cool-warm colour map and an opacity ramp over the scalar
range, unit distance 1/20 of the diagonal, a three-quarter view.
"""
import json
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
# Files written by Exodus pipelines carry vtkExodusIIReader's information keys:
# its module defines them (else each one is a "Could not locate key" warning).
import vtkmodules.vtkIOExodus  # noqa: F401,E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
    vtkWindowToImageFilter,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401


def load(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetPointData().GetScalars() is None and grid.GetPointData().GetNumberOfArrays():
        grid.GetPointData().SetActiveScalars(grid.GetPointData().GetArrayName(0))
    return grid


def volume_property(grid):
    """Cool-warm colours and an opacity ramp over the active scalars' range."""
    scalars = grid.GetPointData().GetScalars() or grid.GetCellData().GetScalars()
    if scalars is None:
        raise SystemExit("no point or cell scalars in the dataset")
    lo, hi = scalars.GetRange()
    color = vtkColorTransferFunction()
    for u, rgb in ((0.0, (0.23, 0.30, 0.75)), (0.5, (0.87, 0.87, 0.87)), (1.0, (0.71, 0.02, 0.15))):
        color.AddRGBPoint(lo + u * (hi - lo), *rgb)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(lo + 0.5 * (hi - lo), 0.05)
    opacity.AddPoint(hi, 0.6)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    b = grid.GetBounds()
    diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5
    prop.SetScalarOpacityUnitDistance(diagonal / 20.0)
    return prop


# ParaView's default colour map, for a VTK without ParaView's presets.
COOL_TO_WARM = {"Name": "Cool to Warm", "ColorSpace": "Diverging",
                "RGBPoints": [0, 0.231373, 0.298039, 0.752941, 0.5, 0.865003, 0.865003, 0.865003,
                              1, 0.705882, 0.0156863, 0.14902]}
COLOR_SPACES = {"RGB": "SetColorSpaceToRGB", "HSV": "SetColorSpaceToHSV",
                "Lab": "SetColorSpaceToLab", "Lab/CIEDE2000": "SetColorSpaceToLabCIEDE2000",
                "Diverging": "SetColorSpaceToDiverging", "Step": "SetColorSpaceToStep"}


def colormap_presets():
    """ParaView's colour map presets (vtkSMTransferFunctionPresets), or None
    when this VTK comes without ParaView."""
    try:
        from paraview.modules.vtkRemotingViews import vtkSMTransferFunctionPresets
    except ImportError:
        return None
    return vtkSMTransferFunctionPresets.GetInstance()


def colormap_names():
    presets = colormap_presets()
    if presets is None:
        return [COOL_TO_WARM["Name"]]
    return [presets.GetPresetName(i) for i in range(presets.GetNumberOfPresets())
            if "RGBPoints" in json.loads(presets.GetPresetAsString(i))]


def colormap(name, lo, hi):
    """A vtkColorTransferFunction for ParaView's colour map preset `name`
    over [lo, hi], as ParaView applies one: its points rescaled to the range,
    in its colour space. KeyError for a name that is not a continuous map."""
    presets = colormap_presets()
    names = [] if presets is None else [presets.GetPresetName(i)
                                        for i in range(presets.GetNumberOfPresets())]
    if name in names:
        preset = json.loads(presets.GetPresetAsString(names.index(name)))
    elif name == COOL_TO_WARM["Name"]:
        preset = COOL_TO_WARM
    else:
        raise KeyError(name)
    points = preset.get("RGBPoints")
    if not points:
        raise KeyError(name)
    x0, x1 = points[0], points[-4]
    color = vtkColorTransferFunction()
    getattr(color, COLOR_SPACES.get(preset.get("ColorSpace", "RGB"), "SetColorSpaceToRGB"))()
    for i in range(0, len(points), 4):
        u = (points[i] - x0) / (x1 - x0) if x1 > x0 else 0.0
        color.AddRGBPoint(lo + u * (hi - lo), *points[i + 1:i + 4])
    return color


def paraview_property(grid, unit_distance=None, colormap_name="Cool to Warm", opacity=None):
    """What ParaView 5.11 shows a new volume with: its Cool to Warm colour map
    (or the preset `colormap_name`) and opacity ramp 0 to 1 (or `opacity`:
    (fraction of the range, opacity) pairs) over the active scalars' range,
    and a unit distance of about one cell (the bounds' diagonal over the cube
    root of the number of cells, its approximate cell length), unless
    `unit_distance` is given."""
    scalars = grid.GetPointData().GetScalars() or grid.GetCellData().GetScalars()
    if scalars is None:
        raise SystemExit("no point or cell scalars in the dataset")
    lo, hi = scalars.GetRange()
    ramp = vtkPiecewiseFunction()
    for u, o in opacity or ((0.0, 0.0), (1.0, 1.0)):
        ramp.AddPoint(lo + u * (hi - lo), o)
    prop = vtkVolumeProperty()
    prop.SetColor(colormap(colormap_name, lo, hi))
    prop.SetScalarOpacity(ramp)
    if unit_distance is None:
        b = grid.GetBounds()
        diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5
        unit_distance = diagonal / max(grid.GetNumberOfCells(), 1) ** (1.0 / 3.0)
    prop.SetScalarOpacityUnitDistance(unit_distance)
    return prop


def scene(grid, mapper, size, prop=None):
    """A window of size x size (or size = (width, height)) rendering `grid`
    with `mapper` and `prop` (default volume_property(grid)), from the
    three-quarter view."""
    prop = prop or volume_property(grid)
    b = grid.GetBounds()
    mapper.SetInputData(grid)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(0, 0, 0)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(1.0, 0.7, 1.3)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCamera()
    camera.SetFocalPoint([(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2])
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetMultiSamples(0)
    window.SetSize(*(size if isinstance(size, (tuple, list)) else (size, size)))
    window.AddRenderer(renderer)
    return window, renderer


def save(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def window_rgb(window):
    """RGB of the window's back buffer as a float array (pixels x 3, rows from
    the bottom)."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)


def read_png(path):
    """RGB of a PNG as a float array (pixels x 3)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    return vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(float)




def reference_rgba(grid, prop, camera, size, blend_mode=None, lights=None, planes=None):
    """The CPU reference renderer's image of `grid` seen by `camera` at
    size x size (or (width, height)): float RGBA, pixels x 4, rows from the
    bottom; and the seconds it took."""
    import ppiray
    width, height = size if isinstance(size, (tuple, list)) else (size, size)
    reference = ppiray.vtkUnstructuredGridReferenceRenderer()
    reference.SetInputData(grid)
    reference.SetVolumeProperty(prop)
    reference.SetCamera(camera)
    reference.SetImageSize(width, height)
    if blend_mode is not None:
        reference.SetBlendMode(blend_mode)
    if lights is not None:
        reference.SetLights(lights)
    if planes is not None:
        reference.SetClippingPlanes(planes)
    start = time.perf_counter()
    reference.Update()
    seconds = time.perf_counter() - start
    return vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars()), seconds


def compare_with_reference(image, rgba):
    """Per-channel differences in 1/255 between an 8-bit RGB image (pixels x
    3) and the reference's RGBA, over the covered pixels (either image shows
    something: reference alpha above 0.5/255, or a channel of either at least
    1/255 once rounded). Returns covered, nan (reference pixels with NaN),
    p99, max, above8 (pixels with a channel off by more than 8/255) and
    brighter (the largest signed excess of the image)."""
    nan = int(np.isnan(rgba).any(axis=1).sum())
    exact = 255.0 * np.clip(np.nan_to_num(rgba[:, :3]), 0, 1)
    alpha = np.nan_to_num(rgba[:, 3])
    covered = (alpha > 0.5 / 255) | (np.rint(exact) >= 1).any(axis=1) | (image >= 1).any(axis=1)
    signed = (image - exact)[covered]
    d = np.abs(signed)
    return dict(covered=int(covered.sum()), nan=nan,
                p99=float(np.percentile(d, 99)) if d.size else 0.0,
                max=float(d.max()) if d.size else 0.0,
                above8=int((d.max(axis=1) > 8).sum()) if d.size else 0,
                brighter=float(signed.max()) if d.size else 0.0)
