"""Module/run bench [--scenes LIST] [--size WxH] [--views N] [--out DIR] [--methods LIST]
                   [--modes LIST] [--stages LIST]

Speed against error. For every scene (ppiray_bench_scenes.py) and method,
renders N views (after a warm-up frame; each frame ends with
WaitForCompletion) in a subprocess of its own, so that a crashing peer is
reported and the run goes on, and measures every image against the exact
CPU reference (vtkUnstructuredGridReferenceRenderer, double precision) of
the same view. Writes DIR/results.csv, DIR/results.md, DIR/pareto.png and
DIR/<scene>.png (images and differences side by side). PPIRay runs in the
fragment stage unless --stages lists others (fragment, compute, automatic:
each PPIRay method once per stage; the automatic stage's probe finishes
before the timed views); --modes keeps the PPIRay methods whose mode
contains one of its comma-separated names.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.environ.get("PPIRAY_ROOT", os.path.dirname(os.path.dirname(HERE)))
DATA_ROOT = os.environ.get("PPIRAY_DATA_ROOT", os.path.join(ROOT, "..", "shared", "data"))

# The march stages of --stages (vtkUnstructuredGridGPURayCastMapper::MarchStages).
STAGES = {"fragment": 0, "compute": 1, "automatic": 2}

# (method, mode, settings): our modes and table sizes, then VTK's mappers.
METHODS = [
    ("ppiray", "PARTIAL_PRE_INTEGRATION psi=64", {"mode": 0, "psi": 64}),
    ("ppiray", "PARTIAL_PRE_INTEGRATION psi=256", {"mode": 0, "psi": 256}),
    ("ppiray", "PARTIAL_PRE_INTEGRATION psi=512 (default)", {"mode": 0, "psi": 512}),
    ("ppiray", "PARTIAL_PRE_INTEGRATION psi=1024", {"mode": 0, "psi": 1024}),
    ("ppiray", "EXACT_LINEAR", {"mode": 1}),
    ("ppiray", "FULL_PRE_INTEGRATION table=32", {"mode": 2, "table": 32}),
    ("ppiray", "FULL_PRE_INTEGRATION table=64", {"mode": 2, "table": 64}),
    ("ppiray", "FULL_PRE_INTEGRATION table=128", {"mode": 2, "table": 128}),
    ("ppiray", "AVERAGE_COLOR", {"mode": 3}),
    ("ppiray", "HEXAHEDRON_ACCURATE", {"mode": 0, "hex": 0}),
    ("ppiray", "HEXAHEDRON_FAST", {"mode": 0, "hex": 1}),
    ("ppiray", "HEXAHEDRON_SUBDIVIDE", {"mode": 0, "hex": 2}),
    ("vtkProjectedTetrahedraMapper", "", {}),
    ("vtkUnstructuredGridVolumeRayCastMapper", "default integrator", {}),
    ("vtkUnstructuredGridVolumeRayCastMapper", "partial pre-integration", {"ppi": True}),
    ("vtkUnstructuredGridVolumeZSweepMapper", "", {}),
    ("resample+vtkGPUVolumeRayCastMapper", "64^3", {"dims": 64}),
    ("resample+vtkGPUVolumeRayCastMapper", "128^3", {"dims": 128}),
    ("resample+vtkGPUVolumeRayCastMapper", "256^3", {"dims": 256}),
]


def make_window(scene_name, args, mapper):
    import ppiray_bench_scenes
    from ppiray_scene import scene

    built = ppiray_bench_scenes.build(scene_name, ROOT, DATA_ROOT, args.wavelet_extent)
    if built is None:
        raise SystemExit("no data for scene %s under %s" % (scene_name, DATA_ROOT))
    grid, prop = built
    window, renderer = scene(grid, mapper, args.width, prop)
    window.SetSize(args.width, args.height)
    return grid, prop, window, renderer


def view(renderer, index, views):
    renderer.GetActiveCamera().Azimuth(0.0 if index == 0 else 360.0 / views)
    renderer.ResetCameraClippingRange()


def run_worker(args):
    """Render one method on one scene; print a JSON line; images to .npy."""
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

    import ppiray_bench_scenes

    method, settings = args.worker_method, json.loads(args.worker_settings)
    extra = {}
    if method == "ppiray":
        import ppiray

        mapper = ppiray.vtkUnstructuredGridGPURayCastMapper()
        mapper.SetIntegrationMode(settings["mode"])
        mapper.SetPsiTableSize(settings.get("psi", 512))
        mapper.SetPreIntegrationTableSize(settings.get("table", 64))
        mapper.SetHexahedronMode(settings.get("hex", 2))
        mapper.SetMarchStage(settings.get("stage", STAGES["fragment"]))
    elif method == "vtkProjectedTetrahedraMapper":
        from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLProjectedTetrahedraMapper

        mapper = vtkOpenGLProjectedTetrahedraMapper()
    elif method == "vtkUnstructuredGridVolumeRayCastMapper":
        from vtkmodules.vtkRenderingVolume import (
            vtkUnstructuredGridPartialPreIntegration,
            vtkUnstructuredGridVolumeRayCastMapper,
        )

        mapper = vtkUnstructuredGridVolumeRayCastMapper()
        mapper.SetImageSampleDistance(1.0)
        mapper.AutoAdjustSampleDistancesOff()
        if settings.get("ppi"):
            mapper.SetRayIntegrator(vtkUnstructuredGridPartialPreIntegration())
    elif method == "vtkUnstructuredGridVolumeZSweepMapper":
        from vtkmodules.vtkRenderingVolume import vtkUnstructuredGridVolumeZSweepMapper

        mapper = vtkUnstructuredGridVolumeZSweepMapper()
        mapper.SetImageSampleDistance(1.0)
        mapper.AutoAdjustSampleDistancesOff()
    else:
        mapper = None
    if mapper is None:  # resample to a grid, then VTK's GPU ray caster for images
        from ppiray_bench_resample import resampled_window

        grid, prop, window, renderer, mapper, extra = resampled_window(
            args.scene, args, settings["dims"], make_window)
    else:
        grid, prop, window, renderer = make_window(args.scene, args, mapper)
        if method != "ppiray" and args.scene in ppiray_bench_scenes.HEXAHEDRAL:
            # VTK's unstructured mappers take tetrahedra only.
            grid = ppiray_bench_scenes.tetrahedralized(grid)
            mapper.SetInputData(grid)
    times = []
    for index in range(args.views):
        view(renderer, index, args.views)
        if index == 0:
            window.Render()  # warm-up: uploads, shaders, sorting structures
            for _ in range(12 if settings.get("stage") == STAGES["automatic"] else 0):
                if mapper.GetStatistics().GetChosenMarchStage() >= 0:
                    break
                window.Render()  # the automatic stage's probe, until it has chosen
            window.WaitForCompletion()
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(1000.0 * (time.perf_counter() - start))
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.ReadFrontBufferOff()
        grab.Update()
        pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3]
        np.save(os.path.join(args.worker_out, "view%d.npy" % index),
                pixels.reshape(args.height, args.width, 3))
    result = {"ms": times, "cells": grid.GetNumberOfCells(), "gpu_bytes": "", **extra}
    if method == "ppiray":
        result["stage_ran"] = mapper.GetStatistics().GetMarchStage()
        result["gpu_bytes"] = mapper.GetStatistics().GetGPUMemorySize()
        result["hexahedra"] = mapper.GetStatistics().GetNumberOfHexahedra()
        result["native"] = mapper.GetStatistics().GetNumberOfNativeCells()
        result["tetrahedra"] = mapper.GetStatistics().GetNumberOfTetrahedra()
        if settings["mode"] == 2:
            result["table_build_s"] = mapper.GetStatistics().GetPreIntegrationTableBuildTime()
    print("RESULT " + json.dumps(result))
    return 0


def reference_views(scene_name, args, folder):
    """The exact images of every view, cached as .npy in `folder`."""
    import ppiray
    from vtkmodules.util.numpy_support import vtk_to_numpy

    paths = [os.path.join(folder, "reference_view%d.npy" % i) for i in range(args.views)]
    if all(os.path.exists(p) for p in paths):
        return [np.load(p) for p in paths]
    grid, prop, window, renderer = make_window(
        scene_name, args, ppiray.vtkUnstructuredGridGPURayCastMapper())
    images = []
    for index in range(args.views):
        view(renderer, index, args.views)
        reference = ppiray.vtkUnstructuredGridReferenceRenderer()
        reference.SetInputData(grid)
        reference.SetVolumeProperty(prop)
        reference.SetCamera(renderer.GetActiveCamera())
        reference.SetImageSize(args.width, args.height)
        start = time.perf_counter()
        reference.Update()
        rgba = vtk_to_numpy(reference.GetOutput().GetPointData().GetScalars())
        rgb = np.clip(255.0 * rgba[:, :3], 0, 255).reshape(args.height, args.width, 3)
        np.save(paths[index], rgb)
        images.append(rgb)
        print("  reference view %d: %.1f s" % (index, time.perf_counter() - start), flush=True)
    return images


def errors(images, references):
    """RMSE, p99, max (1/255 units) and the fraction of values off by > 2/255."""
    diff = np.concatenate([np.abs(i.astype(float) - np.rint(r)).ravel()
                           for i, r in zip(images, references)])
    return (float(np.sqrt(np.mean(diff ** 2))), float(np.percentile(diff, 99)),
            float(diff.max()), float(np.mean(diff > 2.0)))


def with_stages(args):
    """METHODS with each PPIRay method once per stage of --stages (the mode
    named with its stage unless fragment), kept by --modes."""
    stages = args.stages.split(",")
    unknown = [s for s in stages if s not in STAGES]
    if unknown:
        raise SystemExit("--stages: unknown %s (fragment, compute, automatic)" % ",".join(unknown))
    keep = [m for m in args.modes.split(",") if m]
    for method, mode, settings in METHODS:
        if method != "ppiray":
            yield method, mode, settings
            continue
        if keep and not any(k in mode for k in keep):
            continue
        for stage in stages:
            named = mode if stage == "fragment" else "%s [%s]" % (mode, stage)
            yield method, named, dict(settings, stage=STAGES[stage])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenes", default=",".join(NAMES_ORDER))
    parser.add_argument("--size", default="256x256")
    parser.add_argument("--views", type=int, default=2)
    parser.add_argument("--out", default="bench")
    parser.add_argument("--methods", default="all",
                        help="comma-separated method names or 'all'")
    parser.add_argument("--modes", default="", help="PPIRay modes to keep (substrings)")
    parser.add_argument("--stages", default="fragment",
                        help="march stages of each PPIRay method: fragment, compute, automatic")
    parser.add_argument("--wavelet-extent", type=int, default=16)
    parser.add_argument("--timeout", type=int, default=900, help="seconds per method")
    parser.add_argument("--merge", action="store_true",
                        help="keep the rows of DIR/results.csv that this run does not redo")
    parser.add_argument("--scene", help=argparse.SUPPRESS)
    parser.add_argument("--worker-method", help=argparse.SUPPRESS)
    parser.add_argument("--worker-settings", help=argparse.SUPPRESS)
    parser.add_argument("--worker-out", help=argparse.SUPPRESS)
    args = parser.parse_args()
    args.width, args.height = (int(v) for v in args.size.lower().split("x"))
    if args.worker_method:
        return run_worker(args)

    from ppiray_bench_report import write_reports

    os.makedirs(args.out, exist_ok=True)
    rows = []
    for scene_name in args.scenes.split(","):
        folder = os.path.join(args.out, scene_name)
        os.makedirs(folder, exist_ok=True)
        print("scene %s" % scene_name, flush=True)
        references = reference_views(scene_name, args, folder)
        import ppiray_bench_scenes

        hexahedral = scene_name in ppiray_bench_scenes.HEXAHEDRAL
        for method, mode, settings in with_stages(args):
            if args.methods != "all" and method not in args.methods.split(","):
                continue
            # Hexahedral scenes: our three hexahedron modes (with the default
            # integration) and the peers; tetrahedral scenes: the rest.
            if method == "ppiray" and ("hex" in settings) != hexahedral:
                continue
            out = os.path.join(folder, tag_of(method, mode))
            os.makedirs(out, exist_ok=True)
            command = [sys.executable, os.path.abspath(__file__), "--scene", scene_name,
                       "--size", args.size, "--views", str(args.views),
                       "--wavelet-extent", str(args.wavelet_extent),
                       "--worker-method", method, "--worker-settings", json.dumps(settings),
                       "--worker-out", out]
            row = {"scene": scene_name, "method": method, "mode": mode, "ms_per_frame": "",
                   "cells": "", "gpu_bytes": "", "rmse_255": "", "p99_255": "", "max_255": "",
                   "frac_over_2": "", "status": "ok", "images": out}
            try:
                run = subprocess.run(command, capture_output=True, text=True,
                                     timeout=args.timeout)
                line = [l for l in run.stdout.splitlines() if l.startswith("RESULT ")]
                if run.returncode != 0 or not line:
                    tail = (run.stderr.strip().splitlines() or ["no output"])[-1][:120]
                    row["status"] = "failed (exit %d): %s" % (run.returncode, tail)
                else:
                    result = json.loads(line[-1][len("RESULT "):])
                    images = [np.load(os.path.join(out, "view%d.npy" % i))
                              for i in range(args.views)]
                    rmse, p99, worst, frac = errors(images, references)
                    row.update({"ms_per_frame": "%.1f" % float(np.median(result["ms"])),
                                "cells": result["cells"], "gpu_bytes": result["gpu_bytes"],
                                "rmse_255": "%.3f" % rmse, "p99_255": "%.1f" % p99,
                                "max_255": "%.0f" % worst, "frac_over_2": "%.4f" % frac})
                    notes = []
                    if settings.get("stage") == STAGES["automatic"]:
                        notes.append("automatic stage: ran %s" % (
                            "compute" if result.get("stage_ran") == STAGES["compute"] else "fragment"))
                    if "table_build_s" in result:
                        notes.append("table built in %.3f s" % result["table_build_s"])
                    if "resample_s" in result:
                        notes.append("resample %.2f s" % result["resample_s"])
                    if result.get("hexahedra"):
                        notes.append("%d hexahedra natively, %.0f GPU B/hexahedron incl. targets"
                                     % (result["hexahedra"],
                                        result["gpu_bytes"] / result["hexahedra"]))
                    elif hexahedral and result.get("tetrahedra"):
                        notes.append("%d tetrahedra" % result["tetrahedra"])
                    row["notes"] = "; ".join(notes)
            except subprocess.TimeoutExpired:
                row["status"] = "timed out after %d s" % args.timeout
            print("  %-40s %-45s %8s ms  rmse %6s  %s" % (
                method, mode, row["ms_per_frame"], row["rmse_255"], row["status"]), flush=True)
            rows.append(row)
    if args.merge and os.path.exists(os.path.join(args.out, "results.csv")):
        redone = {(r["scene"], r["method"], r["mode"]) for r in rows}
        with open(os.path.join(args.out, "results.csv")) as f:
            kept = [r for r in csv.DictReader(f)
                    if (r["scene"], r["method"], r["mode"]) not in redone]
        from ppiray_bench_report import notes_path

        notes = {}
        if os.path.exists(notes_path(args)):
            with open(notes_path(args)) as f:
                notes = json.load(f)
        for r in kept:
            r["images"] = os.path.join(args.out, r["scene"], tag_of(r["method"], r["mode"]))
            r["notes"] = notes.get("|".join((r["scene"], r["method"], r["mode"])), "")
        order = {(s, m, d): i for i, (s, (m, d, _)) in enumerate(
            (s, x) for s in NAMES_ORDER for x in METHODS)}
        rows = sorted(kept + rows, key=lambda r: order.get(
            (r["scene"], r["method"], r["mode"]), len(order)))
    write_reports(rows, args)
    return 0


NAMES_ORDER = ["wavelet", "graded", "graded-spikes", "graded-opaque", "bluntfin", "loxpost",
               "bluntfin-hex", "bluntfin-hex-spikes", "loxpost-hex"]


def tag_of(method, mode):
    """Folder name of a method's images."""
    tag = (method + "_" + mode).replace(" ", "_").replace("^", "").replace("=", "")
    return tag.replace("(", "").replace(")", "").replace("+", "_").replace("[", "").replace("]", "")


if __name__ == "__main__":
    sys.exit(main())
