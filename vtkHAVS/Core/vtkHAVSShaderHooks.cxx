/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSShaderHooks.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSShaderHooks.h"

#include "vtkShaderProperty.h"
#include "vtkUniforms.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
const std::vector<std::string>& vtkHAVSShaderHooks::HonouredTags()
{
  static const std::vector<std::string> tags = { "//VTK::CustomUniforms::Dec", "//VTK::Base::Dec",
    "//VTK::Base::Exit" };
  return tags;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkHAVSShaderHooks::TimeOf(vtkShaderProperty* property)
{
  if (!property)
  {
    return 0;
  }
  return std::max({ property->GetMTime(), property->GetFragmentCustomUniforms()->GetMTime(),
    property->GetVertexCustomUniforms()->GetMTime(),
    property->GetGeometryCustomUniforms()->GetMTime() });
}

//------------------------------------------------------------------------------
vtkHAVSShaderHooks vtkHAVSShaderHooks::From(vtkShaderProperty* property)
{
  vtkHAVSShaderHooks hooks;
  if (!property)
  {
    return hooks;
  }
  hooks.Time = TimeOf(property);
  const std::vector<std::string>& honoured = HonouredTags();
  for (int i = 0; i < property->GetNumberOfShaderReplacements(); ++i)
  {
    Replacement r;
    property->GetNthShaderReplacement(i, r.Tag, r.First, r.Code, r.All);
    const std::string stage = property->GetNthShaderReplacementTypeAsString(i);
    if (stage == "Fragment" && std::find(honoured.begin(), honoured.end(), r.Tag) != honoured.end())
    {
      hooks.Fragment.push_back(std::move(r));
    }
    else
    {
      hooks.Ignored.push_back(stage + " replacement of \"" + r.Tag + "\"");
    }
  }
  if (property->GetFragmentCustomUniforms()->GetNumberOfUniforms() > 0)
  {
    hooks.FragmentUniforms = property->GetFragmentCustomUniforms();
  }
  if (property->GetVertexCustomUniforms()->GetNumberOfUniforms() > 0)
  {
    hooks.Ignored.push_back("vertex custom uniforms");
  }
  if (property->GetGeometryCustomUniforms()->GetNumberOfUniforms() > 0)
  {
    hooks.Ignored.push_back("geometry custom uniforms");
  }
  if (property->HasVertexShaderCode() || property->HasFragmentShaderCode() ||
    property->HasGeometryShaderCode())
  {
    hooks.Ignored.push_back("whole shader code (SetVertex/Fragment/GeometryShaderCode)");
  }
  return hooks;
}

VTK_ABI_NAMESPACE_END
