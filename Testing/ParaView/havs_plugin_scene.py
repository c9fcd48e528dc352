# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""What the ParaView plugin tests share: the LOX post read with VTK, the HAVS Volume
display styled the same way in every test, PNG pixels, image differences and the exact
reference image of a scene."""
import ctypes
import math
import os
import subprocess
import sys
import traceback

from paraview.simple import (CreateRenderView, GetColorTransferFunction,
                             GetOpacityTransferFunction, LegacyVTKReader, Show, Tetrahedralize)
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkRenderingCore import vtkVolumeProperty

import vtkhavs

SIZE = 200


def mpi_setup():
    """The global controller, this rank and the number of ranks (None, 0, 1 serially). An
    exception on one rank then ends the job instead of leaving the others waiting in a
    collective call."""

    def abort_on_exception(kind, value, trace):
        traceback.print_exception(kind, value, trace)
        sys.stderr.flush()
        os._exit(2)

    sys.excepthook = abort_on_exception
    controller = vtkMultiProcessController.GetGlobalController()
    rank = controller.GetLocalProcessId() if controller else 0
    ranks = controller.GetNumberOfProcesses() if controller else 1
    return controller, rank, ranks


def gather_all(controller, ranks, value):
    """`value` of every rank, on every rank (a list of floats; collective)."""
    local = vtkDoubleArray()
    local.InsertNextValue(float(value))
    every = vtkDoubleArray()
    every.SetNumberOfValues(ranks)
    if controller and ranks > 1:
        controller.AllGather(local, every)
        return [every.GetValue(i) for i in range(ranks)]
    return [float(value)]


def expat_status():
    """Which expat this process runs with, and whether VTK's XML readers work with it:
    (description, broken). Broken: this expat defers reparsing (Debian 12's
    2.5.0-1+deb12u5, expat >= 2.6), which VTK 9.2's XML parser cannot take, and
    vtkHAVSExpatFix (LD_PRELOAD) is not in the process."""
    process = ctypes.CDLL(None)
    deferral = hasattr(process, "XML_SetReparseDeferralEnabled")
    fixed = hasattr(process, "vtkHAVSExpatFixParserCount")
    try:
        package = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "libexpat1"],
                                 capture_output=True, text=True).stdout or "unknown"
    except OSError:
        package = "unknown"
    version = "unknown"
    if hasattr(process, "XML_ExpatVersion"):
        process.XML_ExpatVersion.restype = ctypes.c_char_p
        version = process.XML_ExpatVersion().decode()
    description = ("expat %s (Debian libexpat1 %s), reparse deferral %s, vtkHAVSExpatFix %s"
                   % (version, package, "yes" if deferral else "no",
                      "loaded" if fixed else "not loaded"))
    return description, deferral and not fixed


def require_working_expat():
    """Prints the expat this process runs with; exits with the reason when it breaks VTK's
    XML readers (ParaView's data redistribution under MPI depends on them)."""
    description, broken = expat_status()
    print("expat: " + description, flush=True)
    if broken:
        print("FAIL: this expat defers reparsing and vtkHAVSExpatFix is not preloaded: VTK's "
              "XML readers (and ParaView's data redistribution) cannot work here. Run with "
              "LD_PRELOAD=<build or install>/lib/libvtkHAVSExpatFix.so (see the user guide).",
              flush=True)
        os._exit(3)


def lox_post_path():
    return os.path.join(os.environ["HAVS_DATA_DIR"], "post.vtk")


def read_lox_post():
    """The LOX post tetrahedralized with VTK (as ParaView's Tetrahedralize does), Pressure active."""
    legacy = vtkUnstructuredGridReader()
    legacy.SetFileName(lox_post_path())
    tetrahedralize = vtkDataSetTriangleFilter()
    tetrahedralize.SetInputConnection(legacy.GetOutputPort())
    tetrahedralize.Update()
    grid = tetrahedralize.GetOutput()
    grid.GetPointData().SetActiveScalars("Pressure")
    return grid


def color_by_points(display, array):
    """Colour `display` by the point array `array`, its colour and opacity maps set directly.

    Not ColorBy: under `pvbatch --symmetric` ParaView 6.1's ColorBy asks every rank for the
    array's range and ranks whose data information differs leave the collective call early
    ("Could not determine array range" on one rank, MPI_ERR_TRUNCATE on the other, for the
    stock Volume and Surface representations alike); the ranges here are set explicitly."""
    display.ColorArrayName = ["POINTS", array]
    display.LookupTable = GetColorTransferFunction(array)
    display.ScalarOpacityFunction = GetOpacityTransferFunction(array)


def style_havs_volume(display, array, data_range, length):
    """Colour by `array`, opacity ramp 0 -> 0.8 over `data_range`, unit distance length / 8,
    HAVS Volume with k = 14 and no early ray termination. Returns the colour and opacity maps."""
    color_by_points(display, array)
    display.Representation = "HAVS Volume"
    lut = GetColorTransferFunction(array)
    pwf = GetOpacityTransferFunction(array)
    lut.RescaleTransferFunction(data_range[0], data_range[1])
    pwf.RescaleTransferFunction(data_range[0], data_range[1])
    pwf.Points = [data_range[0], 0.0, 0.5, 0.0, data_range[1], 0.8, 0.5, 0.0]
    display.ScalarOpacityUnitDistance = length / 8.0
    display.HAVSKBufferSize = 14
    display.HAVSEarlyRayTerminationOpacity = 1.0
    return lut, pwf


def new_view():
    """A new SIZE x SIZE render view on a black background, without orientation axes."""
    view = CreateRenderView()
    view.ViewSize = [SIZE, SIZE]
    view.OrientationAxesVisibility = 0
    view.Background = [0.0, 0.0, 0.0]
    view.UseColorPaletteForBackground = 0
    return view


def show_lox_post(grid):
    """The LOX post as HAVS Volume in a new SIZE x SIZE view on a black background, seen
    from azimuth 30, elevation 20. Returns (tets source, view, display, lut, pwf)."""
    tets = Tetrahedralize(Input=LegacyVTKReader(FileNames=[lox_post_path()]))
    view = new_view()
    display = Show(tets, view)
    lut, pwf = style_havs_volume(
        display, "Pressure", grid.GetPointData().GetArray("Pressure").GetRange(),
        grid.GetLength())
    view.CameraPosition = [0.0, 0.0, 1.0]
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Azimuth(30.0)
    camera.Elevation(20.0)
    view.ResetCamera()
    return tets, view, display, lut, pwf


def png_rgb(path):
    """The RGB pixels of a PNG, in [0, 1], bottom row first (empty when unreadable)."""
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    image = png.GetOutput()
    scalars = image.GetPointData().GetScalars()
    if scalars is None:
        return []
    return [[scalars.GetComponent(i, k) / 255.0 for k in range(3)]
            for i in range(image.GetNumberOfPoints())]


def compare(a, b):
    """RMSE and maximum absolute difference of two RGB pixel lists (1e30 if they differ in size)."""
    if len(a) != len(b) or not a:
        return 1e30, 1e30
    diffs = [abs(x[k] - y[k]) for x, y in zip(a, b) for k in range(3)]
    return math.sqrt(sum(d * d for d in diffs) / len(diffs)), max(diffs)


def reference_image(grid, lut, pwf, unit_distance, camera, size=SIZE, blend=0, isovalues=(),
                    mixed=False, shade=None, lights=None, planes=None):
    """The exact image (vtkHAVSReferenceRenderer) of `grid` with ParaView's colour and opacity
    maps: premultiplied RGBA, size x size tuples, bottom row first. `blend`: vtkVolumeMapper's
    blend mode (5: the isosurfaces `isovalues`); `mixed`: the composite with them inside;
    `shade`: (ambient, diffuse, specular, specular power) to light the isosurfaces by
    `lights` (a vtkLightCollection); `planes`: clipping planes (a vtkPlaneCollection, world
    coordinates, each keeping the side its normal points to)."""
    prop = vtkVolumeProperty()
    prop.SetColor(lut.GetClientSideObject())
    prop.SetScalarOpacity(pwf.GetClientSideObject())
    prop.SetScalarOpacityUnitDistance(unit_distance)
    if shade:
        prop.ShadeOn()
        prop.SetAmbient(shade[0])
        prop.SetDiffuse(shade[1])
        prop.SetSpecular(shade[2])
        prop.SetSpecularPower(shade[3])
    for i, value in enumerate(isovalues):
        prop.GetIsoSurfaceValues().SetValue(i, value)
    reference = vtkhavs.vtkHAVSReferenceRenderer()
    reference.SetInputData(grid)
    reference.SetProperty(prop)
    reference.SetCamera(camera)
    reference.SetSize(size, size)
    reference.SetBlendMode(blend)
    reference.SetIsoSurfacesInComposite(mixed)
    if lights is not None:
        reference.SetLights(lights)
    if planes is not None:
        reference.SetClippingPlanes(planes)
    reference.Render()
    return reference.GetImage()


def reference_rgb(grid, lut, pwf, unit_distance, camera, size=SIZE, **modes):
    """reference_image as RGB over black, clamped to 1 (a list of pixels)."""
    exact = reference_image(grid, lut, pwf, unit_distance, camera, size, **modes)
    return [[min(1.0, exact.GetComponent(i, k)) for k in range(3)] for i in range(size * size)]
