/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSKBufferRenderer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSKBufferRenderer.h"

#include "vtkCommand.h"
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
#include "vtkHAVSOpenGL.h"

#include "vtkHAVSKBufferShaders.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>

vtkStandardNewMacro(vtkHAVSKBufferRenderer);

namespace
{
const float kEmpty = 3.0e38f;
const float kNoFront = -2.0e38f;

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

/// HAVS_EMULATE_INTERLOCK=1 on llvmpipe: run the interlock path without the
/// interlock. llvmpipe shades each tile in one thread, a pixel's fragments one
/// at a time in primitive order, so the storage-buffer k-buffer is race-free
/// there without it; this tests the path's layout, clear and resolve on a
/// machine without an interlock GPU. Ignored anywhere else.
bool InterlockEmulated()
{
  const char* requested = std::getenv("HAVS_EMULATE_INTERLOCK");
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return requested && std::string(requested) == "1" && renderer &&
    std::strstr(renderer, "llvmpipe") != nullptr;
}

vtkHAVSKBufferShaders::InterlockKind AvailableInterlock()
{
  if (HasGLExtension("GL_ARB_fragment_shader_interlock"))
  {
    return vtkHAVSKBufferShaders::InterlockARB;
  }
  if (HasGLExtension("GL_NV_fragment_shader_interlock"))
  {
    return vtkHAVSKBufferShaders::InterlockNV;
  }
  return vtkHAVSKBufferShaders::InterlockNone;
}

/// Fills the buffers of the bound vertex array that the face vertex shader
/// reads: points (location 0, 3 floats each) and normalized scalars (location 1).
void UploadVertexAttributes(GLuint pointBuffer, GLuint scalarBuffer,
  const std::vector<float>& points, const std::vector<float>& scalars, GLenum usage)
{
  glBindBuffer(GL_ARRAY_BUFFER, pointBuffer);
  glBufferData(GL_ARRAY_BUFFER, points.size() * sizeof(float), points.data(), usage);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, scalarBuffer);
  glBufferData(GL_ARRAY_BUFFER, scalars.size() * sizeof(float), scalars.data(), usage);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
}

double Now()
{
  return vtkTimerLog::GetUniversalTime();
}
}

namespace
{
constexpr GLuint kLoggedViolations = 16; // pixels logged with the order-violation count

/// Saves the GL state a vtkHAVS pass changes (restored when it goes out of
/// scope) and sets what every pass needs: no depth test, culling or scissor,
/// no depth writes.
struct ScopedPassState
{
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable Cull;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglColorMask ColorMask;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;

  explicit ScopedPassState(vtkOpenGLState* state)
    : Viewport(state)
    , DepthTest(state, GL_DEPTH_TEST)
    , Blend(state, GL_BLEND)
    , Cull(state, GL_CULL_FACE)
    , Scissor(state, GL_SCISSOR_TEST)
    , DepthMask(state)
    , ColorMask(state)
    , BlendFunc(state)
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglDepthMask(GL_FALSE);
  }
};
}

struct vtkHAVSKBufferRenderer::Internals
{
  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned long WindowDeleteObserver = 0;

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

