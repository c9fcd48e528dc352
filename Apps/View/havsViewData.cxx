/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewData.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsViewData.h"

#include "vtkHAVSDataSets.h"

#include "vtkAppendFilter.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#if HAVS_VIEW_HAS_EXODUS
#include "vtkExodusIIReader.h"
#endif
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace havsview
{
namespace
{
std::string Extension(const std::string& path)
{
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos)
  {
    return std::string();
  }
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool Readable(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return in.good();
}

/// Every block of an Exodus file appended into one grid, `array` (point data
/// first, then cell data) made active.
vtkSmartPointer<vtkUnstructuredGrid> ReadExodus(
  const std::string& path, const std::string& array, std::string& error)
{
#if !HAVS_VIEW_HAS_EXODUS
  (void)array;
  error = "this build of havs_view reads no Exodus files (VTK::IOExodus was not found when it "
          "was configured: install libhdf5-dev and libnetcdf-dev and configure again): " +
    path;
  return nullptr;
#else
  vtkNew<vtkExodusIIReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    error = "not an Exodus II file VTK can read: " + path;
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK_ATTRIB, 1);
  reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
  reader->Update();
  auto* blocks = vtkCompositeDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!blocks)
  {
    error = "the Exodus reader gave no blocks for " + path;
    return nullptr;
  }
  vtkNew<vtkAppendFilter> append;
  append->MergePointsOn();
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(blocks->NewIterator());
  int count = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (auto* block = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
    {
      append->AddInputData(block);
      ++count;
    }
  }
  if (count == 0)
  {
    error = "the Exodus file has no element blocks: " + path;
    return nullptr;
  }
  append->Update();
  vtkUnstructuredGrid* merged = append->GetOutput();
  vtkDataArray* scalars = nullptr;
  if (!array.empty())
  {
    scalars = merged->GetPointData()->GetArray(array.c_str());
    if (!scalars && merged->GetCellData()->GetArray(array.c_str()))
    {
      merged->GetCellData()->SetActiveScalars(array.c_str());
    }
    else if (!scalars)
    {
      error = "the Exodus file has no array named " + array;
      return nullptr;
    }
  }
  if (!scalars && !merged->GetCellData()->GetScalars() &&
    merged->GetPointData()->GetNumberOfArrays() > 0)
  {
    scalars = merged->GetPointData()->GetArray(0);
  }
  if (scalars)
  {
    merged->GetPointData()->SetScalars(scalars);
  }
  if (!merged->GetPointData()->GetScalars() && !merged->GetCellData()->GetScalars())
  {
    error = "the Exodus file has no point or cell array to render: " + path;
    return nullptr;
  }
  return vtkHAVSDataSets::Tetrahedralize(merged);
#endif
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> LoadMesh(const DataSource& source, std::string& error)
{
  const auto names = vtkHAVSDataSets::GetNames();
  if (std::find(names.begin(), names.end(), source.Name) != names.end())
  {
    auto grid = vtkHAVSDataSets::Load(source.Name);
    if (!grid)
    {
      error = "the data set " + source.Name + " could not be loaded (data directory " +
        vtkHAVSDataSets::GetDataDirectory() + ", or HAVS_DATA_DIR)";
    }
    return grid;
  }
  if (!Readable(source.Name))
  {
    error = source.Name + " is neither a data set name nor a readable file";
    return nullptr;
  }
  const std::string ext = Extension(source.Name);
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  if (ext == "vtu" || ext == "vtk")
  {
    grid = vtkHAVSDataSets::ReadFile(source.Name, source.Array);
  }
  else if (ext == "exo" || ext == "e" || ext == "ex2" || ext == "g" || ext == "exii")
  {
    return ReadExodus(source.Name, source.Array, error);
  }
  else if (ext == "xyz" || ext == "bin" || ext == "x" || ext == "g3d")
  {
    if (source.Solution.empty())
    {
      error = "a PLOT3D grid needs its solution file: --q FILE";
      return nullptr;
    }
    grid = vtkHAVSDataSets::ReadPlot3D(source.Name, source.Solution, source.Function);
  }
  else
  {
    error = "unknown file type ." + ext + " (" + DescribeSources() + ")";
    return nullptr;
  }
  if (!grid)
  {
    error = "VTK could not read " + source.Name;
  }
  return grid;
}

//------------------------------------------------------------------------------
std::string DescribeSources()
{
  std::ostringstream text;
  text << "a data set name (";
  const auto names = vtkHAVSDataSets::GetNames();
  for (size_t i = 0; i < names.size(); ++i)
  {
    text << (i ? ", " : "") << names[i];
  }
  text << ") or a file: .vtu, .vtk, PLOT3D .xyz/.bin with --q, Exodus .exo/.e/.ex2/.g";
  return text.str();
}
}
