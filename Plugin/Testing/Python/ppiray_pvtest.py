"""Shared by the plugin's pvbatch tests: load the plugin, a reproducible scene
shown as "PPIRay Volume", and image checks.

Scene: the wavelet (RTData) tetrahedralized, a blue-yellow-red colour map and a
linear opacity ramp given explicitly (not rescaled from the data, so that every
rank of a parallel run uses the same transfer function).
"""
import os

from paraview import servermanager
from paraview.simple import (
    CreateView,
    GetColorTransferFunction,
    GetOpacityTransferFunction,
    LoadPlugin,
    Render,
    SaveScreenshot,
    Show,
)

REPRESENTATION = "PPIRay Volume"
SKIP = 125  # ctest SKIP_RETURN_CODE
RGB_POINTS = [40.0, 0.1, 0.1, 0.8, 150.0, 0.9, 0.9, 0.2, 260.0, 0.9, 0.1, 0.1]
OPACITY_POINTS = [40.0, 0.0, 0.5, 0.0, 260.0, 0.5, 0.5, 0.0]
BACKGROUND = (0.32, 0.34, 0.43)  # render_view()'s


def load_plugin(path):
    """LoadPlugin on this process (in pvbatch --mpi every rank runs the
    session, so the plugin is loaded where the representation lives)."""
    if not os.path.exists(path):
        fail("plugin not found: %s" % path)
    LoadPlugin(path, remote=False, ns=globals())


def fail(message):
    """Stop the test. pvbatch 5.11 returns 1 on any exception but tears down
    badly after sys.exit() (X errors while views are destroyed), so tests
    raise instead of calling sys.exit()."""
    print("FAILED:", message, flush=True)
    raise RuntimeError(message)


def finish(failures):
    """Print the failures and raise if there are any (see fail())."""
    for failure in failures:
        print("FAILED:", failure, flush=True)
    if failures:
        raise RuntimeError("%d check(s) failed" % len(failures))


def write_pvd(folder, grids):
    """A time series: `grids` as step<k>.vtu (time k) and a series.pvd naming
    them, in `folder`; the .pvd's path."""
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    os.makedirs(folder, exist_ok=True)
    entries = []
    for k, grid in enumerate(grids):
        name = "step%d.vtu" % k
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetInputData(grid)
        writer.SetFileName(os.path.join(folder, name))
        writer.Write()
        entries.append('    <DataSet timestep="%d" file="%s"/>' % (k, name))
    path = os.path.join(folder, "series.pvd")
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                "  <Collection>\n%s\n  </Collection>\n</VTKFile>\n" % "\n".join(entries))
    return path


def render_view(size=(300, 300)):
    view = CreateView("RenderView")
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.Background = list(BACKGROUND)
    try:  # ParaView >= 5.10 has palettes; keep the background we set.
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view


def show_volume(source, view, array, rgb_points=RGB_POINTS, opacity_points=OPACITY_POINTS,
                unit_distance=4.0):
    """Show `source` as PPIRay Volume coloured by point array `array`."""
    display = Show(source, view)
    display.SetRepresentationType(REPRESENTATION)
    if display.Representation != REPRESENTATION:
        fail("'%s' is not offered (plugin not loaded?); representations: %s"
             % (REPRESENTATION, display.GetProperty("Representation").Available))
    lut = GetColorTransferFunction(array)
    lut.RGBPoints = list(rgb_points)
    pwf = GetOpacityTransferFunction(array)
    pwf.Points = list(opacity_points)
    display.ColorArrayName = ["POINTS", array]
    display.LookupTable = lut
    display.ScalarOpacityFunction = pwf
    display.ScalarOpacityUnitDistance = unit_distance
    return display


def set_camera(view, position, focal_point=(0.0, 0.0, 0.0), view_up=(0.0, 1.0, 0.0),
               zoom=1.0):
    """Look from `position` at `focal_point`, fit the data, then move `zoom`
    times closer. Renders once first: paraview.simple resets the camera on
    the first render of a session, which would undo this."""
    Render(view)
    view.CameraPosition = list(position)
    view.CameraFocalPoint = list(focal_point)
    view.CameraViewUp = list(view_up)
    view.ResetCamera()
    if zoom != 1.0:
        view.UpdatePropertyInformation()
        eye = view.GetProperty("CameraPositionInfo")
        view.CameraPosition = [f + (e - f) / zoom for f, e in zip(focal_point, eye)]


def combustor_view(size=400):
    """VTK's combustor as a ParaView user opens it (PLOT3D reader, Merge
    Blocks) shown as PPIRay Volume coloured by point Density in a size x size
    view on black, the camera reset: (view, display). The data root is
    PPIRAY_DATA_ROOT, else ../shared/data."""
    from paraview.simple import MergeBlocks, PLOT3DReader
    root = os.environ.get("PPIRAY_DATA_ROOT", "../shared/data")
    reader = PLOT3DReader(FileName=os.path.join(root, "combustor", "combxyz.bin"),
                          QFileName=[os.path.join(root, "combustor", "combq.bin")])
    reader.Functions = []
    view = CreateView("RenderView")
    view.ViewSize = [size, size]
    view.Background = [0, 0, 0]
    view.UseColorPaletteForBackground = 0
    display = Show(MergeBlocks(Input=reader), view)
    display.SetRepresentationType(REPRESENTATION)
    display.ColorArrayName = ["POINTS", "Density"]
    display.RescaleTransferFunctionToDataRange(True, False)
    view.ResetCamera()
    return view, display


