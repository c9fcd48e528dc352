#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: vertex shader of every pass that rasterizes the mesh faces.
//
// Coordinates: MC = the mapper's model coordinates (input points shifted by
// the bounds centre, float); RC = world coordinates relative to the eye
// (world minus camera position, computed in double on the CPU so that huge
// coordinates keep their precision); DC = clip coordinates.
//HAVS::Defines
#ifndef HAVS_CELL_SCALARS
#define HAVS_CELL_SCALARS 0
#endif
layout(location = 0) in vec3 vertexMC;
#if HAVS_CELL_SCALARS
// Cell scalars: every face has vertices of its own carrying (the value of the
// cell its normal points into, the value of the cell on the other side); the
// fragment shader picks the cell behind the fragment by its facing.
layout(location = 1) in vec2 cellScalarsNormalized;
flat out vec2 havsCellScalars;
#else
layout(location = 1) in float scalarNormalized; // the point scalar mapped to [0, 1] over the table range
out float havsScalar;
#endif
#if HAVS_ISO_SHADE
// Shaded isosurfaces: the point's gradient (vtkHAVSPointGradients), interpolated
// over the face as the point gradients are inside a tetrahedron.
layout(location = 2) in vec3 gradientMC;
out vec3 havsGradient;
#endif

uniform mat4 havsMCRC; // model -> eye-relative world (volume matrix included)
uniform mat4 havsMCDC; // model -> clip

out vec3 havsPositionRC;

void main()
{
  havsPositionRC = (havsMCRC * vec4(vertexMC, 1.0)).xyz;
#if HAVS_CELL_SCALARS
  havsCellScalars = cellScalarsNormalized;
#else
  havsScalar = scalarNormalized;
#endif
#if HAVS_ISO_SHADE
  havsGradient = gradientMC;
#endif
  gl_Position = havsMCDC * vec4(vertexMC, 1.0);
}
