/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSIsoSurfaces.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSIsoSurfaces.h"

#include "vtkHAVSPreIntegrationTable.h"

#include "vtkContourValues.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
void vtkHAVSIsoSurfaces::SurfaceColor(vtkVolumeProperty* property, double v, double rgba[4])
{
  double color[3];
  vtkHAVSPreIntegrationTable::EvaluateColor(property, 0, v, color);
  const double a = std::min(1.0, std::max(0.0, property->GetScalarOpacity(0)->GetValue(v)));
  for (int c = 0; c < 3; ++c)
  {
    rgba[c] = color[c] * a;
  }
  rgba[3] = a;
}

//------------------------------------------------------------------------------
vtkHAVSIsoSurfaces vtkHAVSIsoSurfaces::Make(
  vtkVolumeProperty* property, int blendMode, bool inComposite, const double scalarRange[2])
{
  vtkHAVSIsoSurfaces s;
  if (!property || !(blendMode == IsoSurfaceBlend || (blendMode == 0 && inComposite)))
  {
    return s;
  }
  s.Composite = blendMode == 0;
  vtkContourValues* contours = property->GetIsoSurfaceValues();
  std::vector<double> values;
  for (int i = 0; contours && i < contours->GetNumberOfContours(); ++i)
  {
    const double v = contours->GetValue(i);
    if (v >= scalarRange[0] && v <= scalarRange[1])
    {
      values.push_back(v);
    }
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  s.Dropped = std::max(0, static_cast<int>(values.size()) - MaximumCount);
  s.Count = std::min(static_cast<int>(values.size()), MaximumCount);
  const double span = scalarRange[1] - scalarRange[0];
  for (int i = 0; i < s.Count; ++i)
  {
    s.Values[i] = values[i];
    s.Normalized[i] = span > 0.0 ? static_cast<float>((values[i] - scalarRange[0]) / span) : 0.0f;
    SurfaceColor(property, values[i], s.Colors[i]);
  }
  return s;
}

//------------------------------------------------------------------------------
std::vector<int> vtkHAVSIsoSurfaces::Crossed(double sf, double sb) const
{
  std::vector<int> crossed;
  const bool rising = sb > sf;
  for (int n = 0; n < this->Count; ++n)
  {
    const int i = rising ? n : this->Count - 1 - n;
    const double v = this->Values[i];
    if (rising ? (v >= sf && v < sb) : (v <= sf && v > sb))
    {
      crossed.push_back(i);
    }
  }
  return crossed;
}

VTK_ABI_NAMESPACE_END
