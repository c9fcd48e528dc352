#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSCellProjectionMapper: one fragment of a cell's front face (back
// faces are culled). The ray enters the cell here; it leaves through the
// nearest of the cell's face planes it moves towards (Weiler, Kraus and Ertl
// 2002, here for perspective and parallel cameras). The scalars at both ends
// come from the cell's linear field, the segment from the pre-integration
// table (havsSegment of the k-buffer library), and blending composites it
// front to back (the cells arrive in the exact order).
//HAVS::Defines
//HAVS::KBufferLib

in vec3 havsPositionMC;
in vec3 havsPositionRC;

// Per tetrahedron (vtkHAVSCellGeometry): 4 outward face planes, then the
// field's gradient and offset, all in model coordinates.
layout(std430, binding = 4) readonly buffer HAVSCells
{
  vec4 havsCells[];
};
// The tetrahedron of each drawn position (4 faces each): the cell order.
layout(std430, binding = 5) readonly buffer HAVSCellOrder
{
  uint havsCellOrder[];
};

uniform vec3 havsEyeMC;        // the eye in model coordinates
uniform vec3 havsDirectionMC;  // the direction of projection in model coordinates
uniform mat3 havsModelToWorld; // the volume matrix's linear part (lengths in world units)
uniform int havsWrongExit;     // testing aid: leave through the farthest plane

layout(location = 0) out vec4 havsSegmentColor;

void main()
{
  int base = int(havsCellOrder[gl_PrimitiveID / 4]) * 5;
  vec3 p = havsPositionMC;
  vec3 d = havsParallel != 0 ? havsDirectionMC : p - havsEyeMC;
  float tExit = HAVS_EMPTY;
  float tFarthest = 0.0;
  for (int j = 0; j < 4; ++j)
  {
    vec4 plane = havsCells[base + j];
    float towards = dot(plane.xyz, d);
    if (towards > 0.0)
    {
      float t = -(dot(plane.xyz, p) + plane.w) / towards;
      tExit = min(tExit, t);
      tFarthest = max(tFarthest, t);
    }
  }
  if (havsWrongExit != 0)
  {
    tExit = tFarthest;
  }
  if (tExit >= HAVS_EMPTY)
  {
    discard;
  }
  // The segment [tEnter, tExit] of the ray in the cell, clipped to the near
  // and clipping planes (eye-relative world coordinates, kept where
  // dot(n, x) + w >= 0): where a plane cuts the cell the ray starts (or
  // stops) on it, with no section to draw.
  vec3 dWorld = havsModelToWorld * d;
  float tEnter = 0.0;
  tExit = max(tExit, 0.0);
  for (int i = 0; i < havsPlaneCount; ++i)
  {
    float atEntry = dot(havsPlanesRC[i].xyz, havsPositionRC) + havsPlanesRC[i].w;
    float rate = dot(havsPlanesRC[i].xyz, dWorld);
    if (rate > 0.0)
    {
      tEnter = max(tEnter, -atEntry / rate);
    }
    else if (rate < 0.0)
    {
      tExit = min(tExit, -atEntry / rate);
    }
    else if (atEntry < 0.0)
    {
      discard;
    }
  }
  if (!(tExit > tEnter))
  {
    discard;
  }
  vec4 field = havsCells[base + 4];
  float sFront = clamp(dot(field.xyz, p + tEnter * d) + field.w, 0.0, 1.0);
  float sBack = clamp(dot(field.xyz, p + tExit * d) + field.w, 0.0, 1.0);
  float len = (tExit - tEnter) * length(dWorld);
#if HAVS_OPAQUE
  // Opaque geometry ends the ray: nothing behind it, the last segment cut.
  float front = havsDistance(havsPositionRC + tEnter * dWorld);
  float opaque = havsOpaqueDistance(gl_FragCoord.xy);
  if (front >= opaque)
  {
    discard;
  }
  if (front + len > opaque && len > 0.0)
  {
    sBack = mix(sFront, sBack, (opaque - front) / len);
    len = opaque - front;
  }
#endif
  havsSegmentColor = havsSegment(vec2(0.0, sFront), vec2(len, sBack));
}
