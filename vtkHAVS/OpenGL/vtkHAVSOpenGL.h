/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSOpenGL.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSOpenGL.h
 * @brief The OpenGL header of the VTK vtkHAVS is built against: VTK < 9.4
 * loads GL through GLEW (vtk_glew.h), newer VTK through glad (vtk_glad.h).
 */
#ifndef vtkHAVSOpenGL_h
#define vtkHAVSOpenGL_h

#include "vtkVersionMacros.h"

#if VTK_MAJOR_VERSION > 9 || (VTK_MAJOR_VERSION == 9 && VTK_MINOR_VERSION >= 4)
#include "vtk_glad.h" // IWYU pragma: export
#else
#include "vtk_glew.h" // IWYU pragma: export
#define VTKHAVS_USES_GLEW 1
#endif

#endif
