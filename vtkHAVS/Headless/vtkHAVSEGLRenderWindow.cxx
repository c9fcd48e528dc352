/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSEGLRenderWindow.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSEGLRenderWindow.h"

#include "vtkHAVSHeadlessDispatch.h"
#include "vtkHAVSOpenGL.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLState.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <mutex>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSEGLRenderWindow);

namespace
{
bool HasExtension(const char* list, const char* name)
{
  if (!list || !name)
  {
    return false;
  }
  const size_t len = std::strlen(name);
  for (const char* p = std::strstr(list, name); p; p = std::strstr(p + len, name))
  {
    const bool startOk = (p == list) || p[-1] == ' ';
    const bool endOk = p[len] == ' ' || p[len] == '\0';
    if (startOk && endOk)
    {
      return true;
    }
  }
  return false;
}

struct EGLDisplayChoice
{
  EGLDisplay Display = EGL_NO_DISPLAY;
  const char* Platform = "";
};

/// Opens an initialized EGL display that needs no window system.
EGLDisplayChoice OpenDisplay()
{
  EGLDisplayChoice choice;
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
    eglGetProcAddress("eglGetPlatformDisplayEXT"));

  if (getPlatformDisplay && HasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
  {
    EGLDisplay dpy =
      getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, nullptr, nullptr))
    {
      choice.Display = dpy;
      choice.Platform = "surfaceless";
      return choice;
    }
  }

  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (getPlatformDisplay && queryDevices &&
    HasExtension(clientExtensions, "EGL_EXT_platform_device"))
  {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (queryDevices(16, devices, &count))
    {
      for (EGLint i = 0; i < count; ++i)
      {
        EGLDisplay dpy = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, nullptr, nullptr))
        {
          choice.Display = dpy;
          choice.Platform = "device";
          return choice;
        }
      }
    }
  }

  EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, nullptr, nullptr))
  {
    choice.Display = dpy;
    choice.Platform = "default";
  }
  return choice;
}
}

struct vtkHAVSEGLRenderWindow::Internals
{
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLContext Context = EGL_NO_CONTEXT;
  std::string Platform;
};

//------------------------------------------------------------------------------
vtkHAVSEGLRenderWindow::vtkHAVSEGLRenderWindow()
  : Internal(new Internals)
{
  this->SetFrameBlitModeToNoBlit();
  this->SetOffScreenRendering(1);
  // One sample per pixel: images are compared pixel by pixel with references.
  this->SetMultiSamples(0);
  this->SetOwnContext(1);
}

//------------------------------------------------------------------------------
vtkHAVSEGLRenderWindow::~vtkHAVSEGLRenderWindow()
{
  // The base destructor would only reach vtkGenericOpenGLRenderWindow::Finalize.
  this->Finalize();
}

//------------------------------------------------------------------------------
struct vtkHAVSEGLRenderWindow::ProbeResult
{
  bool Available = false;
  std::string Report;
};

