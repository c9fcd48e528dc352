# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""Plots of havs_benchmark's CSV: time against RMSE (log axes, Pareto front),
time against the number of tets, time against the number of pixels. Needs matplotlib (Debian
python3-matplotlib); without it, says so and does nothing."""
import csv
import math
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("havs_benchmark_plots: matplotlib is not installed (python3-matplotlib); no plots")
    sys.exit(0)

rows = list(csv.DictReader(open(sys.argv[1])))
out = sys.argv[2]


def number(text):
    try:
        value = float(text)
        return value if math.isfinite(value) else None
    except ValueError:
        return None


fig, ax = plt.subplots(figsize=(8, 6))
for dataset in sorted({r["dataset"] for r in rows}):
    points = [(number(r["ms_median"]), number(r["rmse"]), r["config"]) for r in rows
              if r["dataset"] == dataset and number(r["rmse"]) and number(r["ms_median"])]
    if not points:
        continue
    xs, ys, names = zip(*points)
    ax.scatter(xs, ys, label=dataset)
    for x, y, name in points:
        ax.annotate(name, (x, y), fontsize=6)
    front, best = [], math.inf
    for x, y, _ in sorted(points):
        if y < best:
            front.append((x, y))
            best = y
    ax.plot([p[0] for p in front], [p[1] for p in front], linestyle="--", linewidth=0.8)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("ms per frame (median)")
ax.set_ylabel("RMSE against the exact reference")
ax.set_title("vtkHAVS benchmark: time against error (dashed: Pareto front)")
ax.legend(fontsize=7)
fig.savefig(f"{out}/benchmark_time_error.png", dpi=120)

fig, ax = plt.subplots(figsize=(8, 6))
for config in sorted({r["config"] for r in rows}):
    points = sorted((number(r["tets"]), number(r["ms_median"])) for r in rows
                    if r["config"] == config and number(r["ms_median"]))
    if points:
        ax.plot([p[0] for p in points], [p[1] for p in points], marker="o", label=config)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("tetrahedra")
ax.set_ylabel("ms per frame (median)")
ax.legend(fontsize=6)
fig.savefig(f"{out}/benchmark_time_tets.png", dpi=120)
fig, ax = plt.subplots(figsize=(8, 6))
for key in sorted({(r["dataset"], r["config"]) for r in rows}):
    points = sorted((number(r.get("size", "")) ** 2, number(r["ms_median"])) for r in rows
                    if (r["dataset"], r["config"]) == key and number(r.get("size", ""))
                    and number(r["ms_median"]))
    if points:
        ax.plot([p[0] for p in points], [p[1] for p in points], marker="o",
                label=f"{key[0]} {key[1]}")
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("pixels")
ax.set_ylabel("ms per frame (median)")
ax.legend(fontsize=6)
fig.savefig(f"{out}/benchmark_time_pixels.png", dpi=120)
print("havs_benchmark_plots: wrote benchmark_time_error.png, benchmark_time_tets.png, "
      "benchmark_time_pixels.png")
