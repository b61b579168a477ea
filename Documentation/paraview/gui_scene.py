# Run inside the ParaView GUI (paraview --script=gui_scene.py) by
# make_screenshot.sh: the bundled non-convex wavelet_hole.vtu shown as
# "PPIRay Volume", with an opaque slice through it.
import os
from paraview.simple import (GetActiveViewOrCreate, GetColorTransferFunction,
                             GetOpacityTransferFunction, Render, SetActiveSource, Show, Slice,
                             XMLUnstructuredGridReader)

data = os.path.join(os.environ["PPIRAY_ROOT"], "Data", "wavelet_hole.vtu")
reader = XMLUnstructuredGridReader(registrationName="wavelet_hole.vtu", FileName=[data])
view = GetActiveViewOrCreate("RenderView")
display = Show(reader, view)
display.SetRepresentationType("PPIRay Volume")
display.ColorArrayName = ["POINTS", "RTData"]
lut = GetColorTransferFunction("RTData")
lut.ApplyPreset("Cool to Warm", True)
lut.RescaleTransferFunction(40.0, 260.0)
pwf = GetOpacityTransferFunction("RTData")
pwf.Points = [40.0, 0.0, 0.5, 0.0, 150.0, 0.05, 0.5, 0.0, 260.0, 0.8, 0.5, 0.0]
display.LookupTable = lut
display.ScalarOpacityFunction = pwf
display.ScalarOpacityUnitDistance = 3.0
display.SetScalarBarVisibility(view, True)
cut = Slice(registrationName="Slice", Input=reader)
cut.SliceType.Normal = [0.0, 0.0, 1.0]
cut.SliceType.Origin = [0.0, 0.0, -8.0]
cut_display = Show(cut, view)
cut_display.ColorArrayName = ["POINTS", ""]
view.CameraPosition = [30.0, 20.0, 40.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera()
SetActiveSource(reader)
Render(view)
