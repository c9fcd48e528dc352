/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestViews.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestViews.h
 * @brief View frames for the GL-free tests of the face orders.
 */
#ifndef havsTestViews_h
#define havsTestViews_h

#include "vtkHAVSViewFrame.h"

namespace havstest
{
/// A perspective view from `eye` towards `centre`, no volume matrix, every
/// matrix the identity, 64 x 64 pixels.
vtkHAVSViewFrame PerspectiveView(const double eye[3], const double centre[3]);
}

#endif
