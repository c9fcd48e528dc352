# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""UseDataPartitions with the user's own pieces (issue 44): mpiexec -np 2 pvbatch --symmetric.

With UseDataPartitions on, ParaView does not redistribute the grid: IceT composites the ranks in
the order of their pieces' bounding boxes, which is exact only when those boxes are disjoint.
The HAVS Volume representation says so once, naming the ranks, when two boxes overlap. A
tetrahedralized wavelet (vtkRTAnalyticSource, 16^3 voxels) is written as a .pvtu of one piece
per rank, two ways:

- interleaved: cell i on rank i mod 2; both pieces span the whole grid: the warning must come;
- slabs: the cells with x < 0 on rank 0, the others on rank 1 (the voxels' faces lie on x = 0:
  the boxes touch, they do not overlap): no warning.

Each case is the other's control: the warning must come for the one and not for the other.

Then the interleaved pieces with UseDataPartitions off (ParaView redistributes them along its kd
cuts): no warning, and no crash. VTK 9.2's .pvtu reader (vtkXMLPUnstructuredGridReader) hands
vtkUnstructuredGrid::SetCells an uninitialized cell-types array; a stray byte 42 (VTK_POLYHEDRON)
there leaves the grid with empty polyhedron face arrays, on which vtkExtractCells, in
vtkRedistributeDataSetFilter::SplitDataSet, reads past the end (SIGSEGV; issue 44). Whether that
byte is there depends on what the process freed before: after the two cases above it was, in
every run without the representation's repair (DropStaleFaces).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from paraview.simple import (ColorBy, CreateRenderView, Delete, Hide, LoadPlugin, Render, Show,
                             XMLPartitionedUnstructuredGridReader)
from vtkmodules.vtkCommonCore import vtkIdList, vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkFiltersCore import vtkExtractCells
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOParallelXML import vtkXMLPUnstructuredGridWriter

from havs_plugin_scene import mpi_setup, require_working_expat

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--out", required=True)
args = parser.parse_args()

controller, rank, ranks = mpi_setup()
if ranks != 2:
    print("TestHAVSPluginPartitions: run it on 2 ranks (mpiexec -np 2)")
    sys.exit(1)
require_working_expat()
os.makedirs(args.out, exist_ok=True)
LoadPlugin(args.plugin, remote=False, ns=globals())

source = vtkRTAnalyticSource()
source.SetWholeExtent(-8, 8, -8, 8, -8, 8)
tetrahedralize = vtkDataSetTriangleFilter()
tetrahedralize.SetInputConnection(source.GetOutputPort())
tetrahedralize.Update()
grid = tetrahedralize.GetOutput()


def write_pieces(how):
    """This rank's piece of the grid (interleaved or slabs) into <out>/<how>.pvtu."""
    ids = vtkIdList()
    for c in range(grid.GetNumberOfCells()):
        if how == "interleaved":
            mine = c % ranks == rank
        else:
            bounds = grid.GetCell(c).GetBounds()
            mine = ((bounds[0] + bounds[1]) < 0.0) == (rank == 0)
        if mine:
            ids.InsertNextId(c)
    extract = vtkExtractCells()
    extract.SetInputData(grid)
    extract.SetCellList(ids)
    extract.Update()
    piece = extract.GetOutput()
    piece.GetCellData().RemoveArray("vtkOriginalCellIds")
    piece.GetPointData().RemoveArray("vtkOriginalPointIds")
    writer = vtkXMLPUnstructuredGridWriter()
    writer.SetController(controller)
    writer.SetInputData(piece)
    writer.SetFileName(os.path.join(args.out, how + ".pvtu"))
    writer.SetNumberOfPieces(ranks)
    writer.SetStartPiece(rank)
    writer.SetEndPiece(rank)
    writer.Write()
    controller.Barrier()
    return ids.GetNumberOfIds()


def warned(how, partitions):
    """Whether showing <how>.pvtu as HAVS Volume (UseDataPartitions `partitions`) warned here."""
    reader = XMLPartitionedUnstructuredGridReader(FileName=[os.path.join(args.out, how + ".pvtu")])
    view = CreateRenderView()
    view.ViewSize = [64, 64]
    view.UseFXAA = 0
    display = Show(reader, view)
    display.Representation = "HAVS Volume"
    ColorBy(display, ("POINTS", "RTData"))
    display.UseDataPartitions = partitions
    # The representation's messages, caught while the view renders (pvbatch's
    # own output window, which also carries Python's stderr, is put back after).
    messages = vtkStringOutputWindow()
    previous = vtkOutputWindow.GetInstance()
    previous.Register(None)
    vtkOutputWindow.SetInstance(messages)
    try:
        Render(view)
        view.CameraPosition = [30.0, 12.0, 20.0]
        view.CameraFocalPoint = [0.0, 0.0, 0.0]
        Render(view)
    finally:
        vtkOutputWindow.SetInstance(previous)
    text = messages.GetOutput()
    Hide(reader, view)
    Delete(view)
    Delete(reader)
    return "overlapping bounding boxes" in text, text


failures = 0
cells = {how: write_pieces(how) for how in ("interleaved", "slabs")}
for how, partitions, expected in (("interleaved", 1, True), ("slabs", 1, False),
                                  ("interleaved", 0, False)):
    got, text = warned(how, partitions)
    ok = got == expected
    failures += 0 if ok else 1
    if rank == 0:
        print("%s  %s, UseDataPartitions %d (%d cells here): %s%s" %
              ("ok  " if ok else "FAIL", how, partitions, cells[how],
               "warned" if got else "no warning",
               "" if ok else " (expected %s)" % ("a warning" if expected else "none")))
        if got:
            line = [l for l in text.splitlines() if "overlapping" in l]
            print("      " + (line[0].strip()[:400] if line else ""))
all_failures = [0]
if controller:
    from vtkmodules.vtkParallelCore import vtkCommunicator
    from vtkmodules.vtkCommonCore import vtkIntArray
    mine, total = vtkIntArray(), vtkIntArray()
    mine.InsertNextValue(failures)
    controller.AllReduce(mine, total, vtkCommunicator.SUM_OP)
    all_failures[0] = total.GetValue(0)
if rank == 0:
    print("TestHAVSPluginPartitions: %s" % ("PASSED" if all_failures[0] == 0 else
                                            "%d FAILED" % all_failures[0]))
# As TestHAVSPluginSeams: MPI finalized on every rank, then out without the
# interpreter's teardown.
sys.stdout.flush()
if controller:
    controller.Barrier()
    controller.Finalize()
os._exit(0 if all_failures[0] == 0 else 1)
