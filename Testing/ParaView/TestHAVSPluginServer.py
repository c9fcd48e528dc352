# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""The vtkHAVS plugin on a pvserver (2 MPI ranks) driven by a pvpython client; the plugin
is found through PV_PLUGIN_PATH on both sides (no LoadPlugin call).

Shows the LOX post as "HAVS Volume" on the server, k set from the client, and compares the
client's screenshot with the serial image of TestHAVSPlugin.py (same scene): equal within a
tolerance; the stock "Volume" representation (projected tetrahedra) of the same scene must
differ from it by more (negative control).

Arguments: --port N --out DIR --serial PNG. Environment: HAVS_DATA_DIR, PV_PLUGIN_PATH.
"""
import argparse
import os
import sys

from paraview.simple import Connect, Render, SaveScreenshot

from havs_plugin_scene import (SIZE, compare, png_rgb, read_lox_post, require_working_expat,
                               show_lox_post)

parser = argparse.ArgumentParser()
parser.add_argument("--port", type=int, required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--serial", required=True)
args, _ = parser.parse_known_args()
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


require_working_expat()
connection = Connect("localhost", args.port)
check(connection is not None, "connected to pvserver on port %d" % args.port)
tets, view, display, lut, pwf = show_lox_post(read_lox_post())
check("HAVS Volume" in display.GetProperty("Representation").Available,
      "the server and the client know the HAVS Volume representation (PV_PLUGIN_PATH)")
Render(view)
os.makedirs(args.out, exist_ok=True)
havs_png = os.path.join(args.out, "havs_plugin_pvserver.png")
SaveScreenshot(havs_png, view, ImageResolution=[SIZE, SIZE])
display.Representation = "Volume"
Render(view)
pt_png = os.path.join(args.out, "havs_plugin_pvserver_pt.png")
SaveScreenshot(pt_png, view, ImageResolution=[SIZE, SIZE])

serial = png_rgb(args.serial)
d_havs, _ = compare(png_rgb(havs_png), serial)
d_pt, _ = compare(png_rgb(pt_png), serial)
print("pvserver (2 ranks) HAVS image vs serial HAVS image: RMSE %.5f" % d_havs)
print("pvserver (2 ranks) stock Volume (PT) image vs serial HAVS image: RMSE %.5f" % d_pt)
check(d_havs < 0.01, "the pvserver's HAVS image equals the serial one (RMSE %.5f)" % d_havs)
check(d_pt > 2 * d_havs, "negative control: the stock mapper's image differs more (RMSE %.5f)"
      % d_pt)
print("PASSED" if not failures else "FAILED", flush=True)
sys.stdout.flush()
os._exit(1 if failures else 0)
