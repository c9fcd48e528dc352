#!/usr/bin/env python3
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""havs_table_candidates.py: issue 45's other two candidates for a cheaper
transfer-function edit, measured on the functions and meshes they would serve.

  havs_table_candidates.py [--datasets bluntfin,loxpost] [--resolution 64]
                           [--tolerance 1e-5] [--output FILE.md] [--control]

(Run with the project's Python set-up: LD_PRELOAD=build/lib/libvtkHAVSExpatFix.so.)
The third candidate, the table built on the GPU, is timed by havs_benchmark's
-gputable configurations and the GPU check's table cases.

1. Incremental rebuilds: an edit changes the functions only between the
   moved node's neighbours, and a table entry changes only where its segment's
   scalar span reaches a fine sample there (the windowed quadrature composites
   each interval from its own samples). The share of entries an edit touches
   is the most an incremental rebuild can save. Counted for the benchmark's
   edit (its middle opacity node) and for every node of each function, at
   --resolution^2 entry pairs; checked against two tables built before and
   after the benchmark's edit, entry by entry (at 24^3: the counts must agree,
   else the exit status is 1; --control counts another node's edit, which must
   disagree).
2. A table independent of the transfer function (Moreland and Angel's
   partial pre-integration): exact only for functions linear between
   breakpoints, so each function is linearized within --tolerance (the
   opacity and the three colour channels as VTK evaluates them, colour
   spaces, midpoints and sharpness included: VTK's GetTable at 65,537
   scalars, greedy longest chords), and every segment then costs one
   evaluation per linear piece its scalar span crosses instead of one table
   look-up. Counted per tetrahedron of each mesh: the pieces its vertices'
   scalar range crosses (a ray's segment in it crosses at most as many).

The functions: the benchmark's (havs_benchmark's standard one), and
ParaView's presets Cool to Warm (diverging space, ParaView's default),
jet (RGB, 9 nodes) and erdc_rainbow_bright (Lab, 13 nodes), from ParaView's
own list (paraview/_colorMaps.py), with the benchmark's opacity.
"""
import argparse
import os
import re
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import havs_app_scene  # noqa: E402,F401  (the build's vtkhavs on the path)
from vtkhavs.vtkHAVSCore import vtkHAVSPreIntegrationTable  # noqa: E402
from vtkhavs.vtkHAVSValidation import vtkHAVSDataSets  # noqa: E402
from vtkmodules.util import numpy_support  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkColorTransferFunction, vtkVolumeProperty)

PRESETS = ("Cool to Warm", "jet", "erdc_rainbow_bright")


def paraview_presets():
    """ParaView's colour maps (name -> (space, [(x, r, g, b)])), or {} without ParaView."""
    try:
        import paraview
        text = open(os.path.join(os.path.dirname(paraview.__file__), "_colorMaps.py")).read()
    except (ImportError, OSError):
        return {}
    maps = {}
    for name, space, body in re.findall(
            r'<ColorMap name="([^"]*)" space="([^"]*)">(.*?)</ColorMap>', text, re.S):
        points = [tuple(float(v) for v in p) for p in re.findall(
            r'<Point x="([^"]*)" o="[^"]*" r="([^"]*)" g="([^"]*)" b="([^"]*)"', body)]
        if not points:
            points = [tuple(float(v) for v in p) for p in re.findall(
                r'<Point x="([^"]*)" r="([^"]*)" g="([^"]*)" b="([^"]*)"', body)]
        maps.setdefault(name, (space, points))
    return maps


def make_property(lo, hi, colors, space="RGB"):
    """The benchmark's opacity (0, 0.1 at 30 %, 0.8) and `colors` [(x in [0, 1], r, g, b)]."""
    span = hi - lo
    color, opacity, prop = vtkColorTransferFunction(), vtkPiecewiseFunction(), vtkVolumeProperty()
    {"RGB": color.SetColorSpaceToRGB, "HSV": color.SetColorSpaceToHSV,
     "Lab": color.SetColorSpaceToLab, "Diverging": color.SetColorSpaceToDiverging}[space]()
    xs = [c[0] for c in colors]
    for x, r, g, b in colors:
        color.AddRGBPoint(lo + span * (x - xs[0]) / (xs[-1] - xs[0]), r, g, b)
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(lo + 0.3 * span, 0.1)
    opacity.AddPoint(hi, 0.8)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(1.0)
    prop.ShadeOff()
    return prop


def node_scalars(f):
    """The scalars of a function's nodes, in order."""
    value = [0.0] * (4 if f.IsA("vtkPiecewiseFunction") else 6)
    scalars = []
    for i in range(f.GetSize()):
        f.GetNodeValue(i, value)
        scalars.append(value[0])
    return scalars


