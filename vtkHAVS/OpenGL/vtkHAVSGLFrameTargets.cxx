/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLFrameTargets.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLFrameTargets.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSMapperInputs.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSShaderHooks.h"
#include "vtkHAVSShaders.h"
#include "vtkHAVSTranslucentLayers.h"
#include "vtkHAVSViewFrame.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLUniforms.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSGLFrameTargets);

//------------------------------------------------------------------------------
namespace
{
/// A 2D texture (nearest, clamped) of this size and format, in `window`.
vtkSmartPointer<vtkTextureObject> NewTexture(vtkOpenGLRenderWindow* window, int w, int h,
  unsigned int internalFormat, unsigned int format, int components, int vtkType)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetInternalFormat(internalFormat);
  texture->SetFormat(format);
  texture->SetDataType(vtkType == VTK_FLOAT ? GL_FLOAT : GL_UNSIGNED_BYTE);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->Allocate2D(w, h, components, vtkType);
  return texture;
}

/// A framebuffer whose one colour attachment is `texture`.
vtkSmartPointer<vtkOpenGLFramebufferObject> NewColorFramebuffer(
  vtkOpenGLRenderWindow* window, vtkTextureObject* texture)
{
  auto framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  framebuffer->SetContext(window);
  window->GetState()->PushFramebufferBindings();
  framebuffer->Bind();
  framebuffer->AddColorAttachment(0, texture);
  window->GetState()->PopFramebufferBindings();
  return framebuffer;
}
}

