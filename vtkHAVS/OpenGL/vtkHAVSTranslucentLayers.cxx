/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTranslucentLayers.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSTranslucentLayers.h"

#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLObjects.h"
#include "vtkHAVSIntermixPass.h"
#include "vtkHAVSShaders.h"

#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSTranslucentLayers);
vtkInformationKeyMacro(vtkHAVSTranslucentLayers, LAYERS, ObjectBase);

vtkHAVSTranslucentLayers::vtkHAVSTranslucentLayers() = default;

vtkHAVSTranslucentLayers::~vtkHAVSTranslucentLayers()
{
  // GL names are deleted only in the window's current context (a host may
  // delete this pass after it destroyed the context: ParaView at exit).
  if (this->Window && !this->Window->IsCurrent())
  {
    this->Window->RemoveObserver(this->WindowDeleteObserver);
    this->Window = nullptr;
  }
  this->ReleaseGraphicsResources(this->Window);
}

//------------------------------------------------------------------------------
void vtkHAVSTranslucentLayers::Allocate(
  vtkOpenGLRenderWindow* window, int count, int width, int height)
{
  if (window != this->Window || width != this->Size[0] || height != this->Size[1])
  {
    if (this->Window && this->Window != window)
    {
      this->Window->MakeCurrent(); // the old window's objects, in their context
    }
    this->ReleaseGraphicsResources(this->Window);
    window->MakeCurrent();
    this->Window = window;
    this->WindowDeleteObserver = window->AddObserver(
      vtkCommand::DeleteEvent, this, &vtkHAVSTranslucentLayers::OnWindowDeleted);
    this->Size[0] = width;
    this->Size[1] = height;
  }
  this->Opaque->SetContext(window);
  this->Opaque->Resize(width, height);
  while (static_cast<int>(this->Layers.size()) < count)
  {
    Layer layer;
    layer.Depth = vtkSmartPointer<vtkTextureObject>::New();
    layer.Depth->SetContext(window);
    layer.Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
    layer.Color = vtkHAVSGLFrameTargets::NewFloatTexture(window, width, height);
    this->Layers.push_back(layer);
  }
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(window);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSTranslucentLayers::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->NumberOfLayers = 0;
  this->Truncated = false;
  this->Taken = false;
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window || !vtkHAVSIntermixPass::HasTranslucentGeometry(s))
  {
    return;
  }
  int width = 0, height = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, this->Origin, this->Origin + 1);
  if (width <= 0 || height <= 0)
  {
    return;
  }
  this->Allocate(window, 1, width, height);
  vtkOpenGLState* state = window->GetState();
  // The opaque geometry's depth: fragments behind it are never peeled.
  this->Opaque->CaptureOpaqueDepth(this->Origin[0], this->Origin[1], width, height, this);

  state->PushFramebufferBindings();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglClearColor clearColor(state);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglViewport(0, 0, width, height);
  // Each translucent actor writes its depth while peeled (VTK's actors do not, translucent).
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    vtkInformation* info = prop->GetPropertyKeys();
    if (!info)
    {
      info = vtkInformation::New();
      prop->SetPropertyKeys(info);
      info->Delete();
    }
    info->Set(vtkOpenGLActor::GLDepthMaskOverride(), 1);
  }
  this->PreRender(s);
  for (int i = 0; i < this->MaximumNumberOfLayers; ++i)
  {
    this->Allocate(window, i + 1, width, height);
    this->Peeling = i;
    this->Framebuffer->Bind();
    this->Framebuffer->AddColorAttachment(0, this->Layers[i].Color);
    this->Framebuffer->AddDepthAttachment(this->Layers[i].Depth);
    this->Framebuffer->ActivateDrawBuffers(1);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    this->Opaque->GetOpaqueDepth()->Activate();
    if (i > 0)
    {
      this->Layers[i - 1].Depth->Activate();
    }
    vtkHAVSGLQueries samples;
    samples.BeginSamples();
    this->Translucent->Render(s);
    samples.EndSamples();
    if (i > 0)
    {
      this->Layers[i - 1].Depth->Deactivate();
    }
    this->Opaque->GetOpaqueDepth()->Deactivate();
    this->NumberOfRenderedProps =
      std::max(this->NumberOfRenderedProps, this->Translucent->GetNumberOfRenderedProps());
    const std::vector<uint64_t> passed = samples.Samples();
    samples.Release();
    if (passed.empty() || passed[0] == 0)
    {
      break;
    }
    this->NumberOfLayers = i + 1;
  }
  this->PostRender(s);
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkInformation* info = s->GetPropArray()[i]->GetPropertyKeys();
    if (info)
    {
      info->Remove(vtkOpenGLActor::GLDepthMaskOverride());
    }
  }
  this->Framebuffer->UnBind();
  state->PopFramebufferBindings();

  this->Truncated = this->NumberOfLayers == this->MaximumNumberOfLayers;
  if (this->Truncated && !this->WarnedTruncated)
  {
    this->WarnedTruncated = true;
    vtkWarningMacro("The translucent geometry has " << this->MaximumNumberOfLayers
                                                    << " or more layers at some pixels: the ones "
                                                       "beyond are left out (said once; raise "
                                                       "MaximumNumberOfLayers).");
  }
  if (this->NumberOfLayers > 0)
  {
    if (!renderer->GetInformation())
    {
      vtkNew<vtkInformation> info;
      renderer->SetInformation(info);
    }
    renderer->GetInformation()->Set(LAYERS(), this);
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSTranslucentLayers::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::DepthPeeling::Dec",
    "uniform sampler2D havsPeelOpaque;\n"
    "uniform sampler2D havsPeelPrevious;\n"
    "uniform int havsPeelFirst;\n");
  // The fragment's depth, unless the mapper already sets it (then its value is used).
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Depth::Impl", "gl_FragDepth = gl_FragCoord.z;");
  // Behind the opaque geometry, or not behind the previous layer: not this layer's.
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::DepthPeeling::PreColor",
    "ivec2 havsPeelPixel = ivec2(gl_FragCoord.xy);\n"
    "  if (gl_FragDepth >= texelFetch(havsPeelOpaque, havsPeelPixel, 0).r) { discard; }\n"
    "  if (havsPeelFirst == 0 &&\n"
    "    gl_FragDepth <= texelFetch(havsPeelPrevious, havsPeelPixel, 0).r + 1.0e-7) { discard; "
    "}\n");
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSTranslucentLayers::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  program->SetUniformi("havsPeelOpaque", this->Opaque->GetOpaqueDepth()->GetTextureUnit());
  program->SetUniformi("havsPeelFirst", this->Peeling == 0 ? 1 : 0);
  vtkTextureObject* previous = this->Peeling > 0 ? this->Layers[this->Peeling - 1].Depth.Get()
                                                 : this->Opaque->GetOpaqueDepth();
  program->SetUniformi("havsPeelPrevious", previous->GetTextureUnit());
  return true;
}

