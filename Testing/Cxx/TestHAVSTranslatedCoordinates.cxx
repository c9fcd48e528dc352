/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSTranslatedCoordinates.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Coordinates moved far from the origin (issue 20), through both mappers at
// their defaults, float results, against the exact reference (havsTestStress.h:
// "exact", the edge pixels left out, the variants HAVS_STRESS_ORDER and
// HAVS_STRESS_PATH): the coordinates moved by 1e6 and 1e9, points stored as
// double: the image equals the unmoved one; control: at 1e9 stored as float
// (the mesh collapses to a few representable values) it does not.
//
// Usage: TestHAVSTranslatedCoordinates
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"
#include "havsTestStress.h"

#include "vtkHAVSDataSets.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <string>

using namespace havstest::stress;

int TestHAVSTranslatedCoordinates(int, char*[])
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  auto property = havstest::MakeRampPropertyFor(grid);
  const size_t edge = 8;
  for (bool cells : { false, true })
  {
    const auto plain = Render(grid, property, cells, 128, 128);
    for (double offset : { 1e6, 1e9 })
    {
      auto moved = Moved(
        grid, [offset](double x) { return x + offset; }, true);
      const auto image = Render(moved, property, cells, 128, 128);
      const auto d = havstest::Compare(image, plain, edge);
      char what[96];
      std::snprintf(what, sizeof(what), "%s, moved by %.0e (double points)", Name(cells), offset);
      Print(std::string(what) + ": vs unmoved", d);
      havstest::Check(Exact(d), std::string(what) + ": equals the unmoved image");
      havstest::Check(havstest::AllFinite(image), std::string(what) + ": finite");
    }
    // Control: at 1e9 as float the points collapse (spacing 64 at 1e9).
    auto collapsed = Moved(
      grid, [](double x) { return x + 1e9; }, false);
    const auto bad = Render(collapsed, property, cells, 128, 128);
    const auto c = havstest::Compare(bad, plain, edge);
    Print(std::string(Name(cells)) + ", moved by 1e9 as float: control", c);
    havstest::Check(!Exact(c), std::string(Name(cells)) + ": control, float points at 1e9 fail");
  }
  return havstest::Result();
}