vtkSmartPointer<vtkTextureObject> vtkHAVSGLFrameTargets::NewFloatTexture(
  vtkOpenGLRenderWindow* window, int w, int h)
{
  return NewTexture(window, w, h, GL_RGBA32F, GL_RGBA, 4, VTK_FLOAT);
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::Resize(int fullWidth, int fullHeight, int width, int height)
{
  if (this->FullSize[0] != fullWidth || this->FullSize[1] != fullHeight || !this->Result)
  {
    this->ReleaseSizeDependent(this->Window);
    this->OpaqueDepth = vtkSmartPointer<vtkTextureObject>::New();
    this->OpaqueDepth->SetContext(this->Window);
    this->OpaqueDepth->AllocateDepth(fullWidth, fullHeight, vtkTextureObject::Float32);
    this->OpaqueDepthFormat = vtkTextureObject::Float32;
    this->Result = NewFloatTexture(this->Window, fullWidth, fullHeight);
    this->ResultFramebuffer = NewColorFramebuffer(this->Window, this->Result);
    this->FullSize[0] = fullWidth;
    this->FullSize[1] = fullHeight;
  }
  this->Size[0] = std::min(width, fullWidth);
  this->Size[1] = std::min(height, fullHeight);
  this->CoverageMesh = nullptr;
  this->CoverageDrawn = false;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::SetCoverage(
  vtkHAVSMesh* mesh, const vtkHAVSViewFrame& view, const vtkHAVSFramePlanes& planes, bool opaque)
{
  this->CoverageMesh = nullptr;
  this->CoverageDrawn = false;
  // Where the near plane cuts the mesh's bounds, rays may start inside it,
  // where no boundary face is: no mask.
  if (!mesh || !mesh->IsValid() || !view.IsReduced() || planes.GetNearPlaneCutsMesh())
  {
    return;
  }
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToClip, this->CoverageModelToClip);
  this->CoverageFlipFacing = view.FlipFacing;
  this->CoverageMesh = mesh;
  this->CoverageOpaque = opaque;
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFrameTargets::DrawCoverage()
{
  vtkHAVSMesh* mesh = this->CoverageMesh;
  const vtkMTimeType version = mesh->GetBuildTime();
  if (this->CoveragePoints.GetVersion() != version || !this->CoverageArray.IsCreated())
  {
    vtkHAVSFaceSet* faces = mesh->GetFaceSet();
    const std::vector<float>& points = mesh->GetPoints();
    const std::vector<uint32_t>& ids = faces->GetFaceVertices();
    const std::vector<uint8_t>& boundary = faces->GetBoundaryFlags();
    std::vector<float> positions;
    positions.reserve(9 * static_cast<size_t>(faces->GetNumberOfBoundaryFaces()));
    for (size_t f = 0; f < boundary.size(); ++f)
    {
      if (boundary[f])
      {
        for (int v = 0; v < 3; ++v)
        {
          const float* p = &points[3 * static_cast<size_t>(ids[3 * f + v])];
          positions.insert(positions.end(), p, p + 3);
        }
      }
    }
    this->CoverageVertices = static_cast<GLsizei>(positions.size() / 3);
    if (positions.empty())
    {
      return false;
    }
    if (!this->CoveragePoints.Update(GL_ARRAY_BUFFER, positions, version))
    {
      return false;
    }
    this->CoverageArray.SetBuffers(this->CoveragePoints, nullptr);
  }
  vtkShaderProgram* program = this->Window->GetShaderCache()->ReadyShaderProgram(
    vtkHAVSShaders::CoverageVertexShader().c_str(), vtkHAVSShaders::CoverageShader().c_str(), "");
  if (!program || !program->GetCompiled())
  {
    return false;
  }
  if (!this->Coverage)
  {
    this->Coverage = NewTexture(
      this->Window, this->FullSize[0], this->FullSize[1], GL_R8, GL_RED, 1, VTK_UNSIGNED_CHAR);
    this->CoverageFramebuffer = NewColorFramebuffer(this->Window, this->Coverage);
  }
  vtkOpenGLState* state = this->Window->GetState();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglClearColor clearColor(state);
  state->PushFramebufferBindings();
  this->CoverageFramebuffer->Bind();
  this->CoverageFramebuffer->ActivateDrawBuffer(0);
  state->vtkglViewport(0, 0, this->FullSize[0], this->FullSize[1]);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_SCISSOR_TEST);
  // The front faces only (wound outward; clockwise on screen where the
  // volume's matrix mirrors): a ray enters the closed boundary through one
  // before it can leave through a back face, so they cover what all do, at
  // half the fragments.
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_BACK);
  glFrontFace(this->CoverageFlipFacing ? GL_CW : GL_CCW);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  this->OpaqueDepth->Activate();
  program->SetUniformMatrix4x4("havsMCDC", this->CoverageModelToClip);
  program->SetUniformi("havsOpaqueDepth", this->OpaqueDepth->GetTextureUnit());
  program->SetUniformi("havsCoverageOpaque", this->CoverageOpaque ? 1 : 0);
  this->CoverageArray.Bind();
  glDrawArrays(GL_TRIANGLES, 0, this->CoverageVertices);
  vtkHAVSGLVertexArray::Unbind();
  glFrontFace(GL_CCW);
  this->OpaqueDepth->Deactivate();
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::SetDepthScaleUniform(vtkShaderProgram* program) const
{
  const float scale[2] = { this->Size[0] > 0 ? static_cast<float>(this->FullSize[0]) / this->Size[0]
                                             : 1.0f,
    this->Size[1] > 0 ? static_cast<float>(this->FullSize[1]) / this->Size[1] : 1.0f };
  program->SetUniform2f("havsOpaqueDepthScale", scale);
}

//------------------------------------------------------------------------------
int vtkHAVSGLFrameTargets::ReadFramebufferDepthFormat()
{
  GLint binding = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &binding);
  const GLenum attachment = binding == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
  GLint type = GL_NONE;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type == GL_NONE)
  {
    return -1;
  }
  GLint bits = 0, component = GL_NONE;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &component);
  if (component == GL_FLOAT)
  {
    return vtkTextureObject::Float32;
  }
  switch (bits)
  {
    case 16:
      return vtkTextureObject::Fixed16;
    case 24:
      return vtkTextureObject::Fixed24;
    case 32:
      return vtkTextureObject::Fixed32;
    default:
      return -1;
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::CaptureOpaqueDepth(
  int x, int y, int width, int height, vtkObject* reporter)
{
  this->CaptureFramebufferDepth(x, y, width, height, reporter);
  // An intermixed frame's slab ends at its layer, or nearer at the opaque geometry.
  vtkTextureObject* layer =
    this->IntermixLayers ? this->IntermixLayers->GetDepthTexture(this->IntermixSlab) : nullptr;
  if (layer)
  {
    this->ClampOpaqueDepth(layer);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::CaptureFramebufferDepth(
  int x, int y, int width, int height, vtkObject* reporter)
{
  GLint sampleBuffers = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
  this->LastCaptureMultisampled = sampleBuffers != 0;
  this->LastCaptureResolved = false;
  if (sampleBuffers == 0)
  {
    this->OpaqueDepth->Activate();
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, x, y, width, height);
    this->OpaqueDepth->Deactivate();
    this->LastCaptureResolved = true;
    return;
  }

  // A multisampled framebuffer cannot be copied from; its depth is resolved
  // by a blit into a single-sample depth texture. The blit needs the same
  // depth format on both sides, so the texture takes the framebuffer's.
  while (glGetError() != GL_NO_ERROR)
  {
  }
  const int format = ReadFramebufferDepthFormat();
  if (format >= 0 && format != this->OpaqueDepthFormat)
  {
    this->OpaqueDepth->ReleaseGraphicsResources(this->Window);
    this->OpaqueDepth->AllocateDepth(width, height, format);
    this->OpaqueDepthFormat = format;
    if (this->DepthResolveFramebuffer)
    {
      this->DepthResolveFramebuffer->ReleaseGraphicsResources(this->Window);
      this->DepthResolveFramebuffer = nullptr;
    }
  }
  vtkOpenGLState* state = this->Window->GetState();
  if (format >= 0)
  {
    state->PushDrawFramebufferBinding();
    if (!this->DepthResolveFramebuffer)
    {
      this->DepthResolveFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      this->DepthResolveFramebuffer->SetContext(this->Window);
      this->DepthResolveFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
      this->DepthResolveFramebuffer->AddDepthAttachment(this->OpaqueDepth);
    }
    else
    {
      this->DepthResolveFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
    }
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    state->vtkglDisable(GL_SCISSOR_TEST); // the blit's destination starts at (0, 0)
    state->vtkglBlitFramebuffer(
      x, y, x + width, y + height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    state->PopDrawFramebufferBinding();
    this->LastCaptureResolved = glGetError() == GL_NO_ERROR;
  }
  if (!this->LastCaptureResolved)
  {
    // No resolve: no opaque cut (the far plane everywhere), said once.
    std::vector<float> far(static_cast<size_t>(width) * height, 1.0f);
    this->OpaqueDepth->ReleaseGraphicsResources(this->Window);
    this->OpaqueDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
    this->OpaqueDepthFormat = vtkTextureObject::Float32;
    if (this->DepthResolveFramebuffer)
    {
      this->DepthResolveFramebuffer->ReleaseGraphicsResources(this->Window);
      this->DepthResolveFramebuffer = nullptr;
    }
    this->OpaqueDepth->Activate();
    glTexSubImage2D(
      GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, far.data());
    this->OpaqueDepth->Deactivate();
    vtkHAVSMapperInputs::WarnOnceBy(reporter, this->WarnedUnresolvedDepth,
      "The depth of this window's multisampled framebuffer could not be resolved: opaque "
      "geometry does not end the volume's rays (said once).");
  }
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::BindResult()
{
  this->ResultFramebuffer->Bind();
  this->ResultFramebuffer->ActivateDrawBuffers(1);
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::BindResultForReading()
{
  this->ResultFramebuffer->Bind(GL_READ_FRAMEBUFFER);
  this->ResultFramebuffer->ActivateReadBuffer(0);
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::ReadResult(std::vector<float>& rgba)
{
  rgba.resize(static_cast<size_t>(this->Size[0]) * this->Size[1] * 4);
  this->BindResultForReading();
  glReadPixels(0, 0, this->Size[0], this->Size[1], GL_RGBA, GL_FLOAT, rgba.data());
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkHAVSGLFrameTargets::CopyResult()
{
  if (!this->ResultCopy)
  {
    this->ResultCopy = NewFloatTexture(this->Window, this->FullSize[0], this->FullSize[1]);
  }
  this->BindResultForReading();
  this->ResultCopy->Activate();
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, this->Size[0], this->Size[1]);
  return this->ResultCopy;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::KeepResult()
{
  if (this->IntermixLayers)
  {
    // A slab's result is not the frame's: the sum is kept after the last slab.
    this->IntermixKeep = true;
    return;
  }
  this->ReadKeptResult();
}

void vtkHAVSGLFrameTargets::ReadKeptResult()
{
  this->ReadResult(this->KeptResult);
  this->KeptSize[0] = this->Size[0];
  this->KeptSize[1] = this->Size[1];
  this->KeptTime.Modified();
}

//------------------------------------------------------------------------------
const std::vector<float>* vtkHAVSGLFrameTargets::GetKeptResult(int size[2]) const
{
  size[0] = this->KeptSize[0];
  size[1] = this->KeptSize[1];
  return this->KeptResult.empty() ? nullptr : &this->KeptResult;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::ResetViolationCounter()
{
  const GLuint zero = 0;
  if (!this->ViolationCounter.GetHandle())
  {
    const GLuint zeros[2 + LoggedViolations] = {};
    this->ViolationCounter.Update(
      GL_SHADER_STORAGE_BUFFER, zeros, sizeof(zeros), 0, GL_DYNAMIC_READ);
  }
  else
  {
    this->ViolationCounter.Write(0, &zero, sizeof(GLuint));
    this->ViolationCounter.Write((1 + LoggedViolations) * sizeof(GLuint), &zero, sizeof(GLuint));
  }
  this->ViolationCounter.BindBase(GL_SHADER_STORAGE_BUFFER, 3);
}

//------------------------------------------------------------------------------
std::uint64_t vtkHAVSGLFrameTargets::ReadViolationCounter(
  std::vector<int>& pixels, std::uint64_t* shaded)
{
  GLuint data[2 + LoggedViolations] = {};
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  this->ViolationCounter.Read(0, data, sizeof(data));
  pixels.clear();
  for (GLuint i = 0; i < std::min<GLuint>(data[0], LoggedViolations); ++i)
  {
    pixels.push_back(static_cast<int>(data[1 + i] & 0xFFFFu));
    pixels.push_back(static_cast<int>(data[1 + i] >> 16));
  }
  if (shaded)
  {
    *shaded = data[1 + LoggedViolations];
  }
  return data[0];
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::SetIntermix(vtkHAVSTranslucentLayers* layers)
{
  this->IntermixLayers = layers;
  this->IntermixKeep = false;
  this->IntermixSlab = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::ClampOpaqueDepth(vtkTextureObject* layerDepth)
{
  vtkShaderProgram* program = this->Window->GetShaderCache()->ReadyShaderProgram(
    vtkHAVSShaders::QuadVertexShader().c_str(), vtkHAVSShaders::IntermixDepthShader().c_str(), "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("The intermixed slab's depth shader could not be built.");
    return;
  }
  vtkOpenGLState* state = this->Window->GetState();
  state->PushDrawFramebufferBinding();
  if (!this->ClampFramebuffer)
  {
    glGenFramebuffers(1, &this->ClampFramebuffer);
  }
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, this->ClampFramebuffer);
  glFramebufferTexture2D(
    GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, this->OpaqueDepth->GetHandle(), 0);
  state->vtkglDrawBuffer(GL_NONE);
  {
    vtkOpenGLState::ScopedglViewport viewport(state);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    state->vtkglViewport(0, 0, this->FullSize[0], this->FullSize[1]);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglDepthMask(GL_TRUE);
    layerDepth->Activate();
    program->SetUniformi("havsLayerDepth", layerDepth->GetTextureUnit());
    this->DrawFullViewport();
    layerDepth->Deactivate();
  }
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
  state->PopDrawFramebufferBinding();
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFrameTargets::AccumulateIntermix(int originX, int originY)
{
  vtkShaderProgram* program = this->Window->GetShaderCache()->ReadyShaderProgram(
    vtkHAVSShaders::QuadVertexShader().c_str(), vtkHAVSShaders::IntermixShader().c_str(), "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("The intermixed sum's shader could not be built.");
    return false;
  }
  const int count = this->IntermixLayers->GetNumberOfLayers();
  const bool last = this->IntermixSlab >= count;
  for (vtkHAVSGLImage* image : { &this->IntermixSum, &this->IntermixPrevious })
  {
    image->Resize(GL_RGBA32F, this->FullSize[0], this->FullSize[1]);
  }
  this->IntermixTransmittance.Resize(GL_R32F, this->FullSize[0], this->FullSize[1]);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  glBindImageTexture(0, this->Result->GetHandle(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  this->IntermixSum.BindImage(1);
  this->IntermixPrevious.BindImage(2);
  this->IntermixTransmittance.BindImage(3);
  vtkTextureObject* color =
    last ? nullptr : this->IntermixLayers->GetColorTexture(this->IntermixSlab);
  if (color)
  {
    color->Activate();
    program->SetUniformi("havsLayerColor", color->GetTextureUnit());
  }
  const float origin[2] = { static_cast<float>(originX), static_cast<float>(originY) };
  program->SetUniform2f("havsViewportOrigin", origin);
  program->SetUniformi("havsIntermixFirst", this->IntermixSlab == 0 ? 1 : 0);
  program->SetUniformi("havsIntermixLast", last ? 1 : 0);
  vtkOpenGLState* state = this->Window->GetState();
  {
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    this->DrawFullViewport();
  }
  if (color)
  {
    color->Deactivate();
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
    GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  for (GLuint unit = 0; unit < 4; ++unit)
  {
    vtkHAVSGLImage::UnbindImage(unit);
  }
  if (last && this->IntermixKeep)
  {
    state->PushReadFramebufferBinding();
    this->ReadKeptResult();
    state->PopReadFramebufferBinding();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFrameTargets::Composite(int originX, int originY)
{
  if (this->IntermixLayers)
  {
    // A slab before the last adds to the intermixed sum only; the last composites it.
    if (!this->AccumulateIntermix(originX, originY))
    {
      return false;
    }
    if (this->IntermixSlab < this->IntermixLayers->GetNumberOfLayers())
    {
      return true;
    }
  }
  const bool reduced = this->Size[0] != this->FullSize[0] || this->Size[1] != this->FullSize[1];
  if (reduced && this->CoverageMesh && !this->CoverageDrawn)
  {
    this->CoverageDrawn = this->DrawCoverage();
    this->CoverageMesh = nullptr; // drawn once a frame (a kept result composited again reuses it)
  }
  vtkOpenGLState* state = this->Window->GetState();
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  // The volume's shader property: its fragment uniforms declared and set here.
  auto* uniforms = vtkOpenGLUniforms::SafeDownCast(
    this->Hooks ? this->Hooks->FragmentUniforms.GetPointer() : nullptr);
  // Composed again only when the hooks were read again (their Time changed).
  const vtkMTimeType hooksTime = this->Hooks ? this->Hooks->Time : 0;
  if (this->CompositeSource.empty() || hooksTime != this->CompositeHooksTime)
  {
    this->CompositeSource =
      vtkHAVSShaders::CompositeShader(this->Hooks, uniforms ? uniforms->GetDeclarations() : "");
    this->CompositeHooksTime = hooksTime;
  }
  vtkShaderProgram* program = this->Window->GetShaderCache()->ReadyShaderProgram(
    vtkHAVSShaders::QuadVertexShader().c_str(), this->CompositeSource.c_str(), "");
  if (!program || !program->GetCompiled())
  {
    return false;
  }
  if (uniforms && !uniforms->SetUniforms(program))
  {
    vtkWarningMacro("The volume's fragment custom uniforms could not all be set in the composite.");
  }
  const bool useCoverage = reduced && this->CoverageDrawn;
  if (useCoverage)
  {
    this->Coverage->Activate();
    program->SetUniformi("havsCoverageTexture", this->Coverage->GetTextureUnit());
  }
  program->SetUniformi("havsUseCoverage", useCoverage ? 1 : 0);
  this->Result->Activate();
  program->SetUniformi("havsResultTexture", this->Result->GetTextureUnit());
  const float origin[2] = { static_cast<float>(originX), static_cast<float>(originY) };
  program->SetUniform2f("havsViewportOrigin", origin);
  // The drawn pixels per viewport pixel: 1 reads the result texel for texel.
  const float scale[2] = {
    this->FullSize[0] > 0 ? static_cast<float>(this->Size[0]) / this->FullSize[0] : 1.0f,
    this->FullSize[1] > 0 ? static_cast<float>(this->Size[1]) / this->FullSize[1] : 1.0f
  };
  program->SetUniform2f("havsResultScale", scale);
  program->SetUniformi("havsResultReduced", reduced ? 1 : 0);
  // The drawn image's last texel (the result texture is of the full size).
  const int last[2] = { std::max(this->Size[0] - 1, 0), std::max(this->Size[1] - 1, 0) };
  program->SetUniform2i("havsResultLast", last);
  this->DrawFullViewport();
  this->Result->Deactivate();
  if (useCoverage)
  {
    this->Coverage->Deactivate();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSGLFrameTargets::EndFrame(bool resolved, bool keep,
  std::initializer_list<vtkTextureObject*> textures, int originX, int originY, vtkObject* reporter)
{
  if (keep)
  {
    this->KeepResult();
  }
  for (vtkTextureObject* t : textures)
  {
    t->Deactivate();
  }
  vtkOpenGLState* state = this->Window->GetState();
  state->PopFramebufferBindings();
  state->vtkglViewport(originX, originY, this->FullSize[0], this->FullSize[1]);
  if (!resolved)
  {
    vtkErrorWithObjectMacro(
      reporter, "The resolve shader could not be built; see the shader log above.");
    return false;
  }
  return this->Composite(originX, originY);
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::DrawFullViewport()
{
  this->EmptyVertexArray.Bind(); // no attributes: the corners come from gl_VertexID
  glDrawArrays(GL_TRIANGLES, 0, 3);
  vtkHAVSGLVertexArray::Unbind();
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::ReleaseSizeDependent(vtkWindow* window)
{
  if (this->OpaqueDepth)
  {
    this->OpaqueDepth->ReleaseGraphicsResources(window);
  }
  if (this->Result)
  {
    this->Result->ReleaseGraphicsResources(window);
  }
  if (this->ResultCopy)
  {
    this->ResultCopy->ReleaseGraphicsResources(window);
  }
  if (this->ResultFramebuffer)
  {
    this->ResultFramebuffer->ReleaseGraphicsResources(window);
  }
  if (this->DepthResolveFramebuffer)
  {
    this->DepthResolveFramebuffer->ReleaseGraphicsResources(window);
  }
  if (this->Coverage)
  {
    this->Coverage->ReleaseGraphicsResources(window);
  }
  if (this->CoverageFramebuffer)
  {
    this->CoverageFramebuffer->ReleaseGraphicsResources(window);
  }
  this->Coverage = nullptr;
  this->CoverageFramebuffer = nullptr;
  this->CoverageDrawn = false;
  this->DepthResolveFramebuffer = nullptr;
  this->OpaqueDepth = nullptr;
  this->Result = nullptr;
  this->ResultCopy = nullptr;
  this->ResultFramebuffer = nullptr;
  this->Size[0] = this->Size[1] = 0;
  this->FullSize[0] = this->FullSize[1] = 0;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::ReleaseGraphicsResources(vtkWindow* window)
{
  this->ReleaseSizeDependent(window);
  this->IntermixSum.Release();
  this->IntermixPrevious.Release();
  this->IntermixTransmittance.Release();
  if (this->ClampFramebuffer)
  {
    glDeleteFramebuffers(1, &this->ClampFramebuffer);
    this->ClampFramebuffer = 0;
  }
  this->ViolationCounter.Release();
  this->EmptyVertexArray.Release();
  this->CoveragePoints.Release();
  this->CoverageArray.Release();
  this->CoverageVertices = 0;
  this->CoverageMesh = nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSGLFrameTargets::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << " (viewport "
     << this->FullSize[0] << " x " << this->FullSize[1] << ")\n";
  os << indent << "LastCaptureMultisampled: " << this->LastCaptureMultisampled << "\n";
  os << indent << "LastCaptureResolved: " << this->LastCaptureResolved << "\n";
  os << indent << "LastCoverageUsed: " << this->CoverageDrawn
     << ", coverage vertices: " << this->CoverageVertices << "\n";
}

VTK_ABI_NAMESPACE_END
