"""ParaView in parallel: "PPIRay Volume" rendered by 2 MPI ranks of pvbatch
(data redistributed into visibility-sortable pieces, each rank ray casting its
piece, IceT compositing them in order) equals the 1-rank image within 1/255
per channel at the 99th percentile, on a distributed source and on a
non-convex mesh read by one rank. Both ranks must have rendered cells, and
their tetrahedra must add up to the whole mesh.

MPI start-up has been seen to abort once in a sandbox and pass on retry: the
2-rank run is tried up to 3 times, each failure printed with its output.

Usage: python3 TestPPIRayParallel.py PVBATCH MPIEXEC PLUGIN TEMPORARY_DIR DATA_DIR
"""
import os
import re
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "ppiray_parallel_scene.py")
# Cells each scene's ranks must render between them: (tetrahedra, hexahedra);
# None where the count depends on the partition (each rank splits its mixed
# cells along diagonals chosen by its own point ids).
CELLS = {"wavelet": (5 * 20 ** 3, 0), "voxels": (0, 20 ** 3), "clipped": None,
         "hole": (71472, 0)}
ATTEMPTS = 3
TIMEOUT = 120  # seconds per run; a run takes ~5 s here


def run(command, label):
    """(ok, output) of one run."""
    print("[%s] %s" % (label, " ".join(command)), flush=True)
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired as error:
        partial = error.output or b""
        if isinstance(partial, bytes):
            partial = partial.decode(errors="replace")
        return False, "timed out after %d s\n%s" % (TIMEOUT, partial)
    return done.returncode == 0, "exit code %d\n%s" % (done.returncode, done.stdout)


def ranks_report(output):
    """{scene: {rank: (tetrahedra, hexahedra)}} from the scene script's PPIRAY lines."""
    report = {}
    for rank, _, scene, tets, hexes in re.findall(
            r"PPIRAY rank (\d+) of (\d+) scene (\w+) tetrahedra (\d+) hexahedra (\d+)", output):
        report.setdefault(scene, {})[int(rank)] = (int(tets), int(hexes))
    return report


def load_rgb(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        raise RuntimeError("could not read %s" % path)
    return vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)


def main(pvbatch, mpiexec, plugin, temporary, data):
    one = os.path.join(temporary, "parallel-1")
    two = os.path.join(temporary, "parallel-2")
    for folder in (one, two):
        os.makedirs(folder, exist_ok=True)

    ok, output = run([pvbatch, SCENE, plugin, one, data], "1 rank")
    if not ok:
        print(output)
        print("FAILED: the 1-rank pvbatch run failed")
        return 1

    mpi = [mpiexec, "--oversubscribe"]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        mpi.append("--allow-run-as-root")
    command = mpi + ["-np", "2", pvbatch, "--mpi", "--symmetric", SCENE, plugin, two, data]
    for attempt in range(1, ATTEMPTS + 1):
        ok, output = run(command, "2 ranks, attempt %d/%d" % (attempt, ATTEMPTS))
        if ok:
            break
        print("2-rank run failed (attempt %d):\n%s" % (attempt, output[-4000:]))
    if not ok:
        print("FAILED: mpiexec -np 2 pvbatch failed %d times (see above): "
              "is Open MPI usable here (mpiexec --version)?" % ATTEMPTS)
        return 1

    failures = []
    report = ranks_report(output)
    for scene, total in CELLS.items():
        per_rank = report.get(scene, {})
        print("%s: (tetrahedra, hexahedra) per rank %s" % (scene, per_rank))
        rendered = tuple(sum(cells[i] for cells in per_rank.values()) for i in range(2))
        if sorted(per_rank) != [0, 1] or min(sum(c) for c in per_rank.values()) == 0:
            failures.append("%s: not both ranks rendered cells: %s" % (scene, per_rank))
        elif total is not None and rendered != total:
            failures.append("%s: ranks rendered (tetrahedra, hexahedra) %s, the mesh has %s"
                            % (scene, rendered, total))
        a = load_rgb(os.path.join(one, scene + ".png"))
        b = load_rgb(os.path.join(two, scene + ".png"))
        if a.shape != b.shape:
            failures.append("%s: image sizes differ" % scene)
            continue
        difference = np.abs(a - b)
        p99 = np.percentile(difference, 99)
        print("%s: 2 ranks vs 1 rank, per channel in 1/255: mean %.3f p99 %.0f max %d"
              % (scene, difference.mean(), p99, difference.max()))
        if p99 > 1:
            failures.append("%s: p99 difference %.0f/255 > 1/255" % (scene, p99))
        # The blend's rounding along the cut between the pieces (measured 2-3).
        if difference.max() > 4:
            failures.append("%s: max difference %d/255 > 4/255" % (scene, difference.max()))
        if a.max() - a.min() < 32:
            failures.append("%s: the 1-rank image is nearly uniform: nothing rendered?" % scene)
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 6:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
