/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRayCastMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSRayCastMapper.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSMapperInputs.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSRayCastMesh.h"
#include "vtkHAVSViewFrame.h"

#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGridBase.h"
#include "vtkVolume.h"

vtkAbstractObjectFactoryNewMacro(vtkHAVSRayCastMapper);

//------------------------------------------------------------------------------
vtkHAVSRayCastMapper::vtkHAVSRayCastMapper()
{
  // Only the near plane would need a section (a ray starts on a clipping
  // plane inside the cell it enters by).
  this->Planes->SetNearPlaneSectionsOnly(true);
}
vtkHAVSRayCastMapper::~vtkHAVSRayCastMapper() = default;

//------------------------------------------------------------------------------
bool vtkHAVSRayCastMapper::DrawRays(vtkRenderer*, const RayFrame&, RayCounts*)
{
  vtkErrorMacro("vtkHAVSRayCastMapper has no graphics layer: use its OpenGL override "
                "(vtkOpenGLHAVSRayCastMapper, from vtkHAVS::OpenGL).");
  return false;
}

const std::vector<float>* vtkHAVSRayCastMapper::GetKeptResult(int[2])
{
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::SetInputData(vtkDataSet* input)
{
  this->SetInputDataInternal(0, input);
}

void vtkHAVSRayCastMapper::SetInputData(vtkUnstructuredGridBase* input)
{
  this->SetInputDataInternal(0, input);
}

double* vtkHAVSRayCastMapper::GetBounds()
{
  if (vtkHAVSMapperInputs::GetCompositeInputBounds(this, this->Bounds))
  {
    return this->Bounds;
  }
  return this->Superclass::GetBounds();
}

int vtkHAVSRayCastMapper::FillInputPortInformation(int vtkNotUsed(port), vtkInformation* info)
{
  return vtkHAVSMapperInputs::FillInputPortInformation(info);
}

void vtkHAVSRayCastMapper::WarnOnce(int which, const std::string& message)
{
  vtkHAVSMapperInputs::WarnOnceBy(this, this->Warned[which], message);
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::SetBrokenNeighboursForTesting(bool broken)
{
  if (this->BrokenNeighboursForTesting != broken)
  {
    this->BrokenNeighboursForTesting = broken;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  this->LastPeelPasses = 0;
  this->LastRaysStarted = 0;
  this->LastCellsCrossed = 0;
  this->LastFoldReentries = 0;
  this->LastPeelSeconds = this->LastCastSeconds = -1.0;
  this->LastSectionTriangles = 0;
  this->LastTileGrid[0] = this->LastTileGrid[1] = 0;
  this->LastTilePasses.clear();
  this->LastPeelFragments.clear();
  switch (this->BlendMode)
  {
    case COMPOSITE_BLEND:
    case MAXIMUM_INTENSITY_BLEND:
    case MINIMUM_INTENSITY_BLEND:
    case ADDITIVE_BLEND:
      break;
    default:
      vtkErrorMacro("Blend mode " << this->BlendMode
                                  << " is not supported by vtkHAVSRayCastMapper (composite, "
                                     "maximum, minimum intensity and additive are).");
      return;
  }
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update();
  }
  auto warnOnce = [this](int which, const std::string& m) { this->WarnOnce(which, m); };
  const auto state = vtkHAVSMapperInputs::PrepareMesh(this, volume, this->Mesh,
    "vtkHAVSRayCastMapper", warnOnce, this->VectorMode, this->VectorComponent);
  if (state == vtkHAVSMapperInputs::MeshFailed)
  {
    return;
  }
  const std::vector<uint32_t>& tets = this->Mesh->GetFaceSet()->GetTetrahedra();
  const std::vector<float>* cellScalars =
    this->Mesh->HasCellScalars() ? &this->Mesh->GetTetrahedronCodes() : nullptr;
  // The neighbours are kept for a new time step on the same mesh (the
  // fields again) and for an unchanged one, unless the testing aid changed.
  const bool keepNeighbours = this->RayMesh &&
    this->RayMeshBroken == this->BrokenNeighboursForTesting &&
    (state == vtkHAVSMapperInputs::MeshUnchanged ||
      state == vtkHAVSMapperInputs::MeshScalarsUpdated);
  if (keepNeighbours && state == vtkHAVSMapperInputs::MeshScalarsUpdated)
  {
    this->RayMesh->UpdateFields(
      this->Mesh->GetPoints(), this->Mesh->GetScalars(), tets, cellScalars);
    this->RayMeshTime.Modified();
  }
  else if (!keepNeighbours)
  {
    this->RayMesh.reset(new vtkHAVSRayCastMesh);
    this->RayMesh->Build(this->Mesh->GetPoints(), this->Mesh->GetScalars(), tets, cellScalars);
    if (this->BrokenNeighboursForTesting)
    {
      this->RayMesh->BreakNeighboursForTesting();
    }
    this->RayMeshBroken = this->BrokenNeighboursForTesting;
    this->RayMeshTime.Modified();
  }
  bool rebuilt = false;
  if (!vtkHAVSMapperInputs::PrepareTable(this, volume, this->Mesh, this->Table,
        this->TableScalarResolution, this->TableLengthResolution, "vtkHAVSRayCastMapper", warnOnce,
        &rebuilt))
  {
    return;
  }
  if (rebuilt)
  {
    this->TableBuildTime.Modified();
  }

  const vtkHAVSViewFrame view = vtkHAVSViewFrame::Make(renderer, volume, this->Mesh->GetShift());
  if (!view.HasPixels())
  {
    return;
  }
  if (!this->Planes->Update(view, this->ClippingPlanes, this->Mesh, this->NearPlaneSection))
  {
    this->WarnOnce(vtkHAVSMapperInputs::WarnPlanes,
      "More than 6 clipping planes; vtkHAVSRayCastMapper uses the first 6.");
  }
  this->LastSectionTriangles = this->Planes->GetNumberOfSectionTriangles();

  RayFrame frame;
  frame.View = &view;
  frame.Mesh = this->Mesh;
  frame.RayMesh = this->RayMesh.get();
  frame.MeshVersion = this->RayMeshTime.GetMTime();
  frame.Table = this->Table;
  frame.TableVersion = this->TableBuildTime.GetMTime();
  frame.Planes = this->Planes;
  frame.Opaque = vtkHAVSMapperInputs::RendererHasOpaqueGeometry(renderer);
  frame.KeepResult = this->KeepFloatResult;
  frame.TerminationOpacity = static_cast<float>(this->EarlyRayTerminationOpacity);
  frame.MaximumPasses = this->MaximumPeelPasses > 0 ? this->MaximumPeelPasses : 1024;
  frame.TileSize = this->Tiles ? this->TileSize : 0;
  frame.Blend = this->BlendMode;
  frame.FoldReentries = this->FoldReentries;
  RayCounts counts;
  if (this->DrawRays(renderer, frame, &counts))
  {
    this->LastPeelPasses = counts.Passes;
    this->LastRaysStarted = static_cast<vtkIdType>(counts.Rays);
    this->LastCellsCrossed = static_cast<vtkIdType>(counts.Cells);
    this->LastFoldReentries = static_cast<vtkIdType>(counts.FoldReentries);
    this->LastDrawSeconds = counts.Seconds;
    this->LastPeelSeconds = counts.PeelSeconds;
    this->LastCastSeconds = counts.CastSeconds;
    this->LastTileGrid[0] = counts.TileGrid[0];
    this->LastTileGrid[1] = counts.TileGrid[1];
    this->LastTilePasses.swap(counts.TilePasses);
    this->LastPeelFragments.swap(counts.PeelFragments);
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSRayCastMapper::GetFloatResult(vtkFloatArray* rgba, int size[2])
{
  return vtkHAVSMapperInputs::CopyResult(this->GetKeptResult(size), size, rgba);
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Table: " << this->TableScalarResolution << "^2 x " << this->TableLengthResolution
     << "\n";
  os << indent << "BlendMode: " << this->BlendMode << "\n";
  os << indent << "EarlyRayTerminationOpacity: " << this->EarlyRayTerminationOpacity
     << ", MaximumPeelPasses: " << this->MaximumPeelPasses << "\n";
  os << indent << "KeepFloatResult: " << this->KeepFloatResult
     << ", BrokenNeighboursForTesting: " << this->BrokenNeighboursForTesting
     << ", NearPlaneSection: " << this->NearPlaneSection
     << ", FoldReentries: " << this->FoldReentries << "\n";
  os << indent << "Tiles: " << this->Tiles << ", TileSize: " << this->TileSize << "\n";
  os << indent << "Last frame: " << this->LastPeelPasses << " peel passes, "
     << this->LastRaysStarted << " rays, " << this->LastCellsCrossed << " cells crossed, "
     << this->LastFoldReentries << " fold re-entries, " << this->LastDrawSeconds << " s (peeling "
     << this->LastPeelSeconds << " s, casting " << this->LastCastSeconds << " s)\n";
}
