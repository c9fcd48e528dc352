/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSOpenGL.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSOpenGL.h
 * @brief The OpenGL side of vtkHAVS's VTK shim: the GL header of the VTK
 * vtkHAVS is built against (VTK < 9.4 loads GL through GLEW, vtk_glew.h;
 * newer VTK through glad, vtk_glad.h) and how a window of ours hands its
 * context's symbol loader to VTK (glad needs one; GLEW finds the symbols
 * itself). The GL-free part of the shim is vtkHAVSVTKCompat.h (Core).
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

#include "vtkOpenGLRenderWindow.h"

namespace havs_gl
{
/// A context API's getProcAddress (eglGetProcAddress, glfwGetProcAddress,
/// OSMesaGetProcAddress all have this type).
using GetProcAddressFunction = void (*(*)(const char*))();

/**
 * Gives `window` the context API's symbol loader, which VTK >= 9.4
 * (`vtkOpenGLRenderWindow::SetOpenGLSymbolLoader`, glad) needs before
 * OpenGLInit() to load GL from a context it did not make; with GLEW (VTK < 9.4)
 * nothing is needed and nothing is done.
 */
inline void SetSymbolLoader(vtkOpenGLRenderWindow* window, GetProcAddressFunction getProc)
{
#if defined(VTKHAVS_USES_GLEW)
  (void)window;
  (void)getProc;
#else
  window->SetOpenGLSymbolLoader(
    [](void* user, const char* name) -> vtkOpenGLRenderWindow::VTKOpenGLAPIProc
    { return reinterpret_cast<GetProcAddressFunction>(user)(name); },
    reinterpret_cast<void*>(getProc));
#endif
}
}

#endif
