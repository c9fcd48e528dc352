# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""A saved ray case for the tests (Data/NAME.vtu and NAME.json): the cells around one pixel's
ray and the view it was seen in (size, pixel, camera with its clipping range), drawn in a
headless window and compared with the exact reference (TestHAVSNearDegenerateRay,
TestHAVSFoldCornerRay)."""
import json
import os

from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkVolume

import vtkhavs

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'Data')
failures = []


def check(condition, what):
    print(('' if condition else 'CHECK FAILED: ') + what, flush=True)
    if not condition:
        failures.append(what)


class SavedRay:
    """Data/`name`.*: `grid`, `view` (the .json), `size`, `pixel`; a window of that size whose
    renderer holds `volume` with `prop`, its `camera` placed by place()."""

    def __init__(self, name, make_property):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(DATA, name + '.vtu'))
        reader.Update()
        self.grid = reader.GetOutput()
        with open(os.path.join(DATA, name + '.json')) as f:
            self.view = json.load(f)
        self.size = self.view['size']
        self.pixel = self.view['pixel']
        self.prop = make_property(self.grid, self.view)
        self.window = vtkhavs.vtkHAVSRenderWindowFactory.CreateRenderWindow()
        self.window.SetSize(self.size, self.size)
        renderer = vtkRenderer()
        self.window.AddRenderer(renderer)
        self.volume = vtkVolume()
        self.volume.SetProperty(self.prop)
        renderer.AddVolume(self.volume)
        self.camera = renderer.GetActiveCamera()
        self.place(0.0)

    def place(self, turn):
        """The saved camera, turned `turn` degrees about the view up (azimuth)."""
        view, camera = self.view, self.camera
        camera.SetPosition(*view['position'])
        camera.SetFocalPoint(*view['focal_point'])
        camera.SetViewUp(*view['view_up'])
        camera.SetViewAngle(view['view_angle'])
        camera.Azimuth(turn)
        camera.SetClippingRange(*view['clipping_range'])

    def exact(self):
        """The exact reference of the camera as placed (premultiplied RGBA floats)."""
        reference = vtkhavs.vtkHAVSReferenceRenderer()
        reference.SetInputData(self.grid)
        reference.SetProperty(self.prop)
        reference.SetCamera(self.camera)
        reference.SetSize(self.size, self.size)
        check(reference.Render(), 'the exact reference renders')
        image = vtkFloatArray()
        image.DeepCopy(reference.GetImage())
        return image

    def draw(self, mapper):
        """`mapper`'s float result of the camera as placed; None without one of the size."""
        mapper.SetInputData(self.grid)
        mapper.KeepFloatResultOn()
        self.volume.SetMapper(mapper)
        self.window.Render()
        image = vtkFloatArray()
        dims = [0, 0]
        ok = mapper.GetFloatResult(image, dims) and dims == [self.size, self.size]
        return image if ok else None

    def at(self, image):
        """The saved pixel's RGBA in `image`."""
        px, py = self.pixel
        first = 4 * (py * self.size + px)
        return [image.GetValue(first + c) for c in range(4)]
