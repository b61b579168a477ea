"""Module/run python Documentation/gallery/make_gallery.py [--only NAME,...]

The gallery (Documentation/gallery/README.md): every dataset of the data root
through the demo (Testing/Python/ppiray_demo.py) as a user runs it, twice:
with the demo's defaults (ParaView's for a new volume) and with a transfer
function tuned to the data (TUNED below); each time PPIRay beside VTK's
projected tetrahedra (--compare pt: the same view, colour map and opacity;
the tetrahedra ParaView's volume preprocessor makes), 256 x 256, median of 3
frames after a warm-up. Also times the demo as a user runs it on each file
(its defaults, 512 x 512, comparison off) and fails (exit 1) when one takes
a minute or more. Writes one JPEG per dataset (default PPIRay, default PT,
tuned PPIRay, tuned PT) and README.md (from gallery.json, the measurements
of every dataset; --only reruns some and keeps the others').
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkJPEGWriter

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Python"))
from ppiray_scene import read_png  # noqa: E402

DEMO = os.path.join(ROOT, "Testing", "Python", "ppiray_demo.py")
DATA = os.environ.get("PPIRAY_DATA_ROOT", os.path.join(os.path.dirname(ROOT), "shared", "data"))
SIZE = 256

# name: (the file and its reading options, the tuned options)
DATASETS = {
    "bluntfin": (["bluntfin/bluntfinxyz.bin", "--q", "bluntfin/bluntfinq.bin"],
                 ["--opacity", "0:0,0.14:0,0.23:0.15,0.63:0.5,1:0.8", "--colormap", "Turbo"]),
    "lox_post": (["lox_post/postxyz.bin", "--q", "lox_post/postq.bin", "--function", "110",
                  "--array", "Pressure"],
                 ["--opacity", "0:0,0.45:0,0.55:0.05,0.7:0.3,1:0.9", "--colormap",
                  "Rainbow Uniform"]),
    "lox_post/post.vtk": (["lox_post/post.vtk"],
                          ["--opacity", "0:0,0.6:0.05,1:0.9", "--colormap", "Inferno (matplotlib)"]),
    "combustor": (["combustor/combxyz.bin", "--q", "combustor/combq.bin"],
                  ["--opacity", "0:0,0.5:0.02,0.8:0.4,1:1", "--colormap", "Viridis (matplotlib)"]),
    "disk_out_ref": (["disk_out_ref/disk_out_ref.ex2"],
                     ["--opacity", "0:0,0.3:0.02,0.7:0.2,1:0.8", "--colormap",
                      "Black-Body Radiation"]),
    "can": (["can/can.vtu"], ["--opacity", "0:0.3,0.05:0.8,1:1", "--colormap", "Plasma (matplotlib)",
                              "--view", "0,30"]),
    "notch": (["notch/notch_stress.vtk"],
              ["--array", "Nodal Stress-normed", "--opacity", "0:0.5,0.1:0.8,1:1", "--colormap",
               "Rainbow Uniform", "--unit-distance", "0.01", "--view", "0,50"]),
    "unisim2": (["unisim2/UNISIM-II-D.vtu"], ["--opacity", "0:0.3,1:0.05", "--colormap",
                                               "Viridis (matplotlib)", "--view", "0,40"]),
    "quadratic/CylinderLinear": (["quadratic/CylinderLinear.vtk"],
                                 ["--opacity", "0:0,0.4:0.02,1:0.9", "--colormap", "Jet"]),
    "fea_kiefer_bracket": (["fea_kiefer_bracket/dataset.vtu"],
                           ["--opacity", "0:0.05,0.1:0.3,1:1", "--colormap", "Turbo"]),
    "office": (["office/office.binary.vtk"], ["--opacity", "0:0,0.3:0,0.6:0.05,1:0.6",
                                              "--colormap", "Cool to Warm"]),
    "kitchen": (["kitchen/kitchen.vtk"], ["--opacity", "0:0,0.4:0,0.7:0.1,1:0.7",
                                          "--colormap", "Inferno (matplotlib)"]),
    "angularsector": (["angularsector/AngularSector.vtk"],
                      ["--opacity", "0:0.2,0.5:0,1:0.2", "--colormap", "Blue Orange (divergent)"]),
    "mesh_fs8": (["mesh_fs8/mesh_fs8.exo"], ["--opacity", "0:0.1,1:0.4", "--colormap", "Jet",
                                             "--view", "30,20"]),
    "bucky": (["bucky/Bucky.raw", "--raw", "32x32x32:uint8"],
              ["--opacity", "0:0,0.3:0,0.5:0.3,1:0.9", "--colormap", "Viridis (matplotlib)"]),
    "neghip": (["neghip/neghip.slc"], ["--opacity", "0:0,0.25:0,0.35:0.2,0.6:0.05,1:0.9",
                                       "--colormap", "Cool to Warm"]),
    "hydrogen": (["hydrogen/hydrogen.vti"], ["--opacity", "0:0,0.003:0.05,0.03:0.3,0.3:0.8,1:1",
                                             "--colormap", "Rainbow Uniform"]),
}


def demo(args):
    start = time.perf_counter()
    run = subprocess.run([sys.executable, DEMO] + args, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if run.returncode != 0:
        raise RuntimeError("demo %s: exit %d\n%s%s" % (" ".join(args), run.returncode, run.stdout,
                                                       run.stderr))
    return run.stdout, seconds


def file_args(spec):
    """The dataset's arguments with its files under the data root."""
    out = []
    for i, a in enumerate(spec):
        is_file = i == 0 or spec[i - 1] == "--q"
        out.append(os.path.join(DATA, a) if is_file else a)
    return out


