#version 450 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
//HAVS::InterlockExtension
// vtkHAVS k-buffer, fragment-shader-interlock path (NVIDIA): draw pass.
// The colour and the k entries of every pixel live in a shader storage buffer;
// the read-modify-write runs inside an *ordered* pixel interlock, so fragments
// of one pixel are processed one at a time in primitive order.
//HAVS::Defines
#define HAVS_FACE_PASS 1 // (the k-buffer library: a face pass, havsOnFace)
//HAVS::KBufferLib

//HAVS::InterlockLayout
// Saturated pixels are rejected before the shader (vtkHAVSGLSaturationMask:
// stencil test between batches); no depth or stencil is written here.
layout(early_fragment_tests) in;

in vec3 havsPositionRC;
HAVS_FACE_SCALAR_INPUT


layout(std430, binding = 0) buffer HAVSPixelEntries
{
  vec4 havsPixelData[]; // per pixel: colour, then HAVS_K entries (2 per vec4)
};

void main()
{
  float tolerance = havsTieTolerance(havsPositionRC);
  havsCountShaded();
  if (havsClipped(havsPositionRC))
  {
    discard;
  }
  vec2 f = havsFaceEntry(havsPositionRC, havsFaceScalar());
  float opaqueDistance = havsOpaqueDistance(gl_FragCoord.xy);
  int base = (int(gl_FragCoord.y) * int(havsViewportSize.x) + int(gl_FragCoord.x)) * HAVS_PIXEL_STRIDE;

  //HAVS::InterlockBegin
  vec4 color = havsPixelData[base];
  vec2 E[HAVS_K];
  for (int i = 0; i < HAVS_K; ++i)
  {
    vec4 pair = havsPixelData[base + 1 + i / 2];
    E[i] = (i % 2 == 0) ? pair.xy : pair.zw;
  }
  if (!havsRayEnded(color, E[0]))
  {
    havsInsert(color, E, f, opaqueDistance, tolerance);
    havsPixelData[base] = color;
    for (int i = 0; i < HAVS_K; i += 2)
    {
      havsPixelData[base + 1 + i / 2] = vec4(E[i], (i + 1 < HAVS_K) ? E[i + 1] : vec2(HAVS_EMPTY, 0.0));
    }
  }
  //HAVS::InterlockEnd
}
