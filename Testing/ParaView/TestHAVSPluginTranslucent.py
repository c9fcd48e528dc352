# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""Translucent surfaces intermixed with the HAVS Volume in ParaView (issue 46), serial.

The LOX post shown as "HAVS Volume" and, in the same view, a Contour of its Pressure (one
value at 45 % of the range) shown as a translucent Surface (opacity 0.7, one colour, lit by
ambient light alone so that its colour does not depend on ParaView's lights). The screenshot
of each mapper against the exact reference with the contour's polygons as events along the
rays (vtkHAVSReferenceRenderer::AddTranslucentSurface, rasterized exactly, no GL), RMSE below
0.004. Control: the representation's "Intermix translucent surfaces" off draws the volume
over the surface (ParaView's own order: within the bound of that image), which must miss the
exact image by twice the bound.

Arguments: --plugin PATH --out DIR
Run under Xvfb (Debian's ParaView is GLX-only).
"""
import argparse
import os
import sys

from paraview import servermanager
from paraview.simple import Contour, LoadPlugin, Render, SaveScreenshot, Show
from vtkmodules.vtkRenderingCore import vtkVolumeProperty

import vtkhavs
from havs_plugin_scene import (SIZE, compare, mpi_setup, png_rgb, read_lox_post,
                               require_working_expat, show_lox_post)

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--out", required=True)
args, _ = parser.parse_known_args()
os.makedirs(args.out, exist_ok=True)
failures = []
# Under `mpiexec pvbatch --symmetric` every rank renders its piece; rank 0 has the
# screenshot and checks it.
controller, rank, ranks = mpi_setup()


def check(condition, what):
    if rank != 0:
        return
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


COLOR = (0.2, 0.8, 0.9)
OPACITY = 0.7

require_working_expat()
LoadPlugin(args.plugin, remote=False, ns=globals())
grid = read_lox_post()
tets, view, display, lut, pwf = show_lox_post(grid)
lo, hi = grid.GetPointData().GetArray("Pressure").GetRange()
surface = Contour(Input=tets, ContourBy=["POINTS", "Pressure"],
                  Isosurfaces=[lo + 0.45 * (hi - lo)])
surface_display = Show(surface, view)
surface_display.ColorArrayName = ["POINTS", ""]  # one colour (not ColorBy: see color_by_points)
surface_display.Representation = "Surface"
surface_display.AmbientColor = list(COLOR)
surface_display.DiffuseColor = list(COLOR)
surface_display.Ambient = 1.0
surface_display.Diffuse = 0.0
surface_display.Specular = 0.0
surface_display.Opacity = OPACITY
Render(view)
polygons = servermanager.Fetch(surface)
if rank == 0:
    print("ranks: %d; the contour's polygons fetched: %d" % (ranks, polygons.GetNumberOfCells()),
          flush=True)
check(polygons.GetNumberOfCells() > 100,
      "the contour has polygons (%d)" % polygons.GetNumberOfCells())
camera = view.GetRenderer().GetActiveCamera()  # the VTK camera, for the reference


def reference_rgba(volume, surface):
    """The exact image (premultiplied RGBA pixels): the volume (or none), the contour's
    polygons as events along the rays (or none)."""
    prop = vtkVolumeProperty()
    prop.SetColor(lut.GetClientSideObject())
    prop.SetScalarOpacity(pwf.GetClientSideObject())
    prop.SetScalarOpacityUnitDistance(display.ScalarOpacityUnitDistance)
    reference = vtkhavs.vtkHAVSReferenceRenderer()
    # No volume: a box too small and too transparent to show (opacity 0 at its one value).
    reference.SetInputData(grid if volume else vtkhavs.vtkHAVSDataSets.MakeBox(
        1, 1, 1, 1e-6, lo - (hi - lo), lo - (hi - lo)))
    reference.SetProperty(prop)
    reference.SetCamera(camera)
    reference.SetSize(SIZE, SIZE)
    if surface:
        reference.AddTranslucentSurface(polygons, COLOR + (OPACITY,))
    reference.Render()
    image = reference.GetImage()
    return [[image.GetComponent(i, k) for k in range(4)] for i in range(SIZE * SIZE)]


def over_black(rgba):
    return [[min(1.0, p[k]) for k in range(3)] for p in rgba]


# The 8-bit screenshot against the float reference: its rounding, and the contour's edge
# pixels (GL's rasterization against the exact one); the two orders differ by more.
BOUND = 0.004
if rank == 0:
    exact = over_black(reference_rgba(True, True))
    volume = reference_rgba(True, False)
    alone = reference_rgba(False, True)
    # ParaView's order: the volume over the surface.
    paraview_order = [[min(1.0, v[k] + (1.0 - v[3]) * a[k]) for k in range(3)]
                      for v, a in zip(volume, alone)]
    rmse_orders, _ = compare(exact, paraview_order)
    print("the exact image against ParaView's order: RMSE %.5f" % rmse_orders, flush=True)

for name in ("HAVS", "HAVS Ray Cast", "HAVS Cell Projection"):
    display.HAVSMapper = name
    display.HAVSIntermixTranslucentGeometry = 1
    Render(view)
    shot = os.path.join(args.out, "havs_plugin_translucent_%s.png" % name.replace(" ", "_"))
    SaveScreenshot(shot, view, ImageResolution=[SIZE, SIZE])
    rmse, worst = compare(png_rgb(shot), exact) if rank == 0 else (0, 0)
    check(rmse < BOUND, "%s: the translucent contour intermixed, RMSE %.5f (max %.4f) against "
          "the reference with the contour's polygons" % (name, rmse, worst))
    # Control: the volume over the surface, as ParaView's own Volume representation draws.
    display.HAVSIntermixTranslucentGeometry = 0
    Render(view)
    off_shot = os.path.join(args.out, "havs_plugin_translucent_off_%s.png"
                            % name.replace(" ", "_"))
    SaveScreenshot(off_shot, view, ImageResolution=[SIZE, SIZE])
    off, _ = compare(png_rgb(off_shot), exact) if rank == 0 else (0, 0)
    order, _ = compare(png_rgb(off_shot), paraview_order) if rank == 0 else (0, 0)
    check(off >= 2 * BOUND and order < BOUND,
          "%s: control, intermixing off: RMSE %.5f against the exact image (misses), %.5f "
          "against the volume over the surface (ParaView's order)" % (name, off, order))
display.HAVSIntermixTranslucentGeometry = 1

print("PASSED" if not failures else "FAILED", flush=True)
sys.stdout.flush()
# As TestHAVSPlugin.py: leave without the interpreter's teardown (GLXBadContext under Xvfb).
os._exit(1 if failures else 0)
