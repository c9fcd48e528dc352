/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLFWRenderWindow.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLFWRenderWindow
 * @brief   A render window on a GLFW 3.3 window and its OpenGL context.
 *
 * A vtkGenericOpenGLRenderWindow whose context is a GLFW window's (OpenGL
 * core, highest of 4.6 … 3.2). VTK renders into its own framebuffers and
 * Frame() blits the result into the window's back buffer and swaps. The
 * window is shown unless off-screen rendering is on (then it stays hidden, and
 * the window still renders: the factory's `glfw` backend uses it so).
 *
 * GLFW needs a window system: on Debian an X server (`$DISPLAY`, a real one or
 * Xvfb). The context is GLX, so Debian's GLEW-built VTK loads GL as usual.
 *
 * Input is the host's job: GetGLFWWindow() gives the GLFW window, on which an
 * application installs its callbacks (havs_view does, and forwards them to a
 * vtkGenericRenderWindowInteractor). The window's framebuffer size follows
 * SetSize(); a resize by the user should be passed on with SetSize().
 */
#ifndef vtkHAVSGLFWRenderWindow_h
#define vtkHAVSGLFWRenderWindow_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkHAVSHeadlessModule.h" // For export macro

#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN

struct GLFWwindow;

class VTKHAVSHEADLESS_EXPORT vtkHAVSGLFWRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkHAVSGLFWRenderWindow* New();
  vtkTypeMacro(vtkHAVSGLFWRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * True when GLFW initializes (a window system is reachable) and a hidden
   * window with an OpenGL >= 3.2 core context can be made (tried once per
   * process, then remembered). Why not, in GetUnavailableReason().
   */
  static bool IsAvailable();
  static std::string GetUnavailableReason();

  /**
   * Creates the GLFW window (shown unless off-screen rendering is on) and its
   * context if needed, makes it current and initializes VTK's OpenGL state.
   */
  void Initialize() override;
  /**
   * Makes the context current (creating the window on first use), then renders.
   */
  void Render() override;

  ///@{
  /**
   * The context is the GLFW window's; these do not go through observers.
   */
  void MakeCurrent() override;
  bool IsCurrent() override;
  int SupportsOpenGL() override;
  vtkTypeBool IsDirect() override;
  void Frame() override;
  ///@}

  ///@{
  /**
   * The GLFW window follows: its size, its title (the window name), shown or
   * hidden with off-screen rendering.
   */
  void SetSize(int width, int height) override;
  void SetSize(int a[2]) override { this->SetSize(a[0], a[1]); }
  void SetWindowName(const char* name) override;
  void SetShowWindow(bool show) override;
  ///@}

  /// The GLFW window (nullptr before Initialize()).
  GLFWwindow* GetGLFWWindow() const { return this->Window; }

  /// True once the user asked the window to close (the close button).
  bool GetShouldClose() const;

  /**
   * Releases the graphics resources of every renderer and destroys the window.
   */
  void Finalize() override;

protected:
  vtkHAVSGLFWRenderWindow();
  ~vtkHAVSGLFWRenderWindow() override;

private:
  vtkHAVSGLFWRenderWindow(const vtkHAVSGLFWRenderWindow&) = delete;
  void operator=(const vtkHAVSGLFWRenderWindow&) = delete;

  bool CreateWindow();

  GLFWwindow* Window = nullptr;
};

VTK_ABI_NAMESPACE_END
#endif
