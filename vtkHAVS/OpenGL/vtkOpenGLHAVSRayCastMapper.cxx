/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSRayCastMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkOpenGLHAVSRayCastMapper.h"

#include "vtkHAVSCellGeometry.h"
#include "vtkHAVSExtremumPass.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSFrameRequest.h"
#include "vtkHAVSGLFrameCapture.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLMapperResources.h"
#include "vtkHAVSGLObjects.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSRayCastMesh.h"
#include "vtkHAVSShaders.h"
#include "vtkHAVSViewFrame.h"

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
#include <memory>
#include <sstream>
#include <string>
#include <vector>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkOpenGLHAVSRayCastMapper);

namespace
{
/// Image units of the ray-casting shaders (vtkHAVSRayCastPeelFS/FS.glsl).
enum ImageUnit : GLuint
{
  EntryKeyUnit = 0,  // the nearest entry's depth key found by the peel
  EntryCellUnit = 1, // its cell
  RayStateUnit = 2,  // how far the ray got, its opacity
  NumberOfImageUnits = 3
};
/// Storage-buffer bindings of the ray-casting shaders.
enum StorageBinding : GLuint
{
  FaceCellBinding = 5,  // the cell of each boundary face (or section triangle)
  NeighbourBinding = 6, // each cell's face neighbours
  CountBinding = 7,     // rays started, cells crossed, fold re-entries
  TileBinding = 8,      // per tile, the last pass that started a ray there
  PeelTileBinding = 9   // per tile, whether the next peel draws it
};
/// The counters the cast adds to (rays started, cells crossed, fold re-entries).
constexpr int NumberOfCounts = 3;
/// The peel's depth tolerance (in the key's units) between a ray's reach and the next entry.
constexpr float PeelTolerance = 1.0e-5f;
/// Segments longer than this contribute nothing: off (the rays know the mesh's gaps).
constexpr float NoGapLength = 3.0e38f;
/// A ray's walk stops after the mesh's cell count plus this many steps (a broken walk ends).
constexpr int ExtraSteps = 16;
/// Vertices of one tile (two triangles), drawn instanced per tile.
constexpr GLsizei TileVertices = 6;
}

/// The mapper's own GPU objects.
struct vtkOpenGLHAVSRayCastMapper::GLObjects : vtkHAVSGLOwnObjects
{
  vtkHAVSGLVertexArray Boundary; // the points, the boundary faces
  vtkHAVSGLVertexArray Tiles;    // no attributes: the tiles' corners come from their ids
  vtkHAVSGLBuffer Points, Faces, FaceCells, Neighbours, Counts, TilePasses, PeelTiles;
  vtkHAVSGLCellRecords Records; // the cells' planes and fields
  vtkHAVSGLImage EntryKey, EntryCell, RayState;
  vtkHAVSGLStencilTarget PeelTarget; // a stencil only: the tiles a pass peels
  int BoundaryFaces = 0;
  int Tetrahedra = 0;

  void Release(vtkOpenGLRenderWindow*) override
  {
    this->Records.Release();
    for (vtkHAVSGLBuffer* b : { &this->Points, &this->Faces, &this->FaceCells, &this->Neighbours,
           &this->Counts, &this->TilePasses, &this->PeelTiles })
    {
      b->Release();
    }
    this->Boundary.Release();
    this->Tiles.Release();
    for (vtkHAVSGLImage* i : { &this->EntryKey, &this->EntryCell, &this->RayState })
    {
      i->Release();
    }
    this->PeelTarget.Release();
    this->BoundaryFaces = this->Tetrahedra = 0;
  }
};

//------------------------------------------------------------------------------
vtkOpenGLHAVSRayCastMapper::vtkOpenGLHAVSRayCastMapper()
{
  this->GL = this->Resources->Own(std::make_unique<GLObjects>());
  this->SetGraphics(this->Resources);
}

