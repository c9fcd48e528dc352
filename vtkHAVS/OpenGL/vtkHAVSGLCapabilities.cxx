/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLCapabilities.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLCapabilities.h"

#include "vtkHAVSOpenGL.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

VTK_ABI_NAMESPACE_BEGIN

namespace vtkHAVSGLCapabilities
{
bool HasExtension(const char* name)
{
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
  {
    const char* ext = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
    if (ext && std::strcmp(ext, name) == 0)
    {
      return true;
    }
  }
  return false;
}

bool HasVersion(int major, int minor)
{
  GLint maj = 0, min = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &maj);
  glGetIntegerv(GL_MINOR_VERSION, &min);
  return maj > major || (maj == major && min >= minor);
}

bool InterlockEmulated()
{
  const char* requested = std::getenv("HAVS_EMULATE_INTERLOCK");
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return requested && std::string(requested) == "1" && renderer &&
    std::strstr(renderer, "llvmpipe") != nullptr;
}

long long FacesPerFinish()
{
  if (const char* requested = std::getenv("HAVS_FACES_PER_FINISH"))
  {
    return std::max(0LL, std::atoll(requested));
  }
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const bool software = renderer &&
    (std::strstr(renderer, "llvmpipe") != nullptr || std::strstr(renderer, "softpipe") != nullptr);
  return software ? (1LL << 18) : 0;
}

DrawThrottle::~DrawThrottle()
{
  for (void*& fence : this->Fences)
  {
    if (fence)
    {
      glDeleteSync(static_cast<GLsync>(fence));
      fence = nullptr;
    }
  }
}

void DrawThrottle::Before()
{
  if (void* fence = this->Fences[this->Next])
  {
    while (glClientWaitSync(static_cast<GLsync>(fence), GL_SYNC_FLUSH_COMMANDS_BIT,
             1000000000ull) == GL_TIMEOUT_EXPIRED)
    {
    }
    glDeleteSync(static_cast<GLsync>(fence));
    this->Fences[this->Next] = nullptr;
  }
}

void DrawThrottle::After()
{
  this->Fences[this->Next] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  this->Next ^= 1;
}

vtkHAVSShaders::InterlockKind AvailableInterlock()
{
  if (HasExtension("GL_ARB_fragment_shader_interlock"))
  {
    return vtkHAVSShaders::InterlockARB;
  }
  if (HasExtension("GL_NV_fragment_shader_interlock"))
  {
    return vtkHAVSShaders::InterlockNV;
  }
  return vtkHAVSShaders::InterlockNone;
}
}

VTK_ABI_NAMESPACE_END
