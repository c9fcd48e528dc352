/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSAnalytic.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Analytic checks of vtkHAVSVolumeMapper, read from the mapper's float result:
// - constant scalar and opacity through a unit box seen orthographically:
//   opacity 1 - exp(-tau L), colour c * opacity, at every covered pixel, to 1e-3;
// - the same with the volume scaled 2x along the view (world-space lengths);
// - a linear scalar ramp along the view with opacity linear in the scalar:
//   optical depth tau_max * L / 2, to 1e-3;
// - negative control: the ramp with a 2x2x2 table must miss the 1e-3 bound;
// - the same through vtkHAVSCellProjectionMapper, and its maximum intensity
//   (colour c, opacity 1) and additive (1/3 grey) blends on the ramp.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
struct Expectation
{
  double Alpha;
  double Color[3];
};

/// Renders the unit box (scaled by zScale along the view) and returns the
/// largest error over the pixels well inside its footprint.
double RenderBox(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, double zScale,
  int tableResolution, const Expectation& expected, const std::string& name, bool cells = false,
  int blend = 0)
{
  const int size = 64;
  auto window = havstest::MakeWindow(size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkHAVSVolumeMapper> havs;
  vtkNew<vtkHAVSCellProjectionMapper> projection;
  havs->KeepFloatResultOn();
  havs->SetEarlyRayTerminationOpacity(1.0);
  havs->SetTableScalarResolution(tableResolution);
  havs->SetTableLengthResolution(tableResolution);
  projection->KeepFloatResultOn();
  projection->SetTableScalarResolution(tableResolution);
  projection->SetTableLengthResolution(tableResolution);
  vtkUnstructuredGridVolumeMapper* mapper = cells
    ? static_cast<vtkUnstructuredGridVolumeMapper*>(projection)
    : static_cast<vtkUnstructuredGridVolumeMapper*>(havs);
  mapper->SetInputData(grid);
  mapper->SetBlendMode(blend);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  volume->SetScale(1.0, 1.0, zScale);
  renderer->AddVolume(volume);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.5, 0.5, 0.5 * zScale);
  camera->SetPosition(0.5, 0.5, 10.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(0.8);
  renderer->ResetCameraClippingRange();
  window->Render();

  vtkNew<vtkFloatArray> result;
  int dims[2];
  const bool kept =
    cells ? projection->GetFloatResult(result, dims) : havs->GetFloatResult(result, dims);
  if (!havstest::Check(kept, name + ": float result kept"))
  {
    return 1.0;
  }
  std::vector<float> rgba(result->GetPointer(0), result->GetPointer(0) + 4 * dims[0] * dims[1]);
  havstest::WritePNG(rgba, dims[0], dims[1], name + ".png");
  // Pixel centre -> world x, y: the view spans [0.5 - 0.8, 0.5 + 0.8].
  double worst = 0.0;
  int covered = 0;
  for (int j = 0; j < dims[1]; ++j)
  {
    for (int i = 0; i < dims[0]; ++i)
    {
      const double x = 0.5 + 0.8 * ((i + 0.5) / dims[0] * 2.0 - 1.0);
      const double y = 0.5 + 0.8 * ((j + 0.5) / dims[1] * 2.0 - 1.0);
      const float* p = &rgba[4 * (j * dims[0] + i)];
      const double margin = 2.0 * 1.6 / size;
      if (x > margin && x < 1 - margin && y > margin && y < 1 - margin)
      {
        ++covered;
        worst = std::max(worst, std::fabs(p[3] - expected.Alpha));
        for (int c = 0; c < 3; ++c)
        {
          worst = std::max(worst, std::fabs(p[c] - expected.Color[c] * expected.Alpha));
        }
      }
      else if (x < -margin || x > 1 + margin || y < -margin || y > 1 + margin)
      {
        worst = std::max(worst, double(std::fabs(p[3]))); // outside: empty
      }
    }
  }
  std::cout << name << ": "
            << (cells ? std::string("cell projection")
                      : std::string("path ") + havs->GetActiveKBufferPathName() + ", k " +
                     std::to_string(havs->GetActiveKBufferSize()))
            << ", " << covered << " covered pixels, max error " << worst << std::endl;
  havstest::Check(covered > 300, name + ": the box covers pixels");
  return worst;
}
}

