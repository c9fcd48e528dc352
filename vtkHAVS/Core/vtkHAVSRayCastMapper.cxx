/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRayCastMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSRayCastMapper.h"

#include "vtkHAVSCellGeometry.h"
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

VTK_ABI_NAMESPACE_BEGIN

vtkAbstractObjectFactoryNewMacro(vtkHAVSRayCastMapper);

//------------------------------------------------------------------------------
vtkHAVSRayCastMapper::vtkHAVSRayCastMapper()
  : vtkHAVSMapperBase("vtkHAVSRayCastMapper")
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
vtkHAVSMemory::Part vtkHAVSRayCastMapper::GetLargestGPUBufferNeed() const
{
  // The cell records (four face planes and the field, 80 bytes a
  // tetrahedron, in up to four buffers) or the neighbours (16 bytes a
  // tetrahedron, one buffer): the larger.
  const size_t tets = static_cast<size_t>(this->Mesh->GetFaceSet()->GetNumberOfTetrahedra());
  const size_t records = vtkHAVSCellGeometry::LargestRecordBufferNeed(tets);
  const size_t neighbours = 4 * sizeof(int32_t) * tets;
  return records >= neighbours
    ? vtkHAVSMemory::Part{ "cell records (80 bytes a tetrahedron, in at most 4 buffers)", records }
    : vtkHAVSMemory::Part{ "neighbours (16 bytes a tetrahedron)", neighbours };
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::AddMemoryParts(std::vector<vtkHAVSMemory::Part>& parts) const
{
  parts.push_back(
    { "ray mesh (cell records, neighbours)", this->RayMesh ? this->RayMesh->GetMemoryBytes() : 0 });
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::ResetLastFrame()
{
  this->LastPeelPasses = 0;
  this->LastRaysStarted = 0;
  this->LastCellsCrossed = 0;
  this->LastFoldReentries = 0;
  this->LastPeelSeconds = this->LastCastSeconds = -1.0;
  this->LastTileGrid[0] = this->LastTileGrid[1] = 0;
  this->LastTilePasses.clear();
  this->LastPeelFragments.clear();
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::MeshPrepared(int update, bool rebuilt)
{
  // The layout (96 bytes a tetrahedron): its neighbours are kept for a new
  // time step on the same mesh (the fields again) and for an unchanged one,
  // unless the testing aid changed.
  const std::vector<uint32_t>& tets = this->Mesh->GetFaceSet()->GetTetrahedra();
  const std::vector<float>* cellScalars =
    this->Mesh->HasCellScalars() ? &this->Mesh->GetTetrahedronCodes() : nullptr;
  if (this->RayMesh && !rebuilt && this->RayMeshBroken == this->BrokenNeighboursForTesting)
  {
    if (update != MeshUnchanged)
    {
      this->UpdateRayFields();
      this->RayMeshTime.Modified();
    }
    return;
  }
  this->RayMesh.reset(new vtkHAVSRayCastMesh);
  this->RayMesh->Build(this->Mesh->GetPoints(), this->Mesh->GetScalars(), tets, cellScalars);
  if (this->BrokenNeighboursForTesting)
  {
    this->RayMesh->BreakNeighboursForTesting();
  }
  this->RayMeshBroken = this->BrokenNeighboursForTesting;
  this->RayMeshTime.Modified();
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::UpdateRayFields()
{
  this->RayMesh->UpdateFields(this->Mesh->GetPoints(), this->Mesh->GetScalars(),
    this->Mesh->GetFaceSet()->GetTetrahedra(),
    this->Mesh->HasCellScalars() ? &this->Mesh->GetTetrahedronCodes() : nullptr);
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::RenderView(
  vtkRenderer* renderer, vtkVolume* vtkNotUsed(volume), const vtkHAVSViewFrame& view)
{
  // The near and clipping planes (the near plane's section where the camera is inside).
  this->UpdatePlanes(view);

  // The draw: peel the entries, cast, per tile.
  RayFrame frame;
  frame.View = &view;
  frame.Mesh = this->Mesh;
  frame.RayMesh = this->RayMesh.get();
  frame.MeshVersion = this->RayMeshTime.GetMTime();
  frame.Table = this->Table;
  frame.TableVersion = this->TableBuildTime.GetMTime();
  frame.Planes = this->Planes;
  frame.Opaque = this->NeedsOpaqueDepth(renderer);
  frame.KeepResult = this->KeepFloatResult;
  frame.TerminationOpacity = static_cast<float>(this->EarlyRayTerminationOpacity);
  frame.MaximumPasses = this->MaximumPeelPasses > 0 ? this->MaximumPeelPasses : 1024;
  frame.TileSize = this->Tiles ? this->TileSize : 0;
  frame.Blend = this->GetFrameBlend();
  frame.FoldReentries = this->FoldReentries;
  frame.RestoreCells = [this]() { this->UpdateRayFields(); };
  RayCounts counts;
  if (!this->DrawRays(renderer, frame, &counts))
  {
    return;
  }
  // The GPU holds the cell records now: the host copy is freed (made again
  // through RestoreCells if the GPU loses them).
  this->RayMesh->ReleaseCells();
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

//------------------------------------------------------------------------------
void vtkHAVSRayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "EarlyRayTerminationOpacity: " << this->EarlyRayTerminationOpacity
     << ", MaximumPeelPasses: " << this->MaximumPeelPasses << "\n";
  os << indent << "BrokenNeighboursForTesting: " << this->BrokenNeighboursForTesting
     << ", FoldReentries: " << this->FoldReentries << "\n";
  os << indent << "Tiles: " << this->Tiles << ", TileSize: " << this->TileSize << "\n";
  os << indent << "Last frame: " << this->LastPeelPasses << " peel passes, "
     << this->LastRaysStarted << " rays, " << this->LastCellsCrossed << " cells crossed, "
     << this->LastFoldReentries << " fold re-entries, " << this->LastDrawSeconds << " s (peeling "
     << this->LastPeelSeconds << " s, casting " << this->LastCastSeconds << " s)\n";
}

VTK_ABI_NAMESPACE_END
