# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""What the Python measuring programs in Apps/ share: the project's modules from the build tree
beside them, a ramp volume property over a grid's scalar range, a headless window and the
mappers by short name."""
import glob
import os
import sys

# The project's Python modules: an install, or the build tree beside this file.
sys.path[:0] = glob.glob(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build",
                                      "lib", "python3*", "*-packages"))
import vtkhavs  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkColorTransferFunction, vtkRenderer, vtkVolumeProperty)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: E402,F401  (the volume mappers' factories)

MAPPERS = {"havs": vtkhavs.vtkHAVSVolumeMapper, "raycast": vtkhavs.vtkHAVSRayCastMapper,
           "cellproj": vtkhavs.vtkHAVSCellProjectionMapper}


def ramp_property(grid):
    """Opacity 0 to 0.5 and blue to red over the grid's scalar range, unit distance a
    twentieth of its diagonal."""
    lo, hi = grid.GetPointData().GetScalars().GetRange()
    opacity, color, prop = vtkPiecewiseFunction(), vtkColorTransferFunction(), vtkVolumeProperty()
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(hi, 0.5)
    color.AddRGBPoint(lo, 0, 0, 1)
    color.AddRGBPoint(hi, 1, 0, 0)
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(grid.GetLength() / 20)
    return prop


def new_window(size):
    """A size x size headless window (vtkHAVSRenderWindowFactory) with one renderer."""
    window = vtkhavs.vtkHAVSRenderWindowFactory.CreateRenderWindow()
    window.SetSize(size, size)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    return window, renderer
