// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS k-buffer library, shared by every k-buffer path (framebuffer fetch,
// fragment-shader interlock, fragment lists). Inserted into the fragment
// shaders at the KBufferLib marker.
//
// A k-buffer of HAVS_K entries per pixel. Entry = vec2(distance, code):
//   distance  the eye distance of a fragment (world units along the ray for a
//             perspective camera, along the direction of projection for a
//             parallel one), so that the difference of two is a segment length;
//   code      the scalar in [0, 1]; + 2 when the fragment lies on a boundary
//             face seen from inside (an exit from the mesh), + 4 on a boundary
//             face seen from outside (an entry).
// E[0] is the front: the last fragment already composited up to (the ray has
// been integrated to it). E[1 .. HAVS_K-1] hold fragments still waiting.
// Each arriving fragment fills an empty slot; when none is left, the nearest
// of the waiting ones and the new one leaves, and the segment from the front
// to it is composited (lazy pop). The image is exact iff the fragments leave
// in depth order, i.e. iff k = HAVS_K entries suffice for the pixel.
//
// A segment whose front is an exit fragment lies outside the mesh (holes,
// cavities, gaps between components): it contributes nothing (boundary
// tagging). An internal fragment that leaves a hair (HAVS_GRAZE, relative)
// after an exit takes the exit's role: rasterization is not exact at a grazing
// exit, where an internal face seen almost edge-on, sharing an edge with the
// exit face, can cover a pixel the exact face misses (vertices are snapped to
// sub-pixel units) with its distance extrapolated a little past the exit; the
// segment from it to the next entry, across the whole gap, counted (blunt fin,
// 1024^2, view 0: one pixel off by 0.12). Not the back end's entry instead:
// where a ray grazes the boundary from inside (an exit and an entry at one
// point, met in either order by rounding) the segment before the entry is
// inside (combustor, 512^2: two pixels off by 0.015 with that rule).

// Fragments at the same distance (up to float rounding) leave in the order
// internal, exit, entry: a ray crossing a seam of coincident boundary faces
// (an exit and an entry at one point, as where a mesh has duplicated points)
// goes on inside, and a ray leaving through an edge shared by an internal and
// a boundary face ends outside.

// Features compiled in or out per frame (vtkHAVSShaders::Features):
// HAVS_COUNT_VIOLATIONS the order-violation counter and its tie tolerance;
// HAVS_TAGGING the boundary role of a boundary face's fragment (its facing); HAVS_OPAQUE the opaque surface that ends the rays (a per-fragment
// depth fetch); HAVS_CLIPPING the clipping and near planes (a loop over
// them). A feature a frame does not need costs nothing.
#ifndef HAVS_COUNT_VIOLATIONS
#define HAVS_COUNT_VIOLATIONS 1
#endif
#ifndef HAVS_TAGGING
#define HAVS_TAGGING 1
#endif
#ifndef HAVS_OPAQUE
#define HAVS_OPAQUE 1
#endif
#ifndef HAVS_CELL_SCALARS
#define HAVS_CELL_SCALARS 0
#endif
#ifndef HAVS_CLIPPING
#define HAVS_CLIPPING 1
#endif
#ifndef HAVS_PROJECTION
#define HAVS_PROJECTION -1
#endif
#ifndef HAVS_ISO
#define HAVS_ISO 0
#endif
#ifndef HAVS_ISO_SHADE
#define HAVS_ISO_SHADE 0
#endif
#ifndef HAVS_ISO_EXACT
#define HAVS_ISO_EXACT 1
#endif

// An entry (see the top): vec2(distance, code). HAVS_ISO_SHADE 2 (HAVS's
// fragment lists shading isosurfaces) adds the fragment's interpolated point
// gradient (model coordinates), read where a segment crosses an isovalue.
#if HAVS_ISO_SHADE == 2
struct HavsEntry
{
  float x; // distance
  float y; // code
  vec3 g;  // gradient
};
#define HAVS_ENTRY HavsEntry
#define havsEntry(d, c) HavsEntry(d, c, vec3(0.0))
#else
#define HAVS_ENTRY vec2
#define havsEntry(d, c) vec2(d, c)
#endif

// The face passes' scalar input (declared with HAVS_FACE_SCALAR_INPUT) and the
// fragment's scalar, havsFaceScalar(). Point scalars: interpolated across the
// face. Cell scalars (HAVS_CELL_SCALARS): the face's two cells' values, and the
// fragment takes the one of the cell behind it (seen from the normal's side,
// front-facing, that is the other side's cell). A segment then lies in the cell
// behind its front fragment and its scalar is constant: the table is read at
// (front, front).
#if HAVS_CELL_SCALARS
#define HAVS_FACE_SCALAR_INPUT flat in vec2 havsCellScalars;
#define havsFaceScalar() (gl_FrontFacing ? havsCellScalars.y : havsCellScalars.x)
#else
#define HAVS_FACE_SCALAR_INPUT in float havsScalar;
#define havsFaceScalar() havsScalar
#endif

const float HAVS_EMPTY = 3.0e38;     // an empty waiting slot
const float HAVS_NO_FRONT = -2.0e38; // nothing composited yet
const float HAVS_DONE = -3.0e38;     // the ray has ended (opaque surface reached)

uniform sampler3D havsTable;     // pre-integrated segments (front s, back s, length)
uniform vec2 havsScalarTexel;    // ((N-1)/N, 0.5/N): [0,1] -> texel centres
uniform vec2 havsLengthTexel;    // same along the length axis
uniform float havsInvMaxLength;  // 1 / the table's longest length
uniform float havsLengthLogScale; // the length axis: 0 linear, else a (see havsLengthCoordinate)
uniform float havsInvLogRange;    // 1 / log(1 + a * the longest length)
uniform float havsTerminationOpacity;

uniform sampler2D havsOpaqueDepth; // window depth of the opaque geometry (the viewport's size)
uniform vec2 havsOpaqueDepthScale; // viewport pixels per drawn pixel (a reduced image: > 1)
uniform mat4 havsDCRC;             // clip -> eye-relative world
uniform vec2 havsViewportSize;
uniform int havsParallel;
uniform vec3 havsDirectionOfProjection;

