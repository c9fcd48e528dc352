/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSKBufferRenderer.cxx

=========================================================================*/
#include "vtkHAVSKBufferRenderer.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtk_glew.h"

#include "vtkHAVSClearFS.h"
#include "vtkHAVSCompositeFS.h"
#include "vtkHAVSExtremumDrawFS.h"
#include "vtkHAVSExtremumResolveFS.h"
#include "vtkHAVSFaceVS.h"
#include "vtkHAVSFetchDrawFS.h"
#include "vtkHAVSInterlockDrawFS.h"
#include "vtkHAVSKBufferLib.h"
#include "vtkHAVSListDrawFS.h"
#include "vtkHAVSQuadVS.h"
#include "vtkHAVSResolveFS.h"

#include <algorithm>
#include <cstring>
#include <sstream>

vtkStandardNewMacro(vtkHAVSKBufferRenderer);

namespace
{
const float kEmpty = 3.0e38f;
const float kNoFront = -2.0e38f;

void Replace(std::string& text, const std::string& marker, const std::string& with)
{
  const size_t at = text.find(marker);
  if (at != std::string::npos)
  {
    text.replace(at, marker.size(), with);
  }
}

bool HasGLExtension(const char* name)
{
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i)
  {
    const char* ext = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
    if (ext && std::strcmp(ext, name) == 0)
    {
      return true;
    }
  }
  return false;
}

bool HasGLVersion(int major, int minor)
{
  GLint maj = 0, min = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &maj);
  glGetIntegerv(GL_MINOR_VERSION, &min);
  return maj > major || (maj == major && min >= minor);
}

int EntryAttachments(int k)
{
  return (k + 1) / 2;
}

/// The fragment-shader source of a pass: the template with the k-buffer
/// library and the defines inserted.
std::string ComposeShader(const char* templ, int k, int pixelStride)
{
  std::string source = templ;
  std::ostringstream defines;
  defines << "#define HAVS_K " << k << "\n#define HAVS_PIXEL_STRIDE " << pixelStride << "\n";
  Replace(source, "//HAVS::Defines", defines.str());
  Replace(source, "//HAVS::KBufferLib", vtkHAVSKBufferLib);
  return source;
}

vtkSmartPointer<vtkTextureObject> NewFloatTexture(vtkOpenGLRenderWindow* window, int w, int h)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetInternalFormat(GL_RGBA32F);
  texture->SetFormat(GL_RGBA);
  texture->SetDataType(GL_FLOAT);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->Allocate2D(w, h, 4, VTK_FLOAT);
  return texture;
}

double Now()
{
  return vtkTimerLog::GetUniversalTime();
}
}

struct vtkHAVSKBufferRenderer::Internals
{
  vtkOpenGLRenderWindow* Window = nullptr;

  // Mesh
  GLuint VertexArray = 0;
  GLuint EmptyVertexArray = 0; // full-viewport passes draw from gl_VertexID
  GLuint PointBuffer = 0;
  GLuint ScalarBuffer = 0;
  GLuint IndexBuffer = 0;
  GLsizei IndexCount = 0;
  vtkSmartPointer<vtkOpenGLBufferObject> BoundaryBuffer;
  vtkSmartPointer<vtkTextureObject> BoundaryTexture;
  bool HaveGeometry = false;
  bool HaveOrder = false;

  // Transfer function
  vtkSmartPointer<vtkTextureObject> Table;
  vtkSmartPointer<vtkTextureObject> TransferFunction1D;
  int ScalarResolution = 0;
  int LengthResolution = 0;
  double MaxLength = 1.0;
  bool HaveTable = false;

  // Per-size targets
  int Size[2] = { 0, 0 };
  vtkSmartPointer<vtkTextureObject> OpaqueDepth;
  vtkSmartPointer<vtkTextureObject> Result;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ResultFramebuffer;
  // framebuffer-fetch path
  std::vector<vtkSmartPointer<vtkTextureObject>> FetchTargets; // colour, then entry pairs
  vtkSmartPointer<vtkOpenGLFramebufferObject> FetchFramebuffer;
  int FetchK = 0;
  // interlock path
  GLuint PixelEntries = 0;
  size_t PixelEntriesBytes = 0;
  // fragment-list path
  GLuint ListHeads = 0;
  GLuint ListNodes = 0;
  GLuint ListCounter = 0;
  GLuint ListCapacity = 0;
  int ListHeadsSize[2] = { 0, 0 };

