/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceSorter.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSFaceSorter.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSRadixSorter.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSFaceSorter);

//------------------------------------------------------------------------------
vtkHAVSFaceSorter::vtkHAVSFaceSorter() = default;

//------------------------------------------------------------------------------
vtkHAVSFaceSorter::~vtkHAVSFaceSorter() = default;

//------------------------------------------------------------------------------
bool vtkHAVSFaceSorter::Sort(vtkHAVSFaceSet* faces, const double modelToWorld[16],
  const double eyeWorld[3], const double directionOfProjectionWorld[3], bool parallelProjection)
{
  if (!faces)
  {
    vtkErrorMacro("Sort: no face set.");
    this->Order.clear();
    this->Valid = false;
    return false;
  }
  std::array<double, 16> matrix;
  std::array<double, 3> eye, direction;
  std::copy(modelToWorld, modelToWorld + 16, matrix.begin());
  std::copy(eyeWorld, eyeWorld + 3, eye.begin());
  std::copy(directionOfProjectionWorld, directionOfProjectionWorld + 3, direction.begin());
  if (this->Valid && faces->GetBuildTime() == this->LastFaceBuildTime &&
    this->GetMTime() == this->LastSortMTime && matrix == this->LastMatrix && eye == this->LastEye &&
    direction == this->LastDirection && parallelProjection == this->LastParallel &&
    this->SubsetVersion == this->LastSubsetVersion)
  {
    return false;
  }

  const double start = vtkTimerLog::GetUniversalTime();
  // World position minus eye of a centroid c (stored relative to the face
  // set's origin o): M3x3 c + (M (o, 1) - eye), the constant part in double.
  const double* m = matrix.data();
  const double* origin = faces->GetCentroidOrigin();
  double offset[3];
  for (int r = 0; r < 3; ++r)
  {
    offset[r] = m[4 * r] * origin[0] + m[4 * r + 1] * origin[1] + m[4 * r + 2] * origin[2] +
      m[4 * r + 3] - eye[r];
  }
  const float* centroids = faces->GetCentroids().data();
  const vtkIdType numberOfFaces = faces->GetNumberOfFaces();
  const uint32_t* subset = nullptr;
  vtkIdType n = numberOfFaces;
  if (this->Subset && !this->Subset->empty() &&
    (this->Subset->size() > static_cast<size_t>(numberOfFaces) ||
      this->Subset->back() >= static_cast<uint32_t>(numberOfFaces)))
  {
    vtkErrorMacro("Sort: the face subset does not belong to this face set; sorting every face.");
  }
  else if (this->Subset)
  {
    subset = this->Subset->data();
    n = static_cast<vtkIdType>(this->Subset->size());
  }
  this->Keys.resize(static_cast<size_t>(n));
  float* keys = this->Keys.data();
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType f = subset ? static_cast<vtkIdType>(subset[i]) : i;
        const float* c = centroids + 3 * f;
        double w[3];
        for (int r = 0; r < 3; ++r)
        {
          w[r] = m[4 * r] * c[0] + m[4 * r + 1] * c[1] + m[4 * r + 2] * c[2] + offset[r];
        }
        const double key = parallelProjection
          ? w[0] * direction[0] + w[1] * direction[1] + w[2] * direction[2]
          : w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        keys[i] = static_cast<float>(key);
      }
    });
  if (subset)
  {
    // Positions in the subset, sorted; then the faces they stand for.
    this->RadixSorter->Sort(keys, static_cast<size_t>(n), this->SubsetOrder);
    this->Order.resize(this->SubsetOrder.size());
    uint32_t* order = this->Order.data();
    const uint32_t* positions = this->SubsetOrder.data();
    vtkSMPTools::For(0, n,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          order[i] = subset[positions[i]];
        }
      });
  }
  else
  {
    this->RadixSorter->Sort(keys, static_cast<size_t>(n), this->Order);
  }
  if (this->BlockReversal > 1)
  {
    for (size_t b = 0; b < this->Order.size(); b += this->BlockReversal)
    {
      const size_t e = std::min(this->Order.size(), b + this->BlockReversal);
      std::reverse(this->Order.begin() + b, this->Order.begin() + e);
    }
  }
  this->Valid = true;
  this->LastFaceBuildTime = faces->GetBuildTime();
  this->LastSortMTime = this->GetMTime();
  this->LastMatrix = matrix;
  this->LastEye = eye;
  this->LastDirection = direction;
  this->LastParallel = parallelProjection;
  this->LastSubsetVersion = this->SubsetVersion;
  this->LastSortSeconds = vtkTimerLog::GetUniversalTime() - start;
  ++this->NumberOfSorts;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceSorter::SetFaceSubset(const std::vector<uint32_t>* faces, vtkMTimeType version)
{
  this->Subset = faces;
  this->SubsetVersion = faces ? version : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceSorter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Faces in order: " << this->Order.size()
     << (this->Subset ? " (a subset)" : " (every face)") << "\n";
  os << indent << "NumberOfSorts: " << this->NumberOfSorts << "\n";
  os << indent << "LastSortSeconds: " << this->LastSortSeconds << "\n";
  os << indent << "BlockReversal: " << this->BlockReversal << "\n";
}

//------------------------------------------------------------------------------
size_t vtkHAVSFaceSorter::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(this->Keys, this->Order, this->SubsetOrder) +
    this->RadixSorter->GetMemoryBytes();
}

VTK_ABI_NAMESPACE_END
