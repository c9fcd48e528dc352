# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
"""Converts an X window dump (xwd -root, 24/32-bit TrueColor, ZPixmap) to PNG with VTK.

Usage: xwd_to_png.py IN.xwd OUT.png [X,Y,W,H]  (a crop, Y from the top)."""
import struct
import sys

from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

data = open(sys.argv[1], "rb").read()
header = struct.unpack(">25I", data[:100])
header_size, width, height = header[0], header[4], header[5]
byte_order, bits_per_pixel, bytes_per_line = header[7], header[11], header[12]
ncolors = header[19]
offset = header_size + ncolors * 12
step = bits_per_pixel // 8
pixels = vtkUnsignedCharArray()
pixels.SetNumberOfComponents(3)
pixels.SetNumberOfTuples(width * height)
for y in range(height):
    row = data[offset + y * bytes_per_line: offset + (y + 1) * bytes_per_line]
    out_row = height - 1 - y  # VTK images start at the bottom
    for x in range(width):
        p = row[x * step: x * step + step]
        b, g, r = (p[0], p[1], p[2]) if byte_order == 0 else (p[-1], p[-2], p[-3])
        pixels.SetTuple3(out_row * width + x, r, g, b)
image = vtkImageData()
image.SetDimensions(width, height, 1)
image.GetPointData().SetScalars(pixels)
writer = vtkPNGWriter()
writer.SetFileName(sys.argv[2])
if len(sys.argv) > 3:
    from vtkmodules.vtkImagingCore import vtkExtractVOI

    x, y, w, h = (int(v) for v in sys.argv[3].split(","))
    crop = vtkExtractVOI()
    crop.SetInputData(image)
    crop.SetVOI(x, x + w - 1, height - y - h, height - 1 - y, 0, 0)
    writer.SetInputConnection(crop.GetOutputPort())
else:
    writer.SetInputData(image)
writer.Write()
