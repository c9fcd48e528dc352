#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS k-buffer, fragment-list fallback (no framebuffer fetch, no
// interlock): draw pass. Every fragment is appended to its pixel's linked
// list (atomic node counter, atomic head exchange); nothing is composited
// here, so the arbitrary order in which fragments arrive does not matter.
// The resolve pass sorts each list exactly.
//HAVS::Defines
#define HAVS_FACE_PASS 1 // (the k-buffer library: a face pass, havsOnFace)
//HAVS::KBufferLib

in vec3 havsPositionRC;
HAVS_FACE_SCALAR_INPUT

uniform int havsNodeCapacity;
#if HAVS_ISO_SHADE
// Shaded isosurfaces: each node's interpolated point gradient beside it.
in vec3 havsGradient;
layout(std430, binding = 13) buffer HAVSListGradients
{
  vec4 havsNodeGradients[];
};
#endif

layout(r32ui, binding = 0) uniform coherent uimage2D havsListHeads;

layout(std430, binding = 1) buffer HAVSListNodes
{
  uvec4 havsNodes[]; // distance bits, code bits, next node, unused
};
layout(std430, binding = 2) buffer HAVSListCounter
{
  uint havsNodeCount;
};

void main()
{
  if (havsClipped(havsPositionRC))
  {
    discard;
  }
  HAVS_ENTRY f = havsFaceEntry(havsPositionRC, havsFaceScalar());
  uint node = atomicAdd(havsNodeCount, 1u);
  if (node < uint(havsNodeCapacity))
  {
    uint next = imageAtomicExchange(havsListHeads, ivec2(gl_FragCoord.xy), node);
    havsNodes[node] = uvec4(floatBitsToUint(f.x), floatBitsToUint(f.y), next, 0u);
#if HAVS_ISO_SHADE
    havsNodeGradients[node] = vec4(havsGradient, 0.0);
#endif
  }
}
