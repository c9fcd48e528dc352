/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSOSMesaRenderWindow.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSOSMesaRenderWindow
 * @brief   Headless render window on a Mesa OSMesa (off-screen, software) context.
 *
 * Built only when OSMesa (`osmesa.pc` / libOSMesa) is found at configure time.
 * The window creates an OSMesa OpenGL core context (highest of 4.5 … 3.2),
 * makes it current on a buffer in memory and lets VTK render into its own
 * framebuffer objects, as vtkHAVSEGLRenderWindow does with EGL.
 *
 * Debian's VTK (ParaView 5.11's) has no OSMesa window of its own
 * (`VTK_OPENGL_HAS_OSMESA` is not defined) and reaches GL through GLVND:
 * GLEW loads every entry point with `glXGetProcAddressARB` (libGLX), which
 * returns libGLdispatch's stubs, and VTK calls the GL 1.1 functions from
 * libOpenGL, also libGLdispatch's stubs. Those stubs call the dispatch table
 * that libGLdispatch holds as current, and `OSMesaMakeCurrent` never sets it
 * (OSMesa uses Mesa's own libglapi): with OSMesa alone every such call is a
 * no-op (`glGetString(GL_RENDERER)` gives NULL, `glClear` leaves the buffer
 * untouched). This window therefore also makes a libGLdispatch table current
 * whose entries are `OSMesaGetProcAddress`'s, through libGLdispatch's
 * window-system interface (the one libGLX and libEGL use, ABI version 1;
 * checked at run time). Without GLVND (a libGL that is Mesa's own) nothing of
 * this is needed and nothing is done.
 *
 * libGLdispatch holds one current context per thread for all of GLX, EGL and
 * this window, and libGLX and libEGL refuse to make a context current while
 * another API holds the thread (GLX: an X error, BadAccess on
 * X_GLXMakeCurrent, which ends the program). So: making this window current
 * releases the thread's GLX or EGL context first; the window hands the thread
 * back at the end of each Render() and of each pixel or depth read;
 * vtkHAVSEGLRenderWindow takes it back itself. After anything else that makes
 * this window current (MakeCurrent() by hand, releasing graphics resources),
 * call ReleaseContext() before a GLX window renders on the same thread.
 *
 * IsAvailable() checks that it really renders: the renderer string through
 * both ways VTK calls GL, and a clear colour found in OSMesa's buffer.
 *
 * Use vtkHAVSRenderWindowFactory (`HAVS_RENDER_WINDOW=osmesa`) rather than this
 * class directly. EGL surfaceless (vtkHAVSEGLRenderWindow) renders with the
 * same llvmpipe and needs none of the above; prefer it where it exists.
 */
#ifndef vtkHAVSOSMesaRenderWindow_h
#define vtkHAVSOSMesaRenderWindow_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSHeadlessModule.h" // For export macro
#include "vtkHAVSSurfacelessRenderWindow.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSHEADLESS_EXPORT vtkHAVSOSMesaRenderWindow : public vtkHAVSSurfacelessRenderWindow
{
public:
  static vtkHAVSOSMesaRenderWindow* New();
  vtkTypeMacro(vtkHAVSOSMesaRenderWindow, vtkHAVSSurfacelessRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * True when an OSMesa OpenGL >= 3.2 core context can be made and renders
   * through the calls VTK makes (probed once per process, then remembered; not
   * probed, and false, while a GLX or EGL context is current on this thread).
   */
  static bool IsAvailable();

  /**
   * What the probe of IsAvailable() found, in a sentence: the renderer and
   * version and the dispatch route, or why OSMesa cannot be used.
   */
  static std::string GetProbeReport();

  /**
   * Creates the OSMesa context if needed, makes it current and initializes
   * VTK's OpenGL state.
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

  ///@{
  /**
   * Reads the depth (VTK makes the window current for it); the thread's
   * libGLdispatch state is handed back after, as after Render().
   */
  using Superclass::GetZbufferData;
  int GetZbufferData(int x1, int y1, int x2, int y2, float* z) override;
  ///@}

  /**
   * Makes no context current on this thread (neither OSMesa's nor
   * libGLdispatch's), so that a GLX or EGL window can be made current.
   */
  void ReleaseContext();

  /**
   * Releases the graphics resources of every renderer, releases the context
   * (OSMesa's and libGLdispatch's) and destroys it.
   */
  void Finalize() override;

  /**
   * How GL calls reach the context: "glvnd" (a libGLdispatch table made
   * current), "direct" (no GLVND in this process), empty before Initialize().
   */
  std::string GetDispatchRoute() const;

protected:
  vtkHAVSOSMesaRenderWindow();
  ~vtkHAVSOSMesaRenderWindow() override;

  const char* GetContextName() const override;

  /**
   * Every colour read of VTK's (GetPixelData, GetRGBACharPixelData, …) comes
   * here; the thread's libGLdispatch state is handed back after.
   */
  int ReadPixels(
    const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right = 0) override;

private:
  vtkHAVSOSMesaRenderWindow(const vtkHAVSOSMesaRenderWindow&) = delete;
  void operator=(const vtkHAVSOSMesaRenderWindow&) = delete;

  bool CreateContext();
  void DestroyContext();

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

VTK_ABI_NAMESPACE_END
#endif