def node_edits(prop):
    """For every node of the opacity and of the colour function, the scalar interval an
    edit of it changes: between its neighbours in its own function."""
    edits = []
    for f in (prop.GetScalarOpacity(), prop.GetRGBTransferFunction()):
        x = node_scalars(f)
        edits += [(x[max(k - 1, 0)], x[min(k + 1, len(x) - 1)]) for k in range(len(x))]
    return edits


def touched_share(lo, hi, changed, n):
    """Share of the n^2 entry pairs whose span reaches the open scalar interval `changed`
    on the table's fine grid (4 sub-steps an interval, plus the functions' nodes: a sample
    strictly inside it changes)."""
    a = (changed[0] - lo) / (hi - lo) * (n - 1)
    b = (changed[1] - lo) / (hi - lo) * (n - 1)
    touched = 0
    for f in range(n):
        for g in range(f, n):
            # The fine samples of [f, g]: is one strictly inside (a, b)? For f < g,
            # exactly when the two overlap: f or g is then inside, or (a, b) lies
            # within [f, g] and holds the moved node.
            hit = a < f < b if f == g else max(a, f) < min(b, g)
            touched += (1 if f == g else 2) if hit else 0
    return touched / (n * n)


def changed_entries(prop, lo, hi, n, node):
    """Entries of two n^3 tables, before and after the benchmark's edit of opacity node
    `node` (its value times 0.9), that differ; and the share the counting predicts."""
    tables = []
    opacity = prop.GetScalarOpacity()
    value = [0.0] * 4
    opacity.GetNodeValue(node, value)
    original = list(value)
    for factor in (1.0, 0.9):
        value[1] = original[1] * factor
        opacity.SetNodeValue(node, value)
        t = vtkHAVSPreIntegrationTable()
        t.SetScalarResolution(n)
        t.SetLengthResolution(n)
        t.Build(prop, 0, (lo, hi), 1.0)
        rgba = [0.0] * 4
        entries = []
        for ell in range(1, n):
            length = t.LengthAt(ell / (n - 1))
            for g in range(n):
                for f in range(n):
                    t.Lookup(lo + (hi - lo) * f / (n - 1), lo + (hi - lo) * g / (n - 1), length,
                             rgba)
                    entries.append(tuple(rgba))
        tables.append(entries)
    opacity.SetNodeValue(node, original)
    differ = sum(1 for x, y in zip(*tables) if x != y)
    return differ / len(tables[0])


def linear_pieces(prop, lo, hi, tolerance, samples=65537):
    """Breakpoints (scalars) of a greedy piecewise-linear fit of the opacity and the three
    colour channels within `tolerance` at `samples` evenly spaced scalars (VTK's GetTable)."""
    opacity = numpy.zeros(samples)
    prop.GetScalarOpacity().GetTable(lo, hi, samples, opacity)
    color = numpy.zeros(3 * samples)
    prop.GetRGBTransferFunction().GetTable(lo, hi, samples, color)
    values = numpy.column_stack([opacity, color.reshape(samples, 3)])
    x = numpy.linspace(0.0, 1.0, samples)

    def fits(i, j):
        t = (x[i:j + 1] - x[i]) / (x[j] - x[i])
        chord = values[i] + numpy.outer(t, values[j] - values[i])
        return numpy.max(numpy.abs(values[i:j + 1] - chord)) <= tolerance

    breaks = [0]
    i = 0
    while i < samples - 1:
        step = 1
        while i + 2 * step < samples and fits(i, i + 2 * step):
            step *= 2
        good, bad = i + step, min(i + 2 * step, samples - 1)
        if bad > good and fits(i, bad):
            good = bad
        while bad - good > 1:
            mid = (good + bad) // 2
            good, bad = (mid, bad) if fits(i, mid) else (good, mid)
        breaks.append(good)
        i = good
    return lo + (hi - lo) * x[numpy.array(breaks)]


