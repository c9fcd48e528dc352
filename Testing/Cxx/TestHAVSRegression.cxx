/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSRegression.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Regression baselines (for regressions only; accuracy is checked elsewhere
// against closed forms and the stock ray-cast mapper). Each scene's window
// image is compared with Testing/Baseline/<scene>.png: RMSE below 1.5/255 and
// fewer than 1 % of the pixels off by more than 4/255. Set
// HAVS_UPDATE_BASELINES=1 to skip the comparison and be told which file to
// copy over the baseline after an intended change.
#include "vtkHAVSTestUtilities.h"

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

namespace
{
void CheckScene(vtkUnstructuredGrid* grid, const std::string& scene, bool parallel)
{
  const int size = 128;
  if (!havstest::Check(grid != nullptr, scene + ": input read"))
  {
    return;
  }
  auto property = havstest::MakeRampPropertyFor(grid);
  vtkNew<vtkHAVSVolumeMapper> mapper;
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
    std::cout << "wrote " << havstest::OutputDir() << "/" << scene
              << ".png; copy it to " << baseline << std::endl;
    return;
  }
  int w = 0, h = 0;
  const std::vector<float> expected = havstest::ReadPNG(baseline, &w, &h);
  if (!havstest::Check(!expected.empty() && w == size && h == size, "baseline exists: " + baseline))
  {
    return;
  }
  // The window image is 8-bit: compare what a PNG holds.
  std::vector<float> quantized(image.size());
  for (size_t i = 0; i < image.size(); ++i)
  {
    quantized[i] = std::round(std::min(std::max(image[i], 0.0f), 1.0f) * 255.0f) / 255.0f;
  }
  // Alpha is not in the comparison: the window's alpha is not part of the picture.
  for (size_t p = 0; p < quantized.size() / 4; ++p)
  {
    quantized[4 * p + 3] = expected[4 * p + 3];
  }
  size_t over4 = 0;
  for (size_t p = 0; p < quantized.size() / 4; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::fabs(quantized[4 * p + c] - expected[4 * p + c]) > 4.0 / 255)
      {
        ++over4;
        break;
      }
    }
  }
  const auto d = havstest::Compare(quantized, expected);
  const double fraction = double(over4) / (size * size);
  std::cout << scene << ": RMSE " << d.RMSE * 255 << "/255, pixels off by > 4/255: "
            << 100 * fraction << " %" << std::endl;
  havstest::Check(d.RMSE < 1.5 / 255 && fraction < 0.01, scene + " matches its baseline");
}
}

int main()
{
  CheckScene(havstest::MakeBox(8, 8, 8, 0.125, 0.0, 1.0), "regression_box_perspective", false);
  CheckScene(havstest::ReadLoxPostVtk(), "regression_loxpost_parallel", true);
  return havstest::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
