/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLFWRenderWindow.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLFWRenderWindow.h"

#include "vtkHAVSHeadlessDispatch.h"
#include "vtkHAVSOpenGL.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLState.h"

#include <GLFW/glfw3.h>

#include <mutex>
#include <string>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSGLFWRenderWindow);

namespace
{
std::string& LastGLFWError()
{
  static std::string message;
  return message;
}

void OnGLFWError(int code, const char* description)
{
  LastGLFWError() =
    std::string(description ? description : "") + " (GLFW error " + std::to_string(code) + ")";
}

/// glfwInit once per process; false (with the reason kept) when it fails.
bool InitializeGLFW()
{
  static std::once_flag once;
  static bool ok = false;
  std::call_once(once,
    []
    {
      glfwSetErrorCallback(OnGLFWError);
      ok = glfwInit() == GLFW_TRUE;
      if (!ok && LastGLFWError().empty())
      {
        LastGLFWError() = "glfwInit failed";
      }
    });
  return ok;
}

/// A window with the highest core context of 4.6 … 3.2 GLFW can make.
GLFWwindow* CreateCoreWindow(int width, int height, const char* title, bool visible)
{
  static const int versions[][2] = { { 4, 6 }, { 4, 5 }, { 4, 3 }, { 4, 1 }, { 3, 3 }, { 3, 2 } };
  for (const auto& version : versions)
  {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, version[0]);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, version[1]);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, 0);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_ALPHA_BITS, 8);
    glfwWindowHint(GLFW_STENCIL_BITS, 8);
    GLFWwindow* window = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (window)
    {
      return window;
    }
  }
  return nullptr;
}

/// Whether this thread's GLVND state (where there is GLVND) is GLX's: an EGL
/// or OSMesa window may have taken the thread since GLFW made ours current.
bool ThreadIsGLX()
{
  const bool glvnd = havs_dispatch::Dispatch().GetCurrentThreadState != nullptr;
  return !glvnd || havs_dispatch::CurrentTag() == havs_dispatch::kTagGLX;
}

struct Availability
{
  bool Available = false;
  std::string Reason;
};

const Availability& ProbeAvailability()
{
  static std::once_flag once;
  static Availability result;
  std::call_once(once,
    []
    {
      if (!InitializeGLFW())
      {
        result.Reason = "GLFW cannot initialize: " + LastGLFWError();
        return;
      }
      GLFWwindow* previous = glfwGetCurrentContext();
      GLFWwindow* probe = CreateCoreWindow(16, 16, "vtkHAVS probe", false);
      if (!probe)
      {
        result.Reason = "GLFW makes no OpenGL >= 3.2 core context: " + LastGLFWError();
        return;
      }
      glfwDestroyWindow(probe);
      glfwMakeContextCurrent(previous);
      result.Available = true;
    });
  return result;
}
}

//------------------------------------------------------------------------------
vtkHAVSGLFWRenderWindow::vtkHAVSGLFWRenderWindow()
{
  this->SetWindowName("vtkHAVS");
}

