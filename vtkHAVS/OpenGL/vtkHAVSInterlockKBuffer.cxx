/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSInterlockKBuffer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSInterlockKBuffer.h"

#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSShaders.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSInterlockKBuffer);

//------------------------------------------------------------------------------
bool vtkHAVSInterlockKBuffer::IsSupported(vtkOpenGLRenderWindow*)
{
  return vtkHAVSGLCapabilities::HasVersion(4, 3) &&
    (vtkHAVSGLCapabilities::HasExtension("GL_ARB_fragment_shader_interlock") ||
      vtkHAVSGLCapabilities::HasExtension("GL_NV_fragment_shader_interlock") ||
      vtkHAVSGLCapabilities::InterlockEmulated());
}

int vtkHAVSInterlockKBuffer::GetPath() const
{
  return vtkHAVSFrameRequest::PathFragmentShaderInterlock;
}

int vtkHAVSInterlockKBuffer::GetMaximumK() const
{
  return vtkHAVSShaders::MaximumInterlockK;
}

//------------------------------------------------------------------------------
bool vtkHAVSInterlockKBuffer::Allocate(vtkHAVSGLPassContext& context)
{
  // At the allocated size: a reduced frame's pixels (indexed by the drawn
  // width) fit, and the buffer is not made again when the level of detail
  // changes the drawn size.
  const size_t bytes = static_cast<size_t>(context.AllocatedWidth()) * context.AllocatedHeight() *
    vtkHAVSShaders::InterlockPixelStride(context.Request.K) * 4 * sizeof(float);
  // Its "version" is its size: made again only when the size changes.
  this->PixelEntries.Update(GL_SHADER_STORAGE_BUFFER, nullptr, bytes, bytes, GL_DYNAMIC_COPY);
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSInterlockKBuffer::Clear(vtkHAVSGLPassContext& context)
{
  this->PixelEntries.BindBase(GL_SHADER_STORAGE_BUFFER, 0);
  context.Targets->BindResult();
  context.Window->GetState()->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  vtkShaderProgram* clear =
    context.QuadProgram(vtkHAVSShaders::InterlockClearShader(context.Request.K));
  if (clear)
  {
    context.DrawFullViewport();
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  if (context.Request.SkipSaturated)
  {
    this->Saturation.Attach(context); // on the result's framebuffer, which rasterizes the faces
  }
  return clear != nullptr;
}

//------------------------------------------------------------------------------
bool vtkHAVSInterlockKBuffer::Draw(vtkHAVSGLPassContext& context)
{
  vtkShaderProgram* program = context.FaceProgram(vtkHAVSShaders::InterlockDrawShader(
    context.Request.K, vtkHAVSGLCapabilities::AvailableInterlock(), context.ShaderFeatures()));
  if (program)
  {
    this->DrawFaces(context, program, true);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  context.Window->GetState()->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  return program != nullptr;
}

//------------------------------------------------------------------------------
bool vtkHAVSInterlockKBuffer::Resolve(vtkHAVSGLPassContext& context)
{
  this->PixelEntries.BindBase(GL_SHADER_STORAGE_BUFFER, 0);
  vtkShaderProgram* program = context.QuadProgram(
    vtkHAVSShaders::ResolveShader(vtkHAVSFrameRequest::PathFragmentShaderInterlock,
      context.Request.K, false, context.ShaderFeatures()));
  if (program)
  {
    context.DrawFullViewport();
  }
  return program != nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSInterlockKBuffer::ReleaseGraphicsResources(vtkWindow*)
{
  this->Saturation.ReleaseGraphicsResources();
  this->PixelEntries.Release();
}

VTK_ABI_NAMESPACE_END
