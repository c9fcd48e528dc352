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
    direction == this->LastDirection && parallelProjection == this->LastParallel)
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
  const vtkIdType n = faces->GetNumberOfFaces();
  this->Keys.resize(static_cast<size_t>(n));
  float* keys = this->Keys.data();
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const float* c = centroids + 3 * f;
        double w[3];
        for (int r = 0; r < 3; ++r)
        {
          w[r] = m[4 * r] * c[0] + m[4 * r + 1] * c[1] + m[4 * r + 2] * c[2] + offset[r];
        }
        const double key = parallelProjection
          ? w[0] * direction[0] + w[1] * direction[1] + w[2] * direction[2]
          : w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        keys[f] = static_cast<float>(key);
      }
    });
  this->RadixSorter->Sort(keys, static_cast<size_t>(n), this->Order);
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
  this->LastSortSeconds = vtkTimerLog::GetUniversalTime() - start;
  ++this->NumberOfSorts;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceSorter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Faces in order: " << this->Order.size() << "\n";
  os << indent << "NumberOfSorts: " << this->NumberOfSorts << "\n";
  os << indent << "LastSortSeconds: " << this->LastSortSeconds << "\n";
  os << indent << "BlockReversal: " << this->BlockReversal << "\n";
}
