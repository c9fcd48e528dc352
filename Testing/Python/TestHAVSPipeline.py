# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""The Python pipeline: the wrapped vtkHAVS module renders a tetrahedralized
box through the same calls a C++ user makes, and the result matches the
closed form (constant slab: opacity 1 - exp(-tau L))."""
import math
import sys

from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkRenderingCore import (
    vtkColorTransferFunction, vtkRenderer, vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction

import vtkhavs

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("CHECK FAILED:", what)


image = vtkImageData()
image.SetDimensions(5, 5, 5)
image.SetSpacing(0.25, 0.25, 0.25)
scalars = vtkDoubleArray()
scalars.SetName("s")
scalars.SetNumberOfTuples(image.GetNumberOfPoints())
for i in range(image.GetNumberOfPoints()):
    scalars.SetValue(i, 0.5)
image.GetPointData().SetScalars(scalars)
tets = vtkDataSetTriangleFilter()
tets.SetInputData(image)

color = vtkColorTransferFunction()
color.AddRGBPoint(0.0, 0.2, 0.6, 0.9)
color.AddRGBPoint(1.0, 0.2, 0.6, 0.9)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(0.0, 0.5)
opacity.AddPoint(1.0, 0.5)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(0.5)

mapper = vtkhavs.vtkHAVSVolumeMapper()
mapper.CountOrderViolationsOn()
mapper.SetInputConnection(tets.GetOutputPort())
mapper.SetKBufferSize(4)
mapper.KeepFloatResultOn()
mapper.SetEarlyRayTerminationOpacity(1.0)
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)

window = vtkhavs.vtkHAVSRenderWindowFactory.CreateRenderWindow()
check(window is not None, "the factory makes a window")
window.SetSize(48, 48)
renderer = vtkRenderer()
window.AddRenderer(renderer)
renderer.AddVolume(volume)
camera = renderer.GetActiveCamera()
camera.ParallelProjectionOn()
camera.SetFocalPoint(0.5, 0.5, 0.5)
camera.SetPosition(0.5, 0.5, 10.0)
camera.SetParallelScale(0.8)
renderer.ResetCameraClippingRange()
window.Render()

print("backend:", vtkhavs.vtkHAVSRenderWindowFactory.GetBackendName(window))
print("path:", mapper.GetActiveKBufferPathName(), "k:", mapper.GetActiveKBufferSize())
check(mapper.GetNumberOfTetrahedra() == 4 * 4 * 4 * 5, "320 tetrahedra")
result = vtkFloatArray()
size = [0, 0]
check(mapper.GetFloatResult(result, size), "float result kept")
expected = 1.0 - math.exp(-1.0)
centre = (size[1] // 2) * size[0] + size[0] // 2
alpha = result.GetComponent(centre, 3)
red = result.GetComponent(centre, 0)
print("centre alpha %.6f expected %.6f" % (alpha, expected))
check(abs(alpha - expected) < 1e-3, "centre opacity is 1 - exp(-1)")
check(abs(red - 0.2 * expected) < 1e-3, "centre red is 0.2 * opacity")

# A transfer-function edit redraws without a re-sort.
opacity.AddPoint(0.5, 0.25)
window.Render()
check(mapper.GetLastFrameStatistics().GetOrderReused(), "a transfer-function edit reuses the sort")
mapper.GetFloatResult(result, size)
check(result.GetComponent(centre, 3) < alpha - 0.05, "the edit changes the image")

# The exact reference renderer and the metrics, from Python.
tets.Update()
reference = vtkhavs.vtkHAVSReferenceRenderer()
reference.SetInputData(tets.GetOutput())
reference.SetProperty(prop)
reference.SetCamera(camera)
reference.SetSize(size[0], size[1])
check(reference.Render(), "the reference renders")
metrics = vtkhavs.vtkHAVSImageMetrics()
window.Render()
mapper.GetFloatResult(result, size)
check(metrics.Compare(result, reference.GetImage()), "images compare")
print("HAVS vs reference: RMSE %.2e, max %.2e" % (metrics.GetRMSE(), metrics.GetMaxAbsError()))
check(metrics.GetMaxAbsError() < 1e-3, "HAVS equals the reference on the edited box")

# The cell-projection mapper swaps in: its override from Python, the same image.
cells = vtkhavs.vtkHAVSCellProjectionMapper()
check(cells.GetClassName() == "vtkOpenGLHAVSCellProjectionMapper",
      "vtkHAVSCellProjectionMapper() gives %s" % cells.GetClassName())
cells.SetInputConnection(tets.GetOutputPort())
cells.KeepFloatResultOn()
volume.SetMapper(cells)
window.Render()
cell_result = vtkFloatArray()
check(cells.GetFloatResult(cell_result, size), "cell projection: float result kept")
check(metrics.Compare(cell_result, reference.GetImage()), "cell projection: images compare")
print("cell projection vs reference: RMSE %.2e, max %.2e (%d cells)"
      % (metrics.GetRMSE(), metrics.GetMaxAbsError(), cells.GetLastCellsDrawn()))
check(metrics.GetMaxAbsError() < 1e-3 and cells.GetLastCellsDrawn() == 320,
      "cell projection equals the reference on the edited box")

# The ray-casting mapper swaps in too: its override from Python, the same image.
rays = vtkhavs.vtkHAVSRayCastMapper()
check(rays.GetClassName() == "vtkOpenGLHAVSRayCastMapper",
      "vtkHAVSRayCastMapper() gives %s" % rays.GetClassName())
rays.SetInputConnection(tets.GetOutputPort())
rays.KeepFloatResultOn()
volume.SetMapper(rays)
window.Render()
ray_result = vtkFloatArray()
check(rays.GetFloatResult(ray_result, size), "ray casting: float result kept")
check(metrics.Compare(ray_result, reference.GetImage()), "ray casting: images compare")
print("ray casting vs reference: RMSE %.2e, max %.2e (%d peel passes, %d rays)"
      % (metrics.GetRMSE(), metrics.GetMaxAbsError(), rays.GetLastPeelPasses(),
         rays.GetLastRaysStarted()))
check(metrics.GetMaxAbsError() < 1e-3 and rays.GetLastPeelPasses() == 1,
      "ray casting equals the reference on the edited box (convex: one pass)")
volume.SetMapper(mapper)

# Order violations and the automatic order, from Python: long, flat cells
# (centroids far from where rays hit the faces) make the centroid order at
# k = 1 inexact; the fragments it composited out of depth order are counted.
# MPVO is exact (the block is convex); Automatic finds that out and switches.
thin = vtkImageData()
thin.SetDimensions(12, 10, 8)
thin.SetSpacing(1.0, 0.15, 0.04)
thin_scalars = vtkDoubleArray()
thin_scalars.SetName("s")
for i in range(thin.GetNumberOfPoints()):
    x = thin.GetPoint(i)
    thin_scalars.InsertNextValue(0.1 * x[0] + 3.0 * x[2])
thin.GetPointData().SetScalars(thin_scalars)
tets.SetInputData(thin)
prop.SetScalarOpacityUnitDistance(0.3)
camera.ParallelProjectionOff()
camera.SetFocalPoint(5.5, 0.675, 0.14)
camera.SetPosition(5.5 - 9.8, 0.675 + 5.6, 0.14 + 14.0)
camera.SetViewUp(0.0, 0.0, 1.0)
camera.SetViewAngle(50.0)
renderer.ResetCameraClippingRange()
mapper.SetKBufferSize(1)
mapper.SetVisibilityOrderToCentroid()
window.Render()
centroid_violations = mapper.GetLastOrderViolations()
mapper.SetVisibilityOrderToMPVO()
window.Render()
mpvo_violations = mapper.GetLastOrderViolations()
mapper.SetVisibilityOrderToAutomatic()
window.Render()
print("k = 1 order violations: centroid %d, MPVO %d; Automatic used %s with %d" % (
    centroid_violations, mpvo_violations,
    "MPVO" if mapper.GetLastVisibilityOrder() == mapper.VisibilityOrderMPVO else "centroid",
    mapper.GetLastOrderViolations()))
check(centroid_violations > 0, "the centroid order at k = 1 has order violations")
check(mpvo_violations == 0, "MPVO has none")
check(mapper.GetLastVisibilityOrder() == mapper.VisibilityOrderMPVO
      and mapper.GetLastOrderViolations() == 0, "Automatic switches to MPVO")

# What users bring (issue 19), from Python: the vtkImageData itself (no
# tetrahedralizing filter) with a cell array, and a 3-component array by its
# magnitude (vector mode), each against the reference of the same input.
cell_image = vtkImageData()
cell_image.SetDimensions(5, 5, 5)
cell_image.SetSpacing(0.25, 0.25, 0.25)
cell_values = vtkDoubleArray()
cell_values.SetName("c")
for c in range(cell_image.GetNumberOfCells()):
    cell_values.InsertNextValue(0.2 + 0.6 * ((c * 7) % 5) / 4.0)
cell_image.GetCellData().SetScalars(cell_values)
vectors = vtkDoubleArray()
vectors.SetName("v")
vectors.SetNumberOfComponents(3)
magnitudes = vtkDoubleArray()
magnitudes.SetName("m")
for i in range(cell_image.GetNumberOfPoints()):
    x = cell_image.GetPoint(i)
    vectors.InsertNextTuple3(x[0], 0.5 * x[1], 0.25 - x[2])
    magnitudes.InsertNextValue(math.sqrt(x[0] ** 2 + (0.5 * x[1]) ** 2 + (0.25 - x[2]) ** 2))
cell_image.GetPointData().AddArray(vectors)
opacity.RemoveAllPoints()
opacity.AddPoint(0.0, 0.0)
opacity.AddPoint(1.2, 0.8)
prop.SetScalarOpacityUnitDistance(0.5)
mapper.SetInputData(cell_image)
mapper.SetVisibilityOrderToMPVO()
mapper.SetKBufferSize(2)
renderer.ResetCamera()
camera.Azimuth(30.0)
camera.Elevation(20.0)
camera.OrthogonalizeViewUp()
renderer.ResetCameraClippingRange()
for what, configure, exact_input in (
        ("cell scalars", lambda m: m.SetScalarModeToUseCellData(), cell_image),
        ("vector magnitude", lambda m: (m.SetScalarModeToUsePointFieldData(),
                                        m.SelectScalarArray("v"), m.SetVectorMode(0)), None)):
    configure(mapper)
    window.Render()
    check(mapper.GetFloatResult(result, size), what + ": float result kept")
    if exact_input is None:
        exact_input = vtkImageData()
        exact_input.DeepCopy(cell_image)
        exact_input.GetCellData().Initialize()
        exact_input.GetPointData().SetScalars(magnitudes)
    reference.SetInputData(exact_input)
    check(reference.Render(), what + ": the reference renders")
    check(metrics.Compare(result, reference.GetImage()), what + ": images compare")
    print("%s (vtkImageData as it is) vs reference: RMSE %.2e, max %.2e"
          % (what, metrics.GetRMSE(), metrics.GetMaxAbsError()))
    check(metrics.GetRMSE() < 5e-4, what + ": HAVS equals the reference")

print("%d passed, %d failed" % (26 - len(failures), len(failures)))
sys.exit(1 if failures else 0)
