/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSKBuffer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSKBuffer.h"

#include "vtkHAVSVolumeMapper.h"

//------------------------------------------------------------------------------
void vtkHAVSKBuffer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Path: " << vtkHAVSVolumeMapper::GetKBufferPathName(this->GetPath())
     << " (k <= " << this->GetMaximumK() << ")\n";
}
