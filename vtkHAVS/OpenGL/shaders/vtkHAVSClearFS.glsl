#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: clears the per-pixel k-buffer storage of the interlock path
// (colour 0, no front, every waiting slot empty).
//HAVS::Defines
//HAVS::KBufferLib

layout(std430, binding = 0) buffer HAVSPixelEntries
{
  vec4 havsPixelData[];
};

void main()
{
  int base = (int(gl_FragCoord.y) * int(havsViewportSize.x) + int(gl_FragCoord.x)) * HAVS_PIXEL_STRIDE;
  havsPixelData[base] = vec4(0.0);
  for (int i = 0; i < HAVS_K; i += 2)
  {
    vec2 first = (i == 0) ? vec2(HAVS_NO_FRONT, 0.0) : vec2(HAVS_EMPTY, 0.0);
    havsPixelData[base + 1 + i / 2] = vec4(first, HAVS_EMPTY, 0.0);
  }
}
