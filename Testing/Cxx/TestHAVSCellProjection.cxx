/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSCellProjection.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSCellProjectionMapper (issue 22: view-independent cell projection in
// the exact cell order, pre-integrated) against the exact reference
// (vtkHAVSReferenceRenderer): the float result at N standard views
// (perspective), a parallel view, and a rotated, stretched volume matrix
// (against the reference of the grid transformed alike). Required: RMSE <
// 5e-4 and max < 0.01 (MISSION's "exact"), leaving out up to 0.05 % of the
// pixels (centres on a face edge, covered differently by rasterizer and rays;
// as TestHAVSExactOrder), for MPVO with the boundary layers and with the
// convexification where the mesh's boundary allows it.
//
// Negative controls that must fail the same bound: the cells drawn back to
// front (in a 20 times denser medium, where MPVO must stay exact), the exit
// face chosen wrongly (the farthest forward plane instead of the nearest).
// The centroid cell order is measured and reported beside them: on these
// meshes it stays within the bound (see the note at the check).
//
// Scene "clip": one and two clipping planes on the hollow sphere, perspective
// and parallel, against the reference clipped alike (control: without them).
// Scene "opaque": an opaque sphere inside a box, against the reference cut at
// the window's depth (control: the reference through the surface).
// Scene "grazing": the LOX post's rays along faces seen almost edge-on
// (GrazingScene).
//
// Usage: TestHAVSCellProjection <scene> [size] [views]
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMapperScenes.h"
#include "havsTestScenes.h"

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSStandardViews.h"
#include "vtkHAVSVisibilityOrder.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
struct Bound
{
  double RMSE = 5e-4;
  double Max = 0.01;
  bool Exact(const havstest::ImageDifference& d) const
  {
    return d.RMSE < this->RMSE && d.Max < this->Max;
  }
};
}

