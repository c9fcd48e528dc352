/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceSorter.cxx

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
  std::array<double, 16> matrix;
  std::array<double, 3> eye, direction;
  std::copy(modelToWorld, modelToWorld + 16, matrix.begin());
  std::copy(eyeWorld, eyeWorld + 3, eye.begin());
  std::copy(directionOfProjectionWorld, directionOfProjectionWorld + 3, direction.begin());
  if (this->Valid && faces->GetBuildTime() == this->LastFaceBuildTime &&
    this->GetMTime() == this->LastSortMTime && matrix == this->LastMatrix &&
    parallelProjection == this->LastParallel && direction == this->LastDirection &&
    (parallelProjection || eye == this->LastEye))
  {
    return false;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  const std::vector<float>& centroids = faces->GetCentroids();
  const vtkIdType n = faces->GetNumberOfFaces();
  this->Keys.resize(n);
  const double* m = matrix.data();
  const double* origin = faces->GetCentroidOrigin();
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType f = begin; f < end; ++f)
    {
      const double c[3] = { centroids[3 * f] + origin[0], centroids[3 * f + 1] + origin[1],
        centroids[3 * f + 2] + origin[2] };
      double w[3];
      for (int r = 0; r < 3; ++r)
      {
        w[r] = m[4 * r] * c[0] + m[4 * r + 1] * c[1] + m[4 * r + 2] * c[2] + m[4 * r + 3] -
          eye[r];
      }
      const double key = parallelProjection
        ? w[0] * direction[0] + w[1] * direction[1] + w[2] * direction[2]
        : w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
      this->Keys[f] = static_cast<float>(key);
    }
  });
  this->Radix->Sort(this->Keys.data(), static_cast<size_t>(n), this->Order);
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
