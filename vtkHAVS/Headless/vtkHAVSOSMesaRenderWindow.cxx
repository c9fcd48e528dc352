/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSOSMesaRenderWindow.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSOSMesaRenderWindow.h"

#include "vtkHAVSHeadlessDispatch.h"
#include "vtkHAVSOpenGL.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLState.h"

// After the GL loader's header: osmesa.h's own #include <GL/gl.h> is then a
// no-op. Only its types and constants are used; the functions come from
// dlsym (see OSMesaLibrary). GLEW undefines gl.h's GLAPI, GLAPIENTRY and
// APIENTRY (Mesa 22's osmesa.h, Debian 12, uses GLAPIENTRY; Mesa 24's,
// Debian 13, APIENTRY).
#ifndef GLAPI
#define GLAPI extern
#define HAVS_UNDEF_GLAPI
#endif
#ifndef GLAPIENTRY
#define GLAPIENTRY
#define HAVS_UNDEF_GLAPIENTRY
#endif
#ifndef APIENTRY
#define APIENTRY
#define HAVS_UNDEF_APIENTRY
#endif
#include <GL/osmesa.h>
#ifdef HAVS_UNDEF_GLAPI
#undef GLAPI
#endif
#ifdef HAVS_UNDEF_GLAPIENTRY
#undef GLAPIENTRY
#endif
#ifdef HAVS_UNDEF_APIENTRY
#undef APIENTRY
#endif

#include <EGL/egl.h>

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <sstream>
#include <vector>

#ifndef HAVS_OSMESA_SONAME
#define HAVS_OSMESA_SONAME "libOSMesa.so.8"
#endif

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSOSMesaRenderWindow);