/// The order-independent blends (maximum, minimum intensity, additive) drawn
/// unsorted, in a shuffled cell order, against the reference under the same
/// blend; controls: the wrong exit face (must fail at each control view).
/// Also: the shuffled and the mesh's own order give the same image, and no
/// per-view order is made (the order is reused across views).
int BlendScene(const std::string& mesh, int size, int views)
{
  auto grid = vtkHAVSDataSets::Load(mesh);
  if (!havstest::Check(grid && grid->GetNumberOfCells() > 0, "scene " + mesh + " loads"))
  {
    return EXIT_FAILURE;
  }
  const bool turned = !(mesh == "bluntfin" || mesh == "combustor");
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  // For the additive blend (its sum is clamped to 1), a unit distance of its own (below).
  auto thin = havstest::MakeRampProperty(range[0], range[1], 0.8, grid->GetLength());
  auto property = havstest::MakeRampPropertyFor(grid);
  vtkNew<vtkHAVSCellProjectionMapper> mapper;
  mapper->KeepFloatResultOn();
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  const size_t edgePixels = static_cast<size_t>(size) * size / 2000;
  const Bound bound;
  {
    // The additive sum scales with 1 / unit distance: scaled so that the
    // brightest pixel of view 0 is 0.5, neither dim nor clamped.
    havstest::PlaceStandardView(s.Renderer, grid, 0, views, turned);
    const auto probe = havstest::ReferenceImage(grid, thin, camera, size, nullptr, nullptr, 4);
    double brightest = 0.0;
    for (size_t p = 0; p < probe.size(); p += 4)
    {
      brightest = std::max(brightest, static_cast<double>(probe[p]));
    }
    if (brightest > 0.0)
    {
      thin->SetScalarOpacityUnitDistance(grid->GetLength() * brightest / 0.5);
    }
  }
  struct Mode
  {
    const char* Name;
    int Blend;
  };
  const Mode modes[] = { { "maximum intensity", 1 }, { "minimum intensity", 2 },
    { "additive", vtkHAVSCellProjectionMapper::ADDITIVE_BLEND } };
  std::printf("%s: %lld cells, %d^2, %d views + parallel, blends drawn unsorted\n", mesh.c_str(),
    static_cast<long long>(grid->GetNumberOfCells()), size, views);
  for (const Mode& mode : modes)
  {
    vtkVolumeProperty* used = mode.Blend == 4 ? thin.Get() : property.Get();
    s.Volume->SetProperty(used);
    mapper->SetBlendMode(mode.Blend);
    int inexact = 0, controls = 0, controlsFailed = 0, reused = 0;
    double worstOrderDifference = 0.0, saturated = 0.0, covered = 0.0, largest = 0.0;
    std::vector<std::vector<float>> shuffledImages;
    mapper->SetShuffleOrderForTesting(true);
    for (int v = 0; v <= views; ++v)
    {
      havstest::PlaceStandardView(s.Renderer, grid, v, views, turned);
      const std::string name =
        std::string(mode.Name) + ", view " + std::to_string(v) + (v == views ? " (parallel)" : "");
      const auto exact =
        havstest::ReferenceImage(grid, used, camera, size, nullptr, nullptr, mode.Blend);
      for (size_t p = 0; p < exact.size(); p += 4)
      {
        covered += exact[p + 3] > 0.0f ? 1.0 : 0.0;
        saturated += mode.Blend == 4 && exact[p] >= 1.0f ? 1.0 : 0.0;
        largest = std::max(largest, static_cast<double>(exact[p]));
      }
      s.Window->Render();
      reused += mapper->GetLastOrderReused() ? 1 : 0;
      shuffledImages.push_back(havstest::FloatResult(mapper));
      const auto d = havstest::Compare(shuffledImages.back(), exact, edgePixels);
      havstest::PrintDifference(name + ": shuffled cells", d);
      if (!bound.Exact(d))
      {
        ++inexact;
      }
      // Control at every view: where the field hardly varies along the rays
      // (a view across its gradient) a wrong exit cannot show for the
      // extremum blends; it must fail at half the views or more.
      ++controls;
      mapper->SetWrongExitForTesting(true);
      s.Window->Render();
      const auto wrong = havstest::Compare(havstest::FloatResult(mapper), exact, edgePixels);
      havstest::PrintDifference(name + ": control, the farthest exit plane", wrong);
      controlsFailed += bound.Exact(wrong) ? 0 : 1;
      mapper->SetWrongExitForTesting(false);
    }
    // The same views in the mesh's own cell order.
    mapper->SetShuffleOrderForTesting(false);
    for (int v = 0; v <= views; ++v)
    {
      havstest::PlaceStandardView(s.Renderer, grid, v, views, turned);
      s.Window->Render();
      const auto plain = havstest::Compare(havstest::FloatResult(mapper), shuffledImages[v]);
      worstOrderDifference = std::max(worstOrderDifference, plain.Max);
    }
    std::printf("  %s: shuffled against the mesh's order: max difference %.2g; order reused at %d "
                "of %d later views; largest red value %.3f, %.1f %% of the covered pixels "
                "saturated\n",
      mode.Name, worstOrderDifference, reused, views, largest,
      covered > 0 ? 100.0 * saturated / covered : 0.0);
    havstest::Check(inexact == 0, std::string(mode.Name) + ": exact at every view, cells shuffled");
    havstest::Check(worstOrderDifference < 1e-5,
      std::string(mode.Name) + ": the cell order does not change the image");
    // The first frame of a mode makes its (view-independent) order; every later view reuses it.
    havstest::Check(reused == views, std::string(mode.Name) + ": no per-view order");
    havstest::Check(
      covered > 0.0 && (mode.Blend != 4 || (largest > 0.1 && saturated < 0.25 * covered)),
      std::string(mode.Name) + ": the scene is covered (additive: bright, mostly unsaturated)");
    std::printf(
      "  %s: the wrong exit fails at %d of %d views\n", mode.Name, controlsFailed, controls);
    havstest::Check(2 * controlsFailed >= controls,
      std::string(mode.Name) +
        ": negative control, the wrong exit fails at half the views or more");
  }
  return havstest::Result();
}

