"""The mapper from Python, swapped into an ordinary VTK pipeline.

vtkRTAnalyticSource -> vtkDataSetTriangleFilter -> vtkUnstructuredGridGPURayCastMapper,
point scalars "RTData", a smooth transfer function: compared with a baseline
image, and the mapper's Python API (counters, GPU memory, mode strings) checked.

Usage: TestGPURayCastPython.py BASELINE.png TEMPORARY_DIR
"""
import os
import sys

from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction,
    vtkRenderer,
    vtkRenderWindow,
    vtkVolume,
    vtkVolumeProperty,
)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import ppiray

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "..", "Testing", "Python"))
import ppiray_baseline  # noqa: E402


def main(baseline, temporary):
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    tetrahedralize = vtkDataSetTriangleFilter()
    tetrahedralize.SetInputConnection(source.GetOutputPort())

    mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
    mapper.SetInputConnection(tetrahedralize.GetOutputPort())

    color = vtkColorTransferFunction()
    color.AddRGBPoint(40.0, 0.1, 0.1, 0.8)
    color.AddRGBPoint(150.0, 0.9, 0.9, 0.2)
    color.AddRGBPoint(260.0, 0.9, 0.1, 0.1)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(40.0, 0.0)
    opacity.AddPoint(260.0, 0.5)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(4.0)

    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    renderer.GetActiveCamera().SetPosition(30, 20, 40)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetMultiSamples(0)
    window.SetSize(300, 300)
    window.AddRenderer(renderer)
    window.Render()

    failures = []
    tets = mapper.GetStatistics().GetNumberOfTetrahedra()
    if tets != 5 * 20 ** 3:
        failures.append("expected 40000 tetrahedra, got %d" % tets)
    if mapper.GetStatistics().GetGPUMemorySize() < 96 * tets:
        failures.append("GPU memory %d below 96 B/tet" % mapper.GetStatistics().GetGPUMemorySize())
    if mapper.GetStatistics().GetNumberOfPeels() != 1:
        failures.append("convex mesh took %d peels" % mapper.GetStatistics().GetNumberOfPeels())

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    image = os.path.join(temporary, os.path.basename(baseline))
    writer = vtkPNGWriter()
    writer.SetFileName(image)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    problem = ppiray_baseline.compare(image, baseline)
    if problem:
        failures.append(problem)
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
