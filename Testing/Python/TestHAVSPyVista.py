# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""The user guide's PyVista recipe, checked: a pyvista.UnstructuredGrid
rendered by vtkHAVSVolumeMapper in a pyvista.Plotter (VTK's own render window,
chosen by VTK at run time, not vtkHAVS's EGL window), its transfer functions
from PyVista's colormap and opacity, against the exact reference.

Where PyVista is not installed (Debian 12 has no package), or where it is on
another VTK than vtkHAVS's (Debian 13: python3-pyvista is on the system VTK,
ParaView has its own), the test exits 125 and ctest reports it as skipped.
Control: the reference with PyVista's opacity unit distance halved must be
outside the bound (the check can fail)."""
import sys

SKIP = 125

try:
    import pyvista as pv
except ImportError as error:
    print("SKIP: PyVista is not installed (%s)" % error)
    sys.exit(SKIP)

import numpy as np
from vtkmodules import vtkCommonCore as _vtk_core_module
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkVersion

import vtkhavs

# One VTK in the process: PyVista's vtkmodules must be the ones vtkhavs was
# built against.
if not hasattr(pv, "vtk_version_info"):
    print("SKIP: this PyVista does not report its VTK version")
    sys.exit(SKIP)
if tuple(pv.vtk_version_info[:2]) != (vtkVersion.GetVTKMajorVersion(),
                                       vtkVersion.GetVTKMinorVersion()):
    print("SKIP: PyVista is on VTK %s, vtkhavs on %s (%s)" % (
        ".".join(map(str, pv.vtk_version_info)), vtkVersion.GetVTKVersion(),
        _vtk_core_module.__file__))
    sys.exit(SKIP)

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("CHECK FAILED:", what)


def exact(metrics):
    """MISSION.md's exact bound on the last comparison."""
    return metrics.GetRMSE() < 5e-4 and metrics.GetMaxAbsError() < 0.01


def total_alpha(image):
    return float(vtk_to_numpy(image)[:, 3].sum())


# --- the recipe (Documentation/UserGuide.md, "PyVista") ----------------------
# A tetrahedral grid from PyVista with a smooth point field.
grid = pv.ImageData(dimensions=(9, 9, 9), spacing=(0.125, 0.125, 0.125)).triangulate()
x = grid.points
grid["density"] = np.exp(-8.0 * ((x - 0.5) ** 2).sum(axis=1))

plotter = pv.Plotter(off_screen=True, window_size=(96, 96))
# PyVista builds the volume property from its colormap and opacity preset.
volume = plotter.add_volume(grid, scalars="density", cmap="viridis", opacity="sigmoid",
                            opacity_unit_distance=0.25, show_scalar_bar=False)
# vtkHAVS's mapper in place of PyVista's ('ugrid': vtkUnstructuredGridVolumeRayCastMapper).
mapper = vtkhavs.vtkHAVSVolumeMapper()
mapper.SetInputData(grid)
mapper.SetScalarModeToUsePointFieldData()
mapper.SelectScalarArray("density")
mapper.KeepFloatResultOn()  # for the check below; not part of the recipe
volume.SetMapper(mapper)
plotter.camera_position = [(2.6, -1.9, 1.7), (0.5, 0.5, 0.5), (0.0, 0.0, 1.0)]
plotter.show(auto_close=False)  # the first render (plotter.render() draws only after show)
# --- end of the recipe --------------------------------------------------------

window = plotter.render_window
print("render window:", window.GetClassName(), "| k-buffer path:",
      mapper.GetActiveKBufferPathName(), "| tetrahedra:", mapper.GetNumberOfTetrahedra())
check(mapper.GetNumberOfTetrahedra() == grid.n_cells, "every tetrahedron prepared")
result = vtkFloatArray()
size = [0, 0]
check(mapper.GetFloatResult(result, size), "float result kept")

prop = volume.GetProperty()
reference = vtkhavs.vtkHAVSReferenceRenderer()
reference.SetInputData(grid)
reference.SetProperty(prop)
reference.SetCamera(plotter.renderer.GetActiveCamera())
reference.SetSize(size[0], size[1])
check(reference.Render(), "the reference renders")
metrics = vtkhavs.vtkHAVSImageMetrics()
check(metrics.Compare(result, reference.GetImage()), "images compare")
print("HAVS in a pyvista.Plotter vs the exact reference: RMSE %.2e, max %.2e" % (
    metrics.GetRMSE(), metrics.GetMaxAbsError()))
check(exact(metrics), "exact (RMSE < 5e-4, max < 0.01)")

# The control: another optical depth must fail the same bound.
unit = prop.GetScalarOpacityUnitDistance()
prop.SetScalarOpacityUnitDistance(0.5 * unit)
check(reference.Render(), "the control's reference renders")
metrics.Compare(result, reference.GetImage())
print("control (unit distance halved): RMSE %.2e, max %.2e" % (
    metrics.GetRMSE(), metrics.GetMaxAbsError()))
check(not exact(metrics), "the control fails the bound")
prop.SetScalarOpacityUnitDistance(unit)

# An opacity edit redraws at once.
before = total_alpha(result)
opacity = prop.GetScalarOpacity()
opacity.RemoveAllPoints()  # PyVista's 256 nodes replaced by a faint ramp
opacity.AddPoint(float(grid["density"].min()), 0.0)
opacity.AddPoint(float(grid["density"].max()), 0.2)
window.Render()  # VTK's own render call on the plotter's window
mapper.GetFloatResult(result, size)
after = total_alpha(result)
check(after < before, "an opacity edit redraws (total alpha %.3f -> %.3f)" % (before, after))
plotter.close()

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
