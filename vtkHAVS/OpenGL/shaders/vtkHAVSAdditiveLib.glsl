// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: the additive blend's per-segment integral of tau(s) s, shared by
// the cell projection and the ray caster (inserted at the AdditiveLib marker).
// (g, G) at evenly spaced normalized scalars: g = tau(s) s, G its integral
// (vtkHAVSPreIntegrationTable::GetAdditive1D).
uniform sampler1D havsAdditive;

vec2 havsAdditiveNode(int i)
{
  return texelFetch(havsAdditive, i, 0).xy;
}

// G(s), exact for g linear between the nodes.
float havsAdditiveIntegral(float s, float h, int last)
{
  float x = s / h;
  int i = clamp(int(floor(x)), 0, last - 1);
  float f = x - float(i);
  vec2 a = havsAdditiveNode(i);
  float gb = havsAdditiveNode(i + 1).x;
  return a.y + h * (a.x * f + 0.5 * (gb - a.x) * f * f);
}

// The segment's integral of tau(s) s: its length times the mean of g.
// Cell scalars: both are the cell's code; g at the cell's value
// (vtkHAVSCellOptics).
float havsAdditiveSegment(float sFront, float sBack, float len)
{
#if HAVS_CELL_SCALARS
  return texelFetch(havsCellOptics, 2 * havsCellIndex(sFront) + 1).z * len;
#else
  int last = textureSize(havsAdditive, 0) - 1;
  float h = 1.0 / float(last);
  float ds = sBack - sFront;
  float mean;
  if (abs(ds) > h)
  {
    mean = (havsAdditiveIntegral(sBack, h, last) - havsAdditiveIntegral(sFront, h, last)) / ds;
  }
  else
  {
    // Within about one node: g at the middle (linear), no cancellation.
    float x = 0.5 * (sFront + sBack) / h;
    int i = clamp(int(floor(x)), 0, last - 1);
    mean = mix(havsAdditiveNode(i).x, havsAdditiveNode(i + 1).x, x - float(i));
  }
  return mean * len;
#endif
}
