/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSOrdering.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// The k-buffer finishes a nearly sorted fragment stream exactly.
// The face order is the centroid sort with every block of 500 consecutive
// faces reversed (vtkHAVSFaceSorter::SetBlockReversal): each face is at most
// 499 places out of its sorted position in the whole order (about 11,000
// faces), far fewer among the 20-30 faces a pixel sees (measured: k = 14 still
// suffices at 1000, not at 2000). At k = 14 the image equals the exact one
// (fragment lists, which sort every pixel fully) and the unperturbed k = 14
// image within 1/255; at k = 1 it is measurably different (negative control).
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"

#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdlib>
#include <iostream>

int TestHAVSOrdering(int, char*[])
{
  auto grid = vtkHAVSDataSets::MakeBox(10, 10, 10, 0.1, 0.0, 1.0);
  auto property = havstest::MakeRampProperty(0.0, 1.0, 0.9, 0.25);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  havstest::UseCentroidOrder(mapper); // the k-buffer's own test: a nearly sorted order
  mapper->KeepFloatResultOn();
  mapper->SetEarlyRayTerminationOpacity(1.0);
  auto scene = havstest::MakeScene(grid, mapper, property, 96, 96);
  havstest::PlaceCamera(scene.Renderer, 30.0, 25.0, false);
  scene.Window->Render();
  if (!mapper->IsKBufferPathSupported(
        scene.Window, vtkHAVSVolumeMapper::KBufferPathFramebufferFetch))
  {
    std::cout << "No framebuffer fetch here: the ordering is checked through fragment lists "
                 "only by TestHAVSPaths."
              << std::endl;
    havstest::Check(false, "framebuffer fetch available (llvmpipe has it)");
    return EXIT_FAILURE;
  }

  mapper->SetKBufferPathToFragmentLists();
  scene.Window->Render();
  const std::vector<float> exact = havstest::FloatResult(mapper);

  mapper->SetKBufferPathToFramebufferFetch();
  mapper->SetKBufferSize(14);
  scene.Window->Render();
  const std::vector<float> sorted14 = havstest::FloatResult(mapper);

  mapper->GetFaceSorter()->SetBlockReversal(500);
  scene.Window->Render();
  const std::vector<float> shuffled14 = havstest::FloatResult(mapper);
  mapper->SetKBufferSize(1);
  scene.Window->Render();
  const std::vector<float> shuffled1 = havstest::FloatResult(mapper);

  const auto a = havstest::Compare(shuffled14, exact);
  const auto b = havstest::Compare(shuffled14, sorted14);
  const auto c = havstest::Compare(shuffled1, exact);
  std::cout << "perturbed order, k = 14 vs exact: RMSE " << a.RMSE << ", max " << a.Max
            << ", pixels > 1/255 " << 100 * a.FractionOver1 << " %" << std::endl;
  std::cout << "perturbed order, k = 14 vs sorted order, k = 14: RMSE " << b.RMSE << ", max "
            << b.Max << std::endl;
  std::cout << "perturbed order, k = 1 vs exact (negative control): RMSE " << c.RMSE << ", max "
            << c.Max << ", pixels > 1/255 " << 100 * c.FractionOver1 << " %" << std::endl;
  havstest::Check(a.FractionOver1 < 0.005 && a.RMSE < 1e-3, "k = 14 absorbs the perturbation");
  havstest::Check(b.FractionOver1 < 0.005, "same image as the sorted order");
  havstest::Check(c.RMSE > 10 * a.RMSE && c.FractionOver1 > 0.05,
    "negative control: k = 1 is measurably different");
  return havstest::Result();
}
