"""Baseline image comparison for the Python tests, the bounds of the C++
tests' PPIRayBaseline.h: per channel, no shift tolerance (llvmpipe rasterizes
the same way on every run); fails when any channel differs by 10/255 or more,
when the 99th percentile exceeds 2/255 or the mean 0.5/255, or when the sizes
differ. On failure a x10 difference image is written beside the test image.
(VTK 9.2's vtkTesting threshold accepts +105/255 on every channel.)
"""
import os

import numpy as np
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy


def read_rgb(path):
    """(height, width, 3) uint8, rows from the bottom as VTK stores them."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(h, w, -1)[:, :, :3]


def write_rgb(path, rgb):
    h, w, _ = rgb.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    array = numpy_to_vtk(np.ascontiguousarray(rgb.reshape(-1, 3)), deep=True)
    image.GetPointData().SetScalars(array)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def compare(image_path, baseline_path):
    """None if the PNG at image_path matches the baseline, else a message."""
    if not os.path.exists(baseline_path):
        return "no baseline %s (the image is %s)" % (baseline_path, image_path)
    image = read_rgb(image_path).astype(np.int32)
    baseline = read_rgb(baseline_path).astype(np.int32)
    if image.shape != baseline.shape:
        return "%s is %s, its baseline %s" % (image_path, image.shape, baseline.shape)
    d = np.abs(image - baseline)
    mean, p99, largest = d.mean(), np.percentile(d, 99), d.max()
    print("baseline %s: mean %.3f p99 %.1f max %d /255"
          % (os.path.basename(baseline_path), mean, p99, largest), flush=True)
    if largest >= 10 or p99 > 2 or mean > 0.5:
        root, _ = os.path.splitext(image_path)
        write_rgb(root + ".diff.png", np.minimum(255, 10 * d).astype(np.uint8))
        return ("%s differs from %s: mean %.3f p99 %.1f max %d /255 (bounds: max < 10, "
                "p99 <= 2, mean <= 0.5)" % (image_path, baseline_path, mean, p99, largest))
    return None
