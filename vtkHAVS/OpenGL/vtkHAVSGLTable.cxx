/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLTable.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLTable.h"

#include <algorithm>
#include <cmath>

#include "vtkHAVSCellOptics.h"
#include "vtkHAVSIsoSurfaces.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSGLTable);

//------------------------------------------------------------------------------
bool vtkHAVSGLTable::Update(vtkHAVSPreIntegrationTable* table, vtkMTimeType version)
{
  if (version != 0 && version == this->UploadedVersion && this->Table)
  {
    return false;
  }
  this->Upload(table);
  this->UploadedVersion = version;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSGLTable::Upload(vtkHAVSPreIntegrationTable* table)
{
  if (!this->Table)
  {
    this->Table = vtkSmartPointer<vtkTextureObject>::New();
    this->Table->SetContext(this->Window);
    this->TransferFunction1D = vtkSmartPointer<vtkTextureObject>::New();
    this->TransferFunction1D->SetContext(this->Window);
    this->Additive1D = vtkSmartPointer<vtkTextureObject>::New();
    this->Additive1D->SetContext(this->Window);
  }
  for (vtkTextureObject* t : { this->Table.Get(), this->TransferFunction1D.Get() })
  {
    t->SetInternalFormat(GL_RGBA32F);
    t->SetFormat(GL_RGBA);
    t->SetDataType(GL_FLOAT);
    t->SetMinificationFilter(vtkTextureObject::Linear);
    t->SetMagnificationFilter(vtkTextureObject::Linear);
    t->SetWrapS(vtkTextureObject::ClampToEdge);
    t->SetWrapT(vtkTextureObject::ClampToEdge);
    t->SetWrapR(vtkTextureObject::ClampToEdge);
  }
  const int ns = table->GetBuiltScalarResolution(), nl = table->GetBuiltLengthResolution();
  if (this->Table->GetHandle() != 0 && ns == this->ScalarResolution && nl == this->LengthResolution)
  {
    // A new table of the same size (a transfer-function edit): into the
    // texture's storage, not a new one.
    this->Table->Bind();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, ns, ns, nl, GL_RGBA, GL_FLOAT, table->GetTable());
  }
  else
  {
    this->Table->Create3DFromRaw(ns, ns, nl, 4, VTK_FLOAT, const_cast<float*>(table->GetTable()));
  }
  this->ScalarResolution = ns;
  this->LengthResolution = nl;
  const std::vector<float>& function = table->GetTransferFunction1D();
  this->TransferFunction1D->Create1DFromRaw(static_cast<unsigned int>(function.size() / 4), 4,
    VTK_FLOAT, const_cast<float*>(function.data()));
  // (g, G) pairs read with texelFetch: no filtering.
  const std::vector<float>& additive = table->GetAdditive1D();
  this->Additive1D->SetInternalFormat(GL_RG32F);
  this->Additive1D->SetFormat(GL_RG);
  this->Additive1D->SetDataType(GL_FLOAT);
  this->Additive1D->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Additive1D->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Additive1D->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Additive1D->Create1DFromRaw(static_cast<unsigned int>(additive.size() / 2), 2, VTK_FLOAT,
    const_cast<float*>(additive.data()));
  // Cell optics (2 RGBA texels a value) in a buffer texture, read with
  // texelFetch; one zero value when there are none.
  // (The shaders clamp a code's index to the values uploaded.)
  const std::vector<float>& optics = table->GetCellOptics()->GetOptics();
  this->CellValues = table->GetCellOptics()->GetNumberOfValues();
  GLint largest = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &largest);
  bool fits = true;
  if (optics.size() / 4 > static_cast<size_t>(largest))
  {
    vtkErrorMacro(<< this->CellValues << " distinct cell values need " << optics.size() / 4
                  << " texels, more than this context's GL_MAX_TEXTURE_BUFFER_SIZE (" << largest
                  << "); the cells are drawn transparent.");
    fits = false;
  }
  static const std::vector<float> placeholder(vtkHAVSCellOptics::FloatsPerValue, 0.0f);
  const std::vector<float>& cellData = this->CellValues > 0 && fits ? optics : placeholder;
  if (!this->CellOptics)
  {
    this->CellOptics = vtkSmartPointer<vtkTextureObject>::New();
    this->CellOptics->SetContext(this->Window);
    this->CellOpticsBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  }
  this->CellOpticsBuffer->Upload(cellData, vtkOpenGLBufferObject::TextureBuffer);
  this->CellOptics->CreateTextureBuffer(
    static_cast<unsigned int>(cellData.size() / 4), 4, VTK_FLOAT, this->CellOpticsBuffer);
  this->MaxLength = table->GetMaxLength() > 0.0 ? table->GetMaxLength() : 1.0;
  this->LengthLogScale = table->GetLengthLogScale();
}

