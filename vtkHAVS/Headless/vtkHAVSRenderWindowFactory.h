/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRenderWindowFactory.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSRenderWindowFactory
 * @brief   Makes the render window the demo, the tests and Python scripts use.
 *
 * The backend is chosen by the environment variable `HAVS_RENDER_WINDOW`:
 * - `egl` : vtkHAVSEGLRenderWindow, headless, no X server needed;
 * - `display` : VTK's own window for this build (GLX on Debian), which needs
 *   `$DISPLAY` (a real X server or Xvfb);
 * - unset or `auto` : `egl` when an EGL context can be made, else `display`
 *   when `$DISPLAY` is set, else an error.
 *
 * OSMesa is not offered: under VTK's GLEW it needs glXGetProcAddressARB routed
 * to OSMesaGetProcAddress, which works but is fragile; EGL surfaceless covers
 * the same headless use with Mesa's llvmpipe.
 */
#ifndef vtkHAVSRenderWindowFactory_h
#define vtkHAVSRenderWindowFactory_h

#include "vtkHAVSHeadlessModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_NEWINSTANCE

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
   * The backend CreateRenderWindow() picks now: "egl" or "display", or "" when
   * none is usable.
   */
  static const char* GetSelectedBackend();

  /**
   * The backend of a window made here ("egl", "display").
   */
  static const char* GetBackendName(vtkRenderWindow* window);

protected:
  vtkHAVSRenderWindowFactory() = default;
  ~vtkHAVSRenderWindowFactory() override = default;

private:
  vtkHAVSRenderWindowFactory(const vtkHAVSRenderWindowFactory&) = delete;
  void operator=(const vtkHAVSRenderWindowFactory&) = delete;
};

#endif
