/*=========================================================================

  Project:   vtkHAVS
  Module:    havsGPUBench.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// What the parts of havs_gpu_bench share (no VTK): the GL functions, taken
// from eglGetProcAddress; a frame case (README.md beside this file); its
// programs; the paths a mapper's part offers, timed and compared by main.
#ifndef havsGPUBench_h
#define havsGPUBench_h

#include <GL/glcorearb.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace havsgpu
{
// --- the GL functions used here, from eglGetProcAddress ------------------------
#define HAVS_GL_FUNCTIONS(X)                                                                       \
  X(PFNGLGETSTRINGPROC, GetString)                                                                 \
  X(PFNGLGETSTRINGIPROC, GetStringi)                                                               \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                             \
  X(PFNGLGETERRORPROC, GetError)                                                                   \
  X(PFNGLCREATESHADERPROC, CreateShader)                                                           \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                           \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                                                         \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                             \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                                   \
  X(PFNGLDELETESHADERPROC, DeleteShader)                                                           \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                         \
  X(PFNGLATTACHSHADERPROC, AttachShader)                                                           \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                             \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                           \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                                 \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                                               \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                               \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                                                 \
  X(PFNGLUNIFORM1UIPROC, Uniform1ui)                                                               \
  X(PFNGLUNIFORM2IPROC, Uniform2i)                                                                 \
  X(PFNGLUNIFORM1FVPROC, Uniform1fv)                                                               \
  X(PFNGLUNIFORM2FVPROC, Uniform2fv)                                                               \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                                               \
  X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                                               \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                                                   \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                                   \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                                     \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                                     \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                                               \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                                               \
  X(PFNGLBUFFERDATAPROC, BufferData)                                                               \
  X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                                         \
  X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData)                                                   \
  X(PFNGLCLEARBUFFERDATAPROC, ClearBufferData)                                                     \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                                       \
  X(PFNGLBINDBUFFERRANGEPROC, BindBufferRange)                                                     \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                                     \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                             \
  X(PFNGLGENTEXTURESPROC, GenTextures)                                                             \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                                                             \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                         \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                                         \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                               \
  X(PFNGLTEXIMAGE3DPROC, TexImage3D)                                                               \
  X(PFNGLTEXSTORAGE2DPROC, TexStorage2D)                                                           \
  X(PFNGLCLEARTEXIMAGEPROC, ClearTexImage)                                                         \
  X(PFNGLBINDIMAGETEXTUREPROC, BindImageTexture)                                                   \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                                     \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                                     \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                           \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                                     \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                                                   \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                                                   \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                                             \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                       \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                                             \
  X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                                         \
  X(PFNGLCLEARBUFFERIVPROC, ClearBufferiv)                                                         \
  X(PFNGLCLEARBUFFERUIVPROC, ClearBufferuiv)                                                       \
  X(PFNGLVIEWPORTPROC, Viewport)                                                                   \
  X(PFNGLENABLEPROC, Enable)                                                                       \
  X(PFNGLDISABLEPROC, Disable)                                                                     \
  X(PFNGLCULLFACEPROC, CullFace)                                                                   \
  X(PFNGLBLENDFUNCPROC, BlendFunc)                                                                 \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                                                 \
  X(PFNGLBLENDEQUATIONPROC, BlendEquation)                                                         \
  X(PFNGLDEPTHMASKPROC, DepthMask)                                                                 \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                                 \
  X(PFNGLSTENCILFUNCPROC, StencilFunc)                                                             \
  X(PFNGLSTENCILOPPROC, StencilOp)                                                                 \
  X(PFNGLSTENCILMASKPROC, StencilMask)                                                             \
  X(PFNGLCOLORMASKPROC, ColorMask)                                                                 \
  X(PFNGLFRONTFACEPROC, FrontFace)                                                                 \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)                                                           \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex)                                       \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                               \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)                                             \
  X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                                                         \
  X(PFNGLFLUSHPROC, Flush)                                                                         \
  X(PFNGLFINISHPROC, Finish)                                                                       \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                                                               \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                                               \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                                                             \
  X(PFNGLGENQUERIESPROC, GenQueries)                                                               \
  X(PFNGLBEGINQUERYPROC, BeginQuery)                                                               \
  X(PFNGLENDQUERYPROC, EndQuery)                                                                   \
  X(PFNGLQUERYCOUNTERPROC, QueryCounter)                                                           \
  X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)                                             \
  X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                                                     \
  X(PFNGLTEXSTORAGE3DPROC, TexStorage3D)                                                           \
  X(PFNGLGETTEXIMAGEPROC, GetTexImage)                                                             \
  X(PFNGLDELETEQUERIESPROC, DeleteQueries)                                                         \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                                       \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                                         \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)

struct GL
{
#define HAVS_GL_MEMBER(type, name) type name = nullptr;
  HAVS_GL_FUNCTIONS(HAVS_GL_MEMBER)
#undef HAVS_GL_MEMBER
};
extern GL gl;

/// Prints "havs_gpu_bench: what" to stderr; false.
bool Fail(const std::string& what);
/// Seconds on a steady clock.
double Now();
/// The median of `values` (0 for none).
double Median(std::vector<double> values);

/// What the context runs on, for the report.
struct Device
{
  std::string Platform; ///< the EGL display that gave the context (device N, surfaceless, default)
  std::string EGLVendor, EGLVersion, EGLDevice;
  std::string Renderer, Version, Vendor;
  bool Fetch = false, InterlockARB = false, InterlockNV = false, Llvmpipe = false;
  std::vector<std::string> Diagnostics; ///< what was tried and missing on the way
};
/// An OpenGL 4.5 (else 4.3) core context without a surface (libEGL opened at
/// run time: the device platform first, then Mesa's surfaceless one, then
/// the default display). False, with `device.Diagnostics` saying what was
/// missing, when none could be made.
bool MakeContext(Device& device);
bool HasExtension(const char* name);

// --- the case --------------------------------------------------------------------
struct Uniform
{
  std::string Program, Name, Type;
  std::vector<float> Values;       ///< as floats (the float types)
  std::vector<long long> Integers; ///< as integers, exactly (int, uint, ivec2: past 2^24 too)
};

/// A frame case (README.md): case.txt's keys and uniforms, its files read on demand.
struct Case
{
  std::string Dir;
  std::string Mapper; ///< havs, cellprojection, raycast
  std::map<std::string, std::string> Keys;
  std::vector<Uniform> Uniforms;
  int Width = 0, Height = 0, TableSize[3] = { 0, 0, 0 };
  long long Cells = 0;       ///< tetrahedra drawn (what tets/s counts)
  std::vector<float> Result; ///< the mapper's float result where captured (RGBA, bottom row first)
  std::vector<float> Exact;  ///< the exact reference's image (empty: none stored)
  std::vector<uint8_t> Folded; ///< 1: a pixel left out of the comparison (empty: none)

  std::string Shader(const std::string& name) const;
  int Int(const std::string& key) const;
  double Double(const std::string& key) const;
  bool Has(const std::string& file) const;
};
bool ReadCase(const std::string& dir, Case& c);
std::string ReadText(const std::string& path);
bool ReadBytes(const std::string& path, std::vector<char>& out);
template <typename T>
bool ReadArray(const std::string& path, std::vector<T>& out)
{
  std::vector<char> bytes;
  if (!ReadBytes(path, bytes))
  {
    return false;
  }
  out.resize(bytes.size() / sizeof(T));
  std::copy(bytes.begin(), bytes.begin() + static_cast<long>(out.size() * sizeof(T)),
    reinterpret_cast<char*>(out.data()));
  return true;
}

// --- GL helpers ------------------------------------------------------------------
/// A program of the case's shaders, its uniforms set from the case's lines of
/// `program` (the name in "uniform PROGRAM ..."), havsTable at unit 0 and
/// havsViewportSize from the case. 0, with the log printed, when it fails.
GLuint Program(const Case& c, const std::string& vertex, const std::string& fragment,
  const std::string& program);
/// A compute program of the case's shader `shader`; 0, with the log printed, when it fails.
GLuint ComputeProgram(const Case& c, const std::string& shader);
GLuint FloatTexture(int w, int h);
GLuint Framebuffer(const std::vector<GLuint>& colors);
void DrawBuffers(size_t n);
/// A storage or vertex buffer holding `bytes` bytes of `data` (nullptr: uninitialized).
GLuint Buffer(GLenum target, const void* data, size_t bytes, GLenum usage = GL_STATIC_DRAW);
template <typename T>
GLuint Buffer(GLenum target, const std::vector<T>& values, GLenum usage = GL_STATIC_DRAW)
{
  return Buffer(target, values.data(), values.size() * sizeof(T), usage);
}
/// The case's pre-integration table as a linear 3D texture on unit 0.
GLuint TableTexture(const Case& c);
/// RGBA floats of colour attachment 0 of `framebuffer` (bottom row first).
std::vector<float> ReadImage(GLuint framebuffer, int width, int height);
/// Sets the int uniform `name` of `program` where the program has it.
void SetInt(GLuint program, const char* name, int value);
/// Binds `framebuffer`'s colour attachment 0 for drawing and clears it to 0.
void ClearTarget(GLuint framebuffer);
/// vtkHAVSGLMapperResources::SetBlending(composite): what is drawn goes under
/// what is in front (premultiplied).
void SetCompositeBlending();
/// The samplers a cell-projection or ray-casting shader declares besides the
/// table (opaque depth, additive table, cell optics), on units of their own:
/// none is read in a captured frame, and two sampler types on one unit are an
/// error where the compiler kept them.
void ParkUnreadSamplers(GLuint program);

/// The cell records (vtkHAVSCellGeometry: FloatsPerCell floats a tetrahedron)
/// as vtkHAVSGLCellRecords holds them: buffers of `cells_per_record_buffer`
/// cells (case.txt; absent: one buffer), the last the rest, at bindings 4,
/// 10, 11, 12.
struct CellRecords
{
  static constexpr size_t FloatsPerCell = 20;
  static constexpr GLuint Bindings[4] = { 4, 10, 11, 12 };
  std::vector<GLuint> Buffers;
  size_t CellsPerBuffer = 0;
  size_t Count = 0; ///< buffers

  /// The split of `tetrahedra` cells (CellsPerBuffer, Count); false (with the
  /// reason printed) when it disagrees with case.txt's `record_buffers` or
  /// with HAVS_CELL_BUFFERS in the case's shader `shader`.
  bool Split(const Case& c, size_t tetrahedra, const std::string& shader);
  /// The buffers of `records` (FloatsPerCell floats a cell), as split.
  void Upload(const std::vector<float>& records);
  void Bind() const;
  /// havsCellsPerBuffer, where the records lie in several buffers.
  void SetUniforms(GLuint program) const;
};

// --- the paths a mapper's part offers --------------------------------------------
struct Options
{
  int Frames = 10;
  std::string Paths;                  ///< the paths asked for (empty: all)
  bool Control = false;               ///< the control: each part's own wrong order (README.md)
  double MaxDifference = 2.0 / 255.0; ///< against the mapper's own result
  std::string SaveImages;             ///< a directory for each path's image (empty: none)
  bool Wanted(const std::string& path) const
  {
    return this->Paths.empty() || this->Paths.find(path) != std::string::npos;
  }
};

/**
 * A table case (mapper table, issue 45: README.md): the pre-integrated table
 * built by the case's compute shader from the inputs havs_gpu_cases made,
 * timed (--frames builds after a warm-up), read back and compared with the
 * CPU's table of the same inputs (at most 5e-6 apart, as
 * TestHAVSGLTableBuilder bounds it). With o.Control, the functions mirrored
 * (their samples in reverse order): that table must miss. Returns the failures.
 */
int RunTableCase(const Case& c, const Options& o, std::ofstream* csv);

/// One way of drawing the case's frame, timed as clear, draw, resolve.
struct Path
{
  std::string Name;
  std::function<void()> Clear, Draw, Resolve;
  /// The float result (RGBA, bottom row first); unset: no image (the raster bound).
  std::function<std::vector<float>()> Image;
  bool RasterBound = false; ///< the trivial-shader draw the others are compared with
};

/// What a part makes of a case: the paths to run and those it cannot, with why.
struct Paths
{
  std::vector<Path> Run;
  std::vector<std::string> NotRun;
};

/// HAVS: framebuffer fetch, interlock, fragment lists, the raster bound.
bool MakeKBufferPaths(Case& c, const Options& o, const Device& device, Paths& paths);
/// The cell projection: its one draw, the raster bound of its faces.
bool MakeCellProjectionPaths(Case& c, const Options& o, const Device& device, Paths& paths);
/// The ray caster: peel and cast, the raster bound.
bool MakeRayCastPaths(Case& c, const Options& o, const Device& device, Paths& paths);
}

#endif
