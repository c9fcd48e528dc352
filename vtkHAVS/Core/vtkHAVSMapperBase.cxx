/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMapperBase.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSMapperBase.h"

#include "vtkHAVSLevelOfDetailController.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMapperGraphics.h"

#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSMapperInputs.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPointGradients.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSTableResolution.h"
#include "vtkHAVSViewFrame.h"

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"
#include "vtkTimerLog.h"
#include "vtkUniforms.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cmath>
#include <string>

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
vtkHAVSMapperBase::vtkHAVSMapperBase(const char* mapperName)
  : Mesh(vtkSmartPointer<vtkHAVSMesh>::New())
  , MapperName(mapperName)
{
  this->Table->SetEntryBuilder([this](const vtkHAVSPreIntegrationTable::Quadrature& inputs,
                                 float* table) { return this->BuildTableEntries(inputs, table); });
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperBase::BuildTableEntries(
  const vtkHAVSPreIntegrationTable::Quadrature& inputs, float* table)
{
  const bool built = this->PreIntegrationOnGPU && this->Graphics && this->FrameRenderer &&
    this->Graphics->BuildTableEntries(this->FrameRenderer, this, this->MapperName, inputs, table);
  this->LastTableBuiltOnGPU = this->LastTableBuiltOnGPU || built;
  return built;
}

vtkHAVSMapperBase::~vtkHAVSMapperBase()
{
  this->SetCaptureDirectory(nullptr);
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperBase::IsBlendModeSupported(int mode)
{
  switch (mode)
  {
    case COMPOSITE_BLEND:
    case MAXIMUM_INTENSITY_BLEND:
    case MINIMUM_INTENSITY_BLEND:
    case ADDITIVE_BLEND:
    case ISOSURFACE_BLEND:
      return true;
    default:
      return false;
  }
}

//------------------------------------------------------------------------------
void vtkHAVSMapperBase::SetInputData(vtkDataSet* input)
{
  this->SetInputDataInternal(0, input);
}

void vtkHAVSMapperBase::SetInputData(vtkUnstructuredGridBase* input)
{
  this->SetInputDataInternal(0, input);
}

double* vtkHAVSMapperBase::GetBounds()
{
  if (vtkHAVSMapperInputs::GetCompositeInputBounds(this, this->Bounds))
  {
    return this->Bounds;
  }
  return this->Superclass::GetBounds();
}

int vtkHAVSMapperBase::FillInputPortInformation(int vtkNotUsed(port), vtkInformation* info)
{
  return vtkHAVSMapperInputs::FillInputPortInformation(info);
}

//------------------------------------------------------------------------------
vtkHAVSMesh* vtkHAVSMapperBase::GetMesh()
{
  return this->Mesh;
}

void vtkHAVSMapperBase::SetMesh(vtkHAVSMesh* mesh)
{
  if (mesh && mesh == this->Mesh)
  {
    return;
  }
  this->Mesh = mesh ? vtkSmartPointer<vtkHAVSMesh>(mesh) : vtkSmartPointer<vtkHAVSMesh>::New();
  // What this mapper saw of the old mesh says nothing about the new one.
  this->SeenMeshBuild = this->SeenMeshScalars = 0;
  this->Modified();
}

const char* vtkHAVSMapperBase::GetMeshUpdateName(int update)
{
  switch (update)
  {
    case MeshUnchanged:
      return "unchanged";
    case MeshBuilt:
      return "built";
    case MeshScalarsMapped:
      return "scalars mapped";
    case MeshShared:
      return "shared (prepared by another mapper)";
    default:
      return "not prepared";
  }
}

//------------------------------------------------------------------------------
void vtkHAVSMapperBase::WarnOnce(int which, const std::string& message)
{
  vtkHAVSMapperInputs::WarnOnceBy(this, this->Warned[which], message);
}

bool vtkHAVSMapperBase::AbortRequested(vtkRenderer* renderer)
{
  vtkRenderWindow* window = renderer ? renderer->GetRenderWindow() : nullptr;
  if (window && window->CheckAbortStatus())
  {
    this->LastFrameAborted = true;
  }
  return this->LastFrameAborted;
}

const std::vector<float>* vtkHAVSMapperBase::GetKeptResult(int size[2])
{
  return this->Graphics ? this->Graphics->GetKeptResult(size) : nullptr;
}

void vtkHAVSMapperBase::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Graphics)
  {
    this->Graphics->Release(window);
  }
}