/// The order is made again only when the view's key changes: not on a
/// redraw, nor on a transfer-function edit (which still redraws at once);
/// a camera move makes it again.
int ReuseScene(int size)
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  auto property = havstest::MakeRampPropertyFor(grid);
  vtkNew<vtkHAVSCellProjectionMapper> mapper;
  mapper->KeepFloatResultOn();
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  havstest::PlaceStandardView(s.Renderer, grid, 1, 6, true);
  s.Window->Render();
  const bool first = mapper->GetLastOrderReused();
  s.Window->Render();
  const bool redraw = mapper->GetLastOrderReused();
  const auto before = havstest::FloatResult(mapper);
  property->GetScalarOpacity()->AddPoint(0.5 *
      (property->GetScalarOpacity()->GetRange()[0] + property->GetScalarOpacity()->GetRange()[1]),
    0.0);
  s.Window->Render();
  const bool edit = mapper->GetLastOrderReused();
  const auto after = havstest::FloatResult(mapper);
  const auto exact = havstest::ReferenceImage(grid, property, s.Renderer->GetActiveCamera(), size);
  const auto d = havstest::Compare(after, exact, static_cast<size_t>(size) * size / 2000);
  const auto changed = havstest::Compare(before, after);
  s.Renderer->GetActiveCamera()->Azimuth(2.0);
  s.Window->Render();
  const bool moved = mapper->GetLastOrderReused();
  std::printf(
    "order reused: first frame %d, redraw %d, transfer-function edit %d, camera moved %d; "
    "the edit changed the image by max %.3f; after it vs the reference: RMSE %.6f max "
    "%.6f\n",
    first, redraw, edit, moved, changed.Max, d.RMSE, d.Max);
  havstest::Check(!first && redraw && edit && !moved,
    "the order is made only for a new view (not on a redraw or a transfer-function edit)");
  havstest::Check(changed.Max > 0.05, "the transfer-function edit redraws at once");
  havstest::Check(d.RMSE < 5e-4 && d.Max < 0.01, "after the edit: exact");
  return havstest::Result();
}

