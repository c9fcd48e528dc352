#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSCellProjectionMapper: one fragment of a cell's front face (back
// faces are culled). The ray enters the cell here; it leaves through the
// nearest of the cell's face planes it moves towards (Weiler, Kraus and Ertl
// 2002, here for perspective and parallel cameras). The scalars at both ends
// come from the cell's linear field, the segment from the pre-integration
// table (havsSegment of the k-buffer library), and blending composites it
// front to back (the cells arrive in the exact order).
//
// The order-independent blends (HAVS_CELL_BLEND 1, 2: maximum and minimum
// intensity; 4: VTK's additive) need no order: the fragment writes the
// segment's extremal scalar (1 - s for the minimum) for GL_MAX blending, or
// its additive integral for GL_FUNC_ADD, with a coverage flag beside it; a
// resolve pass colours the pixel (vtkHAVSExtremumResolveFS).
//
// Near-plane sections (the camera inside the mesh): the same shader draws the
// triangles where the near plane cuts a cell (1 triangle per entry of the
// cell buffer instead of the faces' 4), the ray starting on them.
//HAVS::Defines
//HAVS::CellBlend
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
uniform int havsTrianglesPerCell; // 4: the cells' faces; 1: near-plane sections
uniform int havsFirstCell;        // the draw's first cell in the order (draws in pieces)
uniform int havsNearSectionDrawn; // 1: the near plane's section was drawn this frame
#if HAVS_CELL_BLEND == 4
//HAVS::AdditiveLib
#endif

layout(location = 0) out vec4 havsSegmentColor;

void main()
{
  int base = int(havsCellOrder[havsFirstCell + gl_PrimitiveID / havsTrianglesPerCell]) * 5;
  vec3 p = havsPositionMC;
  vec3 d = havsParallel != 0 ? havsDirectionMC : p - havsEyeMC;
  float tExit = HAVS_EMPTY;
  float tFarthest = 0.0;
  // A plane the ray runs along (a face seen edge-on: the eye in its plane,
  // its rays on the shared face of two cells) is no exit: in float its
  // 'towards' is rounding noise, and so would be the distance to it. The
  // noise of a three-term float dot product of a unit normal and d is at
  // most about 3 * 2^-24 |d|: the bound is twice that, so that a needle
  // (a face 1e6 times longer than wide, turned 1e-6 from the ray) still
  // has its exit.
  float parallelToRay = 4e-7 * length(d);
  for (int j = 0; j < 4; ++j)
  {
    vec4 plane = havsCells[base + j];
    float towards = dot(plane.xyz, d);
    if (towards > parallelToRay)
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
  // Where the near plane's section was drawn (plane 0 is then the near
  // plane) a face fragment in front of it is the section's: GL's near clip
  // lies a hair in front of the section, the faces between are left out.
  if (havsTrianglesPerCell == 4 && havsNearSectionDrawn != 0 &&
    dot(havsPlanesRC[0].xyz, havsPositionRC) + havsPlanesRC[0].w < 0.0)
  {
    discard;
  }
  float tEnter = 0.0;
  tExit = max(tExit, 0.0);
  if (!havsClipRay(havsPositionRC, dWorld, tEnter, tExit) || !(tExit > tEnter))
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
#if HAVS_CELL_BLEND == 1
  havsSegmentColor = vec4(max(sFront, sBack), 1.0, 0.0, 0.0);
#elif HAVS_CELL_BLEND == 2
  havsSegmentColor = vec4(1.0 - min(sFront, sBack), 1.0, 0.0, 0.0);
#elif HAVS_CELL_BLEND == 4
  havsSegmentColor = vec4(havsAdditiveSegment(sFront, sBack, len), 1.0, 0.0, 0.0);
#else
  havsSegmentColor = havsSegment(vec2(0.0, sFront), vec2(len, sBack));
#endif
}
