/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLSaturationMask.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLSaturationMask.h"

#include "vtkHAVSGLMesh.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSViewFrame.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"

VTK_ABI_NAMESPACE_BEGIN

namespace
{
vtkIdType ReadQuery(GLuint query)
{
  GLuint64 value = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &value);
  return static_cast<vtkIdType>(value);
}
}

//------------------------------------------------------------------------------
void vtkHAVSGLSaturationMask::Attach(vtkHAVSGLPassContext& context)
{
  const int w = context.Width(), h = context.Height();
  if (!this->Stencil || this->Size[0] != w || this->Size[1] != h)
  {
    if (!this->Stencil)
    {
      glGenRenderbuffers(1, &this->Stencil);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, this->Stencil);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    this->Size[0] = w;
    this->Size[1] = h;
  }
  glFramebufferRenderbuffer(
    GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, this->Stencil);
  vtkOpenGLState* state = context.Window->GetState();
  state->vtkglStencilMask(0xFF);
  const GLint zero = 0;
  glClearBufferiv(GL_STENCIL, 0, &zero);
}

//------------------------------------------------------------------------------
void vtkHAVSGLSaturationMask::DrawFaces(vtkHAVSGLPassContext& context, vtkShaderProgram* program,
  const std::string& markShader, bool storageBarrier, bool measure)
{
  this->LastSaturatedPixels = -1;
  if (markShader.empty())
  {
    context.DrawFaces(program);
    return;
  }
  if (measure && !this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  vtkOpenGLState* state = context.Window->GetState();
  vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
  state->vtkglEnable(GL_STENCIL_TEST);
  state->vtkglStencilFunc(GL_EQUAL, 0, 0xFF);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  bool marked = false;
  auto mark = [&](int batch)
  {
    if (storageBarrier)
    {
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    if (context.QuadProgram(markShader))
    {
      vtkOpenGLState::ScopedglColorMask colorMask(state);
      state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      state->vtkglStencilFunc(GL_ALWAYS, 1, 0xFF);
      state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      const bool count = measure && batch + 2 == Batches; // the last mark
      if (count)
      {
        glBeginQuery(GL_SAMPLES_PASSED, this->Query);
      }
      context.DrawFullViewport();
      if (count)
      {
        glEndQuery(GL_SAMPLES_PASSED);
        marked = true;
      }
      state->vtkglStencilFunc(GL_EQUAL, 0, 0xFF);
      state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    }
    context.Window->GetShaderCache()->ReadyShaderProgram(program);
  };
  context.Mesh->DrawFaces(program, context.Request.View->FlipFacing, Batches, mark);
  state->vtkglStencilFunc(GL_ALWAYS, 0, 0xFF);
  if (marked)
  {
    this->LastSaturatedPixels = ReadQuery(this->Query);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLSaturationMask::ReleaseGraphicsResources()
{
  if (this->Stencil)
  {
    glDeleteRenderbuffers(1, &this->Stencil);
    this->Stencil = 0;
  }
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
    this->Query = 0;
  }
  this->Size[0] = this->Size[1] = 0;
}

VTK_ABI_NAMESPACE_END
