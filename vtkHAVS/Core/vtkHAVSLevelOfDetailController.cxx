/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSLevelOfDetailController.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSLevelOfDetailController.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSLevelOfDetailController);

//------------------------------------------------------------------------------
double vtkHAVSLevelOfDetailController::Choose(double targetSeconds)
{
  if (!(targetSeconds > 0.0) || this->LastSeconds < 0.0)
  {
    return 1.0;
  }
  // Full quality whenever the budget allows it.
  if (this->FullSeconds >= 0.0 && this->FullSeconds <= targetSeconds)
  {
    return 1.0;
  }
  if (!(this->LastSeconds > 0.0))
  {
    return 1.0;
  }
  const double ratio = targetSeconds / this->LastSeconds;
  if (std::abs(ratio - 1.0) <= this->Deadband)
  {
    return this->LastFraction;
  }
  // From a frame that drew (nearly) nothing but its fixed part (a
  // boundary-only frame) a step starts at the smallest fraction: that frame
  // still tells how much time is left.
  const double smallest = this->SmallestFraction;
  const double from = std::max(this->LastFraction, smallest);
  const double next = from * std::pow(ratio, this->Gain);
  return std::min(1.0, std::max(0.0, next < smallest && ratio < 1.0 ? 0.0 : next));
}

//------------------------------------------------------------------------------
void vtkHAVSLevelOfDetailController::FrameDrawn(double fraction, double seconds)
{
  this->LastFraction = std::min(1.0, std::max(0.0, fraction));
  this->LastSeconds = std::max(0.0, seconds);
  if (this->LastFraction >= 1.0)
  {
    this->FullSeconds = this->LastSeconds;
  }
}

//------------------------------------------------------------------------------
void vtkHAVSLevelOfDetailController::Reset()
{
  this->LastFraction = 1.0;
  this->LastSeconds = -1.0;
  this->FullSeconds = -1.0;
}

//------------------------------------------------------------------------------
void vtkHAVSLevelOfDetailController::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Gain: " << this->Gain << ", dead band " << this->Deadband
     << ", smallest fraction " << this->SmallestFraction << "\n";
  os << indent << "Last frame: fraction " << this->LastFraction << ", " << this->LastSeconds
     << " s; last full frame " << this->FullSeconds << " s\n";
}

VTK_ABI_NAMESPACE_END
