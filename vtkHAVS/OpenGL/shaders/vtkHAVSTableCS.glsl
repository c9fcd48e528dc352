#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: the pre-integrated table built on the GPU (vtkHAVSGLTableBuilder,
// issue 45), the same windowed quadrature as vtkHAVSPreIntegrationTable::Build
// in single precision. One work group per (j, l, direction): j = |b - f|
// table intervals (0: the diagonal), length layer l. Its threads composite
// every table interval's sub-steps at that j and l (a sub-step's world
// length is its scalar span times L_l (NS - 1) / j), then every entry of
// that j is the composite of j consecutive intervals, a sliding window:
// each block of j intervals' prefix and suffix composites (van Herk /
// Gil-Werman), an entry one suffix over one prefix.
//HAVS::Defines
// HAVS_CELLS: NS - 1, the table's scalar intervals; HAVS_LOCAL: the work group's size.
layout(local_size_x = HAVS_LOCAL) in;

layout(std430, binding = 0) readonly buffer havsSampleBuffer
{
  vec4 havsSamples[]; // per fine sample: tau, red, green, blue
};
layout(std430, binding = 1) readonly buffer havsStepBuffer
{
  float havsStepDepth[]; // per sub-step: tau's integral over its normalized span
};
layout(std430, binding = 2) readonly buffer havsTableSampleBuffer
{
  int havsTableSample[]; // per table scalar: its fine sample
};
layout(std430, binding = 3) readonly buffer havsLayerBuffer
{
  float havsLayerLength[]; // per length layer: the segment length
};
layout(rgba32f, binding = 0) writeonly uniform image3D havsTableImage;

// A composited stretch: premultiplied colour, and its optical depth (in .a)
// rather than its transmittance: a product of hundreds of attenuations
// exp(-x) near 1, each rounded, drifts by 1e-5 in single precision, their
// exponents' sum does not.
shared vec4 havsItems[HAVS_CELLS];    // the intervals, then their blocks' suffixes
shared vec4 havsPrefixes[HAVS_CELLS]; // the blocks' prefixes

vec4 havsOver(vec4 front, vec4 back)
{
  return vec4(front.rgb + exp(-front.a) * back.rgb, front.a + back.a);
}

// 1 - exp(-x): its series where the difference would cancel (x < 0.1,
// truncated by less than 2e-9 of it).
float havsOpacity(float x)
{
  return x < 0.1 ? x * (1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x * (1.0 / 120.0)))))
                 : 1.0 - exp(-x);
}

// A sub-step's end weights up to a common factor (StepWeights): its front
// end's and its back end's, for optical depth x and attenuation a. Below
// x = 1, where 1 - (1 - a) / x cancels in single precision, their series
// (the sums over n of (-x)^n / (n + 2)! and (n + 1) (-x)^n / (n + 2)!, to
// n = 7: truncated by less than 3e-7 of 1/2).
vec2 havsStepWeights(float x, float a)
{
  if (x < 1.0)
  {
    const float front = 0.5 -
      x * (1.0 / 6.0 -
            x * (1.0 / 24.0 -
                  x * (1.0 / 120.0 -
                        x * (1.0 / 720.0 -
                              x * (1.0 / 5040.0 - x * (1.0 / 40320.0 - x * (1.0 / 362880.0)))))));
    const float back = 0.5 -
      x * (1.0 / 3.0 -
            x * (1.0 / 8.0 -
                  x * (1.0 / 30.0 -
                        x * (1.0 / 144.0 -
                              x * (1.0 / 840.0 - x * (1.0 / 5760.0 - x * (1.0 / 45360.0)))))));
    return vec2(front, back);
  }
  const float r = (1.0 - a) / x;
  return vec2(1.0 - r, r - a);
}

// A sub-step's premultiplied colour (StepColor, unattenuated) from its
// front and back samples, weights w and opacity.
vec3 havsStepColor(vec4 front, vec4 back, vec2 w, float opacity)
{
  float wf = w.x * front.x, wb = w.y * back.x;
  return opacity / max(wf + wb, 1e-30) * (wf * front.yzw + wb * back.yzw);
}

void main()
{
  const int cells = HAVS_CELLS;
  const int j = int(gl_WorkGroupID.x);
  const int l = int(gl_WorkGroupID.y);
  const bool forward = gl_WorkGroupID.z == 0u;
  const int thread = int(gl_LocalInvocationID.x);
  const float length = havsLayerLength[l];
  if (j == 0)
  {
    // The diagonal: one sub-step of the constant optics at f.
    if (forward)
    {
      for (int f = thread; f <= cells; f += HAVS_LOCAL)
      {
        vec4 s = havsSamples[havsTableSample[f]];
        float opacity = havsOpacity(s.x * length);
        imageStore(havsTableImage, ivec3(f, f, l), vec4(opacity * s.yzw, opacity));
      }
    }
    return;
  }
  // World length per unit normalized scalar.
  const float scale = float(cells) / float(j) * length;
  // The intervals front to back: forward, interval i's sub-steps in
  // increasing order at i; backward, in decreasing order at cells - 1 - i.
  for (int i = thread; i < cells; i += HAVS_LOCAL)
  {
    vec4 c = vec4(0.0); // colour, optical depth
    float transmittance = 1.0;
    const int first = havsTableSample[i], end = havsTableSample[i + 1];
    for (int k = first; k < end; ++k)
    {
      const vec4 lower = havsSamples[k], upper = havsSamples[k + 1];
      const float x = havsStepDepth[k] * scale;
      const float a = exp(-x);
      const float opacity = havsOpacity(x);
      const vec2 w = havsStepWeights(x, a);
      if (forward)
      {
        c.rgb += transmittance * havsStepColor(lower, upper, w, opacity); // the lower end in front
        transmittance *= a;
      }
      else
      {
        c.rgb = havsStepColor(upper, lower, w, opacity) + a * c.rgb; // this sub-step in front
      }
      c.a += x;
    }
    havsItems[forward ? i : cells - 1 - i] = c;
  }
  barrier();
  // Each block of j intervals: its prefixes, and its suffixes in place.
  for (int block = thread * j; block < cells; block += HAVS_LOCAL * j)
  {
    const int last = min(block + j, cells) - 1;
    havsPrefixes[block] = havsItems[block];
    for (int p = block + 1; p <= last; ++p)
    {
      havsPrefixes[p] = havsOver(havsPrefixes[p - 1], havsItems[p]);
    }
    for (int p = last - 1; p >= block; --p)
    {
      havsItems[p] = havsOver(havsItems[p], havsItems[p + 1]);
    }
  }
  barrier();
  // Every window of j intervals: forward, entry (s, s + j); backward, the
  // intervals cells - 1 - s down to cells - s - j, entry (cells - s, cells - s - j).
  for (int s = thread; s + j <= cells; s += HAVS_LOCAL)
  {
    const vec4 w = s % j == 0 ? havsItems[s] : havsOver(havsItems[s], havsPrefixes[s + j - 1]);
    const int f = forward ? s : cells - s;
    imageStore(havsTableImage, ivec3(f, forward ? f + j : f - j, l), vec4(w.rgb, havsOpacity(w.a)));
  }
}
