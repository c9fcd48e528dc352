/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTetrahedralizer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSTetrahedralizer.h"

#include "vtkCellTypes.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkNew.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

//------------------------------------------------------------------------------
bool vtkHAVSTetrahedralizer::IsTetrahedral(vtkDataSet* data)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid)
  {
    return false;
  }
  if (grid->GetNumberOfCells() == 0)
  {
    return true;
  }
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  if (!types)
  {
    return false;
  }
  const unsigned char* t = types->GetPointer(0);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (t[c] != VTK_TETRA)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSTetrahedralizer::Tetrahedralize(
  vtkDataSet* data, Report* report)
{
  Report local;
  Report& r = report ? *report : local;
  r = Report();
  if (!data)
  {
    return nullptr;
  }
  r.InputCells = data->GetNumberOfCells();
  if (IsTetrahedral(data))
  {
    r.OutputTetrahedra = r.InputCells;
    return vtkUnstructuredGrid::SafeDownCast(data);
  }
  const double start = vtkTimerLog::GetUniversalTime();
  for (vtkIdType c = 0; c < r.InputCells; ++c)
  {
    const int type = data->GetCellType(c);
    const int dimension = vtkCellTypes::GetDimension(type);
    if (dimension < 3)
    {
      ++r.LowerDimensionCells;
    }
    else if (type != VTK_TETRA)
    {
      ++r.SplitCells;
    }
  }
  vtkNew<vtkDataSetTriangleFilter> split;
  split->SetInputData(data);
  split->TetrahedraOnlyOn();
  split->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = split->GetOutput();
  r.Tessellated = true;
  r.OutputTetrahedra = grid->GetNumberOfCells();
  r.Seconds = vtkTimerLog::GetUniversalTime() - start;
  return grid;
}
