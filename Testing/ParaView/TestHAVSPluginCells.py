# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""The vtkHAVS ParaView plugin with what users bring (issue 19), serial (pvpython).

A multiblock data set of mixed cells -- hexahedra in some layers of the unit cube,
tetrahedra in others, interleaved in depth with gaps -- carrying a cell array, shown as
"HAVS Volume" coloured by that cell array. The screenshot is compared with the exact
reference (vtkHAVSReferenceRenderer) of the blocks appended, split into tetrahedra, with
cell scalars (RMSE bound as the other plugin tests); control: the reference of the same
data smoothed to points must be further off. The same again with the ray caster
("HAVS Ray Cast").

Arguments: --plugin PATH --out DIR
Run under Xvfb (Debian's ParaView is GLX-only).
"""
import argparse
import os
import sys

from paraview.simple import (ColorBy, GetColorTransferFunction,
                             GetOpacityTransferFunction, LoadPlugin, Render, SaveScreenshot,
                             Show, TrivialProducer)
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, vtkMultiBlockDataSet,
                                           vtkUnstructuredGrid)
from vtkmodules.vtkFiltersCore import vtkAppendFilter, vtkCellDataToPointData, vtkExtractCells

import vtkhavs
from havs_plugin_scene import (SIZE, compare, new_view, png_rgb, reference_rgb,
                               require_working_expat)

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--out", required=True)
args, _ = parser.parse_known_args()
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


N = 6  # cells along each axis of the unit cube
HEX_LAYERS = (0, 3, 4)
TET_LAYERS = (1, 5)  # layer 2 stays empty


def cell_value(centre):
    """The cell array: jumps from cell to cell (no point field stands for it)."""
    i, j, k = (int(c * N) for c in centre)
    return 0.2 + 0.6 * ((i * 7 + j * 3 + k * 5) % 5) / 4.0


def with_cell_array(grid):
    values = vtkDoubleArray()
    values.SetName("c")
    values.SetNumberOfTuples(grid.GetNumberOfCells())
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        centre = [0.0, 0.0, 0.0]
        for v in range(ids.GetNumberOfIds()):
            x = grid.GetPoint(ids.GetId(v))
            centre = [centre[d] + x[d] / ids.GetNumberOfIds() for d in range(3)]
        values.SetValue(c, cell_value(centre))
    grid.GetPointData().Initialize()
    grid.GetCellData().SetScalars(values)
    return grid


def hexahedra():
    points = vtkPoints()
    for k in range(N + 1):
        for j in range(N + 1):
            for i in range(N + 1):
                points.InsertNextPoint(i / N, j / N, k / N)
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)

    def pid(i, j, k):
        return i + (N + 1) * (j + (N + 1) * k)

    for k in HEX_LAYERS:
        for j in range(N):
            for i in range(N):
                bottom = [pid(i, j, k), pid(i + 1, j, k), pid(i + 1, j + 1, k), pid(i, j + 1, k)]
                top = [p + (N + 1) * (N + 1) for p in bottom]
                ids = vtkIdList()
                for p in bottom + top:
                    ids.InsertNextId(p)
                grid.InsertNextCell(VTK_HEXAHEDRON, ids)
    return with_cell_array(grid)


def tetrahedra():
    box = vtkhavs.vtkHAVSDataSets.MakeBox(N, N, N, 1.0 / N, 0.0, 1.0)
    keep = vtkIdList()
    for c in range(box.GetNumberOfCells()):
        ids = box.GetCell(c).GetPointIds()
        z = sum(box.GetPoint(ids.GetId(v))[2] for v in range(4)) / 4.0
        if int(z * N) in TET_LAYERS:
            keep.InsertNextId(c)
    extract = vtkExtractCells()
    extract.SetInputData(box)
    extract.SetCellList(keep)
    extract.Update()
    grid = vtkUnstructuredGrid()
    grid.DeepCopy(extract.GetOutput())
    return with_cell_array(grid)


require_working_expat()
LoadPlugin(args.plugin, remote=False, ns=globals())

blocks = vtkMultiBlockDataSet()
blocks.SetNumberOfBlocks(2)
blocks.SetBlock(0, hexahedra())
blocks.SetBlock(1, tetrahedra())

source = TrivialProducer()
source.GetClientSideObject().SetOutput(blocks)
source.UpdatePipeline()
view = new_view()
display = Show(source, view)
ColorBy(display, ("CELLS", "c"))
display.Representation = "HAVS Volume"
lut = GetColorTransferFunction("c")
pwf = GetOpacityTransferFunction("c")
lut.RescaleTransferFunction(0.0, 1.0)
pwf.RescaleTransferFunction(0.0, 1.0)
pwf.Points = [0.0, 0.0, 0.5, 0.0, 1.0, 0.8, 0.5, 0.0]
display.ScalarOpacityUnitDistance = 0.15
display.HAVSEarlyRayTerminationOpacity = 1.0
view.CameraPosition = [0.0, 0.0, 1.0]
view.ResetCamera()
camera = view.GetActiveCamera()
camera.Azimuth(30.0)
camera.Elevation(20.0)
view.ResetCamera()
Render(view)

rep = display.GetClientSideObject().GetActiveRepresentation()
mapper = rep.GetActiveVolumeMapper()
check(mapper is not None and mapper.IsA("vtkHAVSVolumeMapper"),
      "the active mapper is %s" % (mapper.GetClassName() if mapper else None))
check(mapper.GetScalarMode() in (2, 4) and mapper.GetArrayName() == "c",
      "the cell array reached the mapper (scalar mode %d, array %s)"
      % (mapper.GetScalarMode(), mapper.GetArrayName()))
name = os.path.join(args.out, "havs_plugin_cells.png")
os.makedirs(args.out, exist_ok=True)
SaveScreenshot(name, view, ImageResolution=[SIZE, SIZE])
shot = png_rgb(name)

appended = vtkAppendFilter()
appended.MergePointsOff()
for b in range(2):
    appended.AddInputData(blocks.GetBlock(b))
appended.Update()
grid = appended.GetOutput()
grid.GetCellData().SetActiveScalars("c")
vtk_camera = view.GetRenderer().GetActiveCamera()
exact = reference_rgb(grid, lut, pwf, 0.15, vtk_camera)
rmse, worst = compare(shot, exact)
print("mixed multiblock coloured by a cell array vs exact reference: RMSE %.5f, max %.4f"
      % (rmse, worst))
check(rmse < 0.01, "the image matches the exact reference with cell scalars (RMSE %.5f)" % rmse)

smooth = vtkCellDataToPointData()
smooth.SetInputData(grid)
smooth.Update()
smoothed = vtkUnstructuredGrid()
smoothed.ShallowCopy(smooth.GetOutput())
smoothed.GetCellData().Initialize()
smoothed.GetPointData().SetActiveScalars("c")
smoothed_exact = reference_rgb(smoothed, lut, pwf, 0.15, vtk_camera)
control, _ = compare(shot, smoothed_exact)
print("control, the reference of the data smoothed to points: RMSE %.5f" % control)
check(control > 3 * rmse and control > 0.01,
      "control: the smoothed field's reference is further off (RMSE %.5f)" % control)

# The same through the ray caster (issue 21): "HAVS Ray Cast", the cell array reaching it,
# against the same references.
display.HAVSMapper = "HAVS Ray Cast"
Render(view)
caster = rep.GetActiveVolumeMapper()
check(caster is not None and caster.IsA("vtkHAVSRayCastMapper")
      and caster.GetScalarMode() in (2, 4) and caster.GetArrayName() == "c",
      "HAVS Ray Cast: the active mapper is %s, the cell array reached it"
      % (caster.GetClassName() if caster else None))
ray_name = os.path.join(args.out, "havs_plugin_cells_raycast.png")
SaveScreenshot(ray_name, view, ImageResolution=[SIZE, SIZE])
ray_shot = png_rgb(ray_name)
ray_rmse, ray_worst = compare(ray_shot, exact)
ray_control, _ = compare(ray_shot, smoothed_exact)
print("ray caster vs exact reference: RMSE %.5f, max %.4f, %d peeling passes; control, the "
      "smoothed field's reference: RMSE %.5f"
      % (ray_rmse, ray_worst, caster.GetLastPeelPasses(), ray_control))
check(ray_rmse < 0.01, "ray caster: matches the exact reference with cell scalars (RMSE %.5f)"
      % ray_rmse)
check(ray_control > 3 * ray_rmse and ray_control > 0.01,
      "ray caster: control, the smoothed field's reference is further off (RMSE %.5f)"
      % ray_control)

print("PASSED" if not failures else "FAILED", flush=True)
sys.stdout.flush()
# As TestHAVSPlugin.py: leave without the interpreter's teardown (GLXBadContext under Xvfb).
os._exit(1 if failures else 0)
