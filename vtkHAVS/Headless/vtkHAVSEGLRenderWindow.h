/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSEGLRenderWindow.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSEGLRenderWindow
 * @brief   Headless render window on an EGL context with no surface.
 *
 * Debian's VTK (the one ParaView 5.11 ships) is built for GLX and loads GL
 * through GLEW, so it has no EGL window of its own. This window creates an
 * OpenGL (core, highest of 4.6 … 3.2) context on an EGL display that needs no
 * X server — `EGL_MESA_platform_surfaceless` (Mesa: llvmpipe or a GPU), then
 * `EGL_EXT_platform_device` (NVIDIA), then the default display — makes it
 * current with no surface (`EGL_KHR_surfaceless_context`) and lets VTK render
 * into its own framebuffer objects.
 *
 * Two things differ from a stock VTK window, both needed with GLEW:
 * - `glewInit()` returns `GLEW_ERROR_NO_GLX_DISPLAY` when no GLX context is
 *   current, after it has loaded every GL entry point; VTK treats any error as
 *   fatal. OpenGLInitContext() accepts exactly that one error (only for VTK
 *   built with GLEW; VTK >= 9.4 loads GL with glad and has EGL windows).
 * - There is no default framebuffer, so the frame blit mode is NoBlit; images
 *   are read back from VTK's own framebuffers as usual.
 *
 * Under GLVND one context is current per thread for GLX, EGL and
 * vtkHAVSOSMesaRenderWindow together, and libEGL refuses while another holds
 * the thread: MakeCurrent() releases a current GLX context or OSMesa window
 * first.
 *
 * Use vtkHAVSRenderWindowFactory rather than this class directly: it picks
 * this window, or another backend where asked.
 */
#ifndef vtkHAVSEGLRenderWindow_h
#define vtkHAVSEGLRenderWindow_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSHeadlessModule.h" // For export macro
#include "vtkHAVSSurfacelessRenderWindow.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSHEADLESS_EXPORT vtkHAVSEGLRenderWindow : public vtkHAVSSurfacelessRenderWindow
{
public:
  static vtkHAVSEGLRenderWindow* New();
  vtkTypeMacro(vtkHAVSEGLRenderWindow, vtkHAVSSurfacelessRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * True when an EGL display and an OpenGL >= 3.2 core context can be made on
   * this machine (tried once per process, then remembered).
   */
  static bool IsAvailable();

  /**
   * What the probe of IsAvailable() found, in a sentence: the EGL platform and
   * the renderer, or that no context can be made.
   */
  static std::string GetProbeReport();

  /**
   * Creates the EGL context if needed, makes it current and initializes VTK's
   * OpenGL state.
   */
  void Initialize() override;

  /**
   * Makes the context current (creating it on first use), then renders.
   */
  void Render() override;

  ///@{
  /**
   * The context is this window's own; these do not go through observers.
   */
  void MakeCurrent() override;
  bool IsCurrent() override;
  int SupportsOpenGL() override;
  ///@}

  /**
   * Releases the graphics resources of every renderer and destroys the context.
   */
  void Finalize() override;

  /**
   * Which EGL platform the context was made on ("surfaceless", "device",
   * "default"), empty before Initialize().
   */
  std::string GetPlatformName() const;

protected:
  vtkHAVSEGLRenderWindow();
  ~vtkHAVSEGLRenderWindow() override;

  const char* GetContextName() const override;

private:
  vtkHAVSEGLRenderWindow(const vtkHAVSEGLRenderWindow&) = delete;
  void operator=(const vtkHAVSEGLRenderWindow&) = delete;

  bool CreateContext();
  void DestroyContext();

  struct ProbeResult;
  static const ProbeResult& Probe();

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

VTK_ABI_NAMESPACE_END
#endif
