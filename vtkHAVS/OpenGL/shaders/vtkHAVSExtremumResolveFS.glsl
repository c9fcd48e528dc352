#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: maximum / minimum intensity resolve: colour and opacity of the
// extremal scalar from the sampled transfer function. Additive
// (havsAdditiveResolve, vtkHAVSCellProjectionMapper): the summed integral of
// tau(s) s, clamped to 1, as grey with opacity 1 where a ray crossed the mesh
// (VTK's additive blend: vec4(vec3(clamp(sum, 0, 1)), 1)).
// Cell scalars (HAVS_CELL_SCALARS): the extremum is a cell code
// (vtkHAVSCellOptics), coloured from the functions at that cell's value.
//HAVS::Defines
uniform sampler2D havsExtremumTexture;
uniform sampler1D havsTransferFunction; // rgb colour, opacity
uniform vec2 havsScalarTexel;
uniform int havsMinimum;
uniform int havsAdditiveResolve;
#if HAVS_CELL_SCALARS
//HAVS::CellOpticsLib
#endif

layout(location = 0) out vec4 havsResult;

void main()
{
  vec4 e = texelFetch(havsExtremumTexture, ivec2(gl_FragCoord.xy), 0);
  if (e.y < 0.5)
  {
    havsResult = vec4(0.0);
    return;
  }
  if (havsAdditiveResolve != 0)
  {
    havsResult = vec4(vec3(clamp(e.x, 0.0, 1.0)), 1.0);
    return;
  }
  float s = havsMinimum != 0 ? 1.0 - e.x : e.x;
#if HAVS_CELL_SCALARS
  int i = havsCellIndex(s);
  vec4 c = vec4(texelFetch(havsCellOptics, 2 * i).rgb, texelFetch(havsCellOptics, 2 * i + 1).y);
#else
  vec4 c = texture(havsTransferFunction, s * havsScalarTexel.x + havsScalarTexel.y);
#endif
  havsResult = vec4(c.rgb * c.a, c.a);
}
