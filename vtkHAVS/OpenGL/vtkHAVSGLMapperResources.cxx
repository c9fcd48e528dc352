/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLMapperResources.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLMapperResources.h"

#include "vtkHAVSExtremumPass.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSFrameRequest.h"
#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameCapture.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLObjects.h"
#include "vtkHAVSGLTable.h"
#include "vtkHAVSGLTableBuilder.h"
#include "vtkHAVSMapperBase.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSTranslucentLayers.h"
#include "vtkHAVSViewFrame.h"

#include "vtkCommand.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSGLMapperResources);

//------------------------------------------------------------------------------
vtkHAVSGLMapperResources::vtkHAVSGLMapperResources()
  : Section(new vtkHAVSGLSection)
  , IsoGradientFields(new vtkHAVSGLBuffer)
{
}

vtkHAVSGLMapperResources::~vtkHAVSGLMapperResources()
{
  this->Release(nullptr);
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkHAVSGLMapperResources::Prepare(
  vtkRenderer* renderer, vtkObject* mapper, const char* mapperName, const char* needs)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorWithObjectMacro(mapper, << mapperName << " needs an OpenGL render window.");
    return nullptr;
  }
  if (this->Window != window)
  {
    this->Release(this->Window);
    this->Window = window;
    this->WindowDeleteObserver = window->AddObserver(
      vtkCommand::DeleteEvent, this, &vtkHAVSGLMapperResources::OnWindowDeleted);
    this->Table->SetContext(window);
    this->Targets->SetContext(window);
  }
  window->MakeCurrent();
  // The volume's shader property, as the mapper read it this frame, reaches the composite.
  auto* base = vtkHAVSMapperBase::SafeDownCast(mapper);
  this->Targets->SetShaderHooks(base ? &base->GetShaderHooks() : nullptr);
  // The frame's isosurfaces reach every pass that composites segments.
  this->Table->SetIsoSurfaces(base ? &base->GetFrameIsoSurfaces() : nullptr);
  if (!vtkHAVSGLCapabilities::HasVersion(4, 3))
  {
    vtkErrorWithObjectMacro(mapper, << mapperName << " needs OpenGL 4.3 (" << needs << ").");
    return nullptr;
  }
  return window;
}

//------------------------------------------------------------------------------
const std::vector<float>* vtkHAVSGLMapperResources::GetKeptResult(int size[2])
{
  return this->Targets->GetKeptResult(size);
}

vtkMTimeType vtkHAVSGLMapperResources::GetKeptResultTime()
{
  return this->Targets->GetKeptResultTime();
}

