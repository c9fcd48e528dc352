/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSHeadlessDispatch.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSHeadlessDispatch.h
 * @brief Private to vtkHAVS::Headless: who holds this thread's GLVND current
 * context (libGLdispatch's thread state), and how a window takes it.
 *
 * Under GLVND one context is current per thread for GLX, EGL and the OSMesa
 * window's dispatch table together; libEGL refuses to make a context current
 * while another API's state is (EGL_BAD_ACCESS), libGLX too (an X error,
 * BadAccess on X_GLXMakeCurrent, which ends the program). The windows of
 * vtkHAVS::Headless therefore take the thread from whichever API holds it
 * before they make their context current. Without GLVND (no libGLdispatch in
 * the process) none of this applies and nothing is done.
 */
#ifndef vtkHAVSHeadlessDispatch_h
#define vtkHAVSHeadlessDispatch_h

#include <EGL/egl.h>

#include <dlfcn.h>

namespace havs_dispatch
{
constexpr int kTagNone = -1;
constexpr int kTagGLX = 0; // libglvnd's GLDISPATCH_API_GLX
constexpr int kTagEGL = 1; // libglvnd's GLDISPATCH_API_EGL
/// The tag of vtkHAVSOSMesaRenderWindow's thread state: neither of the above,
/// so that libGLX and libEGL never take it for theirs.
constexpr int kTagOSMesa = 0x4f534d;

struct Entries
{
  int* (*GetCurrentThreadState)() = nullptr;
  void (*LoseCurrent)() = nullptr;
};

inline const Entries& Dispatch()
{
  static const Entries entries = []
  {
    Entries e;
    if (void* handle = dlopen("libGLdispatch.so.0", RTLD_NOW | RTLD_NOLOAD))
    {
      e.GetCurrentThreadState =
        reinterpret_cast<int* (*)()>(dlsym(handle, "__glDispatchGetCurrentThreadState"));
      e.LoseCurrent = reinterpret_cast<void (*)()>(dlsym(handle, "__glDispatchLoseCurrent"));
      if (!e.GetCurrentThreadState || !e.LoseCurrent)
      {
        e = Entries();
      }
    }
    return e;
  }();
  return entries;
}

/// The API holding this thread (a state begins with its tag), kTagNone if none.
inline int CurrentTag()
{
  const Entries& e = Dispatch();
  const int* state = e.GetCurrentThreadState ? e.GetCurrentThreadState() : nullptr;
  return state ? *state : kTagNone;
}

/// Releases the thread's GLX context (glXMakeCurrent(display, None, NULL)).
inline void ReleaseGLX()
{
  void* glx = dlopen("libGLX.so.0", RTLD_NOW | RTLD_NOLOAD);
  if (!glx)
  {
    return;
  }
  auto getDisplay = reinterpret_cast<void* (*)()>(dlsym(glx, "glXGetCurrentDisplay"));
  auto makeCurrent =
    reinterpret_cast<int (*)(void*, unsigned long, void*)>(dlsym(glx, "glXMakeCurrent"));
  if (getDisplay && makeCurrent && getDisplay())
  {
    makeCurrent(getDisplay(), 0, nullptr);
  }
  dlclose(glx);
}

/// Releases whichever API other than `tag` holds this thread.
inline void TakeThread(int tag)
{
  const int current = CurrentTag();
  if (current == kTagNone || current == tag)
  {
    return;
  }
  if (current == kTagEGL)
  {
    eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  else if (current == kTagGLX)
  {
    ReleaseGLX();
  }
  else if (current == kTagOSMesa)
  {
    Dispatch().LoseCurrent();
  }
}
}

#endif
