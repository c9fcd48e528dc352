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
// One bit a tetrahedron: mirrored (vtkHAVSCellGeometry::ComputeMirrored).
layout(std430, binding = 7) readonly buffer HAVSMirrored
{
  uint havsMirrored[];
};
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

#if HAVS_ISO && !HAVS_CELL_SCALARS && HAVS_ISO_EXACT
// Isosurfaces: the scalars where the ray enters and leaves the cell taken on
// the faces it crosses, where the pixel centre's ray meets them in double
// (havsTriangleWeightsd), from the corners' scalars, as the exact reference
// takes them. The cell's field evaluated at the float crossing point o + t d
// misses by the gradient along the ray times that point's rounding, up to
// 1e-5 of the range at eye distance 50 (the combustor, view 7 at 128^2: an
// isovalue 6.7e-6 below the scalar where the ray leaves the mesh, crossed by
// the reference, missed by the field's value), and the two cells of a face
// computed two values a rounding apart: an isovalue between them was crossed
// in both or in neither. The corners are taken in ascending point id, so both
// cells of a face compute the same double. havsFaceScalars 0: the scalars
// could not be uploaded, the field's value stays. (HAVS_ISO_EXACT 0, the
// testing control FloatIsoStretchesForTesting, compiles none of this.) What
// stays float: the stretch, from the cell's float planes; computing it in
// double too made the isosurface frame 1.26x slower on llvmpipe (combustor,
// 256^2) and changed one view of the LOX post's 14 (a thin cell seen 1 to 4
// degrees off its long faces comes out empty: view 0, 0.14, then 0.07). And a cell is drawn at a pixel only where the rasterizer
// covers the pixel centre with one of its faces (vertices snapped to 1/256
// pixel): on the LOX post's view 7, pixel (62, 61), the exact ray crosses an
// isovalue in a needle cell along the post's axis 0.05 pixel wide, 0.002
// pixel inside its edge, and the cell is not drawn there (HAVS, which draws
// faces, only joins two stretches where it misses a face).
uniform int havsFaceScalars;
layout(std430, binding = 6) readonly buffer HAVSTetrahedra
{
  uint havsTetrahedra[]; // 4 point ids each
};
layout(std430, binding = 8) readonly buffer HAVSPoints
{
  float havsPoints[]; // 3 each
};
layout(std430, binding = 9) readonly buffer HAVSPointScalars
{
  float havsPointScalars[]; // normalized, one each
};

dvec3 havsPointd(uint id)
{
  return dvec3(vec3(havsPoints[3u * id], havsPoints[3u * id + 1u], havsPoints[3u * id + 2u]));
}

// Face j of `cell` (the face opposite corner j): its corners in ascending
// point id, so that both cells of a face compute the same doubles.
void havsFaceCorners(int cell, int j, out uint lo, out uint mid, out uint hi)
{
  uint base = 4u * uint(cell);
  uint i0 = havsTetrahedra[base + (j == 0 ? 1u : 0u)];
  uint i1 = havsTetrahedra[base + (j <= 1 ? 2u : 1u)];
  uint i2 = havsTetrahedra[base + (j <= 2 ? 3u : 2u)];
  lo = min(i0, min(i1, i2));
  hi = max(i0, max(i1, i2));
  mid = i0 + i1 + i2 - lo - hi;
}

// The plane (0 to 3) that gives the ray's parameter t as havsBound computes
// it (the same expression: the same float), moving towards it (`sign` > 0)
// or away from it; -1 when none does (a near-plane section or a clipping
// plane starts or ends the stretch there).
int havsPlaneAt(vec4 planes[4], vec3 o, vec3 d, float t, float sign)
{
  int found = -1;
  for (int j = 0; j < 4; ++j)
  {
    float towards = dot(planes[j].xyz, d);
    float tj = -(dot(planes[j].xyz, o) + planes[j].w) / towards;
    found = found < 0 && towards * sign > 0.0 && tj == t ? j : found;
  }
  return found;
}

