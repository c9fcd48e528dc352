/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSCompositeInput.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Composite input (issue 19), through both mappers at their defaults against
// the exact reference (havsTestCells.h: the views, the image size, "exact", the
// edge pixels left out): a vtkMultiBlockDataSet of hexahedra and tetrahedra in
// layers that interleave in depth, with a cell array, a block without it
// (skipped, warned) and an empty slot: one order across the blocks, against the
// reference of the blocks appended; control: the blocks as two volumes (VTK
// orders whole volumes) fail.
//
// Usage: TestHAVSCompositeInput
#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkAppendFilter.h"
#include "vtkFloatArray.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace havstest::cells;

namespace
{
/// Layers of the unit cube (10 cells high) whose index is in `layers`.
std::function<bool(const double*)> InLayers(std::vector<int> layers)
{
  return [layers](const double* c)
  {
    const int layer = static_cast<int>(c[2] * 10.0);
    return std::find(layers.begin(), layers.end(), layer) != layers.end();
  };
}
}

int TestHAVSCompositeInput(int, char*[])
{
  // Two blocks interleaved in depth, apart by one empty layer each time:
  // hexahedra in layers 0-1 and 6-7, tetrahedra in layers 3-4 and 9, each
  // with the cell array "c"; a third block without it and an empty slot.
  auto hexes = WithCellField(vtkHAVSDataSets::KeepCells(
    CubeGrid(10, 0.0, [](int, int, int) { return CubeAs::Hexahedron; }), InLayers({ 0, 1, 6, 7 })));
  auto tets = WithCellField(vtkHAVSDataSets::KeepCells(
    vtkHAVSDataSets::MakeBox(10, 10, 10, 0.1, 0.0, 1.0), InLayers({ 3, 4, 9 })));
  auto other = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.05, 0.0, 1.0); // point scalars "s" only
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(4);
  blocks->SetBlock(0, hexes);
  blocks->SetBlock(1, other);
  blocks->SetBlock(2, tets);
  vtkNew<vtkAppendFilter> both;
  both->AddInputData(hexes);
  both->AddInputData(tets);
  both->MergePointsOff();
  both->Update();
  vtkUnstructuredGrid* exactOf = both->GetOutput();
  auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.15);

  havstest::ImageDifference worst;
  for (bool cells : { false, true })
  {
    for (const View& view : kViews)
    {
      auto mapper = MakeMapper(cells);
      mapper->SetScalarModeToUseCellFieldData();
      mapper->SelectScalarArray("c");
      const Frame f = RenderAndReference(blocks, mapper, property, view, exactOf);
      havstest::Check(f.Errors == 0 && !f.Image.empty(), "multiblock: rendered");
      havstest::Check(
        f.Warnings >= 1 && f.Text.find("1 of the input's 3 blocks") != std::string::npos,
        "multiblock: the block without the array is skipped with a warning");
      const auto d = havstest::Compare(f.Image, f.Exact, cells ? kEdge : kEdgeCellScalars);
      worst.RMSE = std::max(worst.RMSE, d.RMSE);
      worst.Max = std::max(worst.Max, d.Max);
    }
  }
  Print("multiblock (hexahedra and tetrahedra interleaved, cell scalars): worst", worst);
  havstest::Check(Exact(worst), "multiblock: one order across the blocks, exact");

  // Control: each block a volume of its own (VTK orders whole volumes).
  vtkNew<vtkHAVSVolumeMapper> a, b;
  havstest::ImageDifference control;
  for (vtkHAVSVolumeMapper* m : { a.Get(), b.Get() })
  {
    m->KeepFloatResultOn();
    m->SetEarlyRayTerminationOpacity(1.0);
  }
  auto s = havstest::MakeScene(hexes, a, property, kSize, kSize);
  vtkNew<vtkVolume> second;
  b->SetInputData(tets);
  second->SetMapper(b);
  second->SetProperty(property);
  s.Renderer->AddVolume(second);
  havstest::PlaceCamera(s.Renderer, kViews[0].Azimuth, kViews[0].Elevation, false);
  s.Window->Render();
  const auto window = havstest::ReadRGBA(s.Window);
  vtkNew<vtkHAVSReferenceRenderer> r;
  r->SetInputData(exactOf);
  r->SetProperty(property);
  r->SetCamera(s.Renderer->GetActiveCamera());
  r->SetSize(kSize, kSize);
  r->Render();
  std::vector<float> exact(
    r->GetImage()->GetPointer(0), r->GetImage()->GetPointer(0) + 4 * kSize * kSize);
  // The window holds the two volumes over a black background: compare the
  // premultiplied colour (8-bit), not the opacity.
  double sum = 0.0, max = 0.0;
  for (size_t i = 0; i < exact.size(); i += 4)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double e = std::abs(window[i + c] - exact[i + c]);
      sum += e * e;
      max = std::max(max, e);
    }
  }
  control.RMSE = std::sqrt(sum / (3.0 * kSize * kSize));
  control.Max = max;
  Print("control: the two blocks as two volumes (window colour, 8-bit)", control);
  havstest::Check(control.Max > 0.05, "control: blocks sorted as whole volumes fail");
  return havstest::Result();
}
