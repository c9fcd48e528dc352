# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""The installed Python package, alone (PYTHONPATH: the install prefix's package directory
only): imports vtkhavs, renders a tetrahedralized block with vtkHAVSVolumeMapper headless and
checks the image is not empty."""
import sys

import vtkhavs
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkVolume,
                                         vtkVolumeProperty)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction

print("vtkhavs from", vtkhavs.__file__)
source = vtkRTAnalyticSource()
source.SetWholeExtent(-8, 8, -8, 8, -8, 8)
tets = vtkDataSetTriangleFilter()
tets.SetInputConnection(source.GetOutputPort())
color = vtkColorTransferFunction()
color.AddRGBPoint(37.0, 0.2, 0.4, 1.0)
color.AddRGBPoint(277.0, 1.0, 0.6, 0.2)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(37.0, 0.3)
opacity.AddPoint(277.0, 0.9)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(4.0)
mapper = vtkhavs.vtkHAVSVolumeMapper()
mapper.SetInputConnection(tets.GetOutputPort())
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
renderer = vtkRenderer()
renderer.AddVolume(volume)
window = vtkhavs.vtkHAVSRenderWindowFactory.CreateRenderWindow()
window.SetSize(64, 64)
window.AddRenderer(renderer)
renderer.ResetCamera()
window.Render()
rgba = vtkFloatArray()
window.GetRGBAPixelData(0, 0, 63, 63, 0, rgba)
centre = [rgba.GetComponent(32 * 64 + 32, c) for c in range(3)]
corner = [rgba.GetComponent(0, c) for c in range(3)]
print("havs_consumer.py: %s, path %s, centre RGB %s, corner RGB %s"
      % (mapper.GetClassName(), mapper.GetActiveKBufferPathName(), centre, corner))
ok = (sum(centre) > 0.3 and sum(corner) == 0.0
      and mapper.GetClassName() == "vtkOpenGLHAVSVolumeMapper")
print("havs_consumer.py: " + ("PASS" if ok else "FAIL: the volume is not drawn where it should be"))
sys.exit(0 if ok else 1)
