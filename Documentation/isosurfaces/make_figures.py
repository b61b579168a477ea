"""Isosurface figures and timings for Documentation/isosurfaces.md.

Blunt Fin as hexahedra (37,479 cells, Density), two isosurfaces, rendered by
PPIRay natively (HEXAHEDRON_ACCURATE), split into tetrahedra
(HEXAHEDRON_SUBDIVIDE), embedded in the volume, and by VTK's usual route
(vtkContourFilter on the hexahedra, then a vtkPolyDataMapper), in one process,
on the same window and camera; each frame time is the median of 5 renders
after one warm-up render. Prints a Markdown table; writes
bluntfin_isosurfaces.png (side by side) and bluntfin_closeup.png (a zoom on
the fin, where cells are coarse).

Run: Module/run python Documentation/isosurfaces/make_figures.py [DATA_ROOT]
"""
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Python"))

import ppiray  # noqa: E402
import ppiray_bench_scenes  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: E402,F401
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkImageAppend  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkActor, vtkColorTransferFunction, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
    vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)

SIZE = 400
ISOVALUES = (0.5, 1.3)
BOUNDS = None  # the grid's: every view frames the same box


def iso_property():
    prop = vtkVolumeProperty()
    color = vtkColorTransferFunction()
    color.AddRGBPoint(0.19, 1.0, 0.5, 0.2)
    color.AddRGBPoint(0.6, 1.0, 0.7, 0.3)
    color.AddRGBPoint(1.2, 0.3, 0.6, 1.0)
    color.AddRGBPoint(5.0, 0.3, 0.5, 1.0)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.19, 1.0)
    opacity.AddPoint(0.5, 1.0)    # opaque surface of the low-density wake
    opacity.AddPoint(0.55, 0.01)
    opacity.AddPoint(1.25, 0.01)
    opacity.AddPoint(1.3, 0.3)    # translucent surface
    opacity.AddPoint(1.35, 0.0)
    opacity.AddPoint(5.0, 0.0)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(0.5)
    for i, v in enumerate(ISOVALUES):
        prop.GetIsoSurfaceValues().SetValue(i, v)
    prop.ShadeOn()
    prop.SetAmbient(0.15)
    prop.SetDiffuse(0.75)
    prop.SetSpecular(0.3)
    prop.SetSpecularPower(30.0)
    return prop


def set_camera(renderer, closeup):
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetPosition(-0.6, -1.0, 0.8)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera(BOUNDS)
    camera.Zoom(1.3)
    if closeup:
        camera.Zoom(2.5)
    renderer.ResetCameraClippingRange()


WINDOW = None


def render(name, add_prop, closeup, path):
    # One window (one X connection) for every view: Xvfb refuses new
    # connections now and then.
    global WINDOW
    if WINDOW is None:
        WINDOW = vtkRenderWindow()
        WINDOW.SetSize(SIZE, SIZE)
        WINDOW.SetMultiSamples(0)
    window = WINDOW
    window.GetRenderers().RemoveAllItems()
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    window.AddRenderer(renderer)
    extra = add_prop(renderer)
    set_camera(renderer, closeup)
    window.Render()
    times = []
    for _ in range(5):
        renderer.GetActiveCamera().Azimuth(0.0)
        start = time.perf_counter()
        window.Render()
        times.append(1000.0 * (time.perf_counter() - start))
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(grab.GetOutput())
    writer.Write()
    return statistics.median(times), extra


def main():
    data_root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "..", "shared", "data")
    built = ppiray_bench_scenes.build("bluntfin-hex", ROOT, data_root)
    if built is None:
        raise SystemExit("no Blunt Fin under %s" % data_root)
    grid = built[0]
    global BOUNDS
    BOUNDS = grid.GetBounds()
    prop = iso_property()
    rows = []
    for closeup in (False, True):
        tiles = []

        def ppiray_view(mode, blend):
            def add(renderer):
                mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
                mapper.SetInputData(grid)
                mapper.SetHexahedronMode(mode)
                if blend == "iso":
                    mapper.SetBlendModeToIsoSurface()
                elif blend == "embedded":
                    mapper.EmbedIsoSurfacesOn()
                volume = vtkVolume()
                volume.SetMapper(mapper)
                volume.SetProperty(prop)
                renderer.AddVolume(volume)
                return mapper
            return add

        def contour_view(renderer):
            contour = vtkContourFilter()
            contour.SetInputData(grid)
            for i, v in enumerate(ISOVALUES):
                contour.SetValue(i, v)
            start = time.perf_counter()
            contour.Update()
            extract_ms = 1000.0 * (time.perf_counter() - start)
            mapper = vtkPolyDataMapper()
            mapper.SetInputConnection(contour.GetOutputPort())
            mapper.SetLookupTable(prop.GetRGBTransferFunction())
            mapper.SetScalarModeToUsePointData()
            mapper.UseLookupTableScalarRangeOn()
            actor = vtkActor()
            actor.SetMapper(mapper)
            actor.GetProperty().SetOpacity(1.0)
            actor.GetProperty().SetAmbient(0.15)
            actor.GetProperty().SetDiffuse(0.75)
            actor.GetProperty().SetSpecular(0.3)
            actor.GetProperty().SetSpecularPower(30.0)
            renderer.AddActor(actor)
            return (extract_ms, contour.GetOutput().GetNumberOfCells())

        views = [
            ("PPIRay, hexahedra natively (ACCURATE)", "native", ppiray_view(0, "iso")),
            ("PPIRay, hexahedra split into 6 tetrahedra (SUBDIVIDE)", "subdivide",
             ppiray_view(2, "iso")),
            ("PPIRay, native, surfaces embedded in the volume", "embedded",
             ppiray_view(0, "embedded")),
            ("vtkContourFilter + vtkPolyDataMapper (opaque, smooth normals)", "contour",
             contour_view),
        ]
        if not closeup:
            views.append(("PPIRay, native, the volume alone (composite, same transfer function)",
                          "composite", ppiray_view(0, "composite")))
        suffix = "closeup" if closeup else "full"
        for label, key, add in views:
            path = os.path.join(HERE, "tile_%s_%s.png" % (key, suffix))
            ms, extra = render(label, add, closeup, path)
            if key != "composite":
                tiles.append(path)
            if not closeup:
                note = ""
                if key == "contour":
                    note = "contour extraction %.0f ms once, %d triangles" % extra
                rows.append((label, ms, note))
        append = vtkImageAppend()
        append.SetAppendAxis(0)
        from vtkmodules.vtkIOImage import vtkPNGReader
        for path in tiles:
            reader = vtkPNGReader()
            reader.SetFileName(path)
            reader.Update()
            append.AddInputData(reader.GetOutput())
        for key in ("native", "subdivide", "embedded", "contour", "composite"):
            path = os.path.join(HERE, "tile_%s_%s.png" % (key, suffix))
            if os.path.exists(path):
                os.remove(path)
        append.Update()
        writer = vtkPNGWriter()
        writer.SetFileName(os.path.join(HERE, "bluntfin_%s.png"
                                        % ("closeup" if closeup else "isosurfaces")))
        writer.SetInputData(append.GetOutput())
        writer.Write()
    print("| view (Blunt Fin, 37,479 hexahedra, isovalues %s, %dx%d) | ms per frame | note |"
          % (", ".join(str(v) for v in ISOVALUES), SIZE, SIZE))
    print("|---|---:|---|")
    for label, ms, note in rows:
        print("| %s | %.0f | %s |" % (label, ms, note))


if __name__ == "__main__":
    main()
