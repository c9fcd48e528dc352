# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""Plots of havs_benchmark's CSV:

- benchmark_time_error.png: time against RMSE, one panel per data set (at one image size:
  512 where measured, else the largest), one marker and colour per mapper family, the Pareto
  front, the face-raster bound as a vertical line; the error is the float result's where the
  row has one (the project's mappers), else the 8-bit window's (VTK's mappers, hollow
  markers), with the window's rounding floor as a grey line;
- benchmark_stages.png: HAVS's frame stages as stacked bars, one panel per data set;
- benchmark_time_tets.png, benchmark_time_pixels.png: time against tets and pixels;
- benchmark_lod.png (when the CSV has havs-lod-* rows): the level of detail, time and RMSE
  against the share of internal faces drawn, one line per strategy, one column per data set
  (100 % is havs-default).

Needs matplotlib (Debian python3-matplotlib); without it, says so and does nothing."""
import csv
import math
import re
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FuncFormatter
except ImportError:
    print("havs_benchmark_plots: matplotlib is not installed (python3-matplotlib); no plots")
    sys.exit(0)

all_rows = list(csv.DictReader(open(sys.argv[1])))
# The level of detail's rows (havs-lod-*) are approximations by design: the report gives
# them their own section and plot; the other plots compare the full-quality mappers.
def level_of_detail(r):
    # A havs-lod-* row, or any row a level-of-detail run measured (its havs-default is
    # the 100 % of that run).
    return r["config"].startswith("havs-lod-") or "havs-lod-" in r.get("command", "")


def edit_run(r):
    # An edit-* row or the reference an edit run made: the report's edit section only.
    return r["config"].startswith("edit-") or "edit-" in r.get("command", "")


def budget_run(r):
    # A lod-<percent>-* row or the reference a frame-budget run made: the report's frame
    # budgets section only.
    return any(re.match(r"lod-[0-9]", text)
               for text in [r["config"]] + re.split(r"[ ,]", r.get("command", "")))


def translucent_run(r):
    # A translucent-* row, or any row a translucent run measured (the rows without the
    # plane beside them and the reference): the report's translucent geometry section only.
    return r["config"].startswith("translucent-") or "translucent-" in r.get("command", "")


def iso_run(r):
    # An iso-* or isomix-* row, or any row an isosurface run measured (its composite rows
    # and reference): the report's isosurface section only.
    command = r.get("command", "")
    return (r["config"].startswith(("iso-", "isomix-")) or ",iso-" in command
            or " iso-" in command or "isomix-" in command)


rows = [r for r in all_rows
        if not level_of_detail(r) and not edit_run(r) and not budget_run(r) and not iso_run(r)
        and not translucent_run(r)]
out = sys.argv[2]
if not rows:
    # Only rows of the report's own sections (an isosurface, translucent, edit or budget run
    # alone): no main plots to draw.
    print("havs_benchmark_plots: no rows for the main plots", file=sys.stderr)
    sys.exit(0)


def number(text):
    try:
        value = float(text)
        return value if math.isfinite(value) else None
    except (TypeError, ValueError):
        return None


# Mapper families: (label, marker, colour), in legend order.
FAMILIES = [
    ("HAVS default settings", "*", "tab:red"),
    ("HAVS centroid order", "o", "tab:blue"),
    ("HAVS MPVO order", "s", "tab:green"),
    ("HAVS Automatic order", "D", "tab:olive"),
    ("HAVS fragment lists", "P", "tab:purple"),
    ("VTK PT", "^", "tab:orange"),
    ("VTK ZSweep", "v", "tab:brown"),
    ("VTK RayCast", "X", "tab:gray"),
    ("cell projection (MPVO cell order)", "h", "tab:cyan"),
    ("GPU ray caster (tetraycast)", "p", "tab:pink"),
]


def family(config):
    if config == "havs-default":
        return FAMILIES[0]
    if config == "havs-lists":
        return FAMILIES[4]
    if config.startswith("havs"):
        if "-mpvo" in config:
            return FAMILIES[2]
        if "-auto" in config:
            return FAMILIES[3]
        return FAMILIES[1]
    if config.startswith("cellproj"):
        return FAMILIES[8]
    if config.startswith("tetraycast"):
        return FAMILIES[9]
    return {"pt": FAMILIES[5], "zsweep": FAMILIES[6], "raycast": FAMILIES[7]}.get(config)


def plot_size(dataset):
    sizes = {number(r.get("size")) for r in rows if r["dataset"] == dataset}
    sizes.discard(None)
    if not sizes:
        return None
    return 512 if 512 in sizes else max(sizes)


datasets = sorted({r["dataset"] for r in rows})


def grid_of(count):
    columns = min(3, max(1, count))
    return (count + columns - 1) // columns, columns


# Time against error, one panel per data set.
nrows, ncols = grid_of(len(datasets))
fig, axes = plt.subplots(nrows, ncols, figsize=(5.2 * ncols, 4.4 * nrows), squeeze=False)
handles = {}
for index, dataset in enumerate(datasets):
    ax = axes[index // ncols][index % ncols]
    size = plot_size(dataset)
    here = [r for r in rows if r["dataset"] == dataset and number(r.get("size")) == size]
    points = []
    floors = []
    for r in here:
        f, t = family(r["config"]), number(r["ms_median"])
        e, window = number(r.get("float_rmse")), False
        if e is None:
            e, window = number(r["rmse"]), True
        if number(r.get("floor_rmse")) is not None:
            floors.append(number(r.get("floor_rmse")))
        if f and t and e is not None:
            e = max(e, 1e-6)  # an exact zero on log axes
            points.append((t, e))
            h = ax.scatter([t], [e], marker=f[1], s=60 if f[1] == "*" else 30,
                           color="none" if window else f[2], edgecolors=f[2] if window else "black",
                           linewidths=1.0 if window else 0.3, zorder=3)
            handles.setdefault(f[0], h)
    front, best = [], math.inf
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    if front:
        h, = ax.plot([p[0] for p in front], [p[1] for p in front], linestyle="--",
                     color="black", linewidth=0.8, drawstyle="steps-post", zorder=2)
        handles.setdefault("Pareto front", h)
    for r in here:
        if r["config"] == "raster-bound" and number(r["ms_median"]):
            h = ax.axvline(number(r["ms_median"]), color="tab:cyan", linewidth=1.2, zorder=1)
            handles.setdefault("face-raster bound", h)
    ax.axhline(5e-4, color="tab:red", linewidth=0.6, linestyle=":", zorder=1)
    if floors:
        h = ax.axhline(max(floors), color="gray", linewidth=0.8, linestyle="-.", zorder=1)
        handles.setdefault("8-bit rounding floor (window errors)", h)
    ax.set_xscale("log")
    ax.set_yscale("log")
    # Plain numbers at 1, 2, 3, 5 x 10^n only: narrow ranges otherwise crowd the axis.
    plain = FuncFormatter(lambda v, _: f"{v:g}" if round(v / 10 ** math.floor(math.log10(v)), 6)
                          in (1, 2, 3, 5) else "")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(plain)
        axis.set_minor_formatter(plain)
    tets = here[0]["tets"] if here else "?"
    ax.set_title(f"{dataset} ({tets} tets, {int(size) if size else '?'}²)", fontsize=9)
    ax.set_xlabel("ms per frame (median)", fontsize=8)
    ax.set_ylabel("RMSE against the exact reference (float result)", fontsize=8)
    ax.tick_params(which="both", labelsize=7)
for index in range(len(datasets), nrows * ncols):
    axes[index // ncols][index % ncols].axis("off")
order = [f[0] for f in FAMILIES] + ["Pareto front", "face-raster bound",
                                    "8-bit rounding floor (window errors)"]
labels = [name for name in order if name in handles]
fig.legend([handles[n] for n in labels], labels, loc="lower center", ncol=min(5, len(labels)),
           fontsize=8, frameon=False)
fig.suptitle("vtkHAVS benchmark: time against error (dotted red: the exact bound, RMSE 5e-4; "
             "hollow markers: measured in the 8-bit window)", fontsize=10)
fig.tight_layout(rect=(0, 0.07, 1, 0.96))
fig.savefig(f"{out}/benchmark_time_error.png", dpi=110)

# The stages of HAVS's frames as stacked bars.
STAGES = [("order", "tab:blue"), ("boundary layers", "tab:green"), ("gather", "tab:olive"),
          ("upload", "tab:pink"), ("draw", "tab:red"), ("resolve", "tab:orange"),
          ("read-backs", "tab:purple"), ("composite", "tab:brown"), ("other", "tab:gray")]


def stages(r):
    get = lambda key: number(r.get(key)) or 0.0
    sort, gather, layers = get("sort_ms"), get("gather_ms"), get("layers_ms")
    parts = [max(0.0, sort - gather - layers), layers, gather, get("upload_ms"), get("draw_ms"),
             get("flush_ms"), get("readback_ms"), get("composite_ms")]
    parts.append(max(0.0, (number(r["ms_median"]) or 0.0) - sum(parts)))
    return parts


fig, axes = plt.subplots(nrows, ncols, figsize=(5.6 * ncols, 4.6 * nrows), squeeze=False)
for index, dataset in enumerate(datasets):
    ax = axes[index // ncols][index % ncols]
    size = plot_size(dataset)
    here = [r for r in rows if r["dataset"] == dataset and number(r.get("size")) == size
            and r["config"].startswith(("havs", "raster")) and number(r.get("sort_ms")) is not None
            and number(r["ms_median"])]
    names = [r["config"] for r in here]
    left = [0.0] * len(here)
    for s, (label, colour) in enumerate(STAGES):
        widths = [stages(r)[s] for r in here]
        ax.barh(range(len(here)), widths, left=left, color=colour, label=label, height=0.7)
        left = [a + b for a, b in zip(left, widths)]
    ax.set_yticks(range(len(here)))
    ax.set_yticklabels(names, fontsize=6)
    ax.invert_yaxis()
    ax.set_xlabel("ms per frame (stage medians)", fontsize=8)
    ax.set_title(f"{dataset} ({int(size) if size else '?'}²)", fontsize=9)
    ax.tick_params(axis="x", labelsize=7)
for index in range(len(datasets), nrows * ncols):
    axes[index // ncols][index % ncols].axis("off")
fig.legend([plt.Rectangle((0, 0), 1, 1, color=c) for _, c in STAGES], [n for n, _ in STAGES],
           loc="lower center", ncol=len(STAGES), fontsize=8, frameon=False)
fig.suptitle("vtkHAVS benchmark: where a frame's time goes", fontsize=10)
fig.tight_layout(rect=(0, 0.05, 1, 0.96))
fig.savefig(f"{out}/benchmark_stages.png", dpi=110)

# Time against the number of tets and of pixels.
fig, ax = plt.subplots(figsize=(8, 6))
for config in sorted({r["config"] for r in rows}):
    points = sorted((number(r["tets"]), number(r["ms_median"])) for r in rows
                    if r["config"] == config and number(r["ms_median"]) and number(r["tets"]))
    if points:
        ax.plot([p[0] for p in points], [p[1] for p in points], marker="o", label=config)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("tetrahedra")
ax.set_ylabel("ms per frame (median)")
ax.legend(fontsize=6, ncol=2)
fig.savefig(f"{out}/benchmark_time_tets.png", dpi=110)
fig, ax = plt.subplots(figsize=(8, 6))
for key in sorted({(r["dataset"], r["config"]) for r in rows}):
    points = sorted((number(r.get("size")) ** 2, number(r["ms_median"])) for r in rows
                    if (r["dataset"], r["config"]) == key and number(r.get("size"))
                    and number(r["ms_median"]))
    if len(points) > 1:
        ax.plot([p[0] for p in points], [p[1] for p in points], marker="o",
                label=f"{key[0]} {key[1]}")
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("pixels")
ax.set_ylabel("ms per frame (median)")
ax.legend(fontsize=6, ncol=2)
fig.savefig(f"{out}/benchmark_time_pixels.png", dpi=110)

# The level of detail: time and error against the share of internal faces drawn.
lod = [r for r in all_rows if r["config"].startswith("havs-lod-") and "rotate" not in r["config"]]
lod_groups = sorted({(r["dataset"], r.get("size")) for r in lod})
if lod_groups:
    fig, axes = plt.subplots(2, len(lod_groups), figsize=(4.5 * len(lod_groups), 7), squeeze=False)
    for column, (dataset, size) in enumerate(lod_groups):
        full = [r for r in all_rows if r["config"] == "havs-default" and level_of_detail(r)
                and r["dataset"] == dataset
                and r.get("size") == size and number(r["ms_median"])]
        for strategy in ["topology", "view", "field", "area", "random"]:
            points = sorted((float(r["config"].rsplit("-", 1)[1]), number(r["ms_median"]),
                             number(r["rmse"])) for r in lod
                            if r["dataset"] == dataset and r.get("size") == size
                            and r["config"].startswith(f"havs-lod-{strategy}-")
                            and number(r["ms_median"]))
            if full:
                points.append((100.0, number(full[0]["ms_median"]), number(full[0]["rmse"])))
            if not points:
                continue
            style = "--" if strategy == "random" else "-"
            axes[0][column].plot([p[0] for p in points], [p[1] for p in points], style,
                                 marker="o", label=strategy)
            axes[1][column].plot([p[0] for p in points], [p[2] for p in points], style,
                                 marker="o", label=strategy)
        axes[0][column].set_title(f"{dataset} ({size}²)")
        axes[0][column].set_ylabel("ms per frame (median)")
        axes[1][column].set_ylabel("RMSE against the exact reference")
        axes[1][column].set_yscale("log")
        for row in (0, 1):
            axes[row][column].set_xlabel("internal faces drawn (%)")
            axes[row][column].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(f"{out}/benchmark_lod.png", dpi=110)
print("havs_benchmark_plots: wrote benchmark_time_error.png, benchmark_stages.png, "
      "benchmark_time_tets.png, benchmark_time_pixels.png"
      + (", benchmark_lod.png" if lod_groups else ""))
