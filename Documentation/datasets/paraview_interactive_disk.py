"""disk_out_ref (ParaView's tutorial data: Exodus II, 7,472 hexahedra, Temp
as point data) shown as PPIRay Volume the way a ParaView user does, then
dragged: interactive renders below ParaView's LOD threshold, each followed
by the still render the view makes when the mouse is released. Prints, per
interactive render, the window's desired update rate, the volume's allocated
time, the mapper's image sample distance and last frame time, and the
interactive frame against the still one at the same camera (lit pixels, p99,
max /255). Writes the screenshots into the folder named on the command line.

Run: Module/run pvbatch Documentation/datasets/paraview_interactive_disk.py OUTDIR
"""
import os
import sys

import numpy as np
from paraview.simple import (ColorBy, CreateView, ExodusIIReader, GetColorTransferFunction,
                             Render, SaveScreenshot, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

import ppiray  # noqa: F401  (the mapper's Python class, for its counters)

root = os.environ.get("PPIRAY_DATA_ROOT", "../shared/data")
out = sys.argv[1]
os.makedirs(out, exist_ok=True)
reader = ExodusIIReader(FileName=[os.path.join(root, "disk_out_ref", "disk_out_ref.ex2")])
reader.PointVariables = ["Temp"]
view = CreateView("RenderView")
view.ViewSize = [600, 450]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.32, 0.34, 0.43]
view.LODThreshold = 1.0e6  # below it: the mapper draws the interactive frames
display = Show(reader, view)
display.SetRepresentationType("PPIRay Volume")
ColorBy(display, ("POINTS", "Temp"))
display.RescaleTransferFunctionToDataRange(True, False)
GetColorTransferFunction("Temp").ApplyPreset("Rainbow Uniform", True)
view.CameraPosition = [-1.0, 0.6, 1.2]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera()

representation = display.GetClientSideObject().GetActiveRepresentation()
mapper = representation.GetActiveVolumeMapper()
volume = representation.GetActor()
background = 255.0 * np.array(view.Background)


def frame():
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    w, h, _ = grab.GetOutput().GetDimensions()
    rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return rgb.astype(float)


def lit(rgb):
    return int((np.abs(rgb - background).max(axis=2) > 2.0).sum())


Render(view)
SaveScreenshot(os.path.join(out, "still_0.png"), view)
print("%d cells, still frame %.3f s, image sample distance %.2f, %d lit pixels"
      % (mapper.GetStatistics().GetNumberOfTetrahedra() + mapper.GetStatistics().GetNumberOfHexahedra(), mapper.GetTimeToDraw(),
         mapper.GetImageSampleDistance(), lit(frame())), flush=True)
camera = view.GetActiveCamera()
for step in range(1, 5):
    camera.Azimuth(20.0)
    view.SMProxy.InteractiveRender()
    interactive = frame()
    print("drag %d: rate %g, allocated %.4f s, distance %.2f, frame %.3f s"
          % (step, view.GetRenderWindow().GetDesiredUpdateRate(), volume.GetAllocatedRenderTime(),
             mapper.GetImageSampleDistance(), mapper.GetTimeToDraw()), flush=True)
    Render(view)
    still = frame()
    SaveScreenshot(os.path.join(out, "still_%d.png" % step), view)
    diff = np.abs(interactive - still).max(axis=2)
    print("   against the still frame (distance %.2f): lit %d and %d, p99 %.1f, max %.1f /255"
          % (mapper.GetImageSampleDistance(), lit(interactive), lit(still),
             np.percentile(diff, 99), diff.max()), flush=True)
    from PIL import Image
    Image.fromarray(interactive[::-1].astype(np.uint8)).save(
        os.path.join(out, "interactive_%d.png" % step))
