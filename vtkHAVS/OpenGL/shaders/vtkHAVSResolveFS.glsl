#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
//HAVS::ResolveExtension
// vtkHAVS: per-pixel pass after the faces. Reads what the draw pass left for
// this pixel (the ResolveLoad marker differs per path), lets the waiting
// entries leave in depth order (flush) and writes the premultiplied result
// into the result texture.
//HAVS::Defines
//HAVS::KBufferLib

//HAVS::ResolveDeclarations

layout(location = 0) out vec4 havsResult;

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float opaqueDistance = havsOpaqueDistance(gl_FragCoord.xy);
  vec4 color = vec4(0.0);
  HAVS_ENTRY E[HAVS_K];
#if HAVS_ISO_SHADE == 2
  havsShadeToEye = havsPixelToEye(gl_FragCoord.xy);
#endif
  //HAVS::ResolveLoad
#ifdef HAVS_BACK_TO_FRONT
  havsFlushBackToFront(color, E, opaqueDistance);
#else
  if (!havsRayEnded(color, E[0]))
  {
    havsFlush(color, E, opaqueDistance);
  }
#endif
  havsResult = color;
}
