/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSSurfacelessRenderWindow.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSSurfacelessRenderWindow
 * @brief   The part of a headless window that does not depend on its context's API.
 *
 * The common base of vtkHAVSEGLRenderWindow (an EGL context with no surface)
 * and vtkHAVSOSMesaRenderWindow (an OSMesa buffer VTK never draws to): VTK
 * renders into its own framebuffer objects, so
 * - Frame() presents nothing (it keeps VTK's framebuffer bindings in sync);
 * - GetColorBufferSizes() reports RGBA8 when no framebuffer object is bound
 *   (there is no default framebuffer to ask);
 * - OpenGLInitContext(), for VTK built with GLEW (Debian's 9.2 and 9.3),
 *   accepts the one error `glewInit()` returns after loading every GL entry
 *   point when no GLX display exists (`GLEW_ERROR_NO_GLX_DISPLAY`), which VTK
 *   would treat as fatal, and asks for OpenGL 3.2.
 * Subclasses make, bind and destroy their context and name it
 * (GetContextName(), for the messages).
 */
#ifndef vtkHAVSSurfacelessRenderWindow_h
#define vtkHAVSSurfacelessRenderWindow_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkHAVSHeadlessModule.h" // For export macro

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSHEADLESS_EXPORT vtkHAVSSurfacelessRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  vtkTypeMacro(vtkHAVSSurfacelessRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * No surface to present or to be indirect about.
   */
  vtkTypeBool IsDirect() override;
  void Frame() override;
  ///@}

  /**
   * With no framebuffer object bound there is no default framebuffer to ask:
   * VTK's own render framebuffers are RGBA8, reported as such.
   */
  int GetColorBufferSizes(int* rgba) override;

protected:
  vtkHAVSSurfacelessRenderWindow() = default;
  ~vtkHAVSSurfacelessRenderWindow() override = default;

  /// GLEW tolerated as described above; otherwise VTK's own.
  void OpenGLInitContext() override;

  /// The context's API, for messages ("EGL", "OSMesa").
  virtual const char* GetContextName() const = 0;

private:
  vtkHAVSSurfacelessRenderWindow(const vtkHAVSSurfacelessRenderWindow&) = delete;
  void operator=(const vtkHAVSSurfacelessRenderWindow&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif
