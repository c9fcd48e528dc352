# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""Makes Data/near_degenerate_ray.vtu and .json, the input of
TestHAVSNearDegenerateRay.py (run once; needs numpy and about 8 GB).

The cells of the scale's 49.7M block (Apps/havs_scale.py: MakeGenerated(215),
its view at 256^2) within 3 cubes of the ray of pixel (37, 95): that ray passes
within 1e-4 pixel of faces it sees almost edge-on, where all three mappers
were off by 0.012 to 0.044 (issue 43's check; 0.02 px away every one was
exact). The cells the ray crosses are all kept, so its pixel is the same as in
the whole block. The .json holds the camera, the scalar range and the block's
length (the transfer function's unit distance) of the whole block.

    python3 Testing/Python/make_near_degenerate_ray.py [build]
"""
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 'Apps'))
import havs_scale  # noqa: E402  (the scale's camera and transfer function)
import vtkhavs  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkCellArray, vtkUnstructuredGrid  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkVolume  # noqa: E402

CUBES, SIZE, PIXEL, RADIUS = 215, 256, (37, 95), 3.0

grid = vtkhavs.vtkHAVSDataSets.MakeGenerated(CUBES)
volume = vtkVolume()
volume.SetProperty(havs_scale.make_property(grid))
window, renderer = havs_scale.make_window(volume, SIZE)
camera = havs_scale.set_camera(grid, renderer)


def world(x, y, z):
    renderer.SetDisplayPoint(x, y, z)
    renderer.DisplayToWorld()
    w = renderer.GetWorldPoint()
    return np.array(w[:3]) / w[3]


a = world(PIXEL[0] + 0.5, PIXEL[1] + 0.5, 0.0)
d = world(PIXEL[0] + 0.5, PIXEL[1] + 0.5, 1.0) - a
d /= np.linalg.norm(d)
points = vtk_to_numpy(grid.GetPoints().GetData()).astype(np.float64)
tets = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 4)
h = (grid.GetBounds()[1] - grid.GetBounds()[0]) / CUBES
v = points[tets].mean(axis=1) - a
keep = np.nonzero(np.linalg.norm(v - np.outer(v @ d, d), axis=1) < RADIUS * h)[0]
ids, inverse = np.unique(tets[keep], return_inverse=True)
out = vtkUnstructuredGrid()
p = vtkPoints()
p.SetData(numpy_to_vtk(points[ids].astype(np.float32), deep=True))
out.SetPoints(p)
cells = vtkCellArray()
cells.SetData(numpy_to_vtkIdTypeArray(np.arange(0, 4 * len(keep) + 1, 4, dtype=np.int64), deep=True),
              numpy_to_vtkIdTypeArray(inverse.reshape(-1).astype(np.int64), deep=True))
out.SetCells(VTK_TETRA, cells)
s = grid.GetPointData().GetScalars()
values = numpy_to_vtk(vtk_to_numpy(s)[ids].copy(), deep=True)
values.SetName(s.GetName() or 'scalars')
out.GetPointData().SetScalars(values)
data = os.path.join(HERE, '..', '..', 'Data')
writer = vtkXMLUnstructuredGridWriter()
writer.SetFileName(os.path.join(data, 'near_degenerate_ray.vtu'))
writer.SetInputData(out)
writer.SetDataModeToBinary()
writer.Write()
with open(os.path.join(data, 'near_degenerate_ray.json'), 'w') as f:
    json.dump({'tetrahedra_of_the_block': grid.GetNumberOfCells(), 'cubes': CUBES, 'size': SIZE,
               'pixel': PIXEL, 'position': camera.GetPosition(),
               'focal_point': camera.GetFocalPoint(), 'view_up': camera.GetViewUp(),
               'view_angle': camera.GetViewAngle(), 'clipping_range': camera.GetClippingRange(),
               'scalar_range': s.GetRange(), 'length': grid.GetLength()}, f, indent=1)
print('kept %d of %d tetrahedra' % (len(keep), grid.GetNumberOfCells()))