  // Sections of the mesh with the near and clipping planes (per frame)
  GLuint SectionArray = 0;
  GLuint SectionPoints = 0;
  GLuint SectionScalars = 0;
  struct SectionDraw
  {
    int PlaneIndex;
    bool Entering;
    GLint First;
    GLsizei Count;
  };
  std::vector<SectionDraw> SectionDraws;

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
  // order-violation counter (one uint, binding 3)
  GLuint ViolationCounter = 0;
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
      this->ListNodes, this->ListCounter, this->SectionPoints, this->SectionScalars,
      this->ViolationCounter };
    for (GLuint b : buffers)
    {
      if (b)
      {
        glDeleteBuffers(1, &b);
      }
    }
    this->PointBuffer = this->ScalarBuffer = this->IndexBuffer = 0;
    this->ListNodes = this->ListCounter = this->ViolationCounter = 0;
    this->SectionPoints = this->SectionScalars = 0;
    this->SectionDraws.clear();
    this->ListCapacity = 0;
    if (this->SectionArray)
    {
      glDeleteVertexArrays(1, &this->SectionArray);
      this->SectionArray = 0;
    }
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

  /// The sections that enter the clipped volume, the faces in draw order,
  /// then the sections that leave it (nearest first along every ray).
  void DrawFaces(vtkShaderProgram* program, const FrameParameters& p)
  {
    const bool roles = program->IsUniformUsed("havsRole");
    const bool ownPlane = program->IsUniformUsed("havsOwnPlane");
    auto drawSections = [&](bool entering) {
      for (const SectionDraw& d : this->SectionDraws)
      {
        if (d.Entering != entering)
        {
          continue;
        }
        if (roles)
        {
          program->SetUniformi("havsRole", entering ? 1 : 2);
        }
        if (ownPlane)
        {
          program->SetUniformi("havsOwnPlane", d.PlaneIndex);
        }
        glBindVertexArray(this->SectionArray);
        glDrawArrays(GL_TRIANGLES, d.First, d.Count);
      }
      if (roles)
      {
        program->SetUniformi("havsRole", 0);
      }
      if (ownPlane)
      {
        program->SetUniformi("havsOwnPlane", -1);
      }
    };
    drawSections(true);
    glFrontFace(p.FlipFacing ? GL_CW : GL_CCW);
    glBindVertexArray(this->VertexArray);
    glDrawElements(GL_TRIANGLES, this->IndexCount, GL_UNSIGNED_INT, nullptr);
    glFrontFace(GL_CCW);
    drawSections(false);
    glBindVertexArray(0);
  }

  /// (Re)allocates the per-size targets: opaque depth, result.
  void Resize(int width, int height)
  {
    if (this->Size[0] == width && this->Size[1] == height)
    {
      return;
    }
    this->ReleaseSizeDependent();
    this->OpaqueDepth = vtkSmartPointer<vtkTextureObject>::New();
    this->OpaqueDepth->SetContext(this->Window);
    this->OpaqueDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
    this->Result = NewFloatTexture(this->Window, width, height);
    this->ResultFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->ResultFramebuffer->SetContext(this->Window);
    this->Window->GetState()->PushFramebufferBindings();
    this->ResultFramebuffer->Bind();
    this->ResultFramebuffer->AddColorAttachment(0, this->Result);
    this->Window->GetState()->PopFramebufferBindings();
    this->Size[0] = width;
    this->Size[1] = height;
  }

  /// Copies the depth of the framebuffer VTK renders into (the opaque
  /// geometry drawn before the volume) for the viewport.
  void CaptureOpaqueDepth(int x, int y, int width, int height)
  {
    GLint sampleBuffers = 0;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
    this->OpaqueDepth->Activate();
    if (sampleBuffers == 0)
    {
      glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, x, y, width, height);
    }
    else
    {
      // A multisampled framebuffer cannot be copied from: no opaque cut.
      std::vector<float> far(static_cast<size_t>(width) * height, 1.0f);
      glTexSubImage2D(
        GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, far.data());
      vtkGenericWarningMacro(
        "vtkHAVS: multisampled framebuffer; opaque geometry does not end the volume's rays.");
    }
    this->OpaqueDepth->Deactivate();
  }

  vtkShaderProgram* FaceProgram(const std::string& fragmentShader, const FrameParameters& p)
  {
    vtkShaderProgram* program =
      this->Program(vtkHAVSKBufferShaders::FaceVertexShader(), fragmentShader);
    if (program)
    {
      this->SetCommonUniforms(program, p);
    }
    return program;
  }

  vtkShaderProgram* QuadProgram(const std::string& fragmentShader, const FrameParameters& p)
  {
    vtkShaderProgram* program =
      this->Program(vtkHAVSKBufferShaders::QuadVertexShader(), fragmentShader);
    if (program)
    {
      this->SetCommonUniforms(program, p);
    }
    return program;
  }

  void SetCommonUniforms(vtkShaderProgram* program, const FrameParameters& p)
  {
    program->SetUniformi("havsTable", this->Table->GetTextureUnit());
    const float ns = static_cast<float>(this->ScalarResolution);
    const float nl = static_cast<float>(this->LengthResolution);
    const float scalarTexel[2] = { (ns - 1.0f) / ns, 0.5f / ns };
    const float lengthTexel[2] = { (nl - 1.0f) / nl, 0.5f / nl };
    program->SetUniform2f("havsScalarTexel", scalarTexel);
    program->SetUniform2f("havsLengthTexel", lengthTexel);
    program->SetUniformf("havsInvMaxLength", static_cast<float>(1.0 / this->MaxLength));
    program->SetUniformf("havsTerminationOpacity", p.TerminationOpacity);
    program->SetUniformi("havsOpaqueDepth", this->OpaqueDepth->GetTextureUnit());
    program->SetUniformMatrix4x4("havsDCRC", const_cast<float*>(p.DCRC));
    const float viewport[2] = { static_cast<float>(this->Size[0]),
      static_cast<float>(this->Size[1]) };
    program->SetUniform2f("havsViewportSize", viewport);
    program->SetUniformi("havsParallel", p.Parallel ? 1 : 0);
    program->SetUniform3f("havsDirectionOfProjection", p.DirectionOfProjection);
    program->SetUniformMatrix4x4("havsMCRC", const_cast<float*>(p.MCRC));
    program->SetUniformMatrix4x4("havsMCDC", const_cast<float*>(p.MCDC));
    program->SetUniformi("havsFaceIsBoundary", this->BoundaryTexture->GetTextureUnit());
    program->SetUniformi("havsMinimum", p.BlendMode == 2 ? 1 : 0);
    program->SetUniformi("havsNodeCapacity", static_cast<int>(this->ListCapacity));
    program->SetUniformi("havsTagging", p.Tagging ? 1 : 0);
    program->SetUniformf("havsGapLength", p.GapLength);
    program->SetUniformi("havsRole", 0);
    program->SetUniformi("havsOwnPlane", -1);
    program->SetUniformi("havsPlaneCount", p.PlaneCount);
    if (p.PlaneCount > 0)
    {
      program->SetUniform4fv("havsPlanesRC", p.PlaneCount, p.PlanesRC);
    }
  }

  /// Maximum / minimum intensity: the faces with GL_MAX blending into the
  /// result (no k-buffer, no sort needed).
  bool DrawExtremum(const FrameParameters& p)
  {
    vtkOpenGLState* state = this->Window->GetState();
    this->ResultFramebuffer->Bind();
    this->ResultFramebuffer->ActivateDrawBuffers(1);
    const float zero[4] = { 0, 0, 0, 0 };
    glClearBufferfv(GL_COLOR, 0, zero);
    vtkShaderProgram* program = this->FaceProgram(vtkHAVSKBufferShaders::ExtremumDrawShader(), p);
    if (!program)
    {
      return false;
    }
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendEquation(GL_MAX);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    this->DrawFaces(program, p);
    state->vtkglBlendEquation(GL_FUNC_ADD);
    state->vtkglDisable(GL_BLEND);
    return true;
  }

  /// The extremal scalar of each pixel coloured from the 1D transfer function.
  bool ResolveExtremum(const FrameParameters& p)
  {
    // The draw wrote the result texture; the resolve reads a copy of it.
    auto extremum = NewFloatTexture(this->Window, this->Size[0], this->Size[1]);
    this->ResultFramebuffer->Bind(GL_READ_FRAMEBUFFER);
    this->ResultFramebuffer->ActivateReadBuffer(0);
    extremum->Activate();
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, this->Size[0], this->Size[1]);
    this->ResultFramebuffer->Bind();
    this->ResultFramebuffer->ActivateDrawBuffers(1);
    this->TransferFunction1D->Activate();
    vtkShaderProgram* program =
      this->QuadProgram(vtkHAVSKBufferShaders::ExtremumResolveShader(), p);
    if (program)
    {
      program->SetUniformi("havsExtremumTexture", extremum->GetTextureUnit());
      program->SetUniformi("havsTransferFunction", this->TransferFunction1D->GetTextureUnit());
      this->DrawFullViewport();
    }
    this->TransferFunction1D->Deactivate();
    extremum->Deactivate();
    extremum->ReleaseGraphicsResources(this->Window);
    return program != nullptr;
  }

  /// Benchmark aid: the sorted faces with a trivial shader (additive), so
  /// that the time is the rasterization alone.
  bool DrawRasterBound(const FrameParameters& p)
  {
    vtkOpenGLState* state = this->Window->GetState();
    this->ResultFramebuffer->Bind();
    this->ResultFramebuffer->ActivateDrawBuffers(1);
    const float zero[4] = { 0, 0, 0, 0 };
    glClearBufferfv(GL_COLOR, 0, zero);
    vtkShaderProgram* program = this->FaceProgram(vtkHAVSKBufferShaders::TrivialShader(), p);
    if (!program)
    {
      return false;
    }
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    this->DrawFaces(program, p);
    state->vtkglDisable(GL_BLEND);
    return true;
  }

  /// Zeroes the order-violation counter and binds it for the k-buffer shaders.
  void ResetViolationCounter()
  {
    const GLuint zero = 0;
    if (!this->ViolationCounter)
    {
      const GLuint zeros[1 + kLoggedViolations] = {};
      glGenBuffers(1, &this->ViolationCounter);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ViolationCounter);
      glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(zeros), zeros, GL_DYNAMIC_READ);
    }
    else
    {
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ViolationCounter);
      glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &zero);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, this->ViolationCounter);
  }

  std::uint64_t ReadViolationCounter(std::vector<int>& pixels)
  {
    GLuint data[1 + kLoggedViolations] = {};
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ViolationCounter);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(data), data);
    pixels.clear();
    for (GLuint i = 0; i < std::min<GLuint>(data[0], kLoggedViolations); ++i)
    {
      pixels.push_back(static_cast<int>(data[1 + i] & 0xFFFFu));
      pixels.push_back(static_cast<int>(data[1 + i] >> 16));
    }
    return data[0];
  }

  /// Clears the k-buffer of the path and draws the faces through it.
  bool DrawKBuffer(const FrameParameters& p, std::uint64_t& fragmentCount)
  {
    this->ResetViolationCounter();
    switch (p.Path)
    {
      case FramebufferFetch:
        return this->DrawFetch(p);
      case FragmentShaderInterlock:
        return this->DrawInterlock(p);
      case FragmentLists:
        return this->DrawLists(p, fragmentCount);
      default:
        return false;
    }
  }

  bool DrawFetch(const FrameParameters& p)
  {
    const int attachments = vtkHAVSKBufferShaders::FetchAttachments(p.K);
    if (this->FetchK != p.K || !this->FetchFramebuffer)
    {
      for (auto& t : this->FetchTargets)
      {
        t->ReleaseGraphicsResources(this->Window);
      }
      this->FetchTargets.clear();
      if (this->FetchFramebuffer)
      {
        this->FetchFramebuffer->ReleaseGraphicsResources(this->Window);
      }
      this->FetchFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->FetchFramebuffer->SetContext(this->Window);
      this->FetchFramebuffer->Bind();
      for (int a = 0; a < attachments; ++a)
      {
        this->FetchTargets.push_back(NewFloatTexture(this->Window, this->Size[0], this->Size[1]));
        this->FetchFramebuffer->AddColorAttachment(a, this->FetchTargets.back());
      }
      this->FetchK = p.K;
    }
    this->FetchFramebuffer->Bind();
    this->FetchFramebuffer->ActivateDrawBuffers(attachments);
    const float zero[4] = { 0, 0, 0, 0 };
    const float firstPair[4] = { kNoFront, 0, kEmpty, 0 };
    const float emptyPair[4] = { kEmpty, 0, kEmpty, 0 };
    glClearBufferfv(GL_COLOR, 0, zero);
    for (int a = 1; a < attachments; ++a)
    {
      glClearBufferfv(GL_COLOR, a, a == 1 ? firstPair : emptyPair);
    }
    vtkShaderProgram* program = this->FaceProgram(vtkHAVSKBufferShaders::FetchDrawShader(p.K), p);
    if (program)
    {
      this->DrawFaces(program, p);
    }
    return program != nullptr;
  }

  bool DrawInterlock(const FrameParameters& p)
  {
    const size_t bytes = static_cast<size_t>(this->Size[0]) * this->Size[1] *
      vtkHAVSKBufferShaders::InterlockPixelStride(p.K) * 4 * sizeof(float);
    if (!this->PixelEntries || this->PixelEntriesBytes != bytes)
    {
      if (!this->PixelEntries)
      {
        glGenBuffers(1, &this->PixelEntries);
      }
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->PixelEntries);
      glBufferData(GL_SHADER_STORAGE_BUFFER, bytes, nullptr, GL_DYNAMIC_COPY);
      this->PixelEntriesBytes = bytes;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->PixelEntries);
    this->ResultFramebuffer->Bind();
    this->ResultFramebuffer->ActivateDrawBuffers(1);
    vtkOpenGLState* state = this->Window->GetState();
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    vtkShaderProgram* clear =
      this->QuadProgram(vtkHAVSKBufferShaders::InterlockClearShader(p.K), p);
    if (clear)
    {
      this->DrawFullViewport();
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    vtkShaderProgram* program = clear
      ? this->FaceProgram(vtkHAVSKBufferShaders::InterlockDrawShader(p.K, AvailableInterlock()), p)
      : nullptr;
    if (program)
    {
      this->DrawFaces(program, p);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return program != nullptr;
  }

  bool DrawLists(const FrameParameters& p, std::uint64_t& fragmentCount)
  {
    const int width = this->Size[0], height = this->Size[1];
    if (!this->ListHeads || this->ListHeadsSize[0] != width || this->ListHeadsSize[1] != height)
    {
      if (this->ListHeads)
      {
        glDeleteTextures(1, &this->ListHeads);
      }
      glGenTextures(1, &this->ListHeads);
      glBindTexture(GL_TEXTURE_2D, this->ListHeads);
      glTexStorage2D(GL_TEXTURE_2D, 1, GL_R32UI, width, height);
      glBindTexture(GL_TEXTURE_2D, 0);
      this->ListHeadsSize[0] = width;
      this->ListHeadsSize[1] = height;
    }
    if (!this->ListCounter)
    {
      glGenBuffers(1, &this->ListCounter);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ListCounter);
      glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(GLuint), nullptr, GL_DYNAMIC_READ);
      glGenBuffers(1, &this->ListNodes);
    }
    const GLuint wanted = static_cast<GLuint>(
      std::max<size_t>(static_cast<size_t>(width) * height * 4, size_t(1) << 20));
    if (this->ListCapacity < wanted)
    {
      this->ListCapacity = wanted;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ListNodes);
      glBufferData(
        GL_SHADER_STORAGE_BUFFER, size_t(this->ListCapacity) * 16, nullptr, GL_DYNAMIC_COPY);
    }
    this->ResultFramebuffer->Bind();
    this->ResultFramebuffer->ActivateDrawBuffers(1);
    vtkOpenGLState* state = this->Window->GetState();
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    bool ok = true;
    // Draw; when the node pool overflows, grow it to fit and draw again.
    for (int attempt = 0; ok && attempt < 2; ++attempt)
    {
      const GLuint noNode = 0xFFFFFFFFu, zero = 0;
      glClearTexImage(this->ListHeads, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noNode);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ListCounter);
      glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &zero);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->ListNodes);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, this->ListCounter);
      glBindImageTexture(0, this->ListHeads, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
      vtkShaderProgram* program = this->FaceProgram(vtkHAVSKBufferShaders::ListDrawShader(), p);
      ok = program != nullptr;
      if (!ok)
      {
        break;
      }
      this->DrawFaces(program, p);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
        GL_BUFFER_UPDATE_BARRIER_BIT);
      GLuint count = 0;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ListCounter);
      glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &count);
      fragmentCount = count;
      if (count <= this->ListCapacity)
      {
        break;
      }
      this->ListCapacity = count + count / 4;
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ListNodes);
      glBufferData(
        GL_SHADER_STORAGE_BUFFER, size_t(this->ListCapacity) * 16, nullptr, GL_DYNAMIC_COPY);
    }
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    return ok;
  }

  /// Flush: the entries left leave in depth order into the result texture.
  bool Resolve(const FrameParameters& p)
  {
    this->ResultFramebuffer->Bind();
    this->ResultFramebuffer->ActivateDrawBuffers(1);
    const bool vote = p.Path == FragmentLists && HasGLExtension("GL_ARB_shader_group_vote");
    if (p.Path == FramebufferFetch)
    {
      for (auto& t : this->FetchTargets)
      {
        t->Activate();
      }
    }
    else if (p.Path == FragmentLists)
    {
      glBindImageTexture(0, this->ListHeads, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, this->ListNodes);
    }
    else
    {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->PixelEntries);
    }
    vtkShaderProgram* program =
      this->QuadProgram(vtkHAVSKBufferShaders::ResolveShader(p.Path, p.K, vote), p);
    if (program)
    {
      if (p.Path == FramebufferFetch)
      {
        program->SetUniformi("havsColorTexture", this->FetchTargets[0]->GetTextureUnit());
        for (size_t a = 1; a < this->FetchTargets.size(); ++a)
        {
          program->SetUniformi(("havsEntryTexture" + std::to_string(a - 1)).c_str(),
            this->FetchTargets[a]->GetTextureUnit());
        }
      }
      this->DrawFullViewport();
    }
    if (p.Path == FramebufferFetch)
    {
      for (auto& t : this->FetchTargets)
      {
        t->Deactivate();
      }
    }
    return program != nullptr;
  }

  /// The premultiplied result over VTK's framebuffer (viewport already set).
  bool Composite(int originX, int originY)
  {
    vtkOpenGLState* state = this->Window->GetState();
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    vtkShaderProgram* program = this->Program(
      vtkHAVSKBufferShaders::QuadVertexShader(), vtkHAVSKBufferShaders::CompositeShader());
    if (!program)
    {
      return false;
    }
    this->Result->Activate();
    program->SetUniformi("havsResultTexture", this->Result->GetTextureUnit());
    const float origin[2] = { static_cast<float>(originX), static_cast<float>(originY) };
    program->SetUniform2f("havsViewportOrigin", origin);
    this->DrawFullViewport();
    this->Result->Deactivate();
    return true;
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
        HasGLExtension("GL_NV_fragment_shader_interlock") || InterlockEmulated();
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
  this->ReleaseGraphicsResources(in.Window);
  in.Window = window;
  // A window that goes away while this mapper is not among its props (so that
  // it is not told to release) takes the resources with it: watch for that.
  in.WindowDeleteObserver = window->AddObserver(
    vtkCommand::DeleteEvent, this, &vtkHAVSKBufferRenderer::OnWindowDeleted);
  window->MakeCurrent();
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSKBufferRenderer::OnWindowDeleted(vtkObject* window, unsigned long, void*)
{
  this->ReleaseGraphicsResources(vtkWindow::SafeDownCast(window));
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
  UploadVertexAttributes(in.PointBuffer, in.ScalarBuffer, pointsMC, scalars, GL_STATIC_DRAW);
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
void vtkHAVSKBufferRenderer::SetSections(const std::vector<Section>& sections)
{
  Internals& in = *this->Internal;
  in.SectionDraws.clear();
  std::vector<float> points, scalars;
  for (const Section& section : sections)
  {
    const GLsizei count = static_cast<GLsizei>(section.Scalars.size());
    if (count < 3 || section.PointsMC.size() != 3 * section.Scalars.size())
    {
      continue;
    }
    in.SectionDraws.push_back({ section.PlaneIndex, section.Entering,
      static_cast<GLint>(scalars.size()), count });
    points.insert(points.end(), section.PointsMC.begin(), section.PointsMC.end());
    scalars.insert(scalars.end(), section.Scalars.begin(), section.Scalars.end());
  }
  if (in.SectionDraws.empty())
  {
    return;
  }
  if (!in.SectionArray)
  {
    glGenVertexArrays(1, &in.SectionArray);
    glGenBuffers(1, &in.SectionPoints);
    glGenBuffers(1, &in.SectionScalars);
  }
  glBindVertexArray(in.SectionArray);
  UploadVertexAttributes(in.SectionPoints, in.SectionScalars, points, scalars, GL_STREAM_DRAW);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
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
  in.Resize(width, height);
  in.CaptureOpaqueDepth(originX, originY, width, height);

  {
    ScopedPassState passState(state);
    state->vtkglDisable(GL_BLEND);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    state->vtkglViewport(0, 0, width, height);

    in.Table->Activate();
    in.OpaqueDepth->Activate();
    in.BoundaryTexture->Activate();
    state->PushFramebufferBindings();

    const double t0 = p.MeasureStages ? (glFinish(), Now()) : 0.0;
    const bool extremum = p.BlendMode == 1 || p.BlendMode == 2;
    bool ok = p.RasterBoundOnly
      ? in.DrawRasterBound(p)
      : (extremum ? in.DrawExtremum(p) : in.DrawKBuffer(p, this->LastFragmentCount));
    const double t1 = p.MeasureStages ? (glFinish(), Now()) : 0.0;
    if (!p.RasterBoundOnly)
    {
      ok = ok && (extremum ? in.ResolveExtremum(p) : in.Resolve(p));
    }
    this->LastViolationPixels.clear();
    this->LastOrderViolations = ok && !p.RasterBoundOnly && !extremum && p.CountOrderViolations
      ? in.ReadViolationCounter(this->LastViolationPixels)
      : 0;
    if (ok && p.KeepResult)
    {
      this->LastResult.resize(static_cast<size_t>(width) * height * 4);
      in.ResultFramebuffer->Bind(GL_READ_FRAMEBUFFER);
      in.ResultFramebuffer->ActivateReadBuffer(0);
      glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, this->LastResult.data());
      this->LastSize[0] = width;
      this->LastSize[1] = height;
    }
    const double t2 = p.MeasureStages ? (glFinish(), Now()) : 0.0;

    in.BoundaryTexture->Deactivate();
    in.OpaqueDepth->Deactivate();
    in.Table->Deactivate();
    state->PopFramebufferBindings();

    if (ok && !p.RasterBoundOnly && p.Composite)
    {
      state->vtkglViewport(originX, originY, width, height);
      ok = in.Composite(originX, originY);
    }
    const double t3 = p.MeasureStages ? (glFinish(), Now()) : 0.0;
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
}

//------------------------------------------------------------------------------
bool vtkHAVSKBufferRenderer::CompositeLastResult(vtkRenderer* renderer)
{
  Internals& in = *this->Internal;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  int width = 0, height = 0, originX = 0, originY = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &originX, &originY);
  if (!window || window != in.Window || !in.Result || width != in.Size[0] ||
    height != in.Size[1])
  {
    vtkErrorMacro("CompositeLastResult needs the last frame's result in this window.");
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  ScopedPassState passState(state);
  state->vtkglViewport(originX, originY, width, height);
  return in.Composite(originX, originY);
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
  in.Window->RemoveObserver(in.WindowDeleteObserver);
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
