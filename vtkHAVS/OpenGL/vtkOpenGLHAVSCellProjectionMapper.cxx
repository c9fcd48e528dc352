/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSCellProjectionMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkOpenGLHAVSCellProjectionMapper.h"

#include "vtkHAVSCellGeometry.h"
#include "vtkHAVSExtremumPass.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameCapture.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLMapperResources.h"
#include "vtkHAVSGLObjects.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSShaders.h"
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
#include <memory>
#include <sstream>
#include <string>
#include <vector>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkOpenGLHAVSCellProjectionMapper);

namespace
{
/// Storage-buffer bindings of the cell-projection shaders (vtkHAVSCellProjectionVS/FS.glsl;
/// the cell records: vtkHAVSGLCellRecords).
constexpr GLuint OrderBinding = 5;    // the cell of each drawn position
constexpr GLuint TetBinding = 6;      // the tetrahedra's point ids
constexpr GLuint MirroredBinding = 7; // one bit a tetrahedron: its faces' windings
constexpr GLuint PointBinding = 8;    // the points (3 floats each)
constexpr GLuint ScalarBinding = 9;   // isosurface frames: the points' scalars (normalized)
/// Segments longer than this contribute nothing: off (the cell projection has no gaps to skip).
constexpr float NoGapLength = 3.0e38f;
}

/// The mapper's own GPU objects.
struct vtkOpenGLHAVSCellProjectionMapper::GLObjects : vtkHAVSGLOwnObjects
{
  vtkHAVSGLVertexArray Cells; // no attributes: the vertex shader pulls the vertices
  vtkHAVSGLBuffer Pattern;    // the faces of PatternCells cells: corner ids 4 slot + k
  size_t PatternCells = 0;
  vtkHAVSGLBuffer PointBuffer;
  vtkHAVSGLBuffer ScalarBuffer; // isosurface frames only (released otherwise)
  vtkHAVSGLBuffer TetBuffer;
  vtkHAVSGLBuffer MirroredBuffer;
  vtkHAVSGLCellRecords Records; // the cells' planes and fields (vtkHAVSCellGeometry)
  vtkHAVSGLBuffer OrderBuffer;
  size_t UploadedCells = 0; // tetrahedra in the order buffer

  void Release(vtkOpenGLRenderWindow*) override
  {
    for (vtkHAVSGLBuffer* b : { &this->PointBuffer, &this->ScalarBuffer, &this->TetBuffer,
           &this->MirroredBuffer, &this->OrderBuffer })
    {
      b->Release();
    }
    this->Records.Release();
    this->Pattern.Release();
    this->PatternCells = 0;
    this->Cells.Release();
    this->UploadedCells = 0;
  }
};

//------------------------------------------------------------------------------
vtkOpenGLHAVSCellProjectionMapper::vtkOpenGLHAVSCellProjectionMapper()
{
  this->GL = this->Resources->Own(std::make_unique<GLObjects>());
  this->SetGraphics(this->Resources);
}

