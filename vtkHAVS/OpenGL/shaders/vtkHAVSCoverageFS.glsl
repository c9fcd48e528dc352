#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: the level of detail's coverage mask, at every viewport pixel. A
// ray enters the volume only through a boundary face; one behind the opaque
// surface at its pixel lets no light through. So a pixel no fragment of this
// pass marks gets nothing from the volume in the exact image, and the
// composite keeps it empty instead of blurring the reduced image into it.
layout(location = 0) out vec4 havsCovered;

uniform sampler2D havsOpaqueDepth; // the viewport's opaque depth (full size)
uniform int havsCoverageOpaque;    // whether it holds this frame's opaque geometry

void main()
{
  if (havsCoverageOpaque != 0 &&
    gl_FragCoord.z > texelFetch(havsOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r)
  {
    discard;
  }
  havsCovered = vec4(1.0);
}
