"""results.csv, results.md, pareto.png and <scene>.png of Module/run bench."""
import csv
import os

import numpy as np

COLUMNS = ["scene", "method", "mode", "ms_per_frame", "cells", "gpu_bytes", "rmse_255",
           "p99_255", "max_255", "frac_over_2", "status"]


def label(row):
    return row["method"].replace("vtkUnstructuredGridVolume", "UGVolume") + (
        " " + row["mode"] if row["mode"] else "")


def pareto_front(points):
    """Indices of the (time, error) points no other point beats in both."""
    front = []
    for i, (t, e) in enumerate(points):
        if not any((t2 <= t and e2 <= e) and (t2 < t or e2 < e) for t2, e2 in points):
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def notes_path(args):
    return os.path.join(args.out, "results_notes.json")


def write_reports(rows, args):
    import json

    with open(notes_path(args), "w") as f:
        json.dump({"|".join((r["scene"], r["method"], r["mode"])): r.get("notes", "")
                   for r in rows}, f, indent=0)
    with open(os.path.join(args.out, "results.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)

    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    lines = ["# Speed against error", "",
             "%dx%d, %d views; error against the exact CPU reference, per channel in 1/255; "
             "produced by `Module/run bench --out %s`." % (args.width, args.height, args.views,
                                                           args.out), ""]
    for scene in scenes:
        lines += ["## %s" % scene, "",
                  "| method | mode | ms/frame | cells | M cells/s | GPU bytes | RMSE | p99 | max | "
                  ">2/255 | status | notes |",
                  "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|"]
        for r in rows:
            if r["scene"] == scene:
                rate = ("%.2f" % (float(r["cells"]) / float(r["ms_per_frame"]) / 1000.0)
                        if r["ms_per_frame"] and r["cells"] else "")
                lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                    r["method"], r["mode"], r["ms_per_frame"], r["cells"], rate, r["gpu_bytes"],
                    r["rmse_255"], r["p99_255"], r["max_255"], r["frac_over_2"], r["status"],
                    r.get("notes", "")))
        lines.append("")
    with open(os.path.join(args.out, "results.md"), "w") as f:
        f.write("\n".join(lines))

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    columns = min(3, len(scenes))
    grid_rows = (len(scenes) + columns - 1) // columns
    fig, axes = plt.subplots(grid_rows, columns, figsize=(6 * columns, 4.5 * grid_rows),
                             squeeze=False)
    for ax, scene in zip(axes.ravel(), scenes):
        ok = [r for r in rows if r["scene"] == scene and r["status"] == "ok"]
        points = [(float(r["ms_per_frame"]), max(float(r["rmse_255"]), 0.01)) for r in ok]
        for r, (t, e) in zip(ok, points):
            ours = r["method"] == "ppiray"
            ax.scatter(t, e, marker="o" if ours else "s", color="C0" if ours else "C1", s=25)
            ax.annotate(label(r), (t, e), fontsize=6, xytext=(3, 3), textcoords="offset points")
        if not points:
            ax.set_title(scene + " (no method succeeded)")
            ax.axis("off")
            continue
        front = pareto_front(points)
        ax.plot([points[i][0] for i in front], [points[i][1] for i in front], "k--", lw=0.8,
                label="non-dominated front")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("ms per frame")
        ax.set_ylabel("RMSE vs reference (1/255)")
        ax.set_title(scene)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    for ax in axes.ravel()[len(scenes):]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "pareto.png"), dpi=110)
    plt.close(fig)

    for scene in scenes:
        folder = os.path.join(args.out, scene)
        reference = np.rint(np.load(os.path.join(folder, "reference_view0.npy")))
        shown = [("reference", reference)]
        for r in rows:
            ours = "default" in r["mode"] or "HEXAHEDRON" in r["mode"]
            wanted = (r["method"] == "ppiray" and ours) or (
                r["method"] != "ppiray" and r["mode"] in ("", "default integrator", "128^3"))
            path = os.path.join(r["images"], "view0.npy")
            if r["scene"] == scene and wanted and r["status"] == "ok" and os.path.exists(path):
                shown.append((label(r), np.load(path).astype(float)))
        fig, axes = plt.subplots(2, len(shown), figsize=(2.6 * len(shown), 5.6), squeeze=False)
        for k, (name, image) in enumerate(shown):
            axes[0, k].imshow(np.clip(image / 255.0, 0, 1), origin="lower")
            axes[0, k].set_title(name, fontsize=7)
            diff = np.clip(np.abs(image - reference) * 8.0 / 255.0, 0, 1)
            axes[1, k].imshow(diff, origin="lower")
            axes[1, k].set_title("|difference| x 8" if k else "", fontsize=7)
            for row in (0, 1):
                axes[row, k].axis("off")
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, scene + ".png"), dpi=100)
        plt.close(fig)
