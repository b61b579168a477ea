"""The scene the demo, the reference command and the benchmarks share: a
tetrahedral .vtu, a cool-warm colour map and an opacity ramp over the scalar
range, unit distance 1/20 of the diagonal, a three-quarter view.
"""
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
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


def paraview_property(grid, unit_distance=None):
    """What ParaView 5.11 shows a new volume with: its Cool to Warm colour map
    (three points in the Diverging colour space) and opacity ramp 0 to 1 over
    the active scalars' range, and a unit distance of about one cell (the
    bounds' diagonal over the cube root of the number of cells, its
    approximate cell length), unless `unit_distance` is given."""
    scalars = grid.GetPointData().GetScalars() or grid.GetCellData().GetScalars()
    if scalars is None:
        raise SystemExit("no point or cell scalars in the dataset")
    lo, hi = scalars.GetRange()
    color = vtkColorTransferFunction()
    color.SetColorSpaceToDiverging()
    color.AddRGBPoint(lo, 0.231373, 0.298039, 0.752941)
    color.AddRGBPoint(0.5 * (lo + hi), 0.865003, 0.865003, 0.865003)
    color.AddRGBPoint(hi, 0.705882, 0.0156863, 0.14902)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(hi, 1.0)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    if unit_distance is None:
        b = grid.GetBounds()
        diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5
        unit_distance = diagonal / max(grid.GetNumberOfCells(), 1) ** (1.0 / 3.0)
    prop.SetScalarOpacityUnitDistance(unit_distance)
    return prop


def scene(grid, mapper, size, prop=None):
    """A window of size x size rendering `grid` with `mapper` and `prop`
    (default volume_property(grid)), from the three-quarter view."""
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
    window.SetSize(size, size)
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


