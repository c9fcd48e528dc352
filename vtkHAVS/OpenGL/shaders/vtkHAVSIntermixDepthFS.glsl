#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: a translucent layer's depth written into the copy of the opaque
// depth, under GL_LESS: the nearer of the two ends the volume's rays for one
// slab of the intermixed frame (vtkHAVSIntermixFS). No colour is written.
uniform sampler2D havsLayerDepth; // the viewport's size, window depth (1: no fragment)

void main()
{
  gl_FragDepth = texelFetch(havsLayerDepth, ivec2(gl_FragCoord.xy), 0).r;
}
