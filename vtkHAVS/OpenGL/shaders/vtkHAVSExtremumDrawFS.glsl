#version 430 core
// Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
// vtkHAVS: maximum / minimum intensity draw pass. No sorting is needed: the
// scalar is linear inside each tetrahedron, so its extremum along a ray lies
// on a face; blending with GL_MAX (of 1 - s for the minimum) over the face fragments in front
// of the opaque geometry finds it.
//HAVS::Defines
//HAVS::KBufferLib

in vec3 havsPositionRC;
HAVS_FACE_SCALAR_INPUT

uniform int havsMinimum; // 1: store 1 - s, so that GL_MAX finds the minimum

layout(location = 0) out vec4 havsExtremum;

void main()
{
  if (havsClipped(havsPositionRC) ||
    havsDistance(havsPositionRC) > havsOpaqueDistance(gl_FragCoord.xy))
  {
    discard;
  }
  // (+ 2 on a boundary face's own vertices, see vtkHAVSGLMesh::UploadFaceOrder)
  float scalar = havsFaceScalar();
  float s = clamp(scalar > 1.5 ? scalar - 2.0 : scalar, 0.0, 1.0);
  havsExtremum = vec4(havsMinimum != 0 ? 1.0 - s : s, 1.0, 0.0, 0.0);
}
