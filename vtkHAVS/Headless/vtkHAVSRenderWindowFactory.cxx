/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRenderWindowFactory.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSRenderWindowFactory.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkHAVSEGLRenderWindow.h"
#include "vtkHAVSHeadlessDispatch.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkRenderingOpenGLConfigure.h" // For VTK_OPENGL_HAS_OSMESA

#if defined(VTK_OPENGL_HAS_OSMESA)
#include "vtkOSOpenGLRenderWindow.h" // VTK's own OSMesa window
#endif
#if defined(HAVS_HAS_OSMESA)
#include "vtkHAVSOSMesaRenderWindow.h"
#endif
#include "vtkHAVSWindowConfigure.h" // For VTKHAVS_HAS_GLFW
#if VTKHAVS_HAS_GLFW
#include "vtkHAVSGLFWRenderWindow.h"
#endif

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <iterator>
#include <map>
#include <mutex>
#include <sstream>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSRenderWindowFactory);

namespace
{
// Every backend this version knows, in the order of the table; `auto` tries
// kAutoOrder's.
const char* const kBackends[] = { "egl", "display", "glfw", "osmesa" };
const char* const kAutoOrder[] = { "egl", "display", "osmesa" };

std::string RequestedBackend()
{
  const char* value = std::getenv("HAVS_RENDER_WINDOW");
  return (value && *value) ? std::string(value) : std::string("auto");
}

bool IsKnown(const std::string& backend)
{
  for (const char* name : kBackends)
  {
    if (backend == name)
    {
      return true;
    }
  }
  return false;
}

/// Whether an X display opens: "" when it does, else why not. libX11 is
/// VTK's (vtkXOpenGLRenderWindow), looked up in the process, not linked. The
/// connection is kept for the process (one per DISPLAY value): an X server
/// without -noreset (xvfb-run's Xvfb) resets when its last client leaves, and
/// a window connecting during the reset fails.
std::string DisplayProblem()
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    return "DISPLAY is not set";
  }
  static void* x11 = dlopen("libX11.so.6", RTLD_NOW | RTLD_NOLOAD);
  if (!x11)
  {
    return ""; // no Xlib in this process: VTK's window is not an X window
  }
  static auto openDisplay = reinterpret_cast<void* (*)(const char*)>(dlsym(x11, "XOpenDisplay"));
  if (!openDisplay)
  {
    return "";
  }
  static std::mutex mutex;
  static std::map<std::string, void*> connections;
  std::lock_guard<std::mutex> lock(mutex);
  if (connections.count(display))
  {
    return "";
  }
  if (void* connection = openDisplay(display))
  {
    connections[display] = connection;
    return "";
  }
  return std::string("the X display '") + display + "' cannot be opened";
}

/// The class of VTK's own window for this build (vtkXOpenGLRenderWindow on Debian).
std::string DisplayWindowClass()
{
  vtkNew<vtkRenderWindow> window; // no connection is made before it renders
  return window->GetClassName();
}

const char* const kOSMesaNotBuilt = VTKHAVS_OSMESA_NOT_BUILT
  ", and this VTK has no OSMesa window (VTK_OPENGL_HAS_OSMESA is not defined)";
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkHAVSRenderWindowFactory::GetBackendNames()
{
  return std::vector<std::string>(std::begin(kBackends), std::end(kBackends));
}

//------------------------------------------------------------------------------
int vtkHAVSRenderWindowFactory::GetNumberOfBackends()
{
  return static_cast<int>(std::size(kBackends));
}

//------------------------------------------------------------------------------
std::string vtkHAVSRenderWindowFactory::GetBackendNameByIndex(int index)
{
  return (index >= 0 && index < vtkHAVSRenderWindowFactory::GetNumberOfBackends())
    ? kBackends[index]
    : "";
}