namespace
{
/// The most planes the shaders take: 6 clipping planes and the near plane.
constexpr int MaximumPlanes = 7;
/// The additive blend's value (vtkVolumeMapper::ADDITIVE_BLEND).
constexpr int AdditiveBlend = 4;
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkHAVSGLMapperResources::BeginFrame(vtkRenderer* renderer,
  vtkObject* mapper, const char* mapperName, const char* needs, const vtkHAVSViewFrame& view,
  bool opaque, const vtkHAVSFramePlanes& planes, vtkHAVSMesh* mesh)
{
  vtkOpenGLRenderWindow* window = this->Prepare(renderer, mapper, mapperName, needs);
  if (!window)
  {
    return nullptr;
  }
  this->Targets->Resize(view.FullWidth, view.FullHeight, view.Width, view.Height);
  this->Targets->SetCoverage(mesh, view, planes, opaque);
  if (opaque)
  {
    this->Targets->CaptureOpaqueDepth(
      view.OriginX, view.OriginY, view.FullWidth, view.FullHeight, mapper);
  }
  this->SectionTriangles = this->Section->Update(planes);
  return window;
}

void vtkHAVSGLMapperResources::DrawSection(unsigned int cellBinding)
{
  this->Section->Draw(cellBinding);
}

void vtkHAVSGLMapperResources::ActivateTextures()
{
  this->Table->GetTable()->Activate();
  this->Targets->GetOpaqueDepth()->Activate();
  this->Table->GetAdditive1D()->Activate();
  this->Table->GetCellOptics()->Activate();
}

void vtkHAVSGLMapperResources::SetTextureUniforms(vtkShaderProgram* program)
{
  this->Table->SetUniforms(program);
  program->SetUniformi("havsAdditive", this->Table->GetAdditive1D()->GetTextureUnit());
  program->SetUniformi("havsOpaqueDepth", this->Targets->GetOpaqueDepth()->GetTextureUnit());
  this->Targets->SetDepthScaleUniform(program);
}

//------------------------------------------------------------------------------
bool vtkHAVSGLMapperResources::BindIsoShading(vtkHAVSMapperBase* mapper, size_t largestBuffer)
{
  if (!mapper || !mapper->GetFrameIsoSurfaces().Shaded)
  {
    return false;
  }
  vtkMTimeType version = 0;
  const std::vector<float>& fields = mapper->GetIsoGradientFields(version);
  const size_t bytes = fields.size() * sizeof(float);
  if (bytes > largestBuffer)
  {
    if (!this->WarnedIsoFields)
    {
      vtkWarningWithObjectMacro(
        mapper, << "The shaded isosurfaces' gradient fields (" << bytes
                << " bytes) exceed the largest GPU buffer (" << largestBuffer
                << " bytes, SetLargestGPUBuffer): the isosurfaces are drawn unshaded (said once).");
      this->WarnedIsoFields = true;
    }
    return false;
  }
  this->IsoGradientFields->Update(GL_SHADER_STORAGE_BUFFER, fields, version);
  this->IsoGradientFields->BindBase(GL_SHADER_STORAGE_BUFFER, 13);
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSGLMapperResources::SetViewUniforms(vtkShaderProgram* program,
  const vtkHAVSViewFrame& view, vtkHAVSFramePlanes* planes, const double shift[3], bool eye)
{
  float m[16];
  vtkHAVSViewFrame::ToColumnMajor(view.ModelToEyeRelative, m);
  program->SetUniformMatrix4x4("havsMCRC", m);
  vtkHAVSViewFrame::ToColumnMajor(view.ClipToEyeRelative, m);
  program->SetUniformMatrix4x4("havsDCRC", m);
  vtkHAVSGLMapperResources::SetDoubleViewUniforms(program, view);
  float eyeModel[3], direction[3], directionWorld[3];
  for (int i = 0; i < 3; ++i)
  {
    eyeModel[i] = static_cast<float>(view.EyeGrid[i] - shift[i]);
    direction[i] = static_cast<float>(view.DirectionGrid[i]);
    directionWorld[i] = static_cast<float>(view.DirectionWorld[i]);
  }
  program->SetUniform3f("havsDirectionOfProjection", directionWorld);
  program->SetUniformi("havsParallel", view.Parallel ? 1 : 0);
  const float viewport[2] = { static_cast<float>(view.Width), static_cast<float>(view.Height) };
  program->SetUniform2f("havsViewportSize", viewport);
  const int planeCount = std::min(planes->GetNumberOfPlanes(), MaximumPlanes);
  program->SetUniformi("havsPlaneCount", planeCount);
  if (planeCount > 0)
  {
    float values[MaximumPlanes][4] = {};
    for (int i = 0; i < planeCount; ++i)
    {
      std::copy(planes->GetPlane(i).begin(), planes->GetPlane(i).end(), values[i]);
    }
    program->SetUniform4fv("havsPlanesRC", planeCount, values);
  }
  if (eye)
  {
    program->SetUniform3f("havsEyeMC", eyeModel);
    program->SetUniform3f("havsDirectionMC", direction);
    double clipToModel[16], toModel[16];
    vtkMatrix4x4::Invert(view.ModelToClip, clipToModel);
    vtkHAVSViewFrame::ToColumnMajor(clipToModel, m);
    program->SetUniformMatrix4x4("havsDCMC", m);
    vtkMatrix4x4::Invert(view.ModelToEyeRelative, toModel);
    float linear[9];
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        linear[3 * j + i] = static_cast<float>(toModel[4 * i + j]); // column-major
      }
    }
    program->SetUniformMatrix3x3("havsRCMC", linear);
  }
}

void vtkHAVSGLMapperResources::SetDoubleViewUniforms(
  vtkShaderProgram* program, const vtkHAVSViewFrame& view)
{
  // (vtkShaderProgram sets float uniforms only.)
  const GLint clipToModel = glGetUniformLocation(program->GetHandle(), "havsDCMCd");
  if (clipToModel >= 0)
  {
    double inverse[16];
    vtkMatrix4x4::Invert(view.ModelToClip, inverse);
    glUniformMatrix4dv(clipToModel, 1, GL_TRUE, inverse); // (row-major)
  }
  const GLint eye = glGetUniformLocation(program->GetHandle(), "havsEyeMCd");
  if (eye >= 0)
  {
    // The eye-relative origin in model coordinates.
    double inverse[16];
    vtkMatrix4x4::Invert(view.ModelToEyeRelative, inverse);
    const double eyeModel[3] = { inverse[3] / inverse[15], inverse[7] / inverse[15],
      inverse[11] / inverse[15] };
    glUniform3dv(eye, 1, eyeModel);
  }
}

void vtkHAVSGLMapperResources::SetBlending(int blend)
{
  vtkOpenGLState* state = this->Window->GetState();
  state->vtkglEnable(GL_BLEND);
  if (blend == vtkHAVSFrameRequest::CompositeBlend)
  {
    // Front to back: what is drawn goes under what is in front (premultiplied).
    state->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
  }
  else
  {
    // Order-independent: the largest (of s, or of 1 - s), or the sum.
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    state->vtkglBlendEquation(blend == AdditiveBlend ? GL_FUNC_ADD : GL_MAX);
  }
}

