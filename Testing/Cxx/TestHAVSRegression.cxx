/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSRegression.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Regression baselines (for regressions only; accuracy is checked elsewhere
// against closed forms and the stock ray-cast mapper). Each scene's window
// image is compared with Testing/Baseline/<scene>.png through
// vtkHAVSImageMetrics: RMSE below 1.5/255 and fewer than 1 % of the pixels off
// by more than 4/255. HAVS_UPDATE_BASELINES=1 writes the new images and tells
// which file to copy over the baseline after an intended change; that run
// FAILS (it compared nothing), so it can never pass in CI. Control: each image
// against the other scene's baseline must fail the same bounds.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
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
/// The window image (8-bit, as a PNG holds it) against a baseline PNG, alpha
/// left out (the window's alpha is not part of the picture).
havstest::ImageDifference CompareWithBaseline(
  const std::vector<float>& image, const std::string& baseline, int size)
{
  int w = 0, h = 0;
  const std::vector<float> expected = havstest::ReadPNG(baseline, &w, &h);
  if (!havstest::Check(!expected.empty() && w == size && h == size, "baseline exists: " + baseline))
  {
    return havstest::Compare({}, expected);
  }
  std::vector<float> quantized(image.size());
  for (size_t i = 0; i < image.size(); ++i)
  {
    quantized[i] = std::round(std::min(std::max(image[i], 0.0f), 1.0f) * 255.0f) / 255.0f;
  }
  for (size_t p = 0; p < quantized.size() / 4; ++p)
  {
    quantized[4 * p + 3] = expected[4 * p + 3];
  }
  return havstest::Compare(quantized, expected);
}

bool Matches(const havstest::ImageDifference& d)
{
  return d.RMSE < 1.5 / 255 && d.FractionOver4 < 0.01;
}

void CheckScene(
  vtkUnstructuredGrid* grid, const std::string& scene, const std::string& control, bool parallel)
{
  const int size = 128;
  if (!havstest::Check(grid != nullptr, scene + ": input read"))
  {
    return;
  }
  auto property = havstest::MakeRampPropertyFor(grid);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  havstest::UseCentroidOrder(mapper); // the k-buffer's own test: a nearly sorted order
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  s.Renderer->SetBackground(0.1, 0.1, 0.15);
  havstest::PlaceCamera(s.Renderer, 35.0, 25.0, parallel);
  s.Window->Render();
  const std::vector<float> image = havstest::ReadRGBA(s.Window);
  havstest::WritePNG(image, size, size, scene + ".png");
  const std::string baseline = havstest::BaselineDir() + "/" + scene + ".png";
  const char* update = std::getenv("HAVS_UPDATE_BASELINES");
  if (update && std::string(update) == "1")
  {
    std::cout << "wrote " << havstest::OutputDir() << "/" << scene << ".png; copy it to "
              << baseline << std::endl;
    havstest::Check(false, scene + ": HAVS_UPDATE_BASELINES=1 compares nothing");
    return;
  }
  const auto d = CompareWithBaseline(image, baseline, size);
  std::cout << scene << ": RMSE " << d.RMSE * 255
            << "/255, pixels off by > 4/255: " << 100 * d.FractionOver4 << " %" << std::endl;
  havstest::Check(Matches(d), scene + " matches its baseline");
  const auto other =
    CompareWithBaseline(image, havstest::BaselineDir() + "/" + control + ".png", size);
  std::cout << scene << " against " << control << "'s baseline (control): RMSE " << other.RMSE * 255
            << "/255" << std::endl;
  havstest::Check(!Matches(other), "control: " + scene + " does not match " + control);
}
}

int TestHAVSRegression(int, char*[])
{
  CheckScene(vtkHAVSDataSets::MakeBox(8, 8, 8, 0.125, 0.0, 1.0), "regression_box_perspective",
    "regression_loxpost_parallel", false);
  CheckScene(vtkHAVSDataSets::Load("loxpostvtk"), "regression_loxpost_parallel",
    "regression_box_perspective", true);
  return havstest::Result();
}
