/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLObjects.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLObjects.h"

#include "vtkHAVSCellGeometry.h"
#include "vtkHAVSFramePlanes.h"

#include "vtkShaderProgram.h"

#include <algorithm>
#include <atomic>

VTK_ABI_NAMESPACE_BEGIN

namespace
{
/// The smallest buffer made: an empty source still binds.
constexpr size_t MinimumBufferBytes = 16;

/// The binding point a target is bound at while this file works on it.
GLenum BindingOf(GLenum target)
{
  switch (target)
  {
    case GL_ARRAY_BUFFER:
      return GL_ARRAY_BUFFER_BINDING;
    case GL_ELEMENT_ARRAY_BUFFER:
      return GL_ELEMENT_ARRAY_BUFFER_BINDING;
    default:
      return GL_SHADER_STORAGE_BUFFER_BINDING;
  }
}
}

//------------------------------------------------------------------------------
namespace
{
std::atomic<size_t> LiveBufferBytes{ 0 };
}

vtkHAVSGLBuffer::~vtkHAVSGLBuffer()
{
  // (The GL name goes with its context; only the ledger is kept right here.)
  LiveBufferBytes -= this->Bytes;
}

size_t vtkHAVSGLBuffer::GetLiveBytes()
{
  return LiveBufferBytes;
}

bool vtkHAVSGLBuffer::Update(
  GLenum target, const void* data, size_t bytes, vtkMTimeType version, GLenum usage)
{
  if (this->Handle && version != 0 && version == this->Version)
  {
    return false;
  }
  if (!this->Handle)
  {
    glGenBuffers(1, &this->Handle);
  }
  // An element buffer binds to the vertex array bound now: upload it through
  // the storage target instead, which binds to nothing.
  const GLenum through = target == GL_ELEMENT_ARRAY_BUFFER ? GL_SHADER_STORAGE_BUFFER : target;
  GLint previous = 0;
  glGetIntegerv(BindingOf(through), &previous);
  glBindBuffer(through, this->Handle);
  LiveBufferBytes -= this->Bytes;
  // A buffer streamed every frame (GL_STREAM_DRAW: the face order, the
  // sections, the ray caster's tiles) keeps the largest size it has had, so
  // that its storage, orphaned and made again each frame, has the same size
  // every frame (the driver recycles it) whatever the frame's count.
  this->Bytes =
    std::max({ bytes, MinimumBufferBytes, usage == GL_STREAM_DRAW ? this->Bytes : size_t(0) });
  LiveBufferBytes += this->Bytes;
  glBufferData(through, static_cast<GLsizeiptr>(this->Bytes), nullptr, usage);
  if (data && bytes > 0)
  {
    glBufferSubData(through, 0, static_cast<GLsizeiptr>(bytes), data);
  }
  glBindBuffer(through, static_cast<GLuint>(previous));
  this->Version = version;
  return true;
}

