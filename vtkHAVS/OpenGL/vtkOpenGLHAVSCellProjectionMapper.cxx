/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSCellProjectionMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkOpenGLHAVSCellProjectionMapper.h"

#include "vtkHAVSExtremumPass.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLMapperResources.h"
#include "vtkHAVSGLObjects.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSShaders.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSViewFrame.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkOpenGLHAVSCellProjectionMapper);

namespace
{
/// Storage-buffer bindings of the cell-projection shaders (vtkHAVSCellProjectionVS/FS.glsl).
constexpr GLuint CellBinding = 4;  // the cells' planes and fields (vtkHAVSCellGeometry)
constexpr GLuint OrderBinding = 5; // the cell of each drawn triangle's position
/// Segments longer than this contribute nothing: off (the cell projection has no gaps to skip).
constexpr float NoGapLength = 3.0e38f;
/// The most planes the shaders take: 6 clipping planes and the near plane.
constexpr int MaximumPlanes = 7;
}

/// The mapper's own GPU objects.
struct vtkOpenGLHAVSCellProjectionMapper::GLObjects
{
  vtkHAVSGLVertexArray Cells; // the points, the ordered faces' indices
  vtkHAVSGLBuffer PointBuffer;
  vtkHAVSGLBuffer IndexBuffer;
  vtkHAVSGLBuffer CellBuffer;
  vtkHAVSGLBuffer OrderBuffer;
  vtkHAVSGLVertexArray Section; // the near plane's section
  vtkHAVSGLBuffer SectionPointBuffer;
  vtkHAVSGLBuffer SectionCellBuffer;
  int SectionTriangles = 0;
  size_t UploadedCells = 0; // tetrahedra in the index buffer (12 indices each)

  void Release()
  {
    for (vtkHAVSGLBuffer* b : { &this->PointBuffer, &this->IndexBuffer, &this->CellBuffer,
           &this->OrderBuffer, &this->SectionPointBuffer, &this->SectionCellBuffer })
    {
      b->Release();
    }
    this->Cells.Release();
    this->Section.Release();
    this->SectionTriangles = 0;
    this->UploadedCells = 0;
  }
};

//------------------------------------------------------------------------------
vtkOpenGLHAVSCellProjectionMapper::vtkOpenGLHAVSCellProjectionMapper()
  : GL(new GLObjects)
{
  this->Resources->SetReleaseCallback([this](vtkOpenGLRenderWindow*) { this->GL->Release(); });
}