// Boundary handling and clipping (see vtkHAVSVolumeMapper::SetBoundaryMode).
uniform float havsGapLength; // segments longer than this contribute nothing (VTK 5's
                             // heuristic; 3e38 = off)
uniform int havsRole;        // what is drawn: 0 mesh faces, 1 a section that enters the
                             // clipped volume (near or clipping plane), 2 one that leaves it
const int HAVS_MAX_PLANES = 7; // VTK's 6 clipping planes and the near plane
uniform int havsPlaneCount;
uniform vec4 havsPlanesRC[HAVS_MAX_PLANES]; // kept where dot(xyz, positionRC) + w >= 0
uniform int havsOwnPlane;    // the plane the drawn section lies on (-1: mesh faces)

// Order violations: fragments that arrive nearer than the fragment their ray
// has already been integrated to (they are then composited out of depth
// order; a fragment that arrives behind the front never is). Counted over the
// frame; zero means the k-buffer sorted every pixel (the face order plus k
// were enough). Differences within the arriving fragment's depth uncertainty
// are ties, not violations: float rounding (relative HAVS_TIE) and half
// of the fragment's depth change per pixel (fwidth). The latter covers what
// sub-pixel rasterization does at a pixel centre on or near an edge: the
// rasterizer (vertices snapped to 1/256 pixel) may cover it with a face the
// exact ray misses, at a depth within that of its neighbours; such a face is
// drawn at its own cell's turn. It is large only on faces seen nearly edge-on.
layout(std430, binding = 3) buffer HAVSOrderViolations
{
  uint havsOrderViolations;
  uint havsViolationPixels[16]; // the first pixels with one: x | y << 16
  uint havsShadedFragments;     // fragments that ran the draw shader (havsCountShaded)
};

void havsCountViolation()
{
  uint i = atomicAdd(havsOrderViolations, 1u);
  if (i < 16u)
  {
    havsViolationPixels[i] = uint(gl_FragCoord.x) | (uint(gl_FragCoord.y) << 16);
  }
}

// Counted with the violations: a fragment that runs the draw shader (one
// rejected by the early stencil test of vtkHAVSGLSaturationMask does not).
void havsCountShaded()
{
#if HAVS_COUNT_VIOLATIONS
  atomicAdd(havsShadedFragments, 1u);
#endif
}

const float HAVS_TIE = 1.0e-4;
// Cell scalars: how close (relative) two internal fragments are a near-tie
// that arrival order decides (havsInsert).
const float HAVS_CELL_TIE = 3.0e-4;

// How close (relative) after an exit an internal fragment takes the exit's
// role (see the top).
const float HAVS_GRAZE = 1.0e-3;


bool havsIsExit(float code)
{
  return code > 1.5 && code < 3.5;
}

float havsScalarOf(float code)
{
  return code > 3.5 ? code - 4.0 : (code > 1.5 ? code - 2.0 : code);
}

// The order in which fragments leave: distance, ties broken internal < exit
// < entry (see above); a tie is a difference below float rounding.
float havsLeaveKey(HAVS_ENTRY e)
{
  float rank = e.y > 3.5 ? 2.0 : (e.y > 1.5 ? 1.0 : 0.0);
#if HAVS_ISO && !HAVS_CELL_SCALARS && HAVS_ISO_EXACT
  // Isosurface frames: the distances are the exact ray's (havsOnFace), and a
  // tie is 1e-7 apart; 4e-6 of the distance reordered a boundary entry and the
  // thin cell's internal face behind it (1.4e-4 apart at eye distance 83 on
  // the LOX post, view 1 unturned at 256^2: a crossing between them lost,
  // 0.088 off; views 0 and 2: 0.12, 0.25 before the exact distances too).
  return e.x + rank * 4.0e-7 * abs(e.x);
#else
  return e.x + rank * 4.0e-6 * abs(e.x);
#endif
}

// HAVS_PROJECTION: 0 perspective, 1 parallel (compiled in: a per-fragment
// select less, 5 % of the draw on llvmpipe), -1 decided by havsParallel.
float havsDistance(vec3 positionRC)
{
#if HAVS_PROJECTION == 0
  return length(positionRC);
#elif HAVS_PROJECTION == 1
  return dot(positionRC, havsDirectionOfProjection);
#else
  return havsParallel != 0 ? dot(positionRC, havsDirectionOfProjection) : length(positionRC);
#endif
}

// The tie tolerance of a fragment at positionRC (call in uniform control flow:
// it takes screen-space derivatives).
float havsTieTolerance(vec3 positionRC)
{
#if HAVS_COUNT_VIOLATIONS
  float d = havsDistance(positionRC);
  return HAVS_TIE * abs(d) + fwidth(d) * 0.5;
#else
  return 0.0;
#endif
}

// Eye distance of the opaque surface at this pixel, HAVS_EMPTY when none.
float havsOpaqueDistance(vec2 fragCoord)
{
#if HAVS_OPAQUE
  float z = texelFetch(havsOpaqueDepth, ivec2(fragCoord * havsOpaqueDepthScale), 0).r;
  if (z >= 1.0)
  {
    return HAVS_EMPTY;
  }
  vec4 ndc = vec4(fragCoord / havsViewportSize * 2.0 - 1.0, z * 2.0 - 1.0, 1.0);
  vec4 p = havsDCRC * ndc;
  return havsDistance(p.xyz / p.w);
#else
  return HAVS_EMPTY;
#endif
}

// The table's length coordinate of a segment length, in [0, 1]
// (vtkHAVSPreIntegrationTable::LengthCoordinate): linear, or logarithmic
// where the longest segment spans many optical lengths.
float havsLengthCoordinate(float len)
{
  float u = havsLengthLogScale > 0.0 ? log(1.0 + len * havsLengthLogScale) * havsInvLogRange
                                     : len * havsInvMaxLength;
  return min(u, 1.0);
}