vtkOpenGLHAVSRayCastMapper::~vtkOpenGLHAVSRayCastMapper() = default;

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::Upload(const RayFrame& frame)
{
  GLObjects& gl = *this->GL;
  const vtkMTimeType version = frame.MeshVersion;
  if (gl.Points.Update(GL_ARRAY_BUFFER, frame.Mesh->GetPoints(), version))
  {
    const vtkHAVSRayCastMesh& mesh = *frame.RayMesh;
    if (mesh.GetCells().empty() && mesh.GetNumberOfTetrahedra() > 0 && frame.RestoreCells)
    {
      frame.RestoreCells(); // (freed after the last upload)
    }
    gl.Faces.Update(GL_ELEMENT_ARRAY_BUFFER, mesh.GetBoundaryFaces(), version);
    gl.FaceCells.Update(GL_SHADER_STORAGE_BUFFER, mesh.GetBoundaryCells(), version);
    gl.Records.Update(mesh.GetCells(), static_cast<size_t>(this->GetLargestGPUBuffer()), version);
    gl.Neighbours.Update(GL_SHADER_STORAGE_BUFFER, mesh.GetNeighbours(), version);
    gl.Counts.Update(GL_SHADER_STORAGE_BUFFER, nullptr, NumberOfCounts * sizeof(uint32_t), version);
    gl.Boundary.SetBuffers(gl.Points, &gl.Faces);
    gl.BoundaryFaces = static_cast<int>(mesh.GetNumberOfBoundaryFaces());
    gl.Tetrahedra = static_cast<int>(mesh.GetNumberOfTetrahedra());
  }
  this->Resources->GetTable()->Update(frame.Table, frame.TableVersion);
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSRayCastMapper::MakePrograms(
  vtkOpenGLRenderWindow* window, const RayFrame& frame, Programs& programs, bool isoShade)
{
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  programs.Peel = cache->ReadyShaderProgram(vtkHAVSShaders::CellProjectionVertexShader().c_str(),
    vtkHAVSShaders::RayCastPeelShader().c_str(), "");
  programs.Cast = programs.Peel && programs.Peel->GetCompiled()
    ? cache->ReadyShaderProgram(vtkHAVSShaders::RayCastTileVertexShader().c_str(),
        vtkHAVSShaders::RayCastShader(frame.Opaque, frame.Blend,
          this->Resources->GetTable()->HasCellOptics(), this->GL->Records.GetBufferCount(),
          this->GetFrameIsoSurfaces().ShaderMode(this->GetBlendMode()), isoShade)
          .c_str(),
        "")
    : nullptr;
  // The tiles a peeling pass draws (a stencil of them): the tile vertex
  // shader with the trivial fragment shader (the peel's framebuffer has no
  // colour attachment: only the stencil is written).
  programs.Mask = programs.Cast && programs.Cast->GetCompiled()
    ? cache->ReadyShaderProgram(vtkHAVSShaders::RayCastTileVertexShader().c_str(),
        vtkHAVSShaders::TrivialShader().c_str(), "")
    : nullptr;
  if (!programs.Cast || !programs.Cast->GetCompiled() || !programs.Mask ||
    !programs.Mask->GetCompiled())
  {
    vtkErrorMacro("The ray-casting shaders could not be built; see the shader log above.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::SetUniforms(vtkOpenGLRenderWindow* window,
  const Programs& programs, const RayFrame& frame, const TileGrid& grid)
{
  const vtkHAVSViewFrame& view = *frame.View;
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  // What the peel and the cast both read (the view, the planes).
  for (vtkShaderProgram* program : { programs.Peel, programs.Cast })
  {
    cache->ReadyShaderProgram(program);
    vtkHAVSGLMapperResources::SetViewUniforms(
      program, view, frame.Planes, frame.Mesh->GetShift(), program == programs.Cast);
  }
  const float viewport[2] = { static_cast<float>(view.Width), static_cast<float>(view.Height) };
  cache->ReadyShaderProgram(programs.Mask);
  programs.Mask->SetUniform2f("havsViewportSize", viewport);
  for (vtkShaderProgram* program : { programs.Peel, programs.Cast, programs.Mask })
  {
    cache->ReadyShaderProgram(program);
    program->SetUniform2i("havsTileCount", grid.Count);
    program->SetUniformi("havsTileSize", grid.Size);
  }
  // The peel's own.
  float m[16];
  cache->ReadyShaderProgram(programs.Peel);
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToClip, m);
  programs.Peel->SetUniformMatrix4x4("havsMCDC", m);
  programs.Peel->SetUniformf("havsPeelTolerance", PeelTolerance);
  // The cast's own: the table, the opaque depth, the walk.
  vtkShaderProgram* cast = programs.Cast;
  cache->ReadyShaderProgram(cast);
  this->Resources->SetTextureUniforms(cast);
  cast->SetUniformf("havsTerminationOpacity", frame.TerminationOpacity);
  cast->SetUniformf("havsGapLength", NoGapLength);
  cast->SetUniformi("havsMaxSteps", this->GL->Tetrahedra + ExtraSteps);
  cast->SetUniformi("havsFolds", frame.FoldReentries ? 1 : 0);
  this->GL->Records.SetUniforms(cast);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::ClearRays(const TileGrid& grid, int width, int height)
{
  GLObjects& gl = *this->GL;
  // Per tile: no pass yet.
  const std::vector<GLuint> none(static_cast<size_t>(grid.Tiles), 0u);
  gl.TilePasses.Update(GL_SHADER_STORAGE_BUFFER, none, 0, GL_STREAM_DRAW);
  gl.PeelTiles.Update(GL_SHADER_STORAGE_BUFFER, none, 0, GL_STREAM_DRAW);
  // Per drawn pixel (the images' lower left width x height): no entry yet,
  // the ray has reached nothing, opacity 0.
  const GLuint noKey = 0xffffffffu, noCell = 0;
  const float fresh[4] = { -3.0e38f, 0.0f, -3.0e38f, 0.0f };
  gl.EntryKey.Clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &noKey, width, height);
  gl.EntryCell.Clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &noCell, width, height);
  gl.RayState.Clear(GL_RGBA, GL_FLOAT, fresh, width, height);
  gl.EntryKey.BindImage(EntryKeyUnit);
  gl.EntryCell.BindImage(EntryCellUnit);
  gl.RayState.BindImage(RayStateUnit);
  const GLuint zeroCounts[NumberOfCounts] = { 0, 0, 0 };
  gl.Counts.Write(0, zeroCounts, sizeof(zeroCounts));
  gl.Records.Bind();
  gl.FaceCells.BindBase(GL_SHADER_STORAGE_BUFFER, FaceCellBinding);
  gl.Neighbours.BindBase(GL_SHADER_STORAGE_BUFFER, NeighbourBinding);
  gl.Counts.BindBase(GL_SHADER_STORAGE_BUFFER, CountBinding);
  gl.TilePasses.BindBase(GL_SHADER_STORAGE_BUFFER, TileBinding);
  gl.PeelTiles.BindBase(GL_SHADER_STORAGE_BUFFER, PeelTileBinding);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::Peel(vtkOpenGLRenderWindow* window, const Programs& programs,
  const RayFrame& frame, const TileGrid& grid, int pass, int sectionTriangles,
  vtkHAVSGLQueries& queries)
{
  GLObjects& gl = *this->GL;
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, gl.PeelTarget.GetFramebuffer());
  state->vtkglDisable(GL_BLEND);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  if (pass > 0 && frame.TileSize > 0)
  {
    // From the second pass on, only the tiles where a ray left the mesh in
    // the last pass (the others have no ray to start): a stencil of them.
    state->vtkglEnable(GL_STENCIL_TEST);
    state->vtkglStencilMask(0xff);
    const GLint none = 0;
    glClearBufferiv(GL_STENCIL, 0, &none);
    state->vtkglStencilFunc(GL_ALWAYS, 1, 0xff);
    state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    cache->ReadyShaderProgram(programs.Mask);
    programs.Mask->SetUniformi("havsPass", pass + 1);
    gl.PeelTiles.BindBase(GL_SHADER_STORAGE_BUFFER, TileBinding);
    gl.Tiles.Bind();
    glDrawArraysInstanced(GL_TRIANGLES, 0, TileVertices, grid.Tiles);
    vtkHAVSGLVertexArray::Unbind();
    gl.TilePasses.BindBase(GL_SHADER_STORAGE_BUFFER, TileBinding);
    state->vtkglStencilFunc(GL_EQUAL, 1, 0xff);
    state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    state->vtkglStencilMask(0);
  }
  else
  {
    state->vtkglDisable(GL_STENCIL_TEST);
  }
  vtkShaderProgram* peel = programs.Peel;
  cache->ReadyShaderProgram(peel);
  peel->SetUniformi("havsPass", pass + 1);
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_BACK);
  glFrontFace(frame.View->FlipFacing ? GL_CW : GL_CCW);
  // Two stages: the nearest entry's key, then its cell (stage 0 counts the
  // fragments that passed the stencil).
  for (int stage = 0; stage < 2; ++stage)
  {
    peel->SetUniformi("havsPeelStage", stage);
    if (stage == 0)
    {
      queries.BeginSamples();
    }
    state->vtkglEnable(GL_CULL_FACE);
    gl.Boundary.Bind();
    gl.FaceCells.BindBase(GL_SHADER_STORAGE_BUFFER, FaceCellBinding);
    glDrawElements(GL_TRIANGLES, 3 * gl.BoundaryFaces, GL_UNSIGNED_INT, nullptr);
    if (pass == 0 && sectionTriangles > 0)
    {
      // The camera inside: the rays start on the near plane's section
      // (either facing), nearer than any boundary face behind it.
      state->vtkglDisable(GL_CULL_FACE);
      this->Resources->DrawSection(FaceCellBinding);
    }
    if (stage == 0)
    {
      queries.EndSamples();
    }
    // The entry images, and the tiles' storage the cast's vertex shader
    // reads (written by stage 1): both need their barrier.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  }
  vtkHAVSGLVertexArray::Unbind();
  glFrontFace(GL_CCW);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_STENCIL_TEST);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::Cast(vtkOpenGLRenderWindow* window, const Programs& programs,
  const RayFrame& frame, const TileGrid& grid, int pass)
{
  this->Resources->GetTargets()->BindResult();
  window->GetShaderCache()->ReadyShaderProgram(programs.Cast);
  window->GetState()->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // This pass's colour goes under the earlier passes' (or order-independently).
  this->Resources->SetBlending(frame.Blend);
  // (Only the tiles where this pass's peeling found entries.)
  programs.Cast->SetUniformi("havsPass", pass + 1);
  this->GL->Tiles.Bind();
  glDrawArraysInstanced(GL_TRIANGLES, 0, TileVertices, grid.Tiles);
  vtkHAVSGLVertexArray::Unbind();
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::ReadCounts(
  const TileGrid& grid, vtkHAVSGLQueries& queries, RayCounts* counts)
{
  // The GPU times: stamps at the start, then per pass after the peel and the cast.
  const std::vector<uint64_t> ns = queries.Timestamps();
  if (ns.size() >= 3)
  {
    double peel = 0.0, cast = 0.0;
    for (size_t i = 1; i + 1 < ns.size(); i += 2)
    {
      peel += 1e-9 * static_cast<double>(ns[i] - ns[i - 1]);
      cast += 1e-9 * static_cast<double>(ns[i + 1] - ns[i]);
    }
    counts->PeelSeconds = peel;
    counts->CastSeconds = cast;
  }
  counts->PeelFragments.clear();
  for (uint64_t samples : queries.Samples())
  {
    counts->PeelFragments.push_back(static_cast<long long>(samples));
  }
  std::vector<GLuint> last(static_cast<size_t>(grid.Tiles), 0u);
  this->GL->TilePasses.Read(0, last.data(), last.size() * sizeof(GLuint));
  counts->TileGrid[0] = grid.Count[0];
  counts->TileGrid[1] = grid.Count[1];
  counts->TilePasses.assign(last.begin(), last.end());
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSRayCastMapper::DrawRays(
  vtkRenderer* renderer, const RayFrame& frame, RayCounts* counts)
{
  // 1. The window, the targets, the section; what changed uploaded; the images at the view's size.
  const vtkHAVSViewFrame& view = *frame.View;
  vtkOpenGLRenderWindow* window =
    this->Resources->BeginFrame(renderer, this, "vtkHAVSRayCastMapper", "storage buffers, images",
      view, frame.Opaque, *frame.Planes, this->GetLastEdgeUpsampling() ? frame.Mesh : nullptr);
  if (!window)
  {
    return false;
  }
  this->Upload(frame);
  GLObjects& gl = *this->GL;
  const int width = view.Width, height = view.Height;
  const int sectionTriangles = this->Resources->GetSectionTriangles();
  // The images at the viewport's size, drawn in their lower left corner: a
  // level of detail that changes the drawn size reallocates nothing.
  gl.EntryKey.Resize(GL_R32UI, view.FullWidth, view.FullHeight);
  gl.EntryCell.Resize(GL_R32UI, view.FullWidth, view.FullHeight);
  gl.RayState.Resize(GL_RGBA32F, view.FullWidth, view.FullHeight);
  gl.PeelTarget.Resize(view.FullWidth, view.FullHeight);

  // 2. The programs, the textures, the uniforms; the screen tiles (without
  // them, one tile covering the viewport).
  Programs programs;
  const bool isoShade =
    this->Resources->BindIsoShading(this, static_cast<size_t>(this->GetLargestGPUBuffer()));
  if (!this->MakePrograms(window, frame, programs, isoShade))
  {
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  vtkHAVSGLScopedPassState passState(state);
  this->Resources->ActivateTextures();
  TileGrid grid;
  grid.Size = frame.TileSize > 0 ? frame.TileSize : std::max(width, height);
  grid.Count[0] = (width + grid.Size - 1) / grid.Size;
  grid.Count[1] = (height + grid.Size - 1) / grid.Size;
  grid.Tiles = grid.Count[0] * grid.Count[1];
  this->SetUniforms(window, programs, frame, grid);

  // 3. Every ray unstarted, the result cleared. The stencil state VTK's state
  // holds is put back after the frame.
  this->ClearRays(grid, width, height);
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
  state->PushFramebufferBindings();
  this->Resources->GetTargets()->BindResult();
  state->vtkglViewport(0, 0, width, height);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const float zero[4] = { 0, 0, 0, 0 };
  glClearBufferfv(GL_COLOR, 0, zero);
  glFinish();

  // 4. The passes: peel the entries, cast from them; until a pass starts no
  // ray (GL timestamps around each step, read after the frame: the passes
  // already wait for their counts, so the queries add no stall of their own).
  const double t0 = vtkTimerLog::GetUniversalTime();
  vtkHAVSGLQueries queries;
  GLuint started = 0;
  int passes = 0;
  GLuint readBack[NumberOfCounts] = { 0, 0, 0 };
  queries.Timestamp();
  for (int pass = 0; pass < frame.MaximumPasses && gl.BoundaryFaces > 0; ++pass)
  {
    this->Peel(window, programs, frame, grid, pass, sectionTriangles, queries);
    queries.Timestamp();
    this->Cast(window, programs, frame, grid, pass);
    queries.Timestamp();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
      GL_BUFFER_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    gl.Counts.Read(0, readBack, sizeof(readBack));
    if (readBack[0] == started)
    {
      break; // this pass started no ray: every ray is done
    }
    started = readBack[0];
    ++passes;
  }
  glFinish();
  counts->Seconds = vtkTimerLog::GetUniversalTime() - t0;

  // 5. The counts, and the state put back.
  this->ReadCounts(grid, queries, counts);
  queries.Release();
  counts->Passes = passes;
  counts->Rays = readBack[0];
  counts->Cells = readBack[1];
  counts->FoldReentries = readBack[2];
  state->vtkglStencilFunc(stencil[0], stencil[1], static_cast<GLuint>(stencil[2]));
  state->vtkglStencilOp(stencil[3], stencil[4], stencil[5]);
  state->vtkglStencilMask(static_cast<GLuint>(stencil[6]));
  for (GLuint unit = 0; unit < NumberOfImageUnits; ++unit)
  {
    vtkHAVSGLImage::UnbindImage(unit);
  }

  // 6. The frame case (a benchmark aid), the extremum blends' resolve, the
  // result composited into the window.
  if (this->GetCaptureDirectory())
  {
    std::string error;
    this->LastCaptureSucceeded =
      this->Capture(this->GetCaptureDirectory(), frame, programs, grid, *counts, error);
    if (!this->LastCaptureSucceeded)
    {
      vtkErrorMacro("No frame capture: " << error << ".");
    }
    this->SetCaptureDirectory(nullptr);
  }
  return this->Resources->EndFrame(frame.Blend, frame.KeepResult, view, this);
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSRayCastMapper::Capture(const std::string& directory, const RayFrame& frame,
  const Programs& programs, const TileGrid& grid, const RayCounts& counts, std::string& error)
{
  using CaseFiles = vtkHAVSGLFrameCapture;
  GLObjects& gl = *this->GL;
  std::string header;
  if (!this->Resources->BeginCapture(directory, "raycast", frame.Blend, frame.Opaque, frame.Planes,
        *frame.View, gl.Records, header, error))
  {
    return false;
  }
  // The cell records were freed after the last upload: made again from the
  // mesh (the same vtkHAVSCellGeometry::Compute as uploaded; freed again
  // after the frame by vtkHAVSRayCastMapper::RenderView).
  const vtkHAVSRayCastMesh& mesh = *frame.RayMesh;
  if (mesh.GetCells().empty() && mesh.GetNumberOfTetrahedra() > 0 && frame.RestoreCells)
  {
    frame.RestoreCells();
  }
  if (mesh.GetCells().size() != vtkHAVSCellGeometry::FloatsPerCell * mesh.GetNumberOfTetrahedra())
  {
    error = "the cell records could not be made again";
    return false;
  }
  const size_t largest = static_cast<size_t>(this->GetLargestGPUBuffer());
  std::ostringstream text;
  text.precision(9);
  text << header << "cells " << mesh.GetNumberOfTetrahedra() << "\npoints "
       << frame.Mesh->GetPoints().size() / 3 << "\nboundary_faces "
       << mesh.GetNumberOfBoundaryFaces() << "\nflip_facing " << (frame.View->FlipFacing ? 1 : 0)
       << "\ntile_size " << frame.TileSize << "\ntile_grid " << grid.Count[0] << " "
       << grid.Count[1] << "\nmaximum_passes " << frame.MaximumPasses << "\nfold_reentries "
       << (frame.FoldReentries ? 1 : 0) << "\ntermination_opacity " << frame.TerminationOpacity
       << "\nlargest_gpu_buffer " << largest << "\nmapper_passes " << counts.Passes
       << "\nmapper_rays " << counts.Rays << "\nmapper_cells_crossed " << counts.Cells
       << "\nmapper_fold_reentries " << counts.FoldReentries << "\n"
       << CaseFiles::UniformLines("peel", programs.Peel->GetHandle())
       << CaseFiles::UniformLines("cast", programs.Cast->GetHandle())
       << CaseFiles::UniformLines("mask", programs.Mask->GetHandle());

  using Shaders = vtkHAVSShaders;
  const std::string dir = directory + "/";
  const bool ok = CaseFiles::WriteText(dir + "case.txt", text.str()) &&
    CaseFiles::WriteArray(dir + "points.f32", frame.Mesh->GetPoints()) &&
    CaseFiles::WriteArray(dir + "boundary_faces.u32", mesh.GetBoundaryFaces()) &&
    CaseFiles::WriteArray(dir + "boundary_cells.u32", mesh.GetBoundaryCells()) &&
    CaseFiles::WriteArray(dir + "neighbours.i32", mesh.GetNeighbours()) &&
    CaseFiles::WriteArray(dir + "cells.f32", mesh.GetCells()) &&
    CaseFiles::WriteText(dir + "peel.vert", Shaders::CellProjectionVertexShader()) &&
    CaseFiles::WriteText(dir + "peel.frag", Shaders::RayCastPeelShader()) &&
    CaseFiles::WriteText(dir + "tile.vert", Shaders::RayCastTileVertexShader()) &&
    CaseFiles::WriteText(dir + "cast.frag",
      Shaders::RayCastShader(frame.Opaque, frame.Blend, false, gl.Records.GetBufferCount())) &&
    CaseFiles::WriteText(dir + "trivial.frag", Shaders::TrivialShader());
  if (!ok)
  {
    error = "cannot write the case into " + directory;
  }
  return ok;
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSRayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Boundary faces: " << this->GL->BoundaryFaces
     << ", tetrahedra: " << this->GL->Tetrahedra << "\n";
  this->Resources->PrintSelf(os, indent.GetNextIndent());
}

VTK_ABI_NAMESPACE_END
