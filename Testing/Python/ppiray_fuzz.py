"""Module/run fuzz [--count N] [--seed S] [--first I] [--case I] [--timeout T] [--log F]

Renders N generated grids, clean and malformed, with
vtkUnstructuredGridGPURayCastMapper, each case in a child process with a
time limit (cases run in batches; a batch that crashes or hangs is rerun one
case at a time to name the case). Case I of seed S is always the same grid,
camera, transfer function and mapper settings (--case I reruns one).

Generated: blocks of tetrahedra or hexahedra (jittered), random overlapping
tetrahedra, one cell of any type, and blocks mixed with every other cell type
VTK has (polyhedra, quadratic and higher-order, pentagonal and hexagonal
prisms, 2D cells, lines, vertices, empty cells); mutated with point ids out
of range or negative, NaN, infinite, huge and tiny coordinates and scalars,
duplicate points, zero-volume, inverted and tangled cells; point or cell
scalars, multi-component arrays, constant fields; 1 to 5,000 transfer
function control points, unit distance positive, zero or negative; every
integration, hexahedron and blend mode, isovalues, clipping planes; cameras
outside, inside and parallel; some cells marked HIDDENCELL, some grids
convexified first (vtkUnstructuredGridConvexify, when built).

Each case must: exit (no crash), finish within the time limit (no hang);
when its input is malformed in a way that leaves something out, say so in a
warning or an error (the substring its mutation names; a grid with
non-finite coordinates that VTK culls before the mapper runs draws and says
nothing); when it is clean,
the reference applies (linear tetrahedra or unjittered hexahedra rendered
natively, an exact integration mode) and the mapper announced no
approximation (a transfer function cut at 4,096 control points), match the
CPU reference renderer:
p99 at most 2/255 and at most 1 % of the covered pixels (3 at least) more
than 8/255 apart (silhouette pixels whose rays graze an edge). Prints one
line per failure with the command that reruns it, then a summary; exit 1 on
any failure.

--log F appends each case's result to F (one JSON line per case) and skips
the cases F already holds, so a long run can stop and resume; the summary
then covers every case of the range in F.
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

SIZE = 64
BATCH = 25

# Cell types mixed into grids: (VTK type, number of points); 0 points: a
# polyhedron (built separately).
OTHER_CELLS = [(1, 1), (3, 2), (4, 3), (5, 3), (7, 4), (9, 4), (11, 8), (12, 8), (13, 6),
               (14, 5), (15, 10), (16, 12), (24, 10), (25, 20), (0, 0), (42, 0)]


def block(rng, n, hexahedra, jitter):
    """An n^3 block of unit cells: points, cells [(type, ids)]."""
    grid = np.stack(np.meshgrid(*[np.arange(n + 1.0)] * 3, indexing="ij"), -1).reshape(-1, 3)
    points = grid / n + jitter * rng.uniform(-0.3, 0.3, grid.shape) / n
    index = lambda i, j, k: (i * (n + 1) + j) * (n + 1) + k  # noqa: E731
    cells = []
    for i in range(n):
        for j in range(n):
            for k in range(n):
                c = [index(i, j, k), index(i + 1, j, k), index(i + 1, j + 1, k),
                     index(i, j + 1, k), index(i, j, k + 1), index(i + 1, j, k + 1),
                     index(i + 1, j + 1, k + 1), index(i, j + 1, k + 1)]
                if hexahedra:
                    cells.append((12, c))
                else:
                    # Six tetrahedra around the diagonal 0-6 (conforming).
                    for a, b in ((1, 2), (2, 3), (3, 7), (7, 4), (4, 5), (5, 1)):
                        cells.append((10, [c[0], c[a], c[b], c[6]]))
    return points, cells


def make_case(seed, case):
    """The case's description (a dict of plain values), from its seed."""
    rng = np.random.default_rng([seed, case])
    # A third of the cases are clean meshes the reference renderer is ground
    # truth for (compared); the rest anything.
    reference = bool(rng.uniform() < 0.33)
    kind = rng.choice(["tetrahedra", "hexahedra", "random", "single", "mixed"],
                      p=[0.35, 0.2, 0.15, 0.1, 0.2])
    kind = str(rng.choice(["tetrahedra", "hexahedra"])) if reference else kind
    jitter = float(rng.choice([0.0, 0.0, rng.uniform(0, 1)]))
    jitter = 0.0 if reference and kind == "hexahedra" else jitter
    expect = []  # message substrings the mutations require
    if kind in ("tetrahedra", "hexahedra", "mixed"):
        points, cells = block(rng, int(rng.integers(1, 7)), kind == "hexahedra", jitter)
    elif kind == "random":
        points = rng.uniform(0, 1, (int(rng.integers(4, 60)), 3))
        cells = [(10, [int(i) for i in rng.choice(len(points), 4, replace=False)])
                 for _ in range(int(rng.integers(1, 80)))]
    else:
        points, cells = np.zeros((0, 3)), []
    if kind in ("single", "mixed"):
        for _ in range(1 if kind == "single" else int(rng.integers(1, 6))):
            cell_type, npts = OTHER_CELLS[int(rng.integers(len(OTHER_CELLS)))]
            if cell_type == 42:
                npts = 4
            first = len(points)
            points = np.vstack([points, rng.uniform(0, 1, (max(npts, 1), 3))])
            cells.append((cell_type, list(range(first, first + npts))))
    points = points.tolist()
    mutations = []
    n = len(points)

    def some_cells():
        return [int(c) for c in rng.choice(len(cells), min(len(cells), 3), replace=False)] \
            if cells else []

    for name, probability in (("ids_past", 0.06), ("ids_negative", 0.06), ("nan_coord", 0.04),
                              ("inf_coord", 0.04), ("huge", 0.05), ("tiny", 0.05),
                              ("duplicates", 0.08), ("flat", 0.1), ("inverted", 0.1),
                              ("nan_scalar", 0.05), ("inf_scalar", 0.04), ("huge_scalar", 0.04),
                              ("constant", 0.06)):
        if rng.uniform() >= probability or n == 0 or reference:
            continue
        mutations.append(name)
        if name in ("ids_past", "ids_negative") and cells:
            c = some_cells()[0]
            if cells[c][1]:
                cells[c][1][int(rng.integers(len(cells[c][1])))] = \
                    n + int(rng.integers(0, 5)) if name == "ids_past" else -int(rng.integers(1, 5))
                expect.append("point ids outside")
        elif name in ("nan_coord", "inf_coord"):
            points[int(rng.integers(n))][int(rng.integers(3))] = \
                float("nan") if name == "nan_coord" else float("inf")
            expect.append("infinite or NaN point coordinates")
        elif name == "huge":
            points = [[x * 1e30 for x in p] for p in points]
        elif name == "tiny":
            points = [[x * 1e-30 for x in p] for p in points]
        elif name == "duplicates":
            for c in some_cells():
                ids = cells[c][1]
                if ids:
                    k = int(rng.integers(len(ids)))
                    if 0 <= ids[k] < len(points):
                        points.append(list(points[ids[k]]))
                        ids[k] = len(points) - 1
        elif name == "flat":
            for c in some_cells():
                ids = cells[c][1]
                if len(ids) >= 2 and all(0 <= i < len(points) for i in ids[:2]):
                    points[ids[1]] = list(points[ids[0]])
        elif name == "inverted":
            for c in some_cells():
                ids = cells[c][1]
                if len(ids) >= 2:
                    ids[0], ids[1] = ids[1], ids[0]
    scalars = {"association": str(rng.choice(["point", "cell"])),
               "components": 1 if reference else int(rng.choice([1, 1, 1, 3]))}
    # Up to 5,000 nodes (rarely: random colours at 5,000 nodes take seconds to
    # turn into control points).
    nodes = int(rng.choice([1, 2, 2, 5, int(rng.integers(2, 60)), int(rng.integers(60, 400))]))
    tf = {"points": 5000 if rng.uniform() < 0.02 else nodes,
          "space": int(rng.integers(0, 6)),
          "unit": float(rng.choice([rng.uniform(0.02, 2.0), rng.uniform(0.02, 2.0), 0.0, -1.0]))}
    if reference:
        tf["points"] = min(tf["points"], 60)
        tf["unit"] = abs(tf["unit"]) or 0.5
    if tf["unit"] <= 0:
        expect.append("not positive")
    mapper = {"integration": int(rng.integers(0, 2 if reference else 4)),
              "hexahedra": 0 if reference else int(rng.integers(0, 3)),
              "blend": int(rng.choice([0, 0, 0, 1, 2, 3, 4, 5])),
              "isovalues": int(rng.integers(0, 4)), "planes": int(rng.choice([0, 0, 0, 1, 2]))}
    camera = {"where": str(rng.choice(["outside", "outside", "inside", "parallel"])),
              "direction": rng.normal(size=3).tolist(), "angle": float(rng.uniform(15, 90)),
              "inside": rng.uniform(0.2, 0.8, 3).tolist(),
              "planes": rng.normal(size=(2, 3)).tolist()}
    # Drawn apart (the draws above stay what they were for every seed): cells
    # marked HIDDENCELL, and the grid convexified before rendering.
    extra = np.random.default_rng([seed, case, 1])
    hidden = [int(c) for c in range(len(cells)) if extra.uniform() < 0.2] \
        if extra.uniform() < 0.1 else []
    convexify = bool(extra.uniform() < 0.1)
    return {"seed": seed, "case": case, "kind": str(kind), "jitter": jitter, "points": points,
            "cells": cells, "mutations": mutations, "expect": expect, "scalars": scalars,
            "tf": tf, "mapper": mapper, "camera": camera, "values": int(rng.integers(1 << 30)),
            "hidden": hidden, "convexify": convexify}