/// Rays along a face seen almost edge-on (scene "grazing"): the LOX post at
/// 512^2, standard view 0 (not turned), havs_benchmark's transfer function,
/// where rays cross faces of the structured grid turned 0.1 to 0.4 degrees
/// from them (|n.d| 1.5e-3 to 7e-3 of |d|) within the rasterizer's band of the
/// face at both ends of the cell's stretch. The cell and its neighbour across
/// such a face must decide alike whether the face bounds their stretches
/// (vtkHAVSCellProjectionFS.glsl, havsEdgeDistance): before, measured from the
/// face's plane at the ends of stretches that differ by a hair, one kept only
/// its side while the other left the whole stretch to it (pixel (225, 405):
/// 0.015 off, a tenth of the ray's length lost) or both kept it (pixel
/// (283, 133) 0.0048 off). Required: those pixels and the windows around them
/// within 2e-3 of the exact per-pixel integration (measured 3.3e-4), the
/// frame within the exact bound with no pixel left out. Negative control: the
/// farthest exit plane (the testing aid) fails the windows.
int GrazingScene(int size)
{
  auto grid = vtkHAVSDataSets::Load("loxpost");
  if (!havstest::Check(grid && grid->GetNumberOfCells() > 0, "scene loxpost loads"))
  {
    return EXIT_FAILURE;
  }
  auto property = havstest::MakeBenchmarkPropertyFor(grid);
  vtkNew<vtkHAVSCellProjectionMapper> mapper;
  mapper->KeepFloatResultOn();
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  vtkHAVSStandardViews::PlaceCamera(camera, grid, 0);
  s.Renderer->ResetCameraClippingRange();
  s.Window->Render();
  const std::vector<float> image = havstest::FloatResult(mapper);
  mapper->SetWrongExitForTesting(true);
  s.Window->Render();
  const std::vector<float> wrong = havstest::FloatResult(mapper);
  mapper->SetWrongExitForTesting(false);
  const std::vector<float> exact = havstest::ReferenceImage(grid, property, camera, size);
  const size_t pixels = static_cast<size_t>(size) * size;
  if (!havstest::Check(
        image.size() == 4 * pixels && wrong.size() == image.size() && exact.size() == image.size(),
        "grazing: float results and the exact image"))
  {
    return havstest::Result();
  }
  // The pixels found at 512^2 (x, y from the bottom row), scaled to `size`,
  // and the windows of 9 x 9 pixels around them.
  const int found[][2] = { { 225, 405 }, { 283, 90 }, { 227, 400 }, { 283, 133 }, { 283, 169 },
    { 284, 298 } };
  std::vector<float> windowImage, windowWrong, windowExact;
  double worstFound = 0.0;
  for (const auto& xy : found)
  {
    const int cx = xy[0] * size / 512, cy = xy[1] * size / 512;
    for (int y = std::max(cy - 4, 0); y <= std::min(cy + 4, size - 1); ++y)
    {
      for (int x = std::max(cx - 4, 0); x <= std::min(cx + 4, size - 1); ++x)
      {
        const size_t p = 4 * (static_cast<size_t>(y) * size + x);
        for (int c = 0; c < 4; ++c)
        {
          windowImage.push_back(image[p + c]);
          windowWrong.push_back(wrong[p + c]);
          windowExact.push_back(exact[p + c]);
          if (x == cx && y == cy)
          {
            worstFound = std::max(worstFound, std::fabs(double(image[p + c]) - exact[p + c]));
          }
        }
      }
    }
    const size_t p = 4 * (static_cast<size_t>(cy) * size + cx);
    std::printf("  pixel (%d, %d): mapper %.4f %.4f %.4f %.4f, exact %.4f %.4f %.4f %.4f\n", cx, cy,
      image[p], image[p + 1], image[p + 2], image[p + 3], exact[p], exact[p + 1], exact[p + 2],
      exact[p + 3]);
  }
  const auto frame = havstest::Compare(image, exact);
  const auto window = havstest::Compare(windowImage, windowExact);
  const auto control = havstest::Compare(windowWrong, windowExact);
  havstest::PrintDifference("loxpost view 0: the frame, no pixel left out", frame);
  havstest::PrintDifference("the windows around the grazing pixels", window);
  havstest::PrintDifference("control, the farthest exit plane: the windows", control);
  std::printf("  the grazing pixels: worst channel off by %.6f\n", worstFound);
  havstest::Check(worstFound < 2e-3, "grazing: the pixels found are within 2e-3 of exact");
  havstest::Check(window.Max < 2e-3, "grazing: the windows around them are within 2e-3");
  havstest::Check(frame.RMSE < 5e-4 && frame.Max < 0.01,
    "grazing: the frame within the exact bound (RMSE < 5e-4, max < 0.01), no pixel left out");
  havstest::Check(control.Max > 0.01, "grazing: negative control, the farthest exit fails");
  return havstest::Result();
}

