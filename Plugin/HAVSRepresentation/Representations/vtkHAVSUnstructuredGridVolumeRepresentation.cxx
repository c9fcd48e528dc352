/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSUnstructuredGridVolumeRepresentation.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSUnstructuredGridVolumeRepresentation.h"

#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkDataSet.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"

#include <dlfcn.h>

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSUnstructuredGridVolumeRepresentation);

namespace
{
/// Whether this process's expat defers reparsing (expat >= 2.6, Debian 12's
/// 2.5.0-1+deb12u5) without vtkHAVSExpatFix preloaded: VTK 9.2's XML parser
/// then fails, and with it ParaView's redistribution of a grid between ranks.
bool ExpatBreaksVTKXML()
{
  return dlsym(RTLD_DEFAULT, "XML_SetReparseDeferralEnabled") != nullptr &&
    dlsym(RTLD_DEFAULT, "vtkHAVSExpatFixParserCount") == nullptr;
}
}

//------------------------------------------------------------------------------
vtkHAVSUnstructuredGridVolumeRepresentation::vtkHAVSUnstructuredGridVolumeRepresentation()
{
  this->HAVSMapper = vtkHAVSVolumeMapper::New();
  static bool warnedExpat = false;
  if (!warnedExpat && ExpatBreaksVTKXML())
  {
    warnedExpat = true;
    vtkWarningMacro("This expat defers reparsing (expat >= 2.6, or Debian 12's security update "
                    "2.5.0-1+deb12u5), which breaks VTK 9.2's XML readers: .vtu files and the "
                    "redistribution of grids between MPI ranks fail. Start ParaView with "
                    "LD_PRELOAD=<vtkHAVS>/lib/libvtkHAVSExpatFix.so (see the vtkHAVS user guide).");
  }
  // The three mappers, one prepared mesh: switching between them does not
  // tetrahedralize and index the grid again (GetHAVSLastMeshUpdate says so).
  // New() gives nullptr without the graphics layer's override
  // (vtkHAVS::OpenGL, which this module links): then that one is not offered.
  this->RayCastMapper = vtkHAVSRayCastMapper::New();
  this->CellProjectionMapper = vtkHAVSCellProjectionMapper::New();
  const std::pair<const char*, vtkHAVSMapperBase*> mappers[] = { { "HAVS", this->HAVSMapper },
    { "HAVS Ray Cast", this->RayCastMapper },
    { "HAVS Cell Projection", this->CellProjectionMapper } };
  for (const auto& named : mappers)
  {
    if (named.second)
    {
      named.second->SetMesh(this->HAVSMapper->GetMesh());
      this->AddVolumeMapper(named.first, named.second);
      this->Mappers.emplace_back(named.first, named.second);
    }
  }
  this->SetActiveVolumeMapper("HAVS");
}

