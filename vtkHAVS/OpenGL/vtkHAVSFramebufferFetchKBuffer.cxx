/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFramebufferFetchKBuffer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSFramebufferFetchKBuffer.h"

#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSShaders.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <string>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSFramebufferFetchKBuffer);

namespace
{
const float kEmpty = 3.0e38f;    // an empty entry's distance
const float kNoFront = -2.0e38f; // no front yet: nothing integrated
}

//------------------------------------------------------------------------------
bool vtkHAVSFramebufferFetchKBuffer::IsSupported(vtkOpenGLRenderWindow*)
{
  GLint drawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
  return vtkHAVSGLCapabilities::HasVersion(4, 3) &&
    vtkHAVSGLCapabilities::HasExtension("GL_EXT_shader_framebuffer_fetch") && drawBuffers >= 8;
}

int vtkHAVSFramebufferFetchKBuffer::GetPath() const
{
  return vtkHAVSFrameRequest::PathFramebufferFetch;
}

int vtkHAVSFramebufferFetchKBuffer::GetMaximumK() const
{
  return vtkHAVSShaders::MaximumFetchK;
}

//------------------------------------------------------------------------------
bool vtkHAVSFramebufferFetchKBuffer::Allocate(vtkHAVSGLPassContext& context)
{
  const int k = context.Request.K;
  const int w = context.AllocatedWidth(), h = context.AllocatedHeight();
  if (this->Framebuffer && this->K == k && this->Size[0] == w && this->Size[1] == h)
  {
    return true;
  }
  this->ReleaseGraphicsResources(context.Window);
  this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  this->Framebuffer->SetContext(context.Window);
  this->Framebuffer->Bind();
  for (int a = 0; a < vtkHAVSShaders::FetchAttachments(k); ++a)
  {
    auto texture = vtkHAVSGLFrameTargets::NewFloatTexture(context.Window, w, h);
    this->Framebuffer->AddColorAttachment(a, texture);
    this->Targets.push_back(texture);
  }
  this->K = k;
  this->Size[0] = w;
  this->Size[1] = h;
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSFramebufferFetchKBuffer::Clear(vtkHAVSGLPassContext& context)
{
  const int attachments = static_cast<int>(this->Targets.size());
  this->Framebuffer->Bind();
  this->Framebuffer->ActivateDrawBuffers(attachments);
  const float zero[4] = { 0, 0, 0, 0 };
  const float firstPair[4] = { kNoFront, 0, kEmpty, 0 };
  const float emptyPair[4] = { kEmpty, 0, kEmpty, 0 };
  glClearBufferfv(GL_COLOR, 0, zero);
  for (int a = 1; a < attachments; ++a)
  {
    glClearBufferfv(GL_COLOR, a, a == 1 ? firstPair : emptyPair);
  }
  if (context.Request.SkipSaturated)
  {
    this->Saturation.Attach(context);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSFramebufferFetchKBuffer::Draw(vtkHAVSGLPassContext& context)
{
  vtkShaderProgram* program = context.FaceProgram(
    vtkHAVSShaders::FetchDrawShader(context.Request.K, context.ShaderFeatures()));
  if (program)
  {
    this->DrawFaces(context, program, false);
  }
  return program != nullptr;
}

//------------------------------------------------------------------------------
bool vtkHAVSFramebufferFetchKBuffer::Resolve(vtkHAVSGLPassContext& context)
{
  for (auto& t : this->Targets)
  {
    t->Activate();
  }
  vtkShaderProgram* program = context.QuadProgram(vtkHAVSShaders::ResolveShader(
    vtkHAVSFrameRequest::PathFramebufferFetch, context.Request.K, false, context.ShaderFeatures()));
  if (program)
  {
    program->SetUniformi("havsColorTexture", this->Targets[0]->GetTextureUnit());
    for (size_t a = 1; a < this->Targets.size(); ++a)
    {
      program->SetUniformi(
        ("havsEntryTexture" + std::to_string(a - 1)).c_str(), this->Targets[a]->GetTextureUnit());
    }
    context.DrawFullViewport();
  }
  for (auto& t : this->Targets)
  {
    t->Deactivate();
  }
  return program != nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSFramebufferFetchKBuffer::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& t : this->Targets)
  {
    t->ReleaseGraphicsResources(window);
  }
  this->Targets.clear();
  this->Saturation.ReleaseGraphicsResources();
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Framebuffer = nullptr;
  this->K = 0;
  this->Size[0] = this->Size[1] = 0;
}

VTK_ABI_NAMESPACE_END
