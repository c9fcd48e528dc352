/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFragmentListKBuffer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSFragmentListKBuffer.h"

#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSShaders.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSFragmentListKBuffer);

namespace
{
const size_t kNodeBytes = 16; // distance, code, next, spare
}

//------------------------------------------------------------------------------
bool vtkHAVSFragmentListKBuffer::IsSupported(vtkOpenGLRenderWindow*)
{
  return vtkHAVSGLCapabilities::HasVersion(4, 3) &&
    (vtkHAVSGLCapabilities::HasVersion(4, 4) ||
      vtkHAVSGLCapabilities::HasExtension("GL_ARB_clear_texture"));
}

int vtkHAVSFragmentListKBuffer::GetPath() const
{
  return vtkHAVSFrameRequest::PathFragmentLists;
}

int vtkHAVSFragmentListKBuffer::GetMaximumK() const
{
  return vtkHAVSShaders::ListResolveCapacity;
}

//------------------------------------------------------------------------------
void vtkHAVSFragmentListKBuffer::GrowNodes(GLuint capacity)
{
  this->Capacity = capacity;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Nodes);
  glBufferData(
    GL_SHADER_STORAGE_BUFFER, size_t(this->Capacity) * kNodeBytes, nullptr, GL_DYNAMIC_COPY);
}

//------------------------------------------------------------------------------
bool vtkHAVSFragmentListKBuffer::Allocate(vtkHAVSGLPassContext& context)
{
  const int width = context.Width(), height = context.Height();
  if (!this->Heads || this->HeadsSize[0] != width || this->HeadsSize[1] != height)
  {
    if (this->Heads)
    {
      glDeleteTextures(1, &this->Heads);
    }
    glGenTextures(1, &this->Heads);
    glBindTexture(GL_TEXTURE_2D, this->Heads);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32UI, width, height);
    glBindTexture(GL_TEXTURE_2D, 0);
    this->HeadsSize[0] = width;
    this->HeadsSize[1] = height;
  }
  if (!this->Counter)
  {
    glGenBuffers(1, &this->Counter);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Counter);
    glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
    glGenBuffers(1, &this->Nodes);
  }
  const GLuint wanted =
    static_cast<GLuint>(std::max<size_t>(static_cast<size_t>(width) * height * 4, size_t(1) << 20));
  if (this->Capacity < wanted)
  {
    this->GrowNodes(wanted);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSFragmentListKBuffer::Clear(vtkHAVSGLPassContext&)
{
  const GLuint noNode = 0xFFFFFFFFu, zero = 0;
  glClearTexImage(this->Heads, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noNode);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Counter);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &zero);
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSFragmentListKBuffer::Draw(vtkHAVSGLPassContext& context)
{
  context.Targets->BindResult();
  vtkOpenGLState* state = context.Window->GetState();
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  bool ok = true;
  // Draw; when the node pool overflows, grow it to fit and draw again.
  for (int attempt = 0; ok && attempt < 2; ++attempt)
  {
    if (attempt > 0)
    {
      this->Clear(context);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->Nodes);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, this->Counter);
    glBindImageTexture(0, this->Heads, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    vtkShaderProgram* program =
      context.FaceProgram(vtkHAVSShaders::ListDrawShader(context.ShaderFeatures()));
    ok = program != nullptr;
    if (!ok)
    {
      break;
    }
    program->SetUniformi("havsNodeCapacity", static_cast<int>(this->Capacity));
    context.DrawFaces(program);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
      GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint count = 0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Counter);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &count);
    this->LastFragmentCount = count;
    if (count <= this->Capacity)
    {
      break;
    }
    this->GrowNodes(count + count / 4);
  }
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  return ok;
}

//------------------------------------------------------------------------------
bool vtkHAVSFragmentListKBuffer::Resolve(vtkHAVSGLPassContext& context)
{
  const bool vote = vtkHAVSGLCapabilities::HasExtension("GL_ARB_shader_group_vote");
  glBindImageTexture(0, this->Heads, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->Nodes);
  vtkShaderProgram* program = context.QuadProgram(vtkHAVSShaders::ResolveShader(
    vtkHAVSFrameRequest::PathFragmentLists, context.Request.K, vote, context.ShaderFeatures()));
  if (program)
  {
    program->SetUniformi("havsNodeCapacity", static_cast<int>(this->Capacity));
    context.DrawFullViewport();
  }
  return program != nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSFragmentListKBuffer::ReleaseGraphicsResources(vtkWindow*)
{
  for (GLuint* buffer : { &this->Nodes, &this->Counter })
  {
    if (*buffer)
    {
      glDeleteBuffers(1, buffer);
      *buffer = 0;
    }
  }
  this->Capacity = 0;
  if (this->Heads)
  {
    glDeleteTextures(1, &this->Heads);
    this->Heads = 0;
    this->HeadsSize[0] = this->HeadsSize[1] = 0;
  }
}

VTK_ABI_NAMESPACE_END
