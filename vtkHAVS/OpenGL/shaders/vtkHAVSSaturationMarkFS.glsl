#version 430 core
//HAVS::MarkExtension
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: marks the saturated pixels between batches of the face draw
// (vtkHAVSGLSaturationMask). Full viewport, colour writes off: a pixel whose
// ray has ended (havsRayEnded: opacity at the termination threshold, or an
// opaque surface reached) passes and its stencil becomes 1; every other
// pixel is discarded. The next batches' fragments at a marked pixel fail the
// early stencil test. The MarkLoad marker reads the pixel's colour and front
// entry the path's way.
//HAVS::Defines
//HAVS::KBufferLib

//HAVS::MarkDeclarations

void main()
{
  vec4 color;
  vec2 front;
  //HAVS::MarkLoad
  if (!havsRayEnded(color, front))
  {
    discard;
  }
}