int TestHAVSCellProjection(int argc, char* argv[])
{
  const std::string scene = argc > 1 ? argv[1] : "hollowsphere";
  const int size = argc > 2 ? std::atoi(argv[2]) : 128;
  const int views = argc > 3 ? std::atoi(argv[3]) : 6;
  if (scene == "opaque")
  {
    vtkNew<vtkHAVSCellProjectionMapper> mapper;
    return havstest::OpaqueSphereScene(mapper, size);
  }
  if (scene == "clip")
  {
    vtkNew<vtkHAVSCellProjectionMapper> mapper;
    return havstest::ClipPlanesScene(mapper, size, true);
  }
  if (scene == "reuse")
  {
    return ReuseScene(size);
  }
  if (scene == "grazing")
  {
    return GrazingScene(argc > 2 ? size : 512);
  }
  if (scene.rfind("blend-", 0) == 0)
  {
    return BlendScene(scene.substr(6), size, argc > 3 ? views : 3);
  }
  if (scene.rfind("inside-", 0) == 0)
  {
    vtkNew<vtkHAVSCellProjectionMapper> mapper;
    return havstest::CameraInsideScene(mapper, scene.substr(7), size);
  }
  auto grid = vtkHAVSDataSets::Load(scene);
  if (!havstest::Check(grid && grid->GetNumberOfCells() > 0, "scene " + scene + " loads"))
  {
    return EXIT_FAILURE;
  }
  const bool dataSet = scene == "bluntfin" || scene == "combustor" || scene == "loxpost";
  // Meshes with face planes through their centre (the test meshes' voxel
  // grids, the LOX post's O-grid): from exactly an axis view whole lines of
  // pixel rays graze faces, where rasterizer and rays disagree whatever the
  // order; as in TestHAVSExactOrder they are seen turned by 7 and 5 degrees.
  const bool turned = !dataSet || scene == "loxpost";
  std::printf("%s: %lld cells, %d^2, %d views\n", scene.c_str(),
    static_cast<long long>(grid->GetNumberOfCells()), size, views);
  auto property = havstest::MakeRampPropertyFor(grid);
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  auto dense = havstest::MakeRampProperty(range[0], range[1], 0.8, grid->GetLength() / 160.0);
  const size_t edgePixels = static_cast<size_t>(size) * size / 2000;
  const Bound bound;

  vtkNew<vtkHAVSCellProjectionMapper> mapper;
  if (!havstest::Check(mapper.GetPointer() != nullptr &&
          std::string(mapper->GetClassName()) == "vtkOpenGLHAVSCellProjectionMapper",
        "New() gives the OpenGL override"))
  {
    return EXIT_FAILURE;
  }
  mapper->KeepFloatResultOn();
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  vtkCamera* camera = s.Renderer->GetActiveCamera();

  // The methods to check: the boundary layers always; the convexification
  // on the test meshes (the data sets' boundaries are not all closed).
  std::vector<int> methods = { vtkHAVSVisibilityOrder::NonConvexBoundaryLayers };
  if (!dataSet)
  {
    methods.push_back(vtkHAVSVisibilityOrder::NonConvexConvexification);
  }
  int inexact = 0, centroidFailed = 0, reversedFailed = 0, wrongExitFailed = 0, controlViews = 0;
  vtkIdType cycleBreaks = 0;
  for (int v = 0; v <= views; ++v)
  {
    // views 0 .. views-1: standard perspective views; the last: parallel.
    const bool parallel = v == views;
    havstest::PlaceStandardView(s.Renderer, grid, v, views, turned);
    const std::string name = "view " + std::to_string(v) + (parallel ? " (parallel)" : "");
    const auto exact = havstest::ReferenceImage(grid, property, camera, size);
    for (int method : methods)
    {
      mapper->SetCellOrderToMPVO();
      mapper->SetNonConvexMethod(method);
      s.Window->Render();
      const auto d = havstest::Compare(havstest::FloatResult(mapper), exact, edgePixels);
      cycleBreaks += mapper->GetLastCycleBreaks();
      havstest::PrintDifference(name +
          (method == vtkHAVSVisibilityOrder::NonConvexBoundaryLayers ? ": MPVO + boundary layers"
                                                                     : ": MPVO + convexification"),
        d);
      if (!bound.Exact(d))
      {
        ++inexact;
        havstest::Check(false, name + ": exact for non-convex method " + std::to_string(method));
      }
    }
    if (v < 2)
    {
      // Controls, at two views: the centroid cell order, the wrong exit face.
      // The order shows where segments are dense: both orders with a 20
      // times denser medium (MPVO must stay exact there).
      ++controlViews;
      mapper->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexBoundaryLayers);
      s.Volume->SetProperty(dense);
      const auto denseExact = havstest::ReferenceImage(grid, dense, camera, size);
      s.Window->Render();
      const auto denseMPVO =
        havstest::Compare(havstest::FloatResult(mapper), denseExact, edgePixels);
      havstest::PrintDifference(name + ": denser medium, MPVO", denseMPVO);
      havstest::Check(bound.Exact(denseMPVO), name + ": denser medium, MPVO exact");
      mapper->SetCellOrderToCentroid();
      s.Window->Render();
      const auto centroid =
        havstest::Compare(havstest::FloatResult(mapper), denseExact, edgePixels);
      havstest::PrintDifference(name + ": control, denser medium, centroid cell order", centroid);
      centroidFailed += bound.Exact(centroid) ? 0 : 1;
      mapper->SetCellOrderToMPVO();
      mapper->SetReverseOrderForTesting(true);
      s.Window->Render();
      const auto reversed =
        havstest::Compare(havstest::FloatResult(mapper), denseExact, edgePixels);
      havstest::PrintDifference(name + ": control, denser medium, MPVO reversed", reversed);
      reversedFailed += bound.Exact(reversed) ? 0 : 1;
      mapper->SetReverseOrderForTesting(false);
      s.Volume->SetProperty(property);
      mapper->SetCellOrderToMPVO();
      mapper->SetWrongExitForTesting(true);
      s.Window->Render();
      const auto wrong = havstest::Compare(havstest::FloatResult(mapper), exact, edgePixels);
      havstest::PrintDifference(name + ": control, the farthest exit plane", wrong);
      wrongExitFailed += bound.Exact(wrong) ? 0 : 1;
      mapper->SetWrongExitForTesting(false);
    }
  }
  std::printf("  cycle breaks (cells out of order) over the views: %lld\n",
    static_cast<long long>(cycleBreaks));
  havstest::Check(inexact == 0, "exact at every view and method");
  havstest::Check(wrongExitFailed == controlViews,
    "negative control: the wrong exit face fails at every control view");
  havstest::Check(reversedFailed == controlViews,
    "negative control: the cells back to front fail at every control view");
  // The centroid cell order is reported, not required to fail: measured, it
  // is within the bound on these meshes (the error of compositing two thin
  // neighbouring segments in the wrong order is second order in their
  // opacities), unlike HAVS's centroid face order at small k.
  std::printf("  centroid cell order: %d of %d control views outside the bound\n", centroidFailed,
    controlViews);

  // The volume's matrix: rotated and stretched, against the transformed grid.
  vtkNew<vtkTransform> transform;
  transform->RotateWXYZ(35.0, 0.3, 1.0, 0.2);
  transform->Scale(1.0, 1.6, 0.7);
  s.Volume->SetUserTransform(transform);
  vtkNew<vtkTransformFilter> moved;
  moved->SetInputData(grid);
  moved->SetTransform(transform);
  moved->Update();
  auto movedGrid = vtkUnstructuredGrid::SafeDownCast(moved->GetOutput());
  vtkHAVSStandardViews::PlaceCamera(camera, movedGrid, 5);
  s.Renderer->ResetCameraClippingRange();
  mapper->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexBoundaryLayers);
  s.Window->Render();
  const auto d = havstest::Compare(havstest::FloatResult(mapper),
    havstest::ReferenceImage(movedGrid, property, camera, size), edgePixels);
  havstest::PrintDifference("volume matrix (rotated, stretched) vs the transformed grid", d);
  havstest::Check(bound.Exact(d), "the volume's matrix: exact");
  return havstest::Result();
}
