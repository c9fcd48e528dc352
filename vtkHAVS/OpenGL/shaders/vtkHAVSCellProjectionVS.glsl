#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSCellProjectionMapper: vertex shader of the cells' faces. The
// fragment shader needs the position in model coordinates (where the cells'
// planes and fields are) and relative to the eye (its distance).
//
// The cells' faces are pulled, not indexed (havsPullVertices): vertex i of
// the draw is corner i % 3 of face (i / 3) % 4 of the cell at position i / 12
// of the order, its point read from the tetrahedra's point ids, so that no
// index buffer in draw order (48 bytes a tetrahedron, made again for every
// view) exists. Face j's corners are vertices (j+1, j+2, j+3) mod 4, the last
// two swapped for even j on a mirrored tetrahedron and for odd j on another
// (vtkHAVSCellGeometry::FaceCorners): counter-clockwise seen from outside.
// The near plane's section (havsPullVertices 0) comes as vertices.
layout(location = 0) in vec3 vertexMC;

layout(std430, binding = 5) readonly buffer HAVSCellOrder
{
  uint havsCellOrder[];
};
layout(std430, binding = 6) readonly buffer HAVSTetrahedra
{
  uint havsTetrahedra[]; // 4 point ids each
};
layout(std430, binding = 7) readonly buffer HAVSMirrored
{
  uint havsMirrored[]; // bit t % 32 of word t / 32: tetrahedron t is mirrored
};
layout(std430, binding = 8) readonly buffer HAVSPoints
{
  float havsPoints[]; // 3 each
};

uniform int havsPullVertices;
uniform mat4 havsMCRC; // model -> eye-relative world (volume matrix included)
uniform mat4 havsMCDC; // model -> clip

out vec3 havsPositionMC;
out vec3 havsPositionRC;

void main()
{
  vec3 position = vertexMC;
  if (havsPullVertices != 0)
  {
    int slot = gl_VertexID / 12;
    int corner = gl_VertexID - 12 * slot;
    int face = corner / 3;
    int k = corner - 3 * face;
    uint cell = havsCellOrder[slot];
    bool mirrored = ((havsMirrored[cell >> 5u] >> (cell & 31u)) & 1u) != 0u;
    bool swapped = ((face & 1) == 0) == mirrored;
    int vertex = face + (k == 0 ? 1 : (k == 1 ? (swapped ? 3 : 2) : (swapped ? 2 : 3)));
    uint id = havsTetrahedra[4u * cell + uint(vertex & 3)];
    position = vec3(havsPoints[3u * id], havsPoints[3u * id + 1u], havsPoints[3u * id + 2u]);
  }
  havsPositionMC = position;
  havsPositionRC = (havsMCRC * vec4(position, 1.0)).xyz;
  gl_Position = havsMCDC * vec4(position, 1.0);
}
