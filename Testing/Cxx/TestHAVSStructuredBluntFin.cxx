/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSStructuredBluntFin.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// A structured grid as it is (issue 19), through both mappers at their defaults
// against the exact reference (havsTestCells.h: the views, the image size,
// "exact", the edge pixels left out): the NASA blunt fin's PLOT3D
// vtkStructuredGrid fed as it is (point and cell scalars) against the reference
// of the same grid.
//
// Usage: TestHAVSStructuredBluntFin
#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"

#include "vtkDataArray.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cstdio>
#include <string>

using namespace havstest::cells;

int TestHAVSStructuredBluntFin(int, char*[])
{
  const std::string dir = vtkHAVSDataSets::GetDataDirectory();
  vtkNew<vtkMultiBlockPLOT3DReader> reader;
  reader->SetXYZFileName((dir + "/bluntfinxyz.bin").c_str());
  reader->SetQFileName((dir + "/bluntfinq.bin").c_str());
  reader->SetScalarFunctionNumber(100);
  reader->Update();
  auto* grid = vtkStructuredGrid::SafeDownCast(reader->GetOutput()->GetBlock(0));
  if (!grid)
  {
    std::printf("the blunt fin could not be read from %s\n", dir.c_str());
    return 125; // skipped: the data set is not there
  }
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  auto property = havstest::MakeRampProperty(range[0], range[1], 0.8, grid->GetLength() / 8.0);
  const auto d = WorstOverViews(
    "blunt fin vtkStructuredGrid, point scalars", grid, grid, property, true, kEdge, false);
  Print("blunt fin vtkStructuredGrid as it is, point scalars: worst vs the reference", d);
  havstest::Check(Exact(d), "blunt fin structured, point scalars: exact");

  auto cellGrid = WithCellField(grid);
  auto cellProperty = havstest::MakeRampProperty(0.0, 1.0, 0.8, grid->GetLength() / 8.0);
  havstest::ImageDifference worst;
  for (bool cells : { false, true })
  {
    for (const View& view : { kViews[0], kViews[3] })
    {
      auto mapper = MakeMapper(cells);
      const Frame f = RenderAndReference(cellGrid, mapper, cellProperty, view, cellGrid);
      const auto e = havstest::Compare(f.Image, f.Exact, cells ? kEdge : kEdgeCellScalars);
      worst.RMSE = std::max(worst.RMSE, e.RMSE);
      worst.Max = std::max(worst.Max, e.Max);
    }
  }
  Print("blunt fin vtkStructuredGrid as it is, cell scalars: worst vs the reference", worst);
  havstest::Check(Exact(worst), "blunt fin structured, cell scalars: exact");
  return havstest::Result();
}
