# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""The plugin's parallel image is exact across ranks (issue 44): mpiexec -np N pvbatch --symmetric.

ParaView splits the grid over the ranks along a kd-tree and IceT composites the ranks' images
in the order of their boxes. The HAVS Volume representation asks for every cell that touches a
rank's box to go there, the mapper clipping the piece to the box (`--redistribution clip`, the
default), or for the cells on the cuts to be split there by ParaView (`split`), so that each
rank's piece lies in its box and the order is exact. Each mapper offered (HAVS, HAVS Ray Cast,
HAVS Cell Projection) is checked on several views against the exact reference
(vtkHAVSReferenceRenderer), in two parts:

- the distribution: the exact images of the ranks' pieces (clipped by the planes their mappers
  hold: the box's under `clip`, and with `--user-plane` the user's own first), composited in
  float in the order of the ranks' boxes, equal the exact image of the whole grid (max <=
  0.5/255 on the Delaunay grid, whose coordinates are double; 1/255 on float32 data, where the
  split's new points move a grazing ray's hits by a hair). Controls: with ParaView's stock
  redistribution (whole cells to one rank) that composite misses the bound (a seam); under
  `clip` the same pieces without their planes miss it (the cells on the cuts counted twice).
- the rendering: the screenshot against the exact image of the whole grid rounded to 8 bits,
  within issue 44's bound (max <= 2/255, RMSE <= 0.25/255) for every mapper and view, the
  ranks' images composited in float (the representation's FloatComposite: every rank says so).
  Control (--control): the same frames composited by IceT in 8 bits (FloatComposite off) miss
  the RMSE bound on the worst view (IceT rounds each rank's image and truncates each blend).

Also printed (and in --csv): the floor that IceT's 8-bit arithmetic alone puts under the error
(the exact pieces composited as IceT does, against the same exact image), and the screenshot
against that IceT composite of the exact pieces.

The grid is written once as a .vtu (the same tetrahedra for the reference and for ParaView):
rank 0 reads it whole and ParaView redistributes it, as it does any reader's output.

Arguments: --plugin PATH --out DIR [--data delaunay|hexes|bluntfin|loxpost] [--size N] [--views N]
  [--mappers a,b] [--redistribution split|clip|whole] [--control] [--user-plane] [--csv PATH]
Environment: HAVS_DATA_DIR (shared/data). Run under Xvfb (Debian's ParaView is GLX-only).
"""
import argparse
import functools
import json
import math
import os
import sys
import time

import numpy
from paraview.simple import (Render, SaveScreenshot, Show, XMLUnstructuredGridReader, LoadPlugin)
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkIOParallel import vtkMultiBlockPLOT3DReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
from vtkmodules.vtkRenderingCore import vtkCamera
from vtkmodules.vtkParallelCore import vtkDummyController
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (vtkPlane, vtkPlaneCollection, vtkPolyData,
                                            vtkStructuredGrid)
from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkFiltersCore import vtkDelaunay3D

from havs_plugin_scene import (gather_all, mpi_setup, new_view, reference_image,
                               require_working_expat, style_havs_volume)

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--data", choices=["bluntfin", "loxpost", "delaunay", "hexes"],
                    default="delaunay")
parser.add_argument("--size", type=int, default=256)
parser.add_argument("--views", type=int, default=4)
parser.add_argument("--first-view", type=int, default=0)
parser.add_argument("--mappers", default="HAVS,HAVS Ray Cast,HAVS Cell Projection")
parser.add_argument("--redistribution", choices=["split", "clip", "whole"], default="split")
parser.add_argument("--control", action="store_true",
                    help="also render with whole cells (ParaView's stock), which must fail")
parser.add_argument("--data-partitions", action="store_true",
                    help="UseDataPartitions on: the reader's pieces as they are (debugging)")
parser.add_argument("--fxaa", action="store_true",
                    help="leave the view's FXAA on (pvpython's default; it blurs edges)")
parser.add_argument("--distribution-max", type=float, default=None,
                    help="the distribution's bound in 1/255 (default: 0.05 for the Delaunay grid, "
                    "whose coordinates are double; 1 for the float32 data sets)")
parser.add_argument("--csv", help="append one row per image here (rank 0)")
parser.add_argument("--no-float-composite", action="store_true",
                    help="IceT's 8-bit composite in every mode (FloatComposite off; debugging)")
parser.add_argument("--table-size", type=int, default=0,
                    help="a fixed pre-integration table of this size (default: the automatic one)")
parser.add_argument("--user-plane", action="store_true",
                    help="give each mapper a clipping plane of the user's own (oblique): the "
                    "clip redistribution keeps it beside the rank's box; the reference of the "
                    "whole grid is clipped by it")
args, _ = parser.parse_known_args()

MODES = {"whole": 0, "split": 1, "clip": 2}
# "icet8": the redistribution asked for, composited by IceT in 8 bits (the float control).
DISTRIBUTION_MAX = (args.distribution_max if args.distribution_max is not None
                    else 0.5 if args.data in ("delaunay", "hexes") else 1.0)
# The rendering (the screenshot against the exact image rounded to 8 bits), in 1/255: issue
# 44's bound. The mappers' own float error (RMSE about 1e-4) rounds a share of the values the
# other way: serially 0.20-0.23 on the Delaunay grid with a 256 table (--table-size), 0.23-0.27
# with the automatic one, which the bound would miss on one view.
RMSE_BOUND = 0.25
MAX_BOUND = 2.0
# The distribution (the exact pieces composited in float against the exact whole image), in
# 1/255: the split's new points are exact in double coordinates up to the rounding of a
# point cut twice (the Delaunay grid: 0.000 at 2 ranks, 0.34 at 4; ParaView's whole cells
# 0.79 at 2, 6.5 at 4), a hair off in float32 ones (LOX post: 0.77).
VIEWS = [(30.0, 20.0), (120.0, -15.0), (215.0, 50.0), (300.0, 5.0), (75.0, 70.0),
         (160.0, -60.0), (250.0, 25.0), (340.0, -35.0)]


controller, rank, ranks = mpi_setup()
failures = []


def check(condition, what):
    if rank == 0:
        print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def gather(value):
    """`value` of every rank, on every rank (a list of floats)."""
    return gather_all(controller, ranks, value)


def whole_grid():
    """The grid ParaView reads, the whole grid as tetrahedra, and its scalar's name. Mixed
    cells ("hexes"): ParaView reads hexahedra and its volume preprocessor splits them into
    tetrahedra (vtkDataSetTriangleFilter) before it redistributes the cells, so the parallel
    image must equal the serial image of that tetrahedralization, which the reference draws."""
    data = os.environ["HAVS_DATA_DIR"]
    if args.data == "bluntfin":
        reader = vtkMultiBlockPLOT3DReader()
        reader.SetController(vtkDummyController())  # the whole grid on every rank, not a piece
        reader.SetXYZFileName(os.path.join(data, "bluntfinxyz.bin"))
        reader.SetQFileName(os.path.join(data, "bluntfinq.bin"))
        reader.SetScalarFunctionNumber(100)  # density
        reader.Update()
        source = reader.GetOutput().GetBlock(0)
        array = "Density"
    elif args.data == "delaunay":
        # 1,500 seeded random points in the unit cube and its corners, Delaunay: cells in every
        # orientation, so that the kd cuts cross many (a structured mesh's cuts can run along
        # its faces), and large (a whole cell on the wrong side shows).
        rng = numpy.random.default_rng(44)
        corners = numpy.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], float)
        xyz = numpy.vstack([corners, rng.random((1500, 3))])
        points = vtkPoints()
        points.SetData(numpy_to_vtk(xyz, deep=True))
        cloud = vtkPolyData()
        cloud.SetPoints(points)
        field = numpy.sin(3.0 * xyz[:, 0]) * numpy.cos(2.0 * xyz[:, 1]) + xyz[:, 2] ** 2
        scalars = numpy_to_vtk(field, deep=True)
        scalars.SetName("Field")
        cloud.GetPointData().SetScalars(scalars)
        delaunay = vtkDelaunay3D()
        delaunay.SetInputData(cloud)
        delaunay.Update()
        source = delaunay.GetOutput()
        array = "Field"
    elif args.data == "hexes":
        # 6 x 5 x 5 hexahedra of a sheared, bent lattice (double coordinates), a smooth field:
        # the kd cuts cross the cells (no cut runs along a lattice plane), the hexahedra's
        # split into tetrahedra is ParaView's.
        n = (7, 6, 6)
        lattice = vtkStructuredGrid()
        lattice.SetDimensions(*n)
        points = vtkPoints()
        points.SetDataTypeToDouble()
        field = []
        for k in range(n[2]):
            for j in range(n[1]):
                for i in range(n[0]):
                    x, y, z = i / (n[0] - 1), j / (n[1] - 1), k / (n[2] - 1)
                    points.InsertNextPoint(x + 0.21 * y + 0.05 * math.sin(3.0 * z),
                                           y + 0.13 * z * z, z + 0.17 * x)
                    field.append(math.sin(3.0 * x) * math.cos(2.0 * y) + z * z)
        lattice.SetPoints(points)
        scalars = numpy_to_vtk(numpy.array(field), deep=True)
        scalars.SetName("Field")
        lattice.GetPointData().SetScalars(scalars)
        append = vtkAppendFilter()
        append.AddInputData(lattice)
        append.Update()
        source = append.GetOutput()
        array = "Field"
    else:
        reader = vtkUnstructuredGridReader()
        reader.SetFileName(os.path.join(data, "post.vtk"))
        reader.Update()
        source = reader.GetOutput()
        array = "Pressure"
    tetrahedralize = vtkDataSetTriangleFilter()
    tetrahedralize.SetInputData(source)
    tetrahedralize.Update()
    grid = tetrahedralize.GetOutput()
    grid.GetPointData().SetActiveScalars(array)
    read = source if args.data == "hexes" else grid
    read.GetPointData().SetActiveScalars(array)
    return read, grid, array


def png_array(path):
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    image = png.GetOutput()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(numpy.float64)
    return pixels.reshape(args.size, args.size, 3)


require_working_expat()
LoadPlugin(args.plugin, remote=False, ns=globals())
read_grid, grid, array = whole_grid()
vtu = os.path.join(args.out, "seams_%s.vtu" % args.data)
if rank == 0:
    os.makedirs(args.out, exist_ok=True)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(vtu)
    writer.SetInputData(read_grid)
    writer.SetDataModeToAppended()
    writer.EncodeAppendedDataOff()
    writer.Write()
if controller and ranks > 1:
    controller.Barrier()

reader = XMLUnstructuredGridReader(FileName=[vtu])
view = new_view()
view.ViewSize = [args.size, args.size]
if not args.fxaa:
    view.UseFXAA = 0
display = Show(reader, view)
lut, pwf = style_havs_volume(display, array, grid.GetPointData().GetArray(array).GetRange(),
                             grid.GetLength())
if args.data_partitions:
    display.UseDataPartitions = 1
if args.table_size:
    display.HAVSAutomaticTable = 0
    display.HAVSTableResolution = args.table_size
rep = display.GetClientSideObject().GetActiveRepresentation()
camera = view.GetActiveCamera()


def set_view(index):
    view.CameraPosition = [0.0, 0.0, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    azimuth, elevation = VIEWS[(index + args.first_view) % len(VIEWS)]
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.OrthogonalizeViewUp()
    view.ResetCamera()


def write_piece(mode):
    """This rank's piece as the active mapper sees it (after the representation's merge),
    and the clipping planes the representation gave the mapper (its kd box's inner faces,
    under the clip redistribution), written for rank 0's reference; its cell count on every
    rank."""
    mapper = rep.GetActiveVolumeMapper()
    piece = mapper.GetInput()
    cells = piece.GetNumberOfCells() if piece else 0
    if cells:
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetFileName(piece_path(mode, rank))
        writer.SetInputData(piece)
        writer.SetDataModeToAppended()
        writer.EncodeAppendedDataOff()
        writer.Write()
        collection = mapper.GetClippingPlanes()
        planes = []
        for i in range(collection.GetNumberOfItems() if collection else 0):
            plane = collection.GetItem(i)
            planes.append(list(plane.GetOrigin()) + list(plane.GetNormal()))
        # The representation puts the mapper's own planes first, the box's last.
        display.UpdatePropertyInformation()
        region = int(display.GetProperty("HAVSLastRegionPlanes").GetElement(0))
        with open(piece_path(mode, rank) + ".planes.json", "w") as out:
            json.dump({"planes": planes, "region": region}, out)
    every = gather(cells)
    if controller and ranks > 1:
        controller.Barrier()
    return every


def piece_path(mode, r):
    return os.path.join(args.out, "seams_%s_%d_%s_piece%d.vtu" % (args.data, ranks, mode, r))


def plane_collection(planes):
    """A vtkPlaneCollection of `planes` ({"planes": [origin + normal, ...], "region": the number
    of the last ones that are the rank's box}, as write_piece records them); None for none."""
    if not planes or not planes["planes"]:
        return None
    collection = vtkPlaneCollection()
    for values in planes["planes"]:
        plane = vtkPlane()
        plane.SetOrigin(values[:3])
        plane.SetNormal(values[3:])
        collection.AddItem(plane)
    return collection


# The user's own clipping plane (oblique, through the grid off its centre).
USER_PLANE = None
if args.user_plane:
    bounds = grid.GetBounds()
    origin = [bounds[0] + 0.62 * (bounds[1] - bounds[0]),
              bounds[2] + 0.5 * (bounds[3] - bounds[2]), bounds[4] + 0.5 * (bounds[5] - bounds[4])]
    normal = list(numpy.array([-1.0, 0.35, 0.2]) / numpy.linalg.norm([-1.0, 0.35, 0.2]))
    USER_PLANE = {"planes": [origin + normal], "region": 0}
    user_planes = plane_collection(USER_PLANE)


def give_user_plane():
    """The active mapper's own planes: the user's plane, unless it holds them already (then its
    collection is the representation's, which starts with them)."""
    mapper = rep.GetActiveVolumeMapper()
    if USER_PLANE and mapper.GetClippingPlanes() is None:
        mapper.SetClippingPlanes(user_planes)


def render_all(mode):
    """Screenshots of every view with every mapper under redistribution `mode`;
    ([(mapper, view, path, seconds, planes per rank)], cells per rank, seconds of the first
    frame, which redistributes)."""
    display.HAVSRedistribution = MODES[args.redistribution if mode == "icet8" else mode]
    display.HAVSFloatComposite = 0 if mode == "icet8" or args.no_float_composite else 1
    shots = []
    cells = None
    first = None
    for mapper in args.mappers.split(","):
        display.HAVSMapper = mapper
        for v in range(args.views):
            give_user_plane()
            set_view(v)
            start = time.perf_counter()
            Render(view)
            seconds = time.perf_counter() - start
            first = seconds if first is None else first
            if v not in cameras:
                # The camera the image was rendered with, for the reference (ResetCamera
                # is collective: rank 0 cannot move the view's camera alone later).
                cameras[v] = vtkCamera()
                cameras[v].DeepCopy(view.GetRenderer().GetActiveCamera())
                if rank == 0:  # beside the pieces, to look at one again
                    with open(os.path.join(args.out, "camera%d.json" % v), "w") as out:
                        c = cameras[v]
                        json.dump({"position": c.GetPosition(), "focal": c.GetFocalPoint(),
                                   "up": c.GetViewUp(), "angle": c.GetViewAngle(),
                                   "parallel": c.GetParallelProjection(),
                                   "scale": c.GetParallelScale(),
                                   "clipping": c.GetClippingRange()}, out)
            if cells is None:
                cells = write_piece(mode)
            display.UpdatePropertyInformation()
            planes = gather(display.GetProperty("HAVSLastRegionPlanes").GetElement(0))
            path = os.path.join(args.out, "seams_%s_%d_%s_%s_%d.png"
                                % (args.data, ranks, mode, mapper.replace(" ", ""), v))
            SaveScreenshot(path, view, ImageResolution=[args.size, args.size])
            # How the screenshot's own frame was composited.
            display.UpdatePropertyInformation()
            floats = gather(display.GetProperty("HAVSLastFloatComposite").GetElement(0))
            shots.append((mapper, v, path, seconds, planes, floats))
    return shots, cells, first


def exact_rgba(camera, data, planes=None):
    """The exact premultiplied RGBA image of `data` (size x size x 4, bottom row first), clipped
    by `planes` (plane_collection's, the side each normal points to kept) if given."""
    image = reference_image(data, lut, pwf, display.ScalarOpacityUnitDistance, camera, args.size,
                            planes=plane_collection(planes))
    return vtk_to_numpy(image).astype(numpy.float64).reshape(args.size, args.size, 4)


def read_piece(path):
    """A rank's piece and its clipping planes."""
    piece_reader = vtkXMLUnstructuredGridReader()
    piece_reader.SetFileName(path)
    piece_reader.Update()
    data = piece_reader.GetOutput()
    data.GetPointData().SetActiveScalars(array)
    with open(path + ".planes.json") as planes:
        return data, json.load(planes)


def region_box(data, planes):
    """A piece's bounds within its box's clipping planes (the last `region` of them): its
    rank's kd box where the planes cut it (the test's volume has no transform, so those planes
    are axis-aligned in the data's coordinates)."""
    box = list(data.GetBounds())
    for values in planes["planes"][len(planes["planes"]) - planes["region"]:]:
        axis = int(numpy.argmax(numpy.abs(values[3:])))
        if values[3 + axis] > 0:
            box[2 * axis] = max(box[2 * axis], values[axis])
        else:
            box[2 * axis + 1] = min(box[2 * axis + 1], values[axis])
    return box


def box_order(boxes, camera):
    """Indices of `boxes` front to back: kd boxes are separated by an axis-aligned plane, and the one
    on the camera's side of it is in front (perspective: the eye; parallel: the direction)."""
    eye = camera.GetPosition()
    direction = numpy.subtract(camera.GetFocalPoint(), eye)

    def before(a, b):
        first, second = boxes[a], boxes[b]
        for axis in range(3):
            for near, far, sign in ((first, second, -1), (second, first, 1)):
                if near[2 * axis + 1] <= far[2 * axis] + 1e-9 * grid.GetLength():
                    plane = near[2 * axis + 1]
                    if camera.GetParallelProjection():
                        near_in_front = direction[axis] > 0
                    else:
                        near_in_front = eye[axis] < plane
                    return sign if near_in_front else -sign
        return 0

    return sorted(range(len(boxes)), key=functools.cmp_to_key(before))


def composite(images, integer):
    """Front-to-back list of premultiplied RGBA images put together with "over": in float, or
    as IceT does in 8 bits (each image rounded, dest * (255 - src alpha) / 255 truncated)."""
    if integer:
        layers = [numpy.clip(numpy.round(image * 255.0), 0, 255).astype(numpy.int64)
                  for image in images]
        result = layers[-1]
        for layer in reversed(layers[:-1]):
            result = (result * (255 - layer[:, :, 3:4])) // 255 + layer
        return numpy.clip(result[:, :, :3], 0, 255).astype(numpy.float64)
    result = numpy.zeros_like(images[0])
    for image in images:
        result = result + (1.0 - result[:, :, 3:4]) * image
    return numpy.clip(result[:, :, :3], 0.0, 1.0) * 255.0


def errors(a, b):
    diff = numpy.abs(a - b)
    return float(numpy.sqrt(numpy.mean(diff * diff))), float(diff.max())


cameras = {}
modes = [args.redistribution] + (["icet8", "whole"] if args.control else [])
results = {}
for mode in modes:
    results[mode] = render_all(mode)

if rank == 0:
    exact = {v: exact_rgba(cameras[v], grid, USER_PLANE) for v in range(args.views)}
    exact255 = {v: numpy.clip(exact[v][:, :, :3], 0.0, 1.0) * 255.0 for v in exact}
    exact8 = {v: numpy.round(exact255[v]) for v in exact}
    # The ranks' boxes: the split pieces' bounds, or the clipped pieces' bounds within their
    # planes (the cuts do not depend on the mode).
    boxes = None
    pieces = {}
    for mode in modes:
        if mode == "icet8":
            continue  # the same pieces as the redistribution asked for
        cells = results[mode][1]
        pieces[mode] = {r: read_piece(piece_path(mode, r)) for r in range(ranks) if cells[r] > 0}
        if mode in ("split", "clip"):
            boxes = {r: region_box(*pieces[mode][r]) for r in pieces[mode]}
    rows = []
    icet_floor = {}  # per view: IceT's 8-bit composite of the exact pieces against the exact image
    icet_images = {}
    for mode in modes:
        shots, cells, first = results[mode]
        print("%s: cells per rank %s (%d in all, %d in the grid), first frame %.2f s"
              % (mode, [int(c) for c in cells], int(sum(cells)), grid.GetNumberOfCells(), first),
              flush=True)
        exact_mode = mode in ("split", "clip")
        piece_checks = ranks > 1 and boxes is not None and mode in pieces
        floor = {}
        icet = {}
        seams = []
        overlaps = []
        if USER_PLANE and piece_checks:
            check(all(pieces[mode][r][1]["planes"][0] == USER_PLANE["planes"][0]
                      for r in pieces[mode]), "%s, %d ranks: every rank's mapper kept the "
                  "user's own plane first" % (mode, ranks))
        for v in range(args.views):
            if not piece_checks:
                continue
            owners = sorted(boxes)
            ranked = [owners[i] for i in box_order([boxes[r] for r in owners], cameras[v])]
            images = [exact_rgba(cameras[v], *pieces[mode][r]) for r in ranked
                      if r in pieces[mode]]
            float_rmse, float_max = errors(composite(images, False), exact255[v])
            icet[v] = composite(images, True)
            floor[v] = errors(icet[v], exact8[v])
            if exact_mode:
                check(float_max <= DISTRIBUTION_MAX, "%s, %d ranks, view %d: the exact pieces "
                      "composited in box order are the exact whole image (max %.3f/255 <= %g, "
                      "RMSE %.4f/255)" % (mode, ranks, v, float_max, DISTRIBUTION_MAX, float_rmse))
                if mode == "clip":
                    # Control: the same pieces without their planes overlap (every cell that
                    # touches a box is in it whole), so their composite misses the bound.
                    unclipped = [exact_rgba(cameras[v], pieces[mode][r][0], USER_PLANE)
                                 for r in ranked if r in pieces[mode]]
                    overlap_rmse, overlap_max = errors(composite(unclipped, False), exact255[v])
                    overlaps.append(overlap_max)
                    print("control, clip pieces without their planes, %d ranks, view %d: max "
                          "%.3f/255, RMSE %.4f/255" % (ranks, v, overlap_max, overlap_rmse),
                          flush=True)
            else:
                seams.append(float_max)
                print("control, whole cells, %d ranks, view %d: the exact pieces composited in "
                      "box order, against the exact whole image: max %.3f/255, RMSE %.4f/255"
                      % (ranks, v, float_max, float_rmse), flush=True)
        if overlaps:
            check(min(overlaps) > DISTRIBUTION_MAX, "control, clip pieces without their planes, "
                  "%d ranks: every view misses the distribution's bound (best view max "
                  "%.3f/255 > %g/255)" % (ranks, min(overlaps), DISTRIBUTION_MAX))
        if seams:
            check(max(seams) > DISTRIBUTION_MAX, "control, whole cells (ParaView's stock), %d "
                  "ranks: the exact pieces composited in box order miss the distribution's bound "
                  "(worst view max %.3f/255 > %g/255)" % (ranks, max(seams), DISTRIBUTION_MAX))
        if mode in pieces:
            icet_floor.update(floor)
            icet_images.update(icet)
        worst = 0.0
        for mapper, v, path, seconds, planes, floats in shots:
            shown = png_array(path)
            rmse, peak = errors(shown, exact8[v])
            worst = max(worst, rmse)
            line = ("%-6s %-21s view %d, %d ranks: against the exact image RMSE %.3f/255, max "
                    "%.0f/255" % (mode, mapper, v, ranks, rmse, peak))
            icet_rmse, icet_max = (float("nan"), float("nan"))
            if v in icet_images:
                icet_rmse, icet_max = errors(shown, icet_images[v])
                line += ("; IceT's floor RMSE %.3f, max %.0f; against IceT's composite of the "
                         "exact pieces RMSE %.3f, max %.0f" % (icet_floor[v] + (icet_rmse,
                                                                               icet_max)))
            if exact_mode:
                if ranks > 1:
                    check(all(f == 1 for f in floats), "%s, %s, %d ranks, view %d: every rank "
                          "composited in float (%s)" % (mode, mapper, ranks, v,
                                                        [int(f) for f in floats]))
                check(peak <= MAX_BOUND and rmse <= RMSE_BOUND,
                      "%s, %s, %d ranks, view %d: the image is the exact image within max %g/255 "
                      "and RMSE %g/255 (RMSE %.3f, max %.0f)"
                      % (mode, mapper, ranks, v, MAX_BOUND, RMSE_BOUND, rmse, peak))
            if mode == "icet8":
                check(all(f == 0 for f in floats), "control, %s, %d ranks, view %d: IceT's "
                      "8-bit composite on every rank (%s)" % (mapper, ranks, v,
                                                              [int(f) for f in floats]))
            print(line + "; planes %s, %.2f s" % ([int(p) for p in planes], seconds), flush=True)
            fl = icet_floor.get(v, (float("nan"), float("nan")))
            rows.append((args.data, ranks, mode, mapper, v, rmse, peak, fl[0], fl[1], icet_rmse,
                         icet_max, int(sum(cells)), int(max(cells)), int(max(planes)), seconds,
                         first))
        if mode == "icet8" and ranks > 1:
            check(worst > RMSE_BOUND, "control, IceT's 8-bit composite, %d ranks: the worst view "
                  "misses the RMSE bound (RMSE %.3f/255 > %g/255)" % (ranks, worst, RMSE_BOUND))
    if args.csv:
        new = not os.path.exists(args.csv)
        with open(args.csv, "a") as out:
            if new:
                out.write("data,ranks,redistribution,mapper,view,rmse_255,max_255,floor_rmse_255,"
                          "floor_max_255,vs_icet_rmse_255,vs_icet_max_255,cells_total,"
                          "cells_max_rank,region_planes,render_s,first_frame_s\n")
            for row in rows:
                out.write("%s,%d,%s,%s,%d,%.4f,%.0f,%.4f,%.0f,%.4f,%.0f,%d,%d,%d,%.3f,%.3f\n"
                          % row)

every_failure = gather(len(failures))
if rank == 0:
    print("%d failures" % len(failures), flush=True)
sys.stdout.flush()
sys.stderr.flush()
# As TestHAVSPlugin.py: finalize MPI (mpiexec requires it of every rank), then leave without
# the interpreter's teardown (ParaView's window destruction under Xvfb can fail at exit).
if controller and ranks > 1:
    controller.Barrier()
    controller.Finalize()
os._exit(1 if any(every_failure) else 0)