def mapper_of(display):
    """The vtkUnstructuredGridGPURayCastMapper behind a PPIRay Volume display
    (its counters are read through the ppiray Python package)."""
    import ppiray  # noqa: F401  (makes the mapper's Python class known)
    representation = display.GetClientSideObject().GetActiveRepresentation()
    if representation.GetClassName() != "vtkPPIRayVolumeRepresentation":
        fail("active representation is %s" % representation.GetClassName())
    return representation.GetActiveVolumeMapper()


def screenshot(view, path):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    Render(view)
    SaveScreenshot(path, view)
    return path


def compare_with_baseline(image, baseline, temporary):
    """Testing/Python/ppiray_baseline.py's comparison (fails on a 10/255
    change); on failure the test and difference images are left beside
    `image` in `temporary`."""
    import sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    "..", "..", "..", "Testing", "Python"))
    import ppiray_baseline
    return ppiray_baseline.compare(image, baseline)


def rank():
    return servermanager.vtkProcessModule.GetProcessModule().GetPartitionId()


def read_rgb(path):
    """(height, width, 3) uint8 of a PNG (Testing/Python/ppiray_baseline.py)."""
    import sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    "..", "..", "..", "Testing", "Python"))
    import ppiray_baseline
    return ppiray_baseline.read_rgb(path)


def against_reference(view, display, image_path, array, background=BACKGROUND,
                      blend=0):
    """The screenshot at `image_path` against the CPU reference renderer given
    ParaView's own lookup table and opacity function objects (evaluated by
    VTK, vtkColorTransferFunction::GetTable), composited over the view's
    background as the window does: C + (1 - alpha) background, 8 bits.
    `blend`: the reference's blend mode (vtkVolumeMapper's values).
    Returns (covered pixels, p99, max) in 1/255 units over the covered pixels."""
    import numpy as np
    import ppiray
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkVolumeProperty
    import sys
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    "..", "..", "..", "Testing", "Python"))
    import ppiray_baseline

    mapper = mapper_of(display)
    prop = vtkVolumeProperty()
    prop.SetColor(display.LookupTable.GetClientSideObject())
    prop.SetScalarOpacity(display.ScalarOpacityFunction.GetClientSideObject())
    prop.SetScalarOpacityUnitDistance(display.ScalarOpacityUnitDistance)
    width, height = view.ViewSize
    reference = ppiray.vtkUnstructuredGridReferenceRenderer()
    reference.SetInputData(mapper.GetInput())
    reference.SetInputArrayToProcess(0, 0, 0, 0, array)
    reference.SetVolumeProperty(prop)
    reference.SetCamera(view.GetClientSideObject().GetActiveCamera())
    reference.SetImageSize(width, height)
    reference.SetBlendMode(blend)
    reference.SetAverageIPScalarRange(mapper.GetAverageIPScalarRange())
    reference.Update()
    rgba = vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars()).reshape(height, width, 4)
    bg = np.round(255.0 * np.array(background))
    expected = 255.0 * np.clip(rgba[:, :, :3], 0, 1) + (1.0 - rgba[:, :, 3:4]) * bg
    shown = ppiray_baseline.read_rgb(image_path).astype(np.float64)
    covered = rgba[:, :, 3] > 0.5 / 255
    d = np.abs(shown - expected)[covered]
    if d.size == 0:
        return 0, 0.0, 0.0
    return int(covered.sum()), float(np.percentile(d, 99)), float(d.max())


def native_and_split(view, display, folder, name, array, background=BACKGROUND):
    """Renders `display` with Hexahedron Mode Accurate (native) and Subdivide
    (split), saves each screenshot as folder/name_MODE.png and prints, per
    mode, the cells the mapper rendered, its peels, the lit pixels and the
    image against the reference (against_reference), then the difference
    between the two images (max, p99, pixels above 8/255)."""
    import numpy as np
    images = {}
    for mode in ("Accurate", "Subdivide"):
        display.HexahedronMode = mode
        Render(view)
        path = os.path.join(folder, "%s_%s.png" % (name, mode))
        SaveScreenshot(path, view)
        images[mode] = read_rgb(path).reshape(-1, 3).astype(np.float64)
        statistics = mapper_of(display).GetStatistics()
        print(mode, "native cells", statistics.GetNumberOfNativeCells(), "tetrahedra",
              statistics.GetNumberOfTetrahedra(), "peels", statistics.GetNumberOfPeels(),
              "lit pixels", int((images[mode].max(axis=1) > 0).sum()),
              "against the reference (covered, p99, max)",
              against_reference(view, display, path, array, background=background))
    diff = np.abs(images["Accurate"] - images["Subdivide"])
    print("native against split: max %.0f, p99 %.1f, pixels > 8: %d"
          % (diff.max(), np.percentile(diff, 99), int((diff.max(axis=1) > 8).sum())))


def run(main, doc, argc):
    """Call main(*sys.argv[1:]) of a test script taking argc - 1 arguments
    (the usage is the last line of `doc`); exit with SKIP when it skips."""
    import sys
    if len(sys.argv) != argc:
        fail("usage: " + doc.strip().splitlines()[-1])
    if main(*sys.argv[1:]) == SKIP:
        raise SystemExit(SKIP)
