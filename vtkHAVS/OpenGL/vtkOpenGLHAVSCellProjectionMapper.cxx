/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSCellProjectionMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkOpenGLHAVSCellProjectionMapper.h"

#include "vtkHAVSExtremumPass.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSKBufferShaders.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSViewFrame.h"

#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"

#include <algorithm>

vtkStandardNewMacro(vtkOpenGLHAVSCellProjectionMapper);

//------------------------------------------------------------------------------
vtkOpenGLHAVSCellProjectionMapper::vtkOpenGLHAVSCellProjectionMapper() = default;

vtkOpenGLHAVSCellProjectionMapper::~vtkOpenGLHAVSCellProjectionMapper()
{
  this->ReleaseGraphicsResources(nullptr);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::PrepareWindow(vtkOpenGLRenderWindow* window)
{
  if (this->Window == window)
  {
    window->MakeCurrent();
    return;
  }
  this->ReleaseGraphicsResources(this->Window);
  this->Window = window;
  this->WindowDeleteObserver = window->AddObserver(
    vtkCommand::DeleteEvent, this, &vtkOpenGLHAVSCellProjectionMapper::OnWindowDeleted);
  window->MakeCurrent();
  this->GLTable->SetContext(window);
  this->Targets->SetContext(window);
}

void vtkOpenGLHAVSCellProjectionMapper::OnWindowDeleted(vtkObject* window, unsigned long, void*)
{
  this->ReleaseGraphicsResources(vtkWindow::SafeDownCast(window));
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::Upload(const CellFrame& frame)
{
  if (!this->VertexArray)
  {
    glGenVertexArrays(1, &this->VertexArray);
    GLuint buffers[4];
    glGenBuffers(4, buffers);
    this->PointBuffer = buffers[0];
    this->IndexBuffer = buffers[1];
    this->CellBuffer = buffers[2];
    this->OrderBuffer = buffers[3];
  }
  glBindVertexArray(this->VertexArray);
  if (this->UploadedGeometry != frame.GeometryVersion)
  {
    const std::vector<float>& points = frame.Mesh->GetPoints();
    glBindBuffer(GL_ARRAY_BUFFER, this->PointBuffer);
    glBufferData(GL_ARRAY_BUFFER, points.size() * sizeof(float), points.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->CellBuffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, frame.Cells->size() * sizeof(float), frame.Cells->data(),
      GL_STATIC_DRAW);
    this->UploadedGeometry = frame.GeometryVersion;
  }
  if (this->UploadedTable != frame.TableVersion)
  {
    this->GLTable->Upload(frame.Table);
    this->UploadedTable = frame.TableVersion;
  }
  // The faces of the cells in the frame's order, and the cell of each
  // position: only when the order changed (not on a redraw or a
  // transfer-function edit; once per mesh for the unsorted blends).
  if (this->UploadedOrder == frame.OrderVersion && this->UploadedCells == frame.Order->size())
  {
    glBindVertexArray(0);
    return;
  }
  this->UploadedOrder = frame.OrderVersion;
  this->UploadedCells = frame.Order->size();
  const std::vector<uint32_t>& order = *frame.Order;
  const std::vector<uint32_t>& faces = *frame.Faces;
  std::vector<uint32_t> indices(12 * order.size()); // (only until uploaded)
  for (size_t i = 0; i < order.size(); ++i)
  {
    std::copy_n(&faces[12 * static_cast<size_t>(order[i])], 12, &indices[12 * i]);
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, this->IndexBuffer);
  glBufferData(
    GL_ELEMENT_ARRAY_BUFFER, indices.size() * sizeof(uint32_t), indices.data(), GL_STREAM_DRAW);
  glBindVertexArray(0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->OrderBuffer);
  glBufferData(
    GL_SHADER_STORAGE_BUFFER, order.size() * sizeof(uint32_t), order.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
int vtkOpenGLHAVSCellProjectionMapper::UploadSection(const CellFrame& frame)
{
  const std::vector<vtkHAVSFramePlanes::Section>& sections = frame.Planes->GetSections();
  if (sections.empty())
  {
    return 0; // (the camera outside the mesh: nothing cut by the near plane)
  }
  const vtkMTimeType version = frame.Planes->GetSectionsVersion();
  if (this->SectionArray && this->UploadedSection == version)
  {
    return this->SectionTriangles;
  }
  if (!this->SectionArray)
  {
    glGenVertexArrays(1, &this->SectionArray);
    GLuint buffers[2];
    glGenBuffers(2, buffers);
    this->SectionPointBuffer = buffers[0];
    this->SectionCellBuffer = buffers[1];
  }
  const vtkHAVSFramePlanes::Section& section = sections.front(); // the near plane's only
  glBindVertexArray(this->SectionArray);
  glBindBuffer(GL_ARRAY_BUFFER, this->SectionPointBuffer);
  glBufferData(
    GL_ARRAY_BUFFER, section.Points.size() * sizeof(float), section.Points.data(), GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->SectionCellBuffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, section.Cells.size() * sizeof(uint32_t),
    section.Cells.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  this->UploadedSection = version;
  this->SectionTriangles = static_cast<int>(section.Cells.size());
  return this->SectionTriangles;
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSCellProjectionMapper::DrawCells(
  vtkRenderer* renderer, const CellFrame& frame, double* drawSeconds)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("vtkHAVSCellProjectionMapper needs an OpenGL render window.");
    return false;
  }
  this->PrepareWindow(window);
  if (!vtkHAVSGLCapabilities::HasVersion(4, 3))
  {
    vtkErrorMacro("vtkHAVSCellProjectionMapper needs OpenGL 4.3 (storage buffers).");
    return false;
  }
  this->Upload(frame);
  const int sectionTriangles = this->UploadSection(frame);
  const vtkHAVSViewFrame& view = *frame.View;
  const int width = view.Width, height = view.Height;
  this->Targets->Resize(width, height);
  const bool opaque = frame.Opaque;
  if (opaque)
  {
    this->Targets->CaptureOpaqueDepth(view.OriginX, view.OriginY, width, height, this);
  }
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    vtkHAVSKBufferShaders::CellProjectionVertexShader().c_str(),
    vtkHAVSKBufferShaders::CellProjectionShader(opaque, frame.Blend, this->GLTable->HasCellOptics())
      .c_str(),
    "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("The cell-projection shader could not be built; see the shader log above.");
    return false;
  }

  vtkOpenGLState* state = window->GetState();
  vtkHAVSGLScopedPassState passState(state);
  vtkTextureObject* table = this->GLTable->GetTable();
  vtkTextureObject* depth = this->Targets->GetOpaqueDepth();
  vtkTextureObject* additive = this->GLTable->GetAdditive1D();
  vtkTextureObject* cellOptics = this->GLTable->GetCellOptics();
  table->Activate();
  depth->Activate();
  additive->Activate();
  cellOptics->Activate();
  this->GLTable->SetUniforms(program);
  program->SetUniformi("havsAdditive", additive->GetTextureUnit());
  float m[16];
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToEyeRelative, m);
  program->SetUniformMatrix4x4("havsMCRC", m);
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToClip, m);
  program->SetUniformMatrix4x4("havsMCDC", m);
  vtkHAVSViewFrame::ToColumnMajor(view.ClipToEyeRelative, m);
  program->SetUniformMatrix4x4("havsDCRC", m);
  const double* shift = frame.Mesh->GetShift();
  float eye[3], direction[3], directionWorld[3], linear[9];
  for (int i = 0; i < 3; ++i)
  {
    eye[i] = static_cast<float>(view.EyeGrid[i] - shift[i]);
    direction[i] = static_cast<float>(view.DirectionGrid[i]);
    directionWorld[i] = static_cast<float>(view.DirectionWorld[i]);
    for (int j = 0; j < 3; ++j)
    {
      linear[3 * j + i] = static_cast<float>(view.GridToWorld[4 * i + j]); // column-major
    }
  }
  program->SetUniform3f("havsEyeMC", eye);
  program->SetUniform3f("havsDirectionMC", direction);
  program->SetUniform3f("havsDirectionOfProjection", directionWorld);
  program->SetUniformMatrix3x3("havsModelToWorld", linear);
  program->SetUniformi("havsParallel", view.Parallel ? 1 : 0);
  program->SetUniformi("havsWrongExit", frame.WrongExit ? 1 : 0);
  program->SetUniformf("havsGapLength", 3.0e38f);
  program->SetUniformi("havsOpaqueDepth", depth->GetTextureUnit());
  const float viewport[2] = { static_cast<float>(width), static_cast<float>(height) };
  program->SetUniform2f("havsViewportSize", viewport);
  const int planeCount = frame.Planes->GetNumberOfPlanes();
  program->SetUniformi("havsPlaneCount", planeCount);
  if (planeCount > 0)
  {
    float planes[7][4];
    for (int i = 0; i < planeCount && i < 7; ++i)
    {
      std::copy(frame.Planes->GetPlane(i).begin(), frame.Planes->GetPlane(i).end(), planes[i]);
    }
    program->SetUniform4fv("havsPlanesRC", std::min(planeCount, 7), planes);
  }

  state->PushFramebufferBindings();
  this->Targets->BindResult();
  state->vtkglViewport(0, 0, width, height);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const float zero[4] = { 0, 0, 0, 0 };
  glClearBufferfv(GL_COLOR, 0, zero);
  state->vtkglEnable(GL_BLEND);
  if (frame.Blend == vtkHAVSCellProjectionMapper::COMPOSITE_BLEND)
  {
    // Front to back: the segment goes under what is in front (premultiplied).
    state->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
  }
  else
  {
    // Order-independent: the largest (of s, or of 1 - s), or the sum.
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    state->vtkglBlendEquation(
      frame.Blend == vtkHAVSCellProjectionMapper::ADDITIVE_BLEND ? GL_FUNC_ADD : GL_MAX);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, this->CellBuffer);
  if (frame.MeasureStages)
  {
    glFinish();
  }
  const double t0 = vtkTimerLog::GetUniversalTime();
  if (sectionTriangles > 0)
  {
    // The near plane's section first: the cells it cuts are the first along
    // their rays (either facing; one triangle per cell entry).
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, this->SectionCellBuffer);
    program->SetUniformi("havsTrianglesPerCell", 1);
    program->SetUniformi("havsNearSectionDrawn", 1);
    glBindVertexArray(this->SectionArray);
    glDrawArrays(GL_TRIANGLES, 0, 3 * sectionTriangles);
  }
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_BACK);
  glFrontFace(view.FlipFacing ? GL_CW : GL_CCW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, this->OrderBuffer);
  program->SetUniformi("havsTrianglesPerCell", 4);
  program->SetUniformi("havsNearSectionDrawn", sectionTriangles > 0 ? 1 : 0);
  glBindVertexArray(this->VertexArray);
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(12 * this->UploadedCells), GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
  if (frame.MeasureStages)
  {
    glFinish();
  }
  *drawSeconds = vtkTimerLog::GetUniversalTime() - t0;
  glFrontFace(GL_CCW);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  const bool resolved =
    vtkHAVSExtremumPass::ResolveBlend(window, this->Targets, this->GLTable, frame.Blend);
  return this->Targets->EndFrame(resolved, frame.KeepResult, { cellOptics, additive, table, depth },
    view.OriginX, view.OriginY, this);
}

