#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: composites the volume's premultiplied result over VTK's
// framebuffer (blend ONE, ONE_MINUS_SRC_ALPHA set by the mapper).
layout(location = 0) out vec4 havsOut;

uniform sampler2D havsResultTexture;
uniform vec2 havsViewportOrigin;

void main()
{
  havsOut = texelFetch(havsResultTexture, ivec2(gl_FragCoord.xy - havsViewportOrigin), 0);
}
