#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: vertex shader of every pass that rasterizes the mesh faces.
//
// Coordinates: MC = the mapper's model coordinates (input points shifted by
// the bounds centre, float); RC = world coordinates relative to the eye
// (world minus camera position, computed in double on the CPU so that huge
// coordinates keep their precision); DC = clip coordinates.
layout(location = 0) in vec3 vertexMC;
layout(location = 1) in float scalarNormalized; // the point scalar mapped to [0, 1] over the table range

uniform mat4 havsMCRC; // model -> eye-relative world (volume matrix included)
uniform mat4 havsMCDC; // model -> clip

out vec3 havsPositionRC;
out float havsScalar;

void main()
{
  havsPositionRC = (havsMCRC * vec4(vertexMC, 1.0)).xyz;
  havsScalar = scalarNormalized;
  gl_Position = havsMCDC * vec4(vertexMC, 1.0);
}
