/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRayCastMesh.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSRayCastMesh.h"

#include "vtkHAVSCellGeometry.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>

VTK_ABI_NAMESPACE_BEGIN

namespace
{
struct FaceKey
{
  std::array<uint32_t, 3> Ids; // sorted point ids
  uint32_t Slot;               // 4 * tetrahedron + face
  bool operator<(const FaceKey& other) const
  {
    return this->Ids != other.Ids ? this->Ids < other.Ids : this->Slot < other.Slot;
  }
};
}

//------------------------------------------------------------------------------
size_t vtkHAVSRayCastMesh::ComputeNeighbours(
  const std::vector<uint32_t>& tets, std::vector<int32_t>& out)
{
  const size_t count = tets.size() / 4;
  std::vector<FaceKey> keys(4 * count);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const uint32_t* ids = &tets[4 * static_cast<size_t>(t)];
        for (int j = 0; j < 4; ++j)
        {
          FaceKey& key = keys[4 * static_cast<size_t>(t) + j];
          key.Ids = { ids[(j + 1) % 4], ids[(j + 2) % 4], ids[(j + 3) % 4] };
          std::sort(key.Ids.begin(), key.Ids.end());
          key.Slot = static_cast<uint32_t>(4 * t + j);
        }
      }
    });
  vtkSMPTools::Sort(keys.begin(), keys.end());
  out.assign(4 * count, -1);
  size_t boundary = 0;
  for (size_t i = 0; i < keys.size();)
  {
    size_t j = i + 1;
    while (j < keys.size() && keys[j].Ids == keys[i].Ids)
    {
      ++j;
    }
    if (j - i >= 2)
    {
      // The first two share the face; any others stay boundary.
      out[keys[i].Slot] = static_cast<int32_t>(keys[i + 1].Slot / 4);
      out[keys[i + 1].Slot] = static_cast<int32_t>(keys[i].Slot / 4);
      boundary += j - i - 2;
    }
    else
    {
      ++boundary;
    }
    i = j;
  }
  return boundary;
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMesh::Build(const std::vector<float>& points, const std::vector<float>& scalars,
  const std::vector<uint32_t>& tets, const std::vector<float>* cellScalars)
{
  vtkHAVSCellGeometry::Compute(points, scalars, tets, this->Cells, nullptr, cellScalars);
  const size_t boundary = ComputeNeighbours(tets, this->Neighbours);
  this->BoundaryFaces.clear();
  this->BoundaryCells.clear();
  this->BoundaryFaces.reserve(3 * boundary);
  this->BoundaryCells.reserve(boundary);
  // Each boundary face wound outward as vtkHAVSCellGeometry winds it (no
  // table of every face's corners: 48 bytes a tetrahedron).
  for (size_t slot = 0; slot < this->Neighbours.size(); ++slot)
  {
    if (this->Neighbours[slot] < 0)
    {
      const size_t t = slot / 4;
      double x[4][3];
      for (int v = 0; v < 4; ++v)
      {
        for (int c = 0; c < 3; ++c)
        {
          x[v][c] = points[3 * static_cast<size_t>(tets[4 * t + v]) + c];
        }
      }
      int corner[3];
      vtkHAVSCellGeometry::FaceCorners(static_cast<int>(slot % 4), vtkHAVSCellGeometry::Mirrored(x),
        corner[0], corner[1], corner[2]);
      for (int k = 0; k < 3; ++k)
      {
        this->BoundaryFaces.push_back(tets[4 * t + corner[k]]);
      }
      this->BoundaryCells.push_back(static_cast<uint32_t>(t));
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMesh::UpdateFields(const std::vector<float>& points,
  const std::vector<float>& scalars, const std::vector<uint32_t>& tets,
  const std::vector<float>* cellScalars)
{
  vtkHAVSCellGeometry::Compute(points, scalars, tets, this->Cells, nullptr, cellScalars);
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMesh::BreakNeighboursForTesting()
{
  for (size_t t = 0; t + 3 < this->Neighbours.size(); t += 4)
  {
    std::rotate(&this->Neighbours[t], &this->Neighbours[t] + 1, &this->Neighbours[t] + 4);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSRayCastMesh::ReleaseCells()
{
  std::vector<float>().swap(this->Cells);
}

//------------------------------------------------------------------------------
size_t vtkHAVSRayCastMesh::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(
    this->Cells, this->Neighbours, this->BoundaryFaces, this->BoundaryCells);
}

VTK_ABI_NAMESPACE_END