//------------------------------------------------------------------------------
void vtkHAVSGLTable::SetUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("havsTable", this->Table->GetTextureUnit());
  const float ns = static_cast<float>(this->ScalarResolution);
  const float nl = static_cast<float>(this->LengthResolution);
  const float scalarTexel[2] = { (ns - 1.0f) / ns, 0.5f / ns };
  const float lengthTexel[2] = { (nl - 1.0f) / nl, 0.5f / nl };
  program->SetUniform2f("havsScalarTexel", scalarTexel);
  program->SetUniform2f("havsLengthTexel", lengthTexel);
  program->SetUniformf("havsInvMaxLength", static_cast<float>(1.0 / this->MaxLength));
  // The length axis (vtkHAVSPreIntegrationTable::LengthCoordinate): linear
  // for a scale of 0, else u = log(1 + a L) / log(1 + a MaxLength).
  const double a = this->LengthLogScale;
  program->SetUniformf("havsLengthLogScale", static_cast<float>(a));
  program->SetUniformf(
    "havsInvLogRange", a > 0.0 ? static_cast<float>(1.0 / std::log1p(a * this->MaxLength)) : 0.0f);
  if (this->CellOptics && this->CellOptics->GetTextureUnit() >= 0)
  {
    program->SetUniformi("havsCellOptics", this->CellOptics->GetTextureUnit());
  }
  // The isosurfaces (vtkHAVSKBufferLib's havsSegment, compiled in with HAVS_ISO).
  const int count = this->IsoSurfaces ? this->IsoSurfaces->Count : 0;
  program->SetUniformi("havsIsoCount", count);
  if (count > 0)
  {
    float colors[vtkHAVSIsoSurfaces::MaximumCount][4];
    for (int i = 0; i < count; ++i)
    {
      std::copy_n(this->IsoSurfaces->Colors[i], 4, colors[i]);
    }
    program->SetUniform1fv("havsIsoValues", count, this->IsoSurfaces->Normalized);
    program->SetUniform4fv("havsIsoColors", count, colors);
  }
  // Their shading (HAVS_ISO_SHADE; vtkHAVSIsoSurfaces::Shade).
  if (count > 0 && this->IsoSurfaces->Shaded)
  {
    const vtkHAVSIsoSurfaces& iso = *this->IsoSurfaces;
    const int lights = iso.LightCount;
    float direction[vtkHAVSIsoSurfaces::MaximumLights][3];
    float diffuse[vtkHAVSIsoSurfaces::MaximumLights][3];
    float specular[vtkHAVSIsoSurfaces::MaximumLights][3];
    for (int i = 0; i < lights; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        direction[i][k] = static_cast<float>(iso.Lights[i].Direction[k]);
        diffuse[i][k] = static_cast<float>(iso.Lights[i].Diffuse[k]);
        specular[i][k] = static_cast<float>(iso.Lights[i].Specular[k]);
      }
    }
    program->SetUniformi("havsLightCount", lights);
    if (lights > 0)
    {
      program->SetUniform3fv("havsLightDirection", lights, direction);
      program->SetUniform3fv("havsLightDiffuse", lights, diffuse);
      program->SetUniform3fv("havsLightSpecular", lights, specular);
    }
    const float shading[4] = { static_cast<float>(iso.Ambient), static_cast<float>(iso.Diffuse),
      static_cast<float>(iso.Specular), static_cast<float>(iso.SpecularPower) };
    program->SetUniform4f("havsShading", shading);
    float normal[9];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        normal[3 * c + r] = static_cast<float>(iso.NormalMatrix[3 * r + c]); // column-major
      }
    }
    program->SetUniformMatrix3x3("havsNormalMatrix", normal);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLTable::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Table)
  {
    this->Table->ReleaseGraphicsResources(window);
  }
  if (this->TransferFunction1D)
  {
    this->TransferFunction1D->ReleaseGraphicsResources(window);
  }
  if (this->Additive1D)
  {
    this->Additive1D->ReleaseGraphicsResources(window);
  }
  if (this->CellOptics)
  {
    this->CellOptics->ReleaseGraphicsResources(window);
    this->CellOpticsBuffer->ReleaseGraphicsResources();
  }
  this->Table = nullptr;
  this->TransferFunction1D = nullptr;
  this->Additive1D = nullptr;
  this->CellOptics = nullptr;
  this->CellOpticsBuffer = nullptr;
  this->CellValues = 0;
  this->UploadedVersion = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSGLTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Table: " << this->ScalarResolution << "^2 x " << this->LengthResolution
     << ", max length " << this->MaxLength << ", length log scale " << this->LengthLogScale
     << ", cell values " << this->CellValues << "\n";
}

VTK_ABI_NAMESPACE_END