//------------------------------------------------------------------------------
const std::vector<float>* vtkOpenGLHAVSCellProjectionMapper::GetKeptResult(int size[2])
{
  return this->Targets->GetKeptResult(size);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  if (!this->Window || (window && window != this->Window))
  {
    return;
  }
  vtkOpenGLRenderWindow* home = this->Window;
  home->MakeCurrent();
  this->GLTable->ReleaseGraphicsResources(home);
  this->Targets->ReleaseGraphicsResources(home);
  if (this->VertexArray)
  {
    glDeleteVertexArrays(1, &this->VertexArray);
    const GLuint buffers[4] = { this->PointBuffer, this->IndexBuffer, this->CellBuffer,
      this->OrderBuffer };
    glDeleteBuffers(4, buffers);
    this->VertexArray = this->PointBuffer = this->IndexBuffer = 0;
    this->CellBuffer = this->OrderBuffer = 0;
  }
  if (this->SectionArray)
  {
    glDeleteVertexArrays(1, &this->SectionArray);
    const GLuint buffers[2] = { this->SectionPointBuffer, this->SectionCellBuffer };
    glDeleteBuffers(2, buffers);
    this->SectionArray = this->SectionPointBuffer = this->SectionCellBuffer = 0;
    this->SectionTriangles = 0;
  }
  this->UploadedCells = 0;
  home->RemoveObserver(this->WindowDeleteObserver);
  this->Window = nullptr;
  this->UploadedGeometry = this->UploadedTable = this->UploadedOrder = this->UploadedSection = 0;
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Window: " << this->Window << "\n";
}
