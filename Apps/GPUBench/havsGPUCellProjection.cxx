/*=========================================================================

  Project:   vtkHAVS
  Module:    havsGPUCellProjection.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_gpu_bench's cell-projection part: the case's cells in the captured
// order (vtkOpenGLHAVSCellProjectionMapper::DrawCells replayed: the vertex
// shader pulls each cell's corners from the order, the tetrahedra, the
// mirrored bits and the points; one pattern of indices drawn in runs with
// the run's first corner as the base vertex; back faces culled; front-to-back
// blending of premultiplied segments into an RGBA32F result), and the same
// faces with the trivial shader (the raster bound). The control: the order
// reversed (the cells back to front) and each cell left through its farthest
// plane (havsWrongExit; back to front alone changes a thin medium's image by
// less than the bound: the blunt fin at 256²).
#include "havsGPUBench.h"

#include <algorithm>
#include <cstdlib>

namespace havsgpu
{
namespace
{
/// Storage-buffer bindings of the cell-projection shaders (vtkHAVSCellProjectionVS/FS.glsl).
constexpr GLuint OrderBinding = 5;
constexpr GLuint TetBinding = 6;
constexpr GLuint MirroredBinding = 7;
constexpr GLuint PointBinding = 8;
/// Face f of a cell, opposite its corner f (vtkOpenGLHAVSCellProjectionMapper::DrawCells).
constexpr GLuint Faces[12] = { 1, 2, 3, 2, 0, 3, 3, 0, 1, 0, 2, 1 };

long long LongKey(const Case& c, const std::string& key, long long otherwise)
{
  auto it = c.Keys.find(key);
  return it == c.Keys.end() ? otherwise : std::atoll(it->second.c_str());
}

}

bool MakeCellProjectionPaths(Case& c, const Options& o, const Device& device, Paths& paths)
{
  const bool wantCells = o.Wanted("cells"), wantRaster = o.Wanted("raster");
  if (!wantCells && !wantRaster)
  {
    return true;
  }
  // The arrays, exactly the mapper's CellFrame fields (README.md).
  std::vector<float> points, records;
  std::vector<uint32_t> tetrahedra, mirrored, order;
  if (!ReadArray(c.Dir + "/points.f32", points) ||
    !ReadArray(c.Dir + "/tetrahedra.u32", tetrahedra) ||
    !ReadArray(c.Dir + "/mirrored.u32", mirrored) || !ReadArray(c.Dir + "/cells.f32", records) ||
    !ReadArray(c.Dir + "/order.u32", order))
  {
    return false;
  }
  const size_t pointCount = points.size() / 3, tetCount = tetrahedra.size() / 4;
  if (points.size() != 3 * static_cast<size_t>(LongKey(c, "points", pointCount)) ||
    tetrahedra.size() != 4 * static_cast<size_t>(LongKey(c, "tetrahedra", tetCount)) ||
    records.size() != CellRecords::FloatsPerCell * tetCount ||
    mirrored.size() < (tetCount + 31) / 32 || order.size() != static_cast<size_t>(c.Cells))
  {
    return Fail("the arrays of " + c.Dir + " do not match case.txt's counts");
  }
  // (An id out of range would read past a buffer on the GPU.)
  if (std::any_of(order.begin(), order.end(), [&](uint32_t t) { return t >= tetCount; }) ||
    std::any_of(tetrahedra.begin(), tetrahedra.end(), [&](uint32_t p) { return p >= pointCount; }))
  {
    return Fail("order.u32 or tetrahedra.u32 of " + c.Dir + " holds an id out of range");
  }
  if (o.Control)
  {
    // The control: the cells back to front.
    std::reverse(order.begin(), order.end());
  }

  // The records' split (vtkHAVSGLCellRecords), checked against the capture's.
  CellRecords recordBuffers;
  if (!recordBuffers.Split(c, tetCount, "cellprojection.frag"))
  {
    return false;
  }

  // What the GPU must have: storage blocks in the vertex shader (GL 4.3
  // allows none there) and the fragment shader, buffers that large.
  GLint vertexBlocks = 0, fragmentBlocks = 0, bindings = 0, blockSize = 0;
  gl.GetIntegerv(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, &vertexBlocks);
  gl.GetIntegerv(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS, &fragmentBlocks);
  gl.GetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &bindings);
  gl.GetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockSize);
  const size_t perBuffer = recordBuffers.CellsPerBuffer, bufferCount = recordBuffers.Count;
  const size_t largest =
    std::max({ points.size() * sizeof(float), tetrahedra.size() * sizeof(uint32_t),
      std::min(perBuffer, tetCount) * CellRecords::FloatsPerCell * sizeof(float) });
  std::string missing;
  if (vertexBlocks < 4)
  {
    missing =
      "the vertex shader needs 4 storage blocks, the GPU has " + std::to_string(vertexBlocks);
  }
  else if (fragmentBlocks < static_cast<GLint>(2 + bufferCount))
  {
    missing = "the fragment shader needs " + std::to_string(2 + bufferCount) +
      " storage blocks, the GPU has " + std::to_string(fragmentBlocks);
  }
  else if (bindings <= static_cast<GLint>(CellRecords::Bindings[bufferCount - 1]))
  {
    missing = "binding " + std::to_string(CellRecords::Bindings[bufferCount - 1]) +
      " needs more storage-buffer bindings than the GPU's " + std::to_string(bindings);
  }
  else if (blockSize > 0 && largest > static_cast<size_t>(blockSize))
  {
    missing = "a storage buffer of " + std::to_string(largest) + " bytes exceeds the GPU's " +
      std::to_string(blockSize);
  }
  if (!missing.empty())
  {
    for (const char* name : { "cell projection", "raster bound (trivial shader)" })
    {
      paths.NotRun.push_back(std::string(name) + " (" + missing + ")");
    }
    return true;
  }

  // The buffers, as vtkOpenGLHAVSCellProjectionMapper::Upload.
  const GLuint orderBuffer = Buffer(GL_SHADER_STORAGE_BUFFER, order, GL_STREAM_DRAW);
  const GLuint tetBuffer = Buffer(GL_SHADER_STORAGE_BUFFER, tetrahedra);
  const GLuint mirroredBuffer = Buffer(GL_SHADER_STORAGE_BUFFER, mirrored);
  const GLuint pointBuffer = Buffer(GL_SHADER_STORAGE_BUFFER, points);
  recordBuffers.Upload(records);
  std::vector<float>().swap(records);

  // The pattern of indices: pattern_cells cells' faces (corner ids 4 slot +
  // k), drawn again for every run of as many cells with its first corner as
  // the base vertex; no attributes (the vertex shader pulls the corners).
  // The mapper draws runs of 2^20 cells on a GPU and smaller ones on a
  // software rasterizer (vtkHAVSGLCapabilities::FacesPerFinish): the
  // captured run length on llvmpipe, the GPU's elsewhere.
  const long long patternKey =
    device.Llvmpipe ? LongKey(c, "pattern_cells", 1LL << 20) : (1LL << 20);
  const size_t cellCount = order.size();
  const size_t patternCells = std::max<size_t>(
    1, std::min(cellCount, static_cast<size_t>(patternKey > 0 ? patternKey : (1LL << 20))));
  std::vector<GLuint> pattern(12 * patternCells);
  for (size_t k = 0; k < patternCells; ++k)
  {
    for (int i = 0; i < 12; ++i)
    {
      pattern[12 * k + i] = static_cast<GLuint>(4 * k) + Faces[i];
    }
  }
  GLuint vao = 0;
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  Buffer(GL_ELEMENT_ARRAY_BUFFER, pattern);
  gl.BindVertexArray(0);
  std::vector<GLuint>().swap(pattern);

  const GLuint result = FloatTexture(c.Width, c.Height);
  gl.BindTexture(GL_TEXTURE_2D, 0);
  const GLuint resultFbo = Framebuffer({ result });
  if (!TableTexture(c))
  {
    return false;
  }

  // The programs: the case's uniforms (program "cells"), the per-draw ones
  // as DrawCells sets them for the faces, havsFirstCell per run.
  auto makeProgram = [&](const std::string& fragmentShader) -> GLuint
  {
    const GLuint program = Program(c, "cellprojection.vert", fragmentShader, "cells");
    if (!program)
    {
      return 0;
    }
    auto set = [program](const char* name, int value) { SetInt(program, name, value); };
    set("havsTrianglesPerCell", 4);
    set("havsPullVertices", 1);
    set("havsNearSectionDrawn", 0);
    set("havsFirstCell", 0);
    if (o.Control)
    {
      // The control's second wrong: every cell left through its farthest
      // plane (the mapper's testing aid), which a thin medium cannot hide.
      set("havsWrongExit", 1);
    }
    recordBuffers.SetUniforms(program);
    ParkUnreadSamplers(program);
    return program;
  };

  const bool flip = c.Int("flip_facing") != 0;
  auto drawCells = [=](GLuint program)
  {
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, OrderBinding, orderBuffer);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, TetBinding, tetBuffer);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, MirroredBinding, mirroredBuffer);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, PointBinding, pointBuffer);
    recordBuffers.Bind();
    gl.UseProgram(program);
    const GLint firstCell = gl.GetUniformLocation(program, "havsFirstCell");
    gl.BindVertexArray(vao);
    SetCompositeBlending();
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(GL_BACK);
    gl.FrontFace(flip ? GL_CW : GL_CCW);
    for (size_t begin = 0; begin < cellCount; begin += patternCells)
    {
      const size_t end = std::min(cellCount, begin + patternCells);
      if (firstCell >= 0)
      {
        gl.Uniform1i(firstCell, static_cast<GLint>(begin));
      }
      gl.DrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(12 * (end - begin)),
        GL_UNSIGNED_INT, nullptr, static_cast<GLint>(4 * begin));
    }
    gl.FrontFace(GL_CCW);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    gl.BindVertexArray(0);
  };
  auto clear = [resultFbo]() { ClearTarget(resultFbo); };

  if (wantCells)
  {
    Path p;
    p.Name = "cell projection";
    const GLuint program = makeProgram("cellprojection.frag");
    if (!program)
    {
      return false;
    }
    p.Clear = clear;
    p.Draw = [=]() { drawCells(program); };
    p.Resolve = []() {};
    p.Image = [=]() { return ReadImage(resultFbo, c.Width, c.Height); };
    paths.Run.push_back(p);
  }
  if (wantRaster)
  {
    // The same front faces, culled and blended alike, with the trivial shader.
    Path p;
    p.Name = "raster bound (trivial shader)";
    const GLuint program = makeProgram("trivial.frag");
    if (!program)
    {
      return false;
    }
    p.Clear = clear;
    p.Draw = [=]() { drawCells(program); };
    p.Resolve = []() {};
    p.RasterBound = true;
    paths.Run.push_back(p);
  }
  return true;
}
}