//------------------------------------------------------------------------------
vtkHAVSTranslucentLayers* vtkHAVSTranslucentLayers::GetLayersOf(vtkRenderer* renderer)
{
  vtkInformation* info = renderer ? renderer->GetInformation() : nullptr;
  return info ? vtkHAVSTranslucentLayers::SafeDownCast(info->Get(LAYERS())) : nullptr;
}

bool vtkHAVSTranslucentLayers::Take()
{
  if (this->Taken || this->NumberOfLayers == 0)
  {
    return false;
  }
  this->Taken = true;
  return true;
}

vtkTextureObject* vtkHAVSTranslucentLayers::GetDepthTexture(int i)
{
  return i >= 0 && i < this->NumberOfLayers ? this->Layers[i].Depth.Get() : nullptr;
}

vtkTextureObject* vtkHAVSTranslucentLayers::GetColorTexture(int i)
{
  return i >= 0 && i < this->NumberOfLayers ? this->Layers[i].Color.Get() : nullptr;
}

//------------------------------------------------------------------------------
bool vtkHAVSTranslucentLayers::ReadLayer(int i, vtkFloatArray* depth, vtkFloatArray* rgba)
{
  if (i < 0 || i >= this->NumberOfLayers || !this->Window)
  {
    return false;
  }
  this->Window->MakeCurrent();
  const vtkIdType pixels = static_cast<vtkIdType>(this->Size[0]) * this->Size[1];
  vtkOpenGLState* state = this->Window->GetState();
  state->PushReadFramebufferBinding();
  this->Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  this->Framebuffer->AddColorAttachment(0, this->Layers[i].Color);
  this->Framebuffer->AddDepthAttachment(this->Layers[i].Depth);
  this->Framebuffer->ActivateReadBuffer(0);
  if (depth)
  {
    depth->SetNumberOfComponents(1);
    depth->SetNumberOfTuples(pixels);
    glReadPixels(
      0, 0, this->Size[0], this->Size[1], GL_DEPTH_COMPONENT, GL_FLOAT, depth->GetPointer(0));
  }
  if (rgba)
  {
    rgba->SetNumberOfComponents(4);
    rgba->SetNumberOfTuples(pixels);
    glReadPixels(0, 0, this->Size[0], this->Size[1], GL_RGBA, GL_FLOAT, rgba->GetPointer(0));
  }
  state->PopReadFramebufferBinding();
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSTranslucentLayers::CompositeLayers(vtkRenderer* renderer)
{
  this->Taken = true;
  if (this->NumberOfLayers == 0 || !this->Window)
  {
    return;
  }
  vtkOpenGLState* state = this->Window->GetState();
  vtkShaderProgram* program = this->Window->GetShaderCache()->ReadyShaderProgram(
    vtkHAVSShaders::QuadVertexShader().c_str(), vtkHAVSShaders::LayerCompositeShader().c_str(), "");
  if (!program || !program->GetCompiled())
  {
    vtkErrorMacro("The layers' composite shader could not be built; see the shader log above.");
    return;
  }
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  state->vtkglViewport(x, y, width, height);
  state->vtkglEnable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const float origin[2] = { static_cast<float>(x), static_cast<float>(y) };
  program->SetUniform2f("havsViewportOrigin", origin);
  for (int i = this->NumberOfLayers - 1; i >= 0; --i)
  {
    this->Layers[i].Color->Activate();
    program->SetUniformi("havsLayerColor", this->Layers[i].Color->GetTextureUnit());
    this->Opaque->DrawFullViewport();
    this->Layers[i].Color->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSTranslucentLayers::FinishFrame(vtkRenderer* renderer)
{
  if (this->NumberOfLayers > 0 && !this->Taken)
  {
    this->CompositeLayers(renderer);
  }
  if (renderer->GetInformation())
  {
    renderer->GetInformation()->Remove(LAYERS());
  }
}

//------------------------------------------------------------------------------
void vtkHAVSTranslucentLayers::OnWindowDeleted(vtkObject* window, unsigned long, void*)
{
  this->ReleaseGraphicsResources(vtkWindow::SafeDownCast(window));
}

//------------------------------------------------------------------------------
void vtkHAVSTranslucentLayers::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Window && (!window || window == this->Window))
  {
    // (VTK's convention: the caller has made the window's context current.)
    window = this->Window;
    this->Window->RemoveObserver(this->WindowDeleteObserver);
    for (Layer& layer : this->Layers)
    {
      layer.Depth->ReleaseGraphicsResources(this->Window);
      layer.Color->ReleaseGraphicsResources(this->Window);
    }
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(this->Window);
    }
    this->Opaque->ReleaseGraphicsResources(this->Window);
  }
  this->Layers.clear();
  this->Framebuffer = nullptr;
  this->Window = nullptr;
  this->Size[0] = this->Size[1] = 0;
  this->NumberOfLayers = 0;
  if (window)
  {
    this->Translucent->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSTranslucentLayers::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumNumberOfLayers: " << this->MaximumNumberOfLayers << "\n";
  os << indent << "NumberOfLayers: " << this->NumberOfLayers
     << (this->Truncated ? " (every layer filled)" : "") << "\n";
  os << indent << "Taken: " << this->Taken << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
}

VTK_ABI_NAMESPACE_END
