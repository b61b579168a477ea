"""The datasets of the data root (../shared/data, its README lists them):
how to read each as one vtkUnstructuredGrid (every leaf of a multiblock
appended; structured cells as hexahedra or voxels) and which array to render.
Shared by Documentation/datasets/measure.py and TestDatasets.py.
"""
import os

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkIOExodus import vtkExodusIIReader
from vtkmodules.vtkIOImage import vtkImageReader, vtkSLCReader
from vtkmodules.vtkIOLegacy import vtkDataSetReader
from vtkmodules.vtkIOParallel import vtkMultiBlockPLOT3DReader
# Files written by Exodus pipelines carry vtkExodusIIReader's information keys:
# its module defines them (else each one is a "Could not locate key" warning).
import vtkmodules.vtkIOExodus  # noqa: F401,E402
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLUnstructuredGridReader

from ppiray_readers import merged

DATA = os.environ.get("PPIRAY_DATA_ROOT", os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                         "..", "..", "..", "shared", "data"))


def plot3d(xyz, q, function=None):
    r = vtkMultiBlockPLOT3DReader()
    r.SetXYZFileName(os.path.join(DATA, xyz))
    r.SetQFileName(os.path.join(DATA, q))
    r.AutoDetectFormatOn()
    if function:
        r.SetScalarFunctionNumber(function)
    r.Update()
    return merged(r.GetOutput())


def legacy(path):
    r = vtkDataSetReader()
    r.SetFileName(os.path.join(DATA, path))
    r.ReadAllScalarsOn()
    r.ReadAllVectorsOn()
    r.Update()
    return merged(r.GetOutput())


def xml_ug(path):
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(DATA, path))
    r.Update()
    return r.GetOutput()


def exodus(path, array=None):
    r = vtkExodusIIReader()
    r.SetFileName(os.path.join(DATA, path))
    r.UpdateInformation()
    if array:
        r.SetPointResultArrayStatus(array, 1)
    r.Update()
    return merged(r.GetOutput())


def image(reader):
    reader.Update()
    return merged(reader.GetOutput())


def with_z(grid):
    """A point field for meshes that carry none: the z coordinate."""
    points = vtk_to_numpy(grid.GetPoints().GetData())
    z = vtkDoubleArray()
    z.SetName("z")
    for v in points[:, 2]:
        z.InsertNextValue(float(v))
    grid.GetPointData().AddArray(z)
    return grid


def bucky():
    r = vtkImageReader()
    r.SetFileName(os.path.join(DATA, "bucky", "Bucky.raw"))
    r.SetDataScalarTypeToUnsignedChar()
    r.SetDataExtent(0, 31, 0, 31, 0, 31)
    r.SetFileDimensionality(3)
    return image(r)


def slc():
    r = vtkSLCReader()
    r.SetFileName(os.path.join(DATA, "neghip", "neghip.slc"))
    return image(r)


def vti():
    r = vtkXMLImageDataReader()
    r.SetFileName(os.path.join(DATA, "hydrogen", "hydrogen.vti"))
    return image(r)


# name: (loader, array, point data?)
DATASETS = {
    "bluntfin": (lambda: plot3d("bluntfin/bluntfinxyz.bin", "bluntfin/bluntfinq.bin"), "Density", True),
    "lox_post": (lambda: plot3d("lox_post/postxyz.bin", "lox_post/postq.bin", 110), "Pressure", True),
    "lox_post/post.vtk": (lambda: legacy("lox_post/post.vtk"), None, True),
    "combustor": (lambda: plot3d("combustor/combxyz.bin", "combustor/combq.bin"), "Density", True),
    "disk_out_ref": (lambda: exodus("disk_out_ref/disk_out_ref.ex2", "Temp"), "Temp", True),
    "can": (lambda: xml_ug("can/can.vtu"), "EQPS", False),
    "notch": (lambda: legacy("notch/notch_stress.vtk"), "Nodal Stress-normed", True),
    "unisim2": (lambda: with_z(xml_ug("unisim2/UNISIM-II-D.vtu")), "z", True),
    "quadratic/CylinderLinear": (lambda: legacy("quadratic/CylinderLinear.vtk"), "vel_norm", True),
    "fea_kiefer_bracket": (lambda: xml_ug("fea_kiefer_bracket/dataset.vtu"), None, False),
    "office": (lambda: legacy("office/office.binary.vtk"), "scalars", True),
    "kitchen": (lambda: legacy("kitchen/kitchen.vtk"), None, True),
    "angularsector": (lambda: with_z(legacy("angularsector/AngularSector.vtk")), "z", True),
    "mesh_fs8": (lambda: with_z(exodus("mesh_fs8/mesh_fs8.exo")), "z", True),
    "bucky": (bucky, None, True),
    "neghip": (slc, None, True),
    "hydrogen": (vti, None, True),
}


def select(grid, array, points):
    data = grid.GetPointData() if points else grid.GetCellData()
    if array is None:
        for i in range(data.GetNumberOfArrays()):
            a = data.GetArray(i)
            if a is not None and a.GetNumberOfComponents() == 1:
                array = a.GetName()
                break
    if array is None or data.GetArray(array) is None:
        return None
    # ppiray_scene's property reads the active point, else cell, scalars.
    grid.GetPointData().SetActiveScalars(None)
    grid.GetCellData().SetActiveScalars(None)
    data.SetActiveScalars(array)
    return array
