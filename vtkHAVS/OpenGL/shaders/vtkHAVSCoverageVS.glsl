#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: the mesh's boundary faces for the level of detail's coverage mask
// (vtkHAVSGLFrameTargets::SetCoverage): positions only, model coordinates.
layout(location = 0) in vec3 vertexMC;

uniform mat4 havsMCDC; // model -> clip

void main()
{
  gl_Position = havsMCDC * vec4(vertexMC, 1.0);
}
