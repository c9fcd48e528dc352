#version 430 core
#extension GL_EXT_shader_framebuffer_fetch : require
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS k-buffer, framebuffer-fetch path: draw pass.
// The colour and the k entries live in RGBA32F colour attachments that the
// shader reads (inout, coherent framebuffer fetch) and writes back; fetch is
// ordered by primitive within the draw call, so the read-modify-write is
// race-free. Attachment 0: premultiplied colour; attachment 1 + i/2 holds
// entries 2i', 2i'+1 (xy, zw).
//HAVS::Defines
#define HAVS_FACE_PASS 1 // (the k-buffer library: a face pass, havsOnFace)
//HAVS::KBufferLib

in vec3 havsPositionRC;
HAVS_FACE_SCALAR_INPUT

//HAVS::FetchDeclarations
// Saturated pixels are rejected before the shader (vtkHAVSGLSaturationMask:
// stencil test between batches); no depth or stencil is written here.
layout(early_fragment_tests) in;

void main()
{
  float tolerance = havsTieTolerance(havsPositionRC);
  havsCountShaded();
  vec4 color = havsColor;
  vec2 E[HAVS_K];
  //HAVS::FetchLoad
  if (havsRayEnded(color, E[0]))
  {
    discard;
  }
  if (havsClipped(havsPositionRC))
  {
    discard;
  }
  vec2 f = havsFaceEntry(havsPositionRC, havsFaceScalar());
  havsInsert(color, E, f, havsOpaqueDistance(gl_FragCoord.xy), tolerance);
  havsColor = color;
  //HAVS::FetchStore
}
