#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSRayCastMapper: the screen tiles of the ray-casting pass (Bernardon
// et al. 2005, seed 002). One instance per tile, two triangles each
// (gl_VertexID 0..5); a tile in which the peeling found no entry this pass
// collapses to a point (no fragment): the ray-casting pass works only where
// the mesh projects and rays are still going. No vertex buffer. Also the
// stencil of the tiles a later peeling pass draws (the buffer at binding 8
// then holds, per tile, the pass that must peel there).
layout(std430, binding = 8) readonly buffer HAVSTiles
{
  uint havsTiles[]; // per tile: the last pass (1-based) in which a ray started there
};

uniform ivec2 havsTileCount;
uniform int havsTileSize;
uniform vec2 havsViewportSize;
uniform int havsPass; // this pass, 1-based

void main()
{
  int tile = gl_InstanceID;
  if (havsTiles[tile] != uint(havsPass))
  {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // (all three corners: no area)
    return;
  }
  const vec2 corners[6] =
    vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
  vec2 pixel = (vec2(tile % havsTileCount.x, tile / havsTileCount.x) + corners[gl_VertexID]) *
    float(havsTileSize);
  pixel = min(pixel, havsViewportSize);
  gl_Position = vec4(pixel / havsViewportSize * 2.0 - 1.0, 0.0, 1.0);
}
