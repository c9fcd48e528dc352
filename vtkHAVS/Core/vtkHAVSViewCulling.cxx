/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSViewCulling.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSViewCulling.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPlaneSection.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSViewCulling);

//------------------------------------------------------------------------------
std::vector<std::array<double, 4>> vtkHAVSViewCulling::FrustumPlanes(const double m[16])
{
  // Clip coordinates c = M p; inside: -w <= x, y, z <= w, i.e. the rows
  // w + x, w - x, w + y, w - y, w + z, w - z are >= 0.
  std::vector<std::array<double, 4>> planes;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (double sign : { 1.0, -1.0 })
    {
      std::array<double, 4> p;
      for (int j = 0; j < 4; ++j)
      {
        p[j] = m[12 + j] + sign * m[4 * axis + j];
      }
      planes.push_back(p);
    }
  }
  return planes;
}

//------------------------------------------------------------------------------
bool vtkHAVSViewCulling::Outside(const float* const points[4], const double plane[4])
{
  for (int v = 0; v < 4; ++v)
  {
    const float* p = points[v];
    if (plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3] >= 0.0)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSViewCulling::Update(vtkHAVSMesh* mesh, const std::vector<std::array<double, 4>>& planes)
{
  // The same planes on the same mesh: the same cells (a still camera).
  if (mesh->GetBuildTime() == this->MeshVersion && planes == this->LastPlanes)
  {
    this->LastSeconds = 0.0;
    return false;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  this->MeshVersion = mesh->GetBuildTime();
  this->LastPlanes = planes;

  // The planes with part of the mesh's bounding box outside (a box inside
  // every plane culls nothing): those that cut it, or have it all outside.
  const double* b = mesh->GetBounds();
  std::vector<std::array<double, 4>> cutting;
  for (const std::array<double, 4>& plane : planes)
  {
    if (vtkHAVSPlaneSection::CutsBox(plane.data(), b) ||
      plane[0] * b[0] + plane[1] * b[2] + plane[2] * b[4] + plane[3] < 0.0)
    {
      cutting.push_back(plane);
    }
  }
  if (cutting.empty())
  {
    const bool changed = this->NumberOfCulledCells != 0;
    this->Culled.clear();
    this->NumberOfCulledCells = 0;
    if (changed)
    {
      this->CullingTime.Modified();
    }
    this->LastSeconds = vtkTimerLog::GetUniversalTime() - start;
    return changed;
  }

  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const std::vector<uint32_t>& tetCells = faces->GetTetrahedronCells();
  const std::vector<float>& points = mesh->GetPoints();
  const vtkIdType cells = mesh->GetGrid()->GetNumberOfCells();
  std::vector<uint8_t> culled(cells, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(tetCells.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const uint32_t* ids = &tets[4 * t];
        const float* p[4] = { &points[3 * static_cast<size_t>(ids[0])],
          &points[3 * static_cast<size_t>(ids[1])], &points[3 * static_cast<size_t>(ids[2])],
          &points[3 * static_cast<size_t>(ids[3])] };
        for (const std::array<double, 4>& plane : cutting)
        {
          if (Outside(p, plane.data()))
          {
            culled[tetCells[t]] = 1;
            break;
          }
        }
      }
    });
  vtkIdType count = 0;
  for (uint32_t c : tetCells)
  {
    count += culled[c];
  }
  const bool changed = culled != this->Culled;
  this->Culled.swap(culled);
  this->NumberOfCulledCells = count;
  if (changed)
  {
    this->CullingTime.Modified();
  }
  this->LastSeconds = vtkTimerLog::GetUniversalTime() - start;
  return changed;
}

//------------------------------------------------------------------------------
void vtkHAVSViewCulling::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Culled cells: " << this->NumberOfCulledCells << " (" << this->LastSeconds
     << " s)\n";
}

//------------------------------------------------------------------------------
size_t vtkHAVSViewCulling::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(this->Culled, this->LastPlanes);
}

VTK_ABI_NAMESPACE_END
