"""Reading what users bring for volumes, as one vtkUnstructuredGrid: XML
(.vtu .vts .vtr .vti .vtm .pvtu .pvd), legacy .vtk, Exodus (.e .ex2 .exo
.exii), PLOT3D (an xyz file with --q), SLC (.slc), raw bricks (with their
dimensions and type, as ParaView's Image Reader asks); composite data merged
(structured cells as hexahedra or voxels). read() raises ReadError with a message a user
can act on.
"""
import os

from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet
from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkIOExodus import vtkExodusIIReader
from vtkmodules.vtkIOImage import vtkImageReader2, vtkSLCReader
from vtkmodules.vtkIOLegacy import vtkDataSetReader
from vtkmodules.vtkIOParallel import vtkMultiBlockPLOT3DReader
from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader

XML = (".vtu", ".vts", ".vtr", ".vti", ".vtm", ".vtmb", ".pvtu", ".pvts", ".pvtr", ".pvti")
EXODUS = (".e", ".ex2", ".exo", ".exii", ".g", ".gen")


class ReadError(Exception):
    pass


def merged(data):
    """An unstructured grid of every leaf of `data`."""
    append = vtkAppendFilter()
    if isinstance(data, vtkCompositeDataSet):
        it = data.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            append.AddInputData(it.GetCurrentDataObject())
            it.GoToNextItem()
    else:
        append.AddInputData(data)
    append.Update()
    return append.GetOutput()


def pvd_file(path, step):
    """The data file of time step `step` (index) of a .pvd collection."""
    from xml.etree import ElementTree
    entries = ElementTree.parse(path).getroot().findall("./Collection/DataSet")
    if not entries:
        raise ReadError("%s lists no data sets" % path)
    if not 0 <= step < len(entries):
        raise ReadError("%s has %d time steps; --time-step %d is not one" % (
            path, len(entries), step))
    return os.path.join(os.path.dirname(path), entries[step].get("file"))


# Raw brick value types: vtkImageReader2's setter.
RAW_TYPES = {"uint8": "SetDataScalarTypeToUnsignedChar", "int8": "SetDataScalarTypeToChar",
             "uint16": "SetDataScalarTypeToUnsignedShort", "int16": "SetDataScalarTypeToShort",
             "int32": "SetDataScalarTypeToInt", "float32": "SetDataScalarTypeToFloat",
             "float64": "SetDataScalarTypeToDouble"}


def raw_reader(path, raw):
    """A raw brick, `raw` = 'NXxNYxNZ[:TYPE]' (TYPE one of RAW_TYPES, default
    uint8; little-endian, x fastest), spacing 1."""
    dims, _, kind = raw.partition(":")
    try:
        n = [int(x) for x in dims.lower().split("x")]
    except ValueError:
        n = []
    kind = kind or "uint8"
    if len(n) != 3 or min(n) < 2 or kind not in RAW_TYPES:
        raise ReadError("--raw NXxNYxNZ[:TYPE] expected (TYPE: %s), not %r"
                        % (" ".join(RAW_TYPES), raw))
    reader = vtkImageReader2()
    reader.SetFileDimensionality(3)
    reader.SetDataExtent(0, n[0] - 1, 0, n[1] - 1, 0, n[2] - 1)
    getattr(reader, RAW_TYPES[kind])()
    reader.SetDataByteOrderToLittleEndian()
    size = n[0] * n[1] * n[2] * {"uint8": 1, "int8": 1, "uint16": 2, "int16": 2}.get(
        kind, 8 if kind == "float64" else 4)
    if os.path.getsize(path) < size:
        raise ReadError("%s has %d bytes; --raw %s needs %d" % (path, os.path.getsize(path), raw,
                                                                size))
    return reader


def read(path, q=None, time_step=0, raw=None, function=None):
    """The cells of `path` as a vtkUnstructuredGrid, with every array
    (PLOT3D: and the derived `function`, vtkMultiBlockPLOT3DReader's number)."""
    if not os.path.isfile(path):
        raise ReadError("no such file: %s" % path)
    ext = os.path.splitext(path)[1].lower()
    if ext == ".pvd":
        return read(pvd_file(path, time_step))
    if raw is not None or ext == ".raw":
        if raw is None:
            raise ReadError("a raw brick needs its dimensions: --raw NXxNYxNZ[:TYPE]")
        reader = raw_reader(path, raw)
    elif ext == ".slc":
        reader = vtkSLCReader()
    elif ext in XML:
        reader = vtkXMLGenericDataObjectReader()
    elif ext == ".vtk":
        reader = vtkDataSetReader()
        reader.ReadAllScalarsOn()
        reader.ReadAllVectorsOn()
    elif ext in EXODUS:
        reader = vtkExodusIIReader()
        reader.SetFileName(path)
        reader.UpdateInformation()
        for i in range(reader.GetNumberOfPointResultArrays()):
            reader.SetPointResultArrayStatus(reader.GetPointResultArrayName(i), 1)
        for i in range(reader.GetNumberOfElementResultArrays()):
            reader.SetElementResultArrayStatus(reader.GetElementResultArrayName(i), 1)
        reader.SetTimeStep(time_step)
    elif q is not None or ext in (".xyz", ".bin", ".x", ".g3d"):
        if q is None:
            raise ReadError("a PLOT3D grid needs its solution file: --q FILE")
        reader = vtkMultiBlockPLOT3DReader()
        reader.SetXYZFileName(path)
        reader.SetQFileName(q)
        reader.AutoDetectFormatOn()
        if function is not None:
            reader.AddFunction(function)
    else:
        raise ReadError("unknown file type %s (XML %s, legacy .vtk, Exodus %s, .pvd, .slc, "
                        "PLOT3D with --q, raw with --raw)" % (ext, " ".join(XML), " ".join(EXODUS)))
    if not isinstance(reader, vtkExodusIIReader) and not isinstance(
            reader, vtkMultiBlockPLOT3DReader):
        reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutputDataObject(0)
    if data is None:
        raise ReadError("could not read %s" % path)
    grid = merged(data)
    if grid.GetNumberOfCells() == 0:
        raise ReadError("%s holds no cells" % path)
    return grid


def three_d_cells(grid):
    """How many cells of `grid` are 3D."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonDataModel import vtkCellTypes
    types, counts = np.unique(vtk_to_numpy(grid.GetCellTypesArray()), return_counts=True)
    return int(sum(n for t, n in zip(types, counts) if vtkCellTypes.GetDimension(int(t)) == 3))
