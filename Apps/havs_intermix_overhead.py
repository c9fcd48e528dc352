# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""havs_intermix_overhead: what vtkHAVSIntermixPass costs where no translucent actor is present.

    VTK_SMP_BACKEND_IN_USE=STDThread HAVS_DATA_DIR=../shared/data \\
        python3 Apps/havs_intermix_overhead.py [dataset] [havs|raycast|cellproj] [size] [--paired=N]

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
import os
import random
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from havs_app_scene import MAPPERS, new_window, ramp_property  # noqa: E402
from vtkhavs.vtkHAVSOpenGL import vtkHAVSIntermixPass  # noqa: E402
from vtkhavs.vtkHAVSValidation import vtkHAVSDataSets  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkVolume  # noqa: E402
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass  # noqa: E402

args = [a for a in sys.argv[1:] if not a.startswith("--paired")]
paired = [int(a.split("=")[1]) for a in sys.argv[1:] if a.startswith("--paired=")]
dataset = args[0] if len(args) > 0 else "bluntfin"
mapper_name = args[1] if len(args) > 1 else "havs"
size = int(args[2]) if len(args) > 2 else 512

grid = vtkHAVSDataSets.Load(dataset)
if grid is None or grid.GetNumberOfCells() == 0:
    sys.exit("cannot load %s (HAVS_DATA_DIR?)" % dataset)
prop = ramp_property(grid)
window, renderer = new_window(size)
mapper = MAPPERS[mapper_name]()
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


def paired_rounds(rounds):
    """--paired=N: N rounds of one timed frame with each pass (each after a
    warm-up frame with it; the order swapped every round), the volume
    visible. Each round's ratio is the intermix frame over the steps frame
    beside it: the machine's drift, slower than a round, cancels. Prints the
    mean ratio with its 95 % interval (normal approximation) and the median
    with its 95 % interval (bootstrap: the frames' times have a long tail)."""
    ratios = []
    for round_ in range(rounds):
        t = {}
        for name in (("steps", "intermix") if round_ % 2 == 0 else ("intermix", "steps")):
            t[name] = block(name, 1)[0]
        ratios.append(t["intermix"] / t["steps"])
    mean = statistics.fmean(ratios)
    half = 1.96 * statistics.stdev(ratios) / len(ratios) ** 0.5
    # The median's 95 % interval: 1,000 bootstrap resamples (seeded).
    rng = random.Random(1)
    medians = sorted(statistics.median(rng.choices(ratios, k=len(ratios))) for _ in range(1000))
    print("| %s | %s | %d | %.4f | %.4f to %.4f | %.4f | %.4f to %.4f |" % (
        dataset, mapper_name, rounds, mean, mean - half, mean + half, statistics.median(ratios),
        medians[25], medians[974]))


if paired:
    print("%s, %s, %d^2, vtkSMPTools backend %s: paired rounds (the volume visible)" % (
        dataset, mapper_name, size, os.environ.get("VTK_SMP_BACKEND_IN_USE", "VTK's default")))
    print("| data set | mapper | rounds | intermix / steps, mean | 95 % interval | median "
          "| 95 % interval |")
    print("|---|---|---|---|---|---|---|")
    paired_rounds(paired[0])
    sys.exit(0)

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
