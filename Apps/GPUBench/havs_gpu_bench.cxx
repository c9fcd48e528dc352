/*=========================================================================

  Project:   vtkHAVS
  Module:    havs_gpu_bench.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_gpu_bench: one HAVS frame on a GPU, with no VTK (issue 16).
//
//   havs_gpu_bench CASE_DIR [--frames N] [--paths fetch,interlock,raster]
//                  [--reverse-order] [--max-difference D]
//
// Reads a frame case written by `havs_benchmark --dump-case DIR`
// (vtkHAVSGLFrameCapture: the vertex and index buffers as the mapper drew
// them, the pre-integration table, every uniform of the draw program, the
// project's own shaders as the mapper generates them, and the mapper's float
// result), makes an OpenGL 4.5 core context through EGL (the device
// platform, else Mesa's surfaceless one, else the default display; libEGL is
// opened at run time, every GL function comes from eglGetProcAddress, so the
// program needs nothing but a driver), and draws the frame through each k-buffer
// path the GPU has: framebuffer fetch (Mesa), fragment-shader interlock (ARB
// or NV: NVIDIA; on llvmpipe, which shades a pixel's fragments in primitive
// order, the interlock path's layout runs without a guard), and the trivial
// shader of the raster bound. Prints per path the median frame time (clear,
// draw, resolve), the draw alone, tets/s and fragments/s, the ratio to the
// raster bound, and the image difference to the mapper's result: a path whose
// image differs by more than --max-difference (default 2/255) fails the run.
// --reverse-order draws the faces back to front (the control: the image must
// then differ).
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// --- EGL, opened at run time ---------------------------------------------------
struct EGL
{
  PFNEGLGETPROCADDRESSPROC GetProcAddress = nullptr;
  PFNEGLGETDISPLAYPROC GetDisplay = nullptr;
  PFNEGLINITIALIZEPROC Initialize = nullptr;
  PFNEGLBINDAPIPROC BindAPI = nullptr;
  PFNEGLCHOOSECONFIGPROC ChooseConfig = nullptr;
  PFNEGLCREATECONTEXTPROC CreateContext = nullptr;
  PFNEGLMAKECURRENTPROC MakeCurrent = nullptr;
  PFNEGLQUERYSTRINGPROC QueryString = nullptr;
  PFNEGLQUERYDEVICESEXTPROC QueryDevices = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplay = nullptr;
};

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
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                         \
  X(PFNGLATTACHSHADERPROC, AttachShader)                                                           \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                             \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                           \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                                 \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                                               \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                               \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                                                 \
  X(PFNGLUNIFORM1FVPROC, Uniform1fv)                                                               \
  X(PFNGLUNIFORM2FVPROC, Uniform2fv)                                                               \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                                               \
  X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                                               \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                                   \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                                     \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                                     \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                                               \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                                               \
  X(PFNGLBUFFERDATAPROC, BufferData)                                                               \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                                       \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                                     \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                             \
  X(PFNGLGENTEXTURESPROC, GenTextures)                                                             \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                                                             \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                         \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                                         \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                               \
  X(PFNGLTEXIMAGE3DPROC, TexImage3D)                                                               \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                                     \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                                     \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                           \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                       \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                                             \
  X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                                         \
  X(PFNGLVIEWPORTPROC, Viewport)                                                                   \
  X(PFNGLDISABLEPROC, Disable)                                                                     \
  X(PFNGLCOLORMASKPROC, ColorMask)                                                                 \
  X(PFNGLFRONTFACEPROC, FrontFace)                                                                 \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)                                                           \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                               \
  X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                                                         \
  X(PFNGLFINISHPROC, Finish)                                                                       \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                                                               \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                                               \
  X(PFNGLGENQUERIESPROC, GenQueries)                                                               \
  X(PFNGLBEGINQUERYPROC, BeginQuery)                                                               \
  X(PFNGLENDQUERYPROC, EndQuery)                                                                   \
  X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)

struct GL
{
#define HAVS_GL_MEMBER(type, name) type name = nullptr;
  HAVS_GL_FUNCTIONS(HAVS_GL_MEMBER)
#undef HAVS_GL_MEMBER
};
GL gl;

bool Fail(const std::string& what)
{
  std::fprintf(stderr, "havs_gpu_bench: %s\n", what.c_str());
  return false;
}

/// An OpenGL 4.5 (else 4.3) core context without a surface.
bool MakeContext(std::string& platform)
{
  void* library = dlopen("libEGL.so.1", RTLD_NOW | RTLD_GLOBAL);
  if (!library)
  {
    return Fail("cannot open libEGL.so.1");
  }
  EGL egl;
  egl.GetProcAddress =
    reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(library, "eglGetProcAddress"));
  if (!egl.GetProcAddress)
  {
    return Fail("libEGL has no eglGetProcAddress");
  }
  auto get = [&](const char* name) -> void*
  {
    void* f = dlsym(library, name);
    return f ? f : reinterpret_cast<void*>(egl.GetProcAddress(name));
  };
  egl.GetDisplay = reinterpret_cast<PFNEGLGETDISPLAYPROC>(get("eglGetDisplay"));
  egl.Initialize = reinterpret_cast<PFNEGLINITIALIZEPROC>(get("eglInitialize"));
  egl.BindAPI = reinterpret_cast<PFNEGLBINDAPIPROC>(get("eglBindAPI"));
  egl.ChooseConfig = reinterpret_cast<PFNEGLCHOOSECONFIGPROC>(get("eglChooseConfig"));
  egl.CreateContext = reinterpret_cast<PFNEGLCREATECONTEXTPROC>(get("eglCreateContext"));
  egl.MakeCurrent = reinterpret_cast<PFNEGLMAKECURRENTPROC>(get("eglMakeCurrent"));
  egl.QueryString = reinterpret_cast<PFNEGLQUERYSTRINGPROC>(get("eglQueryString"));
  egl.QueryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(get("eglQueryDevicesEXT"));
  egl.GetPlatformDisplay =
    reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(get("eglGetPlatformDisplayEXT"));

  std::vector<std::pair<std::string, EGLDisplay>> displays;
  if (egl.QueryDevices && egl.GetPlatformDisplay)
  {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (egl.QueryDevices(8, devices, &count))
    {
      for (EGLint d = 0; d < count; ++d)
      {
        displays.emplace_back("device " + std::to_string(d),
          egl.GetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[d], nullptr));
      }
    }
  }
  if (egl.GetPlatformDisplay)
  {
    displays.emplace_back("surfaceless",
      egl.GetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
  }
  displays.emplace_back("default", egl.GetDisplay(EGL_DEFAULT_DISPLAY));
  for (const auto& [name, display] : displays)
  {
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !egl.Initialize(display, &major, &minor) ||
      !egl.BindAPI(EGL_OPENGL_API))
    {
      continue;
    }
    const EGLint configAttributes[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
    EGLConfig config = nullptr;
    EGLint configs = 0;
    egl.ChooseConfig(display, configAttributes, &config, 1, &configs);
    for (int minorVersion : { 5, 3 })
    {
      const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION,
        minorVersion, EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_NONE };
      EGLContext context = egl.CreateContext(
        display, configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttributes);
      if (context != EGL_NO_CONTEXT &&
        egl.MakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
      {
        platform = name + " (EGL " + std::to_string(major) + "." + std::to_string(minor) + ", " +
          (egl.QueryString(display, EGL_VENDOR) ? egl.QueryString(display, EGL_VENDOR) : "?") + ")";
#define HAVS_GL_LOAD(type, name)                                                                   \
  gl.name = reinterpret_cast<type>(egl.GetProcAddress("gl" #name));                                \
  if (!gl.name)                                                                                    \
  {                                                                                                \
    return Fail("no gl" #name);                                                                    \
  }
        HAVS_GL_FUNCTIONS(HAVS_GL_LOAD)
#undef HAVS_GL_LOAD
        return true;
      }
    }
  }
  return Fail("no EGL display gives an OpenGL 4.3 core context without a surface");
}

bool HasExtension(const char* name)
{
  GLint count = 0;
  gl.GetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
  {
    if (std::strcmp(reinterpret_cast<const char*>(gl.GetStringi(GL_EXTENSIONS, i)), name) == 0)
    {
      return true;
    }
  }
  return false;
}

// --- the case --------------------------------------------------------------------
struct Uniform
{
  std::string Name, Type;
  std::vector<float> Values;
};

struct Case
{
  std::string Dir;
  std::map<std::string, std::string> Keys;
  std::vector<Uniform> Uniforms;
  std::vector<float> Points, Scalars, Table, Result;
  std::vector<uint32_t> Indices;
  int Width = 0, Height = 0, K = 0, TableSize[3] = { 0, 0, 0 };
  long long Cells = 0;
  std::string Shader(const std::string& name) const;
  int Int(const std::string& key) const
  {
    auto it = this->Keys.find(key);
    return it == this->Keys.end() ? 0 : std::atoi(it->second.c_str());
  }
};

std::string ReadText(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string Case::Shader(const std::string& name) const
{
  return ReadText(this->Dir + "/" + name);
}

template <typename T>
bool ReadBinary(const std::string& path, std::vector<T>& out)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
  {
    return Fail("cannot read " + path);
  }
  const std::streamsize bytes = in.tellg();
  in.seekg(0);
  out.resize(static_cast<size_t>(bytes) / sizeof(T));
  in.read(reinterpret_cast<char*>(out.data()), bytes);
  return static_cast<bool>(in);
}

bool ReadCase(const std::string& dir, Case& c)
{
  c.Dir = dir;
  std::istringstream text(ReadText(dir + "/case.txt"));
  std::string line;
  while (std::getline(text, line))
  {
    std::istringstream words(line);
    std::string key;
    if (!(words >> key) || key[0] == '#')
    {
      continue;
    }
    if (key == "uniform")
    {
      Uniform u;
      int n = 0;
      words >> u.Name >> u.Type >> n;
      u.Values.resize(n);
      for (float& v : u.Values)
      {
        words >> v;
      }
      c.Uniforms.push_back(u);
      continue;
    }
    std::string rest;
    std::getline(words, rest);
    c.Keys[key] = rest.substr(
      rest.find_first_not_of(' ') == std::string::npos ? rest.size() : rest.find_first_not_of(' '));
  }
  c.Width = c.Int("width");
  c.Height = c.Int("height");
  c.K = c.Int("k");
  c.Cells = std::atoll(c.Keys["cells"].c_str());
  std::istringstream table(c.Keys["table"]);
  table >> c.TableSize[0] >> c.TableSize[1] >> c.TableSize[2];
  if (c.Width <= 0 || c.Height <= 0 || c.K <= 0 || c.TableSize[2] <= 0)
  {
    return Fail("not a frame case: " + dir + "/case.txt");
  }
  return ReadBinary(dir + "/points.f32", c.Points) && ReadBinary(dir + "/scalars.f32", c.Scalars) &&
    ReadBinary(dir + "/indices.u32", c.Indices) && ReadBinary(dir + "/table.f32", c.Table) &&
    ReadBinary(dir + "/result.f32", c.Result);
}

// --- GL helpers ------------------------------------------------------------------
GLuint Compile(GLenum type, const std::string& source, const std::string& name)
{
  GLuint shader = gl.CreateShader(type);
  const char* text = source.c_str();
  gl.ShaderSource(shader, 1, &text, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok)
  {
    char log[4096];
    gl.GetShaderInfoLog(shader, sizeof(log), nullptr, log);
    Fail(name + " does not compile:\n" + log);
    return 0;
  }
  return shader;
}

/// A program of the case's shaders, its uniforms set from the case.
GLuint Program(const Case& c, const std::string& vertex, const std::string& fragment)
{
  const std::string vs = c.Shader(vertex), fs = c.Shader(fragment);
  if (vs.empty() || fs.empty())
  {
    Fail("missing shader " + vertex + " or " + fragment);
    return 0;
  }
  GLuint v = Compile(GL_VERTEX_SHADER, vs, vertex), f = Compile(GL_FRAGMENT_SHADER, fs, fragment);
  if (!v || !f)
  {
    return 0;
  }
  GLuint program = gl.CreateProgram();
  gl.AttachShader(program, v);
  gl.AttachShader(program, f);
  gl.LinkProgram(program);
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
  {
    char log[4096];
    gl.GetProgramInfoLog(program, sizeof(log), nullptr, log);
    Fail(vertex + " + " + fragment + " do not link:\n" + log);
    return 0;
  }
  gl.UseProgram(program);
  for (const Uniform& u : c.Uniforms)
  {
    const GLint location = gl.GetUniformLocation(program, u.Name.c_str());
    if (location < 0)
    {
      continue;
    }
    if (u.Type == "int")
      gl.Uniform1i(location, static_cast<GLint>(u.Values[0]));
    else if (u.Type == "float")
      gl.Uniform1fv(location, 1, u.Values.data());
    else if (u.Type == "vec2")
      gl.Uniform2fv(location, 1, u.Values.data());
    else if (u.Type == "vec3")
      gl.Uniform3fv(location, 1, u.Values.data());
    else if (u.Type == "vec4")
      gl.Uniform4fv(location, 1, u.Values.data());
    else if (u.Type == "mat4")
      gl.UniformMatrix4fv(location, 1, GL_FALSE, u.Values.data());
  }
  const GLint table = gl.GetUniformLocation(program, "havsTable");
  if (table >= 0)
  {
    gl.Uniform1i(table, 0);
  }
  // The per-pixel passes index their storage by the viewport size, which the
  // captured (fetch) draw program may not use: set from the case.
  const GLint viewport = gl.GetUniformLocation(program, "havsViewportSize");
  if (viewport >= 0)
  {
    const float size[2] = { static_cast<float>(c.Width), static_cast<float>(c.Height) };
    gl.Uniform2fv(viewport, 1, size);
  }
  return program;
}

GLuint FloatTexture(int w, int h)
{
  GLuint t = 0;
  gl.GenTextures(1, &t);
  gl.BindTexture(GL_TEXTURE_2D, t);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, nullptr);
  return t;
}

GLuint Framebuffer(const std::vector<GLuint>& colors)
{
  GLuint fbo = 0;
  gl.GenFramebuffers(1, &fbo);
  gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
  for (size_t a = 0; a < colors.size(); ++a)
  {
    gl.FramebufferTexture2D(
      GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(a), GL_TEXTURE_2D, colors[a], 0);
  }
  return fbo;
}

void DrawBuffers(size_t n)
{
  std::vector<GLenum> buffers(n);
  for (size_t a = 0; a < n; ++a)
  {
    buffers[a] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(a);
  }
  gl.DrawBuffers(static_cast<GLsizei>(n), buffers.data());
}

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

/// One path's frame: clear, draw, resolve (functions), timed.
struct Path
{
  std::string Name;
  std::function<void()> Clear, Draw, Resolve;
  GLuint ResultFramebuffer = 0;
  bool HasResult = true;
};

struct Timing
{
  double Frame = 0, Draw = 0;
  unsigned long long Fragments = 0;
  double RMSE = 0, Max = 0;
};

Timing Run(const Case& c, Path& p, int frames)
{
  Timing t;
  GLuint query = 0;
  gl.GenQueries(1, &query);
  std::vector<double> frame, draw;
  for (int f = -2; f < frames; ++f) // two warm-up frames
  {
    gl.Finish();
    const double t0 = Now();
    p.Clear();
    gl.Finish();
    const double t1 = Now();
    if (f == 0)
    {
      gl.BeginQuery(GL_SAMPLES_PASSED, query);
    }
    p.Draw();
    if (f == 0)
    {
      gl.EndQuery(GL_SAMPLES_PASSED);
    }
    gl.Finish();
    const double t2 = Now();
    p.Resolve();
    gl.Finish();
    const double t3 = Now();
    if (f >= 0)
    {
      frame.push_back(t3 - t0);
      draw.push_back(t2 - t1);
    }
  }
  GLuint64 samples = 0;
  gl.GetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
  t.Fragments = samples;
  t.Frame = Median(frame);
  t.Draw = Median(draw);
  if (p.HasResult)
  {
    std::vector<float> image(static_cast<size_t>(c.Width) * c.Height * 4);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, p.ResultFramebuffer);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.ReadPixels(0, 0, c.Width, c.Height, GL_RGBA, GL_FLOAT, image.data());
    double sum = 0;
    for (size_t i = 0; i < image.size() && i < c.Result.size(); ++i)
    {
      const double d = std::isfinite(image[i]) ? std::abs(image[i] - c.Result[i]) : 1e30;
      sum += d * d;
      t.Max = std::max(t.Max, d);
    }
    t.RMSE = std::sqrt(sum / std::max<size_t>(1, image.size()));
  }
  return t;
}
}

int main(int argc, char* argv[])
{
  if (argc < 2 || argv[1][0] == '-')
  {
    std::printf("usage: havs_gpu_bench CASE_DIR [--frames N] [--paths fetch,interlock,raster] "
                "[--reverse-order] [--max-difference D]\n");
    return argc < 2 ? EXIT_FAILURE : EXIT_SUCCESS;
  }
  const std::string dir = argv[1];
  int frames = 10;
  std::string paths = "fetch,interlock,raster";
  bool reverse = false;
  double maxDifference = 2.0 / 255.0;
  for (int i = 2; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--frames")
      frames = std::max(1, std::atoi(next().c_str()));
    else if (a == "--paths")
      paths = next();
    else if (a == "--reverse-order")
      reverse = true;
    else if (a == "--max-difference")
      maxDifference = std::atof(next().c_str());
    else
    {
      std::fprintf(stderr, "havs_gpu_bench: unknown option %s\n", a.c_str());
      return EXIT_FAILURE;
    }
  }
  Case c;
  std::string platform;
  if (!ReadCase(dir, c) || !MakeContext(platform))
  {
    return EXIT_FAILURE;
  }
  const char* renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
  const char* version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
  const bool fetch = HasExtension("GL_EXT_shader_framebuffer_fetch");
  const bool arb = HasExtension("GL_ARB_fragment_shader_interlock");
  const bool nv = HasExtension("GL_NV_fragment_shader_interlock");
  const bool llvmpipe = renderer && std::strstr(renderer, "llvmpipe");
  std::printf("GPU: %s, OpenGL %s, EGL %s\n", renderer ? renderer : "?", version ? version : "?",
    platform.c_str());
  std::printf("framebuffer fetch %s, ARB interlock %s, NV interlock %s\n", fetch ? "yes" : "no",
    arb ? "yes" : "no", nv ? "yes" : "no");
  std::printf("case %s: %d x %d, k = %d, %lld cells, %zu faces, table %d x %d x %d, path captured "
              "%s, order %s\n",
    dir.c_str(), c.Width, c.Height, c.K, c.Cells, c.Indices.size() / 3, c.TableSize[0],
    c.TableSize[1], c.TableSize[2], c.Keys["captured_path"].c_str(),
    reverse ? "REVERSED (control)" : "as drawn");

  if (reverse)
  {
    std::vector<uint32_t> reversed(c.Indices.size());
    const size_t faces = c.Indices.size() / 3;
    for (size_t f = 0; f < faces; ++f)
    {
      std::copy_n(&c.Indices[3 * (faces - 1 - f)], 3, &reversed[3 * f]);
    }
    c.Indices.swap(reversed);
  }

  // Geometry and table.
  GLuint vao = 0, buffers[3] = { 0, 0, 0 };
  gl.GenVertexArrays(1, &vao);
  gl.BindVertexArray(vao);
  gl.GenBuffers(3, buffers);
  gl.BindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  gl.BufferData(GL_ARRAY_BUFFER, c.Points.size() * sizeof(float), c.Points.data(), GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  gl.BindBuffer(GL_ARRAY_BUFFER, buffers[1]);
  gl.BufferData(
    GL_ARRAY_BUFFER, c.Scalars.size() * sizeof(float), c.Scalars.data(), GL_STATIC_DRAW);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
  gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[2]);
  gl.BufferData(
    GL_ELEMENT_ARRAY_BUFFER, c.Indices.size() * sizeof(uint32_t), c.Indices.data(), GL_STATIC_DRAW);
  const GLsizei indexCount = static_cast<GLsizei>(c.Indices.size());
  GLuint quadVao = 0;
  gl.GenVertexArrays(1, &quadVao);

  GLuint table = 0;
  gl.ActiveTexture(GL_TEXTURE0);
  gl.GenTextures(1, &table);
  gl.BindTexture(GL_TEXTURE_3D, table);
  for (GLenum p : { GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER })
  {
    gl.TexParameteri(GL_TEXTURE_3D, p, GL_LINEAR);
  }
  for (GLenum p : { GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R })
  {
    gl.TexParameteri(GL_TEXTURE_3D, p, GL_CLAMP_TO_EDGE);
  }
  gl.TexImage3D(GL_TEXTURE_3D, 0, GL_RGBA32F, c.TableSize[0], c.TableSize[1], c.TableSize[2], 0,
    GL_RGBA, GL_FLOAT, c.Table.data());

  gl.Disable(GL_DEPTH_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_CULL_FACE);
  gl.Disable(GL_SCISSOR_TEST);
  gl.Viewport(0, 0, c.Width, c.Height);
  const bool flip = c.Int("flip_facing") != 0;
  auto drawFaces = [&](GLuint program)
  {
    gl.UseProgram(program);
    gl.BindVertexArray(vao);
    gl.FrontFace(flip ? GL_CW : GL_CCW);
    gl.DrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
    gl.FrontFace(GL_CCW);
  };
  auto drawQuad = [&](GLuint program)
  {
    gl.UseProgram(program);
    gl.BindVertexArray(quadVao);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
  };
  const GLuint result = FloatTexture(c.Width, c.Height);
  const GLuint resultFbo = Framebuffer({ result });

  std::vector<Path> run;
  std::vector<std::string> skipped;
  auto wanted = [&](const char* name) { return paths.find(name) != std::string::npos; };
  if (wanted("fetch") && fetch)
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
    const GLuint draw = Program(c, "face.vert", "fetch_draw.frag");
    const GLuint resolve = Program(c, "quad.vert", "fetch_resolve.frag");
    if (!draw || !resolve)
    {
      return EXIT_FAILURE;
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
    p.ResultFramebuffer = resultFbo;
    run.push_back(p);
  }
  else if (wanted("fetch"))
  {
    skipped.push_back("framebuffer fetch (no GL_EXT_shader_framebuffer_fetch)");
  }
  if (wanted("interlock") && (arb || nv || llvmpipe))
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
    const GLuint clear = Program(c, "quad.vert", "interlock_clear.frag");
    const GLuint draw = Program(c, "face.vert", shader);
    const GLuint resolve = Program(c, "quad.vert", "interlock_resolve.frag");
    if (!clear || !draw || !resolve)
    {
      return EXIT_FAILURE;
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
    p.ResultFramebuffer = resultFbo;
    run.push_back(p);
  }
  else if (wanted("interlock"))
  {
    skipped.push_back("interlock (no ARB or NV fragment_shader_interlock)");
  }
  if (wanted("raster"))
  {
    Path p;
    p.Name = "raster bound (trivial shader)";
    const GLuint draw = Program(c, "face.vert", "trivial.frag");
    if (!draw)
    {
      return EXIT_FAILURE;
    }
    p.Clear = [=]()
    {
      gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resultFbo);
      DrawBuffers(1);
      const float zero[4] = { 0, 0, 0, 0 };
      gl.ClearBufferfv(GL_COLOR, 0, zero);
    };
    p.Draw = [=]() { drawFaces(draw); };
    p.Resolve = []() {};
    p.HasResult = false;
    run.push_back(p);
  }

  std::printf("\n| path | frame ms (median of %d) | draw ms | Mtets/s | Mfragments/s | × raster "
              "bound | RMSE vs mapper | max vs mapper |\n|---|---|---|---|---|---|---|---|\n",
    frames);
  std::vector<Timing> timings;
  double rasterDraw = 0;
  for (Path& p : run)
  {
    timings.push_back(Run(c, p, frames));
    if (!p.HasResult)
    {
      rasterDraw = timings.back().Draw;
    }
  }
  int failures = 0;
  for (size_t i = 0; i < run.size(); ++i)
  {
    const Timing& t = timings[i];
    char ratio[32] = "-";
    if (rasterDraw > 0)
    {
      std::snprintf(ratio, sizeof(ratio), "%.2f", t.Frame / rasterDraw);
    }
    std::printf("| %s | %.2f | %.2f | %.1f | %.1f | %s | %s | %s |\n", run[i].Name.c_str(),
      1e3 * t.Frame, 1e3 * t.Draw, 1e-6 * c.Cells / std::max(1e-9, t.Draw),
      1e-6 * t.Fragments / std::max(1e-9, t.Draw), ratio,
      run[i].HasResult ? std::to_string(t.RMSE).c_str() : "-",
      run[i].HasResult ? std::to_string(t.Max).c_str() : "-");
    if (run[i].HasResult && !(t.Max <= maxDifference))
    {
      ++failures;
    }
  }
  for (const std::string& s : skipped)
  {
    std::printf("not run here: %s\n", s.c_str());
  }
  const GLenum error = gl.GetError();
  if (error != GL_NO_ERROR)
  {
    std::printf("GL error 0x%x\n", error);
    ++failures;
  }
  std::printf("%s\n",
    failures == 0 ? "every path drew the mapper's image"
                  : "FAILED: a path's image differs from the mapper's (or a GL error)");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
