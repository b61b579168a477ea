"""The cell textures' CPU build (adjacency, boundary, folds) of two builds, A/B.

For each mesh, each cell layout that takes it (vtkTetrahedralCellTextures,
vtkHexahedralCellTextures): the best of three BuildGeometry() times and a
SHA-1 of what the adjacency decides (neighbour codes, boundary triangles and
their faces, boundary points), so that two builds can be compared for time
and for identical output.

    # this build
    Module/run python Documentation/datasets/adjacency_ab.py MESH.vtu ... [--wavelet N]
    # another build of PPIRay (e.g. a worktree of an older commit), the same way:
    PYTHONPATH=OTHER/lib/python3.11/site-packages LD_LIBRARY_PATH=OTHER/lib \\
        /usr/bin/python3 Documentation/datasets/adjacency_ab.py MESH.vtu ...

Meshes: Documentation/datasets/write_vtu.py writes the data root's datasets as
.vtu (as given, and split into tetrahedra). --wavelet N adds
vtkRTAnalyticSource over [-N, N]^3 as hexahedra (vtkAppendFilter).
OMP_NUM_THREADS=1 for single-thread numbers.
"""

import argparse
import hashlib
import time

from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

import ppiray.ppirayFilters as filters


def meshes(args):
    for path in args.files:
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        yield path.split("/")[-1], reader.GetOutput()
    if args.wavelet:
        source = vtkRTAnalyticSource()
        n = args.wavelet
        source.SetWholeExtent(-n, n, -n, n, -n, n)
        append = vtkAppendFilter()
        append.SetInputConnection(source.GetOutputPort())
        append.Update()
        yield f"wavelet{n}", append.GetOutput()


def digest(textures):
    parts = []
    for name in ("GetNeighbors", "GetBoundaryTriangles", "GetBoundaryFaces", "GetBoundaryPoints"):
        values = tuple(getattr(textures, name)())
        parts.append(hashlib.sha1(repr(values).encode()).hexdigest()[:10])
    return " ".join(parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*")
    parser.add_argument("--wavelet", type=int, default=0)
    args = parser.parse_args()
    for name, grid in meshes(args):
        for layout in (filters.vtkTetrahedralCellTextures, filters.vtkHexahedralCellTextures):
            textures = layout()
            best = float("inf")
            built = False
            for _ in range(3):
                start = time.perf_counter()
                built = textures.BuildGeometry(grid)
                best = min(best, time.perf_counter() - start)
            if not built:
                continue
            print(
                f"{name} {layout.__name__}: {grid.GetNumberOfCells()} cells, "
                f"BuildGeometry {best * 1000:.0f} ms, non-manifold "
                f"{textures.GetNumberOfNonManifoldFaces()}, folded "
                f"{textures.GetNumberOfFoldedFaces()}, output {digest(textures)}"
            )


if __name__ == "__main__":
    main()
