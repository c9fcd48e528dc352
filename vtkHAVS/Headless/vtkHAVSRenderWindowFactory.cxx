/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRenderWindowFactory.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSRenderWindowFactory.h"

#include "vtkHAVSEGLRenderWindow.h"
#include "vtkHAVSWindowConfigure.h"
#if VTKHAVS_HAS_GLFW
#include "vtkHAVSGLFWRenderWindow.h"
#endif
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"

#include <cstdlib>
#include <cstring>
#include <string>

vtkStandardNewMacro(vtkHAVSRenderWindowFactory);

namespace
{
std::string RequestedBackend()
{
  const char* value = std::getenv("HAVS_RENDER_WINDOW");
  return (value && *value) ? std::string(value) : std::string("auto");
}

bool HaveDisplay()
{
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}
}

//------------------------------------------------------------------------------
const char* vtkHAVSRenderWindowFactory::GetSelectedBackend()
{
  const std::string requested = RequestedBackend();
  if (requested == "egl")
  {
    return "egl";
  }
  if (requested == "display")
  {
    return "display";
  }
  if (requested == "glfw")
  {
    return "glfw";
  }
  if (requested != "auto")
  {
    vtkGenericWarningMacro(
      "HAVS_RENDER_WINDOW=" << requested << " is not one of egl, display, glfw, auto; using auto.");
  }
  if (vtkHAVSEGLRenderWindow::IsAvailable())
  {
    return "egl";
  }
  return HaveDisplay() ? "display" : "";
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkHAVSRenderWindowFactory::CreateRenderWindow()
{
  const std::string backend = vtkHAVSRenderWindowFactory::GetSelectedBackend();
  if (backend == "egl")
  {
    if (!vtkHAVSEGLRenderWindow::IsAvailable())
    {
      vtkGenericWarningMacro("HAVS_RENDER_WINDOW=egl but no EGL OpenGL context can be made here.");
      return nullptr;
    }
    return vtkHAVSEGLRenderWindow::New();
  }
  if (backend == "display")
  {
    if (!HaveDisplay())
    {
      vtkGenericWarningMacro("HAVS_RENDER_WINDOW=display but DISPLAY is not set.");
      return nullptr;
    }
    vtkRenderWindow* window = vtkRenderWindow::New();
    window->SetMultiSamples(0);
    return window;
  }
  if (backend == "glfw")
  {
#if VTKHAVS_HAS_GLFW
    if (!vtkHAVSGLFWRenderWindow::IsAvailable())
    {
      vtkGenericWarningMacro("HAVS_RENDER_WINDOW=glfw but no GLFW window can be made here: "
        << vtkHAVSGLFWRenderWindow::GetUnavailableReason());
      return nullptr;
    }
    // A hidden GLFW window: the factory's windows render off screen.
    vtkHAVSGLFWRenderWindow* window = vtkHAVSGLFWRenderWindow::New();
    window->SetShowWindow(false);
    return window;
#else
    vtkGenericWarningMacro("HAVS_RENDER_WINDOW=glfw but this build has no GLFW (libglfw3-dev "
                           "was not found when vtkHAVS was configured).");
    return nullptr;
#endif
  }
  vtkGenericWarningMacro("No render window can be made: no EGL context and no DISPLAY.");
  return nullptr;
}

//------------------------------------------------------------------------------
const char* vtkHAVSRenderWindowFactory::GetBackendName(vtkRenderWindow* window)
{
  if (!window)
  {
    return "";
  }
  if (vtkHAVSEGLRenderWindow::SafeDownCast(window))
  {
    return "egl";
  }
#if VTKHAVS_HAS_GLFW
  if (vtkHAVSGLFWRenderWindow::SafeDownCast(window))
  {
    return "glfw";
  }
#endif
  return "display";
}

//------------------------------------------------------------------------------
void vtkHAVSRenderWindowFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Selected backend: " << vtkHAVSRenderWindowFactory::GetSelectedBackend() << "\n";
}