#if HAVS_CELL_SCALARS
// Cell scalars: a fragment's scalar is its cell's code (havsCellIndex).
//HAVS::CellOpticsLib

// The segment of length len in the cell of `code`: the scalar is constant,
// so the emission-absorption integral is closed: opacity 1 - exp(-tau len),
// colour the cell's colour times it (the table's model, the function taken
// at the cell's value itself: a spike of it narrower than a table node
// spacing is not interpolated away).
vec4 havsCellSegment(float code, float len)
{
  vec4 o = texelFetch(havsCellOptics, 2 * havsCellIndex(code));
  float x = o.a * len;
  float alpha = x < 1.0e-3 ? x * (1.0 - 0.5 * x) : 1.0 - exp(-x);
  return vec4(o.rgb * alpha, alpha);
}
#endif

#if !HAVS_CELL_SCALARS
// The pre-integrated segment from scalar sf to sb of length len (the table).
vec4 havsTableSegment(float sf, float sb, float len)
{
  vec3 t = vec3(sf, sb, havsLengthCoordinate(len));
  vec3 coord = vec3(t.xy * havsScalarTexel.x + havsScalarTexel.y,
    t.z * havsLengthTexel.x + havsLengthTexel.y);
  // Level 0 named: no derivatives, no level selection (the table has one level).
  return textureLod(havsTable, coord, 0.0);
}
#endif

#if HAVS_ISO
// The isosurfaces (vtkHAVSIsoSurfaces; vtkHAVSGLTable sets them), compiled
// in only where a frame draws them (HAVS_ISO 1: the isosurface blend, 2: the
// composite blend with its surfaces inside, the mixed mode; a runtime branch
// cost llvmpipe's composite frames 1.4 to 1.8 times their draw). Values in
// the scalars' [0, 1], ascending; colours premultiplied.
const int HAVS_MAX_ISO = 8;
uniform int havsIsoCount;
uniform float havsIsoValues[HAVS_MAX_ISO];
uniform vec4 havsIsoColors[HAVS_MAX_ISO];

#if HAVS_ISO_SHADE
// Shaded isosurfaces (the property's ShadeOn; vtkHAVSIsoSurfaces::Shade, here
// in float): Phong's model with the normal of the interpolated point
// gradients (vtkHAVSPointGradients: each tetrahedron's field, three rows
// G_k(p) = row.xyz . p + row.w in model coordinates), turned towards the eye.
// The mappers that know each segment's cell (the ray caster, the cell
// projection) set its cell and ends (model coordinates) and the direction
// towards the eye (world) before havsSegment.
const int HAVS_MAX_LIGHTS = 8;
uniform int havsLightCount;
uniform vec3 havsLightDirection[HAVS_MAX_LIGHTS]; // world, towards the light
uniform vec3 havsLightDiffuse[HAVS_MAX_LIGHTS];   // colour times intensity
uniform vec3 havsLightSpecular[HAVS_MAX_LIGHTS];
uniform vec4 havsShading;      // ambient, diffuse, specular, specular power
uniform mat3 havsNormalMatrix; // model gradient -> world normal
vec3 havsShadeToEye = vec3(0.0, 0.0, 1.0);
#if HAVS_ISO_SHADE == 2
// (HAVS: the segment's two entries' gradients, set by havsSegment.)
vec3 havsShadeGradientFrom = vec3(0.0);
vec3 havsShadeGradientTo = vec3(0.0);
#else
layout(std430, binding = 13) readonly buffer HAVSGradientFields
{
  vec4 havsGradientFields[];
};
int havsShadeCell = 0;
vec3 havsShadeFrom = vec3(0.0);
vec3 havsShadeTo = vec3(0.0);
#endif

// The direction towards the eye (world) of the pixel at fragCoord.
vec3 havsPixelToEye(vec2 fragCoord)
{
  if (havsParallel != 0)
  {
    return -havsDirectionOfProjection;
  }
  vec4 p = havsDCRC * vec4(fragCoord / havsViewportSize * 2.0 - 1.0, 0.0, 1.0);
  return -normalize(p.xyz / p.w);
}

// The surface of premultiplied colour rgba where the segment is crossed at
// its share t, lit.
vec4 havsShadeSurface(vec4 rgba, float t)
{
#if HAVS_ISO_SHADE == 2
  vec3 g = mix(havsShadeGradientFrom, havsShadeGradientTo, t);
#else
  vec3 p = mix(havsShadeFrom, havsShadeTo, t);
  int row = 3 * havsShadeCell;
  vec3 g = vec3(dot(havsGradientFields[row].xyz, p) + havsGradientFields[row].w,
    dot(havsGradientFields[row + 1].xyz, p) + havsGradientFields[row + 1].w,
    dot(havsGradientFields[row + 2].xyz, p) + havsGradientFields[row + 2].w);
#endif
  vec3 n = havsNormalMatrix * g;
  float len = length(n);
  if (!(rgba.a > 0.0) || !(len > 0.0) || isinf(len))
  {
    return rgba;
  }
  n = (dot(n, havsShadeToEye) < 0.0 ? -n : n) / len;
  vec3 c = rgba.rgb / rgba.a;
  vec3 lit = havsShading.x * c;
  for (int i = 0; i < havsLightCount; ++i)
  {
    float nl = dot(n, havsLightDirection[i]);
    if (nl > 0.0)
    {
      lit += havsShading.y * nl * havsLightDiffuse[i] * c;
      vec3 r = 2.0 * nl * n - havsLightDirection[i];
      float rv = dot(r, havsShadeToEye);
      if (rv > 0.0)
      {
        lit += havsShading.z * pow(rv, havsShading.w) * havsLightSpecular[i];
      }
    }
  }
  return vec4(clamp(lit, 0.0, 1.0) * rgba.a, rgba.a);
}
#endif

