"""Module/run reference FILE.vtu [--out ref.png] [--size N] [--float ref.vti]

Ground truth for a tetrahedral mesh: vtkUnstructuredGridReferenceRenderer
(CPU, double precision, exact for linear tetrahedra and a piecewise-linear
transfer function) on the demo's view and transfer function. Writes the image
over black as PNG (and optionally the float RGBA as .vti) and prints the time.
"""
import argparse
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter

import ppiray
from ppiray_scene import load, scene

ROOT = os.environ.get("PPIRAY_ROOT", os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", nargs="?", default=os.path.join(ROOT, "Data", "wavelet_hole.vtu"))
    parser.add_argument("--out", default="reference.png")
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--float", help="also write the float RGBA image (.vti)")
    args = parser.parse_args()

    grid = load(args.file)
    # The same camera and property the demo uses (its mapper is not rendered).
    window, renderer = scene(grid, ppiray.vtkUnstructuredGridGPURayCastMapper(), args.size)
    volume = renderer.GetVolumes().GetLastProp()
    reference = ppiray.vtkUnstructuredGridReferenceRenderer()
    reference.SetInputData(grid)
    reference.SetVolumeProperty(volume.GetProperty())
    reference.SetCamera(renderer.GetActiveCamera())
    reference.SetImageSize(args.size, args.size)
    start = time.perf_counter()
    reference.Update()
    seconds = time.perf_counter() - start

    rgba = vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars())
    rgb = np.clip(np.rint(255.0 * rgba[:, :3]), 0, 255).astype(np.uint8)
    image = vtkImageData()
    image.SetDimensions(args.size, args.size, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(rgb, deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(args.out)
    writer.SetInputData(image)
    writer.Write()
    if args.float:
        vti = vtkXMLImageDataWriter()
        vti.SetFileName(args.float)
        vti.SetInputData(reference.GetOutput())
        vti.Write()
    print("reference %s: %d cells, %dx%d in %.1f s (double precision, exact per piece)" % (
        os.path.basename(args.file), grid.GetNumberOfCells(), args.size, args.size, seconds))
    print("image     %s" % os.path.abspath(args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
