/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSRayCastMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkOpenGLHAVSRayCastMapper.h"

#include "vtkHAVSExtremumPass.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSKBufferShaders.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSRayCastMesh.h"
#include "vtkHAVSViewFrame.h"

#include "vtkCommand.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkOpenGLHAVSRayCastMapper);

namespace
{
enum BufferIndex
{
  PointBuffer,
  FaceBuffer,
  FaceCellBuffer,
  CellBuffer,
  NeighbourBuffer,
  CountBuffer,
  TileBuffer,
  PeelTileBuffer,
  NumberOfBuffers
};
enum ImageIndex
{
  EntryKeyImage,
  EntryCellImage,
  RayStateImage
};
}

//------------------------------------------------------------------------------
vtkOpenGLHAVSRayCastMapper::vtkOpenGLHAVSRayCastMapper() = default;

vtkOpenGLHAVSRayCastMapper::~vtkOpenGLHAVSRayCastMapper()
{
  this->ReleaseGraphicsResources(nullptr);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::PrepareWindow(vtkOpenGLRenderWindow* window)
{
  if (this->Window == window)
  {
    window->MakeCurrent();
    return;
  }
  this->ReleaseGraphicsResources(this->Window);
  this->Window = window;
  this->WindowDeleteObserver = window->AddObserver(
    vtkCommand::DeleteEvent, this, &vtkOpenGLHAVSRayCastMapper::OnWindowDeleted);
  window->MakeCurrent();
  this->GLTable->SetContext(window);
  this->Targets->SetContext(window);
}

void vtkOpenGLHAVSRayCastMapper::OnWindowDeleted(vtkObject* window, unsigned long, void*)
{
  this->ReleaseGraphicsResources(vtkWindow::SafeDownCast(window));
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::Upload(const RayFrame& frame)
{
  if (!this->VertexArray)
  {
    glGenVertexArrays(1, &this->VertexArray);
    glGenBuffers(NumberOfBuffers, this->Buffers);
    glGenVertexArrays(1, &this->TileArray);
  }
  if (this->UploadedMesh != frame.MeshVersion)
  {
    const vtkHAVSRayCastMesh& mesh = *frame.RayMesh;
    const std::vector<float>& points = frame.Mesh->GetPoints();
    glBindVertexArray(this->VertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, this->Buffers[PointBuffer]);
    glBufferData(GL_ARRAY_BUFFER, points.size() * sizeof(float), points.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, this->Buffers[FaceBuffer]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, mesh.GetBoundaryFaces().size() * sizeof(uint32_t),
      mesh.GetBoundaryFaces().data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    auto storage = [](GLuint buffer, size_t bytes, const void* data)
    {
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
      // (At least 16 bytes: an empty mesh still binds a buffer.)
      glBufferData(GL_SHADER_STORAGE_BUFFER, std::max<size_t>(bytes, 16), bytes ? data : nullptr,
        GL_STATIC_DRAW);
    };
    storage(this->Buffers[FaceCellBuffer], mesh.GetBoundaryCells().size() * sizeof(uint32_t),
      mesh.GetBoundaryCells().data());
    storage(
      this->Buffers[CellBuffer], mesh.GetCells().size() * sizeof(float), mesh.GetCells().data());
    storage(this->Buffers[NeighbourBuffer], mesh.GetNeighbours().size() * sizeof(int32_t),
      mesh.GetNeighbours().data());
    storage(this->Buffers[CountBuffer], 3 * sizeof(uint32_t), nullptr);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    this->BoundaryFaces = static_cast<int>(mesh.GetNumberOfBoundaryFaces());
    this->Tetrahedra = static_cast<int>(mesh.GetNumberOfTetrahedra());
    this->UploadedMesh = frame.MeshVersion;
  }
  if (this->UploadedTable != frame.TableVersion)
  {
    this->GLTable->Upload(frame.Table);
    this->UploadedTable = frame.TableVersion;
  }
}

//------------------------------------------------------------------------------
int vtkOpenGLHAVSRayCastMapper::UploadSection(const RayFrame& frame)
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
    glGenBuffers(2, this->SectionBuffers);
  }
  const vtkHAVSFramePlanes::Section& section = sections.front(); // the near plane's only
  glBindVertexArray(this->SectionArray);
  glBindBuffer(GL_ARRAY_BUFFER, this->SectionBuffers[0]);
  glBufferData(
    GL_ARRAY_BUFFER, section.Points.size() * sizeof(float), section.Points.data(), GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindVertexArray(0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->SectionBuffers[1]);
  glBufferData(GL_SHADER_STORAGE_BUFFER, section.Cells.size() * sizeof(uint32_t),
    section.Cells.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  this->UploadedSection = version;
  this->SectionTriangles = static_cast<int>(section.Cells.size());
  return this->SectionTriangles;
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::ResizeImages(int width, int height)
{
  if (this->Images[0] && this->ImageSize[0] == width && this->ImageSize[1] == height)
  {
    return;
  }
  this->ReleaseImages();
  GLint drawn = 0; // (the draw framebuffer VTK's state has bound, put back below)
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawn);
  glGenTextures(3, this->Images);
  const GLenum formats[3] = { GL_R32UI, GL_R32UI, GL_RGBA32F };
  for (int i = 0; i < 3; ++i)
  {
    glBindTexture(GL_TEXTURE_2D, this->Images[i]);
    glTexStorage2D(GL_TEXTURE_2D, 1, formats[i], width, height);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  // (Only a stencil: the peeling writes no colour, reads no depth.)
  glGenRenderbuffers(1, &this->PeelStencil);
  glBindRenderbuffer(GL_RENDERBUFFER, this->PeelStencil);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &this->PeelFramebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->PeelFramebuffer);
  glFramebufferRenderbuffer(
    GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, this->PeelStencil);
  glDrawBuffer(GL_NONE);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawn));
  this->ImageSize[0] = width;
  this->ImageSize[1] = height;
}

void vtkOpenGLHAVSRayCastMapper::ReleaseImages()
{
  if (this->Images[0])
  {
    glDeleteTextures(3, this->Images);
    std::fill(this->Images, this->Images + 3, 0u);
  }
  if (this->PeelFramebuffer)
  {
    glDeleteFramebuffers(1, &this->PeelFramebuffer);
    glDeleteRenderbuffers(1, &this->PeelStencil);
    this->PeelFramebuffer = this->PeelStencil = 0;
  }
  this->ImageSize[0] = this->ImageSize[1] = 0;
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSRayCastMapper::DrawRays(
  vtkRenderer* renderer, const RayFrame& frame, RayCounts* counts)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("vtkHAVSRayCastMapper needs an OpenGL render window.");
    return false;
  }
  this->PrepareWindow(window);
  if (!vtkHAVSGLCapabilities::HasVersion(4, 3))
  {
    vtkErrorMacro("vtkHAVSRayCastMapper needs OpenGL 4.3 (storage buffers, images).");
    return false;
  }
  this->Upload(frame);
  const int sectionTriangles = this->UploadSection(frame);
  const vtkHAVSViewFrame& view = *frame.View;
  const int width = view.Width, height = view.Height;
  this->Targets->Resize(width, height);
  this->ResizeImages(width, height);
  if (frame.Opaque)
  {
    this->Targets->CaptureOpaqueDepth(view.OriginX, view.OriginY, width, height, this);
  }
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  vtkShaderProgram* peel =
    cache->ReadyShaderProgram(vtkHAVSKBufferShaders::CellProjectionVertexShader().c_str(),
      vtkHAVSKBufferShaders::RayCastPeelShader().c_str(), "");
  vtkShaderProgram* cast = peel && peel->GetCompiled()
    ? cache->ReadyShaderProgram(vtkHAVSKBufferShaders::RayCastTileVertexShader().c_str(),
        vtkHAVSKBufferShaders::RayCastShader(
          frame.Opaque, frame.Blend, this->GLTable->HasCellOptics())
          .c_str(),
        "")
    : nullptr;
  // The tiles a peeling pass draws (a stencil of them): the tile vertex
  // shader with the trivial fragment shader (the peel's framebuffer has no
  // colour attachment: only the stencil is written).
  vtkShaderProgram* mask = cast && cast->GetCompiled()
    ? cache->ReadyShaderProgram(vtkHAVSKBufferShaders::RayCastTileVertexShader().c_str(),
        vtkHAVSKBufferShaders::TrivialShader().c_str(), "")
    : nullptr;
  if (!cast || !cast->GetCompiled() || !mask || !mask->GetCompiled())
  {
    vtkErrorMacro("The ray-casting shaders could not be built; see the shader log above.");
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

  // The uniforms both programs read (the view, the planes).
  float m[16];
  const double* shift = frame.Mesh->GetShift();
  float eye[3], direction[3], directionWorld[3];
  for (int i = 0; i < 3; ++i)
  {
    eye[i] = static_cast<float>(view.EyeGrid[i] - shift[i]);
    direction[i] = static_cast<float>(view.DirectionGrid[i]);
    directionWorld[i] = static_cast<float>(view.DirectionWorld[i]);
  }
  const float viewport[2] = { static_cast<float>(width), static_cast<float>(height) };
  const int planeCount = std::min(frame.Planes->GetNumberOfPlanes(), 7);
  float planes[7][4] = {};
  for (int i = 0; i < planeCount; ++i)
  {
    std::copy(frame.Planes->GetPlane(i).begin(), frame.Planes->GetPlane(i).end(), planes[i]);
  }
  for (vtkShaderProgram* program : { peel, cast })
  {
    cache->ReadyShaderProgram(program);
    vtkHAVSViewFrame::ToColumnMajor(view.ModelToEyeRelative, m);
    program->SetUniformMatrix4x4("havsMCRC", m);
    vtkHAVSViewFrame::ToColumnMajor(view.ClipToEyeRelative, m);
    program->SetUniformMatrix4x4("havsDCRC", m);
    program->SetUniform3f("havsDirectionOfProjection", directionWorld);
    program->SetUniformi("havsParallel", view.Parallel ? 1 : 0);
    program->SetUniform2f("havsViewportSize", viewport);
    program->SetUniformi("havsPlaneCount", planeCount);
    if (planeCount > 0)
    {
      program->SetUniform4fv("havsPlanesRC", planeCount, planes);
    }
  }
  // Screen tiles (without them, one tile covering the viewport).
  const int tileSize = frame.TileSize > 0 ? frame.TileSize : std::max(width, height);
  const int tileCount[2] = { (width + tileSize - 1) / tileSize,
    (height + tileSize - 1) / tileSize };
  const int tiles = tileCount[0] * tileCount[1];
  {
    const std::vector<GLuint> none(static_cast<size_t>(tiles), 0u);
    for (int buffer : { TileBuffer, PeelTileBuffer })
    {
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[buffer]);
      glBufferData(
        GL_SHADER_STORAGE_BUFFER, none.size() * sizeof(GLuint), none.data(), GL_STREAM_DRAW);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  }
  cache->ReadyShaderProgram(mask);
  mask->SetUniform2f("havsViewportSize", viewport);
  for (vtkShaderProgram* program : { peel, cast, mask })
  {
    cache->ReadyShaderProgram(program);
    program->SetUniform2i("havsTileCount", tileCount);
    program->SetUniformi("havsTileSize", tileSize);
  }
  cache->ReadyShaderProgram(peel);
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToClip, m);
  peel->SetUniformMatrix4x4("havsMCDC", m);
  peel->SetUniformf("havsPeelTolerance", 1.0e-5f);
  cache->ReadyShaderProgram(cast);
  this->GLTable->SetUniforms(cast);
  cast->SetUniformf("havsTerminationOpacity", frame.TerminationOpacity);
  cast->SetUniformf("havsGapLength", 3.0e38f);
  cast->SetUniformi("havsOpaqueDepth", depth->GetTextureUnit());
  cast->SetUniformi("havsAdditive", additive->GetTextureUnit());
  double clipToModel[16];
  vtkMatrix4x4::Invert(view.ModelToClip, clipToModel);
  vtkHAVSViewFrame::ToColumnMajor(clipToModel, m);
  cast->SetUniformMatrix4x4("havsDCMC", m);
  cast->SetUniform3f("havsEyeMC", eye);
  cast->SetUniform3f("havsDirectionMC", direction);
  cast->SetUniformi("havsMaxSteps", this->Tetrahedra + 16);
  cast->SetUniformi("havsFolds", frame.FoldReentries ? 1 : 0);

  // Per pixel: no entry yet, the ray has reached nothing, opacity 0.
  const GLuint noKey = 0xffffffffu, noCell = 0;
  const float fresh[4] = { -3.0e38f, 0.0f, -3.0e38f, 0.0f };
  glClearTexImage(this->Images[EntryKeyImage], 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noKey);
  glClearTexImage(this->Images[EntryCellImage], 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noCell);
  glClearTexImage(this->Images[RayStateImage], 0, GL_RGBA, GL_FLOAT, fresh);
  glBindImageTexture(0, this->Images[EntryKeyImage], 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindImageTexture(1, this->Images[EntryCellImage], 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindImageTexture(2, this->Images[RayStateImage], 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  const GLuint zeroCounts[3] = { 0, 0, 0 };
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[CountBuffer]);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(zeroCounts), zeroCounts);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, this->Buffers[CellBuffer]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, this->Buffers[FaceCellBuffer]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, this->Buffers[NeighbourBuffer]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, this->Buffers[CountBuffer]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, this->Buffers[TileBuffer]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, this->Buffers[PeelTileBuffer]);
  // The stencil state VTK's state holds, put back after the frame.
  vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
  GLint stencil[7] = { GL_ALWAYS, 0, -1, GL_KEEP, GL_KEEP, GL_KEEP, -1 };
  {
    const GLenum names[7] = { GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK,
      GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS,
      GL_STENCIL_WRITEMASK };
    for (int i = 0; i < 7; ++i)
    {
      glGetIntegerv(names[i], &stencil[i]);
    }
  }
  // Peeled fragments per pass (stage 0: those that passed the stencil).
  std::vector<GLuint> fragmentQueries;

  state->PushFramebufferBindings();
  this->Targets->BindResult();
  state->vtkglViewport(0, 0, width, height);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const float zero[4] = { 0, 0, 0, 0 };
  glClearBufferfv(GL_COLOR, 0, zero);
  glFinish();
  const double t0 = vtkTimerLog::GetUniversalTime();
  GLuint started = 0;
  int passes = 0;
  GLuint readBack[3] = { 0, 0, 0 };
  // The peel and cast split: a GL timestamp before the first peel and after
  // each pass's peel and cast (read after the frame; the passes already wait
  // for their counts, so the queries add no stall of their own).
  std::vector<GLuint> stamps;
  auto stamp = [&stamps]()
  {
    GLuint query = 0;
    glGenQueries(1, &query);
    glQueryCounter(query, GL_TIMESTAMP);
    stamps.push_back(query);
  };
  stamp();
  for (int pass = 0; pass<frame.MaximumPasses&& this->BoundaryFaces> 0; ++pass)
  {
    // Peel: the nearest front-facing boundary entry beyond each ray's reach.
    state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->PeelFramebuffer);
    state->vtkglDisable(GL_BLEND);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    const bool masked = pass > 0 && frame.TileSize > 0;
    if (masked)
    {
      // From the second pass on, only the tiles where a ray left the mesh in
      // the last pass (the others have no ray to start): a stencil of them.
      state->vtkglEnable(GL_STENCIL_TEST);
      state->vtkglStencilMask(0xff);
      const GLint none = 0;
      glClearBufferiv(GL_STENCIL, 0, &none);
      state->vtkglStencilFunc(GL_ALWAYS, 1, 0xff);
      state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      cache->ReadyShaderProgram(mask);
      mask->SetUniformi("havsPass", pass + 1);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, this->Buffers[PeelTileBuffer]);
      glBindVertexArray(this->TileArray);
      glDrawArraysInstanced(GL_TRIANGLES, 0, 6, tiles);
      glBindVertexArray(0);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, this->Buffers[TileBuffer]);
      state->vtkglStencilFunc(GL_EQUAL, 1, 0xff);
      state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      state->vtkglStencilMask(0);
    }
    else
    {
      state->vtkglDisable(GL_STENCIL_TEST);
    }
    cache->ReadyShaderProgram(peel);
    peel->SetUniformi("havsPass", pass + 1);
    state->vtkglEnable(GL_CULL_FACE);
    state->vtkglCullFace(GL_BACK);
    glFrontFace(view.FlipFacing ? GL_CW : GL_CCW);
    for (int stage = 0; stage < 2; ++stage)
    {
      peel->SetUniformi("havsPeelStage", stage);
      if (stage == 0)
      {
        GLuint query = 0;
        glGenQueries(1, &query);
        glBeginQuery(GL_SAMPLES_PASSED, query);
        fragmentQueries.push_back(query);
      }
      state->vtkglEnable(GL_CULL_FACE);
      glBindVertexArray(this->VertexArray);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, this->Buffers[FaceCellBuffer]);
      glDrawElements(GL_TRIANGLES, 3 * this->BoundaryFaces, GL_UNSIGNED_INT, nullptr);
      if (pass == 0 && sectionTriangles > 0)
      {
        // The camera inside: the rays start on the near plane's section
        // (either facing), nearer than any boundary face behind it.
        state->vtkglDisable(GL_CULL_FACE);
        glBindVertexArray(this->SectionArray);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, this->SectionBuffers[1]);
        glDrawArrays(GL_TRIANGLES, 0, 3 * sectionTriangles);
      }
      if (stage == 0)
      {
        glEndQuery(GL_SAMPLES_PASSED);
      }
      glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    glBindVertexArray(0);
    glFrontFace(GL_CCW);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDisable(GL_STENCIL_TEST);
    this->Targets->BindResult();
    stamp();
    // Cast: walk the rays from their entries, the pass's colour under the result.
    cache->ReadyShaderProgram(cast);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    state->vtkglEnable(GL_BLEND);
    if (frame.Blend == vtkHAVSRayCastMapper::COMPOSITE_BLEND)
    {
      // Front to back: this pass goes under the earlier ones (premultiplied).
      state->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
    }
    else
    {
      // Order-independent: the largest (of s, or of 1 - s), or the sum.
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
      state->vtkglBlendEquation(
        frame.Blend == vtkHAVSRayCastMapper::ADDITIVE_BLEND ? GL_FUNC_ADD : GL_MAX);
    }
    // (Only the tiles where this pass's peeling found entries.)
    cast->SetUniformi("havsPass", pass + 1);
    glBindVertexArray(this->TileArray);
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, tiles);
    glBindVertexArray(0);
    stamp();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
      GL_BUFFER_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[CountBuffer]);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(readBack), readBack);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    if (readBack[0] == started)
    {
      break; // this pass started no ray: every ray is done
    }
    started = readBack[0];
    ++passes;
  }
  glFinish();
  counts->Seconds = vtkTimerLog::GetUniversalTime() - t0;
  if (stamps.size() >= 3)
  {
    // stamps: start, then per pass (peeled, cast).
    std::vector<GLuint64> ns(stamps.size(), 0);
    for (size_t i = 0; i < stamps.size(); ++i)
    {
      glGetQueryObjectui64v(stamps[i], GL_QUERY_RESULT, &ns[i]);
    }
    double peel = 0.0, castTime = 0.0;
    for (size_t i = 1; i + 1 < ns.size(); i += 2)
    {
      peel += 1e-9 * static_cast<double>(ns[i] - ns[i - 1]);
      castTime += 1e-9 * static_cast<double>(ns[i + 1] - ns[i]);
    }
    counts->PeelSeconds = peel;
    counts->CastSeconds = castTime;
  }
  if (!stamps.empty())
  {
    glDeleteQueries(static_cast<GLsizei>(stamps.size()), stamps.data());
  }
  counts->PeelFragments.clear();
  for (GLuint query : fragmentQueries)
  {
    GLuint64 samples = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
    counts->PeelFragments.push_back(static_cast<long long>(samples));
  }
  if (!fragmentQueries.empty())
  {
    glDeleteQueries(static_cast<GLsizei>(fragmentQueries.size()), fragmentQueries.data());
  }
  state->vtkglStencilFunc(stencil[0], stencil[1], static_cast<GLuint>(stencil[2]));
  state->vtkglStencilOp(stencil[3], stencil[4], stencil[5]);
  state->vtkglStencilMask(static_cast<GLuint>(stencil[6]));
  counts->Passes = passes;
  counts->Rays = readBack[0];
  counts->Cells = readBack[1];
  counts->FoldReentries = readBack[2];
  {
    std::vector<GLuint> last(static_cast<size_t>(tiles), 0u);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[TileBuffer]);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, last.size() * sizeof(GLuint), last.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    counts->TileGrid[0] = tileCount[0];
    counts->TileGrid[1] = tileCount[1];
    counts->TilePasses.assign(last.begin(), last.end());
  }
  state->vtkglDisable(GL_BLEND);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  const bool resolved =
    vtkHAVSExtremumPass::ResolveBlend(window, this->Targets, this->GLTable, frame.Blend);
  for (GLuint unit = 0; unit < 3; ++unit)
  {
    glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
  }
  return this->Targets->EndFrame(resolved, frame.KeepResult, { cellOptics, additive, table, depth },
    view.OriginX, view.OriginY, this);
}

//------------------------------------------------------------------------------
const std::vector<float>* vtkOpenGLHAVSRayCastMapper::GetKeptResult(int size[2])
{
  return this->Targets->GetKeptResult(size);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::ReleaseGraphicsResources(vtkWindow* window)
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
    glDeleteVertexArrays(1, &this->TileArray);
    glDeleteBuffers(NumberOfBuffers, this->Buffers);
    this->VertexArray = this->TileArray = 0;
    std::fill(this->Buffers, this->Buffers + NumberOfBuffers, 0u);
  }
  if (this->SectionArray)
  {
    glDeleteVertexArrays(1, &this->SectionArray);
    glDeleteBuffers(2, this->SectionBuffers);
    this->SectionArray = 0;
    this->SectionBuffers[0] = this->SectionBuffers[1] = 0;
    this->SectionTriangles = 0;
  }
  this->UploadedSection = 0;
  this->ReleaseImages();
  home->RemoveObserver(this->WindowDeleteObserver);
  this->Window = nullptr;
  this->UploadedMesh = this->UploadedTable = 0;
  this->BoundaryFaces = this->Tetrahedra = 0;
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Window: " << this->Window << "\n";
}
