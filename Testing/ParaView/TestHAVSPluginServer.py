# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""The vtkHAVS plugin on a pvserver (2 MPI ranks) driven by a pvpython client; the plugin
is found through PV_PLUGIN_PATH on both sides (no LoadPlugin call).

Shows the LOX post as "HAVS Volume" on the server, k set from the client, and compares the
client's screenshot with the serial image of TestHAVSPlugin.py (same scene): equal within a
tolerance; the stock "Volume" representation (projected tetrahedra) of the same scene must
differ from it by more (negative control).

Then cell data (issue 44): the same grid's Pressure averaged to its cells (PointDatatoCellData
on the server), shown as HAVS Volume coloured by that cell array through the 2 ranks, for the
three mappers, against the exact reference (vtkHAVSReferenceRenderer, in the client) of the
same cell-data grid with the same maps and camera, FXAA off, within issue 44's bound (max
<= 2/255, RMSE <= 0.25/255); control: the reference with the camera turned 2 degrees must miss it.

Arguments: --port N --out DIR --serial PNG. Environment: HAVS_DATA_DIR, PV_PLUGIN_PATH.
"""
import argparse
import os
import sys

from paraview.simple import (Connect, GetSettingsProxy, Hide, PointDatatoCellData, Render,
                             SaveScreenshot, Show)
from vtkmodules.vtkFiltersCore import vtkPointDataToCellData
from vtkmodules.vtkRenderingCore import vtkCamera

from havs_plugin_scene import (SIZE, compare, png_rgb, read_lox_post, reference_rgb,
                               require_working_expat, show_lox_post)

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
# Render on the server's ranks, never on the client: below this threshold (20 MB by default)
# ParaView may deliver data to the client and render it there. (Volumes on a 2-rank server
# rendered there even with the threshold at 1e9 MB: ordered compositing needs the ranks.)
GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0
grid = read_lox_post()
tets, view, display, lut, pwf = show_lox_post(grid)
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

# Cell data through the server's ranks, against the exact reference of the same cells.
# FXAA off, as the seams tests have it: on, it smooths the composited image's edges (92
# pixels up to 30/255 off the exact image here, for all three mappers alike).
view.UseFXAA = 0
display.Representation = "HAVS Volume"
Hide(tets, view)
cells = PointDatatoCellData(Input=tets)
cell_display = Show(cells, view)
cell_display.ColorArrayName = ["CELLS", "Pressure"]
cell_display.LookupTable = lut
cell_display.ScalarOpacityFunction = pwf
cell_display.ScalarOpacityUnitDistance = display.ScalarOpacityUnitDistance
cell_display.Representation = "HAVS Volume"
cell_display.HAVSKBufferSize = 14
cell_display.HAVSEarlyRayTerminationOpacity = 1.0
averaged = vtkPointDataToCellData()
averaged.SetInputData(grid)
averaged.Update()
cell_grid = averaged.GetOutput()
cell_grid.GetPointData().Initialize()
cell_grid.GetCellData().SetActiveScalars("Pressure")
camera = view.GetRenderer().GetActiveCamera()  # the client-side vtkCamera
unit = display.ScalarOpacityUnitDistance
exact_cells = reference_rgb(cell_grid, lut, pwf, unit, camera)
turned = vtkCamera()
turned.DeepCopy(camera)
turned.Azimuth(2.0)
exact_turned = reference_rgb(cell_grid, lut, pwf, unit, turned)
for mapper in ("HAVS", "HAVS Ray Cast", "HAVS Cell Projection"):
    cell_display.HAVSMapper = mapper
    Render(view)
    cell_png = os.path.join(args.out, "havs_plugin_pvserver_cells_%s.png"
                            % mapper.replace(" ", "_").lower())
    SaveScreenshot(cell_png, view, ImageResolution=[SIZE, SIZE])
    shot = png_rgb(cell_png)
    # The representation has the mapper asked for, and the view rendered on the server's
    # ranks (distributed rendering), not on the client.
    local = cell_display.GetClientSideObject().GetActiveRepresentation().GetActiveVolumeMapper()
    expected = {"HAVS": "vtkHAVSVolumeMapper", "HAVS Ray Cast": "vtkHAVSRayCastMapper",
                "HAVS Cell Projection": "vtkHAVSCellProjectionMapper"}[mapper]
    remote = view.GetClientSideObject().GetUseDistributedRenderingForRender()
    check(local is not None and local.IsA(expected) and remote,
          "%s: the mapper is %s, rendered on the server's ranks (%s)"
          % (mapper, local.GetClassName() if local else None, remote))
    d_cells, worst = compare(shot, exact_cells)
    d_turned, _ = compare(shot, exact_turned)
    off = sum(1 for a, b in zip(shot, exact_cells) if max(abs(x - y) for x, y in zip(a, b))
              > 3.0 / 255.0)
    print("pvserver (2 ranks) %s, cell data vs the exact reference of the cells: RMSE %.5f, "
          "max %.4f, %d pixels off by more than 3/255; control, the reference with the camera "
          "turned 2 degrees: RMSE %.5f" % (mapper, d_cells, worst, off, d_turned))
    # Issue 44's bound for the parallel image: max <= 2/255, RMSE <= 0.25/255 (here against
    # the exact float image, so the screenshot's own rounding counts too).
    check(d_cells <= 0.25 / 255 and worst <= 2.0 / 255,
          "%s: the cell-data image matches the exact reference (RMSE %.3f/255, max %.1f/255)"
          % (mapper, 255 * d_cells, 255 * worst))
    check(d_turned > 0.25 / 255,
          "%s: control, the reference of a view turned 2 degrees misses it (RMSE %.2f/255)"
          % (mapper, 255 * d_turned))
    # The server's ranks composited their images in float (the representation's
    # FloatComposite) and that image reached the client: IceT's 8-bit composite of the same
    # frame (FloatComposite off) is another image, farther from the exact one. (The
    # representation's HAVSLastFloatComposite says so on the server's ranks; a client reads
    # its own copy of the representation, which renders nothing.)
    cell_display.HAVSFloatComposite = 0
    Render(view)
    SaveScreenshot(cell_png + ".icet.png", view, ImageResolution=[SIZE, SIZE])
    icet_shot = png_rgb(cell_png + ".icet.png")
    cell_display.HAVSFloatComposite = 1
    d_icet, worst_icet = compare(icet_shot, exact_cells)
    changed = sum(1 for a, b in zip(shot, icet_shot) if a != b)
    print("%s, IceT's 8-bit composite instead (FloatComposite off): RMSE %.3f/255, max "
          "%.1f/255; %d pixels differ from the float composite" % (mapper, 255 * d_icet,
                                                                   255 * worst_icet, changed))
    check(changed > 0 and d_cells < d_icet, "%s: the client shows the server's float composite "
          "(%d pixels differ from IceT's 8-bit one; RMSE %.3f/255 against IceT's %.3f/255)"
          % (mapper, changed, 255 * d_cells, 255 * d_icet))

print("PASSED" if not failures else "FAILED", flush=True)
sys.stdout.flush()
os._exit(1 if failures else 0)
