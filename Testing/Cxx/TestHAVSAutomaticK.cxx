/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSAutomaticK.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// The automatic k per view (issue 17, item 5) with the centroid order on the
// generated block (12^3 voxels, 5 tets each, inner points jittered), 64^2,
// several views:
// - the k analysis (vtkHAVSSoftwareKBuffer on the exact fragments in the
//   mapper's centroid order) knows each view's required k (the largest over
//   its pixels, the 0.05 % edge pixels the exactness tests allow left out);
//   the automatic k picks that k;
// - the image at the picked k is exact against the reference;
// - the same view, or one turned by 1 degree, keeps the k without a search;
//   a view turned by 20 degrees searches again.
// Control: the manual k one below the pick has order violations (counted on
// the GPU).
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSSoftwareKBuffer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <string>
#include <vector>

namespace
{
constexpr int kSize = 64;
}

int TestHAVSAutomaticK(int, char*[])
{
  // The block with its inner points moved by up to 0.35 of a voxel (a fixed
  // pseudo-random sequence): cells of mixed sizes and shapes, whose centroid
  // order needs more than k = 2 in places.
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::MakeGenerated(12);
  unsigned int state = 2026u;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    bool inner = true;
    for (int c = 0; c < 3; ++c)
    {
      inner = inner && x[c] > 1e-9 && x[c] < 1.0 - 1e-9;
    }
    for (int c = 0; c < 3 && inner; ++c)
    {
      state = state * 1664525u + 1013904223u;
      x[c] += 0.35 / 12.0 * ((state >> 8) / 8388608.0 - 1.0);
    }
    grid->GetPoints()->SetPoint(i, x);
  }
  grid->GetPoints()->Modified();
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  auto property = havstest::MakeRampProperty(range[0], range[1], 0.8, 0.15);

  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->SetVisibilityOrderToCentroid();
  mapper->SetKBufferPathToFramebufferFetch();
  mapper->AutomaticKBufferSizeOn();
  mapper->KeepFloatResultOn();
  mapper->SetEarlyRayTerminationOpacity(1.0); // the analysis composites every fragment
  auto scene = havstest::MakeScene(grid, mapper, property, kSize, kSize);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  vtkHAVSFrameStatistics* stats = mapper->GetLastFrameStatistics();

  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(kSize, kSize);
  vtkNew<vtkHAVSFaceSorter> centroid;
  vtkNew<vtkHAVSSoftwareKBuffer> analysis;

  const double views[][2] = { { 35.0, 25.0 }, { 120.0, -40.0 }, { 200.0, 60.0 }, { 300.0, 10.0 } };
  int matched = 0, tested = 0, largest = 0;
  for (const auto& v : views)
  {
    havstest::PlaceCamera(scene.Renderer, v[0], v[1], false);
    // The k analysis of this view, in the mapper's centroid order.
    havstest::Check(reference->ComputeFragments(), "reference fragments");
    double eye[3], dop[3];
    camera->GetPosition(eye);
    camera->GetDirectionOfProjection(dop);
    const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    centroid->Invalidate();
    centroid->Sort(reference->GetFaceSet(), identity, eye, dop, false);
    analysis->SetFaceOrder(centroid->GetOrder());
    vtkNew<vtkIntArray> requiredK;
    analysis->Analyze(reference, requiredK, nullptr);
    // The view's required k: the smallest k that every pixel needs at most,
    // the few edge pixels (0.05 %, as the exactness tests allow) left out,
    // where the rasterizer and the exact rays may see different fragments or
    // near-ties (within the violation counter's tie tolerance).
    const size_t edge = static_cast<size_t>(kSize) * kSize / 2000;
    std::vector<size_t> pixelsOver(analysis->GetMaximumRequiredK() + 2, 0);
    for (vtkIdType p = 0; p < requiredK->GetNumberOfTuples(); ++p)
    {
      for (int k = 0; k < requiredK->GetValue(p) && k < static_cast<int>(pixelsOver.size()); ++k)
      {
        ++pixelsOver[k]; // pixels needing more than k
      }
    }
    int known = 1;
    while (known < static_cast<int>(pixelsOver.size()) && pixelsOver[known] > edge)
    {
      ++known;
    }

    scene.Window->Render();
    const int picked = mapper->GetActiveKBufferSize();
    const int draws = stats->GetAutomaticKDraws();
    reference->Render();
    vtkFloatArray* image = reference->GetImage();
    const std::vector<float> exact(image->GetPointer(0), image->GetPointer(0) + 4 * kSize * kSize);
    const auto d = havstest::Compare(havstest::FloatResult(mapper), exact, 2);
    std::printf("view (%.0f, %.0f): the analysis needs k = %d (largest %d, on %zu pixels; %lld "
                "pixels over 2); automatic k = %d after %d counted draws; RMSE %.6f max %.5f\n",
      v[0], v[1], known, analysis->GetMaximumRequiredK(),
      pixelsOver[analysis->GetMaximumRequiredK() - 1],
      static_cast<long long>(analysis->GetPixelsOverK2()), picked, draws, d.RMSE, d.Max);
    ++tested;
    matched += picked == known ? 1 : 0;
    largest = std::max(largest, known);
    havstest::Check(picked == known, "the automatic k is the analysis' k");
    havstest::Check(draws > 0, "a new view searches");
    havstest::Check(d.RMSE < 5e-4 && d.Max < 0.01, "exact at the automatic k");

    // Control: one entry fewer has violations, on the GPU and in the analysis.
    if (picked > 1)
    {
      mapper->AutomaticKBufferSizeOff();
      mapper->SetKBufferSize(picked - 1);
      mapper->CountOrderViolationsOn();
      scene.Window->Render();
      const vtkIdType violations = mapper->GetLastOrderViolations();
      std::printf(
        "  control k = %d: %lld violations\n", picked - 1, static_cast<long long>(violations));
      havstest::Check(violations > 0, "control: one entry fewer has order violations");
      mapper->CountOrderViolationsOff();
      mapper->AutomaticKBufferSizeOn();
      scene.Window->Render(); // back to the automatic k (the mapper kept it)
    }
  }
  havstest::Check(largest >= 3, "some view needs more than the default k = 2");

  // Re-checked only when the camera moves far enough.
  scene.Window->Render();
  havstest::Check(stats->GetAutomaticKDraws() == 0, "the same view keeps its k");
  camera->Azimuth(1.0);
  scene.Window->Render();
  havstest::Check(stats->GetAutomaticKDraws() == 0, "a view turned by 1 degree keeps its k");
  camera->Azimuth(20.0);
  scene.Window->Render();
  std::printf("turned by 20 degrees: %d counted draws, k = %d\n", stats->GetAutomaticKDraws(),
    mapper->GetActiveKBufferSize());
  havstest::Check(stats->GetAutomaticKDraws() > 0, "a view turned by 20 degrees searches again");
  return havstest::Result();
}
