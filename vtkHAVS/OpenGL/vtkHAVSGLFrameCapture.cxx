/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLFrameCapture.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLFrameCapture.h"

#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLMesh.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSShaders.h"
#include "vtkHAVSViewFrame.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtksys/SystemTools.hxx"

#include <cstdint>
#include <fstream>
#include <sstream>
#include <vector>

VTK_ABI_NAMESPACE_BEGIN

namespace
{
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFrameCapture::WriteBytes(const std::string& path, const void* data, size_t bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
  return static_cast<bool>(out);
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFrameCapture::WriteText(const std::string& path, const std::string& text)
{
  std::ofstream out(path);
  out << text;
  return static_cast<bool>(out);
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFrameCapture::MakeDirectory(const std::string& directory, std::string& error)
{
  if (!vtksys::SystemTools::MakeDirectory(directory))
  {
    error = "cannot make " + directory;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkHAVSGLFrameCapture::Header(
  const std::string& mapper, int width, int height, const int tableSize[3])
{
  std::ostringstream text;
  text << "# vtkHAVS frame case (Apps/GPUBench/README.md): the stand-alone GPU program's input\n"
       << "format 2\nmapper " << mapper << "\nwidth " << width << "\nheight " << height
       << "\ntable " << tableSize[0] << " " << tableSize[1] << " " << tableSize[2] << "\n";
  return text.str();
}

//------------------------------------------------------------------------------
std::vector<float> vtkHAVSGLFrameCapture::ReadTable(vtkTextureObject* table, int size[3])
{
  size[0] = table->GetWidth();
  size[1] = table->GetHeight();
  size[2] = table->GetDepth();
  std::vector<float> values(static_cast<size_t>(size[0]) * size[1] * size[2] * 4);
  table->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, values.data());
  table->Deactivate();
  return values;
}

//------------------------------------------------------------------------------
std::string vtkHAVSGLFrameCapture::UniformLines(const std::string& programName, unsigned int handle)
{
  const GLuint program = handle;
  std::ostringstream lines;
  lines.precision(9);
  GLint count = 0, longest = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
  std::vector<char> name(static_cast<size_t>(longest) + 1);
  for (GLint u = 0; u < count; ++u)
  {
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, u, longest, nullptr, &size, &type, name.data());
    std::string base(name.data());
    const size_t bracket = base.find('[');
    if (bracket != std::string::npos)
    {
      base = base.substr(0, bracket);
    }
    int components = 0;
    bool integer = false;
    const char* typeName = nullptr;
    switch (type)
    {
      case GL_FLOAT:
        components = 1, typeName = "float";
        break;
      case GL_FLOAT_VEC2:
        components = 2, typeName = "vec2";
        break;
      case GL_FLOAT_VEC3:
        components = 3, typeName = "vec3";
        break;
      case GL_FLOAT_VEC4:
        components = 4, typeName = "vec4";
        break;
      case GL_FLOAT_MAT3:
        components = 9, typeName = "mat3";
        break;
      case GL_FLOAT_MAT4:
        components = 16, typeName = "mat4";
        break;
      case GL_INT:
      case GL_BOOL:
        components = 1, integer = true, typeName = "int";
        break;
      case GL_INT_VEC2:
        components = 2, integer = true, typeName = "ivec2";
        break;
      case GL_UNSIGNED_INT:
        components = 1, integer = true, typeName = "uint";
        break;
      default: // samplers and images: bound by the program that draws
        continue;
    }
    for (GLint i = 0; i < size; ++i)
    {
      const std::string element = size > 1 ? base + "[" + std::to_string(i) + "]" : base;
      const GLint location = glGetUniformLocation(program, element.c_str());
      if (location < 0)
      {
        continue;
      }
      lines << "uniform " << programName << " " << element << " " << typeName << " " << components;
      if (integer)
      {
        GLint values[4] = {};
        glGetUniformiv(program, location, values);
        for (int c = 0; c < components; ++c)
        {
          lines << " " << (type == GL_UNSIGNED_INT ? static_cast<GLuint>(values[c]) : values[c]);
        }
      }
      else
      {
        float values[16] = {};
        glGetUniformfv(program, location, values);
        for (int c = 0; c < components; ++c)
        {
          lines << " " << values[c];
        }
      }
      lines << "\n";
    }
  }
  return lines.str();
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFrameCapture::Write(
  const std::string& directory, vtkHAVSGLPassContext& context, vtkIdType cells, std::string& error)
{
  using Shaders = vtkHAVSShaders;
  const vtkHAVSFrameRequest& request = context.Request;
  const bool fetch = request.Path == vtkHAVSFrameRequest::PathFramebufferFetch;
  const bool interlock = request.Path == vtkHAVSFrameRequest::PathFragmentShaderInterlock;
  if ((!fetch && !interlock) || request.BlendMode != vtkHAVSFrameRequest::CompositeBlend ||
    request.RasterBoundOnly)
  {
    error = "only composite frames of the framebuffer-fetch or interlock path are captured";
    return false;
  }
  if (request.CellScalars)
  {
    error = "frames of cell scalars are not captured (the stand-alone program reads one scalar "
            "per vertex)";
    return false;
  }
  if (request.Opaque || context.Mesh->HasSections() || request.CountViolations)
  {
    error = "frames with opaque geometry, plane sections or the violation counter are not "
            "captured (the stand-alone program draws the faces alone)";
    return false;
  }
  if (!MakeDirectory(directory, error))
  {
    return false;
  }
  const std::string dir = directory + "/";
  const Shaders::Features features = context.ShaderFeatures();
  const int k = request.K;

  // The draw program of the frame's path, for its uniforms (the shader cache
  // gives back the program the frame used, its uniforms set again).
  const std::string drawShader = fetch
    ? Shaders::FetchDrawShader(k, features)
    : Shaders::InterlockDrawShader(k, vtkHAVSGLCapabilities::AvailableInterlock(), features);
  vtkShaderProgram* program = context.FaceProgram(drawShader);
  if (!program)
  {
    error = "the draw program is not available";
    return false;
  }
  const std::string uniforms = UniformLines("draw", program->GetHandle());

  std::vector<float> points, scalars, result;
  std::vector<uint32_t> indices;
  context.Mesh->ReadBack(points, scalars, indices);
  int tableSize[3];
  const std::vector<float> table = ReadTable(context.Table->GetTable(), tableSize);
  context.Targets->ReadResult(result);

  std::ostringstream text;
  text << Header("havs", context.Width(), context.Height(), tableSize) << "k " << k << "\ncells "
       << cells << "\nvertices " << scalars.size() << "\nindices " << indices.size()
       << "\nflip_facing " << (request.View->FlipFacing ? 1 : 0) << "\ntagging "
       << (features.Tagging ? 1 : 0) << "\ncaptured_path " << (fetch ? "fetch" : "interlock")
       << "\nfetch_attachments " << Shaders::FetchAttachments(k) << "\ninterlock_stride "
       << Shaders::InterlockPixelStride(k) << "\nlist_capacity " << Shaders::ListResolveCapacity
       << "\n"
       << uniforms;

  const int fetchPath = vtkHAVSFrameRequest::PathFramebufferFetch;
  const int interlockPath = vtkHAVSFrameRequest::PathFragmentShaderInterlock;
  const int listPath = vtkHAVSFrameRequest::PathFragmentLists;
  bool ok = WriteText(dir + "case.txt", text.str()) && WriteArray(dir + "points.f32", points) &&
    WriteArray(dir + "scalars.f32", scalars) && WriteArray(dir + "indices.u32", indices) &&
    WriteArray(dir + "table.f32", table) && WriteArray(dir + "result.f32", result) &&
    WriteText(dir + "face.vert", Shaders::FaceVertexShader()) &&
    WriteText(dir + "quad.vert", Shaders::QuadVertexShader()) &&
    WriteText(dir + "trivial.frag", Shaders::TrivialShader()) &&
    WriteText(dir + "fetch_draw.frag", Shaders::FetchDrawShader(k, features)) &&
    WriteText(dir + "fetch_resolve.frag", Shaders::ResolveShader(fetchPath, k, false, features)) &&
    WriteText(dir + "interlock_arb_draw.frag",
      Shaders::InterlockDrawShader(k, Shaders::InterlockARB, features)) &&
    WriteText(dir + "interlock_nv_draw.frag",
      Shaders::InterlockDrawShader(k, Shaders::InterlockNV, features)) &&
    WriteText(dir + "interlock_none_draw.frag",
      Shaders::InterlockDrawShader(k, Shaders::InterlockNone, features)) &&
    WriteText(dir + "interlock_clear.frag", Shaders::InterlockClearShader(k)) &&
    WriteText(
      dir + "interlock_resolve.frag", Shaders::ResolveShader(interlockPath, k, false, features)) &&
    WriteText(dir + "list_draw.frag", Shaders::ListDrawShader(features)) &&
    WriteText(dir + "list_resolve.frag", Shaders::ResolveShader(listPath, k, false, features)) &&
    WriteText(dir + "list_resolve_vote.frag", Shaders::ResolveShader(listPath, k, true, features));
  if (!ok)
  {
    error = "cannot write the case into " + directory;
  }
  return ok;
}

VTK_ABI_NAMESPACE_END
