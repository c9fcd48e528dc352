/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSABINamespace.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSABINamespace.h
 * @brief VTK's ABI namespace for vtkHAVS's classes, as VTK's own modules use it.
 *
 * Since VTK 9.3 every VTK class is declared between VTK_ABI_NAMESPACE_BEGIN
 * and VTK_ABI_NAMESPACE_END (vtkABINamespace.h, through vtkABI.h): a VTK built
 * with an ABI namespace (VTK_ABI_NAMESPACE_NAME) puts its classes in it, so
 * that two VTKs can live in one process. vtkHAVS's headers and sources wrap
 * their classes, and their forward declarations of VTK's, the same way. VTK
 * 9.2 has no ABI namespace: the macros are empty there. Part of the VTK shim
 * (with vtkHAVSVTKCompat.h and vtkHAVSOpenGL.h).
 */
#ifndef vtkHAVSABINamespace_h
#define vtkHAVSABINamespace_h

#include "vtkABI.h" // VTK >= 9.3: vtkABINamespace.h

#ifndef VTK_ABI_NAMESPACE_BEGIN // VTK 9.2
#define VTK_ABI_NAMESPACE_BEGIN
#define VTK_ABI_NAMESPACE_END
#endif

#endif
// VTK-HeaderTest-Exclude: vtkHAVSABINamespace.h
