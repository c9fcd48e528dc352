# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""havs_intermix_overhead: what vtkHAVSIntermixPass costs where no translucent actor is present.

    VTK_SMP_BACKEND_IN_USE=STDThread HAVS_DATA_DIR=../shared/data \\
        python3 Apps/havs_intermix_overhead.py [dataset] [havs|raycast|cellproj] [size]

Issue 46: the intermixing pass is on by default only if it costs at most 2 % of
a frame without translucent geometry. One window, one volume, no actor; the
renderer's pass alternates between VTK's own vtkRenderStepsPass and
vtkHAVSIntermixPass in short blocks (16 rounds, each round's order swapped: the machine's drift cancels), frames
timed to the end of Render():

- the volume visible: whole frames, as a user has them (the GPU's work and its
  noise included);
- the volume hidden: what the pass itself adds per frame (its prop loops and
  information-key look-ups), with no GPU work to hide it.

Prints both with the ratio and the difference per frame. Speed only: nothing
is asserted (the tests assert correctness).
"""
import glob
import os
import statistics
import sys
import time

# The project's Python modules: an install, or the build tree beside this file.
sys.path[:0] = glob.glob(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build",
                                      "lib", "python3*", "*-packages"))
import vtkhavs  # noqa: E402
from vtkhavs.vtkHAVSOpenGL import vtkHAVSIntermixPass  # noqa: E402
from vtkhavs.vtkHAVSValidation import vtkHAVSDataSets  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkRenderingCore import (  # noqa: E402
    vtkColorTransferFunction, vtkRenderer, vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass  # noqa: E402
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: E402,F401  (the volume mappers' factories)

dataset = sys.argv[1] if len(sys.argv) > 1 else "bluntfin"
mapper_name = sys.argv[2] if len(sys.argv) > 2 else "havs"
size = int(sys.argv[3]) if len(sys.argv) > 3 else 512

grid = vtkHAVSDataSets.Load(dataset)
if grid is None or grid.GetNumberOfCells() == 0:
    sys.exit("cannot load %s (HAVS_DATA_DIR?)" % dataset)
lo, hi = grid.GetPointData().GetScalars().GetRange()
opacity, color, prop = vtkPiecewiseFunction(), vtkColorTransferFunction(), vtkVolumeProperty()
opacity.AddPoint(lo, 0.0)
opacity.AddPoint(hi, 0.5)
color.AddRGBPoint(lo, 0, 0, 1)
color.AddRGBPoint(hi, 1, 0, 0)
prop.SetScalarOpacity(opacity)
prop.SetColor(color)
prop.SetScalarOpacityUnitDistance(grid.GetLength() / 20)

window = vtkhavs.vtkHAVSRenderWindowFactory.CreateRenderWindow()
window.SetSize(size, size)
renderer = vtkRenderer()
window.AddRenderer(renderer)
mapper = {"havs": vtkhavs.vtkHAVSVolumeMapper, "raycast": vtkhavs.vtkHAVSRayCastMapper,
          "cellproj": vtkhavs.vtkHAVSCellProjectionMapper}[mapper_name]()
mapper.SetInputData(grid)
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
renderer.AddVolume(volume)
renderer.ResetCamera()
passes = {"steps": vtkRenderStepsPass(), "intermix": vtkHAVSIntermixPass()}
for _ in range(3):
    window.Render()


def block(name, frames):
    renderer.SetPass(passes[name])
    window.Render()
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        window.Render()
        times.append(time.perf_counter() - start)
    return times


print("%s, %s, %d^2, %s, vtkSMPTools backend %s" % (
    dataset, mapper_name, size, window.GetClassName(),
    os.environ.get("VTK_SMP_BACKEND_IN_USE", "VTK's default")))
print("| volume | vtkRenderStepsPass ms | vtkHAVSIntermixPass ms | ratio | difference per frame |")
print("|---|---|---|---|---|")
for visible in (True, False):
    volume.SetVisibility(visible)
    times = {"steps": [], "intermix": []}
    for round_ in range(16):
        for name in (("steps", "intermix") if round_ % 2 == 0 else ("intermix", "steps")):
            times[name] += block(name, 5 if visible else 100)
    a = statistics.median(times["steps"]) * 1e3
    b = statistics.median(times["intermix"]) * 1e3
    print("| %s | %.3f | %.3f | %.4f | %+.1f us |"
          % ("visible" if visible else "hidden", a, b, b / a, (b - a) * 1e3))