def clean_for_reference(case):
    """Whether the reference renderer is ground truth for this case."""
    m = case["mapper"]
    exact = m["integration"] in (0, 1)  # partial pre-integration, exact linear
    geometry = case["kind"] == "tetrahedra" or (
        case["kind"] == "hexahedra" and case["jitter"] == 0.0 and m["hexahedra"] == 0)
    # Hidden cells are rendered empty by both. A convexified grid is not
    # compared: split boundary faces are not crossed exactly yet
    # (Documentation/convexification.md).
    harmless = not case["mutations"] and not case.get("convexify")
    return (exact and geometry and harmless and case["tf"]["unit"] > 0
            and case["tf"]["points"] <= 60 and case["scalars"]["components"] == 1)


# ---------------------------------------------------------------- child side
def build(case):
    """The grid and volume property of a case."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction, vtkUnstructuredGrid
    from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolumeProperty
    rng = np.random.default_rng(case["values"])
    grid = vtkUnstructuredGrid()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    for p in case["points"]:
        points.InsertNextPoint(p)
    grid.SetPoints(points)
    for cell_type, ids in case["cells"]:
        if cell_type == 42:  # a polyhedron: a face stream of 4 triangles on its 4 points
            stream = vtkIdList()
            a, b, c, d = ids
            stream.InsertNextId(4)
            for face in ((a, b, c), (a, b, d), (b, c, d), (a, c, d)):
                stream.InsertNextId(3)
                for i in face:
                    stream.InsertNextId(i)
            grid.InsertNextCell(42, stream)
        else:
            grid.InsertNextCell(int(cell_type), len(ids), ids)
    s = case["scalars"]
    count = grid.GetNumberOfPoints() if s["association"] == "point" else grid.GetNumberOfCells()
    values = rng.uniform(0, 1, (count, s["components"]))
    if "constant" in case["mutations"]:
        values[:] = 0.5
    if "huge_scalar" in case["mutations"]:
        values *= 1e30
    if count and "nan_scalar" in case["mutations"]:
        values[int(rng.integers(count)), 0] = np.nan
    if count and "inf_scalar" in case["mutations"]:
        values[int(rng.integers(count)), 0] = np.inf
    array = vtkDoubleArray()
    array.SetName("s")
    array.SetNumberOfComponents(s["components"])
    for row in values:
        array.InsertNextTuple(row)
    data = grid.GetPointData() if s["association"] == "point" else grid.GetCellData()
    data.SetScalars(array)
    if case.get("hidden"):
        from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes
        ghosts = grid.AllocateCellGhostArray()
        for c in case["hidden"]:
            ghosts.SetValue(c, vtkDataSetAttributes.HIDDENCELL)

    finite = values[np.isfinite(values)]
    lo, hi = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    hi = hi if hi > lo else lo + 1.0
    tf = case["tf"]
    color, opacity = vtkColorTransferFunction(), vtkPiecewiseFunction()
    [color.SetColorSpaceToRGB, color.SetColorSpaceToHSV, color.SetColorSpaceToLab,
     color.SetColorSpaceToLabCIEDE2000, color.SetColorSpaceToDiverging,
     color.SetColorSpaceToStep][tf["space"]]()
    xs = np.sort(rng.uniform(lo, hi, tf["points"]))
    for x in xs:
        color.AddRGBPoint(x, *rng.uniform(0, 1, 3))
        opacity.AddPoint(x, float(rng.uniform(0, 1)))
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(tf["unit"])
    for i in range(case["mapper"]["isovalues"]):
        prop.GetIsoSurfaceValues().SetValue(i, float(rng.uniform(lo, hi)))
    return grid, prop


def place_camera(renderer, case, grid):
    camera = renderer.GetActiveCamera()
    c = case["camera"]
    camera.SetViewAngle(c["angle"])
    camera.SetParallelProjection(c["where"] == "parallel")
    d = np.array(c["direction"])
    d = d / (np.linalg.norm(d) or 1.0)
    b = np.array(grid.GetBounds() if grid.GetNumberOfPoints() else (0, 1, 0, 1, 0, 1), float)
    b = np.nan_to_num(b, nan=0.0, posinf=1.0, neginf=0.0)
    centre = 0.5 * (b[0::2] + b[1::2])
    if c["where"] == "inside":
        eye = b[0::2] + np.array(c["inside"]) * (b[1::2] - b[0::2])
        camera.SetPosition(*eye)
        camera.SetFocalPoint(*(eye + d))
        camera.SetClippingRange(1e-3 * max(np.ptp(b), 1e-30), 10 * max(np.ptp(b), 1e-30))
    else:
        camera.SetFocalPoint(*centre)
        camera.SetPosition(*(centre + d))
        renderer.ResetCamera(*b)
    camera.SetViewUp(*(np.cross(d, [0.3, 1.0, 0.2]) + 1e-9))
    camera.OrthogonalizeViewUp()


def render_case(case, window, renderer, messages, images=None):
    """Render one case; returns its result (a dict). images, a dict, receives
    the mapper's image and the reference's (RGB, 0-255) when given."""
    import ppiray
    from vtkmodules.vtkCommonDataModel import vtkPlane
    from vtkmodules.vtkRenderingCore import vtkVolume
    from ppiray_scene import compare_with_reference, reference_rgba, window_rgb
    before = len(messages.GetOutput() or "")  # the filter's messages count too
    grid, prop = build(case)
    if case.get("convexify") and hasattr(ppiray, "vtkUnstructuredGridConvexify"):
        # Malformed grids too: a defined result (refused with an error: the
        # input as it is) and never a crash or hang.
        convexify = ppiray.vtkUnstructuredGridConvexify()
        convexify.SetInputData(grid)
        convexify.Update()
        grid = convexify.GetOutput()
    Mapper = ppiray.vtkUnstructuredGridGPURayCastMapper
    mapper = Mapper()
    m = case["mapper"]
    mapper.SetIntegrationMode(m["integration"])
    mapper.SetHexahedronMode(m["hexahedra"])
    mapper.SetBlendMode(m["blend"])
    planes = []
    for k in range(m["planes"]):
        plane = vtkPlane()
        b = np.nan_to_num(np.array(grid.GetBounds(), float), nan=0.0, posinf=1.0, neginf=0.0)
        plane.SetOrigin(*(0.5 * (b[0::2] + b[1::2])))
        plane.SetNormal(*case["camera"]["planes"][k])
        mapper.AddClippingPlane(plane)
        planes.append(plane)
    mapper.SetInputData(grid)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer.RemoveAllViewProps()
    renderer.AddVolume(volume)
    place_camera(renderer, case, grid)
    window.Render()
    image = window_rgb(window)
    text = (messages.GetOutput() or "")[before:]
    result = {"case": case["case"], "messages": text[-2000:], "lit": int((image > 0).sum())}
    if images is not None:
        images["mapper"] = image
    # Infinite coordinates stop the frame (nothing else is read); the unit
    # distance is read with the transfer function, when cells render.
    # A grid with non-finite (or degenerate) bounds may be culled by the
    # renderer before the mapper is asked to draw: nothing drawn, nothing said.
    fatal = "infinite or NaN point coordinates"
    required = [fatal] if fatal in case["expect"] else case["expect"]
    if fatal in required and result["lit"] == 0 and not text.strip():
        required = []
    if np.all(np.isfinite(np.array(case["points"], float))):  # a later mutation overwrote it
        required = [e for e in required if e != fatal] or [
            e for e in case["expect"] if e != fatal]
    # A later mutation (duplicated points appended) may have made an id
    # past the end valid again: expected only if one is still out of range.
    count = len(case["points"])
    if not any(i < 0 or i >= count for _, ids in case["cells"] for i in ids):
        required = [e for e in required if e != "point ids outside"]
    missing = [e for e in required if e not in text and (e != "not positive" or result["lit"] > 0)]
    if missing:
        result["failure"] = "no message saying %s (mutations %s)" % (
            " / ".join(missing), ", ".join(case["mutations"]))
    # A transfer function cut at MaximumNumberOfControlPoints is an
    # approximation the mapper announces (a warning): not compared.
    truncated = "control points to stay within" in text
    if clean_for_reference(case) and grid.GetNumberOfCells() and not truncated:
        rgba, _ = reference_rgba(grid, prop, renderer.GetActiveCamera(), SIZE, m["blend"],
                                 renderer.GetLights(),
                                 mapper.GetClippingPlanes() if planes else None)
        if images is not None:
            images["reference"] = 255.0 * np.clip(rgba[:, :3], 0, 1)
        c = compare_with_reference(image, rgba)
        if c["covered"]:
            result["reference"] = [c["covered"], c["p99"], c["max"], c["above8"]]
            if c["p99"] > 2.0 or c["above8"] > max(3, c["covered"] // 100):
                result["failure"] = "differs from the reference: %d pixels, p99 %.1f, max %.0f, " \
                    "%d above 8/255" % (c["covered"], c["p99"], c["max"], c["above8"])
    volume.SetMapper(None)
    renderer.RemoveAllViewProps()
    return result


def child(seed, first, count):
    from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
    messages = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(messages)
    window = vtkRenderWindow()
    window.SetMultiSamples(0)
    window.SetSize(SIZE, SIZE)
    renderer = vtkRenderer()
    # No culling: a prop VTK finds too small on screen (coordinates x 1e-30)
    # would never reach the mapper, which is what is under test.
    renderer.GetCullers().RemoveAllItems()
    window.AddRenderer(renderer)
    for case in range(first, first + count):
        start = time.perf_counter()
        result = render_case(make_case(seed, case), window, renderer, messages)
        result["seconds"] = time.perf_counter() - start
        print("RESULT " + json.dumps(result), flush=True)


# --------------------------------------------------------------- parent side
def read_log(path, seed, cases):
    """Results already in the log for this seed and these cases."""
    results = {}
    if os.path.exists(path):
        with open(path) as log:
            for line in log:
                r = json.loads(line)
                if r.get("seed") == seed and r["case"] in cases:
                    results[r["case"]] = r
    return results


def run_batch(seed, first, count, timeout):
    """Results of cases [first, first + count) by case; a crash or a hang
    ends the batch (the cases without a result are returned as missing)."""
    command = [sys.executable, os.path.abspath(__file__), "--child", "--seed", str(seed),
               "--case", str(first), "--count", str(count)]
    try:
        run = subprocess.run(command, capture_output=True, text=True, timeout=timeout * count)
        outcome = None if run.returncode == 0 else "exit %d" % run.returncode
        out = run.stdout
    except subprocess.TimeoutExpired as expired:
        outcome = "no result within %g s per case" % timeout
        out = expired.stdout.decode() if isinstance(expired.stdout, bytes) else (expired.stdout or "")
    results = {}
    for line in out.splitlines():
        if line.startswith("RESULT "):
            r = json.loads(line[7:])
            results[r["case"]] = r
    return results, outcome


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                     epilog="\n".join(__doc__.splitlines()[2:]),
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--count", type=int, default=200, help="cases (default 200)")
    parser.add_argument("--seed", type=int, default=1, help="seed (default 1)")
    parser.add_argument("--first", type=int, default=0, help="first case (default 0)")
    parser.add_argument("--case", type=int, help="run this case only (with --child: the first)")
    parser.add_argument("--log", help="append results to this file and resume from it")
    parser.add_argument("--timeout", type=float, default=120.0,
                        help="seconds a case may take (default 120)")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--show", action="store_true", help="print the case (with --case)")
    args = parser.parse_args()
    if args.child:
        child(args.seed, args.case, args.count)
        return 0
    if args.show and args.case is not None:
        print(json.dumps(make_case(args.seed, args.case), indent=1))
        return 0
    first, count = (args.case, 1) if args.case is not None else (args.first, args.count)
    start = time.perf_counter()
    results = read_log(args.log, args.seed, range(first, first + count)) if args.log else {}
    for batch in range(first, first + count, BATCH):
        todo = [case for case in range(batch, min(batch + BATCH, first + count))
                if case not in results]
        if not todo:
            continue
        got, outcome = run_batch(args.seed, todo[0], todo[-1] + 1 - todo[0], args.timeout)
        if outcome:
            # Name the case: rerun each case without a result alone.
            for case in todo:
                if case not in got:
                    single, why = run_batch(args.seed, case, 1, args.timeout)
                    got.update(single)
                    if why:
                        got[case] = {"case": case, "failure": why}
        got = {case: r for case, r in got.items() if case in todo}
        results.update(got)
        if args.log:
            with open(args.log, "a") as log:
                for case in sorted(got):
                    log.write(json.dumps(dict(got[case], seed=args.seed)) + "\n")
    failures = []
    for case, r in sorted(results.items()):
        if "failure" in r:
            failures.append((case, r["failure"]))
    compared = [r["reference"] for r in results.values() if "reference" in r]
    slowest = sorted(results.values(), key=lambda r: -r.get("seconds", 0))[:3]
    kinds = {}
    for case in range(first, first + count):
        for m in make_case(args.seed, case)["mutations"] or ["clean"]:
            kinds[m] = kinds.get(m, 0) + 1
    for case, why in sorted(failures):
        print("FAILED case %d: %s  (Module/run fuzz --seed %d --case %d)"
              % (case, why, args.seed, case))
    print("fuzz seed %d: %d cases in %.0f s (%.0f s of cases), %d failures; %d compared with "
          "the reference (worst p99 %.2f, worst max %.0f /255); slowest cases %s; mutations %s"
          % (args.seed, count, time.perf_counter() - start,
             sum(r.get("seconds", 0) for r in results.values()), len(failures), len(compared),
             max([c[1] for c in compared], default=0), max([c[2] for c in compared], default=0),
             ", ".join("%d (%.1f s)" % (r["case"], r["seconds"]) for r in slowest),
             ", ".join("%s %d" % kv for kv in sorted(kinds.items()))))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
