// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: the cell optics of cell scalars (vtkHAVSCellOptics), shared by the
// k-buffer library and the extremum resolve (inserted at the CellOpticsLib
// marker). A cell's scalar is its code, index * 2^-HAVS_CELL_CODE_BITS (exact
// in a float, with the k-buffer's tags + 2, + 4 too; HAVS_CELL_CODE_BITS is
// vtkHAVSCellOptics::CodeBits, defined by vtkHAVSShaders), the index of
// the cell's value among the mesh's distinct cell values; havsCellOptics
// holds the transfer function at each value: (r, g, b, tau), (s, opacity,
// tau s, 0).
uniform samplerBuffer havsCellOptics;

// The value index of a code, clamped to the values uploaded (a placeholder of
// one transparent value where they do not fit the context, vtkHAVSGLTable).
int havsCellIndex(float code)
{
  return min(int(ldexp(code, HAVS_CELL_CODE_BITS) + 0.5), textureSize(havsCellOptics) / 2 - 1);
}
