#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVSRayCastMapper: the ray-casting pass (Weiler et al. 2003; Bernardon
// et al. 2005, seed 002), one full-viewport fragment per pixel. Where the
// peeling found an entry (the tetrahedron behind the nearest boundary face
// beyond the ray's reach), the pixel's ray walks from cell to cell through
// the face neighbours: it leaves each cell through the nearest of its face
// planes it moves towards, the scalars at both ends come from the cell's
// linear field, the segment from the pre-integration table; segments are
// composited front to back into this pass's colour, which blending puts
// under what the earlier passes left (ONE_MINUS_DST_ALPHA, ONE). The walk
// ends where the ray leaves the mesh (neighbour -1: the next pass peels the
// next entry beyond it, unless it comes back in at once across a fold of
// the boundary: havsFoldReentry), at the clipping planes or the opaque surface, or at
// the termination opacity (the ray is then done for every later pass).
//
// The order-independent blends (HAVS_CELL_BLEND 1, 2: maximum and minimum
// intensity; 4: VTK's additive) write the ray's extremal scalar in the mesh
// (1 - s for the minimum) for GL_MAX blending across passes, or its additive
// integral for GL_FUNC_ADD, with a coverage flag beside it; the extremum
// resolve (vtkHAVSExtremumResolveFS) colours the pixel.
//HAVS::Defines
//HAVS::CellBlend
//HAVS::KBufferLib
#if HAVS_CELL_BLEND == 4
//HAVS::AdditiveLib
#endif

//HAVS::CellRecordsLib
// Per tetrahedron: the tetrahedron across face j, -1 on the boundary.
layout(std430, binding = 6) readonly buffer HAVSNeighbours
{
  int havsNeighbours[];
};
// Counts over the frame: rays started, cells crossed, fold re-entries taken.
layout(std430, binding = 7) buffer HAVSRayCounts
{
  uint havsRaysStarted;
  uint havsCellsCrossed;
  uint havsFoldReentries;
};
// Per screen tile: the next pass (1-based) whose peeling must draw there (a
// ray left the mesh there in this pass and may come back in).
layout(std430, binding = 9) buffer HAVSPeelTiles
{
  uint havsPeelTiles[];
};
uniform int havsTileSize;
uniform ivec2 havsTileCount;
uniform int havsPass; // this pass, 1-based

layout(binding = 0, r32ui) uniform coherent uimage2D havsEntryKey;
layout(binding = 1, r32ui) uniform coherent uimage2D havsEntryCell;
layout(binding = 2, rgba32f) uniform coherent image2D havsRayState;

uniform mat4 havsDCMC;        // clip -> model
uniform mat4 havsMCRC;        // model -> eye-relative world (volume matrix included)
uniform vec3 havsEyeMC;       // the eye in model coordinates
uniform vec3 havsDirectionMC; // the direction of projection in model coordinates
uniform int havsMaxSteps;     // a guard against a cycle in a broken table
uniform int havsFolds;        // 1: re-enter across a boundary fold (see havsFoldReentry)

layout(location = 0) out vec4 havsPassColor;

float havsKeyDistance(uint k)
{
  return uintBitsToFloat((k & 0x80000000u) != 0u ? (k & 0x7fffffffu) : ~k);
}

// The distance from p to the line where planes a and b (unit normals) meet.
float havsEdgeDistance(vec4 a, vec4 b, vec3 p)
{
  float fa = dot(a.xyz, p) + a.w, fb = dot(b.xyz, p) + b.w;
  float c = dot(a.xyz, b.xyz);
  float sine2 = max(1.0 - c * c, 1e-12);
  return sqrt(max(fa * fa + fb * fb - 2.0 * c * fa * fb, 0.0) / sine2);
}

