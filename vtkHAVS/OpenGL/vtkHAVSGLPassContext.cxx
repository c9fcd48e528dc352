/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLPassContext.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLPassContext.h"

#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLMapperResources.h"
#include "vtkHAVSGLMesh.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSShaders.h"
#include "vtkHAVSViewFrame.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <vector>

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
vtkHAVSGLPassContext::vtkHAVSGLPassContext(vtkOpenGLRenderWindow* window, vtkHAVSGLMesh* mesh,
  vtkHAVSGLTable* table, vtkHAVSGLFrameTargets* targets, const vtkHAVSFrameRequest& request)
  : Window(window)
  , Mesh(mesh)
  , Table(table)
  , Targets(targets)
  , Request(request)
{
  const vtkHAVSViewFrame& view = *request.View;
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToEyeRelative, this->ModelToEyeRelative);
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToClip, this->ModelToClip);
  vtkHAVSViewFrame::ToColumnMajor(view.ClipToEyeRelative, this->ClipToEyeRelative);
  for (int i = 0; i < 3; ++i)
  {
    this->Direction[i] = static_cast<float>(view.DirectionWorld[i]);
  }
}

int vtkHAVSGLPassContext::Width() const
{
  return this->Targets->GetSize()[0];
}

int vtkHAVSGLPassContext::Height() const
{
  return this->Targets->GetSize()[1];
}

int vtkHAVSGLPassContext::AllocatedWidth() const
{
  return this->Targets->GetAllocatedSize()[0];
}

int vtkHAVSGLPassContext::AllocatedHeight() const
{
  return this->Targets->GetAllocatedSize()[1];
}

vtkHAVSShaders::Features vtkHAVSGLPassContext::ShaderFeatures() const
{
  vtkHAVSShaders::Features f;
  f.CountViolations = this->Request.CountViolations;
  f.Tagging = this->Request.Tagging;
  f.Opaque = this->Request.Opaque;
  f.CellScalars = this->Request.CellScalars;
  f.Clipping = this->Request.Planes && this->Request.Planes->GetNumberOfPlanes() > 0;
  f.Projection = this->Request.View ? (this->Request.View->Parallel ? 1 : 0) : -1;
  f.IsoSurfaces = this->Request.IsoSurfaces;
  f.IsoShade = this->Request.IsoShade ? 2 : 0;
  f.IsoExact = this->Request.IsoExact;
  return f;
}

//------------------------------------------------------------------------------
vtkShaderProgram* vtkHAVSGLPassContext::Program(
  const std::string& vertexShader, const std::string& fragmentShader)
{
  vtkShaderProgram* program = this->Window->GetShaderCache()->ReadyShaderProgram(
    vertexShader.c_str(), fragmentShader.c_str(), "");
  if (!program || !program->GetCompiled())
  {
    return nullptr;
  }
  this->SetCommonUniforms(program);
  return program;
}

vtkShaderProgram* vtkHAVSGLPassContext::FaceProgram(const std::string& fragmentShader)
{
  return this->Program(
    vtkHAVSShaders::FaceVertexShader(this->Request.CellScalars, this->Request.IsoShade),
    fragmentShader);
}

vtkShaderProgram* vtkHAVSGLPassContext::QuadProgram(const std::string& fragmentShader)
{
  return this->Program(vtkHAVSShaders::QuadVertexShader(), fragmentShader);
}

//------------------------------------------------------------------------------
void vtkHAVSGLPassContext::SetCommonUniforms(vtkShaderProgram* program)
{
  const vtkHAVSFrameRequest& r = this->Request;
  this->Table->SetUniforms(program);
  program->SetUniformf("havsTerminationOpacity", r.TerminationOpacity);
  program->SetUniformi("havsOpaqueDepth", this->Targets->GetOpaqueDepth()->GetTextureUnit());
  this->Targets->SetDepthScaleUniform(program);
  program->SetUniformMatrix4x4("havsDCRC", this->ClipToEyeRelative);
  const float viewport[2] = { static_cast<float>(this->Width()),
    static_cast<float>(this->Height()) };
  program->SetUniform2f("havsViewportSize", viewport);
  program->SetUniformi("havsParallel", r.View->Parallel ? 1 : 0);
  program->SetUniform3f("havsDirectionOfProjection", this->Direction);
  program->SetUniformMatrix4x4("havsMCRC", this->ModelToEyeRelative);
  program->SetUniformMatrix4x4("havsMCDC", this->ModelToClip);
  vtkHAVSGLMapperResources::SetDoubleViewUniforms(program, *r.View); // (havsOnFace)
  program->SetUniformi(
    "havsMinimum", r.BlendMode == vtkHAVSFrameRequest::MinimumIntensityBlend ? 1 : 0);
  program->SetUniformf("havsGapLength", r.GapLength);
  program->SetUniformi("havsRole", 0);
  program->SetUniformi("havsOwnPlane", -1);
  const int planeCount = r.Planes->GetNumberOfPlanes();
  program->SetUniformi("havsPlaneCount", planeCount);
  if (planeCount > 0)
  {
    std::vector<float> planes(4 * planeCount);
    for (int i = 0; i < planeCount; ++i)
    {
      std::copy(r.Planes->GetPlane(i).begin(), r.Planes->GetPlane(i).end(), &planes[4 * i]);
    }
    program->SetUniform4fv(
      "havsPlanesRC", planeCount, reinterpret_cast<const float(*)[4]>(planes.data()));
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLPassContext::DrawFaces(vtkShaderProgram* program)
{
  this->Mesh->DrawFaces(program, this->Request.View->FlipFacing);
}

void vtkHAVSGLPassContext::DrawFullViewport()
{
  this->Targets->DrawFullViewport();
}

//------------------------------------------------------------------------------
vtkHAVSGLScopedPassState::vtkHAVSGLScopedPassState(vtkOpenGLState* state)
  : Viewport(state)
  , DepthTest(state, GL_DEPTH_TEST)
  , Blend(state, GL_BLEND)
  , Cull(state, GL_CULL_FACE)
  , Scissor(state, GL_SCISSOR_TEST)
  , DepthMask(state)
  , ColorMask(state)
  , BlendFunc(state)
{
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDepthMask(GL_FALSE);
}

VTK_ABI_NAMESPACE_END