bool vtkHAVSGLMapperResources::EndFrame(
  int blend, bool keep, const vtkHAVSViewFrame& view, vtkObject* mapper)
{
  vtkOpenGLState* state = this->Window->GetState();
  state->vtkglDisable(GL_BLEND);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  const bool resolved =
    vtkHAVSExtremumPass::ResolveBlend(this->Window, this->Targets, this->Table, blend);
  return this->Targets->EndFrame(resolved, keep,
    { this->Table->GetCellOptics(), this->Table->GetAdditive1D(), this->Table->GetTable(),
      this->Targets->GetOpaqueDepth() },
    view.OriginX, view.OriginY, mapper);
}

//------------------------------------------------------------------------------
int vtkHAVSGLMapperResources::BeginIntermix(vtkRenderer* renderer)
{
  vtkHAVSTranslucentLayers* layers = vtkHAVSTranslucentLayers::GetLayersOf(renderer);
  if (!layers || !layers->Take())
  {
    return 0;
  }
  this->Targets->SetIntermix(layers);
  return layers->GetNumberOfLayers();
}

void vtkHAVSGLMapperResources::SetIntermixSlab(int slab)
{
  this->Targets->SetIntermixSlab(slab);
}

void vtkHAVSGLMapperResources::EndIntermix(bool drawn)
{
  vtkHAVSTranslucentLayers* layers = this->Targets->GetIntermixLayers();
  if (layers && !drawn)
  {
    layers->GiveBack();
  }
  this->Targets->SetIntermix(nullptr);
}

//------------------------------------------------------------------------------
void vtkHAVSGLMapperResources::OnWindowDeleted(vtkObject* window, unsigned long, void*)
{
  this->Release(vtkWindow::SafeDownCast(window));
}

void vtkHAVSGLMapperResources::Release(vtkWindow* window)
{
  if (!this->Window || (window && window != this->Window))
  {
    return;
  }
  vtkOpenGLRenderWindow* home = this->Window;
  home->MakeCurrent();
  if (this->Owned)
  {
    this->Owned->Release(home);
  }
  this->Section->Release();
  this->SectionTriangles = 0;
  this->IsoGradientFields->Release();
  this->Table->ReleaseGraphicsResources(home);
  this->TableBuilder->ReleaseGraphicsResources(home);
  this->Targets->ReleaseGraphicsResources(home);
  home->RemoveObserver(this->WindowDeleteObserver);
  this->Window = nullptr;
}

//------------------------------------------------------------------------------
bool vtkHAVSGLMapperResources::BuildTableEntries(vtkRenderer* renderer, vtkObject* mapper,
  const char* mapperName, const vtkHAVSPreIntegrationTable::Quadrature& inputs, float* table)
{
  vtkOpenGLRenderWindow* window =
    this->Prepare(renderer, mapper, mapperName, "compute shaders for the table");
  return window && this->TableBuilder->Build(window, inputs, table);
}

//------------------------------------------------------------------------------
void vtkHAVSGLMapperResources::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Window: " << this->Window << "\n";
  this->Table->PrintSelf(os, indent.GetNextIndent());
  this->TableBuilder->PrintSelf(os, indent.GetNextIndent());
  this->Targets->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
size_t vtkHAVSGLMapperResources::GetMemoryBytes() const
{
  return vtkHAVSGLBuffer::GetLiveBytes();
}

//------------------------------------------------------------------------------
bool vtkHAVSGLMapperResources::BeginCapture(const std::string& directory, const char* mapper,
  int blend, bool opaque, vtkHAVSFramePlanes* planes, const vtkHAVSViewFrame& view,
  const vtkHAVSGLCellRecords& records, std::string& header, std::string& error)
{
  using Capture = vtkHAVSGLFrameCapture;
  if (blend != vtkHAVSFrameRequest::CompositeBlend || opaque || planes->GetNumberOfPlanes() > 0 ||
    this->SectionTriangles > 0)
  {
    error = "only composite frames without opaque geometry, clipping planes or the near plane's "
            "section are captured (the stand-alone program draws the cells alone)";
    return false;
  }
  if (this->Table->HasCellOptics())
  {
    error = "frames of cell scalars are not captured (the stand-alone program has no cell optics)";
    return false;
  }
  if (!Capture::MakeDirectory(directory, error))
  {
    return false;
  }
  int tableSize[3];
  const std::vector<float> table = Capture::ReadTable(this->Table->GetTable(), tableSize);
  std::vector<float> result;
  this->Targets->ReadResult(result);
  if (!Capture::WriteArray(directory + "/table.f32", table) ||
    !Capture::WriteArray(directory + "/result.f32", result))
  {
    error = "cannot write the case into " + directory;
    return false;
  }
  header = Capture::Header(mapper, view.Width, view.Height, tableSize) + "record_buffers " +
    std::to_string(records.GetBufferCount()) + "\ncells_per_record_buffer " +
    std::to_string(records.GetCellsPerBuffer()) + "\n";
  return true;
}

VTK_ABI_NAMESPACE_END
