# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""What a rank's frame costs under the two exact parallel routes (issue 44), in one process.

    python3 Apps/havs_region_clip_cost.py [dataset] [mapper] [size] [cuts]

dataset: a vtkHAVSDataSets name (loxpost, bluntfin, ...) or genN (N^3 cubes of 5 tetrahedra);
mapper: havs, raycast or cellproj; size: the image (512); cuts: 1 (the piece x <= the median, as
a rank of 2 has it) or 2 (x and y <= their medians, a rank of 4).

The same piece of the grid drawn two ways, as the HAVS Volume representation's routes give it
to a rank's mapper:
- clip: every cell whose bounds reach into the region, whole, and the mapper's clipping planes
  at the region's inner faces (what ParaView's ASSIGN_TO_ALL_INTERSECTING_REGIONS sends; the
  cell bounds are the same test vtkRedistributeDataSetFilter makes);
- split: the grid clipped at those planes (vtkTableBasedClipDataSet, as ParaView's split does)
  with its coincident points merged (vtkStaticCleanUnstructuredGrid, as the representation
  does).
Each piece's first frame (mesh, order, table), then frames with the camera turned 20 degrees
before each (a new visibility order each frame), in alternating blocks of 3, 8 blocks each:
medians, their ratio and the tetrahedra each mapper draws. vtkSMPTools' backend as
VTK_SMP_BACKEND_IN_USE says (printed). Absolute times mean something only on a GPU; the ratio
is the route's cost per frame on this machine.
"""
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from havs_app_scene import MAPPERS, new_window, ramp_property  # noqa: E402
from vtkhavs.vtkHAVSValidation import vtkHAVSDataSets  # noqa: E402
from vtkmodules.vtkCommonCore import vtkIdList  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPlane, vtkPlaneCollection  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkStaticCleanUnstructuredGrid  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkTableBasedClipDataSet  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkVolume  # noqa: E402
try:
    from vtkmodules.vtkFiltersCore import vtkExtractCells  # noqa: E402  (VTK 9.2, 9.3)
except ImportError:
    from vtkmodules.vtkFiltersExtraction import vtkExtractCells  # noqa: E402

dataset = sys.argv[1] if len(sys.argv) > 1 else "loxpost"
mapper_name = sys.argv[2] if len(sys.argv) > 2 else "havs"
size = int(sys.argv[3]) if len(sys.argv) > 3 else 512
cuts = int(sys.argv[4]) if len(sys.argv) > 4 else 1

if dataset.startswith("gen"):
    grid = vtkHAVSDataSets.MakeGenerated(int(dataset[3:]))
else:
    grid = vtkHAVSDataSets.Load(dataset)
if grid is None or grid.GetNumberOfCells() == 0:
    sys.exit("cannot load %s (HAVS_DATA_DIR?)" % dataset)

# The region: x (and y) at most the points' median, as a kd cut halves the points.
points = grid.GetPoints()
medians = []
for axis in range(cuts):
    values = sorted(points.GetPoint(i)[axis] for i in range(0, points.GetNumberOfPoints(), 7))
    medians.append(values[len(values) // 2])

# clip: the cells whose bounds reach x (y) <= the median, whole.
ids = vtkIdList()
bounds = [0.0] * 6
for c in range(grid.GetNumberOfCells()):
    grid.GetCellBounds(c, bounds)
    if all(bounds[2 * axis] <= medians[axis] for axis in range(cuts)):
        ids.InsertNextId(c)
extract = vtkExtractCells()
extract.SetInputData(grid)
extract.SetCellList(ids)
extract.Update()
clip_piece = extract.GetOutput()
def median_plane(axis, sign):
    """The plane through the median on `axis` with normal sign * that axis."""
    plane = vtkPlane()
    origin = [0.0, 0.0, 0.0]
    origin[axis] = medians[axis]
    normal = [0.0, 0.0, 0.0]
    normal[axis] = sign
    plane.SetOrigin(origin)
    plane.SetNormal(normal)
    return plane


# The clip route's mapper planes, each keeping x (y) <= the median (the side its normal points
# to).
planes = vtkPlaneCollection()
for axis in range(cuts):
    planes.AddItem(median_plane(axis, -1.0))

# split: the grid clipped there (each plane in turn), coincident points merged.
piece = grid
for axis in range(cuts):
    clipper = vtkTableBasedClipDataSet()
    clipper.SetInputData(piece)
    clipper.SetClipFunction(median_plane(axis, 1.0))
    clipper.InsideOutOn()  # keeps x <= the median
    clipper.Update()
    piece = clipper.GetOutput()
merge = vtkStaticCleanUnstructuredGrid()
merge.SetInputData(piece)
merge.Update()
split_piece = merge.GetOutput()

prop = ramp_property(grid)
window, renderer = new_window(size)
make = MAPPERS[mapper_name]
routes = {}
for name, data, clip in (("clip", clip_piece, planes), ("split", split_piece, None)):
    mapper = make()
    mapper.SetInputData(data)
    if clip is not None:
        mapper.SetClippingPlanes(clip)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    routes[name] = (mapper, volume)
renderer.AddVolume(routes["clip"][1])
renderer.ResetCamera()
renderer.RemoveVolume(routes["clip"][1])
camera = renderer.GetActiveCamera()
camera.Azimuth(30.0)
camera.Elevation(20.0)


def show(name):
    renderer.RemoveAllViewProps()
    renderer.AddVolume(routes[name][1])


first = {}
for name in ("clip", "split"):
    show(name)
    start = time.perf_counter()
    window.Render()
    first[name] = time.perf_counter() - start
# Alternating blocks: each route draws the same three views in turn.
times = {"clip": [], "split": []}
for block in range(8):
    for name in (("clip", "split") if block % 2 == 0 else ("split", "clip")):
        show(name)
        for _ in range(3):
            camera.Azimuth(20.0)
            start = time.perf_counter()
            window.Render()
            times[name].append(time.perf_counter() - start)
        camera.Azimuth(-60.0)
    camera.Azimuth(60.0)

print("%s (%d tetrahedra), %s, %d^2, %d cut(s) at %s, %s, vtkSMPTools backend %s" % (
    dataset, grid.GetNumberOfCells(), mapper_name, size, cuts,
    ", ".join("%.4g" % m for m in medians), window.GetClassName(),
    os.environ.get("VTK_SMP_BACKEND_IN_USE", "VTK's default")))
print("| route | cells | tetrahedra drawn | first frame s | frame ms (median of %d) |"
      % len(times["clip"]))
print("|---|---|---|---|---|")
for name, data in (("clip", clip_piece), ("split", split_piece)):
    mesh = routes[name][0].GetMesh()
    print("| %s | %d | %d | %.2f | %.1f |" % (
        name, data.GetNumberOfCells(), mesh.GetFaceSet().GetNumberOfTetrahedra(), first[name],
        statistics.median(times[name]) * 1e3))
print("clip / split per frame: %.3f"
      % (statistics.median(times["clip"]) / statistics.median(times["split"])))