namespace
{
/**
 * libOSMesa, opened with RTLD_LOCAL rather than linked: it exports every gl*
 * function itself (bound to its own libglapi), and linked into the process it
 * could come before libOpenGL in the global symbol scope and take VTK's
 * direct GL calls away from GLVND, which would leave EGL and GLX windows
 * drawing nothing.
 */
struct OSMesaLibrary
{
  std::string Error;
  decltype(&OSMesaCreateContextAttribs) CreateContextAttribs = nullptr;
  decltype(&OSMesaDestroyContext) DestroyContext = nullptr;
  decltype(&OSMesaMakeCurrent) MakeCurrent = nullptr;
  decltype(&OSMesaGetCurrentContext) GetCurrentContext = nullptr;
  decltype(&OSMesaGetProcAddress) GetProcAddress = nullptr;
};

const OSMesaLibrary& OSMesa()
{
  static OSMesaLibrary lib;
  static std::once_flag once;
  std::call_once(once,
    []
    {
      void* handle = nullptr;
      for (const char* name : { HAVS_OSMESA_SONAME, "libOSMesa.so.8", "libOSMesa.so" })
      {
        handle = dlopen(name, RTLD_NOW | RTLD_LOCAL);
        if (handle)
        {
          break;
        }
      }
      if (!handle)
      {
        lib.Error = std::string("libOSMesa could not be opened (") + HAVS_OSMESA_SONAME + ")";
        return;
      }
      lib.CreateContextAttribs = reinterpret_cast<decltype(lib.CreateContextAttribs)>(
        dlsym(handle, "OSMesaCreateContextAttribs"));
      lib.DestroyContext =
        reinterpret_cast<decltype(lib.DestroyContext)>(dlsym(handle, "OSMesaDestroyContext"));
      lib.MakeCurrent =
        reinterpret_cast<decltype(lib.MakeCurrent)>(dlsym(handle, "OSMesaMakeCurrent"));
      lib.GetCurrentContext =
        reinterpret_cast<decltype(lib.GetCurrentContext)>(dlsym(handle, "OSMesaGetCurrentContext"));
      lib.GetProcAddress =
        reinterpret_cast<decltype(lib.GetProcAddress)>(dlsym(handle, "OSMesaGetProcAddress"));
      if (!lib.CreateContextAttribs || !lib.DestroyContext || !lib.MakeCurrent ||
        !lib.GetCurrentContext || !lib.GetProcAddress)
      {
        lib.Error = "libOSMesa lacks OSMesaCreateContextAttribs (Mesa >= 12 is needed)";
      }
    });
  return lib;
}

// libGLdispatch's window-system interface (libglvnd's GLdispatch.h, ABI 1):
// what libGLX and libEGL call to make a vendor's dispatch table current.
struct DispatchTableRec;
struct ThreadState
{
  int Tag;
  void (*ThreadDestroyed)(ThreadState*);
  void* Private;
};
constexpr int kTagOSMesa = havs_dispatch::kTagOSMesa;
constexpr int kDispatchABIVersion = 1;

void ThreadDestroyed(ThreadState*) {}

thread_local ThreadState OSMesaThreadState = { kTagOSMesa, &ThreadDestroyed, nullptr };

void* OSMesaProc(const char* name, void*)
{
  return reinterpret_cast<void*>(OSMesa().GetProcAddress(name));
}

struct GLDispatch
{
  bool Present = false; // libGLdispatch is in the process (GLVND)
  std::string Error;
  void (*LoseCurrent)() = nullptr;
  ThreadState* (*GetCurrentThreadState)() = nullptr;
  unsigned char (*MakeCurrent)(ThreadState*, DispatchTableRec*, int, const void*) = nullptr;
  DispatchTableRec* Table = nullptr;
  int VendorID = 0;
};

const GLDispatch& Dispatch()
{
  static GLDispatch d;
  static std::once_flag once;
  std::call_once(once,
    []
    {
      void* handle = dlopen("libGLdispatch.so.0", RTLD_NOW | RTLD_NOLOAD);
      if (!handle)
      {
        return; // no GLVND: libGL is Mesa's own and shares libglapi with OSMesa
      }
      d.Present = true;
      auto abi = reinterpret_cast<int (*)()>(dlsym(handle, "__glDispatchGetABIVersion"));
      auto init = reinterpret_cast<void (*)()>(dlsym(handle, "__glDispatchInit"));
      auto newVendor = reinterpret_cast<int (*)()>(dlsym(handle, "__glDispatchNewVendorID"));
      auto createTable =
        reinterpret_cast<DispatchTableRec* (*)(void* (*)(const char*, void*), void*)>(
          dlsym(handle, "__glDispatchCreateTable"));
      d.MakeCurrent =
        reinterpret_cast<decltype(d.MakeCurrent)>(dlsym(handle, "__glDispatchMakeCurrent"));
      d.LoseCurrent = reinterpret_cast<void (*)()>(dlsym(handle, "__glDispatchLoseCurrent"));
      d.GetCurrentThreadState = reinterpret_cast<decltype(d.GetCurrentThreadState)>(
        dlsym(handle, "__glDispatchGetCurrentThreadState"));
      if (!abi || !init || !newVendor || !createTable || !d.MakeCurrent || !d.LoseCurrent ||
        !d.GetCurrentThreadState)
      {
        d.Error = "libGLdispatch lacks its window-system interface";
        return;
      }
      if (abi() != kDispatchABIVersion)
      {
        d.Error = "libGLdispatch has ABI version " + std::to_string(abi()) + ", not " +
          std::to_string(kDispatchABIVersion);
        return;
      }
      init();
      d.VendorID = newVendor();
      d.Table = createTable(&OSMesaProc, nullptr);
      if (!d.Table)
      {
        d.Error = "libGLdispatch could not create a dispatch table";
      }
    });
  return d;
}

/// Makes the OSMesa dispatch current in libGLdispatch for this thread.
bool BindDispatch(bool releaseOthers, std::string* error)
{
  const GLDispatch& d = Dispatch();
  if (!d.Present)
  {
    return true;
  }
  if (!d.Error.empty())
  {
    *error = d.Error;
    return false;
  }
  ThreadState* current = d.GetCurrentThreadState();
  if (current == &OSMesaThreadState)
  {
    return true;
  }
  if (current)
  {
    if (!releaseOthers)
    {
      *error = "a GLX or EGL context is current on this thread";
      return false;
    }
    havs_dispatch::TakeThread(kTagOSMesa);
    if (d.GetCurrentThreadState())
    {
      *error = "the GLX or EGL context current on this thread could not be released";
      return false;
    }
  }
  if (!d.MakeCurrent(&OSMesaThreadState, d.Table, d.VendorID, nullptr))
  {
    *error = "libGLdispatch refused to make the OSMesa dispatch table current";
    return false;
  }
  return true;
}

bool DispatchBound()
{
  const GLDispatch& d = Dispatch();
  return !d.Present || (d.Error.empty() && d.GetCurrentThreadState() == &OSMesaThreadState);
}

void UnbindDispatch()
{
  const GLDispatch& d = Dispatch();
  if (d.Present && d.Error.empty() && d.GetCurrentThreadState() == &OSMesaThreadState)
  {
    d.LoseCurrent();
  }
}

/// An OSMesa core context, the highest version of 4.5 … 3.2.
OSMesaContext CreateCoreContext()
{
  const int versions[][2] = { { 4, 5 }, { 4, 3 }, { 4, 1 }, { 3, 3 }, { 3, 2 } };
  for (const auto& v : versions)
  {
    const int attributes[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
      OSMESA_STENCIL_BITS, 8, OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION,
      v[0], OSMESA_CONTEXT_MINOR_VERSION, v[1], 0 };
    if (OSMesaContext context = OSMesa().CreateContextAttribs(attributes, nullptr))
    {
      return context;
    }
  }
  return nullptr;
}

struct ProbeResult
{
  bool Done = false;
  bool Available = false;
  std::string Report;
};

const char* String(const GLubyte* s)
{
  return s ? reinterpret_cast<const char*>(s) : "";
}

/// Creates a context and checks it renders through the calls VTK makes.
ProbeResult Probe()
{
  ProbeResult result;
  result.Done = true;
  if (!OSMesa().Error.empty())
  {
    result.Report = OSMesa().Error;
    return result;
  }
  const GLDispatch& d = Dispatch();
  if (d.Present && !d.Error.empty())
  {
    result.Report = "GLVND: " + d.Error;
    return result;
  }
  if (d.Present && d.GetCurrentThreadState() && !DispatchBound())
  {
    result.Done = false; // not remembered: probed again when nothing is current
    result.Report = "not probed: a GLX or EGL context is current on this thread";
    return result;
  }
  OSMesaContext context = CreateCoreContext();
  if (!context)
  {
    result.Report = "OSMesa could not create an OpenGL >= 3.2 core context";
    return result;
  }
  const int size = 4;
  std::vector<unsigned char> buffer(4 * size * size, 0);
  std::string error;
  if (!BindDispatch(false, &error) ||
    !OSMesa().MakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, size, size))
  {
    UnbindDispatch();
    result.Report = "the OSMesa context could not be made current" +
      (error.empty() ? std::string() : ": " + error);
    OSMesa().DestroyContext(context);
    return result;
  }
  // The two ways VTK reaches GL: direct GL 1.1 symbols (libOpenGL under
  // GLVND) and the loader's entry points (GLEW: glXGetProcAddressARB).
  const std::string renderer = String(glGetString(GL_RENDERER));
  const std::string version = String(glGetString(GL_VERSION));
  std::string loaderRenderer = renderer;
#if defined(VTKHAVS_USES_GLEW)
  {
    using GetStringProc = const GLubyte* (*)(GLenum);
    void* glx = dlopen("libGLX.so.0", RTLD_NOW | RTLD_NOLOAD);
    if (!glx)
    {
      glx = dlopen("libGL.so.1", RTLD_NOW | RTLD_NOLOAD);
    }
    auto getProc = glx
      ? reinterpret_cast<void* (*)(const GLubyte*)>(dlsym(glx, "glXGetProcAddressARB"))
      : nullptr;
    auto getString = getProc
      ? reinterpret_cast<GetStringProc>(getProc(reinterpret_cast<const GLubyte*>("glGetString")))
      : nullptr;
    loaderRenderer = getString ? String(getString(GL_RENDERER)) : "";
    if (glx)
    {
      dlclose(glx);
    }
  }
#endif
  glClearColor(1.0f, 0.5f, 0.25f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  const bool cleared = buffer[0] == 255 && buffer[1] >= 127 && buffer[1] <= 128 &&
    buffer[2] >= 63 && buffer[2] <= 64 && buffer[3] == 255;

  UnbindDispatch();
  OSMesa().MakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  OSMesa().DestroyContext(context);

  const std::string route = d.Present ? "GLVND dispatch table" : "direct (no GLVND)";
  if (renderer.empty() || loaderRenderer.empty() || !cleared)
  {
    std::ostringstream os;
    os << "the OSMesa context does not receive VTK's GL calls (" << route
       << "): glGetString(GL_RENDERER) gives '" << renderer << "' directly, '" << loaderRenderer
       << "' through the loader, and a clear " << (cleared ? "reaches" : "does not reach")
       << " its buffer";
    result.Report = os.str();
    return result;
  }
  result.Available = true;
  result.Report = renderer + ", OpenGL " + version + ", " + route;
  return result;
}

std::mutex ProbeMutex;
ProbeResult& ProbeState()
{
  static ProbeResult state;
  return state;
}

const ProbeResult& Probed()
{
  std::lock_guard<std::mutex> lock(ProbeMutex);
  ProbeResult& state = ProbeState();
  if (!state.Done)
  {
    state = Probe();
  }
  return state;
}
}

