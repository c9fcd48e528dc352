/*=========================================================================

  Project:   vtkHAVS
  Module:    havsGPUBench.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_gpu_bench's shared parts: the EGL context (and what is missing when
// there is none), the frame case, the GL helpers.
#include "havsGPUBench.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

#ifndef EGL_DRM_DEVICE_FILE_EXT
#define EGL_DRM_DEVICE_FILE_EXT 0x3233
#endif
#ifndef EGL_RENDERER_EXT
#define EGL_RENDERER_EXT 0x335F
#endif

namespace havsgpu
{
GL gl;

bool Fail(const std::string& what)
{
  std::fprintf(stderr, "havs_gpu_bench: %s\n", what.c_str());
  return false;
}

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

namespace
{
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
  PFNEGLGETERRORPROC GetError = nullptr;
  PFNEGLQUERYDEVICESEXTPROC QueryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceString = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplay = nullptr;
};

std::string Hex(unsigned int v)
{
  char text[16];
  std::snprintf(text, sizeof(text), "0x%x", v);
  return text;
}

bool Exists(const std::string& path)
{
  struct stat s;
  return stat(path.c_str(), &s) == 0;
}

/// What libglvnd needs to find an NVIDIA EGL driver, said when no context came.
void DiagnoseDrivers(Device& device)
{
  const char* vendorFiles = std::getenv("__EGL_VENDOR_LIBRARY_FILENAMES");
  const char* vendorDirs = std::getenv("__EGL_VENDOR_LIBRARY_DIRS");
  device.Diagnostics.push_back(std::string("__EGL_VENDOR_LIBRARY_FILENAMES=") +
    (vendorFiles ? vendorFiles : "(unset)") +
    ", __EGL_VENDOR_LIBRARY_DIRS=" + (vendorDirs ? vendorDirs : "(unset)"));
  for (const char* dir : { "/usr/share/glvnd/egl_vendor.d", "/etc/glvnd/egl_vendor.d",
         "/usr/local/nvidia/share/glvnd/egl_vendor.d" })
  {
    for (const char* file : { "10_nvidia.json", "50_mesa.json" })
    {
      const std::string path = std::string(dir) + "/" + file;
      if (Exists(path))
      {
        device.Diagnostics.push_back("vendor file present: " + path);
      }
    }
  }
  for (const char* library : { "libEGL_nvidia.so.0", "libnvidia-eglcore.so", "libnvidia-glcore.so",
         "libGLdispatch.so.0", "libEGL_mesa.so.0" })
  {
    // The versioned NVIDIA libraries are found by their soname's prefix in
    // the loader's path; a dlopen of the exact name says what the loader sees.
    void* handle = dlopen(library, RTLD_LAZY | RTLD_LOCAL);
    device.Diagnostics.push_back(std::string(library) + ": " +
      (handle ? "loads" : std::string("does not load (") + dlerror() + ")"));
    if (handle)
    {
      dlclose(handle);
    }
  }
}
}

bool MakeContext(Device& device)
{
  void* library = dlopen("libEGL.so.1", RTLD_NOW | RTLD_GLOBAL);
  if (!library)
  {
    device.Diagnostics.push_back(std::string("cannot open libEGL.so.1 (libglvnd): ") + dlerror() +
      "; carry libEGL.so.1 and libGLdispatch.so.0 and point __EGL_VENDOR_LIBRARY_FILENAMES at "
      "the driver's vendor file (README.md)");
    DiagnoseDrivers(device);
    return false;
  }
  EGL egl;
  egl.GetProcAddress =
    reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(library, "eglGetProcAddress"));
  if (!egl.GetProcAddress)
  {
    device.Diagnostics.push_back("libEGL.so.1 has no eglGetProcAddress");
    return false;
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
  egl.GetError = reinterpret_cast<PFNEGLGETERRORPROC>(get("eglGetError"));
  egl.QueryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(get("eglQueryDevicesEXT"));
  egl.QueryDeviceString =
    reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(get("eglQueryDeviceStringEXT"));
  egl.GetPlatformDisplay =
    reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(get("eglGetPlatformDisplayEXT"));
  const char* clientExtensions = egl.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const std::string client = clientExtensions ? clientExtensions : "";
  device.Diagnostics.push_back("EGL client extensions: " + (client.empty() ? "(none)" : client));

  struct Candidate
  {
    std::string Name, Device;
    EGLDisplay Display;
  };
  std::vector<Candidate> displays;
  if (egl.QueryDevices && egl.GetPlatformDisplay &&
    client.find("EGL_EXT_platform_device") != std::string::npos)
  {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (egl.QueryDevices(8, devices, &count))
    {
      device.Diagnostics.push_back("EGL devices: " + std::to_string(count));
      for (EGLint d = 0; d < count; ++d)
      {
        std::string what;
        if (egl.QueryDeviceString)
        {
          const char* file = egl.QueryDeviceString(devices[d], EGL_DRM_DEVICE_FILE_EXT);
          const char* extensions = egl.QueryDeviceString(devices[d], EGL_EXTENSIONS);
          what = std::string(file ? file : "no DRM file") + "; " + (extensions ? extensions : "");
        }
        displays.push_back({ "device " + std::to_string(d), what,
          egl.GetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[d], nullptr) });
      }
    }
    else
    {
      device.Diagnostics.push_back(
        "eglQueryDevicesEXT failed: " + Hex(egl.GetError ? egl.GetError() : 0));
    }
  }
  else
  {
    device.Diagnostics.push_back("no EGL_EXT_platform_device (libglvnd found no vendor with it)");
  }
  if (egl.GetPlatformDisplay && client.find("EGL_MESA_platform_surfaceless") != std::string::npos)
  {
    displays.push_back({ "surfaceless", "",
      egl.GetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr) });
  }
  displays.push_back({ "default", "", egl.GetDisplay(EGL_DEFAULT_DISPLAY) });
  for (const Candidate& candidate : displays)
  {
    EGLint major = 0, minor = 0;
    if (candidate.Display == EGL_NO_DISPLAY)
    {
      device.Diagnostics.push_back(candidate.Name + ": no display");
      continue;
    }
    if (!egl.Initialize(candidate.Display, &major, &minor))
    {
      device.Diagnostics.push_back(candidate.Name + ": eglInitialize failed, " +
        Hex(egl.GetError ? egl.GetError() : 0) +
        (candidate.Device.empty() ? "" : " (" + candidate.Device + ")"));
      continue;
    }
    if (!egl.BindAPI(EGL_OPENGL_API))
    {
      device.Diagnostics.push_back(candidate.Name + ": no desktop OpenGL API (eglBindAPI)");
      continue;
    }
    const EGLint configAttributes[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
    EGLConfig config = nullptr;
    EGLint configs = 0;
    egl.ChooseConfig(candidate.Display, configAttributes, &config, 1, &configs);
    for (int minorVersion : { 5, 3 })
    {
      const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION,
        minorVersion, EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_NONE };
      EGLContext context = egl.CreateContext(candidate.Display,
        configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttributes);
      if (context == EGL_NO_CONTEXT ||
        !egl.MakeCurrent(candidate.Display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
      {
        device.Diagnostics.push_back(candidate.Name + ": no OpenGL 4." +
          std::to_string(minorVersion) + " core context, " +
          Hex(egl.GetError ? egl.GetError() : 0));
        continue;
      }
      device.Platform = candidate.Name;
      device.EGLDevice = candidate.Device;
      device.EGLVersion = std::to_string(major) + "." + std::to_string(minor);
      const char* vendor = egl.QueryString(candidate.Display, EGL_VENDOR);
      device.EGLVendor = vendor ? vendor : "?";
#define HAVS_GL_LOAD(type, name)                                                                   \
  gl.name = reinterpret_cast<type>(egl.GetProcAddress("gl" #name));                                \
  if (!gl.name)                                                                                    \
  {                                                                                                \
    device.Diagnostics.push_back("the driver has no gl" #name);                                    \
    return false;                                                                                  \
  }
      HAVS_GL_FUNCTIONS(HAVS_GL_LOAD)
#undef HAVS_GL_LOAD
      auto text = [](GLenum name)
      {
        const char* s = reinterpret_cast<const char*>(gl.GetString(name));
        return std::string(s ? s : "?");
      };
      device.Renderer = text(GL_RENDERER);
      device.Version = text(GL_VERSION);
      device.Vendor = text(GL_VENDOR);
      device.Fetch = HasExtension("GL_EXT_shader_framebuffer_fetch");
      device.InterlockARB = HasExtension("GL_ARB_fragment_shader_interlock");
      device.InterlockNV = HasExtension("GL_NV_fragment_shader_interlock");
      device.Llvmpipe = device.Renderer.find("llvmpipe") != std::string::npos;
      return true;
    }
  }
  DiagnoseDrivers(device);
  return false;
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
std::string ReadText(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool ReadBytes(const std::string& path, std::vector<char>& out)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
  {
    return Fail("cannot read " + path);
  }
  const std::streamsize bytes = in.tellg();
  in.seekg(0);
  out.resize(static_cast<size_t>(bytes));
  in.read(out.data(), bytes);
  return static_cast<bool>(in);
}

std::string Case::Shader(const std::string& name) const
{
  return ReadText(this->Dir + "/" + name);
}

int Case::Int(const std::string& key) const
{
  auto it = this->Keys.find(key);
  return it == this->Keys.end() ? 0 : std::atoi(it->second.c_str());
}

double Case::Double(const std::string& key) const
{
  auto it = this->Keys.find(key);
  return it == this->Keys.end() ? 0.0 : std::atof(it->second.c_str());
}

bool Case::Has(const std::string& file) const
{
  return Exists(this->Dir + "/" + file);
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
      words >> u.Program >> u.Name >> u.Type >> n;
      for (int i = 0; i < n; ++i)
      {
        std::string value;
        words >> value;
        u.Values.push_back(std::strtof(value.c_str(), nullptr));
        u.Integers.push_back(std::strtoll(value.c_str(), nullptr, 10));
      }
      c.Uniforms.push_back(u);
      continue;
    }
    std::string rest;
    std::getline(words, rest);
    const size_t first = rest.find_first_not_of(' ');
    c.Keys[key] = first == std::string::npos ? "" : rest.substr(first);
  }
  c.Mapper = c.Keys["mapper"];
  c.Width = c.Int("width");
  c.Height = c.Int("height");
  c.Cells = std::atoll(c.Keys["cells"].c_str());
  std::istringstream table(c.Keys["table"]);
  table >> c.TableSize[0] >> c.TableSize[1] >> c.TableSize[2];
  if (c.Int("format") != 2 || c.Width <= 0 || c.Height <= 0 || c.TableSize[2] <= 0)
  {
    return Fail("not a frame case of format 2: " + dir + "/case.txt");
  }
  if (c.Has("result.f32") && !ReadArray(dir + "/result.f32", c.Result))
  {
    return false;
  }
  std::vector<uint16_t> steps;
  if (c.Has("reference.u16") && !ReadArray(dir + "/reference.u16", steps))
  {
    return false;
  }
  c.Exact.resize(steps.size());
  for (size_t i = 0; i < steps.size(); ++i)
  {
    c.Exact[i] = static_cast<float>(steps[i]) / 65535.0f;
  }
  if (c.Has("folded.u8") && !ReadArray(dir + "/folded.u8", c.Folded))
  {
    return false;
  }
  return true;
}

// --- GL helpers ------------------------------------------------------------------
namespace
{
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

/// A program of `shaders` (deleted here); 0, with the log printed, when it does not link.
GLuint Link(const std::vector<GLuint>& shaders, const std::string& name)
{
  GLuint program = gl.CreateProgram();
  for (GLuint shader : shaders)
  {
    gl.AttachShader(program, shader);
  }
  gl.LinkProgram(program);
  for (GLuint shader : shaders)
  {
    gl.DeleteShader(shader);
  }
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
  {
    char log[4096];
    gl.GetProgramInfoLog(program, sizeof(log), nullptr, log);
    Fail(name + " does not link:\n" + log);
    return 0;
  }
  return program;
}
}

GLuint ComputeProgram(const Case& c, const std::string& shader)
{
  const std::string source = c.Shader(shader);
  if (source.empty())
  {
    Fail("missing shader " + shader);
    return 0;
  }
  const GLuint s = Compile(GL_COMPUTE_SHADER, source, shader);
  return s ? Link({ s }, shader) : 0;
}

GLuint Program(
  const Case& c, const std::string& vertex, const std::string& fragment, const std::string& name)
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
  const GLuint program = Link({ v, f }, vertex + " + " + fragment);
  if (!program)
  {
    return 0;
  }
  gl.UseProgram(program);
  for (const Uniform& u : c.Uniforms)
  {
    const GLint location = gl.GetUniformLocation(program, u.Name.c_str());
    if (u.Program != name || location < 0 || u.Values.empty())
    {
      continue;
    }
    if (u.Type == "int")
      gl.Uniform1i(location, static_cast<GLint>(u.Integers[0]));
    else if (u.Type == "uint")
      gl.Uniform1ui(location, static_cast<GLuint>(u.Integers[0]));
    else if (u.Type == "ivec2" && u.Values.size() >= 2)
      gl.Uniform2i(location, static_cast<GLint>(u.Integers[0]), static_cast<GLint>(u.Integers[1]));
    else if (u.Type == "float")
      gl.Uniform1fv(location, 1, u.Values.data());
    else if (u.Type == "vec2")
      gl.Uniform2fv(location, 1, u.Values.data());
    else if (u.Type == "vec3")
      gl.Uniform3fv(location, 1, u.Values.data());
    else if (u.Type == "vec4")
      gl.Uniform4fv(location, 1, u.Values.data());
    else if (u.Type == "mat3")
      gl.UniformMatrix3fv(location, 1, GL_FALSE, u.Values.data());
    else if (u.Type == "mat4")
      gl.UniformMatrix4fv(location, 1, GL_FALSE, u.Values.data());
  }
  const GLint table = gl.GetUniformLocation(program, "havsTable");
  if (table >= 0)
  {
    gl.Uniform1i(table, 0);
  }
  // The per-pixel passes index their storage by the viewport size, which the
  // captured program may not use: set from the case.
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

GLuint Buffer(GLenum target, const void* data, size_t bytes, GLenum usage)
{
  GLuint buffer = 0;
  gl.GenBuffers(1, &buffer);
  gl.BindBuffer(target, buffer);
  gl.BufferData(target, static_cast<GLsizeiptr>(std::max<size_t>(bytes, 4)), data, usage);
  return buffer;
}

GLuint TableTexture(const Case& c)
{
  std::vector<float> values;
  if (!ReadArray(c.Dir + "/table.f32", values) ||
    values.size() != static_cast<size_t>(c.TableSize[0]) * c.TableSize[1] * c.TableSize[2] * 4)
  {
    Fail("table.f32 does not hold the table of case.txt's size");
    return 0;
  }
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
    GL_RGBA, GL_FLOAT, values.data());
  return table;
}

std::vector<float> ReadImage(GLuint framebuffer, int width, int height)
{
  std::vector<float> image(static_cast<size_t>(width) * height * 4);
  gl.BindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, image.data());
  return image;
}

void ClearTarget(GLuint framebuffer)
{
  gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  DrawBuffers(1);
  gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const float zero[4] = { 0, 0, 0, 0 };
  gl.ClearBufferfv(GL_COLOR, 0, zero);
}

void SetCompositeBlending()
{
  gl.Enable(GL_BLEND);
  gl.BlendEquation(GL_FUNC_ADD);
  gl.BlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
}

void SetInt(GLuint program, const char* name, int value)
{
  gl.UseProgram(program);
  const GLint location = gl.GetUniformLocation(program, name);
  if (location >= 0)
  {
    gl.Uniform1i(location, value);
  }
}

void ParkUnreadSamplers(GLuint program)
{
  SetInt(program, "havsOpaqueDepth", 1);
  SetInt(program, "havsAdditive", 2);
  SetInt(program, "havsCellOptics", 3);
}

constexpr GLuint CellRecords::Bindings[4];

bool CellRecords::Split(const Case& c, size_t tetrahedra, const std::string& shader)
{
  const double perBufferKey = c.Double("cells_per_record_buffer");
  this->CellsPerBuffer =
    perBufferKey > 0 ? static_cast<size_t>(perBufferKey) : std::max<size_t>(tetrahedra, 1);
  this->Count = std::max<size_t>((tetrahedra + this->CellsPerBuffer - 1) / this->CellsPerBuffer, 1);
  const std::string define = "#define HAVS_CELL_BUFFERS ";
  const std::string source = c.Shader(shader);
  const size_t at = source.find(define);
  const size_t defined =
    at == std::string::npos ? 0 : std::strtoul(source.c_str() + at + define.size(), nullptr, 10);
  if (this->Count > 4 || this->Count != defined ||
    (c.Keys.count("record_buffers") && static_cast<size_t>(c.Int("record_buffers")) != this->Count))
  {
    return Fail("the cell records' split of " + c.Dir +
      " (record_buffers, cells_per_record_buffer, " + shader + "'s HAVS_CELL_BUFFERS) disagrees");
  }
  return true;
}

void CellRecords::Upload(const std::vector<float>& records)
{
  const size_t tetrahedra = records.size() / FloatsPerCell;
  this->Buffers.clear();
  for (size_t i = 0; i < this->Count; ++i)
  {
    const size_t first = i * this->CellsPerBuffer;
    const size_t n = std::min(this->CellsPerBuffer, tetrahedra - std::min(first, tetrahedra));
    this->Buffers.push_back(Buffer(GL_SHADER_STORAGE_BUFFER, records.data() + FloatsPerCell * first,
      FloatsPerCell * n * sizeof(float)));
  }
  gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void CellRecords::Bind() const
{
  for (size_t i = 0; i < this->Buffers.size(); ++i)
  {
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, Bindings[i], this->Buffers[i]);
  }
}

void CellRecords::SetUniforms(GLuint program) const
{
  if (this->Buffers.size() > 1)
  {
    SetInt(program, "havsCellsPerBuffer", static_cast<int>(this->CellsPerBuffer));
  }
}
}
