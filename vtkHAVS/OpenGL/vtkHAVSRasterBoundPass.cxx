/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRasterBoundPass.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSRasterBoundPass.h"

#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSShaders.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSRasterBoundPass);

//------------------------------------------------------------------------------
bool vtkHAVSRasterBoundPass::Draw(vtkHAVSGLPassContext& context)
{
  vtkOpenGLState* state = context.Window->GetState();
  context.Targets->BindResult();
  const float zero[4] = { 0, 0, 0, 0 };
  glClearBufferfv(GL_COLOR, 0, zero);
  vtkShaderProgram* program = context.FaceProgram(vtkHAVSShaders::TrivialShader());
  if (!program)
  {
    return false;
  }
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  context.DrawFaces(program);
  state->vtkglDisable(GL_BLEND);
  return true;
}

VTK_ABI_NAMESPACE_END