struct vtkHAVSOSMesaRenderWindow::Internals
{
  OSMesaContext Context = nullptr;
  std::vector<unsigned char> Buffer; // OSMesa's own framebuffer (VTK draws into its FBOs)
  int BufferSize[2] = { 0, 0 };
  std::string Route;
};

//------------------------------------------------------------------------------
vtkHAVSOSMesaRenderWindow::vtkHAVSOSMesaRenderWindow()
  : Internal(new Internals)
{
  this->SetFrameBlitModeToNoBlit();
  this->SetOffScreenRendering(1);
  // One sample per pixel: images are compared pixel by pixel with references.
  this->SetMultiSamples(0);
  this->SetOwnContext(1);
}

//------------------------------------------------------------------------------
vtkHAVSOSMesaRenderWindow::~vtkHAVSOSMesaRenderWindow()
{
  // The base destructor would only reach vtkGenericOpenGLRenderWindow::Finalize.
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkHAVSOSMesaRenderWindow::IsAvailable()
{
  return Probed().Available;
}

//------------------------------------------------------------------------------
std::string vtkHAVSOSMesaRenderWindow::GetProbeReport()
{
  return Probed().Report;
}

//------------------------------------------------------------------------------
bool vtkHAVSOSMesaRenderWindow::CreateContext()
{
  if (this->Internal->Context)
  {
    return true;
  }
  if (!OSMesa().Error.empty())
  {
    return false;
  }
  this->Internal->Context = CreateCoreContext();
  return this->Internal->Context != nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSOSMesaRenderWindow::DestroyContext()
{
  if (this->Internal->Context)
  {
    if (OSMesa().GetCurrentContext() == this->Internal->Context)
    {
      UnbindDispatch();
      OSMesa().MakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    }
    OSMesa().DestroyContext(this->Internal->Context);
    this->Internal->Context = nullptr;
  }
  this->Internal->Buffer.clear();
  this->Internal->BufferSize[0] = this->Internal->BufferSize[1] = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSOSMesaRenderWindow::Initialize()
{
  if (!this->CreateContext())
  {
    vtkErrorMacro("Could not create an OSMesa OpenGL (>= 3.2 core) context: "
      << (OSMesa().Error.empty() ? std::string("OSMesaCreateContextAttribs failed")
                                 : OSMesa().Error)
      << ". Set HAVS_RENDER_WINDOW=egl for a headless EGL context instead.");
    return;
  }
  this->MakeCurrent();
  if (this->IsCurrent() && !this->Initialized)
  {
    havs_gl::SetSymbolLoader(this, OSMesa().GetProcAddress);
    this->OpenGLInit();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSOSMesaRenderWindow::Render()
{
  // The generic window initializes OpenGL from whatever context is current:
  // make ours current (creating it on first use) first.
  this->Initialize();
  if (!this->IsCurrent())
  {
    return;
  }
  this->Superclass::Render();
  // Hand the thread's libGLdispatch state back: a GLX or EGL window can be
  // made current next. OSMesa's context stays current; VTK calls MakeCurrent
  // before it reads pixels or releases resources, which binds it again.
  UnbindDispatch();
}

//------------------------------------------------------------------------------
int vtkHAVSOSMesaRenderWindow::ReadPixels(
  const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right)
{
  const bool bound = DispatchBound();
  const int result = this->Superclass::ReadPixels(rect, front, glFormat, glType, data, right);
  if (!bound)
  {
    UnbindDispatch();
  }
  return result;
}

//------------------------------------------------------------------------------
int vtkHAVSOSMesaRenderWindow::GetZbufferData(int x1, int y1, int x2, int y2, float* z)
{
  const bool bound = DispatchBound();
  const int result = this->Superclass::GetZbufferData(x1, y1, x2, y2, z);
  if (!bound)
  {
    UnbindDispatch();
  }
  return result;
}

//------------------------------------------------------------------------------
void vtkHAVSOSMesaRenderWindow::ReleaseContext()
{
  if (this->Internal->Context && OSMesa().GetCurrentContext() == this->Internal->Context)
  {
    UnbindDispatch();
    OSMesa().MakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSOSMesaRenderWindow::MakeCurrent()
{
  if (!this->Internal->Context && !this->CreateContext())
  {
    return;
  }
  // First the thread's libGLdispatch state: releasing a GLX or EGL context
  // there also clears Mesa's current context, which OSMesa shares (libglapi).
  std::string error;
  if (!BindDispatch(true, &error))
  {
    vtkErrorMacro("GL calls cannot be routed to the OSMesa context: " << error);
    return;
  }
  // OSMesa's buffer follows the window's size (VTK renders into its own
  // framebuffer objects; the buffer is only the context's default one).
  const int width = std::max(this->Size[0], 1);
  const int height = std::max(this->Size[1], 1);
  if (OSMesa().GetCurrentContext() != this->Internal->Context ||
    this->Internal->BufferSize[0] != width || this->Internal->BufferSize[1] != height)
  {
    this->Internal->Buffer.assign(4 * static_cast<size_t>(width) * height, 0);
    if (!OSMesa().MakeCurrent(
          this->Internal->Context, this->Internal->Buffer.data(), GL_UNSIGNED_BYTE, width, height))
    {
      UnbindDispatch();
      vtkErrorMacro("OSMesaMakeCurrent failed.");
      return;
    }
    this->Internal->BufferSize[0] = width;
    this->Internal->BufferSize[1] = height;
  }
  this->Internal->Route = Dispatch().Present ? "glvnd" : "direct";
}

//------------------------------------------------------------------------------
bool vtkHAVSOSMesaRenderWindow::IsCurrent()
{
  return this->Internal->Context && OSMesa().GetCurrentContext() == this->Internal->Context &&
    DispatchBound();
}

//------------------------------------------------------------------------------
int vtkHAVSOSMesaRenderWindow::SupportsOpenGL()
{
  return vtkHAVSOSMesaRenderWindow::IsAvailable() ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSOSMesaRenderWindow::Finalize()
{
  if (this->Internal->Context)
  {
    this->MakeCurrent();
    if (this->Initialized && this->IsCurrent())
    {
      this->ReleaseGraphicsResources(this);
    }
    this->DestroyContext();
  }
  this->Initialized = false;
}

//------------------------------------------------------------------------------
std::string vtkHAVSOSMesaRenderWindow::GetDispatchRoute() const
{
  return this->Internal->Route;
}

//------------------------------------------------------------------------------
const char* vtkHAVSOSMesaRenderWindow::GetContextName() const
{
  return "OSMesa";
}

//------------------------------------------------------------------------------
void vtkHAVSOSMesaRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent
     << "Dispatch route: " << (this->Internal->Route.empty() ? "(none yet)" : this->Internal->Route)
     << "\n";
  os << indent << "Probe: " << vtkHAVSOSMesaRenderWindow::GetProbeReport() << "\n";
}

VTK_ABI_NAMESPACE_END