// A fold of the boundary: the ray has left the mesh through boundary face
// `face` of `cell` at p (parameter tOut), and the boundary face on the other
// side of that face's nearest edge, found by walking around the edge through
// the face neighbours, may be an entry the ray crosses right there (a crease:
// combustor, 512^2, view 1, pixel (119, 240): out at eye distance 42.057024,
// in again at 42.057045, 0.00014 px inside the entry face's edge, which the
// rasterizer then misses, so the peeling never finds that entry and the rest
// of the ray is lost). Only where the rasterizer may have missed such an
// entry: the ray passes within 0.05 px (`near`, model units at the exit) of
// that edge (snapping moves an edge by about 1/256 px; elsewhere the peeling
// finds the entry). Returns the cell the ray re-enters, with where (tNext),
// or -1: no such cell, or the ray does not pass through it, or it enters it
// more than `gap` after the exit.
int havsFoldReentry(int cell, int face, vec3 o, vec3 d, float tOut, float gap, float near,
  float parallelToRay, out float tNext)
{
  tNext = tOut;
  vec3 p = o + tOut * d;
  // The exit face's edge nearest to p: the face of `cell` that shares it.
  vec4 exitPlane = havsCell(cell, face);
  int side = -1;
  float nearest = HAVS_EMPTY;
  for (int j = 0; j < 4; ++j)
  {
    float e = j == face ? HAVS_EMPTY : havsEdgeDistance(exitPlane, havsCell(cell, j), p);
    if (e < nearest)
    {
      nearest = e;
      side = j;
    }
  }
  // The ray's distance from the edge's line, across the ray: p lies on the
  // exit plane, `nearest` from the line, along m (in that plane, across the edge).
  vec3 u = cross(exitPlane.xyz, havsCell(cell, side).xyz);
  vec3 across = cross(d, u);
  float acrossLength = length(across);
  if (acrossLength > 1e-6 * length(d) * length(u))
  {
    vec3 m = normalize(cross(u, exitPlane.xyz));
    if (nearest * abs(dot(m, across)) > near * acrossLength)
    {
      return -1;
    }
  }
  // Around the edge: into the neighbour across `side`, out through its other
  // face on the edge (the one whose line with the face come in by lies
  // nearest p), until a boundary face.
  int previous = cell;
  int current = havsNeighbours[4 * cell + side];
  for (int around = 0; around < 32 && current >= 0 && current != cell; ++around)
  {
    int back = -1;
    for (int j = 0; j < 4; ++j)
    {
      back = havsNeighbours[4 * current + j] == previous ? j : back;
    }
    if (back < 0)
    {
      return -1; // (a broken table)
    }
    vec4 backPlane = havsCell(current, back);
    int leave = -1;
    nearest = HAVS_EMPTY;
    for (int j = 0; j < 4; ++j)
    {
      float e = j == back ? HAVS_EMPTY : havsEdgeDistance(backPlane, havsCell(current, j), p);
      if (e < nearest)
      {
        nearest = e;
        leave = j;
      }
    }
    int next = havsNeighbours[4 * current + leave];
    if (next >= 0)
    {
      previous = current;
      current = next;
      continue;
    }
    // The boundary face on the other side of the edge: the ray's interval in
    // its cell, which must go on past the exit and begin within `gap` of it.
    // Not strictly past: a ray within rounding of the edge cuts the cell's
    // corner there, an interval empty in float, and the walk goes on from it
    // into the cells beyond (a kd piece of whole cells, 3 ranks, 128^2: out
    // at eye distance 3.2584821, in again 3e-7 further, 4e-6 of the faces'
    // width from their edge; strictly, the rest of the ray was lost: 0.63).
    float tIn = -HAVS_EMPTY, tLeave = HAVS_EMPTY;
    for (int j = 0; j < 4; ++j)
    {
      vec4 plane = havsCell(current, j);
      float towards = dot(plane.xyz, d);
      float t = -(dot(plane.xyz, o) + plane.w) / towards;
      if (towards < -parallelToRay)
      {
        tIn = max(tIn, t);
      }
      else if (towards > parallelToRay)
      {
        tLeave = min(tLeave, t);
      }
    }
    if (tIn <= tOut + gap && tLeave >= max(tIn, tOut))
    {
      tNext = max(tIn, tOut);
      return current;
    }
    return -1;
  }
  return -1;
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint entry = imageLoad(havsEntryCell, pixel).x;
  if (entry == 0u)
  {
    discard;
  }
  float keyDistance = havsKeyDistance(imageLoad(havsEntryKey, pixel).x);
  // Ready for the next pass.
  imageStore(havsEntryCell, pixel, uvec4(0u));
  imageStore(havsEntryKey, pixel, uvec4(0xffffffffu));
  vec4 state = imageLoad(havsRayState, pixel); // reach, opacity so far, last entry
  atomicAdd(havsRaysStarted, 1u);

  // The pixel's ray, o + t d, in model coordinates.
  vec2 ndc = gl_FragCoord.xy / havsViewportSize * 2.0 - 1.0;
  vec4 nearMC = havsDCMC * vec4(ndc, -1.0, 1.0);
  vec3 o, d;
  if (havsParallel != 0)
  {
    o = nearMC.xyz / nearMC.w;
    d = havsDirectionMC;
  }
  else
  {
    o = havsEyeMC;
    d = nearMC.xyz / nearMC.w - havsEyeMC;
  }
  vec3 oRC = (havsMCRC * vec4(o, 1.0)).xyz;
  vec3 dRC = mat3(havsMCRC) * d;
  float worldPerT = length(dRC);
  // The neighbouring pixel's ray (model units apart: pixelApart0 + t pixelApartPerT).
  vec4 nextMC = havsDCMC * vec4(ndc + vec2(2.0 / havsViewportSize.x, 0.0), -1.0, 1.0);
  float pixelApart0 = havsParallel != 0 ? length(nextMC.xyz / nextMC.w - o) : 0.0;
  float pixelApartPerT = havsParallel != 0 ? 0.0 : length(nextMC.xyz / nextMC.w - havsEyeMC - d);
  // The eye distance along the ray is linear in t.
  float distance0 = havsParallel != 0 ? dot(oRC, havsDirectionOfProjection) : 0.0;
  float distanceRate = havsParallel != 0 ? dot(dRC, havsDirectionOfProjection) : worldPerT;

  // What of the ray is kept: the clipping (and near) planes, the opaque surface.
  float tLow = -HAVS_EMPTY, tHigh = HAVS_EMPTY;
  if (!havsClipRay(oRC, dRC, tLow, tHigh))
  {
    tHigh = -HAVS_EMPTY;
  }
  // Nothing before the reach is integrated again (an entry taken a hair
  // before it, at a seam).
  if (state.x > -HAVS_EMPTY)
  {
    tLow = max(tLow, (state.x - distance0) / distanceRate);
  }
#if HAVS_OPAQUE
  float opaque = havsOpaqueDistance(gl_FragCoord.xy);
  if (opaque < HAVS_EMPTY)
  {
    tHigh = min(tHigh, (opaque - distance0) / distanceRate);
  }
#endif

  // Where the ray enters its first cell: the farthest of its boundary faces'
  // planes it enters by (the peeled face is one), else (a cell the near
  // plane's section found) the farthest of all the planes it enters by, else
  // the rasterized entry distance. Not the farthest of all where a boundary
  // face was peeled: at a pixel centre within snapping distance of a face's
  // edge the peeled cell may be one the exact ray misses, beside the one it
  // enters, and an inner plane of it that the ray runs almost along then puts
  // the entry far past the exits of the next cells, whose stretches came out
  // empty (the 49.7M block at 256^2, a ray within 1e-4 px of a lattice plane of
  // the mesh: 10 cells skipped, 0.044 too transparent).
  int cell = int(entry) - 1;
  float parallelToRay = 4e-7 * length(d);
  float tIn = -HAVS_EMPTY;
  float tInBoundary = -HAVS_EMPTY;
  for (int j = 0; j < 4; ++j)
  {
    vec4 plane = havsCell(cell, j);
    float towards = dot(plane.xyz, d);
    if (towards < -parallelToRay)
    {
      float t = -(dot(plane.xyz, o) + plane.w) / towards;
      tIn = max(tIn, t);
      tInBoundary = havsNeighbours[4 * cell + j] < 0 ? max(tInBoundary, t) : tInBoundary;
    }
  }
  tIn = tInBoundary > -HAVS_EMPTY ? tInBoundary : tIn;
  if (tIn <= -HAVS_EMPTY)
  {
    tIn = (keyDistance - distance0) / distanceRate;
  }

#if HAVS_ISO_SHADE
  havsShadeToEye = -normalize(mat3(havsMCRC) * d);
#endif
  vec4 color = vec4(0.0);
  float extremum = 0.0; // (the order-independent blends)
  bool covered = false;
  float before = state.y;
  bool ended = false;
  // The scalar where the last segment ended (its cell's exit face) and its
  // t: the next cell's segment starts there with that value, not its own
  // field's there, which differs by rounding. An isovalue within that
  // rounding of the face was otherwise crossed in both cells or in neither
  // (the half-open [sf, sb) of havsIsoSegment counts it once only given one
  // value at the face; seen as one surface too many or too few at a pixel or
  // two a view, LOX post and combustor at 128^2). HAVS shares the face
  // fragment's scalar by construction. Point scalars only: a cell scalar
  // is the cell's own.
  float carriedT = -HAVS_EMPTY, carriedS = 0.0;
  int steps = 0;
  for (; steps < havsMaxSteps; ++steps)
  {
    vec3 p = o + tIn * d;
    float dt = HAVS_EMPTY;
    int face = -1;
    for (int j = 0; j < 4; ++j)
    {
      vec4 plane = havsCell(cell, j);
      float towards = dot(plane.xyz, d);
      if (towards > parallelToRay)
      {
        float s = -(dot(plane.xyz, p) + plane.w) / towards;
        if (s < dt)
        {
          dt = s;
          face = j;
        }
      }
    }
    if (face < 0)
    {
      break; // (a degenerate cell: the ray leaves here)
    }
    float tOut = tIn + max(dt, 0.0);
    float a = max(tIn, tLow), b = min(tOut, tHigh);
    if (b > a)
    {
      vec4 field = havsCell(cell, 4);
      // (Cell scalars jump at the faces: nothing carried.)
      float sA = HAVS_CELL_SCALARS == 0 && a == carriedT
        ? carriedS
        : clamp(dot(field.xyz, p + (a - tIn) * d) + field.w, 0.0, 1.0);
      float sB = clamp(dot(field.xyz, p + (b - tIn) * d) + field.w, 0.0, 1.0);
      carriedT = b;
      carriedS = sB;
      covered = true;
#if HAVS_CELL_BLEND == 1
      extremum = max(extremum, max(sA, sB));
#elif HAVS_CELL_BLEND == 2
      extremum = max(extremum, 1.0 - min(sA, sB));
#elif HAVS_CELL_BLEND == 4
      extremum += havsAdditiveSegment(sA, sB, (b - a) * worldPerT);
#else
#if HAVS_ISO_SHADE
      havsShadeCell = cell;
      havsShadeFrom = o + a * d;
      havsShadeTo = o + b * d;
#endif
      color += (1.0 - color.a) * havsSegment(vec2(0.0, sA), vec2((b - a) * worldPerT, sB));
#endif
    }
    tIn = tOut;
    if (tOut >= tHigh || before + (1.0 - before) * color.a >= havsTerminationOpacity)
    {
      ended = true;
      ++steps;
      break;
    }
    int next = havsNeighbours[4 * cell + face];
    if (next < 0 && havsFolds != 0)
    {
      // In again at once across a fold of the boundary (see havsFoldReentry),
      // within a thousandth of the eye distance.
      float tNext;
      next = havsFoldReentry(cell, face, o, d, tOut, 1e-3 * abs(distance0 / distanceRate + tOut),
        0.05 * (pixelApart0 + tOut * pixelApartPerT), parallelToRay, tNext);
      if (next >= 0)
      {
        atomicAdd(havsFoldReentries, 1u);
        tIn = tNext;
      }
    }
    if (next < 0)
    {
      ++steps;
      break; // out of the mesh: the next pass finds where it comes back
    }
    cell = next;
  }
  atomicAdd(havsCellsCrossed, uint(steps));
  // (Never before the entry the peeling found.)
  float reach = ended ? HAVS_EMPTY : max(distance0 + tIn * distanceRate, keyDistance);
  if (!ended)
  {
    ivec2 tile = pixel / havsTileSize;
    havsPeelTiles[tile.y * havsTileCount.x + tile.x] = uint(havsPass + 1);
  }
  imageStore(
    havsRayState, pixel, vec4(reach, before + (1.0 - before) * color.a, keyDistance, 0.0));
#if HAVS_CELL_BLEND != 0
  if (!covered)
  {
    discard; // (the ray state is written already)
  }
  havsPassColor = vec4(extremum, 1.0, 0.0, 0.0);
#else
  havsPassColor = color;
#endif
}