  void ReleaseSizeDependent()
  {
    if (this->OpaqueDepth)
    {
      this->OpaqueDepth->ReleaseGraphicsResources(this->Window);
    }
    if (this->Result)
    {
      this->Result->ReleaseGraphicsResources(this->Window);
    }
    if (this->ResultFramebuffer)
    {
      this->ResultFramebuffer->ReleaseGraphicsResources(this->Window);
    }
    for (auto& t : this->FetchTargets)
    {
      t->ReleaseGraphicsResources(this->Window);
    }
    if (this->FetchFramebuffer)
    {
      this->FetchFramebuffer->ReleaseGraphicsResources(this->Window);
    }
    this->OpaqueDepth = nullptr;
    this->Result = nullptr;
    this->ResultFramebuffer = nullptr;
    this->FetchTargets.clear();
    this->FetchFramebuffer = nullptr;
    this->FetchK = 0;
    this->Size[0] = this->Size[1] = 0;
    if (this->PixelEntries)
    {
      glDeleteBuffers(1, &this->PixelEntries);
      this->PixelEntries = 0;
      this->PixelEntriesBytes = 0;
    }
    if (this->ListHeads)
    {
      glDeleteTextures(1, &this->ListHeads);
      this->ListHeads = 0;
      this->ListHeadsSize[0] = this->ListHeadsSize[1] = 0;
    }
  }

  void ReleaseAll()
  {
    this->ReleaseSizeDependent();
    GLuint buffers[] = { this->PointBuffer, this->ScalarBuffer, this->IndexBuffer,
      this->ListNodes, this->ListCounter };
    for (GLuint b : buffers)
    {
      if (b)
      {
        glDeleteBuffers(1, &b);
      }
    }
    this->PointBuffer = this->ScalarBuffer = this->IndexBuffer = 0;
    this->ListNodes = this->ListCounter = 0;
    this->ListCapacity = 0;
    if (this->VertexArray)
    {
      glDeleteVertexArrays(1, &this->VertexArray);
      this->VertexArray = 0;
    }
    if (this->EmptyVertexArray)
    {
      glDeleteVertexArrays(1, &this->EmptyVertexArray);
      this->EmptyVertexArray = 0;
    }
    if (this->BoundaryTexture)
    {
      this->BoundaryTexture->ReleaseGraphicsResources(this->Window);
    }
    if (this->BoundaryBuffer)
    {
      this->BoundaryBuffer->ReleaseGraphicsResources();
    }
    if (this->Table)
    {
      this->Table->ReleaseGraphicsResources(this->Window);
    }
    if (this->TransferFunction1D)
    {
      this->TransferFunction1D->ReleaseGraphicsResources(this->Window);
    }
    this->BoundaryTexture = nullptr;
    this->BoundaryBuffer = nullptr;
    this->Table = nullptr;
    this->TransferFunction1D = nullptr;
    this->IndexCount = 0;
    this->HaveGeometry = this->HaveOrder = this->HaveTable = false;
  }