//------------------------------------------------------------------------------
vtkHAVSUnstructuredGridVolumeRepresentation::~vtkHAVSUnstructuredGridVolumeRepresentation()
{
  for (const auto& named : this->Mappers)
  {
    named.second->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::SetActiveVolumeMapper(const char*)
{
  this->Superclass::SetActiveVolumeMapper(this->HAVSMapperName.c_str());
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSMapper(const char* name)
{
  const std::string wanted = name ? name : "";
  if (!this->FindMapper(wanted))
  {
    std::string known;
    for (const auto& named : this->Mappers)
    {
      known += (known.empty() ? "\"" : ", \"") + named.first + "\"";
    }
    vtkErrorMacro("Unknown HAVS mapper \"" << wanted << "\" (" << known << ").");
    return;
  }
  if (wanted != this->HAVSMapperName)
  {
    this->HAVSMapperName = wanted;
    this->Superclass::SetActiveVolumeMapper(this->HAVSMapperName.c_str());
    this->Modified();
  }
}

vtkHAVSMapperBase* vtkHAVSUnstructuredGridVolumeRepresentation::FindMapper(
  const std::string& name) const
{
  for (const auto& named : this->Mappers)
  {
    if (named.first == name)
    {
      return named.second;
    }
  }
  return nullptr;
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSLastMeshUpdate()
{
  vtkHAVSMapperBase* active = this->FindMapper(this->HAVSMapperName);
  return active ? active->GetLastMeshUpdate() : 0;
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSMaximumPeelPasses(int passes)
{
  if (this->RayCastMapper)
  {
    this->RayCastMapper->SetMaximumPeelPasses(passes);
  }
  this->Modified();
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSLastPeelPasses()
{
  return this->RayCastMapper ? this->RayCastMapper->GetLastPeelPasses() : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSKBufferSize(int k)
{
  if (this->KBufferSize != k)
  {
    this->KBufferSize = k;
    this->HAVSMapper->SetKBufferSize(k);
    this->Modified();
  }
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSKBufferSize()
{
  return this->KBufferSize;
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSActiveKBufferSize()
{
  return this->HAVSMapper->GetActiveKBufferSize();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSEarlyRayTerminationOpacity(double opacity)
{
  this->HAVSMapper->SetEarlyRayTerminationOpacity(opacity);
  if (this->RayCastMapper)
  {
    this->RayCastMapper->SetEarlyRayTerminationOpacity(opacity);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSTableResolution(int resolution)
{
  for (const auto& named : this->Mappers)
  {
    named.second->SetTableScalarResolution(resolution);
    named.second->SetTableLengthResolution(resolution);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSHigherOrderSubdivision(int level)
{
  for (const auto& named : this->Mappers)
  {
    named.second->SetHigherOrderSubdivision(level);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSAutomaticTable(int automatic)
{
  this->HAVSMapper->SetAutomaticTableResolution(automatic != 0);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSSkipHiddenCells(int skip)
{
  this->HAVSMapper->SetSkipInvisibleCells(skip != 0);
  this->HAVSMapper->SetSkipOffscreenCells(skip != 0);
  this->HAVSMapper->SetSkipSaturatedPixels(skip != 0
      ? vtkHAVSVolumeMapper::SkipSaturatedPixelsAutomatic
      : vtkHAVSVolumeMapper::SkipSaturatedPixelsNever);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSBoundaryMode(int mode)
{
  this->HAVSMapper->SetBoundaryMode(mode);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSVisibilityOrder(int order)
{
  this->HAVSMapper->SetVisibilityOrder(order);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSNonConvexMethod(int method)
{
  this->HAVSMapper->SetNonConvexMethod(method);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSCountOrderViolations(int count)
{
  this->HAVSMapper->SetCountOrderViolations(count != 0);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSLODStrategy(int strategy)
{
  this->HAVSMapper->SetLevelOfDetailStrategy(strategy);
  this->Modified();
}

double vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSLastLODFraction()
{
  return this->HAVSMapper->GetLastFrameStatistics()->GetLevelOfDetailFraction();
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSLastOrderViolations()
{
  return static_cast<int>(this->HAVSMapper->GetLastOrderViolations());
}

//------------------------------------------------------------------------------
int vtkHAVSUnstructuredGridVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  vtkAbstractVolumeMapper* active = this->GetActiveVolumeMapper();
  if (request_type != vtkPVView::REQUEST_RENDER() || !vtkHAVSMapperBase::SafeDownCast(active))
  {
    return 1;
  }
  vtkAlgorithmOutput* producer = vtkPVRenderView::GetPieceProducer(inInfo, this);
  vtkDataSet* piece =
    producer ? vtkDataSet::SafeDownCast(producer->GetProducer()->GetOutputDataObject(0)) : nullptr;
  if (!piece || piece->GetNumberOfCells() == 0)
  {
    this->Actor->SetMapper(nullptr); // an empty piece of a parallel run: nothing to draw
    return 1;
  }
  if (active == this->HAVSMapper)
  {
    // HAVS's own level of detail instead of ParaView's LOD geometry: keep the
    // volume while interacting, with a subset of the internal faces that fits
    // the interactive target time and fewer k-buffer entries; every face when
    // still (an unlimited budget). (The ray caster and the cell projection
    // have no level of detail of their own: ParaView's LOD while
    // interacting, as for the stock mappers.)
    const bool interactive = inInfo->Has(vtkPVRenderView::USE_LOD()) != 0;
    if (!this->InteractiveLOD)
    {
      this->HAVSMapper->SetKBufferSize(this->KBufferSize);
      this->HAVSMapper->SetLevelOfDetailTargetSeconds(VTK_DOUBLE_MAX);
      return 1; // ParaView's LOD geometry while interacting
    }
    this->Actor->SetEnableLOD(0);
    this->HAVSMapper->SetLevelOfDetailTargetSeconds(
      interactive ? this->InteractiveTargetSeconds : VTK_DOUBLE_MAX);
    this->HAVSMapper->SetKBufferSize(
      interactive ? std::min(this->InteractiveKBufferSize, this->KBufferSize) : this->KBufferSize);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HAVSMapper: " << this->HAVSMapperName << "\n";
  os << indent << "KBufferSize: " << this->KBufferSize << "\n";
  os << indent << "InteractiveLOD: " << this->InteractiveLOD << "\n";
  os << indent << "InteractiveKBufferSize: " << this->InteractiveKBufferSize << "\n";
  os << indent << "InteractiveTargetSeconds: " << this->InteractiveTargetSeconds << "\n";
  for (const auto& named : this->Mappers)
  {
    os << indent << named.first << ":\n";
    named.second->PrintSelf(os, indent.GetNextIndent());
  }
}

VTK_ABI_NAMESPACE_END
