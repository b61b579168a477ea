"""Runs the README's "Use it in Python" script exactly as written: the first
```python block of that section, saved as render.py in a scratch folder that
holds the repository's Data/ (the script reads Data/wavelet_hole.vtu relative
to the repository), run by /usr/bin/python3 with the build's ppiray on
PYTHONPATH (the ctest environment). Fails unless it exits 0, prints at least
one peel and writes a render.png with at least 2,000 lit pixels.

Run: TestReadmePython.py REPOSITORY_ROOT SCRATCH_DIR
"""
import os
import re
import shutil
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader


def main(root, scratch):
    readme = open(os.path.join(root, "README.md"), encoding="utf-8").read()
    section = readme[readme.index("## Use it in Python"):]
    section = section[:section.index("\n## ", 1)]
    script = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    os.symlink(os.path.join(root, "Data"), os.path.join(scratch, "Data"))
    with open(os.path.join(scratch, "render.py"), "w", encoding="utf-8") as f:
        f.write(script)
    run = subprocess.run(["/usr/bin/python3", "render.py"], cwd=scratch, capture_output=True,
                         text=True, timeout=300)
    print(run.stdout + run.stderr)
    failures = []
    if run.returncode != 0:
        failures.append("render.py exited with %d" % run.returncode)
    peels = re.search(r"peels (\d+)", run.stdout)
    if not peels or int(peels.group(1)) < 1:
        failures.append("render.py printed no peel")
    png = os.path.join(scratch, "render.png")
    lit = 0
    if os.path.exists(png):
        reader = vtkPNGReader()
        reader.SetFileName(png)
        reader.Update()
        pixels = reader.GetOutput().GetPointData().GetScalars()
        for i in range(pixels.GetNumberOfTuples()):
            if max(pixels.GetTuple(i)[:3]) > 0:
                lit += 1
    print("render.png: %d lit pixels" % lit)
    if lit < 2000:
        failures.append("render.png has %d lit pixels (at least 2000 expected)" % lit)
    for failure in failures:
        print("FAILED: " + failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    main(*sys.argv[1:])