//------------------------------------------------------------------------------
bool vtkHAVSRenderWindowFactory::IsBackendBuilt(const std::string& backend)
{
  if (backend == "egl" || backend == "display")
  {
    return true;
  }
  if (backend == "osmesa")
  {
#if defined(VTK_OPENGL_HAS_OSMESA) || defined(HAVS_HAS_OSMESA)
    return true;
#else
    return false;
#endif
  }
  if (backend == "glfw")
  {
    return VTKHAVS_HAS_GLFW != 0;
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkHAVSRenderWindowFactory::IsBackendAvailable(const std::string& backend)
{
  if (!vtkHAVSRenderWindowFactory::IsBackendBuilt(backend))
  {
    return false;
  }
  if (backend == "egl")
  {
    return vtkHAVSEGLRenderWindow::IsAvailable();
  }
  if (backend == "display")
  {
    return DisplayProblem().empty();
  }
  if (backend == "osmesa")
  {
#if defined(VTK_OPENGL_HAS_OSMESA)
    return true; // VTK's own window: VTK reports its own failures
#elif defined(HAVS_HAS_OSMESA)
    return vtkHAVSOSMesaRenderWindow::IsAvailable();
#endif
  }
#if VTKHAVS_HAS_GLFW
  if (backend == "glfw")
  {
    return vtkHAVSGLFWRenderWindow::IsAvailable();
  }
#endif
  return false;
}

//------------------------------------------------------------------------------
std::string vtkHAVSRenderWindowFactory::GetBackendStatus(const std::string& backend)
{
  if (!IsKnown(backend))
  {
    return "unknown backend '" + backend + "' (known: egl, display, glfw, osmesa)";
  }
  if (backend == "egl")
  {
    return (vtkHAVSEGLRenderWindow::IsAvailable() ? "available: " : "unavailable: ") +
      vtkHAVSEGLRenderWindow::GetProbeReport();
  }
  if (backend == "display")
  {
    const std::string problem = DisplayProblem();
    return problem.empty()
      ? "available: " + DisplayWindowClass() + " on DISPLAY=" + std::getenv("DISPLAY")
      : "unavailable: " + problem;
  }
  if (backend == "osmesa")
  {
#if defined(VTK_OPENGL_HAS_OSMESA)
    return "available: VTK's own vtkOSOpenGLRenderWindow (VTK_OPENGL_HAS_OSMESA)";
#elif defined(HAVS_HAS_OSMESA)
    return (vtkHAVSOSMesaRenderWindow::IsAvailable() ? "available: " : "unavailable: ") +
      vtkHAVSOSMesaRenderWindow::GetProbeReport();
#else
    return std::string("not built: ") + kOSMesaNotBuilt;
#endif
  }
  // glfw
#if VTKHAVS_HAS_GLFW
  return vtkHAVSGLFWRenderWindow::IsAvailable()
    ? std::string("available: a hidden GLFW 3.3 window, its GLX context")
    : "unavailable: " + vtkHAVSGLFWRenderWindow::GetUnavailableReason();
#else
  return "not built: GLFW 3.3 (libglfw3-dev) was not found when vtkHAVS was configured";
#endif
}

//------------------------------------------------------------------------------
std::string vtkHAVSRenderWindowFactory::DescribeBackends()
{
  std::ostringstream os;
  os << "| backend | built | usable now | note |\n";
  os << "|---|---|---|---|\n";
  for (const char* name : kBackends)
  {
    const bool built = vtkHAVSRenderWindowFactory::IsBackendBuilt(name);
    const bool available = vtkHAVSRenderWindowFactory::IsBackendAvailable(name);
    os << "| " << name << " | " << (built ? "yes" : "no") << " | " << (available ? "yes" : "no")
       << " | " << vtkHAVSRenderWindowFactory::GetBackendStatus(name) << " |\n";
  }
  const std::string selected = vtkHAVSRenderWindowFactory::GetSelectedBackend();
  os << "\nHAVS_RENDER_WINDOW=" << RequestedBackend()
     << " selects: " << (selected.empty() ? std::string("(none)") : selected) << "\n";
  return os.str();
}

//------------------------------------------------------------------------------
const char* vtkHAVSRenderWindowFactory::GetSelectedBackend()
{
  const std::string requested = RequestedBackend();
  for (const char* name : kBackends)
  {
    if (requested == name)
    {
      return name;
    }
  }
  if (requested != "auto")
  {
    vtkGenericWarningMacro("HAVS_RENDER_WINDOW=" << requested
                                                 << " is not one of egl, display, glfw, osmesa, "
                                                    "auto; using auto.");
  }
  for (const char* name : kAutoOrder)
  {
    if (vtkHAVSRenderWindowFactory::IsBackendAvailable(name))
    {
      return name;
    }
  }
  return "";
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkHAVSRenderWindowFactory::CreateRenderWindow()
{
  const std::string backend = vtkHAVSRenderWindowFactory::GetSelectedBackend();
  if (backend.empty())
  {
    vtkGenericWarningMacro("No render window can be made:\n"
      << vtkHAVSRenderWindowFactory::DescribeBackends());
    return nullptr;
  }
  return vtkHAVSRenderWindowFactory::CreateRenderWindow(backend);
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkHAVSRenderWindowFactory::CreateRenderWindow(const std::string& backend)
{
  if (backend == "auto")
  {
    return vtkHAVSRenderWindowFactory::CreateRenderWindow();
  }
  if (!vtkHAVSRenderWindowFactory::IsBackendAvailable(backend))
  {
    vtkGenericWarningMacro("The '" << backend << "' render window cannot be made here ("
                                   << vtkHAVSRenderWindowFactory::GetBackendStatus(backend)
                                   << ").");
    return nullptr;
  }
  if (backend == "egl")
  {
    return vtkHAVSEGLRenderWindow::New();
  }
  if (backend == "display")
  {
    // VTK >= 9.4 chooses its window at run time and makes the X window's GLX
    // context current inside vtkRenderWindow::New(): the thread must be free
    // of our EGL and OSMesa contexts already (see below).
    havs_dispatch::TakeThread(havs_dispatch::kTagGLX);
    vtkRenderWindow* window = vtkRenderWindow::New();
    window->SetMultiSamples(0);
    // Under GLVND libGLX cannot make its context current while an EGL or
    // OSMesa window of this process holds the thread: release it first.
    vtkNew<vtkCallbackCommand> takeThread;
    takeThread->SetCallback([](vtkObject*, unsigned long, void*, void*)
      { havs_dispatch::TakeThread(havs_dispatch::kTagGLX); });
    window->AddObserver(vtkCommand::StartEvent, takeThread);
    return window;
  }
  if (backend == "osmesa")
  {
#if defined(VTK_OPENGL_HAS_OSMESA)
    vtkRenderWindow* window = vtkOSOpenGLRenderWindow::New();
    window->SetMultiSamples(0);
    return window;
#elif defined(HAVS_HAS_OSMESA)
    return vtkHAVSOSMesaRenderWindow::New();
#endif
  }
#if VTKHAVS_HAS_GLFW
  if (backend == "glfw")
  {
    // A hidden GLFW window: the factory's windows render off screen.
    vtkHAVSGLFWRenderWindow* window = vtkHAVSGLFWRenderWindow::New();
    window->SetShowWindow(false);
    return window;
  }
#endif
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSRenderWindowFactory::ReleaseCurrentContext()
{
  havs_dispatch::TakeThread(havs_dispatch::kTagNone);
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
  // VTK's own OSMesa window or ours.
  if (window->IsA("vtkOSOpenGLRenderWindow") || window->IsA("vtkHAVSOSMesaRenderWindow"))
  {
    return "osmesa";
  }
  return "display";
}

//------------------------------------------------------------------------------
void vtkHAVSRenderWindowFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Selected backend: " << vtkHAVSRenderWindowFactory::GetSelectedBackend() << "\n";
}

VTK_ABI_NAMESPACE_END