//------------------------------------------------------------------------------
vtkHAVSGLFWRenderWindow::~vtkHAVSGLFWRenderWindow()
{
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFWRenderWindow::IsAvailable()
{
  return ProbeAvailability().Available;
}

//------------------------------------------------------------------------------
std::string vtkHAVSGLFWRenderWindow::GetUnavailableReason()
{
  return ProbeAvailability().Reason;
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFWRenderWindow::CreateWindow()
{
  if (this->Window)
  {
    return true;
  }
  if (!InitializeGLFW())
  {
    return false;
  }
  const int width = this->Size[0] > 0 ? this->Size[0] : 300;
  const int height = this->Size[1] > 0 ? this->Size[1] : 300;
  const bool visible = this->ShowWindow && !this->GetOffScreenRendering();
  this->Window = CreateCoreWindow(width, height, this->WindowName, visible);
  if (!this->Window)
  {
    return false;
  }
  this->Size[0] = width;
  this->Size[1] = height;
  // Under GLVND one context is current per thread: an EGL or OSMesa window of
  // this process may hold it (see vtkHAVSHeadlessDispatch.h).
  havs_dispatch::TakeThread(havs_dispatch::kTagGLX);
  glfwMakeContextCurrent(this->Window);
  // VTK paces nothing; swapping without waiting for the display keeps frame
  // times what the mapper costs.
  glfwSwapInterval(0);
  this->Mapped = visible ? 1 : 0;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::Initialize()
{
  if (!this->CreateWindow())
  {
    vtkErrorMacro("Could not create a GLFW window with an OpenGL (>= 3.2 core) context: "
      << LastGLFWError() << ". GLFW needs an X server ($DISPLAY, or Xvfb); without one use "
      << "HAVS_RENDER_WINDOW=egl.");
    return;
  }
  this->MakeCurrent();
  if (!this->Initialized)
  {
    havs_gl::SetSymbolLoader(this, &glfwGetProcAddress);
    this->OpenGLInit();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::Render()
{
  this->Initialize();
  if (!this->IsCurrent())
  {
    return;
  }
  this->Superclass::Render();
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::MakeCurrent()
{
  if (!this->Window && !this->CreateWindow())
  {
    return;
  }
  if (glfwGetCurrentContext() != this->Window || !ThreadIsGLX())
  {
    havs_dispatch::TakeThread(havs_dispatch::kTagGLX);
    glfwMakeContextCurrent(this->Window);
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFWRenderWindow::IsCurrent()
{
  return this->Window && glfwGetCurrentContext() == this->Window && ThreadIsGLX();
}

//------------------------------------------------------------------------------
int vtkHAVSGLFWRenderWindow::SupportsOpenGL()
{
  return vtkHAVSGLFWRenderWindow::IsAvailable() ? 1 : 0;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkHAVSGLFWRenderWindow::IsDirect()
{
  return 1;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::Frame()
{
  if (!this->Initialized || !this->IsCurrent())
  {
    return;
  }
  // The superclass blits VTK's framebuffer into the window's back buffer.
  this->Superclass::Frame();
  if (this->SwapBuffers && this->Mapped)
  {
    glfwSwapBuffers(this->Window);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::SetSize(int width, int height)
{
  this->Superclass::SetSize(width, height);
  if (this->Window && width > 0 && height > 0)
  {
    int current[2] = { 0, 0 };
    glfwGetWindowSize(this->Window, &current[0], &current[1]);
    if (current[0] != width || current[1] != height)
    {
      glfwSetWindowSize(this->Window, width, height);
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::SetWindowName(const char* name)
{
  this->Superclass::SetWindowName(name);
  if (this->Window && name)
  {
    glfwSetWindowTitle(this->Window, name);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::SetShowWindow(bool show)
{
  this->Superclass::SetShowWindow(show);
  if (this->Window)
  {
    const bool visible = show && !this->GetOffScreenRendering();
    if (visible)
    {
      glfwShowWindow(this->Window);
    }
    else
    {
      glfwHideWindow(this->Window);
    }
    this->Mapped = visible ? 1 : 0;
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFWRenderWindow::GetShouldClose() const
{
  return this->Window && glfwWindowShouldClose(this->Window);
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::Finalize()
{
  if (this->Window)
  {
    this->MakeCurrent();
    if (this->Initialized)
    {
      this->ReleaseGraphicsResources(this);
    }
    glfwMakeContextCurrent(nullptr);
    glfwDestroyWindow(this->Window);
    this->Window = nullptr;
  }
  this->Initialized = false;
  this->Mapped = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFWRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GLFW window: " << (this->Window ? "created" : "(none yet)") << "\n";
  if (this->Window)
  {
    os << indent
       << "GLFW context version: " << glfwGetWindowAttrib(this->Window, GLFW_CONTEXT_VERSION_MAJOR)
       << "." << glfwGetWindowAttrib(this->Window, GLFW_CONTEXT_VERSION_MINOR) << "\n";
  }
}

VTK_ABI_NAMESPACE_END