//------------------------------------------------------------------------------
const vtkHAVSEGLRenderWindow::ProbeResult& vtkHAVSEGLRenderWindow::Probe()
{
  static std::once_flag once;
  static ProbeResult probe;
  std::call_once(once,
    []
    {
      vtkHAVSEGLRenderWindow* window = vtkHAVSEGLRenderWindow::New();
      probe.Available = window->CreateContext();
      if (!probe.Available)
      {
        probe.Report = "no EGL display gives an OpenGL >= 3.2 core context";
      }
      else
      {
        probe.Report = "EGL " + window->GetPlatformName() + " display";
        // The renderer, where no context is current on this thread (under
        // GLVND a current GLX context makes eglMakeCurrent fail: then unsaid).
        const Internals& internal = *window->Internal;
        if (eglGetCurrentContext() == EGL_NO_CONTEXT &&
          eglMakeCurrent(internal.Display, EGL_NO_SURFACE, EGL_NO_SURFACE, internal.Context))
        {
          // Through EGL's loader: with glad (VTK >= 9.4) VTK's gl* entry
          // points are not loaded before a window's OpenGLInit().
          using GetStringFunction = const GLubyte* (*)(GLenum);
          auto getString = reinterpret_cast<GetStringFunction>(eglGetProcAddress("glGetString"));
          if (const GLubyte* renderer = getString ? getString(GL_RENDERER) : nullptr)
          {
            probe.Report += std::string(", ") + reinterpret_cast<const char*>(renderer);
          }
          eglMakeCurrent(internal.Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
      }
      window->DestroyContext();
      window->Delete();
    });
  return probe;
}

//------------------------------------------------------------------------------
bool vtkHAVSEGLRenderWindow::IsAvailable()
{
  return vtkHAVSEGLRenderWindow::Probe().Available;
}

//------------------------------------------------------------------------------
std::string vtkHAVSEGLRenderWindow::GetProbeReport()
{
  return vtkHAVSEGLRenderWindow::Probe().Report;
}

//------------------------------------------------------------------------------
bool vtkHAVSEGLRenderWindow::CreateContext()
{
  if (this->Internal->Context != EGL_NO_CONTEXT)
  {
    return true;
  }
  EGLDisplayChoice choice = OpenDisplay();
  if (choice.Display == EGL_NO_DISPLAY)
  {
    return false;
  }
  const char* displayExtensions = eglQueryString(choice.Display, EGL_EXTENSIONS);
  if (!HasExtension(displayExtensions, "EGL_KHR_surfaceless_context") ||
    !eglBindAPI(EGL_OPENGL_API))
  {
    eglTerminate(choice.Display);
    return false;
  }

  const EGLint configAttributes[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  EGLConfig config = nullptr;
  EGLint numConfigs = 0;
  if (!eglChooseConfig(choice.Display, configAttributes, &config, 1, &numConfigs) || numConfigs < 1)
  {
    config = nullptr; // EGL_KHR_no_config_context
  }

  const int versions[][2] = { { 4, 6 }, { 4, 5 }, { 4, 3 }, { 4, 1 }, { 3, 3 }, { 3, 2 } };
  EGLContext context = EGL_NO_CONTEXT;
  for (const auto& v : versions)
  {
    const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, v[0], EGL_CONTEXT_MINOR_VERSION,
      v[1], EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    context = eglCreateContext(choice.Display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context != EGL_NO_CONTEXT)
    {
      break;
    }
  }
  if (context == EGL_NO_CONTEXT)
  {
    eglTerminate(choice.Display);
    return false;
  }
  this->Internal->Display = choice.Display;
  this->Internal->Context = context;
  this->Internal->Platform = choice.Platform;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSEGLRenderWindow::DestroyContext()
{
  if (this->Internal->Context != EGL_NO_CONTEXT)
  {
    if (eglGetCurrentContext() == this->Internal->Context)
    {
      eglMakeCurrent(this->Internal->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(this->Internal->Display, this->Internal->Context);
    this->Internal->Context = EGL_NO_CONTEXT;
  }
  // The display is shared per process by EGL (same handle for every window):
  // it is not terminated here, which would destroy the other windows' contexts.
  this->Internal->Display = EGL_NO_DISPLAY;
}

//------------------------------------------------------------------------------
void vtkHAVSEGLRenderWindow::Initialize()
{
  if (!this->CreateContext())
  {
    vtkErrorMacro("Could not create a headless EGL OpenGL (>= 3.2 core) context. Install Mesa's "
                  "EGL (libegl-mesa0) or a GPU driver with EGL, or set "
                  "HAVS_RENDER_WINDOW=display to render in an X window.");
    return;
  }
  this->MakeCurrent();
  if (!this->Initialized)
  {
    havs_gl::SetSymbolLoader(this, &eglGetProcAddress);
    this->OpenGLInit();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSEGLRenderWindow::Render()
{
  // The generic window initializes OpenGL from whatever context is current:
  // make ours current (creating it on first use) first.
  this->Initialize();
  if (!this->IsCurrent())
  {
    return;
  }
  this->Superclass::Render();
}

//------------------------------------------------------------------------------
void vtkHAVSEGLRenderWindow::MakeCurrent()
{
  if (this->Internal->Context == EGL_NO_CONTEXT && !this->CreateContext())
  {
    return;
  }
  if (eglGetCurrentContext() != this->Internal->Context)
  {
    // Under GLVND a GLX context or an OSMesa window may hold the thread.
    havs_dispatch::TakeThread(havs_dispatch::kTagEGL);
    eglMakeCurrent(
      this->Internal->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, this->Internal->Context);
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSEGLRenderWindow::IsCurrent()
{
  return this->Internal->Context != EGL_NO_CONTEXT &&
    eglGetCurrentContext() == this->Internal->Context;
}

//------------------------------------------------------------------------------
int vtkHAVSEGLRenderWindow::SupportsOpenGL()
{
  return vtkHAVSEGLRenderWindow::IsAvailable() ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSEGLRenderWindow::Finalize()
{
  if (this->Internal->Context != EGL_NO_CONTEXT)
  {
    this->MakeCurrent();
    if (this->Initialized)
    {
      this->ReleaseGraphicsResources(this);
    }
    this->DestroyContext();
  }
  this->Initialized = false;
}

//------------------------------------------------------------------------------
std::string vtkHAVSEGLRenderWindow::GetPlatformName() const
{
  return this->Internal->Platform;
}

//------------------------------------------------------------------------------
const char* vtkHAVSEGLRenderWindow::GetContextName() const
{
  return "EGL";
}

//------------------------------------------------------------------------------
void vtkHAVSEGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EGL platform: "
     << (this->Internal->Platform.empty() ? "(none yet)" : this->Internal->Platform) << "\n";
}

VTK_ABI_NAMESPACE_END