  vtkShaderProgram* Program(const std::string& vs, const std::string& fs)
  {
    vtkShaderProgram* program =
      this->Window->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), "");
    return (program && program->GetCompiled()) ? program : nullptr;
  }

  void DrawFullViewport()
  {
    if (!this->EmptyVertexArray)
    {
      glGenVertexArrays(1, &this->EmptyVertexArray);
    }
    glBindVertexArray(this->EmptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
  }

  void DrawFaces(bool flipFacing)
  {
    glFrontFace(flipFacing ? GL_CW : GL_CCW);
    glBindVertexArray(this->VertexArray);
    glDrawElements(GL_TRIANGLES, this->IndexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glFrontFace(GL_CCW);
  }
};

//------------------------------------------------------------------------------
vtkHAVSKBufferRenderer::vtkHAVSKBufferRenderer()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkHAVSKBufferRenderer::~vtkHAVSKBufferRenderer()
{
  if (this->Internal->Window)
  {
    vtkErrorMacro("ReleaseGraphicsResources was not called before destruction.");
  }
}

//------------------------------------------------------------------------------
const char* vtkHAVSKBufferRenderer::GetPathName(int path)
{
  switch (path)
  {
    case FramebufferFetch:
      return "FramebufferFetch";
    case FragmentShaderInterlock:
      return "FragmentShaderInterlock";
    case FragmentLists:
      return "FragmentLists";
    default:
      return "None";
  }
}

//------------------------------------------------------------------------------
int vtkHAVSKBufferRenderer::GetMaximumK(int path)
{
  switch (path)
  {
    case FramebufferFetch:
      return MaximumFetchK;
    case FragmentShaderInterlock:
      return MaximumInterlockK;
    case FragmentLists:
      return ListResolveCapacity;
    default:
      return 0;
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSKBufferRenderer::IsPathSupported(vtkOpenGLRenderWindow* window, int path)
{
  if (!window)
  {
    return false;
  }
  window->MakeCurrent();
  if (!HasGLVersion(4, 3))
  {
    return false;
  }
  switch (path)
  {
    case FramebufferFetch:
    {
      GLint drawBuffers = 0;
      glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
      return HasGLExtension("GL_EXT_shader_framebuffer_fetch") && drawBuffers >= 8;
    }
    case FragmentShaderInterlock:
      return HasGLExtension("GL_ARB_fragment_shader_interlock") ||
        HasGLExtension("GL_NV_fragment_shader_interlock");
    case FragmentLists:
      return HasGLVersion(4, 4) || HasGLExtension("GL_ARB_clear_texture");
    default:
      return false;
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSKBufferRenderer::PrepareWindow(vtkOpenGLRenderWindow* window)
{
  Internals& in = *this->Internal;
  if (in.Window == window)
  {
    window->MakeCurrent();
    return !(in.HaveGeometry && in.HaveOrder && in.HaveTable);
  }
  if (in.Window)
  {
    in.Window->MakeCurrent();
    in.ReleaseAll();
  }
  in.Window = window;
  window->MakeCurrent();
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSKBufferRenderer::SetGeometry(
  const std::vector<float>& pointsMC, const std::vector<float>& scalars)
{
  Internals& in = *this->Internal;
  if (!in.VertexArray)
  {
    glGenVertexArrays(1, &in.VertexArray);
    glGenBuffers(1, &in.PointBuffer);
    glGenBuffers(1, &in.ScalarBuffer);
    glGenBuffers(1, &in.IndexBuffer);
  }
  glBindVertexArray(in.VertexArray);
  glBindBuffer(GL_ARRAY_BUFFER, in.PointBuffer);
  glBufferData(GL_ARRAY_BUFFER, pointsMC.size() * sizeof(float), pointsMC.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, in.ScalarBuffer);
  glBufferData(GL_ARRAY_BUFFER, scalars.size() * sizeof(float), scalars.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, in.IndexBuffer);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  in.HaveGeometry = true;
}

//------------------------------------------------------------------------------
void vtkHAVSKBufferRenderer::SetFaceOrder(
  const std::vector<uint32_t>& triangles, const std::vector<uint8_t>& boundary)
{
  Internals& in = *this->Internal;
  if (!in.VertexArray)
  {
    vtkErrorMacro("SetFaceOrder before SetGeometry.");
    return;
  }
  glBindVertexArray(in.VertexArray);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, in.IndexBuffer);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, triangles.size() * sizeof(uint32_t), triangles.data(),
    GL_STREAM_DRAW);
  glBindVertexArray(0);
  in.IndexCount = static_cast<GLsizei>(triangles.size());

  if (!in.BoundaryBuffer)
  {
    in.BoundaryBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    in.BoundaryTexture = vtkSmartPointer<vtkTextureObject>::New();
    in.BoundaryTexture->SetContext(in.Window);
  }
  // One byte per face: 255 for a boundary face (read as 1.0 from an R8 buffer).
  std::vector<uint8_t> flags(std::max<size_t>(boundary.size(), 1), 0);
  for (size_t i = 0; i < boundary.size(); ++i)
  {
    flags[i] = boundary[i] ? 255 : 0;
  }
  in.BoundaryBuffer->Upload(flags, vtkOpenGLBufferObject::TextureBuffer);
  in.BoundaryTexture->CreateTextureBuffer(
    static_cast<unsigned int>(flags.size()), 1, VTK_UNSIGNED_CHAR, in.BoundaryBuffer);
  in.HaveOrder = true;
}

//------------------------------------------------------------------------------
void vtkHAVSKBufferRenderer::SetTable(const float* table, int scalarResolution,
  int lengthResolution, double maxLength, const std::vector<float>& transferFunction1D)
{
  Internals& in = *this->Internal;
  if (!in.Table)
  {
    in.Table = vtkSmartPointer<vtkTextureObject>::New();
    in.Table->SetContext(in.Window);
    in.TransferFunction1D = vtkSmartPointer<vtkTextureObject>::New();
    in.TransferFunction1D->SetContext(in.Window);
  }
  for (vtkTextureObject* t : { in.Table.Get(), in.TransferFunction1D.Get() })
  {
    t->SetInternalFormat(GL_RGBA32F);
    t->SetFormat(GL_RGBA);
    t->SetDataType(GL_FLOAT);
    t->SetMinificationFilter(vtkTextureObject::Linear);
    t->SetMagnificationFilter(vtkTextureObject::Linear);
    t->SetWrapS(vtkTextureObject::ClampToEdge);
    t->SetWrapT(vtkTextureObject::ClampToEdge);
    t->SetWrapR(vtkTextureObject::ClampToEdge);
  }
  in.Table->Create3DFromRaw(scalarResolution, scalarResolution, lengthResolution, 4, VTK_FLOAT,
    const_cast<float*>(table));
  in.TransferFunction1D->Create1DFromRaw(static_cast<unsigned int>(transferFunction1D.size() / 4),
    4, VTK_FLOAT, const_cast<float*>(transferFunction1D.data()));
  in.ScalarResolution = scalarResolution;
  in.LengthResolution = lengthResolution;
  in.MaxLength = maxLength > 0.0 ? maxLength : 1.0;
  in.HaveTable = true;
}

//------------------------------------------------------------------------------
bool vtkHAVSKBufferRenderer::Render(vtkRenderer* renderer, const FrameParameters& p)
{
  Internals& in = *this->Internal;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window || window != in.Window)
  {
    vtkErrorMacro("Render called on a window whose resources were not prepared.");
    return false;
  }
  if (!in.HaveGeometry || !in.HaveOrder || !in.HaveTable)
  {
    vtkErrorMacro("Render called before the geometry, face order and table were uploaded.");
    return false;
  }
  int width = 0, height = 0, originX = 0, originY = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &originX, &originY);
  if (width <= 0 || height <= 0)
  {
    return true;
  }
  vtkOpenGLState* state = window->GetState();

  // Per-size targets.
  if (in.Size[0] != width || in.Size[1] != height)
  {
    in.ReleaseSizeDependent();
    in.OpaqueDepth = vtkSmartPointer<vtkTextureObject>::New();
    in.OpaqueDepth->SetContext(window);
    in.OpaqueDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
    in.Result = NewFloatTexture(window, width, height);
    in.ResultFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    in.ResultFramebuffer->SetContext(window);
    state->PushFramebufferBindings();
    in.ResultFramebuffer->Bind();
    in.ResultFramebuffer->AddColorAttachment(0, in.Result);
    state->PopFramebufferBindings();
    in.Size[0] = width;
    in.Size[1] = height;
  }

  // 1. The opaque geometry's depth, from the framebuffer VTK renders into.
  {
    GLint readFramebuffer = 0, sampleBuffers = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
    in.OpaqueDepth->Activate();
    if (sampleBuffers == 0)
    {
      glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, originX, originY, width, height);
    }
    else
    {
      // A multisampled framebuffer cannot be copied from: no opaque cut.
      std::vector<float> far(static_cast<size_t>(width) * height, 1.0f);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, far.data());
      vtkWarningMacro("Multisampled framebuffer: opaque geometry does not end the volume's rays.");
    }
  in.OpaqueDepth->Deactivate();
  }

  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);

  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglViewport(0, 0, width, height);

  const std::string faceVS = vtkHAVSFaceVS;
  const std::string quadVS = vtkHAVSQuadVS;

  auto setCommonUniforms = [&](vtkShaderProgram* program) {
    program->SetUniformi("havsTable", in.Table->GetTextureUnit());
    const float ns = static_cast<float>(in.ScalarResolution);
    const float nl = static_cast<float>(in.LengthResolution);
    const float scalarTexel[2] = { (ns - 1.0f) / ns, 0.5f / ns };
    const float lengthTexel[2] = { (nl - 1.0f) / nl, 0.5f / nl };
    program->SetUniform2f("havsScalarTexel", scalarTexel);
    program->SetUniform2f("havsLengthTexel", lengthTexel);
    program->SetUniformf("havsInvMaxLength", static_cast<float>(1.0 / in.MaxLength));
    program->SetUniformf("havsTerminationOpacity", p.TerminationOpacity);
    program->SetUniformi("havsOpaqueDepth", in.OpaqueDepth->GetTextureUnit());
    program->SetUniformMatrix4x4("havsDCRC", const_cast<float*>(p.DCRC));
    const float viewport[2] = { static_cast<float>(width), static_cast<float>(height) };
    program->SetUniform2f("havsViewportSize", viewport);
    program->SetUniformi("havsParallel", p.Parallel ? 1 : 0);
    program->SetUniform3f("havsDirectionOfProjection", p.DirectionOfProjection);
    program->SetUniformMatrix4x4("havsMCRC", const_cast<float*>(p.MCRC));
    program->SetUniformMatrix4x4("havsMCDC", const_cast<float*>(p.MCDC));
    program->SetUniformi("havsFaceIsBoundary", in.BoundaryTexture->GetTextureUnit());
  };

  in.Table->Activate();
  in.OpaqueDepth->Activate();
  in.BoundaryTexture->Activate();
  state->PushFramebufferBindings();

  double t0 = p.MeasureStages ? (glFinish(), Now()) : 0.0;
  bool ok = true;
  std::string resolveFS = vtkHAVSResolveFS;
  int resolveK = p.K;
  bool listVote = false;
  std::vector<vtkTextureObject*> resolveTextures;

  if (p.BlendMode == 1 || p.BlendMode == 2)
  {
    // Maximum / minimum intensity: no k-buffer, no sort needed.
    in.ResultFramebuffer->Bind();
    in.ResultFramebuffer->ActivateDrawBuffers(1);
    const float zero[4] = { 0, 0, 0, 0 };
    glClearBufferfv(GL_COLOR, 0, zero);
    vtkShaderProgram* program = in.Program(faceVS, ComposeShader(vtkHAVSExtremumDrawFS, 1, 1));
    ok = program != nullptr;
    if (ok)
    {
      setCommonUniforms(program);
      program->SetUniformi("havsMinimum", p.BlendMode == 2 ? 1 : 0);
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendEquation(GL_MAX);
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
      in.DrawFaces(p.FlipFacing);
      state->vtkglBlendEquation(GL_FUNC_ADD);
      state->vtkglDisable(GL_BLEND);
    }
  }
  else if (p.Path == FramebufferFetch)
  {
    const int attachments = 1 + EntryAttachments(p.K);
    if (in.FetchK != p.K || !in.FetchFramebuffer)
    {
      for (auto& t : in.FetchTargets)
      {
        t->ReleaseGraphicsResources(window);
      }
      in.FetchTargets.clear();
      if (in.FetchFramebuffer)
      {
        in.FetchFramebuffer->ReleaseGraphicsResources(window);
      }
      in.FetchFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      in.FetchFramebuffer->SetContext(window);
      in.FetchFramebuffer->Bind();
      for (int a = 0; a < attachments; ++a)
      {
        in.FetchTargets.push_back(NewFloatTexture(window, width, height));
        in.FetchFramebuffer->AddColorAttachment(a, in.FetchTargets.back());
      }
      in.FetchK = p.K;
    }
    in.FetchFramebuffer->Bind();
    in.FetchFramebuffer->ActivateDrawBuffers(attachments);
    const float zero[4] = { 0, 0, 0, 0 };
    const float firstPair[4] = { kNoFront, 0, kEmpty, 0 };
    const float emptyPair[4] = { kEmpty, 0, kEmpty, 0 };
    glClearBufferfv(GL_COLOR, 0, zero);
    for (int a = 1; a < attachments; ++a)
    {
      glClearBufferfv(GL_COLOR, a, a == 1 ? firstPair : emptyPair);
    }

    std::ostringstream decl, load, store;
    decl << "layout(location = 0) inout vec4 havsColor;\n";
    for (int a = 0; a + 1 < attachments; ++a)
    {
      decl << "layout(location = " << a + 1 << ") inout vec4 havsEntries" << a << ";\n";
    }
    for (int i = 0; i < p.K; ++i)
    {
      load << "E[" << i << "] = havsEntries" << i / 2 << (i % 2 ? ".zw" : ".xy") << ";\n  ";
    }
    for (int a = 0; a + 1 < attachments; ++a)
    {
      const int second = 2 * a + 1;
      store << "havsEntries" << a << " = vec4(E[" << 2 * a << "], "
            << (second < p.K ? "E[" + std::to_string(second) + "]" : "vec2(HAVS_EMPTY, 0.0)")
            << ");\n  ";
    }
    std::string fs = ComposeShader(vtkHAVSFetchDrawFS, p.K, 1);
    Replace(fs, "//HAVS::FetchDeclarations", decl.str());
    Replace(fs, "//HAVS::FetchLoad", load.str());
    Replace(fs, "//HAVS::FetchStore", store.str());
    vtkShaderProgram* program = in.Program(faceVS, fs);
    ok = program != nullptr;
    if (ok)
    {
      setCommonUniforms(program);
  in.DrawFaces(p.FlipFacing);
    }

    std::ostringstream rdecl, rload;
    rdecl << "uniform sampler2D havsColorTexture;\n";
    rload << "color = texelFetch(havsColorTexture, pixel, 0);\n  ";
    for (int a = 0; a + 1 < attachments; ++a)
    {
      rdecl << "uniform sampler2D havsEntryTexture" << a << ";\n";
      rload << "vec4 pair" << a << " = texelFetch(havsEntryTexture" << a << ", pixel, 0);\n  ";
    }
    for (int i = 0; i < p.K; ++i)
    {
      rload << "E[" << i << "] = pair" << i / 2 << (i % 2 ? ".zw" : ".xy") << ";\n  ";
    }
    Replace(resolveFS, "//HAVS::ResolveDeclarations", rdecl.str());
    Replace(resolveFS, "//HAVS::ResolveLoad", rload.str());
    for (auto& t : in.FetchTargets)
    {
      resolveTextures.push_back(t);
    }
  }
  else if (p.Path == FragmentShaderInterlock)
  {
    const int stride = 1 + EntryAttachments(p.K);
    const size_t bytes = static_cast<size_t>(width) * height * stride * 4 * sizeof(float);
    if (!in.PixelEntries || in.PixelEntriesBytes != bytes)
    {
      if (!in.PixelEntries)
      {
        glGenBuffers(1, &in.PixelEntries);
      }
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, in.PixelEntries);
      glBufferData(GL_SHADER_STORAGE_BUFFER, bytes, nullptr, GL_DYNAMIC_COPY);
      in.PixelEntriesBytes = bytes;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.PixelEntries);
    in.ResultFramebuffer->Bind();
    in.ResultFramebuffer->ActivateDrawBuffers(1);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);

    vtkShaderProgram* clear = in.Program(quadVS, ComposeShader(vtkHAVSClearFS, p.K, stride));
    const bool arb = HasGLExtension("GL_ARB_fragment_shader_interlock");
    std::string fs = ComposeShader(vtkHAVSInterlockDrawFS, p.K, stride);
    Replace(fs, "//HAVS::InterlockExtension",
      arb ? "#extension GL_ARB_fragment_shader_interlock : require"
          : "#extension GL_NV_fragment_shader_interlock : require");
    Replace(fs, "//HAVS::InterlockBegin",
      arb ? "beginInvocationInterlockARB();" : "beginInvocationInterlockNV();");
    Replace(fs, "//HAVS::InterlockEnd",
      arb ? "endInvocationInterlockARB();" : "endInvocationInterlockNV();");
    ok = clear != nullptr;
    if (ok)
    {
      setCommonUniforms(clear);
      in.DrawFullViewport();
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      vtkShaderProgram* program = in.Program(faceVS, fs);
      ok = program != nullptr;
      if (ok)
      {
        setCommonUniforms(program);
        in.DrawFaces(p.FlipFacing);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      }
    }
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    Replace(resolveFS, "//HAVS::ResolveDeclarations",
      "layout(std430, binding = 0) buffer HAVSPixelEntries { vec4 havsPixelData[]; };\n");
    Replace(resolveFS, "//HAVS::ResolveLoad",
      "int base = (pixel.y * int(havsViewportSize.x) + pixel.x) * HAVS_PIXEL_STRIDE;\n"
      "  color = havsPixelData[base];\n"
      "  for (int i = 0; i < HAVS_K; ++i)\n"
      "  {\n"
      "    vec4 pair = havsPixelData[base + 1 + i / 2];\n"
      "    E[i] = (i % 2 == 0) ? pair.xy : pair.zw;\n"
      "  }\n");
    resolveFS = ComposeShader(resolveFS.c_str(), p.K, stride);
  }
  else if (p.Path == FragmentLists)
  {
    if (!in.ListHeads || in.ListHeadsSize[0] != width || in.ListHeadsSize[1] != height)
    {
      if (in.ListHeads)
      {
        glDeleteTextures(1, &in.ListHeads);
      }
      glGenTextures(1, &in.ListHeads);
      glBindTexture(GL_TEXTURE_2D, in.ListHeads);
      glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32UI, width, height);
      glBindTexture(GL_TEXTURE_2D, 0);
      in.ListHeadsSize[0] = width;
      in.ListHeadsSize[1] = height;
    }
    if (!in.ListCounter)
    {
      glGenBuffers(1, &in.ListCounter);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, in.ListCounter);
      glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
      glGenBuffers(1, &in.ListNodes);
    }
    const GLuint wanted = static_cast<GLuint>(
      std::max<size_t>(static_cast<size_t>(width) * height * 4, size_t(1) << 20));
    if (in.ListCapacity < wanted)
    {
      in.ListCapacity = wanted;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, in.ListNodes);
      glBufferData(GL_SHADER_STORAGE_BUFFER, size_t(in.ListCapacity) * 16, nullptr, GL_DYNAMIC_COPY);
    }
    vtkShaderProgram* program = in.Program(faceVS, ComposeShader(vtkHAVSListDrawFS, p.K, 1));
    ok = program != nullptr;
    in.ResultFramebuffer->Bind();
    in.ResultFramebuffer->ActivateDrawBuffers(1);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // Draw; when the node pool overflows, grow it to fit and draw again.
    for (int attempt = 0; ok && attempt < 2; ++attempt)
    {
      const GLuint noNode = 0xFFFFFFFFu, zero = 0;
      glClearTexImage(in.ListHeads, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noNode);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, in.ListCounter);
      glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &zero);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, in.ListNodes);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, in.ListCounter);
      glBindImageTexture(0, in.ListHeads, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
      setCommonUniforms(program);
      program->SetUniformi("havsNodeCapacity", static_cast<int>(in.ListCapacity));
      in.DrawFaces(p.FlipFacing);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
        GL_BUFFER_UPDATE_BARRIER_BIT);
      GLuint count = 0;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, in.ListCounter);
      glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &count);
      this->LastFragmentCount = count;
      if (count <= in.ListCapacity)
      {
        break;
      }
      in.ListCapacity = count + count / 4;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, in.ListNodes);
      glBufferData(GL_SHADER_STORAGE_BUFFER, size_t(in.ListCapacity) * 16, nullptr, GL_DYNAMIC_COPY);
    }
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // The list walk. Where shader group vote exists, the loop runs until no
    // invocation of the group has nodes left and every invocation loads an
    // in-range node each turn: llvmpipe (Mesa 22.3) returns wrong data for a
    // storage-buffer load inside a loop whose trip count differs between the
    // invocations of a group (measured: lists cut after one node).
    const bool vote = HasGLExtension("GL_ARB_shader_group_vote");
    std::ostringstream rload;
    rload << "E[0] = vec2(HAVS_NO_FRONT, 0.0);\n"
          << "  for (int i = 1; i < HAVS_K; ++i) { E[i] = vec2(HAVS_EMPTY, 0.0); }\n"
          << "  uint node = imageLoad(havsListHeads, pixel).r;\n"
          << "  for (uint n = 0u; n < uint(havsNodeCapacity); ++n)\n"
          << "  {\n"
          << "    bool walking = node < uint(havsNodeCapacity);\n"
          << (vote ? "    if (!anyInvocationARB(walking)) { break; }\n"
                   : "    if (!walking) { break; }\n")
          << "    uvec4 entry = havsNodes[walking ? node : 0u];\n"
          << "    if (walking)\n"
          << "    {\n"
          << "      havsInsertBackToFront(color, E, vec2(uintBitsToFloat(entry.x), "
             "uintBitsToFloat(entry.y)), opaqueDistance);\n"
          << "      node = entry.z;\n"
          << "    }\n"
          << "  }\n";
    listVote = vote;
    Replace(resolveFS, "//HAVS::ResolveDeclarations",
      "layout(r32ui, binding = 0) uniform readonly uimage2D havsListHeads;\n"
      "layout(std430, binding = 1) readonly buffer HAVSListNodes { uvec4 havsNodes[]; };\n"
      "uniform int havsNodeCapacity;\n");
    Replace(resolveFS, "//HAVS::ResolveLoad", rload.str());
    resolveK = ListResolveCapacity;
  }
  else
  {
    vtkErrorMacro("Unknown k-buffer path " << p.Path);
    ok = false;
  }

  double t1 = p.MeasureStages ? (glFinish(), Now()) : 0.0;

  // 2. Resolve: flush what is left into the result texture.
  if (ok && (p.BlendMode == 1 || p.BlendMode == 2))
  {
    // The extremum pass wrote straight into the result; colour it now.
    // Copy it aside first, since the resolve writes the same texture.
    auto extremum = NewFloatTexture(window, width, height);
    in.ResultFramebuffer->Bind(GL_READ_FRAMEBUFFER);
    in.ResultFramebuffer->ActivateReadBuffer(0);
    extremum->Activate();
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, width, height);
    in.ResultFramebuffer->Bind();
    in.ResultFramebuffer->ActivateDrawBuffers(1);
    vtkShaderProgram* program = in.Program(quadVS, vtkHAVSExtremumResolveFS);
    ok = program != nullptr;
    if (ok)
    {
      in.TransferFunction1D->Activate();
      program->SetUniformi("havsExtremumTexture", extremum->GetTextureUnit());
      program->SetUniformi("havsTransferFunction", in.TransferFunction1D->GetTextureUnit());
      const float ns = static_cast<float>(in.ScalarResolution);
      const float scalarTexel[2] = { (ns - 1.0f) / ns, 0.5f / ns };
      program->SetUniform2f("havsScalarTexel", scalarTexel);
      program->SetUniformi("havsMinimum", p.BlendMode == 2 ? 1 : 0);
      in.DrawFullViewport();
      in.TransferFunction1D->Deactivate();
    }
    extremum->Deactivate();
    extremum->ReleaseGraphicsResources(window);
  }
  else if (ok)
  {
    if (p.Path == FramebufferFetch)
    {
      resolveFS = ComposeShader(resolveFS.c_str(), p.K, 1);
    }
    else if (p.Path == FragmentLists)
    {
      resolveFS = ComposeShader(resolveFS.c_str(), resolveK, 1);
    }
    Replace(resolveFS, "//HAVS::ResolveExtension",
      std::string(listVote ? "#extension GL_ARB_shader_group_vote : require\n" : "") +
        (p.Path == FragmentLists ? "#define HAVS_BACK_TO_FRONT\n" : ""));
    in.ResultFramebuffer->Bind();
    in.ResultFramebuffer->ActivateDrawBuffers(1);
    for (vtkTextureObject* t : resolveTextures)
    {
      t->Activate();
    }
    vtkShaderProgram* program = in.Program(quadVS, resolveFS);
    ok = program != nullptr;
    if (ok)
    {
      setCommonUniforms(program);
      if (p.Path == FramebufferFetch)
      {
        program->SetUniformi("havsColorTexture", resolveTextures[0]->GetTextureUnit());
        for (size_t a = 1; a < resolveTextures.size(); ++a)
        {
          program->SetUniformi(("havsEntryTexture" + std::to_string(a - 1)).c_str(),
            resolveTextures[a]->GetTextureUnit());
        }
      }
      else if (p.Path == FragmentLists)
      {
        program->SetUniformi("havsNodeCapacity", static_cast<int>(in.ListCapacity));
        glBindImageTexture(0, in.ListHeads, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, in.ListNodes);
      }
      else
      {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.PixelEntries);
      }
      in.DrawFullViewport();
    }
    for (vtkTextureObject* t : resolveTextures)
    {
      t->Deactivate();
    }
  }
  if (p.KeepResult && ok)
  {
    this->LastResult.resize(static_cast<size_t>(width) * height * 4);
    in.ResultFramebuffer->Bind(GL_READ_FRAMEBUFFER);
    in.ResultFramebuffer->ActivateReadBuffer(0);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, this->LastResult.data());
    this->LastSize[0] = width;
    this->LastSize[1] = height;
  }
  double t2 = p.MeasureStages ? (glFinish(), Now()) : 0.0;

  in.BoundaryTexture->Deactivate();
  in.OpaqueDepth->Deactivate();
  in.Table->Deactivate();
  state->PopFramebufferBindings();

  // 3. Composite the premultiplied result over VTK's framebuffer.
  if (ok)
  {
    state->vtkglViewport(originX, originY, width, height);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    vtkShaderProgram* program = in.Program(quadVS, vtkHAVSCompositeFS);
    ok = program != nullptr;
    if (ok)
    {
      in.Result->Activate();
      program->SetUniformi("havsResultTexture", in.Result->GetTextureUnit());
      const float origin[2] = { static_cast<float>(originX), static_cast<float>(originY) };
      program->SetUniform2f("havsViewportOrigin", origin);
      in.DrawFullViewport();
      in.Result->Deactivate();
    }
  }
  double t3 = p.MeasureStages ? (glFinish(), Now()) : 0.0;
  this->LastDrawSeconds = t1 - t0;
  this->LastFlushSeconds = t2 - t1;
  this->LastCompositeSeconds = t3 - t2;
  if (!ok)
  {
    vtkErrorMacro("A vtkHAVS shader could not be built for the "
      << GetPathName(p.Path) << " path with k = " << p.K << "; see the shader log above.");
  }
  return ok;
}

//------------------------------------------------------------------------------
void vtkHAVSKBufferRenderer::ReleaseGraphicsResources(vtkWindow* window)
{
  Internals& in = *this->Internal;
  if (!in.Window)
  {
    return;
  }
  if (window && window != in.Window)
  {
    return;
  }
  in.Window->MakeCurrent();
  in.ReleaseAll();
  in.Window = nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSKBufferRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const Internals& in = *this->Internal;
  os << indent << "Target size: " << in.Size[0] << " x " << in.Size[1] << "\n";
  os << indent << "Faces uploaded: " << in.IndexCount / 3 << "\n";
  os << indent << "Table: " << in.ScalarResolution << "^2 x " << in.LengthResolution << "\n";
}
