/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestViews.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestViews.h"

#include "vtkMatrix4x4.h"

#include <cmath>

namespace havstest
{
vtkHAVSViewFrame PerspectiveView(const double eye[3], const double centre[3])
{
  vtkHAVSViewFrame v;
  vtkMatrix4x4::Identity(v.GridToWorld);
  vtkMatrix4x4::Identity(v.GridToClip);
  vtkMatrix4x4::Identity(v.ModelToEyeRelative);
  vtkMatrix4x4::Identity(v.ModelToClip);
  vtkMatrix4x4::Identity(v.ClipToEyeRelative);
  double d[3], n = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    v.EyeWorld[k] = v.EyeGrid[k] = eye[k];
    d[k] = centre[k] - eye[k];
    n += d[k] * d[k];
  }
  for (int k = 0; k < 3; ++k)
  {
    v.DirectionWorld[k] = v.DirectionGrid[k] = d[k] / std::sqrt(n);
  }
  v.Width = v.Height = 64;
  return v;
}
}
