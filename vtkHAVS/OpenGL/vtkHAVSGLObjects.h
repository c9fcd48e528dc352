/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLObjects.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSGLObjects.h
 * @brief The few OpenGL objects VTK does not wrap for us, each owning its GL
 * name and what it holds: storage buffers (with the version of their
 * contents), vertex arrays, image textures, a stencil-only framebuffer and
 * queries.
 *
 * VTK's wrappers are used where they fit (vtkTextureObject for the tables and
 * targets, vtkOpenGLFramebufferObject for the result): vtkOpenGLBufferObject
 * has no shader-storage target, vtkOpenGLVertexArrayObject binds attributes
 * by a program's names (these arrays serve several programs, by location),
 * the ray caster's per-pixel images are only ever bound as images (immutable
 * integer and float storage, cleared with glClearTexImage), and VTK has no
 * query objects. Every class here is movable, not copyable; Release() needs
 * the context current (the owners release in ReleaseGraphicsResources).
 */
#ifndef vtkHAVSGLObjects_h
#define vtkHAVSGLObjects_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSOpenGL.h" // For GLuint, GLenum
#include "vtkType.h"       // For vtkMTimeType

#include <cstddef> // For size_t
#include <cstdint> // For uint64_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSFramePlanes;
class vtkShaderProgram;

/// A GL buffer object and the version of what it holds.
class vtkHAVSGLBuffer
{
public:
  vtkHAVSGLBuffer() = default;
  ~vtkHAVSGLBuffer();
  vtkHAVSGLBuffer(const vtkHAVSGLBuffer&) = delete;
  vtkHAVSGLBuffer& operator=(const vtkHAVSGLBuffer&) = delete;

  /**
   * Uploads `bytes` from `data` (nullptr: uninitialized) through `target`
   * unless it already holds `version` (0: always); at least 16 bytes are
   * allocated, so that an empty source still binds. With GL_STREAM_DRAW (data
   * streamed every frame) the storage keeps the largest size it has had.
   * Returns whether it uploaded.
   */
  bool Update(GLenum target, const void* data, size_t bytes, vtkMTimeType version,
    GLenum usage = GL_STATIC_DRAW);
  template <class T>
  bool Update(GLenum target, const std::vector<T>& values, vtkMTimeType version,
    GLenum usage = GL_STATIC_DRAW)
  {
    return this->Update(target, values.data(), values.size() * sizeof(T), version, usage);
  }
  /// Overwrites `bytes` at `offset` (the buffer keeps its size and version).
  void Write(size_t offset, const void* data, size_t bytes);
  /// Reads `bytes` at `offset` back (a GPU sync).
  void Read(size_t offset, void* data, size_t bytes) const;
  /// Binds it to the indexed `target` (a shader storage binding) at `index`.
  void BindBase(GLenum target, GLuint index) const;

  GLuint GetHandle() const { return this->Handle; }
  size_t GetBytes() const { return this->Bytes; }
  /// The bytes of every vtkHAVSGLBuffer of this process now (the memory ledger's GPU part).
  static size_t GetLiveBytes();
  vtkMTimeType GetVersion() const { return this->Version; }
  /// Forgets the version: the next Update uploads.
  void Invalidate() { this->Version = 0; }
  void Release();

private:
  GLuint Handle = 0;
  size_t Bytes = 0;
  vtkMTimeType Version = 0;
};

/**
 * The cells' records (vtkHAVSCellGeometry, 80 bytes a tetrahedron) in up to
 * vtkHAVSCellGeometry::MaximumRecordBuffers storage buffers of at most a
 * given size each (a shader addresses one buffer with 32-bit byte offsets),
 * bound where vtkHAVSCellRecordsLib.glsl reads them: binding 4, then 10, 11, 12.
 */
class vtkHAVSGLCellRecords
{
public:
  static constexpr GLuint FirstBinding = 4;
  static constexpr GLuint MoreBindings = 10; ///< buffers 1, 2, 3: 10, 11, 12

  /**
   * Uploads `records` (vtkHAVSCellGeometry::FloatsPerCell floats a cell) in
   * buffers of at most `largestBuffer` bytes (vtkHAVSCellGeometry::
   * CellsPerRecordBuffer cells each, the last the rest) unless they hold
   * `version` in that split already. Returns whether it uploaded; false too
   * when they would take more than MaximumRecordBuffers buffers (nothing then).
   */
  bool Update(const std::vector<float>& records, size_t largestBuffer, vtkMTimeType version);
  /// havsCellsPerBuffer set in `program` where there are several buffers.
  void SetUniforms(vtkShaderProgram* program) const;
  /// Every buffer bound at its binding.
  void Bind() const;
  /// The buffers in use (the shaders' HAVS_CELL_BUFFERS), at least 1.
  int GetBufferCount() const { return this->Count; }
  /// The cells in each buffer but the last (the shaders' havsCellsPerBuffer).
  size_t GetCellsPerBuffer() const { return this->CellsPerBuffer; }
  vtkMTimeType GetVersion() const { return this->Buffers[0].GetVersion(); }
  void Release();

private:
  vtkHAVSGLBuffer Buffers[4];
  int Count = 1;
  size_t CellsPerBuffer = 0;
};

