// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: the cells' records, read by the cell projection and the ray caster
// (vtkHAVSCellGeometry: per tetrahedron its four outward face planes, plane j
// opposite vertex j, then the field's gradient and offset, in model
// coordinates: 5 vec4). They lie in HAVS_CELL_BUFFERS storage buffers of
// havsCellsPerBuffer tetrahedra each, the last holding the rest
// (vtkHAVSGLCellRecords): a shader addresses one buffer with 32-bit byte
// offsets, and llvmpipe's shaders crash past 2 GiB (26.8 million
// tetrahedra's records). Inserted at the CellRecordsLib marker.
#ifndef HAVS_CELL_BUFFERS
#define HAVS_CELL_BUFFERS 1
#endif

layout(std430, binding = 4) readonly buffer HAVSCells
{
  vec4 havsCells0[];
};
#if HAVS_CELL_BUFFERS > 1
layout(std430, binding = 10) readonly buffer HAVSCells1
{
  vec4 havsCells1[];
};
uniform int havsCellsPerBuffer;
#endif
#if HAVS_CELL_BUFFERS > 2
layout(std430, binding = 11) readonly buffer HAVSCells2
{
  vec4 havsCells2[];
};
#endif
#if HAVS_CELL_BUFFERS > 3
layout(std430, binding = 12) readonly buffer HAVSCells3
{
  vec4 havsCells3[];
};
#endif

// Record j of tetrahedron `cell`: 0 to 3 its face plane j (unit outward
// normal, offset), 4 its field (gradient, offset).
vec4 havsCell(int cell, int j)
{
#if HAVS_CELL_BUFFERS > 1
  int piece = cell / havsCellsPerBuffer;
  int i = 5 * (cell - piece * havsCellsPerBuffer) + j;
#if HAVS_CELL_BUFFERS > 3
  if (piece == 3)
  {
    return havsCells3[i];
  }
#endif
#if HAVS_CELL_BUFFERS > 2
  if (piece == 2)
  {
    return havsCells2[i];
  }
#endif
  return piece == 1 ? havsCells1[i] : havsCells0[i];
#else
  return havsCells0[5 * cell + j];
#endif
}
