#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSCellProjectionMapper: vertex shader of the cells' faces. The
// fragment shader needs the position in model coordinates (where the cells'
// planes and fields are) and relative to the eye (its distance).
layout(location = 0) in vec3 vertexMC;

uniform mat4 havsMCRC; // model -> eye-relative world (volume matrix included)
uniform mat4 havsMCDC; // model -> clip

out vec3 havsPositionMC;
out vec3 havsPositionRC;

void main()
{
  havsPositionMC = vertexMC;
  havsPositionRC = (havsMCRC * vec4(vertexMC, 1.0)).xyz;
  gl_Position = havsMCDC * vec4(vertexMC, 1.0);
}
