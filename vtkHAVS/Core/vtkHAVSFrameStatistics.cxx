/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFrameStatistics.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSFrameStatistics.h"

#include "vtkHAVSVolumeMapper.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSFrameStatistics);

//------------------------------------------------------------------------------
void vtkHAVSFrameStatistics::Reset()
{
  this->KBufferPath = 0;
  this->KBufferSize = 0;
  this->VisibilityOrder = -1;
  this->OrderReused = false;
  this->CycleBreaks = 0;
  this->BoundaryRelations = 0;
  this->BoundaryLayerSeconds = 0.0;
  this->Tagging = false;
  this->OpaqueGeometry = false;
  this->OpaqueDepthMultisampled = false;
  this->OpaqueDepthCaptured = false;
  this->PlaneCount = 0;
  this->SectionTriangles = 0;
  this->SectionSeconds = 0.0;
  this->OrderViolations = -1;
  this->ViolationPixels.clear();
  this->Fragments = 0;
  this->SaturatedPixels = -1;
  this->ShadedFragments = -1;
  this->FacesDrawn = 0;
  this->FacesOrdered = 0;
  this->MeshUpdate = 0;
  this->MeshSeconds = 0.0;
  this->TableRebuilt = false;
  this->GeometryUploaded = false;
  this->ScalarsUploaded = false;
  this->OrderUploaded = false;
  this->TableUploaded = false;
  this->InvisibleCells = 0;
  this->VisibilitySeconds = 0.0;
  this->CulledCells = 0;
  this->CullingSeconds = 0.0;
  this->LevelOfDetailFraction = 1.0;
  this->LongSegmentTable = false;
  this->RankingSeconds = 0.0;
  this->FrameSeconds = 0.0;
  this->AutomaticKDraws = 0;
  this->SortSeconds = 0.0;
  this->GatherSeconds = 0.0;
  this->UploadSeconds = 0.0;
  this->DrawSeconds = 0.0;
  this->FlushSeconds = 0.0;
  this->CompositeSeconds = 0.0;
  this->ReadbackSeconds = 0.0;
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkHAVSFrameStatistics::GetKBufferPathName() const
{
  return vtkHAVSVolumeMapper::GetKBufferPathName(this->KBufferPath);
}

//------------------------------------------------------------------------------
int vtkHAVSFrameStatistics::GetOrderViolationPixels(vtkIntArray* pixels) const
{
  const int count = static_cast<int>(this->ViolationPixels.size() / 2);
  if (pixels)
  {
    pixels->SetNumberOfComponents(2);
    pixels->SetNumberOfTuples(count);
    std::copy(this->ViolationPixels.begin(), this->ViolationPixels.begin() + 2 * count,
      pixels->GetPointer(0));
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkHAVSFrameStatistics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* orders[] = { "Centroid", "MPVO", "Automatic" };
  os << indent << "KBufferPath: " << this->GetKBufferPathName() << " (k = " << this->KBufferSize
     << ")\n";
  os << indent << "VisibilityOrder: "
     << (this->VisibilityOrder >= 0 && this->VisibilityOrder <= 2 ? orders[this->VisibilityOrder]
                                                                  : "none")
     << (this->OrderReused ? " (reused)" : "") << ", cycle breaks " << this->CycleBreaks
     << ", boundary relations " << this->BoundaryRelations << " (" << this->BoundaryLayerSeconds
     << " s)\n";
  os << indent << "Tagging: " << this->Tagging << ", planes " << this->PlaneCount
     << ", section triangles " << this->SectionTriangles << " (" << this->SectionSeconds << " s)\n";
  os << indent << "OrderViolations: " << this->OrderViolations << ", fragments " << this->Fragments
     << ", faces drawn " << this->FacesDrawn << " (ordered " << this->FacesOrdered << ")"
     << ", saturated pixels " << this->SaturatedPixels << ", shaded fragments "
     << this->ShadedFragments << "\n";
  os << indent << "OpaqueGeometry: " << this->OpaqueGeometry << " (depth multisampled "
     << this->OpaqueDepthMultisampled << ", captured " << this->OpaqueDepthCaptured << ")\n";
  os << indent << "Seconds: sort " << this->SortSeconds << " (gather " << this->GatherSeconds
     << "), upload " << this->UploadSeconds << ", draw " << this->DrawSeconds << ", flush "
     << this->FlushSeconds << ", read-backs " << this->ReadbackSeconds << ", composite "
     << this->CompositeSeconds << ", table (last build) " << this->TableSeconds << "\n";
  os << indent << "MeshUpdate: " << this->MeshUpdate << " (" << this->MeshSeconds << " s)\n";
  os << indent << "TableRebuilt: " << this->TableRebuilt << ", uploaded: geometry "
     << this->GeometryUploaded << ", scalars " << this->ScalarsUploaded << ", order "
     << this->OrderUploaded << ", table " << this->TableUploaded << "\n";
  os << indent << "InvisibleCells: " << this->InvisibleCells << " (" << this->VisibilitySeconds
     << " s), culled cells " << this->CulledCells << " (" << this->CullingSeconds << " s)\n";
  os << indent << "Level of detail: " << this->LevelOfDetailFraction
     << (this->LongSegmentTable ? " (long-segment table)" : "") << ", ranking "
     << this->RankingSeconds << " s; frame " << this->FrameSeconds << " s\n";
  os << indent << "Automatic k draws: " << this->AutomaticKDraws << "\n";
}

VTK_ABI_NAMESPACE_END