vtkOpenGLHAVSCellProjectionMapper::~vtkOpenGLHAVSCellProjectionMapper() = default;

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::Upload(const CellFrame& frame)
{
  GLObjects& gl = *this->GL;
  const vtkMTimeType version = frame.GeometryVersion;
  if (gl.PointBuffer.Update(GL_ARRAY_BUFFER, frame.Mesh->GetPoints(), version))
  {
    if (frame.Cells->empty() && frame.RestoreCells)
    {
      frame.RestoreCells(); // (freed after the last upload)
    }
    gl.Records.Update(*frame.Cells, static_cast<size_t>(this->GetLargestGPUBuffer()), version);
    gl.TetBuffer.Update(GL_SHADER_STORAGE_BUFFER, *frame.Tetrahedra, version);
    gl.MirroredBuffer.Update(GL_SHADER_STORAGE_BUFFER, *frame.Mirrored, version);
  }
  this->Resources->GetTable()->Update(frame.Table, frame.TableVersion);
  // The cell of each position: only when the order changed (not on a redraw
  // or a transfer-function edit; once per mesh for the unsorted blends). The
  // vertex shader winds each cell's four faces from its point ids.
  if (gl.OrderBuffer.GetVersion() == frame.OrderVersion && gl.UploadedCells == frame.Order->size())
  {
    return;
  }
  gl.OrderBuffer.Update(GL_SHADER_STORAGE_BUFFER, *frame.Order, frame.OrderVersion, GL_STREAM_DRAW);
  gl.UploadedCells = frame.Order->size();
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::SetUniforms(
  vtkShaderProgram* program, const CellFrame& frame)
{
  const vtkHAVSViewFrame& view = *frame.View;
  this->Resources->SetTextureUniforms(program);
  vtkHAVSGLMapperResources::SetViewUniforms(
    program, view, frame.Planes, frame.Mesh->GetShift(), true);
  // The projection's own: the clip matrix, the model's linear part in world
  // units (the segment lengths), the testing aid, no gap length.
  float m[16];
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToClip, m);
  program->SetUniformMatrix4x4("havsMCDC", m);
  float linear[9];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      linear[3 * j + i] = static_cast<float>(view.GridToWorld[4 * i + j]); // column-major
    }
  }
  program->SetUniformMatrix3x3("havsModelToWorld", linear);
  program->SetUniformi("havsWrongExit", frame.WrongExit ? 1 : 0);
  this->GL->Records.SetUniforms(program);
  program->SetUniformf("havsGapLength", NoGapLength);
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSCellProjectionMapper::DrawCells(
  vtkRenderer* renderer, const CellFrame& frame, double* drawSeconds)
{
  // 1. The window, the targets, the section; what changed uploaded.
  const vtkHAVSViewFrame& view = *frame.View;
  const bool opaque = frame.Opaque;
  vtkOpenGLRenderWindow* window =
    this->Resources->BeginFrame(renderer, this, "vtkHAVSCellProjectionMapper", "storage buffers",
      view, opaque, *frame.Planes, this->GetLastEdgeUpsampling() ? frame.Mesh : nullptr);
  if (!window)
  {
    return false;
  }
  GLObjects& gl = *this->GL;
  this->Upload(frame);
  const int sectionTriangles = this->Resources->GetSectionTriangles();

  // 2. The program, its textures and uniforms.
  const bool isoShade =
    this->Resources->BindIsoShading(this, static_cast<size_t>(this->GetLargestGPUBuffer()));
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    vtkHAVSShaders::CellProjectionVertexShader().c_str(),
    vtkHAVSShaders::CellProjectionShader(opaque, frame.Blend,
      this->Resources->GetTable()->HasCellOptics(), gl.Records.GetBufferCount(),
      this->GetFrameIsoSurfaces().ShaderMode(this->GetBlendMode()), isoShade,
      !frame.FloatIsoStretches)
      .c_str(),
    "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("The cell-projection shader could not be built; see the shader log above.");
    return false;
  }

  vtkOpenGLState* state = window->GetState();
  vtkHAVSGLScopedPassState passState(state);
  this->Resources->ActivateTextures();
  this->SetUniforms(program, frame);

  // 3. The draw: the near plane's section, then every cell's front faces in
  // the order, blended front to back (or order-independently).
  state->PushFramebufferBindings();
  this->Resources->GetTargets()->BindResult();
  state->vtkglViewport(0, 0, view.Width, view.Height);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const float zero[4] = { 0, 0, 0, 0 };
  glClearBufferfv(GL_COLOR, 0, zero);
  this->Resources->SetBlending(frame.Blend);
  gl.Records.Bind();
  if (frame.MeasureStages)
  {
    glFinish();
  }
  const double t0 = vtkTimerLog::GetUniversalTime();
  if (sectionTriangles > 0)
  {
    // The near plane's section first: the cells it cuts are the first along
    // their rays (either facing; one triangle per cell entry).
    program->SetUniformi("havsTrianglesPerCell", 1);
    program->SetUniformi("havsPullVertices", 0);
    program->SetUniformi("havsFirstCell", 0);
    program->SetUniformi("havsNearSectionDrawn", 1);
    this->Resources->DrawSection(OrderBinding);
  }
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_BACK);
  glFrontFace(view.FlipFacing ? GL_CW : GL_CCW);
  gl.OrderBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, OrderBinding);
  gl.TetBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, TetBinding);
  gl.MirroredBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, MirroredBinding);
  gl.PointBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, PointBinding);
  if (program->IsUniformUsed("havsFaceScalars"))
  {
    // Isosurface frames: each cell's stretch from the exact ray in double,
    // and the scalars where it enters and leaves interpolated on those faces
    // from the points' scalars (the shader's havsStretchd and
    // havsFaceScalarAt), uploaded only for them.
    const std::vector<float>& scalars = frame.Mesh->GetScalars();
    const bool usable = !frame.Mesh->HasCellScalars() &&
      scalars.size() == frame.Mesh->GetPoints().size() / 3 && !scalars.empty();
    if (usable)
    {
      gl.ScalarBuffer.Update(GL_SHADER_STORAGE_BUFFER, scalars,
        std::max(frame.Mesh->GetBuildTime(), frame.Mesh->GetScalarTime()));
      gl.ScalarBuffer.BindBase(GL_SHADER_STORAGE_BUFFER, ScalarBinding);
    }
    program->SetUniformi("havsFaceScalars", usable ? 1 : 0);
  }
  else if (gl.ScalarBuffer.GetHandle())
  {
    gl.ScalarBuffer.Release();
  }
  program->SetUniformi("havsTrianglesPerCell", 4);
  program->SetUniformi("havsNearSectionDrawn", sectionTriangles > 0 ? 1 : 0);
  program->SetUniformi("havsPullVertices", 1);
  // The faces of a run of cells as one pattern of indices, drawn again for
  // every run with its first corner as the base vertex: each cell's 4
  // corners are shaded once (the vertex cache), and no index buffer in draw
  // order exists. Runs of at most PatternCells cells: a software
  // rasterizer's pieces (at most two queued, its binned scenes stay
  // bounded), else 2^20.
  const long long perPiece = vtkHAVSGLCapabilities::FacesPerFinish() / 4;
  const size_t patternCells = static_cast<size_t>(perPiece > 0 ? perPiece : (1LL << 20));
  if (gl.PatternCells != patternCells)
  {
    // Face f of a cell, opposite its corner f, counter-clockwise seen from
    // outside a tetrahedron of positive volume (the vertex shader swaps
    // corners 2 and 3 of a mirrored one).
    static constexpr GLuint Faces[12] = { 1, 2, 3, 2, 0, 3, 3, 0, 1, 0, 2, 1 };
    std::vector<GLuint> pattern(12 * patternCells);
    for (size_t c = 0; c < patternCells; ++c)
    {
      for (int i = 0; i < 12; ++i)
      {
        pattern[12 * c + i] = static_cast<GLuint>(4 * c) + Faces[i];
      }
    }
    gl.Pattern.Update(GL_ELEMENT_ARRAY_BUFFER, pattern, 0);
    gl.PatternCells = patternCells;
    gl.Cells.SetIndices(&gl.Pattern);
  }
  gl.Cells.Bind();
  // Each draw told its first cell (gl_PrimitiveID restarts at every draw).
  const auto drawRun = [program](long long begin, long long end)
  {
    program->SetUniformi("havsFirstCell", static_cast<int>(begin));
    glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(12 * (end - begin)),
      GL_UNSIGNED_INT, nullptr, static_cast<GLint>(4 * begin));
  };
  if (perPiece > 0)
  {
    vtkHAVSGLCapabilities::DrawInPieces(
      0, static_cast<long long>(gl.UploadedCells), perPiece, drawRun);
  }
  else
  {
    for (long long begin = 0; begin < static_cast<long long>(gl.UploadedCells);
         begin += static_cast<long long>(patternCells))
    {
      drawRun(begin,
        std::min(
          static_cast<long long>(gl.UploadedCells), begin + static_cast<long long>(patternCells)));
    }
  }
  vtkHAVSGLVertexArray::Unbind();
  if (frame.MeasureStages)
  {
    glFinish();
  }
  *drawSeconds = vtkTimerLog::GetUniversalTime() - t0;
  glFrontFace(GL_CCW);
  state->vtkglDisable(GL_CULL_FACE);

  // The frame case (a benchmark aid, SetCaptureDirectory): the result as
  // drawn, before the composite.
  if (this->CaptureDirectory)
  {
    std::string error;
    this->LastCaptureSucceeded = this->WriteCase(frame, program, patternCells, error);
    if (!this->LastCaptureSucceeded)
    {
      vtkErrorMacro("No frame capture: " << error << ".");
    }
    this->SetCaptureDirectory(nullptr);
  }

  // 4. The extremum blends' resolve, the result composited into the window.
  return this->Resources->EndFrame(frame.Blend, frame.KeepResult, view, this);
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSCellProjectionMapper::WriteCase(
  const CellFrame& frame, vtkShaderProgram* program, size_t patternCells, std::string& error)
{
  // What the stand-alone replay draws: the cells' faces alone, composited
  // front to back (Apps/GPUBench/havsGPUCellProjection.cxx).
  using Capture = vtkHAVSGLFrameCapture;
  const GLObjects& gl = *this->GL;
  if (frame.Mesh->HasCellScalars())
  {
    error = "frames of cell scalars are not captured (the stand-alone program has no cell optics)";
    return false;
  }
  std::string header;
  if (!this->Resources->BeginCapture(this->CaptureDirectory, "cellprojection", frame.Blend,
        frame.Opaque, frame.Planes, *frame.View, gl.Records, header, error))
  {
    return false;
  }
  // The records as the GPU holds them: the host copy is freed after its
  // upload, made again here (vtkHAVSCellGeometry::Compute, as uploaded).
  if (frame.Cells->empty() && frame.RestoreCells)
  {
    frame.RestoreCells();
  }
  const std::vector<float>& points = frame.Mesh->GetPoints();
  const size_t tetrahedra = frame.Tetrahedra->size() / 4;
  if (frame.Cells->size() != tetrahedra * vtkHAVSCellGeometry::FloatsPerCell)
  {
    error = "the cell records are not available";
    return false;
  }
  const std::string dir = std::string(this->CaptureDirectory) + "/";
  std::ostringstream text;
  text << header << "cells " << frame.Order->size() << "\npoints " << points.size() / 3
       << "\ntetrahedra " << tetrahedra << "\nflip_facing " << (frame.View->FlipFacing ? 1 : 0)
       << "\npattern_cells " << patternCells << "\n"
       << Capture::UniformLines("cells", program->GetHandle());
  const bool ok = Capture::WriteText(dir + "case.txt", text.str()) &&
    Capture::WriteArray(dir + "points.f32", points) &&
    Capture::WriteArray(dir + "tetrahedra.u32", *frame.Tetrahedra) &&
    Capture::WriteArray(dir + "mirrored.u32", *frame.Mirrored) &&
    Capture::WriteArray(dir + "cells.f32", *frame.Cells) &&
    Capture::WriteArray(dir + "order.u32", *frame.Order) &&
    Capture::WriteText(dir + "cellprojection.vert", vtkHAVSShaders::CellProjectionVertexShader()) &&
    Capture::WriteText(dir + "cellprojection.frag",
      vtkHAVSShaders::CellProjectionShader(
        frame.Opaque, frame.Blend, false, gl.Records.GetBufferCount())) &&
    Capture::WriteText(dir + "trivial.frag", vtkHAVSShaders::TrivialShader());
  if (!ok)
  {
    error = "cannot write the case into " + dir;
  }
  return ok;
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSCellProjectionMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Cells uploaded: " << this->GL->UploadedCells << "\n";
  this->Resources->PrintSelf(os, indent.GetNextIndent());
}

VTK_ABI_NAMESPACE_END
