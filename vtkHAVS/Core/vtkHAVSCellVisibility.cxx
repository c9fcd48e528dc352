/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellVisibility.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSCellVisibility.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSCellVisibility);

//------------------------------------------------------------------------------
void vtkHAVSCellVisibility::SetOpacityThreshold(double threshold)
{
  threshold = std::max(0.0, threshold);
  if (threshold != this->OpacityThreshold)
  {
    this->OpacityThreshold = threshold;
    this->Invalidate();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSCellVisibility::Invalidate()
{
  this->MeshVersion = 0;
  this->ScalarVersion = 0;
  this->TableVersion = 0;
}

//------------------------------------------------------------------------------
bool vtkHAVSCellVisibility::Update(
  vtkHAVSMesh* mesh, const vtkHAVSPreIntegrationTable* table, vtkMTimeType tableVersion)
{
  if (!mesh || !table)
  {
    return false;
  }
  if (this->MeshVersion == mesh->GetBuildTime() && this->ScalarVersion == mesh->GetScalarTime() &&
    this->TableVersion == tableVersion)
  {
    return false;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  this->MeshVersion = mesh->GetBuildTime();
  this->ScalarVersion = mesh->GetScalarTime();
  this->TableVersion = tableVersion;

  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const std::vector<uint32_t>& tetCells = faces->GetTetrahedronCells();
  const std::vector<float>& pointScalars = mesh->GetScalars();
  const std::vector<float>& tetScalars = mesh->GetTetrahedronScalars();
  const bool cellScalars = mesh->HasCellScalars();
  const vtkIdType numberOfTets = static_cast<vtkIdType>(tetCells.size());
  std::vector<uint8_t> visible(mesh->GetGrid()->GetNumberOfCells(), 0);

  // The table's transparent node pairs at the longest length: nodes a <= b
  // with nothing over [a, b] (a zero-opacity run of the transfer function).
  const int ns = table->GetBuiltScalarResolution();
  const int nl = table->GetBuiltLengthResolution();
  const float* data = table->GetTable();
  const bool usable = ns >= 2 && nl >= 1 && data;
  const float threshold = static_cast<float>(this->OpacityThreshold);
  auto transparent = [&](int a, int b)
  {
    const size_t index = ((static_cast<size_t>(nl - 1) * ns + b) * ns + a) * 4;
    if (threshold > 0.0f)
    {
      return data[index + 3] <= threshold;
    }
    return data[index] == 0.0f && data[index + 1] == 0.0f && data[index + 2] == 0.0f &&
      data[index + 3] == 0.0f;
  };

  vtkSMPTools::For(0, numberOfTets,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        float lo, hi;
        if (cellScalars)
        {
          lo = hi = tetScalars[t];
        }
        else
        {
          const uint32_t* ids = &tets[4 * t];
          lo = hi = pointScalars[ids[0]];
          for (int v = 1; v < 4; ++v)
          {
            lo = std::min(lo, pointScalars[ids[v]]);
            hi = std::max(hi, pointScalars[ids[v]]);
          }
        }
        bool hidden = false;
        if (usable && std::isfinite(lo) && std::isfinite(hi))
        {
          auto node = [ns](float s, bool up)
          {
            const double x = std::min(std::max(static_cast<double>(s), 0.0), 1.0) * (ns - 1);
            return static_cast<int>(up ? std::ceil(x) : std::floor(x));
          };
          const int a = node(lo, false), b = node(hi, true);
          hidden = transparent(a, b) && transparent(b, a);
        }
        visible[tetCells[t]] = hidden ? 0 : 1;
      }
    });
  vtkIdType invisible = 0;
  for (uint32_t c : tetCells)
  {
    invisible += visible[c] ? 0 : 1;
  }
  const bool changed = visible != this->Visible;
  this->Visible.swap(visible);
  this->NumberOfInvisibleCells = invisible;
  this->NumberOfCells = numberOfTets;
  if (changed)
  {
    this->VisibilityTime.Modified();
  }
  this->LastSeconds = vtkTimerLog::GetUniversalTime() - start;
  return changed;
}

//------------------------------------------------------------------------------
void vtkHAVSCellVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OpacityThreshold: " << this->OpacityThreshold << "\n";
  os << indent << "Cells: " << this->NumberOfCells << ", invisible " << this->NumberOfInvisibleCells
     << " (" << this->LastSeconds << " s)\n";
}

//------------------------------------------------------------------------------
size_t vtkHAVSCellVisibility::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(this->Visible);
}

VTK_ABI_NAMESPACE_END