void vtkHAVSGLBuffer::Write(size_t offset, const void* data, size_t bytes)
{
  glBindBuffer(GL_COPY_WRITE_BUFFER, this->Handle);
  glBufferSubData(
    GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}

void vtkHAVSGLBuffer::Read(size_t offset, void* data, size_t bytes) const
{
  glBindBuffer(GL_COPY_READ_BUFFER, this->Handle);
  glGetBufferSubData(
    GL_COPY_READ_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
}

void vtkHAVSGLBuffer::BindBase(GLenum target, GLuint index) const
{
  glBindBufferBase(target, index, this->Handle);
}

void vtkHAVSGLBuffer::Release()
{
  if (this->Handle)
  {
    glDeleteBuffers(1, &this->Handle);
  }
  this->Handle = 0;
  LiveBufferBytes -= this->Bytes;
  this->Bytes = 0;
  this->Version = 0;
}

//------------------------------------------------------------------------------
bool vtkHAVSGLCellRecords::Update(
  const std::vector<float>& records, size_t largestBuffer, vtkMTimeType version)
{
  constexpr size_t per = vtkHAVSCellGeometry::FloatsPerCell;
  const size_t cells = records.size() / per;
  const size_t cellsPerBuffer = vtkHAVSCellGeometry::CellsPerRecordBuffer(largestBuffer);
  const size_t count = std::max<size_t>((cells + cellsPerBuffer - 1) / cellsPerBuffer, 1);
  if (count > vtkHAVSCellGeometry::MaximumRecordBuffers)
  {
    return false;
  }
  if (version != 0 && version == this->GetVersion() && cellsPerBuffer == this->CellsPerBuffer)
  {
    return false;
  }
  this->Release();
  for (size_t i = 0; i < count; ++i)
  {
    const size_t first = i * cellsPerBuffer;
    const size_t n = std::min(cellsPerBuffer, cells - std::min(first, cells));
    this->Buffers[i].Update(
      GL_SHADER_STORAGE_BUFFER, records.data() + per * first, per * n * sizeof(float), version);
  }
  this->Count = static_cast<int>(count);
  this->CellsPerBuffer = cellsPerBuffer;
  return true;
}

void vtkHAVSGLCellRecords::Bind() const
{
  this->Buffers[0].BindBase(GL_SHADER_STORAGE_BUFFER, FirstBinding);
  for (int i = 1; i < this->Count; ++i)
  {
    this->Buffers[i].BindBase(GL_SHADER_STORAGE_BUFFER, MoreBindings + static_cast<GLuint>(i - 1));
  }
}

void vtkHAVSGLCellRecords::SetUniforms(vtkShaderProgram* program) const
{
  if (this->Count > 1)
  {
    program->SetUniformi("havsCellsPerBuffer", static_cast<int>(this->CellsPerBuffer));
  }
}

void vtkHAVSGLCellRecords::Release()
{
  for (vtkHAVSGLBuffer& buffer : this->Buffers)
  {
    buffer.Release();
  }
  this->Count = 1;
  this->CellsPerBuffer = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSGLVertexArray::SetBuffers(const vtkHAVSGLBuffer& points, const vtkHAVSGLBuffer* indices)
{
  this->SetAttribute(0, points, 3);
  this->SetIndices(indices);
}

void vtkHAVSGLVertexArray::SetAttribute(
  GLuint location, const vtkHAVSGLBuffer& buffer, int components)
{
  this->Bind();
  glBindBuffer(GL_ARRAY_BUFFER, buffer.GetHandle());
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  Unbind();
}

void vtkHAVSGLVertexArray::SetIndices(const vtkHAVSGLBuffer* indices)
{
  this->Bind();
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices ? indices->GetHandle() : 0);
  Unbind();
}

void vtkHAVSGLVertexArray::Bind()
{
  if (!this->Handle)
  {
    glGenVertexArrays(1, &this->Handle);
  }
  glBindVertexArray(this->Handle);
}

void vtkHAVSGLVertexArray::Unbind()
{
  glBindVertexArray(0);
}

void vtkHAVSGLVertexArray::Release()
{
  if (this->Handle)
  {
    glDeleteVertexArrays(1, &this->Handle);
  }
  this->Handle = 0;
}

//------------------------------------------------------------------------------
int vtkHAVSGLSection::Update(const vtkHAVSFramePlanes& planes)
{
  const std::vector<vtkHAVSFramePlanes::Section>& sections = planes.GetSections();
  if (sections.empty())
  {
    return 0; // (the camera outside the mesh: nothing cut by the near plane)
  }
  const vtkMTimeType version = planes.GetSectionsVersion();
  const vtkHAVSFramePlanes::Section& section = sections.front(); // the near plane's only
  if (this->Points.Update(GL_ARRAY_BUFFER, section.Points, version, GL_STREAM_DRAW))
  {
    this->Cells.Update(GL_SHADER_STORAGE_BUFFER, section.Cells, version, GL_STREAM_DRAW);
    this->Array.SetBuffers(this->Points, nullptr);
    this->Triangles = static_cast<int>(section.Cells.size());
  }
  return this->Triangles;
}

void vtkHAVSGLSection::Draw(GLuint cellBinding)
{
  this->Cells.BindBase(GL_SHADER_STORAGE_BUFFER, cellBinding);
  this->Array.Bind();
  glDrawArrays(GL_TRIANGLES, 0, 3 * this->Triangles);
  vtkHAVSGLVertexArray::Unbind();
}

void vtkHAVSGLSection::Release()
{
  this->Array.Release();
  this->Points.Release();
  this->Cells.Release();
  this->Triangles = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSGLImage::Resize(GLenum internalFormat, int width, int height)
{
  if (this->Handle && this->Format == internalFormat && this->Size[0] == width &&
    this->Size[1] == height)
  {
    return;
  }
  this->Release();
  glGenTextures(1, &this->Handle);
  glBindTexture(GL_TEXTURE_2D, this->Handle);
  glTexStorage2D(GL_TEXTURE_2D, 1, internalFormat, width, height);
  glBindTexture(GL_TEXTURE_2D, 0);
  this->Format = internalFormat;
  this->Size[0] = width;
  this->Size[1] = height;
}

void vtkHAVSGLImage::Clear(GLenum format, GLenum type, const void* value, int width, int height)
{
  if (width > 0 && height > 0)
  {
    glClearTexSubImage(this->Handle, 0, 0, 0, 0, width, height, 1, format, type, value);
  }
  else
  {
    glClearTexImage(this->Handle, 0, format, type, value);
  }
}

void vtkHAVSGLImage::BindImage(GLuint unit) const
{
  glBindImageTexture(unit, this->Handle, 0, GL_FALSE, 0, GL_READ_WRITE, this->Format);
}

void vtkHAVSGLImage::UnbindImage(GLuint unit)
{
  glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
}

void vtkHAVSGLImage::Release()
{
  if (this->Handle)
  {
    glDeleteTextures(1, &this->Handle);
  }
  this->Handle = 0;
  this->Format = 0;
  this->Size[0] = this->Size[1] = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSGLStencilTarget::Resize(int width, int height)
{
  if (this->Framebuffer && this->Size[0] == width && this->Size[1] == height)
  {
    return;
  }
  this->Release();
  GLint drawn = 0; // (the draw framebuffer VTK's state has bound, put back below)
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawn);
  glGenRenderbuffers(1, &this->Renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, this->Renderbuffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  glGenFramebuffers(1, &this->Framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->Framebuffer);
  glFramebufferRenderbuffer(
    GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, this->Renderbuffer);
  glDrawBuffer(GL_NONE);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawn));
  this->Size[0] = width;
  this->Size[1] = height;
}

void vtkHAVSGLStencilTarget::Release()
{
  if (this->Framebuffer)
  {
    glDeleteFramebuffers(1, &this->Framebuffer);
    glDeleteRenderbuffers(1, &this->Renderbuffer);
  }
  this->Framebuffer = this->Renderbuffer = 0;
  this->Size[0] = this->Size[1] = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSGLQueries::Timestamp()
{
  GLuint query = 0;
  glGenQueries(1, &query);
  glQueryCounter(query, GL_TIMESTAMP);
  this->Stamps.push_back(query);
}

void vtkHAVSGLQueries::BeginSamples()
{
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  this->SampleQueries.push_back(query);
}

void vtkHAVSGLQueries::EndSamples()
{
  glEndQuery(GL_SAMPLES_PASSED);
}

std::vector<uint64_t> vtkHAVSGLQueries::Results(const std::vector<GLuint>& queries) const
{
  std::vector<uint64_t> results(queries.size(), 0);
  for (size_t i = 0; i < queries.size(); ++i)
  {
    GLuint64 value = 0;
    glGetQueryObjectui64v(queries[i], GL_QUERY_RESULT, &value);
    results[i] = static_cast<uint64_t>(value);
  }
  return results;
}

void vtkHAVSGLQueries::Release()
{
  for (std::vector<GLuint>* queries : { &this->Stamps, &this->SampleQueries })
  {
    if (!queries->empty())
    {
      glDeleteQueries(static_cast<GLsizei>(queries->size()), queries->data());
    }
    queries->clear();
  }
}

VTK_ABI_NAMESPACE_END
