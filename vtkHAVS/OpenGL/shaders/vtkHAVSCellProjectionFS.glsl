#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSCellProjectionMapper: one fragment of a cell's front face (back
// faces are culled). The pixel's ray enters the cell through the farthest
// of the cell's face planes it moves away from and leaves through the
// nearest it moves towards (Weiler, Kraus and Ertl 2002, here for perspective
// and parallel cameras). The scalars at both ends
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

//HAVS::CellRecordsLib
// The tetrahedron of each drawn position (4 faces each): the cell order.
layout(std430, binding = 5) readonly buffer HAVSCellOrder
{
  uint havsCellOrder[];
};

uniform vec3 havsEyeMC;        // the eye in model coordinates
uniform mat3 havsRCMC;         // eye-relative world -> model, the linear part
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
  int cell = int(havsCellOrder[havsFirstCell + gl_PrimitiveID / havsTrianglesPerCell]);
  // The pixel's ray o + t d in model coordinates, through the pixel's centre
  // (t = 0 at the eye, or on the near plane for a parallel camera), and the
  // rasterizer's tolerance across it at t: 1/256 pixel (vertices are snapped
  // to sub-pixel units), from the spacing of the pixels' rays.
  // (Through eye-relative coordinates: far from the model's origin the near
  // plane's point in model coordinates minus the eye would lose the
  // direction to rounding; measured on a needle 3e6 long, 3 wide.)
  vec2 ndc = gl_FragCoord.xy / havsViewportSize * 2.0 - 1.0;
  vec4 nearRC = havsDCRC * vec4(ndc, -1.0, 1.0);
  vec3 toNearRC = nearRC.xyz / nearRC.w;
  vec3 toNear = havsRCMC * toNearRC;
  vec3 o = havsParallel != 0 ? havsEyeMC + toNear : havsEyeMC;
  vec3 d = havsParallel != 0 ? havsDirectionMC : toNear;
  // The same ray in eye-relative world coordinates: oRC + t dRC.
  vec3 oRC = havsParallel != 0 ? toNearRC : vec3(0.0);
  vec3 dRC = havsParallel != 0 ? havsModelToWorld * havsDirectionMC : toNearRC;
  vec3 spacing0 = max(abs(dFdx(o)), abs(dFdy(o)));
  vec3 spacingPerT = max(abs(dFdx(d)), abs(dFdy(d)));
  // The face this fragment is of: the cell's triangle j is its face plane j
  // (-1: a near-plane section).
  int own = havsTrianglesPerCell == 4 ? gl_PrimitiveID % 4 : -1;
  // The ray meets the cell where it is inside all four face planes: from the
  // farthest plane it enters by to the nearest it leaves by (Weiler, Kraus and
  // Ertl's exit, and the entry found the same way, not taken as the
  // fragment's position: at a pixel centre within snapping distance of a
  // face's edge the rasterizer may cover it with a face of this cell that the
  // exact ray crosses outside the cell, or with a cell the exact ray misses).
  //
  // A plane the ray runs along within the rasterizer's tolerance over the
  // whole stretch (a face seen almost edge-on, the eye within a hair of its
  // plane) does not bound the stretch: which side of it the ray lies on, the
  // rasterizer decided when it covered the pixel with this cell, its
  // neighbour across that face, or both (then this cell's own face is that
  // face, a sliver: its fragment is left out, the neighbour has the stretch).
  // (Before: the entry taken as the fragment's position and the exit from
  // every plane the ray moves towards; the 49.7M block at 256^2 had a ray
  // within 1e-4 px of such faces that came out 0.012 too opaque.)
  float f[4], towards[4];
  for (int j = 0; j < 4; ++j)
  {
    vec4 plane = havsCell(cell, j);
    f[j] = dot(plane.xyz, o) + plane.w;
    towards[j] = dot(plane.xyz, d);
  }
  // Exactly parallel to the ray: |towards| below float noise, at most about
  // 3 * 2^-24 |d| for a three-term dot product of a unit normal and d (the
  // bound is twice that, so that a needle, a face 1e6 times longer than wide
  // turned 1e-6 from the ray, still bounds it): the plane keeps the ray only
  // on its inner side. Almost parallel (below 1e-2: 0.6 degrees), the plane
  // is looked at after the others have bounded the stretch.
  float parallelToRay = 4e-7 * length(d);
  float grazing = 1e-2 * length(d);
  float tEnter = -HAVS_EMPTY;
  float tExit = HAVS_EMPTY;
  float tFarthest = 0.0;
  bool outside = own >= 0 && !(towards[own] < -parallelToRay); // (its face seen from behind)
  for (int pass = 0; pass < 2; ++pass)
  {
    for (int j = 0; j < 4; ++j)
    {
      if ((abs(towards[j]) < grazing) != (pass == 1))
      {
        continue;
      }
      if (pass == 1 &&
        abs(f[j] + towards[j] * tEnter) < length(spacing0 + tEnter * spacingPerT) / 256.0 &&
        abs(f[j] + towards[j] * tExit) < length(spacing0 + tExit * spacingPerT) / 256.0)
      {
        outside = outside || j == own;
        continue;
      }
      float t = -f[j] / towards[j];
      if (towards[j] > parallelToRay)
      {
        tExit = min(tExit, t);
        tFarthest = max(tFarthest, t);
      }
      else if (towards[j] < -parallelToRay)
      {
        tEnter = max(tEnter, t);
      }
      else
      {
        outside = outside || f[j] > 0.0;
      }
    }
  }
  // A near-plane section: the ray starts on it (where the fragment is).
  tEnter = own < 0 ? max(tEnter, dot(havsPositionMC - o, d) / dot(d, d)) : tEnter;
  if (outside || tEnter <= -HAVS_EMPTY)
  {
    discard;
  }
  if (havsWrongExit != 0)
  {
    tExit = tFarthest;
  }
  if (tExit >= HAVS_EMPTY)
  {
    discard;
  }
  // Where the near plane's section was drawn (plane 0 is then the near
  // plane) a face fragment in front of it is the section's: GL's near clip
  // lies a hair in front of the section, the faces between are left out.
  if (havsTrianglesPerCell == 4 && havsNearSectionDrawn != 0 &&
    dot(havsPlanesRC[0].xyz, havsPositionRC) + havsPlanesRC[0].w < 0.0)
  {
    discard;
  }
  // The segment [tEnter, tExit] of the ray in the cell, clipped to the near
  // and clipping planes (eye-relative world coordinates, kept where
  // dot(n, x) + w >= 0): where a plane cuts the cell the ray starts (or
  // stops) on it, with no section to draw.
  if (!havsClipRay(oRC, dRC, tEnter, tExit) || !(tExit > tEnter))
  {
    discard;
  }
  vec4 field = havsCell(cell, 4);
  float sFront = clamp(dot(field.xyz, o + tEnter * d) + field.w, 0.0, 1.0);
  float sBack = clamp(dot(field.xyz, o + tExit * d) + field.w, 0.0, 1.0);
  float len = (tExit - tEnter) * length(dRC);
#if HAVS_OPAQUE
  // Opaque geometry ends the ray: nothing behind it, the last segment cut.
  float front = havsDistance(oRC + tEnter * dRC);
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
