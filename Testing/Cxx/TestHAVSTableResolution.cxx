/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSTableResolution.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSTableResolution, the automatic choice of the table:
// - the tests' ramp is met by a table smaller than 128^3, and the chosen
//   table's error at independent random segments (against the adaptive
//   integral) stays within the bound;
// - a narrow opacity peak needs more than 64^3: its 64^3 table misses the
//   bound (the control: the measure can fail), the choice goes up to the
//   largest allowed;
// - a bound no table meets gives the largest allowed;
// - NeedsRebuild follows the property, the bound and the largest resolutions.
#include "havsTestChecks.h"
#include "havsTestProperties.h"

#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSTableResolution.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

namespace
{
/// The largest error of `table` at `count` uniformly random segments.
double RandomError(vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property, int count)
{
  std::mt19937 random(7u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double* range = table->GetScalarRange();
  double error = 0.0;
  for (int i = 0; i < count; ++i)
  {
    const double sf = range[0] + unit(random) * (range[1] - range[0]);
    const double sb = range[0] + unit(random) * (range[1] - range[0]);
    const double length = unit(random) * table->GetMaxLength();
    double looked[4], exact[4];
    table->Lookup(sf, sb, length, looked);
    vtkHAVSPreIntegrationTable::IntegrateSegment(property, 0, sf, sb, length, exact);
    for (int c = 0; c < 4; ++c)
    {
      error = std::max(error, std::abs(looked[c] - exact[c]));
    }
  }
  return error;
}
}

int TestHAVSTableResolution(int, char*[])
{
  const double range[2] = { 0.0, 1.0 };
  vtkNew<vtkHAVSPreIntegrationTable> table;
  vtkNew<vtkHAVSTableResolution> chooser;
  const double bound = chooser->GetErrorBound();

  // The ramp of the tests and the benchmark, segments up to 1.5 unit distances.
  auto ramp = havstest::MakeRampProperty(0.0, 1.0, 0.8, 1.0);
  for (int n : { 32, 64 })
  {
    table->SetScalarResolution(n);
    table->SetLengthResolution(n);
    table->Build(ramp, 0, range, 1.5);
    std::cout << "ramp " << n << "^3 (built in " << table->GetLastBuildSeconds()
              << " s): measured error " << chooser->MeasureError(table, ramp, 0)
              << ", at random segments " << RandomError(table, ramp, 400) << std::endl;
  }
  havstest::Check(chooser->Build(table, ramp, 0, range, 1.5, 128, 128), "ramp builds");
  const double rampError = RandomError(table, ramp, 2000);
  std::cout << "ramp: chose " << table->GetScalarResolution() << "^2 x "
            << table->GetLengthResolution() << " (" << chooser->GetLastCandidates()
            << " candidates, " << chooser->GetLastSeconds() << " s), measured error "
            << chooser->GetLastError() << ", at 2000 random segments " << rampError << std::endl;
  havstest::Check(table->GetScalarResolution() < 128, "the ramp needs less than 128^3");
  havstest::Check(chooser->GetLastError() <= bound, "the chosen table meets the bound");
  havstest::Check(rampError <= bound, "the chosen table meets the bound at random segments");

  // Unchanged inputs: no rebuild; the property, the bound, the largest size: rebuild.
  havstest::Check(!chooser->NeedsRebuild(table, ramp, 0, range, 1.5, 128, 128),
    "unchanged inputs need no rebuild");
  havstest::Check(chooser->NeedsRebuild(table, ramp, 0, range, 1.5, 256, 128),
    "a new largest resolution needs a rebuild");
  ramp->GetScalarOpacity()->AddPoint(0.9, 0.2);
  havstest::Check(chooser->NeedsRebuild(table, ramp, 0, range, 1.5, 128, 128),
    "an edited transfer function needs a rebuild");
  chooser->Build(table, ramp, 0, range, 1.5, 128, 128);
  chooser->SetErrorBound(bound / 2);
  havstest::Check(
    chooser->NeedsRebuild(table, ramp, 0, range, 1.5, 128, 128), "a new bound needs a rebuild");
  chooser->SetErrorBound(bound);

  // A narrow, opaque peak: 64^3 misses the bound (control), the choice goes up.
  auto peak = havstest::MakeConstantProperty(1.0, 0.5, 0.2, 0.0, 0.05);
  peak->GetScalarOpacity()->RemoveAllPoints();
  peak->GetScalarOpacity()->AddPoint(0.0, 0.0);
  peak->GetScalarOpacity()->AddPoint(0.48, 0.0);
  peak->GetScalarOpacity()->AddPoint(0.5, 1.0);
  peak->GetScalarOpacity()->AddPoint(0.52, 0.0);
  peak->GetScalarOpacity()->AddPoint(1.0, 0.0);
  table->SetScalarResolution(64);
  table->SetLengthResolution(64);
  table->Build(peak, 0, range, 0.2);
  const double peak64 = chooser->MeasureError(table, peak, 0);
  std::cout << "peak 64^3: measured error " << peak64 << std::endl;
  havstest::Check(peak64 > bound, "control: the peak's 64^3 table misses the bound");
  havstest::Check(chooser->Build(table, peak, 0, range, 0.2, 128, 128), "peak builds");
  std::cout << "peak: chose " << table->GetScalarResolution() << "^3, measured error "
            << chooser->GetLastError() << std::endl;
  havstest::Check(table->GetScalarResolution() > 64, "the peak needs more than 64^3");

  // A bound no table meets: the largest allowed.
  chooser->SetErrorBound(1e-9);
  chooser->Build(table, ramp, 0, range, 1.5, 64, 32);
  havstest::Check(table->GetScalarResolution() == 64 && table->GetLengthResolution() == 32,
    "an unmet bound gives the largest table allowed");
  return havstest::Result();
}