// The cell's corner scalars' range, and whether an isovalue lies within it
// or within 1e-4 of it (the float path's scalars err by up to 1e-5).
bool havsCellNearIsovalue(int cell, out vec2 range)
{
  uint base = 4u * uint(cell);
  float s0 = havsPointScalars[havsTetrahedra[base]];
  float s1 = havsPointScalars[havsTetrahedra[base + 1u]];
  float s2 = havsPointScalars[havsTetrahedra[base + 2u]];
  float s3 = havsPointScalars[havsTetrahedra[base + 3u]];
  range = vec2(min(min(s0, s1), min(s2, s3)), max(max(s0, s1), max(s2, s3)));
  return havsNearIsovalue(range.x, range.y, 1e-4);
}

// The scalar where the ray o + t d meets face j of `cell`, from its corners'
// scalars (weights clamped to the face: a ray through an edge or a vertex
// may pass a rounding outside; the same in both cells).
float havsFaceScalarAt(int cell, int j, dvec3 o, dvec3 d, float fallback)
{
  uint lo, mid, hi;
  havsFaceCorners(cell, j, lo, mid, hi);
  dvec3 w;
  bool inside;
  if (!havsTriangleWeightsd(
        o, d, havsPointd(lo), havsPointd(mid), havsPointd(hi), w, inside))
  {
    return fallback;
  }
  if (!inside)
  {
    w = max(w, dvec3(0.0));
    w /= w.x + w.y + w.z;
  }
  double s = w.x * double(havsPointScalars[lo]) + w.y * double(havsPointScalars[mid]) +
    w.z * double(havsPointScalars[hi]);
  return float(clamp(s, 0.0, 1.0));
}
#endif

// The stretch of the ray o + t d in the cell narrowed by `plane` unless the
// ray runs almost along it (|n.d| below `grazing`: see havsBoundGrazing);
// returns |n.d|. `enterBy`, `exitBy`: the planes the stretch starts and ends
// on, as (n, n.d).
float havsBound(vec4 plane, vec3 o, vec3 d, float grazing, inout float tEnter, inout float tExit,
  inout float tFarthest, inout vec4 enterBy, inout vec4 exitBy)
{
  float towards = dot(plane.xyz, d);
  float t = -(dot(plane.xyz, o) + plane.w) / towards;
  bool bounds = abs(towards) >= grazing;
  enterBy = bounds && towards < 0.0 && t > tEnter ? vec4(plane.xyz, towards) : enterBy;
  exitBy = bounds && towards > 0.0 && t < tExit ? vec4(plane.xyz, towards) : exitBy;
  tExit = bounds && towards > 0.0 ? min(tExit, t) : tExit;
  tFarthest = bounds && towards > 0.0 ? max(tFarthest, t) : tFarthest;
  tEnter = bounds && towards < 0.0 ? max(tEnter, t) : tEnter;
  return abs(towards);
}

// The ray's distance from the line where a plane (n.d: `towards`, n.o + w:
// `f`) meets the plane `by` (n', n'.d) that the stretch ends on at `t`: the
// distance from the plane at t, |f + towards t|, made independent of the
// angle between the two planes. (The two cells that share a face end their
// stretches on different planes through the face's edge, and the distances
// from the face where the ray meets them differ by a factor 1 - cos(n, n')
// towards / n'.d; the distance from the edge is one for both.)
float havsEdgeDistance(vec3 n, float towards, float f, vec4 by, float t)
{
  float c = dot(n, by.xyz);
  return abs(f + towards * t) * abs(by.w) /
    sqrt(max(towards * towards + by.w * by.w - 2.0 * c * towards * by.w, 1e-30));
}

