/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRenderWindowFactory.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSRenderWindowFactory
 * @brief   Makes the render window the demo, the tests and Python scripts use,
 *          and says which OpenGL contexts this build can make here.
 *
 * The backend is chosen by the environment variable `HAVS_RENDER_WINDOW`:
 * - `egl` : vtkHAVSEGLRenderWindow, headless, no X server needed;
 * - `display` : VTK's own window for this build (GLX on Debian), which needs
 *   `$DISPLAY` (a real X server or Xvfb);
 * - `glfw` : a hidden GLFW window (vtkHAVSGLFWRenderWindow; needs an X server),
 *   where GLFW 3.3 was found at configure time;
 * - `osmesa` : Mesa's off-screen software context. VTK's own
 *   vtkOSOpenGLRenderWindow where the VTK built against has it
 *   (`VTK_OPENGL_HAS_OSMESA`), else vtkHAVSOSMesaRenderWindow where OSMesa was
 *   found at configure time (with Debian's GLVND/GLEW VTK it routes GLVND's
 *   dispatch to OSMesa, see that class);
 * - unset or `auto` : the first usable of `egl`, `display`, `osmesa`, else an
 *   error.
 *
 * The table of contexts: GetBackendNames() lists every backend name this
 * version knows, built or not; IsBackendBuilt() says whether this build has
 * it, IsBackendAvailable() whether it can be made now on this machine, and
 * GetBackendStatus() says which, in a sentence. DescribeBackends() gives it
 * all as a Markdown table.
 */
#ifndef vtkHAVSRenderWindowFactory_h
#define vtkHAVSRenderWindowFactory_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSHeadlessModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_NEWINSTANCE

#include <string> // For std::string
#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkRenderWindow;

class VTKHAVSHEADLESS_EXPORT vtkHAVSRenderWindowFactory : public vtkObject
{
public:
  static vtkHAVSRenderWindowFactory* New();
  vtkTypeMacro(vtkHAVSRenderWindowFactory, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * A new render window of the chosen backend (the caller owns the reference),
   * or nullptr with an error when none can be made.
   */
  VTK_NEWINSTANCE
  static vtkRenderWindow* CreateRenderWindow();

  /**
   * A new render window of the given backend (one of GetBackendNames(), or
   * "auto"), or nullptr with a warning saying why when it cannot be made here.
   */
  VTK_NEWINSTANCE
  static vtkRenderWindow* CreateRenderWindow(const std::string& backend);

  /**
   * The backend CreateRenderWindow() picks now: one of GetBackendNames(), or
   * "" when none is usable.
   */
  static const char* GetSelectedBackend();

  /**
   * The backend of a window made here ("egl", "display", "osmesa").
   */
  static const char* GetBackendName(vtkRenderWindow* window);

  /**
   * Releases the EGL, OSMesa or GLX context current on this thread. Under
   * GLVND one context is current per thread for all of them, and VTK's GLX
   * window cannot make its own current while an EGL or OSMesa window holds
   * the thread: the EGL and OSMesa windows take the thread themselves, and a
   * `display` window made here releases them when it starts rendering; call
   * this before anything else of a GLX window (reading its pixels, say) that
   * follows direct GL work with an EGL or OSMesa window (e.g. reading a
   * mapper's kept float result).
   */
  static void ReleaseCurrentContext();

  ///@{
  /**
   * Every backend name this version knows, built in this build or not:
   * egl, display, glfw, osmesa (also by index, for wrappers).
   */
  static std::vector<std::string> GetBackendNames();
  static int GetNumberOfBackends();
  static std::string GetBackendNameByIndex(int index);
  ///@}

  /**
   * True when this build has the backend (its class and libraries).
   */
  static bool IsBackendBuilt(const std::string& backend);

  /**
   * True when the backend is built and a context of it can be made now
   * (EGL and OSMesa: probed once per process; display: an X display opens).
   */
  static bool IsBackendAvailable(const std::string& backend);

  /**
   * The backend's state in a sentence: "available: ...", "unavailable: ..."
   * (built, but not usable here now) or "not built: ...".
   */
  static std::string GetBackendStatus(const std::string& backend);

  /**
   * The table of contexts in Markdown: backend | built | usable now | note,
   * then the backend `auto` picks.
   */
  static std::string DescribeBackends();

protected:
  vtkHAVSRenderWindowFactory() = default;
  ~vtkHAVSRenderWindowFactory() override = default;

private:
  vtkHAVSRenderWindowFactory(const vtkHAVSRenderWindowFactory&) = delete;
  void operator=(const vtkHAVSRenderWindowFactory&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif
