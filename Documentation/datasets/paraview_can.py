"""The crushed can (can/can.vtu, 4,800 hexahedra, cell array EQPS) the way a
ParaView user opens it: XML reader, "PPIRay Volume", coloured by EQPS with
ParaView's default colour map (Cool to Warm, Diverging) and opacity,
rescaled to the data. Prints what reached the mapper, the frame time, and
the screenshot against the CPU reference renderer given ParaView's own
lookup-table objects (covered pixels, p99, max, pixels above 8/255); writes
the image and a x10 difference image to OUT.

Run: Module/run pvbatch Documentation/datasets/paraview_can.py [OUT]
"""
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "Plugin", "Testing", "Python"))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Python"))
import numpy as np  # noqa: E402
import ppiray_baseline  # noqa: E402
import ppiray_pvtest as pt  # noqa: E402
from paraview.simple import (  # noqa: E402
    ColorBy, GetColorTransferFunction, GetOpacityTransferFunction, Render, Show,
    XMLUnstructuredGridReader)

DATA = os.environ.get("PPIRAY_DATA_ROOT", os.path.join(ROOT, "..", "shared", "data"))
out = sys.argv[1] if len(sys.argv) > 1 else "build/datasets"
os.makedirs(out, exist_ok=True)
reader = XMLUnstructuredGridReader(FileName=[os.path.join(DATA, "can", "can.vtu")])
reader.UpdatePipeline()
view = pt.render_view((400, 400))
display = Show(reader, view)
display.SetRepresentationType(pt.REPRESENTATION)
ColorBy(display, ("CELLS", "EQPS"))
lo, hi = reader.CellData["EQPS"].GetRange()
GetColorTransferFunction("EQPS").RescaleTransferFunction(lo, hi)
GetOpacityTransferFunction("EQPS").RescaleTransferFunction(lo, hi)
b = reader.GetDataInformation().GetBounds()
centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
pt.set_camera(view, [centre[0] + 1, centre[1] + 0.6, centre[2] + 1.3], centre)
image = pt.screenshot(view, os.path.join(out, "can_paraview.png"))
mapper = pt.mapper_of(display)
start = time.perf_counter()
Render(view)
ms = 1000 * (time.perf_counter() - start)
print("input cells %d, hexahedra rendered natively %d, peels %d, %.0f ms per frame"
      % (mapper.GetInput().GetNumberOfCells(), mapper.GetStatistics().GetNumberOfHexahedra(),
         mapper.GetStatistics().GetNumberOfPeels(), ms))

import ppiray  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkVolumeProperty  # noqa: E402

prop = vtkVolumeProperty()
prop.SetColor(display.LookupTable.GetClientSideObject())
prop.SetScalarOpacity(display.ScalarOpacityFunction.GetClientSideObject())
prop.SetScalarOpacityUnitDistance(display.ScalarOpacityUnitDistance)
reference = ppiray.vtkUnstructuredGridReferenceRenderer()
reference.SetInputData(mapper.GetInput())
reference.SetInputArrayToProcess(0, 0, 0, 1, "EQPS")  # cell data
reference.SetVolumeProperty(prop)
reference.SetCamera(view.GetClientSideObject().GetActiveCamera())
reference.SetImageSize(400, 400)
reference.Update()
rgba = vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars()).reshape(400, 400, 4)
background = np.round(255.0 * np.array([0.32, 0.34, 0.43]))
expected = 255.0 * np.clip(rgba[:, :, :3], 0, 1) + (1.0 - rgba[:, :, 3:4]) * background
shown = ppiray_baseline.read_rgb(image).astype(np.float64)
covered = rgba[:, :, 3] > 0.5 / 255
d = np.abs(shown - expected)
print("against the reference: %d pixels, p99 %.2f, max %.2f /255, %d pixels above 8/255"
      % (covered.sum(), np.percentile(d[covered], 99), d[covered].max(),
         (d[covered].max(axis=1) > 8).sum()))
diff = np.where(covered[:, :, None], np.minimum(255, 10 * d), 0).astype(np.uint8)
ppiray_baseline.write_rgb(os.path.join(out, "can_paraview_diff.png"), diff)
