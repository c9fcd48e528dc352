#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: translucent layers intermixed with the volume (vtkHAVSIntermixPass).
// The volume is drawn once per slab: slab i cut at layer i's depth (the
// opaque geometry's cut, as every mapper ends its rays), the last slab at the
// opaque geometry. Each draw's result V_i is the volume from the eye to that
// depth; the volume between two cuts is V_i - V_(i-1) (front to back, the
// piece behind the first cut is already weighted by the volume in front of
// it). This pass adds it, under the layers in front of it (their
// transmittance T), then layer i, under the volume in front of it and the
// earlier layers:
//   S += T * (V_i - V_(i-1));  S += T * (1 - V_i.a) * (a_i c_i, a_i);  T *= 1 - a_i.
// The last slab writes S into the result (then composited as any frame).
// One invocation per pixel, reading and writing only its own texels.
layout(rgba32f, binding = 0) uniform image2D havsIntermixResult;   // V_i; S after the last slab
layout(rgba32f, binding = 1) uniform image2D havsIntermixSum;      // S
layout(rgba32f, binding = 2) uniform image2D havsIntermixPrevious; // V_(i-1)
layout(r32f, binding = 3) uniform image2D havsIntermixTransmittance; // T of the layers so far

uniform sampler2D havsLayerColor; // layer i: colour (not premultiplied), opacity
uniform vec2 havsViewportOrigin;
uniform int havsIntermixFirst; // slab 0: nothing before it
uniform int havsIntermixLast;  // the slab up to the opaque geometry: no layer behind it

void main()
{
  ivec2 pixel = ivec2(floor(gl_FragCoord.xy - havsViewportOrigin));
  vec4 volume = imageLoad(havsIntermixResult, pixel);
  vec4 previous = havsIntermixFirst != 0 ? vec4(0.0) : imageLoad(havsIntermixPrevious, pixel);
  float transmittance =
    havsIntermixFirst != 0 ? 1.0 : imageLoad(havsIntermixTransmittance, pixel).r;
  vec4 sum = havsIntermixFirst != 0 ? vec4(0.0) : imageLoad(havsIntermixSum, pixel);
  sum += transmittance * (volume - previous);
  if (havsIntermixLast != 0)
  {
    imageStore(havsIntermixResult, pixel, sum);
    return;
  }
  vec4 layer = texelFetch(havsLayerColor, pixel, 0);
  float a = clamp(layer.a, 0.0, 1.0);
  float w = transmittance * (1.0 - volume.a) * a;
  sum += vec4(w * layer.rgb, w);
  imageStore(havsIntermixSum, pixel, sum);
  imageStore(havsIntermixPrevious, pixel, volume);
  imageStore(havsIntermixTransmittance, pixel, vec4(transmittance * (1.0 - a)));
}