// A plane the ray runs almost along narrows the stretch unless the ray lies
// within the rasterizer's band of it at both `ends` of the stretch the others
// left (`bands`: the band there; `enterBy`, `exitBy`: the planes they lie
// on), measured from the face's edges there (havsEdgeDistance); exactly
// parallel (|n.d| at most `parallelToRay`), it keeps the ray only on its
// inner side. True where the fragment is left out: the ray runs outside an
// exactly parallel plane, or within the band of the plane of the fragment's
// own face (`own`).
bool havsBoundGrazing(vec4 plane, bool own, vec3 o, vec3 d, float grazing, float parallelToRay,
  vec2 ends, vec2 bands, vec4 enterBy, vec4 exitBy, inout float tEnter, inout float tExit,
  inout float tFarthest)
{
  float towards = dot(plane.xyz, d);
  float f = dot(plane.xyz, o) + plane.w;
  bool near = abs(towards) < grazing;
  bool banded = near && bands.x > 0.0 &&
    havsEdgeDistance(plane.xyz, towards, f, enterBy, ends.x) < bands.x &&
    havsEdgeDistance(plane.xyz, towards, f, exitBy, ends.y) < bands.y;
  bool bounds = near && !banded;
  float t = -f / towards;
  tExit = bounds && towards > parallelToRay ? min(tExit, t) : tExit;
  tFarthest = bounds && towards > parallelToRay ? max(tFarthest, t) : tFarthest;
  tEnter = bounds && towards < -parallelToRay ? max(tEnter, t) : tEnter;
  return (banded && own) || (bounds && abs(towards) <= parallelToRay && f > 0.0);
}

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
  // The face this fragment is of, -1 on a near-plane section: the cell's
  // triangle f lies opposite its corner f as the vertex shader pulled them,
  // which on a mirrored tetrahedron swaps corners 2 and 3: face plane j.
  int own = havsTrianglesPerCell == 4 ? gl_PrimitiveID % 4 : -1;
  bool mirrored = ((havsMirrored[uint(cell) >> 5u] >> (uint(cell) & 31u)) & 1u) != 0u;
  own = mirrored && own >= 2 ? 5 - own : own;
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
  // Exactly parallel to the ray: |towards| below float noise, at most about
  // 3 * 2^-24 |d| for a three-term dot product of a unit normal and d (the
  // bound is twice that, so that a needle, a face 1e6 times longer than wide
  // turned 1e-6 from the ray, still bounds it): the plane keeps the ray only
  // on its inner side. Almost parallel (below 1e-2: 0.6 degrees), the plane
  // is looked at after the others have bounded the stretch. (Two loops over
  // the planes, no arrays: llvmpipe keeps an array indexed in a loop in
  // memory, and the draw took 1.5 times as long.)
  float parallelToRay = 4e-7 * length(d);
  float grazing = 1e-2 * length(d);
  float tEnter = -HAVS_EMPTY;
  float tExit = HAVS_EMPTY;
  float tFarthest = 0.0;
  vec4 enterBy = vec4(0.0);
  vec4 exitBy = vec4(0.0);
  vec4 planes[4] = vec4[4](havsCell(cell, 0), havsCell(cell, 1), havsCell(cell, 2), havsCell(cell, 3));
  float least =
    min(min(havsBound(planes[0], o, d, grazing, tEnter, tExit, tFarthest, enterBy, exitBy),
          havsBound(planes[1], o, d, grazing, tEnter, tExit, tFarthest, enterBy, exitBy)),
      min(havsBound(planes[2], o, d, grazing, tEnter, tExit, tFarthest, enterBy, exitBy),
        havsBound(planes[3], o, d, grazing, tEnter, tExit, tFarthest, enterBy, exitBy)));
  // The almost parallel planes: each bounds the stretch unless the ray stays
  // within the band of it at both ends of the stretch the others left,
  // measured from the face's edges there, so that the cell and its neighbour
  // across the face decide alike. (Before: measured from the plane, which the
  // two cells' stretches meet a hair apart; where the ray crossed the face
  // with the band's edge between them one cell left the stretch to the
  // neighbour, which kept only its own side, or both kept it: the LOX post,
  // view 0 at 512^2, lost a tenth of a ray's length at pixel (225, 405),
  // 0.015 off.)
  bool finite = tEnter > -HAVS_EMPTY && tExit < HAVS_EMPTY;
  vec2 ends = vec2(tEnter, tExit);
  vec2 bands = finite ? vec2(length(spacing0 + tEnter * spacingPerT),
                          length(spacing0 + tExit * spacingPerT)) / 256.0
                      : vec2(0.0);
  bool outside = own >= 0 &&
    !(dot((own == 0 ? planes[0] : (own == 1 ? planes[1] : (own == 2 ? planes[2] : planes[3]))).xyz,
        d) < -parallelToRay); // (its face seen from behind)
  // (Skipped where no plane is almost parallel: nearly everywhere.)
  if (least < grazing)
  {
  outside = havsBoundGrazing(planes[0], own == 0, o, d, grazing, parallelToRay, ends, bands,
              enterBy, exitBy, tEnter, tExit, tFarthest) ||
    outside;
  outside = havsBoundGrazing(planes[1], own == 1, o, d, grazing, parallelToRay, ends, bands,
              enterBy, exitBy, tEnter, tExit, tFarthest) ||
    outside;
  outside = havsBoundGrazing(planes[2], own == 2, o, d, grazing, parallelToRay, ends, bands,
              enterBy, exitBy, tEnter, tExit, tFarthest) ||
    outside;
  outside = havsBoundGrazing(planes[3], own == 3, o, d, grazing, parallelToRay, ends, bands,
              enterBy, exitBy, tEnter, tExit, tFarthest) ||
    outside;
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
#if HAVS_ISO && !HAVS_CELL_SCALARS && HAVS_ISO_EXACT
  // Isosurface frames: the faces the stretch starts and ends on (before a
  // clipping plane cuts it), for their scalars below; only in a cell whose
  // corner scalars come within 1e-4 of an isovalue, the only cells that can
  // cross one.
  vec2 cellRange = vec2(0.0, 1.0);
  bool exact = havsFaceScalars != 0 && havsCellNearIsovalue(cell, cellRange);
  float tFace[2] = float[2](tEnter, tExit);
  int enterFace = exact ? havsPlaneAt(planes, o, d, tEnter, -1.0) : -1;
  int exitFace = exact ? havsPlaneAt(planes, o, d, tExit, 1.0) : -1;
#endif
  if (!havsClipRay(oRC, dRC, tEnter, tExit) || !(tExit > tEnter))
  {
    discard;
  }
  vec4 field = havsCell(cell, 4);
  float sFront = clamp(dot(field.xyz, o + tEnter * d) + field.w, 0.0, 1.0);
  float sBack = clamp(dot(field.xyz, o + tExit * d) + field.w, 0.0, 1.0);
#if HAVS_ISO && !HAVS_CELL_SCALARS && HAVS_ISO_EXACT
  // The scalars where the stretch meets its faces from the pixel centre's ray
  // in double (where a clipping plane cut it, or a near-plane section starts
  // it, that end is not on a face: the field's value). A cell far from every
  // isovalue keeps its field's values within its corners' range: no crossing.
  if (exact)
  {
    dvec3 rayO, rayD;
    havsPixelRayMCd(rayO, rayD);
    sFront = enterFace >= 0 && tEnter == tFace[0]
      ? havsFaceScalarAt(cell, enterFace, rayO, rayD, sFront)
      : sFront;
    sBack = exitFace >= 0 && tExit == tFace[1]
      ? havsFaceScalarAt(cell, exitFace, rayO, rayD, sBack)
      : sBack;
  }
  else
  {
    sFront = clamp(sFront, cellRange.x, cellRange.y);
    sBack = clamp(sBack, cellRange.x, cellRange.y);
  }
#endif
  float len = (tExit - tEnter) * length(dRC);
#if HAVS_ISO_SHADE
  havsShadeCell = cell;
  havsShadeFrom = o + tEnter * d;
  havsShadeTo = o + tExit * d;
  havsShadeToEye = -normalize(dRC);
#endif
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
#if HAVS_ISO_SHADE
    havsShadeTo = mix(havsShadeFrom, havsShadeTo, (opaque - front) / len);
#endif
    len = opaque - front;
  }
#endif
#if HAVS_CELL_BLEND == 1
  havsSegmentColor = vec4(max(sFront, sBack), 1.0, 0.0, 0.0);
#elif HAVS_CELL_BLEND == 2
  havsSegmentColor = vec4(1.0 - min(sFront, sBack), 1.0, 0.0, 0.0);
#elif HAVS_CELL_BLEND == 4
  havsSegmentColor = vec4(havsAdditiveSegment(sFront, sBack, len), 1.0, 0.0, 0.0);
#elif HAVS_ISO && !HAVS_CELL_SCALARS
  // (havsSegment's isosurfaces; a stretch of length 0 still crosses what its
  // scalars cross.)
  havsSegmentColor = havsIsoSegment(sFront, sBack, max(len, 0.0));
#else
  havsSegmentColor = havsSegment(vec2(0.0, sFront), vec2(len, sBack));
#endif
}
