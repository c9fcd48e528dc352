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

bool RendererIs(const char* name)
{
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && std::strstr(renderer, name) != nullptr;
}

bool InterlockEmulated()
{
  const char* requested = std::getenv("HAVS_EMULATE_INTERLOCK");
  return requested && std::string(requested) == "1" && RendererIs("llvmpipe");
}

long long FacesPerFinish()
{
  if (const char* requested = std::getenv("HAVS_FACES_PER_FINISH"))
  {
    return std::max(0LL, std::atoll(requested));
  }
  return RendererIs("llvmpipe") || RendererIs("softpipe") ? (1LL << 18) : 0;
}

void DrawInPieces(long long first, long long last, long long perPiece,
  const std::function<void(long long, long long)>& draw)
{
  GLsync fences[2] = { nullptr, nullptr }; // the last two pieces drawn
  int next = 0;
  for (long long piece = first; piece < last;)
  {
    const long long end = perPiece > 0 ? std::min(last, piece + perPiece) : last;
    if (GLsync fence = fences[next])
    {
      while (
        glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000ull) == GL_TIMEOUT_EXPIRED)
      {
      }
      glDeleteSync(fence);
      fences[next] = nullptr;
    }
    draw(piece, end);
    if (end < last)
    {
      fences[next] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
      next ^= 1;
    }
    piece = end;
  }
  for (GLsync fence : fences)
  {
    if (fence)
    {
      glDeleteSync(fence);
    }
  }
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
