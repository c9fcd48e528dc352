/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellOptics.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSCellOptics.h"

#include "vtkHAVSPreIntegrationTable.h"
#include "vtkObjectFactory.h"
#include "vtkTimerLog.h"
#include "vtkVolumeProperty.h"

#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSCellOptics);

//------------------------------------------------------------------------------
float vtkHAVSCellOptics::CodeOf(uint32_t index)
{
  return std::ldexp(static_cast<float>(index), -CodeBits);
}

//------------------------------------------------------------------------------
bool vtkHAVSCellOptics::NeedsRebuild(
  vtkVolumeProperty* property, int component, vtkMTimeType valuesVersion) const
{
  // vtkVolumeProperty::GetMTime includes its transfer functions.
  return !property || property != this->BuiltProperty || component != this->Component ||
    valuesVersion != this->ValuesVersion || property->GetMTime() > this->BuildTime;
}

//------------------------------------------------------------------------------
void vtkHAVSCellOptics::Clear()
{
  this->Optics.clear();
  this->BuiltProperty = nullptr;
  this->Component = -1;
  this->ValuesVersion = 0;
}

//------------------------------------------------------------------------------
bool vtkHAVSCellOptics::Build(vtkVolumeProperty* property, int component,
  const std::vector<double>& values, const double scalarRange[2], vtkMTimeType valuesVersion)
{
  const double start = vtkTimerLog::GetUniversalTime();
  this->Clear();
  if (!property)
  {
    vtkErrorMacro("No volume property.");
    return false;
  }
  const double unit = property->GetScalarOpacityUnitDistance(component);
  if (!(unit > 0.0))
  {
    vtkErrorMacro("ScalarOpacityUnitDistance must be positive, it is " << unit << ".");
    return false;
  }
  if (values.size() > MaximumValues)
  {
    vtkErrorMacro(<< values.size() << " distinct cell values; at most " << MaximumValues
                  << " have codes.");
    return false;
  }
  this->BuiltProperty = property;
  this->Component = component;
  this->ValuesVersion = valuesVersion;
  this->BuildTime.Modified();
  const double span = scalarRange[1] - scalarRange[0];
  this->Optics.resize(values.size() * FloatsPerValue);
  // Serial: the functions' GetValue/GetColor are not safe to call from
  // several threads (they cache their last search).
  for (size_t i = 0; i < values.size(); ++i)
  {
    double tau, color[3];
    vtkHAVSPreIntegrationTable::EvaluateOptics(property, component, values[i], tau, color);
    const double s = span > 0.0 ? (values[i] - scalarRange[0]) / span : 0.0;
    float* o = &this->Optics[FloatsPerValue * i];
    o[0] = static_cast<float>(color[0]);
    o[1] = static_cast<float>(color[1]);
    o[2] = static_cast<float>(color[2]);
    o[3] = static_cast<float>(tau);
    o[4] = static_cast<float>(s);
    o[5] = static_cast<float>(tau * unit);
    o[6] = static_cast<float>(tau * s);
    o[7] = 0.0f;
  }
  this->LastBuildSeconds = vtkTimerLog::GetUniversalTime() - start;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSCellOptics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Values: " << this->GetNumberOfValues() << " (built in " << this->LastBuildSeconds
     << " s)\n";
}

VTK_ABI_NAMESPACE_END