// The segment from scalar sf to sb (length len) with its isosurfaces: each
// value it crosses, in [sf, sb) rising or (sb, sf] falling (a crossing at a
// shared face counted once, in the segment behind it), composited front to
// back in the order the ray meets them; in the mixed mode the volume's
// pieces between them too (the scalar is linear along the segment).
vec4 havsIsoSegment(float sf, float sb, float len)
{
  vec4 color = vec4(0.0);
  bool rising = sb > sf;
  float from = 0.0; // (the mixed mode) the part of the segment composited
  float sFrom = sf;
  for (int n = 0; n < havsIsoCount; ++n)
  {
    int i = rising ? n : havsIsoCount - 1 - n;
    float v = havsIsoValues[i];
    if (rising ? (v >= sf && v < sb) : (v <= sf && v > sb))
    {
#if !HAVS_CELL_SCALARS && HAVS_ISO == 2
      {
        float t = (v - sf) / (sb - sf);
        color += (1.0 - color.a) * havsTableSegment(sFrom, v, (t - from) * len);
        from = t;
        sFrom = v;
      }
#endif
#if HAVS_ISO_SHADE
      color += (1.0 - color.a) * havsShadeSurface(havsIsoColors[i], (v - sf) / (sb - sf));
#else
      color += (1.0 - color.a) * havsIsoColors[i];
#endif
    }
  }
#if !HAVS_CELL_SCALARS && HAVS_ISO == 2
  color += (1.0 - color.a) * havsTableSegment(sFrom, sb, (1.0 - from) * len);
#endif
  return color;
}
#endif

// The entry where the segment from a to b (one cell: scalar and gradient
// linear) is cut at `distance`, share t of it.
HAVS_ENTRY havsCut(HAVS_ENTRY a, HAVS_ENTRY b, float distance, float t)
{
  HAVS_ENTRY e = havsEntry(distance, mix(havsScalarOf(a.y), havsScalarOf(b.y), t));
#if HAVS_ISO_SHADE == 2
  e.g = mix(a.g, b.g, t);
#endif
  return e;
}

// Premultiplied colour and opacity of the segment from a to b.
vec4 havsSegment(HAVS_ENTRY a, HAVS_ENTRY b)
{
  float len = b.x - a.x;
  if (havsIsExit(a.y) || !(len > 0.0) || len > havsGapLength)
  {
    return vec4(0.0);
  }
#if HAVS_CELL_SCALARS && HAVS_ISO == 1
  // (The segment lies in the cell behind its front fragment; its scalar is
  // constant: no isosurface inside it.)
  return vec4(0.0);
#elif HAVS_CELL_SCALARS
  return havsCellSegment(havsScalarOf(a.y), len);
#elif HAVS_ISO
#if HAVS_ISO_SHADE == 2
  havsShadeGradientFrom = a.g;
  havsShadeGradientTo = b.g;
#endif
  return havsIsoSegment(havsScalarOf(a.y), havsScalarOf(b.y), len);
#else
  return havsTableSegment(havsScalarOf(a.y), havsScalarOf(b.y), len);
#endif
}

// Moves the front to p (the next fragment in depth order), compositing the
// segment between them front to back; ends the ray at the opaque surface,
// cutting the last segment there with its scalar interpolated. One table
// look-up either way: a rasterizer that runs both sides of a branch (llvmpipe
// masks lanes instead of branching) pays for each look-up written.
void havsAdvance(inout vec4 color, inout HAVS_ENTRY front, HAVS_ENTRY p, float opaqueDistance)
{
  if (front.x == HAVS_DONE)
  {
    return;
  }
  // A fragment behind the front (out of order): the ray is integrated past
  // it, so the front stays where it is (never again over a stretch
  // composited already) and takes only a boundary fragment's role. At a pixel
  // centre on or near a face's edge the rasterizer (vertices snapped to
  // sub-pixel units) can cover it with a face the exact ray misses, whose
  // cell the exact order draws later; moving the front back to it counted
  // the stretch between twice (the 49.7M block at 256^2, a ray within 1e-4 px
  // of faces seen almost edge-on: 0.020 too opaque). With cell scalars a
  // near-tie (HAVS_CELL_TIE) still moves the front: the fragment that leaves
  // last gives the next segment its cell (see havsCellTieLeaves).
#if HAVS_CELL_SCALARS
  bool behind = front.x > HAVS_NO_FRONT && p.x < front.x - HAVS_CELL_TIE * abs(front.x);
#else
  bool behind = front.x > HAVS_NO_FRONT && p.x < front.x;
#endif
  if (behind)
  {
    front.y = p.y < 1.5 ? front.y : havsScalarOf(front.y) + (p.y - havsScalarOf(p.y));
    return;
  }
  HAVS_ENTRY back = p;
#if HAVS_OPAQUE
  bool reached = p.x > opaqueDistance;
  if (reached)
  {
    // Empty when the surface lies in front of the front (havsSegment: length <= 0).
    float t = clamp((opaqueDistance - front.x) / (p.x - front.x), 0.0, 1.0);
    back = havsCut(front, p, opaqueDistance, t);
  }
#endif
  if (front.x > HAVS_NO_FRONT)
  {
    color += (1.0 - color.a) * havsSegment(front, back);
  }
#if HAVS_TAGGING
  if (havsIsExit(front.y) && p.y < 1.5 && p.x - front.x < HAVS_GRAZE * abs(front.x))
  {
    p.y += 2.0; // a grazing exit's stray internal fragment: still outside
  }
#endif
#if HAVS_OPAQUE
  front = reached ? havsEntry(HAVS_DONE, 0.0) : p;
#else
  front = p;
#endif
}

bool havsRayEnded(vec4 color, HAVS_ENTRY front)
{
  return front.x == HAVS_DONE || color.a >= havsTerminationOpacity;
}

