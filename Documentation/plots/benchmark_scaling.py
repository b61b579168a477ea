"""Frame time against mesh size: PPIRay and vtkProjectedTetrahedraMapper on the
tetrahedralized wavelet (vtkRTAnalyticSource over [-e, e]^3, 5 * (2e)^3
tetrahedra), 512x512, median of the views, same machine, same run.

Writes Documentation/plots/benchmark_scaling[_FUNCTION].png and prints the table.
Run: Module/run python Documentation/plots/benchmark_scaling.py
     [--transfer-function ramp|realistic|cutoff] [--extents 8,16,24,32] [--views 8]
(the bench's transfer functions: ppirayBenchmark --help).
"""
import argparse
import os
import re
import subprocess

from loglog import save_loglog

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--transfer-function", default="ramp")
parser.add_argument("--extents", default="8,16,24,32",
                    help="wavelet half extents (64: 10.5 M tetrahedra)")
parser.add_argument("--views", type=int, default=8)
args = parser.parse_args()
build = os.environ.get("PPIRAY_BUILD_DIR", "build")
bench = os.path.join(build, "bin", "ppirayBenchmark")
extents = [int(e) for e in args.extents.split(",")]
rows = {}
for e in extents:
    for mapper in ("ppiray", "pt"):  # one process each: a crash or leak stays there
        out = subprocess.run([bench, "--wavelet", str(e), "--size", "512x512", "--views",
                              str(args.views), "--mappers", mapper, "--transfer-function",
                              args.transfer_function],
                             capture_output=True, text=True, check=True)
        for line in out.stdout.splitlines():
            m = re.match(r"\| (.+?) \| ([\d.]+) \| \d+ \| ([\d.]+) \| (.*?) \|", line)
            if m:
                rows.setdefault(m.group(1), []).append((5 * (2 * e) ** 3, float(m.group(2))))

print("| tetrahedra | " + " | ".join(rows) + " | ratio |")
print("|---:|" + "---:|" * (len(rows) + 1))
names = list(rows)
for i, e in enumerate(extents):
    times = [rows[n][i][1] for n in names]
    print("| %d | %s | %.2fx |" % (rows[names[0]][i][0], " | ".join("%.1f ms" % t for t in times),
                                    times[1] / times[0]))

suffix = "" if args.transfer_function == "ramp" else "_" + args.transfer_function
out = save_loglog(
    "benchmark_scaling" + suffix,
    [([p[0] for p in points], [p[1] for p in points], "o-", name) for name, points in rows.items()],
    "tetrahedra", "ms per frame (512x512, llvmpipe)",
    "Frame time vs mesh size (%s transfer function)" % args.transfer_function)
print("wrote", out)
