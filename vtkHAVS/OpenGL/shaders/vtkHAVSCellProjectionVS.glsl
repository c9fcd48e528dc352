#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSCellProjectionMapper: vertex shader of the cells' faces. The
// fragment shader needs the position in model coordinates (where the cells'
// planes and fields are) and relative to the eye (its distance).
//
// The cells' corners are pulled (havsPullVertices): vertex 4 i + k of the
// draw (gl_VertexID, the base vertex included) is corner k of the cell at
// position i of the order, its point read from the tetrahedra's point ids,
// corners 2 and 3 swapped on a mirrored tetrahedron (negative volume in its
// vertex order, vtkHAVSCellGeometry::ComputeMirrored), so that one pattern of
// indices winds every cell's faces outward (vtkOpenGLHAVSCellProjectionMapper)
// and no index buffer in draw order (48 bytes a tetrahedron, made again for
// every view) exists. The near plane's section (havsPullVertices 0) comes as
// vertices.
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
    int slot = gl_VertexID >> 2;
    uint corner = uint(gl_VertexID & 3);
    uint cell = havsCellOrder[slot];
    bool mirrored = ((havsMirrored[cell >> 5u] >> (cell & 31u)) & 1u) != 0u;
    corner = mirrored && corner >= 2u ? 5u - corner : corner;
    uint id = havsTetrahedra[4u * cell + corner];
    position = vec3(havsPoints[3u * id], havsPoints[3u * id + 1u], havsPoints[3u * id + 2u]);
  }
  havsPositionMC = position;
  havsPositionRC = (havsMCRC * vec4(position, 1.0)).xyz;
  gl_Position = havsMCDC * vec4(position, 1.0);
}
