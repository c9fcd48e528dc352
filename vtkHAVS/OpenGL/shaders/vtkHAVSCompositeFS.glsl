#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: composites the volume's premultiplied result over VTK's
// framebuffer (blend ONE, ONE_MINUS_SRC_ALPHA set by the mapper). The one
// pass of all three mappers where the volume's shader property applies
// (vtkHAVSShaderHooks): its custom uniforms, the user's declarations and
// the user's exit code on g_fragColor, under vtkOpenGLGPUVolumeRayCastMapper's
// tag names.
layout(location = 0) out vec4 havsOut;

uniform sampler2D havsResultTexture;
uniform vec2 havsViewportOrigin;

//VTK::CustomUniforms::Dec

//VTK::Base::Dec

void main()
{
  vec4 g_fragColor =
    texelFetch(havsResultTexture, ivec2(gl_FragCoord.xy - havsViewportOrigin), 0);

  //VTK::Base::Exit

  havsOut = g_fragColor;
}
