"""Frame time against mesh size: PPIRay and vtkProjectedTetrahedraMapper on the
tetrahedralized wavelet (vtkRTAnalyticSource over [-e, e]^3, 5 * (2e)^3
tetrahedra), 512x512, median of 8 views, same machine, same run.

Writes Documentation/plots/benchmark_scaling.png and prints the table.
Run: Module/run python Documentation/plots/benchmark_scaling.py
"""
import os
import re
import subprocess

from loglog import save_loglog

build = os.environ.get("PPIRAY_BUILD_DIR", "build")
bench = os.path.join(build, "bin", "ppirayBenchmark")
extents = [8, 16, 24, 32]
rows = {}
for e in extents:
    for mapper in ("ppiray", "pt"):  # one process each: a crash or leak stays there
        out = subprocess.run([bench, "--wavelet", str(e), "--size", "512x512", "--views", "8",
                              "--mappers", mapper], capture_output=True, text=True, check=True)
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

out = save_loglog(
    "benchmark_scaling",
    [([p[0] for p in points], [p[1] for p in points], "o-", name) for name, points in rows.items()],
    "tetrahedra", "ms per frame (512x512, llvmpipe)", "Frame time vs mesh size")
print("wrote", out)
