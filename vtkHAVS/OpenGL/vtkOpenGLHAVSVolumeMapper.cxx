/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSVolumeMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkOpenGLHAVSVolumeMapper.h"

#include "vtkHAVSExtremumPass.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFragmentListKBuffer.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSFramebufferFetchKBuffer.h"
#include "vtkHAVSGLFrameCapture.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLMapperResources.h"
#include "vtkHAVSGLMesh.h"
#include "vtkHAVSGLPassContext.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSInterlockKBuffer.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSRasterBoundPass.h"
#include "vtkHAVSViewFrame.h"

#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGridBase.h"

#include <dlfcn.h>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkOpenGLHAVSVolumeMapper);

namespace
{
/// Keeps this library loaded until the process ends. vtk_module_autoinit
/// registers this module's object factory with VTK, and VTK deletes the
/// registered factories in its own static cleanup at exit; a ParaView plugin
/// that brought this library in may be unloaded before that (ParaView 5.13
/// does), and the factory's code with it: the exit then crashed in
/// vtkObjectFactory::UnRegisterAllFactories. RTLD_NODELETE pins the library.
struct KeepLoaded
{
  KeepLoaded()
  {
    Dl_info self;
    if (dladdr(reinterpret_cast<void*>(&vtkOpenGLHAVSVolumeMapper::New), &self) && self.dli_fname)
    {
      dlopen(self.dli_fname, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
    }
  }
} keepLoaded;
}

//------------------------------------------------------------------------------
/// The mapper's own GPU objects, released with the resources (its mesh and k-buffers).
struct vtkOpenGLHAVSVolumeMapper::GLObjects : vtkHAVSGLOwnObjects
{
  vtkOpenGLHAVSVolumeMapper* Self = nullptr;
  void Release(vtkOpenGLRenderWindow* window) override
  {
    this->Self->GLMesh->ReleaseGraphicsResources(window);
    this->Self->FetchKBuffer->ReleaseGraphicsResources(window);
    this->Self->InterlockKBuffer->ReleaseGraphicsResources(window);
    this->Self->ListKBuffer->ReleaseGraphicsResources(window);
  }
};

//------------------------------------------------------------------------------
vtkOpenGLHAVSVolumeMapper::vtkOpenGLHAVSVolumeMapper()
{
  this->Resources->Own(std::make_unique<GLObjects>())->Self = this;
  this->SetGraphics(this->Resources);
}

vtkOpenGLHAVSVolumeMapper::~vtkOpenGLHAVSVolumeMapper()
{
  this->ReleaseGraphicsResources(nullptr);
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSVolumeMapper::IsKBufferPathSupported(vtkRenderWindow* window, int path)
{
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!glWindow)
  {
    return false;
  }
  glWindow->MakeCurrent();
  switch (path)
  {
    case KBufferPathFramebufferFetch:
      return vtkHAVSFramebufferFetchKBuffer::IsSupported(glWindow);
    case KBufferPathFragmentShaderInterlock:
      return vtkHAVSInterlockKBuffer::IsSupported(glWindow);
    case KBufferPathFragmentLists:
      return vtkHAVSFragmentListKBuffer::IsSupported(glWindow);
    default:
      return false;
  }
}

//------------------------------------------------------------------------------
int vtkOpenGLHAVSVolumeMapper::ChooseKBufferPath(vtkRenderer* renderer, int requested)
{
  vtkRenderWindow* window = renderer->GetRenderWindow();
  if (requested != KBufferPathAutomatic && this->IsKBufferPathSupported(window, requested))
  {
    return requested;
  }
  for (int path :
    { KBufferPathFramebufferFetch, KBufferPathFragmentShaderInterlock, KBufferPathFragmentLists })
  {
    if (this->IsKBufferPathSupported(window, path))
    {
      return path;
    }
  }
  return 0;
}

//------------------------------------------------------------------------------
int vtkOpenGLHAVSVolumeMapper::GetMaximumK(int path)
{
  vtkHAVSKBuffer* kbuffer = this->GetKBuffer(path);
  return kbuffer ? kbuffer->GetMaximumK() : 0;
}

//------------------------------------------------------------------------------
vtkHAVSKBuffer* vtkOpenGLHAVSVolumeMapper::GetKBuffer(int path)
{
  switch (path)
  {
    case KBufferPathFramebufferFetch:
      return this->FetchKBuffer;
    case KBufferPathFragmentShaderInterlock:
      return this->InterlockKBuffer;
    case KBufferPathFragmentLists:
      return this->ListKBuffer;
    default:
      return nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSVolumeMapper::Upload(const FrameRequest& request, FrameResult& result)
{
  // Each GPU object uploads what changed since its last upload (its versions).
  const int geometry = this->GLMesh->UpdateGeometry(request.Mesh);
  result.GeometryUploaded = geometry == vtkHAVSGLMesh::UploadedGeometry;
  result.ScalarsUploaded = geometry == vtkHAVSGLMesh::UploadedScalars;
  // (Shaded isosurfaces: the points' gradients before the order, which copies
  // the boundary vertices' ones.)
  this->GLMesh->UpdateGradients(
    request.IsoShade ? request.PointGradients : nullptr, request.PointGradientsVersion);
  bool failed = false;
  result.OrderUploaded = this->GLMesh->UpdateFaceOrder(*request.DrawTriangles,
    *request.DrawBoundary, request.Tagging, request.DrawOrderVersion, &failed);
  if (failed)
  {
    return false;
  }
  this->GLMesh->UpdateSections(request.Planes->GetSections(), request.Planes->GetSectionsVersion(),
    request.Mesh->GetFaceSet()->GetTetrahedra());
  result.TableUploaded = this->Resources->GetTable()->Update(request.Table, request.TableVersion);
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSVolumeMapper::DrawFrame(
  vtkRenderer* renderer, const FrameRequest& request, FrameResult& result)
{
  vtkOpenGLRenderWindow* window =
    this->Resources->Prepare(renderer, this, "vtkHAVSVolumeMapper", "storage buffers, images");
  if (!window)
  {
    return false;
  }
  this->GLMesh->SetContext(window);
  vtkHAVSGLFrameTargets* targets = this->Resources->GetTargets();
  vtkHAVSGLTable* glTable = this->Resources->GetTable();
  const bool measure = request.MeasureStages;
  auto now = [measure]()
  {
    if (!measure)
    {
      return 0.0;
    }
    glFinish();
    return vtkTimerLog::GetUniversalTime();
  };
  const double uploadStart = now();
  if (!this->Upload(request, result))
  {
    return false;
  }
  result.UploadSeconds = now() - uploadStart;
  const vtkHAVSViewFrame& view = *request.View;
  const int width = view.Width, height = view.Height;
  vtkOpenGLState* state = window->GetState();
  targets->Resize(view.FullWidth, view.FullHeight, width, height);
  targets->SetCoverage(
    this->GetLastEdgeUpsampling() ? request.Mesh : nullptr, view, *request.Planes, request.Opaque);
  if (request.Opaque)
  {
    targets->CaptureOpaqueDepth(view.OriginX, view.OriginY, view.FullWidth, view.FullHeight, this);
    result.OpaqueDepthMultisampled = targets->GetLastCaptureMultisampled();
    result.OpaqueDepthCaptured = targets->GetLastCaptureResolved();
  }
  vtkHAVSGLPassContext context(window, this->GLMesh, glTable, targets, request);
  const bool extremum = request.BlendMode != COMPOSITE_BLEND;
  vtkHAVSKBuffer* kbuffer = this->GetKBuffer(request.Path);

  vtkHAVSGLScopedPassState passState(state);
  state->vtkglDisable(GL_BLEND);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglViewport(0, 0, width, height);
  vtkTextureObject* textures[] = { glTable->GetTable(), glTable->GetCellOptics(),
    targets->GetOpaqueDepth() };
  for (vtkTextureObject* t : textures)
  {
    t->Activate();
  }
  state->PushFramebufferBindings();

  // Draw, resolve.
  const double t0 = now();
  bool ok = false;
  if (request.RasterBoundOnly)
  {
    ok = this->RasterBound->Draw(context);
  }
  else if (extremum)
  {
    ok = this->Extremum->Draw(context);
  }
  else if (kbuffer)
  {
    targets->ResetViolationCounter();
    ok = kbuffer->Allocate(context) && kbuffer->Clear(context) && kbuffer->Draw(context);
    result.Fragments = kbuffer->GetLastFragmentCount();
    result.SaturatedPixels = kbuffer->GetLastSaturatedPixels();
  }
  const double t1 = now();
  if (ok && !request.RasterBoundOnly)
  {
    targets->BindResult();
    ok = extremum ? this->Extremum->Resolve(context) : kbuffer->Resolve(context);
  }

  // Read backs.
  const double tr = now();
  if (ok && !request.RasterBoundOnly && !extremum && request.CountViolations)
  {
    std::uint64_t shaded = 0;
    result.Violations =
      static_cast<vtkIdType>(targets->ReadViolationCounter(result.ViolationPixels, &shaded));
    if (kbuffer->GetPath() != KBufferPathFragmentLists)
    {
      result.ShadedFragments = static_cast<vtkIdType>(shaded);
    }
  }
  if (ok && request.KeepResult)
  {
    targets->KeepResult();
  }
  const double t2 = now();
  if (ok && this->CaptureDirectory && !request.RasterBoundOnly && !extremum)
  {
    std::string error;
    this->LastCaptureSucceeded = vtkHAVSGLFrameCapture::Write(this->CaptureDirectory, context,
      this->GetInput() ? this->GetInput()->GetNumberOfCells() : 0, error);
    if (!this->LastCaptureSucceeded)
    {
      vtkErrorMacro("No frame capture: " << error << ".");
    }
    this->SetCaptureDirectory(nullptr);
  }
  for (vtkTextureObject* t : textures)
  {
    t->Deactivate();
  }
  state->PopFramebufferBindings();

  // Composite.
  if (ok && !request.RasterBoundOnly && request.Composite)
  {
    state->vtkglViewport(view.OriginX, view.OriginY, view.FullWidth, view.FullHeight);
    ok = targets->Composite(view.OriginX, view.OriginY);
  }
  if (request.Finish && !measure)
  {
    glFinish(); // the level of detail times the whole frame
  }
  const double t3 = now();
  result.DrawSeconds = t1 - t0;
  result.FlushSeconds = tr - t1;
  result.ReadbackSeconds = t2 - tr;
  result.CompositeSeconds = t3 - t2;
  if (!ok)
  {
    vtkErrorMacro("A vtkHAVS shader could not be built for the " << GetKBufferPathName(request.Path)
                                                                 << " path with k = " << request.K
                                                                 << "; see the shader log above.");
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkOpenGLHAVSVolumeMapper::CompositeKeptResult(vtkRenderer* renderer)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkHAVSGLFrameTargets* targets = this->Resources->GetTargets();
  int width = 0, height = 0, originX = 0, originY = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &originX, &originY);
  if (!window || window != this->Resources->GetWindow() || !targets->GetResult() ||
    width != targets->GetFullSize()[0] || height != targets->GetFullSize()[1])
  {
    vtkErrorMacro("CompositeKeptResult needs the last frame's result in this window.");
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  vtkHAVSGLScopedPassState passState(state);
  state->vtkglViewport(originX, originY, width, height);
  return targets->Composite(originX, originY);
}

//------------------------------------------------------------------------------
void vtkOpenGLHAVSVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->GLMesh->PrintSelf(os, indent.GetNextIndent());
  this->Resources->PrintSelf(os, indent.GetNextIndent());
}

VTK_ABI_NAMESPACE_END
