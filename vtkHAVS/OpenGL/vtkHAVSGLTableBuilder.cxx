/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLTableBuilder.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLTableBuilder.h"

#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSShaders.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTimerLog.h"

#include <string>
#include <vector>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSGLTableBuilder);

//------------------------------------------------------------------------------
vtkHAVSGLTableBuilder::~vtkHAVSGLTableBuilder()
{
  if (this->Program != 0 || this->Image)
  {
    vtkWarningMacro("Deleted with its GPU objects held: call ReleaseGraphicsResources first.");
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSGLTableBuilder::MakeProgram(int cells)
{
  if (this->Program != 0 && this->ProgramCells == cells)
  {
    return true;
  }
  if (this->Program != 0)
  {
    glDeleteProgram(this->Program);
    this->Program = 0;
  }
  const std::string source = vtkHAVSShaders::TableComputeShader(cells, LocalSize);
  const char* text = source.c_str();
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  std::string log;
  auto readLog = [&log](GLuint object, bool program)
  {
    GLint size = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &size)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &size);
    std::vector<char> text(static_cast<size_t>(size) + 1, '\0');
    program ? glGetProgramInfoLog(object, size, nullptr, text.data())
            : glGetShaderInfoLog(object, size, nullptr, text.data());
    log = text.data();
  };
  if (ok != GL_TRUE)
  {
    readLog(shader, false);
    glDeleteShader(shader);
    vtkErrorMacro("The table's compute shader does not compile; the table is built on the CPU:\n"
      << log);
    return false;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader); // (kept by the program until it is deleted)
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE)
  {
    readLog(program, true);
    glDeleteProgram(program);
    vtkErrorMacro("The table's compute program does not link; the table is built on the CPU:\n"
      << log);
    return false;
  }
  this->Program = program;
  this->ProgramCells = cells;
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSGLTableBuilder::Build(
  vtkOpenGLRenderWindow* window, const vtkHAVSPreIntegrationTable::Quadrature& inputs, float* table)
{
  const int ns = inputs.ScalarResolution, nl = inputs.LengthResolution;
  const int cells = ns - 1;
  if (!window || !table || ns < 2 || nl < 2 || this->Failed)
  {
    return false;
  }
  if (ns > 1024)
  {
    vtkErrorMacro("A table of " << ns << " scalars is more than the GPU build's 1024; it is "
                                << "built on the CPU.");
    return false;
  }
  if (window != this->Window)
  {
    this->ReleaseGraphicsResources(this->Window);
    this->Window = window;
  }
  if (!vtkHAVSGLCapabilities::HasVersion(4, 3) || !this->MakeProgram(cells))
  {
    this->Failed = true; // once per context: not every edit
    return false;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  this->Samples.Update(GL_SHADER_STORAGE_BUFFER, inputs.Samples, 0);
  this->Steps.Update(GL_SHADER_STORAGE_BUFFER, inputs.StepDepth, 0);
  this->TableSamples.Update(GL_SHADER_STORAGE_BUFFER, inputs.TableSample, 0);
  this->Layers.Update(GL_SHADER_STORAGE_BUFFER, inputs.LayerLength, 0);
  this->Samples.BindBase(GL_SHADER_STORAGE_BUFFER, 0);
  this->Steps.BindBase(GL_SHADER_STORAGE_BUFFER, 1);
  this->TableSamples.BindBase(GL_SHADER_STORAGE_BUFFER, 2);
  this->Layers.BindBase(GL_SHADER_STORAGE_BUFFER, 3);

  if (!this->Image)
  {
    this->Image = vtkSmartPointer<vtkTextureObject>::New();
    this->Image->SetContext(window);
  }
  if (this->Image->GetHandle() == 0 || static_cast<int>(this->Image->GetWidth()) != ns ||
    static_cast<int>(this->Image->GetDepth()) != nl)
  {
    this->Image->SetInternalFormat(GL_RGBA32F);
    this->Image->SetFormat(GL_RGBA);
    this->Image->SetDataType(GL_FLOAT);
    this->Image->Create3DFromRaw(ns, ns, nl, 4, VTK_FLOAT, nullptr);
  }
  glBindImageTexture(0, this->Image->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  GLint previous = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
  glUseProgram(this->Program);
  // (j = 0 .. cells: the diagonal and every span; each length layer; both directions.)
  glDispatchCompute(static_cast<GLuint>(cells + 1), static_cast<GLuint>(nl), 2);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  glUseProgram(static_cast<GLuint>(previous));
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glFinish();
  const double computed = vtkTimerLog::GetUniversalTime();
  this->Image->Bind();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, table);
  this->LastComputeSeconds = computed - start;
  this->LastReadSeconds = vtkTimerLog::GetUniversalTime() - computed;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSGLTableBuilder::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Program != 0)
  {
    glDeleteProgram(this->Program);
    this->Program = 0;
  }
  this->ProgramCells = 0;
  this->Samples.Release();
  this->Steps.Release();
  this->TableSamples.Release();
  this->Layers.Release();
  if (this->Image)
  {
    this->Image->ReleaseGraphicsResources(window);
    this->Image = nullptr;
  }
  this->Window = nullptr;
  this->Failed = false;
}

//------------------------------------------------------------------------------
void vtkHAVSGLTableBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LocalSize: " << LocalSize << "\n";
  os << indent << "ProgramCells: " << this->ProgramCells << "\n";
  os << indent << "Failed: " << this->Failed << "\n";
  os << indent << "LastComputeSeconds: " << this->LastComputeSeconds << "\n";
  os << indent << "LastReadSeconds: " << this->LastReadSeconds << "\n";
}

VTK_ABI_NAMESPACE_END
