/*=========================================================================

  Project:   vtkHAVS
  Module:    havsGPUKBuffer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_gpu_bench's HAVS part: the case's faces, in the mapper's draw order,
// through each k-buffer path the GPU has (framebuffer fetch: Mesa; the
// fragment-shader interlock: NVIDIA, on llvmpipe its layout without a guard,
// since llvmpipe shades a pixel's fragments in primitive order; fragment
// lists: any GL 4.3), and the trivial shader of the raster bound.
#include "havsGPUBench.h"

#include <algorithm>
#include <cstdlib>
#include <memory>

namespace havsgpu
{
bool MakeKBufferPaths(Case& c, const Options& o, const Device& device, Paths& paths)
{
  std::vector<float> points, scalars;
  std::vector<uint32_t> indices;
  if (!ReadArray(c.Dir + "/points.f32", points) || !ReadArray(c.Dir + "/scalars.f32", scalars) ||
    !ReadArray(c.Dir + "/indices.u32", indices))
  {
    return false;
  }
  if (o.Control)
  {
    // The control: the faces back to front.
    std::vector<uint32_t> reversed(indices.size());
    const size_t faces = indices.size() / 3;
    for (size_t f = 0; f < faces; ++f)
    {
      std::copy_n(&indices[3 * (faces - 1 - f)], 3, &reversed[3 * f]);
    }
    indices.swap(reversed);
  }
  const bool arb = device.InterlockARB, nv = device.InterlockNV;

  // Geometry and table.
  GLuint vao = 0, buffers[3] = { 0, 0, 0 };
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  gl.GenBuffers(3, buffers);
  gl.BindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  gl.BufferData(GL_ARRAY_BUFFER, points.size() * sizeof(float), points.data(), GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  gl.BindBuffer(GL_ARRAY_BUFFER, buffers[1]);
  gl.BufferData(GL_ARRAY_BUFFER, scalars.size() * sizeof(float), scalars.data(), GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[2]);
  gl.BufferData(
    GL_ELEMENT_ARRAY_BUFFER, indices.size() * sizeof(uint32_t), indices.data(), GL_STATIC_DRAW);
  const GLsizei indexCount = static_cast<GLsizei>(indices.size());
  GLuint quadVao = 0;
  gl.GenVertexArrays(1, &quadVao);

  if (!TableTexture(c))
  {
    return false;
  }

  gl.Disable(GL_DEPTH_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_CULL_FACE);
  gl.Disable(GL_SCISSOR_TEST);
  gl.Viewport(0, 0, c.Width, c.Height);
  const bool flip = c.Int("flip_facing") != 0;
  auto drawFaces = [=](GLuint program)
  {
    gl.UseProgram(program);
    gl.BindVertexArray(vao);
    gl.FrontFace(flip ? GL_CW : GL_CCW);
    gl.DrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
    gl.FrontFace(GL_CCW);
  };
  auto drawQuad = [=](GLuint program)
  {
    gl.UseProgram(program);
    gl.BindVertexArray(quadVao);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
  };
  const GLuint result = FloatTexture(c.Width, c.Height);
  const GLuint resultFbo = Framebuffer({ result });

  if (o.Wanted("fetch") && device.Fetch)
  {
    Path p;
    p.Name = "framebuffer fetch";
    const int attachments = c.Int("fetch_attachments");
    std::vector<GLuint> targets;
    for (int a = 0; a < attachments; ++a)
    {
      targets.push_back(FloatTexture(c.Width, c.Height));
    }
    const GLuint fbo = Framebuffer(targets);
    const GLuint draw = Program(c, "face.vert", "fetch_draw.frag", "draw");
    const GLuint resolve = Program(c, "quad.vert", "fetch_resolve.frag", "draw");
    if (!draw || !resolve)
    {
      return false;
    }
    gl.UseProgram(resolve);
    gl.Uniform1i(gl.GetUniformLocation(resolve, "havsColorTexture"), 1);
    for (int a = 1; a < attachments; ++a)
    {
      gl.Uniform1i(
        gl.GetUniformLocation(resolve, ("havsEntryTexture" + std::to_string(a - 1)).c_str()),
        1 + a);
    }
    p.Clear = [=]()
    {
      gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
      DrawBuffers(targets.size());
      const float zero[4] = { 0, 0, 0, 0 };
      const float firstPair[4] = { -2.0e38f, 0, 3.0e38f, 0 };
      const float emptyPair[4] = { 3.0e38f, 0, 3.0e38f, 0 };
      gl.ClearBufferfv(GL_COLOR, 0, zero);
      for (size_t a = 1; a < targets.size(); ++a)
      {
        gl.ClearBufferfv(GL_COLOR, static_cast<GLint>(a), a == 1 ? firstPair : emptyPair);
      }
    };
    p.Draw = [=]() { drawFaces(draw); };
    p.Resolve = [=]()
    {
      gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resultFbo);
      DrawBuffers(1);
      for (size_t a = 0; a < targets.size(); ++a)
      {
        gl.ActiveTexture(GL_TEXTURE1 + static_cast<GLenum>(a));
        gl.BindTexture(GL_TEXTURE_2D, targets[a]);
      }
      gl.ActiveTexture(GL_TEXTURE0);
      drawQuad(resolve);
    };
    p.Image = [=]() { return ReadImage(resultFbo, c.Width, c.Height); };
    paths.Run.push_back(p);
  }
  else if (o.Wanted("fetch"))
  {
    paths.NotRun.push_back("framebuffer fetch (no GL_EXT_shader_framebuffer_fetch)");
  }
  if (o.Wanted("interlock") && (arb || nv || device.Llvmpipe))
  {
    Path p;
    const char* shader = arb ? "interlock_arb_draw.frag"
                             : (nv ? "interlock_nv_draw.frag" : "interlock_none_draw.frag");
    p.Name = arb ? "interlock (ARB)"
                 : (nv ? "interlock (NV)" : "interlock layout, no guard (llvmpipe: in order)");
    GLuint ssbo = 0;
    gl.GenBuffers(1, &ssbo);
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, ssbo);
    gl.BufferData(GL_SHADER_STORAGE_BUFFER,
      static_cast<GLsizeiptr>(c.Width) * c.Height * c.Int("interlock_stride") * 4 * sizeof(float),
      nullptr, GL_DYNAMIC_COPY);
    const GLuint clear = Program(c, "quad.vert", "interlock_clear.frag", "draw");
    const GLuint draw = Program(c, "face.vert", shader, "draw");
    const GLuint resolve = Program(c, "quad.vert", "interlock_resolve.frag", "draw");
    if (!clear || !draw || !resolve)
    {
      return false;
    }
    p.Clear = [=]()
    {
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, ssbo);
      gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resultFbo);
      DrawBuffers(1);
      gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      drawQuad(clear);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    };
    p.Draw = [=]()
    {
      drawFaces(draw);
      gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    };
    p.Resolve = [=]() { drawQuad(resolve); };
    p.Image = [=]() { return ReadImage(resultFbo, c.Width, c.Height); };
    paths.Run.push_back(p);
  }
  else if (o.Wanted("interlock"))
  {
    paths.NotRun.push_back("interlock (no ARB or NV fragment_shader_interlock)");
  }
  if (o.Wanted("lists"))
  {
    // Fragment lists (vtkHAVSFragmentListKBuffer): every fragment appended
    // to its pixel's list (heads: an R32UI image at unit 0; nodes of 16
    // bytes at binding 1, their counter at 2), sorted and integrated by the
    // resolve. The pool is sized by a first draw, as the mapper grows it.
    Path p;
    const bool vote = HasExtension("GL_ARB_shader_group_vote");
    p.Name = std::string("fragment lists") + (vote ? " (group vote)" : "");
    const GLuint draw = Program(c, "face.vert", "list_draw.frag", "draw");
    const GLuint resolve =
      Program(c, "quad.vert", vote ? "list_resolve_vote.frag" : "list_resolve.frag", "draw");
    if (!draw || !resolve)
    {
      return false;
    }
    GLuint heads = 0;
    gl.GenTextures(1, &heads);
    gl.BindTexture(GL_TEXTURE_2D, heads);
    gl.TexStorage2D(GL_TEXTURE_2D, 1, GL_R32UI, c.Width, c.Height);
    const GLuint counter =
      Buffer(GL_SHADER_STORAGE_BUFFER, nullptr, sizeof(GLuint), GL_DYNAMIC_READ);
    auto capacity = std::make_shared<GLuint>(static_cast<GLuint>(
      std::max<size_t>(static_cast<size_t>(c.Width) * c.Height * 4, size_t(1) << 20)));
    auto nodes = std::make_shared<GLuint>(
      Buffer(GL_SHADER_STORAGE_BUFFER, nullptr, size_t(*capacity) * 16, GL_DYNAMIC_COPY));
    p.Clear = [=]()
    {
      const GLuint noNode = 0xFFFFFFFFu, zero = 0;
      gl.ClearTexImage(heads, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noNode);
      gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, counter);
      gl.BufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &zero);
      gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resultFbo);
      DrawBuffers(1);
    };
    p.Draw = [=]()
    {
      for (int attempt = 0; attempt < 2; ++attempt)
      {
        if (attempt > 0)
        {
          p.Clear();
        }
        gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, *nodes);
        gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, counter);
        gl.BindImageTexture(0, heads, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
        gl.UseProgram(draw);
        gl.Uniform1i(
          gl.GetUniformLocation(draw, "havsNodeCapacity"), static_cast<GLint>(*capacity));
        gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        drawFaces(draw);
        gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
          GL_BUFFER_UPDATE_BARRIER_BIT);
        GLuint count = 0;
        gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, counter);
        gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &count);
        if (count <= *capacity)
        {
          break;
        }
        *capacity = count + count / 4; // the pool overflowed: grow it, draw again
        gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, *nodes);
        gl.BufferData(GL_SHADER_STORAGE_BUFFER, size_t(*capacity) * 16, nullptr, GL_DYNAMIC_COPY);
      }
    };
    p.Resolve = [=]()
    {
      gl.BindImageTexture(0, heads, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
      gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, *nodes);
      gl.UseProgram(resolve);
      gl.Uniform1i(
        gl.GetUniformLocation(resolve, "havsNodeCapacity"), static_cast<GLint>(*capacity));
      drawQuad(resolve);
    };
    p.Image = [=]() { return ReadImage(resultFbo, c.Width, c.Height); };
    paths.Run.push_back(p);
  }
  if (o.Wanted("raster"))
  {
    Path p;
    p.Name = "raster bound (trivial shader)";
    const GLuint draw = Program(c, "face.vert", "trivial.frag", "draw");
    if (!draw)
    {
      return false;
    }
    p.Clear = [=]() { ClearTarget(resultFbo); };
    p.Draw = [=]() { drawFaces(draw); };
    p.Resolve = []() {};
    p.RasterBound = true;
    paths.Run.push_back(p);
  }

  return true;
}
}
