/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTetrahedralizer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSTetrahedralizer.h"

#include "vtkAppendFilter.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <vector>

namespace
{
const char* const kOriginalCell = "vtkHAVSTetrahedralizerOriginalCell";

/**
 * VTK's split of every cell but the quadratic tetrahedra, which get the
 * canonical eight tetrahedra. nullptr when VTK's split renumbered the points
 * (then its split is used for all).
 */
vtkSmartPointer<vtkUnstructuredGrid> SplitWithCanonicalQuadraticTetrahedra(vtkDataSet* data)
{
  auto* input = vtkUnstructuredGrid::SafeDownCast(data);
  if (!input)
  {
    return nullptr;
  }
  // VTK's split, each tetrahedron knowing the cell it came from.
  vtkNew<vtkUnstructuredGrid> tagged;
  tagged->ShallowCopy(input);
  vtkNew<vtkIdTypeArray> original;
  original->SetName(kOriginalCell);
  original->SetNumberOfTuples(input->GetNumberOfCells());
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    original->SetValue(c, c);
  }
  tagged->GetCellData()->AddArray(original);
  vtkNew<vtkDataSetTriangleFilter> split;
  split->SetInputData(tagged);
  split->TetrahedraOnlyOn();
  split->Update();
  vtkUnstructuredGrid* vtkSplit = split->GetOutput();
  auto* from = vtkIdTypeArray::SafeDownCast(vtkSplit->GetCellData()->GetArray(kOriginalCell));
  if (!from || vtkSplit->GetNumberOfPoints() != input->GetNumberOfPoints())
  {
    return nullptr;
  }

  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->SetPoints(input->GetPoints());
  out->GetPointData()->PassData(input->GetPointData());
  vtkCellData* outCD = out->GetCellData();
  outCD->CopyAllocate(input->GetCellData(), vtkSplit->GetNumberOfCells());
  out->Allocate(vtkSplit->GetNumberOfCells());
  auto insert = [&](const vtkIdType ids[4], vtkIdType source)
  {
    const vtkIdType cell = out->InsertNextCell(VTK_TETRA, 4, ids);
    outCD->CopyData(input->GetCellData(), source, cell);
  };
  for (vtkIdType t = 0; t < vtkSplit->GetNumberOfCells(); ++t)
  {
    const vtkIdType source = from->GetValue(t);
    if (input->GetCellType(source) == VTK_QUADRATIC_TETRA)
    {
      continue;
    }
    vtkIdType npts = 0;
    const vtkIdType* ids = nullptr;
    vtkSplit->GetCellPoints(t, npts, ids);
    insert(ids, source);
  }
  // vtkQuadraticTetra's nodes: corners 0-3, then the edges 01, 12, 20, 03, 13, 23.
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    if (input->GetCellType(c) != VTK_QUADRATIC_TETRA)
    {
      continue;
    }
    vtkIdType npts = 0;
    const vtkIdType* n = nullptr;
    input->GetCellPoints(c, npts, n);
    const vtkIdType e01 = n[4], e12 = n[5], e20 = n[6], e03 = n[7], e13 = n[8], e23 = n[9];
    const vtkIdType tets[8][4] = { { n[0], e01, e20, e03 }, { n[1], e12, e01, e13 },
      { n[2], e20, e12, e23 }, { n[3], e03, e13, e23 },
      // the octahedron e01 e12 e20 e03 e13 e23 around its diagonal e01-e23
      { e01, e23, e12, e13 }, { e01, e23, e13, e03 }, { e01, e23, e03, e20 },
      { e01, e23, e20, e12 } };
    for (const auto& t : tets)
    {
      insert(t, c);
    }
  }
  return out;
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSTetrahedralizer::AppendBlocks(
  vtkCompositeDataSet* blocks, const std::function<bool(vtkDataSet*)>& keep, vtkIdType* skipped,
  vtkIdType* appended)
{
  vtkIdType left = 0, used = 0;
  vtkNew<vtkAppendFilter> append;
  append->MergePointsOff();
  vtkDataSet* first = nullptr;
  if (blocks)
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(blocks->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (!leaf || leaf->GetNumberOfCells() == 0 || (keep && !keep(leaf)))
      {
        ++left;
        continue;
      }
      first = first ? first : leaf;
      append->AddInputData(leaf);
      ++used;
    }
  }
  if (skipped)
  {
    *skipped = left;
  }
  if (appended)
  {
    *appended = used;
  }
  if (used == 0)
  {
    return nullptr;
  }
  append->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = append->GetOutput();
  vtkDataArray* pointScalars = first->GetPointData()->GetScalars();
  if (pointScalars && pointScalars->GetName())
  {
    grid->GetPointData()->SetActiveScalars(pointScalars->GetName());
  }
  vtkDataArray* cellScalars = first->GetCellData()->GetScalars();
  if (cellScalars && cellScalars->GetName())
  {
    grid->GetCellData()->SetActiveScalars(cellScalars->GetName());
  }
  return grid;
}

namespace
{
/// An unstructured grid's cells whose point ids are all in range; nullptr
/// when every cell is (then the input is used as it is). VTK's split reads a
/// cell's points by id: a corrupt file's id must never reach it.
vtkSmartPointer<vtkUnstructuredGrid> WithoutInvalidCells(vtkDataSet* data, vtkIdType& invalid)
{
  invalid = 0;
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid || !grid->GetCells())
  {
    return nullptr;
  }
  const vtkIdType numberOfPoints = grid->GetNumberOfPoints();
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  std::vector<char> valid(static_cast<size_t>(numberOfCells), 1);
  vtkCellArray* cells = grid->GetCells();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    cells->GetCellAtId(c, ids);
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      const vtkIdType id = ids->GetId(i);
      if (id < 0 || id >= numberOfPoints)
      {
        valid[c] = 0;
        ++invalid;
        break;
      }
    }
  }
  if (invalid == 0)
  {
    return nullptr;
  }
  auto kept = vtkSmartPointer<vtkUnstructuredGrid>::New();
  kept->SetPoints(grid->GetPoints());
  kept->GetPointData()->ShallowCopy(grid->GetPointData());
  kept->GetCellData()->CopyAllocate(grid->GetCellData(), numberOfCells - invalid);
  kept->Allocate(numberOfCells - invalid);
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    if (valid[c])
    {
      cells->GetCellAtId(c, ids);
      const vtkIdType id = kept->InsertNextCell(grid->GetCellType(c), ids);
      kept->GetCellData()->CopyData(grid->GetCellData(), c, id);
    }
  }
  return kept;
}
}

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
  vtkSmartPointer<vtkUnstructuredGrid> valid = WithoutInvalidCells(data, r.InvalidCells);
  if (valid)
  {
    data = valid;
  }
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
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
      r.QuadraticTetrahedra += type == VTK_QUADRATIC_TETRA ? 1 : 0;
    }
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  if (r.QuadraticTetrahedra > 0)
  {
    grid = SplitWithCanonicalQuadraticTetrahedra(data);
  }
  if (!grid)
  {
    vtkNew<vtkDataSetTriangleFilter> split;
    split->SetInputData(data);
    split->TetrahedraOnlyOn();
    split->Update();
    grid = split->GetOutput();
  }
  r.Tessellated = true;
  r.OutputTetrahedra = grid->GetNumberOfCells();
  r.Seconds = vtkTimerLog::GetUniversalTime() - start;
  return grid;
}
