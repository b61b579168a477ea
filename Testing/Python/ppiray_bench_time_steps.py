"""Module/run python Testing/Python/ppiray_bench_time_steps.py [--voxels N ...] [--hexahedra] [--convexify]

What stepping through time costs: the first frame of a new grid and what a
time series hands over at every step, for PPIRay and VTK's projected
tetrahedra (tetrahedra only), each mapper in its own process, one run. The
mesh: the cube [-1, 1]^3 in N^3 voxels, 6 tetrahedra each (or N^3
hexahedra with --hexahedra, marched natively), s = sin(3x) cos(2y) + z^2 at
the points (ppiray_large_mesh.py's blocks). Rows, in milliseconds of wall time per
frame (render call to return, size x size):
  first frame       a new mapper: preparation, upload and frame
  steady frame      the camera turned by 1 degree (median of 3)
  scalars in place  the scalars array edited and Modified()
  new grid, shared  a new grid object with the same points and cells
                    arrays and a new scalars array (a reader's next step)
  new grid, copied  the same with deep copies of the points and cells
  points moved      a new grid, same cells, every point moved (deforming)
PPIRay's columns add its CPU preparation (statistics) and whether the
geometry was kept (no geometry upload: GetGeometryUploadCount()); a second table splits the
preparation by stage (GetPreparationStageName/Time). --convexify: PPIRay in
NON_CONVEX_CONVEXIFY (the convexifier's fill is in the preparation's wall
time, before the stages). A benchmark, not a test: its
numbers go in Documentation/results.md with the command that made them.
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

ROWS = ["first frame", "steady frame", "scalars in place", "new grid, shared",
        "new grid, copied", "points moved"]


def new_scalars(grid, source, step):
    """`grid`'s point scalars: a new array, `source`'s values shifted by step."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    values = vtk_to_numpy(source.GetPointData().GetScalars()) + 0.05 * step
    array = numpy_to_vtk(values.astype(np.float64), deep=1)
    array.SetName("s")
    grid.GetPointData().SetScalars(array)


def worker(args):
    from ppiray_large_mesh import hexahedral_block, tetrahedral_block
    from ppiray_scene import scene, volume_property
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

    grid = hexahedral_block(args.voxels) if args.hexahedra else tetrahedral_block(args.voxels)
    prop = volume_property(grid)
    prop.SetScalarOpacityUnitDistance(0.5)
    ours = args.worker == "ppiray"
    if ours:
        import ppiray
        mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
        if args.convexify:
            import ppiray.ppirayConvexify  # noqa: F401  (registers the convexifier)
            mapper.SetNonConvexMode(mapper.NON_CONVEX_CONVEXIFY)
    else:
        from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLProjectedTetrahedraMapper
        mapper = vtkOpenGLProjectedTetrahedraMapper()
    window, renderer = scene(grid, mapper, args.size, prop)
    camera = renderer.GetActiveCamera()
    result = {"cells": grid.GetNumberOfCells()}

    def timed(row):
        start = time.perf_counter()
        window.Render()
        wall = 1000.0 * (time.perf_counter() - start)
        entry = {"ms": wall}
        if ours:
            s = mapper.GetStatistics()
            entry.update(prepare=s.GetPreparationTime(), reused=s.GetGeometryReuseCount(),
                         uploads=s.GetGeometryUploadCount(),
                         stages=[(s.GetPreparationStageName(i), s.GetPreparationStageTime(i))
                                 for i in range(s.GetNumberOfPreparationStages())])
        result[row] = entry

    timed("first frame")
    steady = []
    for _ in range(3):
        camera.Azimuth(1.0)
        timed("steady frame")
        steady.append(result["steady frame"]["ms"])
    result["steady frame"]["ms"] = float(np.median(steady))

    scalars = grid.GetPointData().GetScalars()
    values = vtk_to_numpy(scalars)
    values += 0.01
    scalars.Modified()
    timed("scalars in place")

    step = vtkUnstructuredGrid()
    step.ShallowCopy(grid)
    new_scalars(step, grid, 1)
    mapper.SetInputData(step)
    timed("new grid, shared")

    copied = vtkUnstructuredGrid()
    copied.DeepCopy(grid)
    new_scalars(copied, grid, 2)
    mapper.SetInputData(copied)
    timed("new grid, copied")

    moved = vtkUnstructuredGrid()
    moved.ShallowCopy(grid)
    xyz = vtk_to_numpy(grid.GetPoints().GetData()) * 0.98
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz.astype(np.float64), deep=1))
    moved.SetPoints(points)
    new_scalars(moved, grid, 3)
    mapper.SetInputData(moved)
    timed("points moved")
    print(json.dumps(result))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--voxels", type=int, nargs="+", default=[60],
                        help="N: 6 N^3 tetrahedra (60: 1.30 M) or N^3 hexahedra")
    parser.add_argument("--hexahedra", action="store_true", help="hexahedra, marched natively")
    parser.add_argument("--convexify", action="store_true",
                        help="PPIRay in NON_CONVEX_CONVEXIFY (imaginary cells fill a box around)")
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--mappers", default="ppiray,pt")
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        args.voxels = args.voxels[0]
        return worker(args)

    for n in args.voxels:
        results = {}
        for name in args.mappers.split(","):
            if name == "pt" and args.hexahedra:
                continue
            command = [sys.executable, os.path.abspath(__file__), "--worker", name,
                       "--voxels", str(n), "--size", str(args.size)]
            command += ["--hexahedra"] if args.hexahedra else []
            command += ["--convexify"] if args.convexify else []
            out = subprocess.run(command, capture_output=True, text=True)
            lines = [l for l in out.stdout.splitlines() if l.startswith("{")]
            if out.returncode != 0 or not lines:
                print(out.stdout + out.stderr, file=sys.stderr)
                return 1
            results[name] = json.loads(lines[-1])
        cells = next(iter(results.values()))["cells"]
        print("\n%d %s, %dx%d, wall ms per frame (PPIRay: CPU preparation, geometry kept)\n"
              % (cells, "hexahedra" if args.hexahedra else "tetrahedra", args.size, args.size))
        header = "| | " + " | ".join(
            ("PPIRay | preparation | kept" if k == "ppiray" else "projected tetrahedra")
            for k in results) + " |"
        print(header)
        print("|---|" + "|".join("---:|---:|:---:" if k == "ppiray" else "---:"
                                for k in results) + "|")
        for row in ROWS:
            cells_out = []
            for k, r in results.items():
                e = r[row]
                if k == "ppiray":
                    before = r[ROWS[ROWS.index(row) - 1]] if row != "first frame" else None
                    kept = "yes" if before and e["uploads"] == before["uploads"] else "no"
                    cells_out.append("%.0f | %.0f | %s" % (e["ms"], e["prepare"],
                                                           kept if row.startswith("new") or row == "points moved" else ""))
                else:
                    cells_out.append("%.0f" % e["ms"])
            print("| %s | %s |" % (row, " | ".join(cells_out)))
        if "ppiray" in results:
            print("\nPPIRay's CPU preparation by stage (statistics), ms\n")
            rows = [r for r in ROWS if r != "steady frame"]
            print("| stage | " + " | ".join(rows) + " |")
            print("|---|" + "---:|" * len(rows))
            names = []
            for row in rows:
                names += [n for n, _ in results["ppiray"][row]["stages"] if n not in names]
            for name in names:
                print("| %s | %s |" % (name, " | ".join(
                    "%.0f" % dict(results["ppiray"][row]["stages"]).get(name, 0.0)
                    if name in dict(results["ppiray"][row]["stages"]) else ""
                    for row in rows)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
