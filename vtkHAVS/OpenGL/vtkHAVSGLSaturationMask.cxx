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
#include "vtkRenderbuffer.h"
#include "vtkShaderProgram.h"

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
void vtkHAVSGLSaturationMask::Attach(vtkHAVSGLPassContext& context)
{
  const int w = context.AllocatedWidth(), h = context.AllocatedHeight();
  if (!this->Stencil || this->Stencil->GetContext() != context.Window)
  {
    // (A renderbuffer lives and dies with its object: vtkRenderbuffer frees
    // its name when deleted, and cannot be made again after a release.)
    this->Stencil = vtkSmartPointer<vtkRenderbuffer>::New();
    this->Stencil->SetContext(context.Window);
    this->Stencil->Create(GL_DEPTH24_STENCIL8, w, h);
  }
  else
  {
    this->Stencil->Resize(w, h); // (nothing when the size is the same)
  }
  glFramebufferRenderbuffer(
    GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, this->Stencil->GetHandle());
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
  this->Queries.Release(); // the last frame's
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
        this->Queries.BeginSamples();
      }
      context.DrawFullViewport();
      if (count)
      {
        this->Queries.EndSamples();
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
    this->LastSaturatedPixels = static_cast<vtkIdType>(this->Queries.Samples().back());
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLSaturationMask::ReleaseGraphicsResources()
{
  this->Stencil = nullptr; // its name deleted with it (the context is current)
  this->Queries.Release();
}

VTK_ABI_NAMESPACE_END
