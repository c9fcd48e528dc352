#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSRayCastMapper: depth peeling of the boundary's entries (Bernardon et
// al. 2005, seed 002). One fragment of a front-facing boundary face (back
// faces culled): an entry into the mesh. A pass keeps, per pixel, the nearest
// entry beyond where the pixel's ray has already been (its ray state: the eye
// distance reached by the previous passes). Stage 0 takes the nearest
// distance (an atomic minimum of an order-preserving key), stage 1 the
// tetrahedron behind the face at that distance; the ray-casting pass
// (vtkHAVSRayCastFS) then walks from it.
//HAVS::Defines
//HAVS::KBufferLib

// The stencil test first: from the second pass on, only the tiles where a ray
// left the mesh in the last pass pass it (vtkOpenGLHAVSRayCastMapper), and a
// fragment that fails it must not touch the images.
layout(early_fragment_tests) in;

in vec3 havsPositionMC;
in vec3 havsPositionRC;

// The tetrahedron behind each boundary face (vtkHAVSRayCastMesh).
layout(std430, binding = 5) readonly buffer HAVSEntryCells
{
  uint havsEntryCells[];
};
// Per screen tile: the last pass (1-based) in which a ray started there.
layout(std430, binding = 8) buffer HAVSTiles
{
  uint havsTiles[];
};
uniform ivec2 havsTileCount;
uniform int havsTileSize;
uniform int havsPass; // this pass, 1-based

layout(binding = 0, r32ui) uniform coherent uimage2D havsEntryKey;
layout(binding = 1, r32ui) uniform coherent uimage2D havsEntryCell;
// The ray: the eye distance it has reached, its opacity, the distance of its
// last entry.
layout(binding = 2, rgba32f) uniform readonly image2D havsRayState;

uniform int havsPeelStage;        // 0: the nearest key; 1: the cell at it
uniform float havsPeelTolerance;  // relative: how far before the reach an entry may lie

layout(location = 0) out vec4 havsUnused; // (colour writes masked)

// Floats to unsigned integers in the same order (negative ones too).
uint havsOrderedKey(float d)
{
  uint b = floatBitsToUint(d);
  return (b & 0x80000000u) != 0u ? ~b : (b | 0x80000000u);
}

void main()
{
  havsUnused = vec4(0.0);
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 ray = imageLoad(havsRayState, pixel);
  float d = havsDistance(havsPositionRC);
  // Beyond the last entry (strictly: every pass moves the ray on), and not
  // before where the ray left the mesh, up to rounding: an entry that
  // coincides with the exit (a seam of duplicated points, the far side of a
  // dropped flat cell) is taken. An ended ray has reached HAVS_EMPTY.
  if (!(d > ray.z && d >= ray.x - havsPeelTolerance * abs(ray.x)))
  {
    return;
  }
  uint key = havsOrderedKey(d);
  if (havsPeelStage == 0)
  {
    imageAtomicMin(havsEntryKey, pixel, key);
  }
  else if (imageLoad(havsEntryKey, pixel).x == key)
  {
    // (Several faces at the same key: an edge; any of them is an entry.)
    imageStore(havsEntryCell, pixel, uvec4(havsEntryCells[gl_PrimitiveID] + 1u));
    ivec2 tile = pixel / havsTileSize;
    havsTiles[tile.y * havsTileCount.x + tile.x] = uint(havsPass);
  }
}