vtkOpenGLHAVSCellProjectionMapper::~vtkOpenGLHAVSCellProjectionMapper()
{
  this->ReleaseGraphicsResources(nullptr);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::Upload(const CellFrame& frame)
{
  GLObjects& gl = *this->GL;
  if (gl.PointBuffer.Update(GL_ARRAY_BUFFER, frame.Mesh->GetPoints(), frame.GeometryVersion))
  {
    gl.CellBuffer.Update(GL_SHADER_STORAGE_BUFFER, *frame.Cells, frame.GeometryVersion);
    gl.Cells.SetBuffers(gl.PointBuffer, &gl.IndexBuffer);
  }
  this->Resources->GetTable()->Update(frame.Table, frame.TableVersion);
  // The faces of the cells in the frame's order, and the cell of each
  // position: only when the order changed (not on a redraw or a
  // transfer-function edit; once per mesh for the unsorted blends).
  if (gl.OrderBuffer.GetVersion() == frame.OrderVersion && gl.UploadedCells == frame.Order->size())
  {
    return;
  }
  const std::vector<uint32_t>& order = *frame.Order;
  const std::vector<uint32_t>& faces = *frame.Faces;
  std::vector<uint32_t> indices(12 * order.size()); // (only until uploaded)
  for (size_t i = 0; i < order.size(); ++i)
  {
    std::copy_n(&faces[12 * static_cast<size_t>(order[i])], 12, &indices[12 * i]);
  }
  gl.IndexBuffer.Update(GL_ELEMENT_ARRAY_BUFFER, indices, 0, GL_STREAM_DRAW);
  gl.OrderBuffer.Update(GL_SHADER_STORAGE_BUFFER, order, frame.OrderVersion, GL_STREAM_DRAW);
  gl.Cells.SetBuffers(gl.PointBuffer, &gl.IndexBuffer);
  gl.UploadedCells = order.size();
}

//------------------------------------------------------------------------------
int vtkOpenGLHAVSCellProjectionMapper::UploadSection(const CellFrame& frame)
{
  const std::vector<vtkHAVSFramePlanes::Section>& sections = frame.Planes->GetSections();
  if (sections.empty())
  {
    return 0; // (the camera outside the mesh: nothing cut by the near plane)
  }
  GLObjects& gl = *this->GL;
  const vtkMTimeType version = frame.Planes->GetSectionsVersion();
  const vtkHAVSFramePlanes::Section& section = sections.front(); // the near plane's only
  if (gl.SectionPointBuffer.Update(GL_ARRAY_BUFFER, section.Points, version, GL_STREAM_DRAW))
  {
    gl.SectionCellBuffer.Update(GL_SHADER_STORAGE_BUFFER, section.Cells, version, GL_STREAM_DRAW);
    gl.Section.SetBuffers(gl.SectionPointBuffer, nullptr);
    gl.SectionTriangles = static_cast<int>(section.Cells.size());
  }
  return gl.SectionTriangles;
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::SetUniforms(
  vtkShaderProgram* program, const CellFrame& frame)
{
  const vtkHAVSViewFrame& view = *frame.View;
  this->Resources->GetTable()->SetUniforms(program);
  program->SetUniformi("havsAdditive", this->Resources->GetTable()->GetAdditive1D()->GetTextureUnit());
  program->SetUniformi(
    "havsOpaqueDepth", this->Resources->GetTargets()->GetOpaqueDepth()->GetTextureUnit());
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
  program->SetUniformf("havsGapLength", NoGapLength);
  const float viewport[2] = { static_cast<float>(view.Width), static_cast<float>(view.Height) };
  program->SetUniform2f("havsViewportSize", viewport);
  const int planeCount = std::min(frame.Planes->GetNumberOfPlanes(), MaximumPlanes);
  program->SetUniformi("havsPlaneCount", planeCount);
  if (planeCount > 0)
  {
    float planes[MaximumPlanes][4];
    for (int i = 0; i < planeCount; ++i)
    {
      std::copy(frame.Planes->GetPlane(i).begin(), frame.Planes->GetPlane(i).end(), planes[i]);
    }
    program->SetUniform4fv("havsPlanesRC", planeCount, planes);
  }
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSCellProjectionMapper::DrawCells(
  vtkRenderer* renderer, const CellFrame& frame, double* drawSeconds)
{
  // 1. The window, and what changed uploaded.
  vtkOpenGLRenderWindow* window = this->Resources->Prepare(
    renderer, this, "vtkHAVSCellProjectionMapper", "storage buffers");
  if (!window)
  {
    return false;
  }
  GLObjects& gl = *this->GL;
  vtkHAVSGLFrameTargets* targets = this->Resources->GetTargets();
  vtkHAVSGLTable* glTable = this->Resources->GetTable();
  this->Upload(frame);
  const int sectionTriangles = this->UploadSection(frame);
  const vtkHAVSViewFrame& view = *frame.View;
  const int width = view.Width, height = view.Height;
  targets->Resize(width, height);
  const bool opaque = frame.Opaque;
  if (opaque)
  {
    targets->CaptureOpaqueDepth(view.OriginX, view.OriginY, width, height, this);
  }

  // 2. The program, its textures and uniforms.
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    vtkHAVSShaders::CellProjectionVertexShader().c_str(),
    vtkHAVSShaders::CellProjectionShader(opaque, frame.Blend, glTable->HasCellOptics())
      .c_str(),
    "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("The cell-projection shader could not be built; see the shader log above.");
    return false;
  }

  vtkOpenGLState* state = window->GetState();
  vtkHAVSGLScopedPassState passState(state);
  vtkTextureObject* table = glTable->GetTable();
  vtkTextureObject* depth = targets->GetOpaqueDepth();
  vtkTextureObject* additive = glTable->GetAdditive1D();
  vtkTextureObject* cellOptics = glTable->GetCellOptics();
  table->Activate();
  depth->Activate();
  additive->Activate();
  cellOptics->Activate();
  this->SetUniforms(program, frame);

  // 3. The draw: the near plane's section, then every cell's front faces in
  // the order, blended front to back (or order-independently).
  state->PushFramebufferBindings();
  targets->BindResult();
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
  gl.CellBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, CellBinding);
  if (frame.MeasureStages)
  {
    glFinish();
  }
  const double t0 = vtkTimerLog::GetUniversalTime();
  if (sectionTriangles > 0)
  {
    // The near plane's section first: the cells it cuts are the first along
    // their rays (either facing; one triangle per cell entry).
    gl.SectionCellBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, OrderBinding);
    program->SetUniformi("havsTrianglesPerCell", 1);
    program->SetUniformi("havsNearSectionDrawn", 1);
    gl.Section.Bind();
    glDrawArrays(GL_TRIANGLES, 0, 3 * sectionTriangles);
  }
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_BACK);
  glFrontFace(view.FlipFacing ? GL_CW : GL_CCW);
  gl.OrderBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, OrderBinding);
  program->SetUniformi("havsTrianglesPerCell", 4);
  program->SetUniformi("havsNearSectionDrawn", sectionTriangles > 0 ? 1 : 0);
  gl.Cells.Bind();
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(12 * gl.UploadedCells), GL_UNSIGNED_INT, nullptr);
  vtkHAVSGLVertexArray::Unbind();
  if (frame.MeasureStages)
  {
    glFinish();
  }
  *drawSeconds = vtkTimerLog::GetUniversalTime() - t0;
  glFrontFace(GL_CCW);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  // 4. The extremum blends' resolve, the result composited into the window.
  const bool resolved = vtkHAVSExtremumPass::ResolveBlend(window, targets, glTable, frame.Blend);
  return targets->EndFrame(resolved, frame.KeepResult, { cellOptics, additive, table, depth },
    view.OriginX, view.OriginY, this);
}

//------------------------------------------------------------------------------
const std::vector<float>* vtkOpenGLHAVSCellProjectionMapper::GetKeptResult(int size[2])
{
  return this->Resources->GetTargets()->GetKeptResult(size);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Resources->Release(window);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Cells uploaded: " << this->GL->UploadedCells
     << ", section triangles: " << this->GL->SectionTriangles << "\n";
  this->Resources->PrintSelf(os, indent.GetNextIndent());
}

VTK_ABI_NAMESPACE_END