#if HAVS_CELL_SCALARS
// Cell scalars: whether the waiting fragment e (key eKey) leaves before
// `later` (key laterKey), which arrived after it. Of an internal fragment and
// an earlier internal or entry one this close (HAVS_CELL_TIE), the earlier
// leaves first. Near a shared edge or vertex a ray crosses a chain of faces at
// nearly one distance, drawn in the exact order (each cell's entry face before
// its exit faces, a boundary entry before the cell's exits), and the one that
// leaves last gives the next segment its cell: rounding must not reorder them
// (measured on 96^2 views: up to 10 pixels off by up to 0.16 with 2e-6; with
// 3e-5 still 0 to 3 interior pixels a view of a box of tetrahedra, off by up
// to 0.17: the interpolated distances differ by more; none with 3e-4, the same
// with 1e-3; an entry and the internal face just behind it, near the silhouette
// of the hollow sphere: 0.017 to 0.048 at 1 or 2 pixels in three of four views
// while only internal pairs counted). Other boundary fragments keep the rank
// order of havsLeaveKey.
bool havsCellTieLeaves(HAVS_ENTRY e, float eKey, HAVS_ENTRY later, float laterKey)
{
  float margin = (later.y < 1.5 && (e.y < 1.5 || e.y > 3.5)) ? HAVS_CELL_TIE * abs(laterKey) : 0.0;
  return e.x < HAVS_EMPTY && eKey < laterKey + margin;
}

#if HAVS_K > 2
// The slot (1 … K-1, in arrival order) of the waiting fragment that leaves
// before the others and before f, HAVS_K when f does: from the latest arrival
// to the earliest, an earlier one takes the place when havsCellTieLeaves.
int havsLeavingSlot(HAVS_ENTRY E[HAVS_K], HAVS_ENTRY f)
{
  int slot = HAVS_K;
  HAVS_ENTRY leaving = f;
  float leavingKey = havsLeaveKey(f);
  for (int i = HAVS_K - 1; i >= 1; --i)
  {
    HAVS_ENTRY e = E[i];
    float key = havsLeaveKey(e);
    bool leaves = havsCellTieLeaves(e, key, leaving, leavingKey);
    slot = leaves ? i : slot;
    leaving = leaves ? e : leaving;
    leavingKey = leaves ? key : leavingKey;
  }
  return slot;
}
#endif
#endif

// Inserts fragment f into the k-buffer E (E[0] = front); tolerance: f's tie
// tolerance (havsTieTolerance).
// One pass over the waiting slots carries the nearest of f and the waiting
// fragments out (a waiting one leaves when its key is strictly less: ties keep
// arrival order) and leaves the others in the slots; an empty slot takes the
// carried fragment and nothing leaves. Selects, no early return: llvmpipe runs
// a SIMD lane group through every path of a divergent branch, and the draw
// with the former search-then-store loop (a return from inside it) cost 1.3x
// this one (combustor 512^2, view 0, k = 2: draw 300 -> 230 ms, same image;
// havs_gpu_bench on the benchmark's dumped frame).
void havsInsert(
  inout vec4 color, inout HAVS_ENTRY E[HAVS_K], HAVS_ENTRY f, float opaqueDistance, float tolerance)
{
#if HAVS_COUNT_VIOLATIONS
  if (E[0].x > HAVS_NO_FRONT && f.x < E[0].x - tolerance)
  {
    havsCountViolation();
  }
#endif
  HAVS_ENTRY leaving = f;
#if HAVS_K == 2
  // k = 2 (the default) written out: the loop below, unrolled by hand, still
  // draws 1.15x slower on llvmpipe (same image).
  HAVS_ENTRY w = E[1];
  bool empty = w.x >= HAVS_EMPTY;
#if HAVS_CELL_SCALARS
  bool leaves = havsCellTieLeaves(w, havsLeaveKey(w), f, havsLeaveKey(f));
#else
  bool leaves = !empty && havsLeaveKey(w) < havsLeaveKey(f);
#endif
  leaving = leaves ? w : f;
  E[1] = (leaves || empty) ? f : w;
  if (!empty)
#elif HAVS_K > 2 && HAVS_CELL_SCALARS
  // Cell scalars, k > 2: the waiting slots E[1 … K-1] hold their fragments
  // in arrival order (filled from slot 1; when one leaves, the later ones move
  // down and f goes last), so that near-ties (havsCellTieLeaves) go by arrival
  // order among all of them, not only against f: the select loop below permutes
  // the slots, and with it a later arrival could leave first (measured at k =
  // 6 on the hollow sphere's 96^2 views: 4 to 10 pixels a view off by up to
  // 0.048, RMSE up to 6.2e-4).
  bool full = E[HAVS_K - 1].x < HAVS_EMPTY;
  if (full)
  {
    int slot = havsLeavingSlot(E, f); // (only when one must leave)
    leaving = slot < HAVS_K ? E[slot] : f;
    for (int i = 1; i < HAVS_K - 1; ++i)
    {
      E[i] = i >= slot ? E[i + 1] : E[i];
    }
    E[HAVS_K - 1] = slot < HAVS_K ? f : E[HAVS_K - 1];
  }
  else
  {
    bool stored = false;
    for (int i = 1; i < HAVS_K; ++i)
    {
      bool here = !stored && E[i].x >= HAVS_EMPTY;
      E[i] = here ? f : E[i];
      stored = stored || here;
    }
  }
  if (full)
#elif HAVS_K > 2
  float leavingKey = havsLeaveKey(f);
  bool stored = false; // an empty slot took the carried fragment
  for (int i = 1; i < HAVS_K; ++i)
  {
    HAVS_ENTRY e = E[i];
    bool empty = e.x >= HAVS_EMPTY;
    float key = havsLeaveKey(e);
    bool leaves = !stored && !empty && key < leavingKey;
    E[i] = (leaves || (empty && !stored)) ? leaving : e;
    stored = stored || empty;
    leaving = leaves ? e : leaving;
    leavingKey = leaves ? key : leavingKey;
  }
  if (!stored)
#endif
  {
    havsAdvance(color, E[0], leaving, opaqueDistance);
  }
}

