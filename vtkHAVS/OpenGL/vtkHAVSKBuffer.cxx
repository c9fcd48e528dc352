/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSKBuffer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSKBuffer.h"

#include "vtkHAVSFrameRequest.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSShaders.h"

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
void vtkHAVSKBuffer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Path: " << vtkHAVSFrameRequest::GetPathName(this->GetPath())
     << " (k <= " << this->GetMaximumK() << ")\n";
}

//------------------------------------------------------------------------------
void vtkHAVSKBuffer::DrawFaces(
  vtkHAVSGLPassContext& context, vtkShaderProgram* program, bool storageBuffer)
{
  const vtkHAVSFrameRequest& r = context.Request;
  const std::string mark =
    r.SkipSaturated ? vtkHAVSShaders::SaturationMarkShader(this->GetPath(), r.K) : std::string();
  // Measured only where the frame waits for the GPU anyway.
  const bool measure = r.MeasureStages || r.KeepResult || r.CountViolations;
  this->Saturation.DrawFaces(context, program, mark, storageBuffer, measure);
}

VTK_ABI_NAMESPACE_END