/// A vertex array: float attributes from buffers, optionally indices.
class vtkHAVSGLVertexArray
{
public:
  vtkHAVSGLVertexArray() = default;
  vtkHAVSGLVertexArray(const vtkHAVSGLVertexArray&) = delete;
  vtkHAVSGLVertexArray& operator=(const vtkHAVSGLVertexArray&) = delete;

  /// Attribute 0 from `points` (3 floats a vertex), and `indices` (0: none).
  void SetBuffers(const vtkHAVSGLBuffer& points, const vtkHAVSGLBuffer* indices);
  /// Attribute `location` from `buffer`, `components` floats a vertex, tightly packed.
  void SetAttribute(GLuint location, const vtkHAVSGLBuffer& buffer, int components);
  /// The index buffer drawn from (nullptr: none).
  void SetIndices(const vtkHAVSGLBuffer* indices);
  /// Bound (made first when needed: an array without attributes draws by ids).
  void Bind();
  static void Unbind();
  bool IsCreated() const { return this->Handle != 0; }
  void Release();

private:
  GLuint Handle = 0;
};

/**
 * The near plane's section of the mesh where it cuts it (the camera inside),
 * as the cell projection and the ray caster draw it: its triangles (points)
 * and the cell of each (a storage buffer), uploaded when their version changed.
 */
class vtkHAVSGLSection
{
public:
  /// The near plane's section of `planes` uploaded if new; its triangle count (0: none).
  int Update(const vtkHAVSFramePlanes& planes);
  /// Draws its triangles with each one's cell bound at `cellBinding`.
  void Draw(GLuint cellBinding);
  void Release();

private:
  vtkHAVSGLVertexArray Array;
  vtkHAVSGLBuffer Points;
  vtkHAVSGLBuffer Cells;
  int Triangles = 0;
};

/// A 2D texture with immutable storage, for image load/store.
class vtkHAVSGLImage
{
public:
  vtkHAVSGLImage() = default;
  vtkHAVSGLImage(const vtkHAVSGLImage&) = delete;
  vtkHAVSGLImage& operator=(const vtkHAVSGLImage&) = delete;

  /// Storage of `internalFormat` at this size (made again only when it changed).
  void Resize(GLenum internalFormat, int width, int height);
  /// Every texel set to `value` (`format`/`type` as glClearTexImage's), or
  /// only those of the lower left `width` x `height` corner where both are
  /// above 0 (a reduced image drawn there: clearing the rest costs a full
  /// image's bandwidth every frame).
  void Clear(GLenum format, GLenum type, const void* value, int width = 0, int height = 0);
  /// Bound to image unit `unit` for reading and writing.
  void BindImage(GLuint unit) const;
  static void UnbindImage(GLuint unit);
  GLuint GetHandle() const { return this->Handle; }
  void Release();

private:
  GLuint Handle = 0;
  GLenum Format = 0;
  int Size[2] = { 0, 0 };
};

/// A framebuffer with a depth-stencil renderbuffer and no colour (a stencil of screen regions).
class vtkHAVSGLStencilTarget
{
public:
  vtkHAVSGLStencilTarget() = default;
  vtkHAVSGLStencilTarget(const vtkHAVSGLStencilTarget&) = delete;
  vtkHAVSGLStencilTarget& operator=(const vtkHAVSGLStencilTarget&) = delete;

  /// Made (again) at this size; the draw framebuffer binding is kept.
  void Resize(int width, int height);
  GLuint GetFramebuffer() const { return this->Framebuffer; }
  void Release();

private:
  GLuint Framebuffer = 0;
  GLuint Renderbuffer = 0;
  int Size[2] = { 0, 0 };
};

/// Timestamp and sample-count queries of one frame, read after it.
class vtkHAVSGLQueries
{
public:
  vtkHAVSGLQueries() = default;
  vtkHAVSGLQueries(const vtkHAVSGLQueries&) = delete;
  vtkHAVSGLQueries& operator=(const vtkHAVSGLQueries&) = delete;
  ~vtkHAVSGLQueries() { this->Release(); }

  /// A GL timestamp now (GPU time).
  void Timestamp();
  /// Counts the samples that pass until EndSamples().
  void BeginSamples();
  void EndSamples();
  /// The results in the order issued (waits for them), nanoseconds or samples.
  std::vector<uint64_t> Timestamps() const { return this->Results(this->Stamps); }
  std::vector<uint64_t> Samples() const { return this->Results(this->SampleQueries); }
  /// Deletes the queries (the context must be current).
  void Release();

private:
  std::vector<uint64_t> Results(const std::vector<GLuint>& queries) const;
  std::vector<GLuint> Stamps;
  std::vector<GLuint> SampleQueries;
};

VTK_ABI_NAMESPACE_END
#endif
// VTK-HeaderTest-Exclude: vtkHAVSGLObjects.h