bool vtkHAVSMapperBase::GetFloatResult(vtkFloatArray* rgba, int size[2])
{
  return vtkHAVSMapperInputs::CopyResult(this->GetKeptResult(size), size, rgba);
}

vtkMTimeType vtkHAVSMapperBase::GetFloatResultTime()
{
  return this->Graphics ? this->Graphics->GetKeptResultTime() : 0;
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperBase::PrepareMesh(vtkVolume* volume)
{
  const auto state = vtkHAVSMapperInputs::PrepareMesh(
    this, volume, this->Mesh, this->MapperName,
    [this](int which, const std::string& m) { this->WarnOnce(which, m); }, this->VectorMode,
    this->VectorComponent, this->HigherOrderSubdivision);
  if (state == vtkHAVSMapperInputs::MeshFailed)
  {
    return false;
  }
  // A mesh whose largest GPU buffer would be larger than the mapper makes:
  // said once per mesh, not drawn.
  const vtkHAVSMemory::Part need = this->GetLargestGPUBufferNeed();
  if (need.Bytes > static_cast<size_t>(this->LargestGPUBuffer))
  {
    if (this->RefusedMeshBuild != this->Mesh->GetBuildTime())
    {
      this->RefusedMeshBuild = this->Mesh->GetBuildTime();
      vtkErrorMacro(<< this->MapperName << ": " << this->Mesh->GetFaceSet()->GetNumberOfTetrahedra()
                    << " tetrahedra need " << need.Bytes << " bytes of " << need.Name
                    << " in one GPU buffer, more than the largest it makes (LargestGPUBuffer, "
                    << this->LargestGPUBuffer
                    << " bytes: shaders address buffers with 32-bit offsets). Nothing is drawn; "
                       "draw this mesh in pieces (ParaView's distributed rendering) or with a "
                       "mapper that needs less in one buffer (vtkHAVSVolumeMapper: 12 bytes a "
                       "face; the ray caster: 20 bytes a tetrahedron, its cell records in 4 "
                       "buffers; the cell projection: 48 bytes a tetrahedron).");
    }
    return false;
  }
  // What changed since this mapper last drew: a shared mesh may have been
  // prepared by another mapper in between.
  const bool rebuilt = this->Mesh->GetBuildTime() != this->SeenMeshBuild;
  const bool remapped = this->Mesh->GetScalarTime() != this->SeenMeshScalars;
  this->SeenMeshBuild = this->Mesh->GetBuildTime();
  this->SeenMeshScalars = this->Mesh->GetScalarTime();
  if (state == vtkHAVSMapperInputs::MeshRebuilt)
  {
    this->LastMeshUpdate = MeshBuilt;
  }
  else if (state == vtkHAVSMapperInputs::MeshScalarsUpdated)
  {
    this->LastMeshUpdate = MeshScalarsMapped;
  }
  else
  {
    this->LastMeshUpdate = rebuilt || remapped ? MeshShared : MeshUnchanged;
  }
  if (state != vtkHAVSMapperInputs::MeshUnchanged)
  {
    this->LastMeshSeconds = this->Mesh->GetLastUpdateSeconds();
  }
  if (rebuilt)
  {
    this->ImageControl->Reset(); // the last frames' times were another mesh's
  }
  this->MeshPrepared(this->LastMeshUpdate, rebuilt);
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSMapperBase::PrepareShaderHooks(vtkVolume* volume)
{
  // Read again only when the property (or one of its uniforms) changed.
  vtkShaderProperty* property = volume ? volume->GetShaderProperty() : nullptr;
  if (property == this->ShaderHooksProperty &&
    vtkHAVSShaderHooks::TimeOf(property) == this->ShaderHooks.Time)
  {
    return;
  }
  this->ShaderHooksProperty = property;
  this->ShaderHooks = vtkHAVSShaderHooks::From(property);
  if (!this->ShaderHooks.Ignored.empty())
  {
    std::string what;
    for (const std::string& line : this->ShaderHooks.Ignored)
    {
      what += (what.empty() ? "" : "; ") + line;
    }
    std::string honoured;
    for (const std::string& tag : vtkHAVSShaderHooks::HonouredTags())
    {
      honoured += (honoured.empty() ? "" : ", ") + tag;
    }
    this->WarnOnce(vtkHAVSMapperInputs::WarnShaderProperty,
      std::string("Part of the volume's shader property is not applied by ") + this->MapperName +
        " (" + what + "): it applies the fragment replacements of " + honoured +
        " and the fragment custom uniforms, in the pass that composites the volume; the rest is "
        "left out.");
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperBase::PrepareTable(vtkVolume* volume)
{
  const bool ok = vtkHAVSMapperInputs::PrepareTable(
    this, volume, this->Mesh, this->Table, this->TableScalarResolution, this->TableLengthResolution,
    this->MapperName,
    [this](int which, const std::string& m)
    {
      // (The isosurface blend draws no volume: its surfaces are what ShadeOn lights.)
      if (which == vtkHAVSMapperInputs::WarnShading && this->BlendMode == ISOSURFACE_BLEND)
      {
        return;
      }
      this->WarnOnce(which, m);
    },
    &this->TableRebuilt, this->AutomaticTableResolution ? this->TableChooser.Get() : nullptr);
  // A table built at the fixed size is not the chooser's: with the
  // automatic choice back on, it chooses again.
  if (this->TableRebuilt && !this->AutomaticTableResolution)
  {
    this->TableChooser->Modified();
  }
  return ok;
}

//------------------------------------------------------------------------------
void vtkHAVSMapperBase::SetTableErrorBound(double bound)
{
  if (bound != this->TableChooser->GetErrorBound())
  {
    this->TableChooser->SetErrorBound(bound);
    this->Modified();
  }
}

double vtkHAVSMapperBase::GetTableErrorBound()
{
  return this->TableChooser->GetErrorBound();
}

int vtkHAVSMapperBase::GetLastTableScalarResolution()
{
  return this->Table->GetScalarResolution();
}

int vtkHAVSMapperBase::GetLastTableLengthResolution()
{
  return this->Table->GetLengthResolution();
}

double vtkHAVSMapperBase::GetLastTableError()
{
  return this->AutomaticTableResolution ? this->TableChooser->GetLastError() : -1.0;
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSMapperBase::GetNumberOfDegenerateTetrahedra()
{
  return this->Mesh->IsValid() ? this->Mesh->GetFaceSet()->GetNumberOfDegenerateTetrahedra() : 0;
}

//------------------------------------------------------------------------------
std::vector<vtkHAVSMemory::Part> vtkHAVSMapperBase::GetMemoryParts() const
{
  std::vector<vtkHAVSMemory::Part> parts;
  parts.push_back(
    { "mesh (tetrahedra, faces, points, scalars: shared)", this->Mesh->GetMemoryBytes() });
  parts.push_back({ "table", this->Table->GetMemoryBytes() });
  this->AddMemoryParts(parts);
  parts.push_back({ "GPU buffers (every vtkHAVS mapper of the process)",
    this->Graphics ? this->Graphics->GetMemoryBytes() : 0 });
  return parts;
}

//------------------------------------------------------------------------------
size_t vtkHAVSMapperBase::GetMemoryBytes() const
{
  return vtkHAVSMemory::Sum(this->GetMemoryParts());
}

//------------------------------------------------------------------------------
void vtkHAVSMapperBase::UpdatePlanes(const vtkHAVSViewFrame& view)
{
  if (!this->Planes->Update(view, this->ClippingPlanes, this->Mesh, this->PlaneSections))
  {
    this->WarnOnce(vtkHAVSMapperInputs::WarnPlanes,
      std::string("More than 6 clipping planes; ") + this->MapperName + " uses the first 6.");
  }
  this->LastSectionTriangles = this->Planes->GetNumberOfSectionTriangles();
}

//------------------------------------------------------------------------------
void vtkHAVSMapperBase::PrepareIsoSurfaces(vtkRenderer* renderer, vtkVolume* volume)
{
  this->FrameIsoSurfaces = vtkHAVSIsoSurfaces::Make(volume->GetProperty(), this->BlendMode,
    this->IsoSurfacesInComposite, this->Mesh->GetScalarRange());
  vtkHAVSIsoSurfaces& iso = this->FrameIsoSurfaces;
  if (iso.Count > 0 && !this->Mesh->HasCellScalars())
  {
    iso.MakeShading(volume->GetProperty(), this->Mesh->GetComponent(),
      renderer ? renderer->GetLights() : nullptr, volume->GetMatrix());
  }
  if (iso.Shaded && (iso.DroppedLights > 0 || iso.PositionalLights > 0))
  {
    this->WarnOnce(vtkHAVSMapperInputs::WarnIsoLights,
      std::string(this->MapperName) + " lights its isosurfaces with the first " +
        std::to_string(vtkHAVSIsoSurfaces::MaximumLights) +
        " lights that are on, each directional (a positional light shines from its position "
        "towards its focal point, with no cone or attenuation; said once).");
  }
  if (iso.Dropped > 0)
  {
    this->WarnOnce(vtkHAVSMapperInputs::WarnIsoSurfaces,
      std::string(this->MapperName) + " draws the lowest " +
        std::to_string(vtkHAVSIsoSurfaces::MaximumCount) + " isovalues; " +
        std::to_string(iso.Dropped) + " more are left out (said once).");
  }
  // (Shading, as for every blend, is warned of by vtkHAVSMapperInputs: unshaded.)
  if (this->BlendMode == ISOSURFACE_BLEND || iso.Count > 0)
  {
    if (this->Mesh->HasCellScalars())
    {
      this->WarnOnce(vtkHAVSMapperInputs::WarnIsoSurfaceCells,
        std::string(this->MapperName) +
          " finds isosurfaces of point scalars: cell scalars are constant in a cell and cross "
          "no isovalue inside one, so no surface is drawn (said once).");
    }
  }
}

//------------------------------------------------------------------------------
const std::vector<float>& vtkHAVSMapperBase::UpdateIsoGradients(
  IsoGradients& made, bool fields, vtkMTimeType& version)
{
  const vtkMTimeType key[2] = { this->Mesh->GetBuildTime(), this->Mesh->GetScalarTime() };
  if (made.Time.GetMTime() == 0 || key[0] != made.Key[0] || key[1] != made.Key[1])
  {
    std::vector<double> gradients;
    const std::vector<uint32_t>& tets = this->Mesh->GetFaceSet()->GetTetrahedra();
    vtkHAVSPointGradients::Compute(
      this->Mesh->GetPoints(), this->Mesh->GetScalars(), tets, gradients);
    if (fields)
    {
      vtkHAVSPointGradients::ComputeFields(this->Mesh->GetPoints(), tets, gradients, made.Values);
    }
    else
    {
      made.Values.assign(gradients.begin(), gradients.end());
    }
    made.Key[0] = key[0];
    made.Key[1] = key[1];
    made.Time.Modified();
  }
  version = made.Time.GetMTime();
  return made.Values;
}

const std::vector<float>& vtkHAVSMapperBase::GetIsoGradientFields(vtkMTimeType& version)
{
  return this->UpdateIsoGradients(this->IsoGradientFields, true, version);
}

const std::vector<float>& vtkHAVSMapperBase::GetIsoPointGradients(vtkMTimeType& version)
{
  return this->UpdateIsoGradients(this->IsoPointGradients, false, version);
}

//------------------------------------------------------------------------------
vtkHAVSLevelOfDetailController* vtkHAVSMapperBase::GetImageReductionController()
{
  return this->ImageControl;
}

//------------------------------------------------------------------------------
double vtkHAVSMapperBase::PixelShare(double detail) const
{
  return this->SharesDetailWithFaces() ? std::sqrt(detail) : detail;
}

//------------------------------------------------------------------------------
double vtkHAVSMapperBase::SmallestDetail() const
{
  const double pixels = this->MinimumImageScale * this->MinimumImageScale;
  return this->SharesDetailWithFaces() ? pixels * pixels : pixels;
}

//------------------------------------------------------------------------------
double vtkHAVSMapperBase::FrameBudget(vtkVolume* volume) const
{
  return this->LevelOfDetailTargetSeconds > 0.0 ? this->LevelOfDetailTargetSeconds
                                                : volume->GetAllocatedRenderTime();
}

//------------------------------------------------------------------------------
double vtkHAVSMapperBase::ChooseImageScale(vtkVolume* volume)
{
  // The detail: the controller's share of the full frame for the budget (1
  // when the last full frame fits it, as a still frame's budget does). The
  // image takes PixelShare of it (never below the smallest image), HAVS's
  // faces the rest; the detail recorded is what the frame draws.
  double detail = 1.0;
  if (this->ImageReduction)
  {
    const double smallest = this->SmallestDetail();
    this->ImageControl->SetSmallestFraction(smallest);
    detail =
      std::min(1.0, std::max(this->ImageControl->Choose(this->FrameBudget(volume)), smallest));
  }
  const double pixels = std::min(1.0, std::max(this->PixelShare(detail), 0.0));
  this->FaceShare = pixels > 0.0 ? std::min(1.0, detail / pixels) : 0.0;
  double scale = std::max(std::sqrt(pixels), this->MinimumImageScale);
  scale = std::min(scale, this->ImageScale);
  // The edges' mask where it fits: dropped at the smallest image once a frame
  // there took longer than the budget, back when the image grows again.
  const bool smallest = this->ImageReduction && scale <= this->MinimumImageScale;
  if (!smallest)
  {
    this->EdgesDroppedForBudget = false;
  }
  else if (this->ImageControl->GetLastSeconds() > this->FrameBudget(volume) &&
    this->LastImageScale <= this->MinimumImageScale)
  {
    this->EdgesDroppedForBudget = true;
  }
  this->LastEdgeUpsampling = this->EdgeUpsampling && scale < 1.0 && !this->EdgesDroppedForBudget;
  this->LastImageScale = scale;
  this->LastDetail = scale * scale * this->FaceShare;
  return scale;
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperBase::NeedsOpaqueDepth(vtkRenderer* renderer) const
{
  // An intermixed frame's slabs before the last end at their layers; the
  // last one only at the opaque geometry, if any.
  return this->IntermixSlab < this->LastIntermixLayers ||
    vtkHAVSMapperInputs::RendererHasOpaqueGeometry(renderer);
}

//------------------------------------------------------------------------------
void vtkHAVSMapperBase::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  // 1. The frame starts (VTK's volume mapper event).
  const double start = vtkTimerLog::GetUniversalTime();
  this->LastMeshUpdate = MeshNotPrepared;
  this->LastMeshSeconds = 0.0;
  this->LastFrameAborted = false;
  this->LastTableSeconds = 0.0;
  this->LastSectionTriangles = 0;
  this->LastIntermixLayers = 0;
  this->TableRebuilt = false;
  this->LastTableBuiltOnGPU = false;
  this->FrameRenderer = renderer; // (the tables' GPU build draws in its window)
  this->ResetLastFrame();
  this->InvokeEvent(vtkCommand::VolumeMapperRenderStartEvent, nullptr);
  bool viewDrawn = false;

  // 2. A blend mode the mapper draws.
  if (!this->IsBlendModeSupported(this->BlendMode))
  {
    vtkErrorMacro(
      "Blend mode " << this->BlendMode << " is not supported by " << this->MapperName << ".");
  }
  else if (!this->AbortRequested(renderer))
  {
    this->PrepareShaderHooks(volume);
    // 3. The input and its mesh, 4. the table: each only when its inputs changed.
    if (this->GetNumberOfInputConnections(0) > 0)
    {
      this->GetInputAlgorithm()->Update();
    }
    if (this->PrepareMesh(volume) && !this->AbortRequested(renderer))
    {
      const double tableStart = vtkTimerLog::GetUniversalTime();
      const bool tableBuilt = this->PrepareTable(volume);
      this->LastTableSeconds = vtkTimerLog::GetUniversalTime() - tableStart;
      if (this->TableRebuilt)
      {
        this->TableBuildTime.Modified();
      }
      this->PrepareIsoSurfaces(renderer, volume);
      // 5. The view: every coordinate frame, once, at the level of detail's
      // image scale; 6. the mapper's own part.
      if (tableBuilt && !this->AbortRequested(renderer))
      {
        // Translucent layers to intermix: the whole image (no reduction),
        // drawn once per slab between them.
        const int layers =
          this->CanIntermix() && this->Graphics ? this->Graphics->BeginIntermix(renderer) : 0;
        this->LastIntermixLayers = layers;
        double scale = this->ChooseImageScale(volume);
        if (layers > 0)
        {
          scale = this->LastImageScale = 1.0;
          this->LastEdgeUpsampling = false;
          this->LastDetail = this->FaceShare;
        }
        const vtkHAVSViewFrame view =
          vtkHAVSViewFrame::Make(renderer, volume, this->Mesh->GetShift(), scale);
        if (view.HasPixels())
        {
          for (int slab = 0; slab <= layers; ++slab)
          {
            if (layers > 0)
            {
              this->Graphics->SetIntermixSlab(slab);
            }
            this->IntermixSlab = slab;
            this->RenderView(renderer, volume, view);
          }
          this->IntermixSlab = 0;
          viewDrawn = true;
        }
        if (layers > 0)
        {
          this->Graphics->EndIntermix(viewDrawn);
        }
      }
    }
  }

  this->FrameRenderer = nullptr;
  // 7. The frame's time (vtkVolume's estimate reads it) and 8. its end.
  this->TimeToDraw = vtkTimerLog::GetUniversalTime() - start;
  if (viewDrawn)
  {
    if (this->ImageReduction)
    {
      this->ImageControl->FrameDrawn(this->LastDetail, this->TimeToDraw);
    }
    this->FrameFinished(this->TimeToDraw);
  }
  this->InvokeEvent(vtkCommand::VolumeMapperRenderEndEvent, nullptr);
}

//------------------------------------------------------------------------------
void vtkHAVSMapperBase::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MapperName: " << this->MapperName << "\n";
  os << indent << "BlendMode: " << this->BlendMode
     << ", IsoSurfacesInComposite: " << this->IsoSurfacesInComposite << " (last frame "
     << this->FrameIsoSurfaces.Count << " surfaces)\n";
  os << indent << "IntermixTranslucentGeometry: " << this->IntermixTranslucentGeometry
     << " (last frame " << this->LastIntermixLayers << " layers)\n";
  os << indent << "VectorMode: " << this->VectorMode
     << ", VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "HigherOrderSubdivision: " << this->HigherOrderSubdivision << "\n";
  os << indent << "TableScalarResolution: " << this->TableScalarResolution
     << ", TableLengthResolution: " << this->TableLengthResolution << "\n";
  os << indent << "AutomaticTableResolution: " << this->AutomaticTableResolution << " (error bound "
     << this->TableChooser->GetErrorBound() << ")\n";
  os << indent << "PreIntegrationOnGPU: " << this->PreIntegrationOnGPU
     << " (last table built on the GPU: " << this->LastTableBuiltOnGPU << ")\n";
  os << indent << "KeepFloatResult: " << this->KeepFloatResult << "\n";
  os << indent << "LargestGPUBuffer: " << this->LargestGPUBuffer << "\n";
  os << indent << "PlaneSections: " << this->PlaneSections
     << ", LastSectionTriangles: " << this->LastSectionTriangles << "\n";
  os << indent << "Mesh: " << this->Mesh.Get() << " (shared by " << this->Mesh->GetReferenceCount()
     << " owners)\n";
  os << indent << "LastMeshUpdate: " << GetMeshUpdateName(this->LastMeshUpdate) << " ("
     << this->LastMeshSeconds << " s)\n";
  os << indent << "LastFrameAborted: " << this->LastFrameAborted << "\n";
  os << indent << "LastTableSeconds: " << this->LastTableSeconds << "\n";
  os << indent
     << "CaptureDirectory: " << (this->CaptureDirectory ? this->CaptureDirectory : "(none)")
     << ", last capture " << (this->LastCaptureSucceeded ? "written" : "none") << "\n";
  os << indent << "DegenerateTetrahedra (dropped): " << this->GetNumberOfDegenerateTetrahedra()
     << "\n";
  os << indent << "ShaderHooks: " << this->ShaderHooks.Fragment.size()
     << " fragment replacements applied, custom uniforms "
     << (this->ShaderHooks.FragmentUniforms ? "applied" : "none") << ", "
     << this->ShaderHooks.Ignored.size() << " parts left out\n";
  os << indent << "ImageReduction: " << this->ImageReduction
     << ", MinimumImageScale: " << this->MinimumImageScale
     << ", EdgeUpsampling: " << this->EdgeUpsampling << " (last frame: " << this->LastEdgeUpsampling
     << ")"
     << ", ImageScale: " << this->ImageScale
     << ", LevelOfDetailTargetSeconds: " << this->LevelOfDetailTargetSeconds << "\n";
  os << indent << "LastImageScale: " << this->LastImageScale << ", LastDetail: " << this->LastDetail
     << "\n";
  os << indent << "ImageReductionController:\n";
  this->ImageControl->PrintSelf(os, indent.GetNextIndent());
  os << indent << "TimeToDraw: " << this->TimeToDraw << "\n";
  os << indent << "Memory:";
  for (const vtkHAVSMemory::Part& part : this->GetMemoryParts())
  {
    os << " " << part.Name << " " << part.Bytes << " B;";
  }
  os << "\n";
}

VTK_ABI_NAMESPACE_END
