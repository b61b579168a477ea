"""Module/run demo as a user meets it: the bundled mesh (default comparison:
all; the first frame timed apart, each speed sentence naming the faster
mapper by the ratio of the times printed), the can's hexahedra (a user file: no comparison, the first field that
is not an id: cell EQPS, rendered natively; with --hexahedra subdivide:
split), a mesh of triangles only (exit 1, "no 3D cells"), a missing file,
an unknown array and an unknown colour map (exit 1, a message, no speed-up
printed); the options (a ParaView preset — Cool to Warm where VTK comes
without ParaView's presets —, opacity points, a view, a projection, a WxH
size) against the reference (p99 at most 1/255); a
comparison past its --budget stops without an error figure. Skips (125) the
can when the data root is absent.

Run: TestDemo.py DATA_ROOT SCRATCH_DIR
"""
import os
import re
import subprocess
import sys

from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

DEMO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ppiray_demo.py")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ppiray_scene import colormap_names  # noqa: E402


def demo(*args):
    run = subprocess.run([sys.executable, DEMO, "--size", "96", "--frames", "1"] + list(args),
                         capture_output=True, text=True, timeout=600)
    print("$ demo %s -> exit %d\n%s%s" % (" ".join(args), run.returncode, run.stdout,
                                          run.stderr[-600:]))
    return run


def speed_wording(out):
    """The comparisons as the demo must word them: the first frame apart,
    each speed sentence naming the faster mapper of the times printed, by
    their ratio (at least 1)."""
    problems = []
    ours = re.search(r"PPIRay +([0-9.]+) ms/frame", out)
    first = re.search(r"first +([0-9.]+) ms for the first frame: ([0-9.]+) ms preparing", out)
    if not ours or not first or float(first.group(2)) > float(first.group(1)):
        problems.append("the first frame and its preparation expected apart from ms/frame")
    for peer, name in (("VTK PT", "projected tetrahedra"), ("VTK CPU", "VTK's CPU ray caster")):
        line = re.search(r"%s +([0-9.]+) ms/frame.*: (PPIRay|%s) (?:is|are) ([0-9.]+)x faster on "
                         r"this mesh here" % (peer, re.escape(name)), out)
        if not line or not ours:
            problems.append("%s: a speed sentence expected" % peer)
            continue
        mine, theirs = float(ours.group(1)), float(line.group(1))
        faster = "PPIRay" if theirs >= mine else name
        ratio = max(mine, theirs) / min(mine, theirs)
        if line.group(2) != faster or abs(float(line.group(3)) - ratio) > 0.051 * ratio + 0.05:
            problems.append("%s: '%s is %sx faster' for %.1f against %.1f ms" % (
                peer, line.group(2), line.group(3), mine, theirs))
    return problems


def main(data, scratch):
    os.makedirs(scratch, exist_ok=True)
    failures = []

    run = demo("--out", os.path.join(scratch, "bundled.png"))
    if run.returncode != 0 or "tetrahedra" not in run.stdout or "reference" not in run.stdout:
        failures.append("the bundled mesh: exit 0, tetrahedra and the comparison expected")
    failures += speed_wording(run.stdout)

    can = os.path.join(data, "can", "can.vtu")
    skipped = not os.path.exists(can)
    if not skipped:
        run = demo(can, "--out", os.path.join(scratch, "can.png"))
        if (run.returncode != 0 or "cell EQPS" not in run.stdout
                or "hexahedra natively" not in run.stdout or "faster" in run.stdout):
            failures.append("can.vtu: cell EQPS, native hexahedra and no comparison expected")

    # A preset of ParaView's (VTK 9.6 alone has only the built-in Cool to Warm).
    preset = "Viridis (matplotlib)" if "Viridis (matplotlib)" in colormap_names() else "Cool to Warm"
    run = demo("--out", os.path.join(scratch, "options.png"), "--size", "120x90",
               "--colormap", preset, "--opacity", "0:0,0.5:0.1,1:0.8",
               "--view", "40,15", "--blend", "maximum", "--compare", "reference")
    error = re.search(r"reference .*p99 ([0-9.]+)", run.stdout)
    if (run.returncode != 0 or preset + ", opacity 0:0 0.5:0.1 1:0.8" not in run.stdout
            or "at 120x90" not in run.stdout or not error or float(error.group(1)) > 1.0):
        failures.append("options: exit 0, the preset, opacity and size echoed, p99 <= 1 expected")
    run = demo("--out", os.path.join(scratch, "budget.png"), "--compare", "all", "--budget", "0")
    if (run.returncode != 0 or "reference stopped" not in run.stdout
            or "error     vs" in run.stdout or "faster" in run.stdout):
        failures.append("--budget 0: both comparisons stopped, no error or speed-up printed")
    if not skipped:
        run = demo(can, "--out", os.path.join(scratch, "can_split.png"), "--hexahedra", "subdivide")
        if run.returncode != 0 or "tetrahedra (cells split)" not in run.stdout:
            failures.append("can.vtu --hexahedra subdivide: split tetrahedra expected")

    sphere = vtkSphereSource()
    append = vtkAppendFilter()
    append.AddInputConnection(sphere.GetOutputPort())
    writer = vtkXMLUnstructuredGridWriter()
    triangles = os.path.join(scratch, "triangles.vtu")
    writer.SetFileName(triangles)
    writer.SetInputConnection(append.GetOutputPort())
    writer.Write()
    for args, message in (((triangles,), "no 3D cells"),
                          ((os.path.join(scratch, "missing.vtu"),), "no such file"),
                          (("--array", "nothing"), "no point or cell array named nothing"),
                          (("--colormap", "nothing"), "no colour map named 'nothing'")):
        run = demo(*args)
        if run.returncode == 0 or message not in run.stderr or "faster" in run.stdout:
            failures.append("%s: exit 1 with '%s' expected" % (" ".join(args), message))

    for failure in failures:
        print("FAILED: " + failure)
    sys.exit(1 if failures else (125 if skipped else 0))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    main(*sys.argv[1:])
