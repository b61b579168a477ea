"""Writes datasets of the data root as .vtu files for ppirayBenchmark --file:
as given (NAME_given.vtu) and as vtkDataSetTriangleFilter tetrahedra
(NAME_tets.vtu), the rendered array active.

Run: Module/run python Documentation/datasets/write_vtu.py OUT_DIR [NAME ...]
(default names: bluntfin lox_post can)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Testing", "Python"))
import ppiray_datasets  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter  # noqa: E402


def main(out, names):
    os.makedirs(out, exist_ok=True)
    for name in names:
        loader, array, points = ppiray_datasets.DATASETS[name]
        grid = loader()
        array = ppiray_datasets.select(grid, array, points)
        tetra = vtkDataSetTriangleFilter()
        tetra.SetInputData(grid)
        tetra.Update()
        tets = tetra.GetOutput()
        ppiray_datasets.select(tets, array, points)
        for label, data in (("given", grid), ("tets", tets)):
            path = os.path.join(out, "%s_%s.vtu" % (name.replace("/", "_"), label))
            writer = vtkXMLUnstructuredGridWriter()
            writer.SetFileName(path)
            writer.SetInputData(data)
            writer.Write()
            print(path)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:] or ["bluntfin", "lox_post", "can"])
