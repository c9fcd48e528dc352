/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSScaledCoordinates.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Coordinates scaled (issue 20), through both mappers at their defaults, float
// results, against the exact reference (havsTestStress.h: "exact", the edge
// pixels left out, the variants HAVS_STRESS_ORDER and HAVS_STRESS_PATH): the
// hollow sphere's coordinates times 1e-8 and 1e8, the opacity unit distance
// scaled alike: the image equals the unscaled one; control: the unit distance
// left unscaled changes it.
//
// Usage: TestHAVSScaledCoordinates
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

int TestHAVSScaledCoordinates(int, char*[])
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  auto property = havstest::MakeRampPropertyFor(grid);
  const double unit = property->GetScalarOpacityUnitDistance();
  const size_t edge = 8;
  for (bool cells : { false, true })
  {
    bool subset = false;
    const auto plain = Render(grid, property, cells, 128, 128, &subset);
    if (!cells && Path() == StressPath::LevelOfDetail)
    {
      // The path's images are only worth comparing if it skips faces.
      havstest::Check(subset, "HAVS on the level-of-detail path draws a subset of the faces");
    }
    for (double factor : { 1e-8, 1e8 })
    {
      auto scaled = Moved(
        grid, [factor](double x) { return x * factor; }, true);
      property->SetScalarOpacityUnitDistance(unit * factor);
      const auto image = Render(scaled, property, cells, 128, 128);
      property->SetScalarOpacityUnitDistance(unit);
      const auto control = Render(scaled, property, cells, 128, 128);
      const auto d = havstest::Compare(image, plain, edge);
      const auto c = havstest::Compare(control, plain, edge);
      char what[96];
      std::snprintf(what, sizeof(what), "%s, coordinates x %.0e", Name(cells), factor);
      Print(std::string(what) + ": vs unscaled", d);
      Print(std::string(what) + ": control, unit distance unscaled", c);
      havstest::Check(Exact(d), std::string(what) + ": equals the unscaled image");
      havstest::Check(!Exact(c), std::string(what) + ": control, the unit distance matters");
      havstest::Check(havstest::AllFinite(image), std::string(what) + ": finite");
    }
  }
  return havstest::Result();
}