// After the last fragment: the waiting entries leave in depth order.
void havsFlush(inout vec4 color, inout HAVS_ENTRY E[HAVS_K], float opaqueDistance)
{
  for (int n = 1; n < HAVS_K; ++n)
  {
#if HAVS_CELL_SCALARS && HAVS_K > 2
    // The same near-tie rule as havsInsert's (no newcomer: an empty one).
    int nearest = havsLeavingSlot(E, havsEntry(HAVS_EMPTY, 0.0));
    nearest = nearest == HAVS_K ? 0 : nearest;
#else
    int nearest = 0;
    float nearestKey = HAVS_EMPTY;
    for (int i = 1; i < HAVS_K; ++i)
    {
      float key = E[i].x < HAVS_EMPTY ? havsLeaveKey(E[i]) : HAVS_EMPTY;
      if (key < nearestKey)
      {
        nearestKey = key;
        nearest = i;
      }
    }
#endif
    if (nearest == 0)
    {
      return;
    }
    havsAdvance(color, E[0], E[nearest], opaqueDistance);
    E[nearest].x = HAVS_EMPTY;
  }
}

// True when the fragment lies on the discarded side of a clipping plane or
// in front of the near plane (a section is not tested against its own plane).
bool havsClipped(vec3 positionRC)
{
#if HAVS_CLIPPING
  for (int i = 0; i < havsPlaneCount; ++i)
  {
    if (i != havsOwnPlane && dot(havsPlanesRC[i].xyz, positionRC) + havsPlanesRC[i].w < 0.0)
    {
      return true;
    }
  }
#endif
  return false;
}

// The part of the ray originRC + t dirRC (eye-relative world coordinates)
// that every plane keeps: [tLow, tHigh] narrowed to it; false where a plane
// parallel to the ray discards all of it. (The cell projection's segment in a
// cell, the ray caster's whole ray.)
bool havsClipRay(vec3 originRC, vec3 dirRC, inout float tLow, inout float tHigh)
{
  for (int i = 0; i < havsPlaneCount; ++i)
  {
    float atOrigin = dot(havsPlanesRC[i].xyz, originRC) + havsPlanesRC[i].w;
    float rate = dot(havsPlanesRC[i].xyz, dirRC);
    if (rate > 0.0)
    {
      tLow = max(tLow, -atOrigin / rate);
    }
    else if (rate < 0.0)
    {
      tHigh = min(tHigh, -atOrigin / rate);
    }
    else if (atOrigin < 0.0)
    {
      return false;
    }
  }
  return true;
}

#if HAVS_ISO && !HAVS_CELL_SCALARS && HAVS_ISO_EXACT
// Isosurface frames: where the pixel centre's ray meets a face, in double.
// An isovalue within rounding of the scalar where a ray meets a face is
// crossed on one side of the face or the other as the float point lies: the
// rasterizer interpolates at vertices snapped to 1/256 pixel (4e-4 world at
// eye distance 48 on the combustor at 256^2), a float ray's point errs by
// about 1e-7 of the eye distance along it and across, and a steep field
// multiplies either (the combustor, view 1 unturned at 256^2, pixel (178,
// 107): the ray enters the mesh at 0.531012, the isovalue 0.531007; HAVS saw
// a crossing there the exact ray does not, 0.19 off). In double, from the
// view's matrices and the float points, the scalar errs by the points'
// rounding alone. In model coordinates, where the points are (the weights do
// not change under the volume's matrix): no point is transformed.
uniform dmat4 havsDCMCd; // clip -> model, in double
uniform dvec3 havsEyeMCd; // the eye in model coordinates (perspective), in double

// The pixel centre's point at normalized depth z (-1: the near plane, 1:
// the far plane), model coordinates.
dvec3 havsPixelPointMCd(double z)
{
  dvec2 ndc = dvec2(gl_FragCoord.xy) / dvec2(havsViewportSize) * 2.0 - 1.0;
  dvec4 p = havsDCMCd * dvec4(ndc, z, 1.0);
  return p.xyz / p.w;
}

dvec3 havsPixelNearMCd()
{
  return havsPixelPointMCd(-1.0);
}

// The pixel centre's ray o + t d, model coordinates.
void havsPixelRayMCd(out dvec3 o, out dvec3 d)
{
  o = havsPixelNearMCd();
  d = havsPixelPointMCd(1.0) - o;
}

// Whether an isovalue lies within `margin` of the scalar range [lo, hi].
bool havsNearIsovalue(float lo, float hi, float margin)
{
  bool near = false;
  for (int n = 0; n < havsIsoCount; ++n)
  {
    near = near || (havsIsoValues[n] >= lo - margin && havsIsoValues[n] <= hi + margin);
  }
  return near;
}

// The barycentric weights (of a, b, c) of the point where the ray o + t d
// meets the plane of triangle abc (Moller and Trumbore); `inside`: whether
// the point lies on the triangle. False where the ray lies within 1e-12 of
// the plane.
bool havsTriangleWeightsd(
  dvec3 o, dvec3 d, dvec3 a, dvec3 b, dvec3 c, out dvec3 w, out bool inside)
{
  inside = false;
  dvec3 e1 = b - a, e2 = c - a;
  dvec3 pv = cross(d, e2);
  double det = dot(e1, pv);
  w = dvec3(1.0, 0.0, 0.0);
  if (!(abs(det) > 1e-12 * length(d) * length(e1) * length(e2)))
  {
    return false;
  }
  dvec3 tv = o - a;
  w.y = dot(tv, pv) / det;
  w.z = dot(d, cross(tv, e1)) / det;
  w.x = 1.0 - w.y - w.z;
  inside = min(w.x, min(w.y, w.z)) >= 0.0;
  return true;
}
#endif

