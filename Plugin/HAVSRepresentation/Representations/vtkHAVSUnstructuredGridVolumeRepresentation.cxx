/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSUnstructuredGridVolumeRepresentation.cxx

=========================================================================*/
#include "vtkHAVSUnstructuredGridVolumeRepresentation.h"

#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkDataSet.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"

#include <algorithm>

vtkStandardNewMacro(vtkHAVSUnstructuredGridVolumeRepresentation);

//------------------------------------------------------------------------------
vtkHAVSUnstructuredGridVolumeRepresentation::vtkHAVSUnstructuredGridVolumeRepresentation()
{
  this->HAVSMapper = vtkHAVSVolumeMapper::New();
  this->AddVolumeMapper("HAVS", this->HAVSMapper);
  this->SetActiveVolumeMapper("HAVS");
}

//------------------------------------------------------------------------------
vtkHAVSUnstructuredGridVolumeRepresentation::~vtkHAVSUnstructuredGridVolumeRepresentation()
{
  this->HAVSMapper->Delete();
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::SetActiveVolumeMapper(const char*)
{
  this->Superclass::SetActiveVolumeMapper("HAVS");
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
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSTableResolution(int resolution)
{
  this->HAVSMapper->SetTableScalarResolution(resolution);
  this->HAVSMapper->SetTableLengthResolution(resolution);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSBoundaryMode(int mode)
{
  this->HAVSMapper->SetBoundaryMode(mode);
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkHAVSUnstructuredGridVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_RENDER() &&
    this->GetActiveVolumeMapper() == this->HAVSMapper)
  {
    // HAVS's own level of detail instead of ParaView's LOD geometry: keep the
    // volume while interacting, with fewer k-buffer entries.
    vtkAlgorithmOutput* producer = vtkPVRenderView::GetPieceProducer(inInfo, this);
    vtkDataSet* piece =
      producer ? vtkDataSet::SafeDownCast(producer->GetProducer()->GetOutputDataObject(0)) : nullptr;
    if (!piece || piece->GetNumberOfCells() == 0)
    {
      this->Actor->SetMapper(nullptr); // an empty piece of a parallel run: nothing to draw
      return 1;
    }
    const bool interactive = inInfo->Has(vtkPVRenderView::USE_LOD()) != 0;
    if (!this->InteractiveLOD)
    {
      this->HAVSMapper->SetKBufferSize(this->KBufferSize);
      return 1; // ParaView's LOD geometry while interacting
    }
    this->Actor->SetEnableLOD(0);
    this->HAVSMapper->SetKBufferSize(interactive
        ? std::min(this->InteractiveKBufferSize, this->KBufferSize)
        : this->KBufferSize);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KBufferSize: " << this->KBufferSize << "\n";
  os << indent << "InteractiveLOD: " << this->InteractiveLOD << "\n";
  os << indent << "InteractiveKBufferSize: " << this->InteractiveKBufferSize << "\n";
  this->HAVSMapper->PrintSelf(os, indent.GetNextIndent());
}