def pieces_per_cell(grid, breaks):
    """Per tetrahedron, the linear pieces its vertices' scalar range crosses."""
    scalars = numpy_support.vtk_to_numpy(grid.GetPointData().GetScalars()).astype(float)
    cells = grid.GetCells()
    connectivity = numpy_support.vtk_to_numpy(cells.GetConnectivityArray())
    offsets = numpy_support.vtk_to_numpy(cells.GetOffsetsArray())
    if not numpy.all(numpy.diff(offsets) == 4):
        raise SystemExit("havs_table_candidates: the mesh is not all tetrahedra")
    s = scalars[connectivity].reshape(-1, 4)
    low, high = s.min(axis=1), s.max(axis=1)
    inner = numpy.asarray(breaks[1:-1])
    return 1 + numpy.searchsorted(inner, high, "left") - numpy.searchsorted(inner, low, "right")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--datasets", default="bluntfin,loxpost")
    parser.add_argument("--resolution", type=int, default=64)
    parser.add_argument("--tolerance", type=float, default=1e-5)
    parser.add_argument("--output", default="")
    parser.add_argument("--control", action="store_true",
                        help="count the benchmark's edit as if it moved the first opacity node: "
                        "the check against the two tables must then fail (exit 1)")
    args = parser.parse_args()
    presets = paraview_presets()
    out = ["# Transfer-function edits: the other two candidates (issue 45)", "",
           "Generated by `Apps/havs_table_candidates.py --datasets %s --resolution %d "
           "--tolerance %g` (not edited by hand). Counts, not timings: what each candidate "
           "would have to do." % (args.datasets, args.resolution, args.tolerance), ""]
    benchmark_colors = [(0.0, 0.1, 0.2, 1.0), (0.3, 0.16, 0.68, 0.58), (0.5, 0.2, 1.0, 0.3),
                        (1.0, 1.0, 0.3, 0.1)]
    functions = [("the benchmark's", benchmark_colors, "RGB")]
    for name in PRESETS:
        if name in presets:
            space, points = presets[name]
            functions.append(("ParaView's %s (%s)" % (name, space), points, space))
        else:
            print("ParaView's preset %s not found: left out" % name)
    failures = 0
    for dataset in args.datasets.split(","):
        grid = vtkHAVSDataSets.Load(dataset)
        lo, hi = grid.GetPointData().GetScalars().GetRange()
        out += ["## %s (%d tetrahedra, scalars %.6g to %.6g)" % (
            dataset, grid.GetNumberOfCells(), lo, hi), ""]
        rows_incremental, rows_partial, check = [], [], ""
        for label, colors, space in functions:
            prop = make_property(lo, hi, colors, space)
            edits = node_edits(prop)
            nodes = len(edits)
            # 1. The benchmark's edit: the middle opacity node (index 1).
            benchmark_share = touched_share(lo, hi, edits[1], args.resolution)
            shares = [touched_share(lo, hi, e, args.resolution) for e in edits]
            if label == "the benchmark's":
                measured = changed_entries(prop, lo, hi, 24, 1)
                predicted = touched_share(lo, hi, edits[0 if args.control else 1], 24)
                agree = abs(measured - predicted) < 1e-9
                failures += 0 if agree else 1
                check = "Checked on two 24^3 tables of the benchmark's function, before and " \
                        "after its edit, entry by entry: %.2f %% of the entries of length > 0 " \
                        "differ; counted: %.2f %%%s." % (100 * measured, 100 * predicted,
                                                        "" if agree else " (DISAGREE)")
            rows_incremental.append("| %s | %d | %.1f %% | %.1f %% | %.1f %% |" % (
                label, nodes, 100 * benchmark_share, 100 * numpy.median(shares),
                100 * min(shares)))
            # 2. Linearized for partial pre-integration.
            breaks = linear_pieces(prop, lo, hi, args.tolerance)
            pieces = pieces_per_cell(grid, breaks)
            rows_partial.append("| %s | %d | %d | %.2f | %d | %d | %.1f %% |" % (
                label, nodes, len(breaks) - 1, pieces.mean(), numpy.percentile(pieces, 95),
                pieces.max(), 100 * numpy.mean(pieces > 1)))
            print("%s, %s: done" % (dataset, label), flush=True)
        out += ["### Incremental rebuilds: the share of the table an edit touches",
                "", "At %d^2 entry pairs (every length alike). The benchmark's edit moves the "
                "middle opacity node; a node's edit changes its function between its "
                "neighbours. Nodes: the opacity's and the colour's." % args.resolution,
                "", "| function | nodes | the benchmark's edit | median over its nodes | "
                "least over its nodes |", "|---|---|---|---|---|"] + rows_incremental + [
                    "", check, ""]
        out += ["### Partial pre-integration: linear pieces a segment crosses", "",
                "Each function linearized within %g (opacity and colour channels); per "
                "tetrahedron, the pieces its vertices' scalar range crosses: what a segment "
                "through it costs in evaluations, against one table look-up." % args.tolerance,
                "", "| function | nodes | linear pieces | pieces per cell, mean | 95th "
                "percentile | most | cells crossing a breakpoint |",
                "|---|---|---|---|---|---|---|"] + rows_partial + [""]
    text = "\n".join(out) + "\n"
    print(text)
    if args.output:
        with open(args.output, "w") as f:
            f.write(text)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
