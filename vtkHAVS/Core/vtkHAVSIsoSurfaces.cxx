/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSIsoSurfaces.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSIsoSurfaces.h"

#include "vtkHAVSPreIntegrationTable.h"

#include "vtkContourValues.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

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

//------------------------------------------------------------------------------
void vtkHAVSIsoSurfaces::MakeShading(vtkVolumeProperty* property, int component,
  vtkLightCollection* lights, vtkMatrix4x4* volumeMatrix)
{
  this->Shaded = property && this->Count > 0 && property->GetShade(component) != 0;
  this->LightCount = this->DroppedLights = this->PositionalLights = 0;
  if (!this->Shaded)
  {
    return;
  }
  this->Ambient = property->GetAmbient(component);
  this->Diffuse = property->GetDiffuse(component);
  this->Specular = property->GetSpecular(component);
  this->SpecularPower = property->GetSpecularPower(component);
  if (lights)
  {
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      if (!light->GetSwitch() || !(light->GetIntensity() > 0.0))
      {
        continue;
      }
      double position[3], focal[3], towards[3];
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focal);
      vtkMath::Subtract(position, focal, towards);
      if (!(vtkMath::Normalize(towards) > 0.0))
      {
        continue;
      }
      if (this->LightCount == MaximumLights)
      {
        ++this->DroppedLights;
        continue;
      }
      this->PositionalLights += light->GetPositional() ? 1 : 0;
      Light& l = this->Lights[this->LightCount++];
      const double intensity = light->GetIntensity();
      double diffuse[3], specular[3];
      light->GetDiffuseColor(diffuse);
      light->GetSpecularColor(specular);
      for (int k = 0; k < 3; ++k)
      {
        l.Direction[k] = towards[k];
        l.Diffuse[k] = diffuse[k] * intensity;
        l.Specular[k] = specular[k] * intensity;
      }
    }
  }
  // World normal = (L^-1)^T g for the linear part L of the volume matrix.
  double linear[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  if (volumeMatrix)
  {
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        linear[r][c] = volumeMatrix->GetElement(r, c);
      }
    }
  }
  double inverse[3][3];
  if (std::fabs(vtkMath::Determinant3x3(linear)) > 0.0)
  {
    vtkMath::Invert3x3(linear, inverse);
  }
  else
  {
    vtkMath::Identity3x3(inverse);
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->NormalMatrix[3 * r + c] = inverse[c][r];
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSIsoSurfaces::Shade(
  const double rgba[4], const double gradient[3], const double toEye[3], double out[4]) const
{
  std::copy_n(rgba, 4, out);
  double n[3] = { gradient[0], gradient[1], gradient[2] };
  const double length = vtkMath::Norm(n);
  if (!(rgba[3] > 0.0) || !(length > 0.0) || !std::isfinite(length))
  {
    return;
  }
  const double side = vtkMath::Dot(n, toEye) < 0.0 ? -1.0 : 1.0;
  for (int k = 0; k < 3; ++k)
  {
    n[k] *= side / length;
  }
  const double a = rgba[3];
  const double color[3] = { rgba[0] / a, rgba[1] / a, rgba[2] / a };
  double lit[3];
  for (int k = 0; k < 3; ++k)
  {
    lit[k] = this->Ambient * color[k];
  }
  for (int i = 0; i < this->LightCount; ++i)
  {
    const Light& light = this->Lights[i];
    const double nl = vtkMath::Dot(n, light.Direction);
    if (nl > 0.0)
    {
      double r[3];
      for (int k = 0; k < 3; ++k)
      {
        lit[k] += this->Diffuse * nl * light.Diffuse[k] * color[k];
        r[k] = 2.0 * nl * n[k] - light.Direction[k];
      }
      const double rv = vtkMath::Dot(r, toEye);
      if (rv > 0.0)
      {
        const double highlight = this->Specular * std::pow(rv, this->SpecularPower);
        for (int k = 0; k < 3; ++k)
        {
          lit[k] += highlight * light.Specular[k];
        }
      }
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    out[k] = std::min(1.0, std::max(0.0, lit[k])) * a;
  }
}

VTK_ABI_NAMESPACE_END
