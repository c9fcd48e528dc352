#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// The cheapest fragment shader: a benchmark aid, to time the faces'
// rasterization alone (the lower bound of any face-based method); and the
// ray caster's tile stencil (drawn with no colour attachment).
layout(location = 0) out vec4 havsCount;

void main()
{
  havsCount = vec4(1.0 / 255.0);
}