int TestHAVSAnalytic(int, char*[])
{
  const double c[3] = { 0.2, 0.6, 0.9 };

  // Constant: tau = opacity / unit distance = 0.5 / 0.5 = 1 per unit, L = 1.
  auto constant = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.5, 0.0);
  auto constantProperty = havstest::MakeConstantProperty(c[0], c[1], c[2], 0.5, 0.5);
  Expectation e1{ 1.0 - std::exp(-1.0), { c[0], c[1], c[2] } };
  havstest::Check(RenderBox(constant, constantProperty, 1.0, 128, e1, "analytic_constant") <= 1e-3,
    "constant slab within 1e-3");
  // Scaled 2x along the view: L = 2 in world space.
  Expectation e2{ 1.0 - std::exp(-2.0), { c[0], c[1], c[2] } };
  havstest::Check(RenderBox(constant, constantProperty, 2.0, 128, e2, "analytic_scaled") <= 1e-3,
    "scaled slab within 1e-3");

  // Ramp: s = z over [0, 1], opacity(s) = s, unit distance 1: tau(z) = z,
  // optical depth 1/2.
  auto ramp = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
  auto rampProperty = havstest::MakeConstantProperty(c[0], c[1], c[2], 1.0, 1.0);
  rampProperty->GetScalarOpacity()->RemoveAllPoints();
  rampProperty->GetScalarOpacity()->AddPoint(0.0, 0.0);
  rampProperty->GetScalarOpacity()->AddPoint(1.0, 1.0);
  Expectation e3{ 1.0 - std::exp(-0.5), { c[0], c[1], c[2] } };
  havstest::Check(RenderBox(ramp, rampProperty, 1.0, 128, e3, "analytic_ramp") <= 1e-3,
    "linear ramp within 1e-3");

  // Negative control: a 2x2x2 table cannot represent the ramp's segments.
  const double coarse = RenderBox(ramp, rampProperty, 1.0, 2, e3, "analytic_ramp_table2");
  havstest::Check(coarse > 1e-3, "negative control: a 2^3 table misses the 1e-3 bound");

  // The same closed forms through vtkHAVSCellProjectionMapper, and its
  // order-independent blends on the ramp: maximum intensity colour c at
  // opacity 1 (s = 1); additive the integral of tau(z) z = z^2 over [0, 1] =
  // 1/3, grey, opacity 1. Controls: the 2^3 table; the additive value taken
  // for the maximum's.
  havstest::Check(
    RenderBox(constant, constantProperty, 1.0, 128, e1, "analytic_constant_cells", true) <= 1e-3,
    "cell projection: constant slab within 1e-3");
  havstest::Check(
    RenderBox(constant, constantProperty, 2.0, 128, e2, "analytic_scaled_cells", true) <= 1e-3,
    "cell projection: scaled slab within 1e-3");
  havstest::Check(RenderBox(ramp, rampProperty, 1.0, 128, e3, "analytic_ramp_cells", true) <= 1e-3,
    "cell projection: linear ramp within 1e-3");
  havstest::Check(
    RenderBox(ramp, rampProperty, 1.0, 2, e3, "analytic_ramp_table2_cells", true) > 1e-3,
    "cell projection: negative control, a 2^3 table misses the 1e-3 bound");
  Expectation maximum{ 1.0, { c[0], c[1], c[2] } };
  Expectation additive{ 1.0, { 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 } };
  havstest::Check(
    RenderBox(ramp, rampProperty, 1.0, 128, maximum, "analytic_maximum_cells", true, 1) <= 1e-3,
    "cell projection: maximum intensity within 1e-3");
  havstest::Check(RenderBox(ramp, rampProperty, 1.0, 128, additive, "analytic_additive_cells", true,
                    vtkHAVSCellProjectionMapper::ADDITIVE_BLEND) <= 1e-3,
    "cell projection: additive within 1e-3");
  havstest::Check(RenderBox(ramp, rampProperty, 1.0, 128, maximum, "analytic_additive_control",
                    true, vtkHAVSCellProjectionMapper::ADDITIVE_BLEND) > 1e-3,
    "cell projection: negative control, the additive image is not the maximum's");

  return havstest::Result();
}
