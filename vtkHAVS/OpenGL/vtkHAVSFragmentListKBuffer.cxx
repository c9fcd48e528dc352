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
const size_t kNodeBytes = 16;         // distance, code, next, spare
const size_t kNodeGradientBytes = 16; // (shaded isosurfaces) the gradient, spare
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
  this->Nodes.Update(
    GL_SHADER_STORAGE_BUFFER, nullptr, size_t(this->Capacity) * kNodeBytes, 0, GL_DYNAMIC_COPY);
  if (this->NodeGradients.GetHandle())
  {
    this->GrowNodeGradients();
  }
}

void vtkHAVSFragmentListKBuffer::GrowNodeGradients()
{
  this->NodeGradients.Update(GL_SHADER_STORAGE_BUFFER, nullptr,
    size_t(this->Capacity) * kNodeGradientBytes, 0, GL_DYNAMIC_COPY);
}

//------------------------------------------------------------------------------
bool vtkHAVSFragmentListKBuffer::Allocate(vtkHAVSGLPassContext& context)
{
  const int width = context.Width(), height = context.Height();
  this->Heads.Resize(GL_R32UI, context.AllocatedWidth(), context.AllocatedHeight());
  if (!this->Counter.GetHandle())
  {
    this->Counter.Update(GL_SHADER_STORAGE_BUFFER, nullptr, sizeof(GLuint), 0, GL_DYNAMIC_READ);
  }
  const GLuint wanted =
    static_cast<GLuint>(std::max<size_t>(static_cast<size_t>(width) * height * 4, size_t(1) << 20));
  if (this->Capacity < wanted)
  {
    this->GrowNodes(wanted);
  }
  // Shaded isosurfaces: a gradient beside every node (released when not).
  if (context.Request.IsoShade && !this->NodeGradients.GetHandle())
  {
    this->GrowNodeGradients();
  }
  else if (!context.Request.IsoShade && this->NodeGradients.GetHandle())
  {
    this->NodeGradients.Release();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSFragmentListKBuffer::Clear(vtkHAVSGLPassContext&)
{
  const GLuint noNode = 0xFFFFFFFFu, zero = 0;
  this->Heads.Clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &noNode);
  this->Counter.Write(0, &zero, sizeof(GLuint));
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
    this->Nodes.BindBase(GL_SHADER_STORAGE_BUFFER, 1);
    this->Counter.BindBase(GL_SHADER_STORAGE_BUFFER, 2);
    this->Heads.BindImage(0);
    if (this->NodeGradients.GetHandle())
    {
      this->NodeGradients.BindBase(GL_SHADER_STORAGE_BUFFER, 13);
    }
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
    this->Counter.Read(0, &count, sizeof(GLuint));
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
  this->Heads.BindImage(0);
  this->Nodes.BindBase(GL_SHADER_STORAGE_BUFFER, 1);
  if (this->NodeGradients.GetHandle())
  {
    this->NodeGradients.BindBase(GL_SHADER_STORAGE_BUFFER, 13);
  }
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
  this->Nodes.Release();
  this->NodeGradients.Release();
  this->Counter.Release();
  this->Capacity = 0;
  this->Heads.Release();
}

VTK_ABI_NAMESPACE_END