#if HAVS_ISO && !HAVS_CELL_SCALARS && HAVS_ISO_EXACT && defined(HAVS_FACE_PASS)
// Isosurfaces: a face's fragment kept on its face, its distance and scalar
// clamped to the face's own ranges. At a pixel centre just outside a sliver
// seen almost edge-on the rasterizer (vertices snapped to sub-pixel units)
// can still cover the pixel, and the face's plane, extrapolated there, gives
// a point far along the ray with a scalar far outside the face's (the
// combustor, view 3 at 128^2: 0.443 at eye distance 51.2 from a face of
// 0.194 to 0.290, between neighbours at 0.242 and 0.155: two crossings of an
// isovalue the ray never meets; a composite frame weighs such a stretch by
// its length, nothing). The face is gl_PrimitiveID + havsFaceBase of the draw
// order (vtkHAVSGLMesh binds its index buffer and the vertices' scalars and
// points here); -1 draws a plane's section, not clamped. Only in HAVS's face
// passes (HAVS_FACE_PASS: the k-buffer paths' draw shaders).
uniform int havsFaceBase;
uniform mat4 havsMCRC;
layout(std430, binding = 14) readonly buffer HAVSFaceIndices
{
  uint havsFaceIndices[];
};
layout(std430, binding = 15) readonly buffer HAVSVertexScalars
{
  float havsVertexScalars[];
};
layout(std430, binding = 16) readonly buffer HAVSVertexPoints
{
  float havsVertexPoints[];
};

vec3 havsVertexPoint(uint v)
{
  return vec3(havsVertexPoints[3u * v], havsVertexPoints[3u * v + 1u], havsVertexPoints[3u * v + 2u]);
}

vec3 havsVertexRC(uint v)
{
  return (havsMCRC * vec4(havsVertexPoint(v), 1.0)).xyz;
}

// The point of triangle abc nearest the eye (the origin; Ericson, Real-Time
// Collision Detection, 5.1.5).
vec3 havsNearestOnTriangle(vec3 a, vec3 b, vec3 c)
{
  vec3 ab = b - a, ac = c - a;
  float d1 = dot(ab, -a), d2 = dot(ac, -a);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return a;
  }
  float d3 = dot(ab, -b), d4 = dot(ac, -b);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return b;
  }
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return a + d1 / (d1 - d3) * ab;
  }
  float d5 = dot(ab, -c), d6 = dot(ac, -c);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return c;
  }
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return a + d2 / (d2 - d6) * ac;
  }
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
  {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  float w = 1.0 / (va + vb + vc);
  return a + ab * (vb * w) + ac * (vc * w);
}

// The entry e of a face's fragment with its distance and scalar clamped to
// the face's ranges: the scalar's is its vertices'; the distance's top is a
// vertex's (the distance is linear or convex over the face), its bottom a
// vertex's too along a parallel view, the nearest point's along a perspective one.
// The fragment's face (gl_PrimitiveID + havsFaceBase in the draw order): its
// vertices, their scalars and the scalars' range (a tagged boundary face's
// vertices carry + 2, taken off the range).
struct HavsFace
{
  uint i, j, k;
  float si, sj, sk;
  bool tagged;
  float smin, smax;
};

HavsFace havsFragmentFace()
{
  HavsFace face;
  uint f = 3u * uint(gl_PrimitiveID + havsFaceBase);
  face.i = havsFaceIndices[f];
  face.j = havsFaceIndices[f + 1u];
  face.k = havsFaceIndices[f + 2u];
  face.si = havsVertexScalars[face.i];
  face.sj = havsVertexScalars[face.j];
  face.sk = havsVertexScalars[face.k];
  face.tagged = min(face.si, min(face.sj, face.sk)) > 1.5;
  face.smin = min(face.si, min(face.sj, face.sk)) - (face.tagged ? 2.0 : 0.0);
  face.smax = max(face.si, max(face.sj, face.sk)) - (face.tagged ? 2.0 : 0.0);
  return face;
}

HAVS_ENTRY havsClampToFace(HAVS_ENTRY e, HavsFace face)
{
  // (The code's boundary role, + 2 or + 4, kept: it comes from the facing.)
  float role = e.y - havsScalarOf(e.y);
  e.y = role +
    clamp(havsScalarOf(e.y), clamp(face.smin, 0.0, 1.0), clamp(face.smax, 0.0, 1.0));
  vec3 a = havsVertexRC(face.i), b = havsVertexRC(face.j), c = havsVertexRC(face.k);
  float da = havsDistance(a), db = havsDistance(b), dc = havsDistance(c);
  float top = max(da, max(db, dc));
#if HAVS_PROJECTION == 1
  float bottom = min(da, min(db, dc));
#else
  float bottom = havsParallel != 0 ? min(da, min(db, dc)) : length(havsNearestOnTriangle(a, b, c));
#endif
  e.x = clamp(e.x, bottom, top);
  return e;
}

// In isosurface frames a face fragment takes its scalar and distance where
// the pixel centre's ray meets the face, in double (havsTriangleWeightsd):
// both decide which side of a face an isovalue lies on. Where that ray passes
// outside the face (the rasterizer covered the pixel within its snapping) or
// along its plane, the rasterizer's values stay, clamped (havsClampToFace).
HAVS_ENTRY havsOnFace(HAVS_ENTRY e)
{
  if (havsFaceBase < 0)
  {
    return e;
  }
  HavsFace face = havsFragmentFace();
  // Only a face whose scalars come within 1e-2 of an isovalue (of the
  // normalized range: far beyond any rounding or snapping) decides a crossing
  // by a hair; the others keep the rasterizer's values, clamped.
  if (!havsNearIsovalue(face.smin, face.smax, 1e-2))
  {
    return havsClampToFace(e, face);
  }
  dvec3 o, d, w;
  bool inside;
  havsPixelRayMCd(o, d);
  vec3 a = havsVertexPoint(face.i), b = havsVertexPoint(face.j), c = havsVertexPoint(face.k);
  if (!havsTriangleWeightsd(o, d, dvec3(a), dvec3(b), dvec3(c), w, inside) || !inside)
  {
    return havsClampToFace(e, face);
  }
  // (The code's boundary role kept, as havsClampToFace keeps it.)
  float role = e.y - havsScalarOf(e.y);
  double s = w.x * double(face.si) + w.y * double(face.sj) + w.z * double(face.sk) -
    (face.tagged ? 2.0 : 0.0);
  e.y = role + float(clamp(s, 0.0, 1.0));
  // (The distance from the float point in eye-relative coordinates: 1e-7 of
  // it, far below the face fragments' spacing.)
  vec3 p = vec3(w.x * dvec3(a) + w.y * dvec3(b) + w.z * dvec3(c));
  e.x = havsDistance((havsMCRC * vec4(p, 1.0)).xyz);
  return e;
}
#endif

