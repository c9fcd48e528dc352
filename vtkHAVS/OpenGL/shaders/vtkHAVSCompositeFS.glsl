#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: composites the volume's premultiplied result over VTK's
// framebuffer (blend ONE, ONE_MINUS_SRC_ALPHA set by the mapper). The one
// pass of all three mappers where the volume's shader property applies
// (vtkHAVSShaderHooks): its custom uniforms, the user's declarations and
// the user's exit code on g_fragColor, under vtkOpenGLGPUVolumeRayCastMapper's
// tag names.
layout(location = 0) out vec4 havsOut;

uniform sampler2D havsResultTexture;
uniform vec2 havsViewportOrigin;
uniform vec2 havsResultScale; // drawn pixels per viewport pixel (the level of detail's image)
uniform int havsResultReduced;
uniform ivec2 havsResultLast; // the drawn image's last texel (the texture is the viewport's size)
// The coverage mask at the viewport's size (vtkHAVSCoverageFS): 0 where the
// exact image gets nothing from the volume; havsUseCoverage: drawn this frame.
uniform sampler2D havsCoverageTexture;
uniform int havsUseCoverage;

// The reduced image at a viewport pixel: bilinear between the four drawn
// pixel centres around it (premultiplied colours, so coverage blends too),
// clamped at the drawn image's edges.
vec4 havsUpsampled(vec2 pixel)
{
  vec2 x = (pixel + 0.5) * havsResultScale - 0.5;
  ivec2 last = havsResultLast;
  ivec2 i0 = clamp(ivec2(floor(x)), ivec2(0), last);
  ivec2 i1 = clamp(ivec2(floor(x)) + 1, ivec2(0), last);
  vec2 f = clamp(x - floor(x), 0.0, 1.0);
  vec4 a = mix(texelFetch(havsResultTexture, i0, 0),
    texelFetch(havsResultTexture, ivec2(i1.x, i0.y), 0), f.x);
  vec4 b = mix(texelFetch(havsResultTexture, ivec2(i0.x, i1.y), 0),
    texelFetch(havsResultTexture, i1, 0), f.x);
  return mix(a, b, f.y);
}

// The reduced image at a viewport pixel, with the coverage mask: empty where
// no ray meets the volume (outside its silhouette, behind opaque geometry),
// as the exact image is there, instead of the reduced image's blur; bilinear
// where one does. (Not a weight over the covered drawn pixels only: a
// volume's opacity fades to its silhouette as the rays' paths through it
// shorten, and such a weight spreads the inner values out to the edge.)
vec4 havsReduced(vec2 pixel)
{
  if (havsUseCoverage == 0)
  {
    return havsUpsampled(pixel);
  }
  return texelFetch(havsCoverageTexture, ivec2(pixel), 0).r > 0.5 ? havsUpsampled(pixel)
                                                                  : vec4(0.0);
}

//VTK::CustomUniforms::Dec

//VTK::Base::Dec

void main()
{
  vec2 pixel = floor(gl_FragCoord.xy - havsViewportOrigin);
  vec4 g_fragColor = havsResultReduced != 0 ? havsReduced(pixel)
                                            : texelFetch(havsResultTexture, ivec2(pixel), 0);

  //VTK::Base::Exit

  havsOut = g_fragColor;
}
