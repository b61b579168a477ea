"""Side-by-side PNGs: montage.py OUT.png IN1.png IN2.png ... (VTK Python, numpy)."""
import sys, numpy as np
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.util.numpy_support import vtk_to_numpy, numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
def read(p):
    r = vtkPNGReader(); r.SetFileName(p); r.Update()
    im = r.GetOutput(); w, h, _ = im.GetDimensions()
    a = vtk_to_numpy(im.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return a
out = sys.argv[1]; ims = [read(p) for p in sys.argv[2:]]
h = max(i.shape[0] for i in ims)
ims = [np.pad(i, ((0, h - i.shape[0]), (0, 4), (0, 0))) for i in ims]
m = np.concatenate(ims, axis=1).astype(np.uint8)
img = vtkImageData(); img.SetDimensions(m.shape[1], m.shape[0], 1)
img.GetPointData().SetScalars(numpy_to_vtk(m.reshape(-1, 3).copy()))
w = vtkPNGWriter(); w.SetFileName(out); w.SetInputData(img); w.Write()