def write_sheet(images, path):
    """The images side by side (each SIZE x SIZE RGB, rows from the bottom)
    as one JPEG, separated by 4 white pixels."""
    gap = 4
    width = len(images) * SIZE + (len(images) - 1) * gap
    sheet = np.full((SIZE, width, 3), 255, np.uint8)
    for k, rgb in enumerate(images):
        x = k * (SIZE + gap)
        sheet[:, x:x + SIZE] = rgb.reshape(SIZE, SIZE, 3).astype(np.uint8)
    image = vtkImageData()
    image.SetDimensions(width, SIZE, 1)
    scalars = numpy_to_vtk(sheet.reshape(-1, 3), deep=True)
    scalars.SetNumberOfComponents(3)
    image.GetPointData().SetScalars(scalars)
    writer = vtkJPEGWriter()
    writer.SetQuality(88)
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def number(pattern, text):
    match = re.search(pattern, text)
    return float(match.group(1)) if match else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", help="comma-separated dataset names")
    args = parser.parse_args()
    names = args.only.split(",") if args.only else list(DATASETS)
    # Rows measured earlier (gallery.json) are kept for the datasets not rerun.
    cache = os.path.join(HERE, "gallery.json")
    rows = json.load(open(cache)) if os.path.exists(cache) else {}
    slow = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            spec, tuned = DATASETS[name]
            files = file_args(spec)
            print("%s ..." % name, flush=True)
            out, seconds = demo(files + ["--out", os.path.join(tmp, "user.png"), "--frames", "1",
                                         "--compare", "none"])
            if seconds >= 60:
                slow.append("%s: %.0f s" % (name, seconds))
            images, times = [], []
            for label, options in (("default", []), ("tuned", tuned)):
                png = os.path.join(tmp, label + ".png")
                text, _ = demo(files + options + ["--out", png, "--size", str(SIZE), "--frames",
                                                  "3", "--compare", "pt"])
                images += [read_png(png), read_png(os.path.join(tmp, label + "_pt.png"))]
                times += [number(r"PPIRay +([0-9.]+) ms", text),
                          number(r"VTK PT +([0-9.]+) ms", text)]
                if label == "default":
                    dataset = re.search(r"dataset +[^:]+: (.*)", text).group(1)
            slug = re.sub(r"[^a-z0-9]+", "_", name.lower()).strip("_")
            write_sheet(images, os.path.join(HERE, slug + ".jpg"))
            rows[name] = (dataset, seconds, times, slug, " ".join(tuned))
    with open(cache, "w") as out:
        json.dump(rows, out, indent=1)
    with open(os.path.join(HERE, "README.md"), "w") as md:
        md.write(GALLERY_HEAD)
        for name in [n for n in DATASETS if n in rows]:
            dataset, seconds, times, slug, tuned = rows[name]
            md.write("### %s\n\n%s. Demo with its defaults at 512², comparison off: %.0f s "
                     "(reading, preparing, one frame).\n\n" % (name, dataset, seconds))
            md.write("| | PPIRay | projected tetrahedra |\n|---|---:|---:|\n")
            md.write("| defaults | %.0f ms | %.0f ms |\n| tuned | %.0f ms | %.0f ms |\n\n"
                     % tuple(times))
            md.write("Tuned: `%s`.\n\n![%s](%s.jpg)\n\n" % (tuned, name, slug))
    print("wrote %s" % os.path.join(HERE, "README.md"))
    if slow:
        print("FAILED: the demo took a minute or more on: %s" % ", ".join(slow))
        return 1
    return 0


GALLERY_HEAD = """# Gallery: every dataset of the data root

Made by `Module/run python Documentation/gallery/make_gallery.py` (its
docstring says what it does): each dataset through `Module/run demo` with the
demo's defaults (ParaView's for a new volume: Cool to Warm, opacity ramp 0
to 1, unit distance about one cell) and with a transfer function tuned to
the data (the options shown); in each picture, left to right: defaults with
PPIRay, defaults with VTK's projected tetrahedra, tuned with PPIRay, tuned
with projected tetrahedra. 256², llvmpipe on 2 cores, ms per frame the
median of 3 frames after a warm-up (PT on the tetrahedra ParaView's volume
preprocessor makes). The seconds are the demo as a user runs it on the
file (512², comparison off), start to exit. Files without a field show their
z coordinate.

"""

if __name__ == "__main__":
    sys.exit(main())