// The k-buffer entry of the fragment being shaded: a mesh face's (tagged by
// the facing of its outward-wound boundary face when tagging is on) or a
// section's (an entry or an exit by its role). With tagging, a boundary face
// is drawn with vertices of its own whose scalar is + 2 (vtkHAVSGLMesh): the
// fragment knows it is on the boundary from its scalar alone.
HAVS_ENTRY havsFaceEntry(vec3 positionRC, float scalar)
{
  float code;
#if HAVS_TAGGING
  if (scalar > 1.5)
  {
    code = clamp(scalar - 2.0, 0.0, 1.0) + (gl_FrontFacing ? 4.0 : 2.0);
  }
  else
#endif
  {
    code = clamp(scalar, 0.0, 1.0);
    if (havsRole == 1)
    {
      code += 4.0;
    }
    else if (havsRole == 2)
    {
      code += 2.0;
    }
  }
#if HAVS_ISO && !HAVS_CELL_SCALARS && HAVS_ISO_EXACT && defined(HAVS_FACE_PASS)
  return havsOnFace(havsEntry(havsDistance(positionRC), code));
#else
  return havsEntry(havsDistance(positionRC), code);
#endif
}

// Back to front, for the fragment-list resolve: a pixel's list comes out in
// reverse draw order, nearly sorted far to near, so the same k-buffer runs
// mirrored. E[0] is the back: the fragment the ray has been integrated from
// (everything behind it is composited); the farthest waiting fragment leaves
// and the segment from it to the back is composited under ("under" operator
// reversed: the new segment goes in front). Exact when the fragments leave in
// depth order, in particular for any list no longer than HAVS_K - 1.
void havsRetreat(inout vec4 color, inout HAVS_ENTRY back, HAVS_ENTRY p, float opaqueDistance)
{
#if HAVS_COUNT_VIOLATIONS
  if (back.x > HAVS_NO_FRONT && p.x > back.x + HAVS_TIE * abs(back.x))
  {
    havsCountViolation();
  }
#endif
#if HAVS_CELL_SCALARS
  if (back.x > HAVS_NO_FRONT && p.x > back.x + HAVS_CELL_TIE * abs(back.x))
#else
  if (back.x > HAVS_NO_FRONT && p.x > back.x)
#endif
  {
    return; // beyond the back (out of order): see havsAdvance
  }
  if (back.x > HAVS_NO_FRONT && p.x < opaqueDistance)
  {
    HAVS_ENTRY b = back;
    if (back.x > opaqueDistance)
    {
      float t = clamp((opaqueDistance - p.x) / (back.x - p.x), 0.0, 1.0);
      b = havsCut(p, back, opaqueDistance, t);
    }
    vec4 segment = havsSegment(p, b);
    color = segment + (1.0 - segment.a) * color;
  }
  back = p;
}

// Back to front, the grazing exit's rule of havsAdvance read the other way:
// an internal fragment that leaves with an exit just in front of it (`next`,
// the one to leave after it, within HAVS_GRAZE) takes the exit's role, so the
// segment behind it is empty, as front to back. (The fragment-list resolve:
// blunt fin, 1024^2, view 0, pixel (524, 363) was 0.142 off without it.)
HAVS_ENTRY havsGrazeRole(HAVS_ENTRY leaving, HAVS_ENTRY next)
{
#if HAVS_TAGGING
  if (next.x < HAVS_EMPTY && havsIsExit(next.y) && leaving.y < 1.5 &&
    leaving.x - next.x < HAVS_GRAZE * abs(next.x))
  {
    leaving.y += 2.0;
  }
#endif
  return leaving;
}

void havsInsertBackToFront(inout vec4 color, inout HAVS_ENTRY E[HAVS_K], HAVS_ENTRY f, float opaqueDistance)
{
  HAVS_ENTRY leaving = f;
  int farthest = 0;
  float leavingKey = havsLeaveKey(f);
  HAVS_ENTRY next = havsEntry(HAVS_EMPTY, 0.0); // the farthest of those that stay
  float nextKey = HAVS_NO_FRONT;
  for (int i = 1; i < HAVS_K; ++i)
  {
    if (E[i].x >= HAVS_EMPTY)
    {
      E[i] = f;
      return;
    }
    float key = havsLeaveKey(E[i]);
    if (key > leavingKey)
    {
      next = leaving;
      nextKey = leavingKey;
      leaving = E[i];
      leavingKey = key;
      farthest = i;
    }
    else if (key > nextKey)
    {
      next = E[i];
      nextKey = key;
    }
  }
  if (farthest > 0)
  {
    E[farthest] = f;
  }
  havsRetreat(color, E[0], havsGrazeRole(leaving, next), opaqueDistance);
}

void havsFlushBackToFront(inout vec4 color, inout HAVS_ENTRY E[HAVS_K], float opaqueDistance)
{
  for (int n = 1; n < HAVS_K; ++n)
  {
    int farthest = 0, second = 0;
    float farthestKey = HAVS_NO_FRONT, secondKey = HAVS_NO_FRONT;
    for (int i = 1; i < HAVS_K; ++i)
    {
      float key = E[i].x < HAVS_EMPTY ? havsLeaveKey(E[i]) : HAVS_NO_FRONT;
      if (key > farthestKey)
      {
        second = farthest;
        secondKey = farthestKey;
        farthestKey = key;
        farthest = i;
      }
      else if (key > secondKey)
      {
        secondKey = key;
        second = i;
      }
    }
    if (farthest == 0)
    {
      return;
    }
    HAVS_ENTRY next = second > 0 ? E[second] : havsEntry(HAVS_EMPTY, 0.0);
    havsRetreat(color, E[0], havsGrazeRole(E[farthest], next), opaqueDistance);
    E[farthest].x = HAVS_EMPTY;
  }
}
