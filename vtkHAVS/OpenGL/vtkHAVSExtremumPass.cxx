/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSExtremumPass.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSExtremumPass.h"

#include "vtkVolumeMapper.h"

#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSShaders.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSExtremumPass);

//------------------------------------------------------------------------------
bool vtkHAVSExtremumPass::Draw(vtkHAVSGLPassContext& context)
{
  vtkOpenGLState* state = context.Window->GetState();
  context.Targets->BindResult();
  const float zero[4] = { 0, 0, 0, 0 };
  glClearBufferfv(GL_COLOR, 0, zero);
  vtkShaderProgram* program =
    context.FaceProgram(vtkHAVSShaders::ExtremumDrawShader(context.ShaderFeatures()));
  if (!program)
  {
    return false;
  }
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendEquation(GL_MAX);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  context.DrawFaces(program);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  state->vtkglDisable(GL_BLEND);
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSExtremumPass::Resolve(vtkHAVSGLPassContext& context)
{
  const bool minimum = context.Request.BlendMode == vtkHAVSFrameRequest::MinimumIntensityBlend;
  return ResolveResult(
    context.Window, context.Targets, context.Table, minimum ? ResolveMinimum : ResolveMaximum);
}

//------------------------------------------------------------------------------
bool vtkHAVSExtremumPass::ResolveResult(vtkOpenGLRenderWindow* window,
  vtkHAVSGLFrameTargets* targets, vtkHAVSGLTable* table, ResolveKind kind)
{
  // The draw wrote the result texture; the resolve reads a copy of it.
  vtkTextureObject* extremum = targets->CopyResult();
  targets->BindResult();
  vtkTextureObject* function = table->GetTransferFunction1D();
  function->Activate();
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkHAVSShaders::QuadVertexShader().c_str(),
      vtkHAVSShaders::ExtremumResolveShader(table->HasCellOptics()).c_str(), "");
  const bool built = program && program->GetCompiled();
  if (built)
  {
    // (The program is shared by every mapper in the window: set every mode uniform.)
    table->SetUniforms(program);
    program->SetUniformi("havsExtremumTexture", extremum->GetTextureUnit());
    program->SetUniformi("havsTransferFunction", function->GetTextureUnit());
    program->SetUniformi("havsMinimum", kind == ResolveMinimum ? 1 : 0);
    program->SetUniformi("havsAdditiveResolve", kind == ResolveAdditive ? 1 : 0);
    window->GetState()->vtkglDisable(GL_BLEND);
    targets->DrawFullViewport();
  }
  function->Deactivate();
  extremum->Deactivate();
  return built;
}

//------------------------------------------------------------------------------
bool vtkHAVSExtremumPass::ResolveBlend(vtkOpenGLRenderWindow* window,
  vtkHAVSGLFrameTargets* targets, vtkHAVSGLTable* table, int blendMode)
{
  switch (blendMode)
  {
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      return ResolveResult(window, targets, table, ResolveMaximum);
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
      return ResolveResult(window, targets, table, ResolveMinimum);
    case vtkVolumeMapper::ADDITIVE_BLEND:
      return ResolveResult(window, targets, table, ResolveAdditive);
    default:
      return true;
  }
}

VTK_ABI_NAMESPACE_END
