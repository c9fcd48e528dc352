/*=========================================================================

  Project:   vtkHAVS
  Module:    havsGPURayCast.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_gpu_bench's ray-caster part: vtkOpenGLHAVSRayCastMapper::DrawRays
// replayed from a frame case with no VTK. Per pixel three images (the peel's
// nearest entry key and its cell, R32UI; the ray's state, RGBA32F) at image
// units 0, 1, 2; storage buffers at 5 (the cell behind each boundary face),
// 6 (the neighbours), 7 (the counts: rays started, cells crossed, fold
// re-entries), 8 (per tile, the last pass that started a ray there), 9 (per
// tile, the next pass whose peel draws there); the cell records at 4 (and 10,
// 11, 12 where they take several buffers, vtkHAVSGLCellRecords). Each pass:
// from the second on (with tiles) a stencil of the tiles to peel (the tile
// vertex shader with the trivial fragment shader), the front-facing boundary
// faces drawn twice (stage 0: the nearest entry's key, stage 1: its cell),
// then the cast over the tiles where the peel found entries, blended under
// the float result (ONE_MINUS_DST_ALPHA, ONE); passes repeat until one
// starts no ray (the counter read back per pass) or the case's maximum.
//
// The control (--control): each cell's neighbours rotated by one face (the
// mapper's own negative control, vtkHAVSRayCastMapper::
// SetBrokenNeighboursForTesting): the walk leaves every cell into a wrong one.
#include "havsGPUBench.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>

namespace havsgpu
{
namespace
{
/// Image units and storage bindings of the ray-casting shaders (vtkOpenGLHAVSRayCastMapper.cxx).
constexpr GLuint EntryKeyUnit = 0, EntryCellUnit = 1, RayStateUnit = 2;
constexpr GLuint FaceCellBinding = 5, NeighbourBinding = 6, CountBinding = 7, TileBinding = 8,
                 PeelTileBinding = 9;
constexpr GLsizei TileVertices = 6;

/// What the last frame drawn counted (reported with the image).
struct Counts
{
  int Passes = 0;
  GLuint Values[3] = { 0, 0, 0 }; // rays started, cells crossed, fold re-entries
};
}

bool MakeRayCastPaths(Case& c, const Options& o, const Device&, Paths& paths)
{
  const bool rays = o.Wanted("rays"), raster = o.Wanted("raster");
  if (!rays && !raster)
  {
    return true;
  }
  // What the GPU must offer: storage blocks in the peel's vertex shader (the
  // cell projection's, which declares four) and the cast's fragment shader,
  // three images in a fragment shader.
  GLint vertexBlocks = 0, fragmentBlocks = 0, fragmentImages = 0;
  gl.GetIntegerv(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, &vertexBlocks);
  gl.GetIntegerv(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, &fragmentBlocks);
  gl.GetIntegerv(GL_MAX_FRAGMENT_IMAGE_UNIFORMS, &fragmentImages);
  const int recordBuffersKey = std::max(1, c.Int("record_buffers"));
  if (vertexBlocks < 4 || fragmentBlocks < 3 + recordBuffersKey || fragmentImages < 3)
  {
    paths.NotRun.push_back("ray caster: the GPU has " + std::to_string(vertexBlocks) +
      " vertex and " + std::to_string(fragmentBlocks) + " fragment storage blocks, " +
      std::to_string(fragmentImages) + " fragment images (needs 4, " +
      std::to_string(3 + recordBuffersKey) + ", 3)");
    return true;
  }

  // The Core arrays (vtkHAVSRayCastMesh) and their counts in case.txt.
  std::vector<float> points, cells;
  std::vector<uint32_t> faces, faceCells;
  std::vector<int32_t> neighbours;
  if (!ReadArray(c.Dir + "/points.f32", points) ||
    !ReadArray(c.Dir + "/boundary_faces.u32", faces) ||
    !ReadArray(c.Dir + "/boundary_cells.u32", faceCells) ||
    !ReadArray(c.Dir + "/neighbours.i32", neighbours) || !ReadArray(c.Dir + "/cells.f32", cells))
  {
    return false;
  }
  const size_t tetrahedra = static_cast<size_t>(c.Cells);
  const size_t boundaryFaces = faceCells.size();
  if (neighbours.size() != 4 * tetrahedra ||
    cells.size() != CellRecords::FloatsPerCell * tetrahedra || faces.size() != 3 * boundaryFaces ||
    (c.Keys.count("boundary_faces") && c.Int("boundary_faces") != static_cast<int>(boundaryFaces)))
  {
    return Fail("the ray caster's arrays do not match case.txt's counts in " + c.Dir);
  }
  if (o.Control)
  {
    // The control: each cell's neighbours rotated by one face.
    for (size_t t = 0; t < tetrahedra; ++t)
    {
      std::rotate(&neighbours[4 * t], &neighbours[4 * t] + 1, &neighbours[4 * t] + 4);
    }
  }

  // The records' split (vtkHAVSGLCellRecords), checked against the capture's.
  CellRecords records;
  if (!records.Split(c, tetrahedra, "cast.frag"))
  {
    return false;
  }

  // The tile grid (DrawRays): tile_size pixels a tile, else one tile over the viewport.
  const int tileSize = c.Int("tile_size");
  const int gridSize = tileSize > 0 ? tileSize : std::max(c.Width, c.Height);
  const int gridCount[2] = { (c.Width + gridSize - 1) / gridSize,
    (c.Height + gridSize - 1) / gridSize };
  const int tiles = gridCount[0] * gridCount[1];
  if (c.Keys.count("tile_grid"))
  {
    std::istringstream grid(c.Keys["tile_grid"]);
    int columns = 0, rows = 0;
    grid >> columns >> rows;
    if (columns != gridCount[0] || rows != gridCount[1])
    {
      return Fail("the tile grid derived from tile_size does not match case.txt's in " + c.Dir);
    }
  }
  const int maximumPasses = c.Keys.count("maximum_passes") ? c.Int("maximum_passes") : 1024;
  const bool flip = c.Int("flip_facing") != 0;
  const int width = c.Width, height = c.Height;
  auto key = [&c](const char* name) { return c.Keys.count(name) ? c.Keys[name] : "?"; };
  const std::string mapperCounts = key("mapper_passes") + " passes, " + key("mapper_rays") +
    " rays, " + key("mapper_cells_crossed") + " cells crossed, " + key("mapper_fold_reentries") +
    " fold re-entries";

  // The buffers (vtkOpenGLHAVSRayCastMapper::Upload).
  GLuint boundary = 0;
  gl.GenVertexArrays(1, &boundary);
  gl.BindVertexArray(boundary);
  Buffer(GL_ARRAY_BUFFER, points);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  Buffer(GL_ELEMENT_ARRAY_BUFFER, faces);
  gl.BindVertexArray(0);
  GLuint tileArray = 0; // no attributes: the tiles' corners come from their ids
  gl.GenVertexArrays(1, &tileArray);
  const GLsizei indexCount = static_cast<GLsizei>(faces.size());
  const GLuint faceCellBuffer = Buffer(GL_SHADER_STORAGE_BUFFER, faceCells);
  const GLuint neighbourBuffer = Buffer(GL_SHADER_STORAGE_BUFFER, neighbours);
  const GLuint countBuffer =
    Buffer(GL_SHADER_STORAGE_BUFFER, nullptr, 3 * sizeof(GLuint), GL_DYNAMIC_READ);
  const std::vector<GLuint> noPass(static_cast<size_t>(tiles), 0u);
  const GLuint tilePasses = Buffer(GL_SHADER_STORAGE_BUFFER, noPass, GL_STREAM_DRAW);
  const GLuint peelTiles = Buffer(GL_SHADER_STORAGE_BUFFER, noPass, GL_STREAM_DRAW);
  records.Upload(cells);
  std::vector<float>().swap(cells);

  // The images (immutable storage, bound only as images).
  auto image = [](GLenum format, int w, int h)
  {
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D, t);
    gl.TexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return t;
  };
  const GLuint entryKey = image(GL_R32UI, c.Width, c.Height);
  const GLuint entryCell = image(GL_R32UI, c.Width, c.Height);
  const GLuint rayState = image(GL_RGBA32F, c.Width, c.Height);

  // The peel's target: a depth-stencil renderbuffer, no colour (vtkHAVSGLStencilTarget).
  GLuint stencil = 0, peelFbo = 0;
  gl.GenRenderbuffers(1, &stencil);
  gl.BindRenderbuffer(GL_RENDERBUFFER, stencil);
  gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, c.Width, c.Height);
  gl.BindRenderbuffer(GL_RENDERBUFFER, 0);
  gl.GenFramebuffers(1, &peelFbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, peelFbo);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, stencil);
  const GLenum none = GL_NONE;
  gl.DrawBuffers(1, &none);
  if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
  {
    return Fail("the peel's stencil framebuffer is not complete");
  }
  // The float result (vtkHAVSGLFrameTargets).
  const GLuint result = FloatTexture(c.Width, c.Height);
  const GLuint resultFbo = Framebuffer({ result });
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);

  if (!TableTexture(c))
  {
    return false;
  }

  // The faces as the peel draws them: front-facing only (back faces culled).
  auto drawBoundary = [=](GLuint program)
  {
    gl.UseProgram(program);
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(GL_BACK);
    gl.FrontFace(flip ? GL_CW : GL_CCW);
    gl.BindVertexArray(boundary);
    gl.DrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
    gl.BindVertexArray(0);
    gl.FrontFace(GL_CCW);
    gl.Disable(GL_CULL_FACE);
  };

  if (rays)
  {
    Path p;
    p.Name = "ray caster (peel and cast)";
    const GLuint peel = Program(c, "peel.vert", "peel.frag", "peel");
    const GLuint cast = Program(c, "tile.vert", "cast.frag", "cast");
    const GLuint mask = Program(c, "tile.vert", "trivial.frag", "mask");
    if (!peel || !cast || !mask)
    {
      return false;
    }
    // The tiles as derived (the same as captured), the records' split; the
    // samplers the cast declares besides the table on units of their own
    // (none of them read in a composite frame without opaque geometry).
    for (GLuint program : { peel, cast, mask })
    {
      gl.UseProgram(program);
      const GLint count = gl.GetUniformLocation(program, "havsTileCount");
      if (count >= 0)
      {
        gl.Uniform2i(count, gridCount[0], gridCount[1]);
      }
      SetInt(program, "havsTileSize", gridSize);
    }
    records.SetUniforms(cast);
    ParkUnreadSamplers(cast);
    auto counts = std::make_shared<Counts>();

    // ClearRays, and the result cleared.
    p.Clear = [=]()
    {
      gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, tilePasses);
      gl.BufferData(
        GL_SHADER_STORAGE_BUFFER, noPass.size() * sizeof(GLuint), noPass.data(), GL_STREAM_DRAW);
      gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, peelTiles);
      gl.BufferData(
        GL_SHADER_STORAGE_BUFFER, noPass.size() * sizeof(GLuint), noPass.data(), GL_STREAM_DRAW);
      const GLuint noKey = 0xffffffffu, noCell = 0;
      const float fresh[4] = { -3.0e38f, 0.0f, -3.0e38f, 0.0f };
      gl.ClearTexImage(entryKey, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noKey);
      gl.ClearTexImage(entryCell, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noCell);
      gl.ClearTexImage(rayState, 0, GL_RGBA, GL_FLOAT, fresh);
      gl.BindImageTexture(EntryKeyUnit, entryKey, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
      gl.BindImageTexture(EntryCellUnit, entryCell, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
      gl.BindImageTexture(RayStateUnit, rayState, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
      const GLuint zero[3] = { 0, 0, 0 };
      gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, countBuffer);
      gl.BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(zero), zero);
      gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
      records.Bind();
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, FaceCellBinding, faceCellBuffer);
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, NeighbourBinding, neighbourBuffer);
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, CountBinding, countBuffer);
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TileBinding, tilePasses);
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PeelTileBinding, peelTiles);
      gl.ActiveTexture(GL_TEXTURE0);
      gl.Disable(GL_DEPTH_TEST);
      gl.DepthMask(GL_FALSE);
      gl.Disable(GL_BLEND);
      gl.Disable(GL_STENCIL_TEST);
      gl.Viewport(0, 0, width, height);
      ClearTarget(resultFbo);
    };

    // The passes: peel the entries, cast from them, until a pass starts no ray.
    p.Draw = [=]()
    {
      GLuint started = 0;
      GLuint readBack[3] = { 0, 0, 0 };
      int passes = 0;
      for (int pass = 0; pass < maximumPasses && boundaryFaces > 0; ++pass)
      {
        // The peel (vtkOpenGLHAVSRayCastMapper::Peel).
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, peelFbo);
        gl.Disable(GL_BLEND);
        gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        if (pass > 0 && tileSize > 0)
        {
          // Only the tiles where a ray left the mesh in the last pass.
          gl.Enable(GL_STENCIL_TEST);
          gl.StencilMask(0xff);
          const GLint noStencil = 0;
          gl.ClearBufferiv(GL_STENCIL, 0, &noStencil);
          gl.StencilFunc(GL_ALWAYS, 1, 0xff);
          gl.StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
          gl.UseProgram(mask);
          gl.Uniform1i(gl.GetUniformLocation(mask, "havsPass"), pass + 1);
          gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TileBinding, peelTiles);
          gl.BindVertexArray(tileArray);
          gl.DrawArraysInstanced(GL_TRIANGLES, 0, TileVertices, tiles);
          gl.BindVertexArray(0);
          gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TileBinding, tilePasses);
          gl.StencilFunc(GL_EQUAL, 1, 0xff);
          gl.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
          gl.StencilMask(0);
        }
        else
        {
          gl.Disable(GL_STENCIL_TEST);
        }
        gl.UseProgram(peel);
        gl.Uniform1i(gl.GetUniformLocation(peel, "havsPass"), pass + 1);
        for (int stage = 0; stage < 2; ++stage)
        {
          gl.Uniform1i(gl.GetUniformLocation(peel, "havsPeelStage"), stage);
          gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, FaceCellBinding, faceCellBuffer);
          drawBoundary(peel);
          gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        }
        gl.Disable(GL_STENCIL_TEST);

        // The cast (vtkOpenGLHAVSRayCastMapper::Cast): under the result, front to back.
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resultFbo);
        gl.UseProgram(cast);
        gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        SetCompositeBlending();
        gl.Uniform1i(gl.GetUniformLocation(cast, "havsPass"), pass + 1);
        gl.BindVertexArray(tileArray);
        gl.DrawArraysInstanced(GL_TRIANGLES, 0, TileVertices, tiles);
        gl.BindVertexArray(0);

        gl.MemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
          GL_BUFFER_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
        gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, countBuffer);
        gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(readBack), readBack);
        gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
        if (readBack[0] == started)
        {
          break; // this pass started no ray: every ray is done
        }
        started = readBack[0];
        ++passes;
      }
      gl.Disable(GL_BLEND);
      counts->Passes = passes;
      std::copy_n(readBack, 3, counts->Values);
    };
    p.Resolve = []() {};
    p.Image = [=]()
    {
      std::printf("ray caster: %d passes, %u rays, %u cells crossed, %u fold re-entries (the "
                  "mapper's frame: %s)\n",
        counts->Passes, counts->Values[0], counts->Values[1], counts->Values[2],
        mapperCounts.c_str());
      return ReadImage(resultFbo, width, height);
    };
    paths.Run.push_back(p);
  }

  if (raster)
  {
    // The raster bound: one draw of the front-facing boundary faces (what
    // each peel stage rasterizes) with the trivial fragment shader.
    Path p;
    p.Name = "raster bound (trivial shader)";
    const GLuint draw = Program(c, "peel.vert", "trivial.frag", "peel");
    if (!draw)
    {
      return false;
    }
    p.Clear = [=]()
    {
      gl.Disable(GL_BLEND);
      gl.Disable(GL_STENCIL_TEST);
      ClearTarget(resultFbo);
    };
    p.Draw = [=]() { drawBoundary(draw); };
    p.Resolve = []() {};
    p.RasterBound = true;
    paths.Run.push_back(p);
  }
  return true;
}
}
