/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSExtremumPass.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSExtremumPass.h"

#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSKBufferShaders.h"
#include "vtkHAVSOpenGL.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkHAVSExtremumPass);

//------------------------------------------------------------------------------
bool vtkHAVSExtremumPass::Draw(vtkHAVSGLPassContext& context)
{
  vtkOpenGLState* state = context.Window->GetState();
  context.Targets->BindResult();
  const float zero[4] = { 0, 0, 0, 0 };
  glClearBufferfv(GL_COLOR, 0, zero);
  vtkShaderProgram* program =
    context.FaceProgram(vtkHAVSKBufferShaders::ExtremumDrawShader(context.ShaderFeatures()));
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
  // The draw wrote the result texture; the resolve reads a copy of it.
  const int w = context.Width(), h = context.Height();
  auto extremum = vtkHAVSGLFrameTargets::NewFloatTexture(context.Window, w, h);
  context.Targets->BindResultForReading();
  extremum->Activate();
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, w, h);
  context.Targets->BindResult();
  vtkTextureObject* function = context.Table->GetTransferFunction1D();
  function->Activate();
  vtkShaderProgram* program = context.QuadProgram(vtkHAVSKBufferShaders::ExtremumResolveShader());
  if (program)
  {
    program->SetUniformi("havsExtremumTexture", extremum->GetTextureUnit());
    program->SetUniformi("havsTransferFunction", function->GetTextureUnit());
    context.DrawFullViewport();
  }
  function->Deactivate();
  extremum->Deactivate();
  extremum->ReleaseGraphicsResources(context.Window);
  return program != nullptr;
}
