#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: one peeled translucent layer composited over the window (blend
// ONE, ONE_MINUS_SRC_ALPHA; the layers drawn back to front): the translucent
// scene where no volume intermixed it (vtkHAVSTranslucentLayers).
layout(location = 0) out vec4 havsOut;

uniform sampler2D havsLayerColor; // colour (not premultiplied), opacity
uniform vec2 havsViewportOrigin;

void main()
{
  vec4 layer = texelFetch(havsLayerColor, ivec2(floor(gl_FragCoord.xy - havsViewportOrigin)), 0);
  float a = clamp(layer.a, 0.0, 1.0);
  havsOut = vec4(layer.rgb * a, a);
}
