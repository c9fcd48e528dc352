"""The vtkHAVS plugin on a pvserver (2 MPI ranks) driven by a pvpython client; the plugin
is found through PV_PLUGIN_PATH on both sides (no LoadPlugin call).

Shows the LOX post as "HAVS Volume" on the server, k set from the client, and compares the
client's screenshot with the serial image of TestHAVSPlugin.py (same scene): equal within a
tolerance; the stock "Volume" representation (projected tetrahedra) of the same scene must
differ from it by more (negative control).

Arguments: --port N --out DIR --serial PNG. Environment: HAVS_DATA_DIR, PV_PLUGIN_PATH.
"""
import argparse
import math
import os
import sys

from paraview.simple import (ColorBy, Connect, CreateRenderView, GetColorTransferFunction,
                             GetOpacityTransferFunction, LegacyVTKReader, Render,
                             SaveScreenshot, Show, Tetrahedralize)
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader

parser = argparse.ArgumentParser()
parser.add_argument("--port", type=int, required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--serial", required=True)
args, _ = parser.parse_known_args()
SIZE = 200
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def pixels(path):
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    scalars = png.GetOutput().GetPointData().GetScalars()
    return [[scalars.GetComponent(i, k) / 255.0 for k in range(3)]
            for i in range(png.GetOutput().GetNumberOfPoints())]


def rmse(a, b):
    if len(a) != len(b) or not a:
        return 1e30
    d = [(x[k] - y[k]) ** 2 for x, y in zip(a, b) for k in range(3)]
    return math.sqrt(sum(d) / len(d))


connection = Connect("localhost", args.port)
check(connection is not None, "connected to pvserver on port %d" % args.port)
data_file = os.path.join(os.environ["HAVS_DATA_DIR"], "post.vtk")
legacy = vtkUnstructuredGridReader()
legacy.SetFileName(data_file)
tetrahedralize = vtkDataSetTriangleFilter()
tetrahedralize.SetInputConnection(legacy.GetOutputPort())
tetrahedralize.Update()
grid = tetrahedralize.GetOutput()
data_range = grid.GetPointData().GetArray("Pressure").GetRange()

reader = LegacyVTKReader(FileNames=[data_file])
tets = Tetrahedralize(Input=reader)
view = CreateRenderView()
view.ViewSize = [SIZE, SIZE]
view.OrientationAxesVisibility = 0
view.Background = [0.0, 0.0, 0.0]
view.UseColorPaletteForBackground = 0
display = Show(tets, view)
ColorBy(display, ("POINTS", "Pressure"))
check("HAVS Volume" in display.GetProperty("Representation").Available,
      "the server and the client know the HAVS Volume representation (PV_PLUGIN_PATH)")
display.Representation = "HAVS Volume"
lut = GetColorTransferFunction("Pressure")
pwf = GetOpacityTransferFunction("Pressure")
lut.RescaleTransferFunction(data_range[0], data_range[1])
pwf.RescaleTransferFunction(data_range[0], data_range[1])
pwf.Points = [data_range[0], 0.0, 0.5, 0.0, data_range[1], 0.8, 0.5, 0.0]
display.ScalarOpacityUnitDistance = grid.GetLength() / 8.0
display.HAVSKBufferSize = 14
display.HAVSEarlyRayTerminationOpacity = 1.0
view.CameraPosition = [0.0, 0.0, 1.0]
view.ResetCamera()
camera = view.GetActiveCamera()
camera.Azimuth(30.0)
camera.Elevation(20.0)
view.ResetCamera()
Render(view)
os.makedirs(args.out, exist_ok=True)
havs_png = os.path.join(args.out, "havs_plugin_pvserver.png")
SaveScreenshot(havs_png, view, ImageResolution=[SIZE, SIZE])
display.Representation = "Volume"
Render(view)
pt_png = os.path.join(args.out, "havs_plugin_pvserver_pt.png")
SaveScreenshot(pt_png, view, ImageResolution=[SIZE, SIZE])

serial = pixels(args.serial)
havs = pixels(havs_png)
pt = pixels(pt_png)
d_havs, d_pt = rmse(havs, serial), rmse(pt, serial)
print("pvserver (2 ranks) HAVS image vs serial HAVS image: RMSE %.5f" % d_havs)
print("pvserver (2 ranks) stock Volume (PT) image vs serial HAVS image: RMSE %.5f" % d_pt)
check(d_havs < 0.01, "the pvserver's HAVS image equals the serial one (RMSE %.5f)" % d_havs)
check(d_pt > 2 * d_havs, "negative control: the stock mapper's image differs more (RMSE %.5f)"
      % d_pt)
print("PASSED" if not failures else "FAILED", flush=True)
sys.stdout.flush()
os._exit(1 if failures else 0)
