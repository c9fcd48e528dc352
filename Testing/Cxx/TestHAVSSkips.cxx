/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSSkips.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Skipping what a scene does not need leaves the image exact (issue 17),
// against the exact reference (vtkHAVSReferenceRenderer, which draws every
// cell):
// - invisible cells: a transfer function with zero opacity over a wide band
//   between two visible bands hides most cells of the generated block
//   (sin(6x) cos(5y) + z); with the default settings (MPVO order, k = 2) the
//   mapper drops them and tags the faces between visible and invisible cells
//   as boundary faces. Exact (RMSE < 5e-4, max < 0.01), the same with point
//   and cell scalars, perspective and parallel, and the same image as with
//   every cell drawn. Control: nearly transparent cells skipped too
//   (SetInvisibleCellOpacity(0.2)) must not be exact. A transfer-function
//   edit that shows the band again draws every cell without a new sort or a
//   new mesh upload. (The suggested control, the cells dropped without their
//   faces tagged, cannot fail here: with continuous point scalars the gap
//   behind such a face lies in one zero-opacity interval and integrates to
//   zero untagged too; the tagging makes it empty by construction.)
// - off-screen cells: a zoom on a corner culls the cells outside the view
//   frustum, a clipping plane those on its discarded side; each frame exact
//   against the reference and the same image as with every cell drawn (their
//   fragments never reach the image), and nothing culled with the skip off.
//   The culled cells' faces are not ordered either (fewer faces ordered than
//   with the skip off), in the MPVO order (also on a grooved, non-convex
//   block: boundary layers) and in the centroid order (not exact here: the
//   same image as with every cell drawn, bit for bit).
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPointDataToCellData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
constexpr int kSize = 96;

/// Opacity in a low and a high band of the range, zero in between.
vtkSmartPointer<vtkVolumeProperty> BandProperty(const double range[2], double unitDistance)
{
  const double lo = range[0], span = range[1] - range[0];
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.1, 0.3, 1.0);
  color->AddRGBPoint(lo + 0.5 * span, 0.2, 1.0, 0.3);
  color->AddRGBPoint(range[1], 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> alpha;
  alpha->AddPoint(lo, 0.9);
  alpha->AddPoint(lo + 0.12 * span, 0.0);
  alpha->AddPoint(lo + 0.88 * span, 0.0);
  alpha->AddPoint(range[1], 0.9);
  property->SetColor(color);
  property->SetScalarOpacity(alpha);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  return property;
}

std::vector<float> Reference(
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, bool cellScalars)
{
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(kSize, kSize);
  reference->SetUseCellScalars(cellScalars);
  reference->Render();
  vtkFloatArray* image = reference->GetImage();
  return std::vector<float>(image->GetPointer(0), image->GetPointer(0) + 4 * kSize * kSize);
}

bool Exact(const havstest::ImageDifference& d)
{
  return d.RMSE < 5e-4 && d.Max < 0.01;
}

void TestInvisibleCells(bool cellScalars, bool parallel)
{
  const std::string name = std::string(cellScalars ? "cell" : "point") + " scalars, " +
    (parallel ? "parallel" : "perspective");
  // Pixels left out, as the other exactness tests do (havsTestCells.h says why
  // cell scalars need two more).
  const size_t edge = cellScalars ? 7 : 5;
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::MakeGenerated(14);
  if (cellScalars)
  {
    vtkNew<vtkPointDataToCellData> toCells;
    toCells->SetInputData(grid);
    toCells->Update();
    grid = vtkUnstructuredGrid::SafeDownCast(toCells->GetOutput());
  }
  double range[2];
  (cellScalars ? grid->GetCellData()->GetScalars() : grid->GetPointData()->GetScalars())
    ->GetRange(range);
  auto property = BandProperty(range, 0.1);

  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  auto scene = havstest::MakeScene(grid, mapper, property, kSize, kSize);
  havstest::PlaceCamera(scene.Renderer, 35.0, 25.0, parallel);
  const std::vector<float> exact =
    Reference(grid, property, scene.Renderer->GetActiveCamera(), cellScalars);

  scene.Window->Render();
  vtkHAVSFrameStatistics* stats = mapper->GetLastFrameStatistics();
  const vtkIdType cells = grid->GetNumberOfCells();
  const vtkIdType hidden = stats->GetInvisibleCells();
  const vtkIdType facesSkipping = stats->GetFacesDrawn();
  const std::vector<float> skippedImage = havstest::FloatResult(mapper);
  const auto skipping = havstest::Compare(skippedImage, exact, edge);
  std::printf("%s: %lld of %lld cells invisible (%.1f %%), %lld faces drawn; RMSE %.6f max %.5f\n",
    name.c_str(), static_cast<long long>(hidden), static_cast<long long>(cells),
    100.0 * hidden / cells, static_cast<long long>(facesSkipping), skipping.RMSE, skipping.Max);
  havstest::Check(hidden >= 0.85 * cells, name + ": most cells are invisible");
  havstest::Check(stats->GetTagging(), name + ": the faces next to invisible cells are tagged");
  havstest::Check(Exact(skipping), name + ": exact with the invisible cells skipped");

  // Nothing skipped: every face drawn, the same image.
  mapper->SkipInvisibleCellsOff();
  scene.Window->Render();
  const vtkIdType facesAll = stats->GetFacesDrawn();
  const std::vector<float> allImage = havstest::FloatResult(mapper);
  const auto all = havstest::Compare(allImage, exact, edge);
  const auto same = havstest::Compare(allImage, skippedImage);
  std::printf("  skip off: %lld faces drawn; RMSE %.6f max %.5f; against the skip: max %.2g\n",
    static_cast<long long>(facesAll), all.RMSE, all.Max, same.Max);
  havstest::Check(stats->GetInvisibleCells() == 0 && facesAll > 2 * facesSkipping,
    name + ": without the skip every face is drawn");
  havstest::Check(Exact(all), name + ": exact without the skip");
  havstest::Check(same.Max < 1e-4, name + ": the same image with and without the skip");

  // Control: nearly transparent cells dropped too (their opacity is small,
  // not zero): more cells skipped, and the image is not exact.
  mapper->SkipInvisibleCellsOn();
  mapper->SetInvisibleCellOpacity(0.2);
  scene.Window->Render();
  const vtkIdType hiddenControl = stats->GetInvisibleCells();
  const auto control = havstest::Compare(havstest::FloatResult(mapper), exact, edge);
  std::printf("  control (cells up to opacity 0.2 skipped): %lld invisible; RMSE %.6f max %.5f\n",
    static_cast<long long>(hiddenControl), control.RMSE, control.Max);
  havstest::Check(hiddenControl > hidden, name + ": control: more cells skipped");
  havstest::Check(!Exact(control), name + ": control: skipping visible cells is not exact");
  mapper->SetInvisibleCellOpacity(0.0);

  if (cellScalars || parallel)
  {
    return;
  }
  // A transfer-function edit shows the band: every cell drawn again, without
  // a new sort or a new upload of the mesh; the image is the new exact one.
  scene.Window->Render();
  vtkPiecewiseFunction* alpha = property->GetScalarOpacity();
  alpha->AddPoint(range[0] + 0.5 * (range[1] - range[0]), 0.3);
  scene.Window->Render();
  const auto shown = havstest::Compare(havstest::FloatResult(mapper),
    Reference(grid, property, scene.Renderer->GetActiveCamera(), false), edge);
  std::printf("  band shown: %lld invisible, order reused %d, geometry uploaded %d, order "
              "uploaded %d; RMSE %.6f max %.5f\n",
    static_cast<long long>(stats->GetInvisibleCells()), stats->GetOrderReused() ? 1 : 0,
    stats->GetGeometryUploaded() ? 1 : 0, stats->GetOrderUploaded() ? 1 : 0, shown.RMSE, shown.Max);
  havstest::Check(stats->GetInvisibleCells() < hidden / 2 && stats->GetOrderReused() &&
      !stats->GetGeometryUploaded() && stats->GetOrderUploaded(),
    "an edit showing the band: faces gathered again, no sort, no mesh upload");
  havstest::Check(Exact(shown), "an edit showing the band: exact");
}
}

/// Saturated pixels: an opaque transfer function ends most rays early; with
/// the skip on, their later fragments fail the early stencil test.
void TestSaturatedPixels(bool interlock)
{
  const std::string name = std::string("saturated pixels, ") +
    (interlock ? "interlock path (emulated on llvmpipe)" : "framebuffer-fetch path");
  if (interlock)
  {
    setenv("HAVS_EMULATE_INTERLOCK", "1", 1);
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::MakeGenerated(14);
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  auto property = havstest::MakeRampProperty(range[0], range[1], 1.0, 0.02);
  property->GetScalarOpacity()->AddPoint(range[0], 0.6);

  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  mapper->CountOrderViolationsOn(); // and the fragments that run the shader
  mapper->SetVisibilityOrderToCentroid();
  mapper->SetKBufferSize(6);
  if (interlock)
  {
    mapper->SetKBufferPathToFragmentShaderInterlock();
  }
  auto scene = havstest::MakeScene(grid, mapper, property, kSize, kSize);
  havstest::PlaceCamera(scene.Renderer, 35.0, 25.0, false);
  // One reference for both paths (the same scene).
  static const std::vector<float> exact =
    Reference(grid, property, scene.Renderer->GetActiveCamera(), false);
  vtkHAVSFrameStatistics* stats = mapper->GetLastFrameStatistics();

  auto render = [&](bool skip, vtkIdType& saturated, vtkIdType& shaded)
  {
    mapper->SetSkipSaturatedPixels(skip);
    scene.Window->Render();
    saturated = stats->GetSaturatedPixels();
    shaded = stats->GetShadedFragments();
    return havstest::FloatResult(mapper);
  };
  vtkIdType saturatedOn = 0, shadedOn = 0, saturatedOff = 0, shadedOff = 0;
  const std::vector<float> on = render(true, saturatedOn, shadedOn);
  const std::vector<float> off = render(false, saturatedOff, shadedOff);
  const auto dOn = havstest::Compare(on, exact, 5);
  const auto dOff = havstest::Compare(off, exact, 5);
  const auto same = havstest::Compare(on, off);
  size_t covered = 0;
  for (size_t i = 3; i < exact.size(); i += 4)
  {
    covered += exact[i] > 1e-3 ? 1 : 0;
  }
  std::printf("%s (path %s): %lld of %zu covered pixels marked saturated; fragments shaded "
              "%lld with the skip, %lld without (%.2f); RMSE %.6f max %.5f (without: %.6f "
              "%.5f); against each other max %.2g\n",
    name.c_str(), vtkHAVSVolumeMapper::GetKBufferPathName(stats->GetKBufferPath()),
    static_cast<long long>(saturatedOn), covered, static_cast<long long>(shadedOn),
    static_cast<long long>(shadedOff), shadedOff > 0 ? double(shadedOn) / shadedOff : 0.0, dOn.RMSE,
    dOn.Max, dOff.RMSE, dOff.Max, same.Max);
  havstest::Check(stats->GetKBufferPath() ==
      (interlock ? vtkHAVSVolumeMapper::KBufferPathFragmentShaderInterlock
                 : vtkHAVSVolumeMapper::KBufferPathFramebufferFetch),
    name + ": the path asked for");
  havstest::Check(saturatedOn > static_cast<vtkIdType>(covered / 2),
    name + ": most covered pixels saturate (the scene has something to skip)");
  havstest::Check(saturatedOff == -1, name + ": without the skip nothing is marked");
  havstest::Check(shadedOff > 0 && shadedOn > 0 && shadedOn < 0.8 * shadedOff,
    name + ": saturated pixels' fragments are rejected before the shader");
  havstest::Check(Exact(dOn) && Exact(dOff), name + ": exact with and without the skip");
  havstest::Check(same.Max < 1e-6, name + ": the same image with and without the skip");
  // The default (Automatic): the interlock path only.
  mapper->SetSkipSaturatedPixels(vtkHAVSVolumeMapper::SkipSaturatedPixelsAutomatic);
  scene.Window->Render();
  const vtkIdType saturatedAuto = stats->GetSaturatedPixels();
  const vtkIdType shadedAuto = stats->GetShadedFragments();
  std::printf("  default (automatic): %lld pixels marked, %lld fragments shaded\n",
    static_cast<long long>(saturatedAuto), static_cast<long long>(shadedAuto));
  havstest::Check(interlock ? saturatedAuto == saturatedOn && shadedAuto == shadedOn
                            : saturatedAuto == -1 && shadedAuto == shadedOff,
    name + ": the default skips on the interlock path only");

  // Control: a transparent transfer function saturates nothing, and the
  // skip then shades every fragment.
  auto faint = havstest::MakeRampProperty(range[0], range[1], 0.05, 1.0);
  scene.Volume->SetProperty(faint);
  vtkIdType saturatedFaint = 0, shadedFaintOn = 0, shadedFaintOff = 0;
  render(true, saturatedFaint, shadedFaintOn);
  render(false, saturatedFaint, shadedFaintOff);
  render(true, saturatedFaint, shadedFaintOn);
  std::printf("  control (transparent): %lld pixels marked; fragments shaded %lld with the skip, "
              "%lld without\n",
    static_cast<long long>(saturatedFaint), static_cast<long long>(shadedFaintOn),
    static_cast<long long>(shadedFaintOff));
  havstest::Check(saturatedFaint == 0 && shadedFaintOn == shadedFaintOff,
    name + ": control: nothing saturated, nothing rejected");
  if (interlock)
  {
    unsetenv("HAVS_EMULATE_INTERLOCK");
  }
}

/// Off-screen cells: a zoom on a corner, then a clipping plane; each exact
/// and the same image as with every cell drawn; the culled cells' faces are
/// neither drawn nor ordered. `order`: the visibility order; `nonConvex`: a
/// groove cut out of the block (the exact order then takes the rays'
/// re-entries from the boundary layers).
void TestOffscreenCells(int order, bool nonConvex)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::MakeGenerated(14);
  if (nonConvex)
  {
    grid = vtkHAVSDataSets::KeepCells(
      grid, [](const double* c) { return !(c[0] > 0.55 && c[0] < 0.75 && c[1] > 0.25); });
  }
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  auto property = havstest::MakeRampProperty(range[0], range[1], 0.8, 0.15);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  mapper->SetVisibilityOrder(order);
  const bool centroid = order == vtkHAVSVolumeMapper::VisibilityOrderCentroid;
  auto scene = havstest::MakeScene(grid, mapper, property, kSize, kSize);
  havstest::PlaceCamera(scene.Renderer, 35.0, 25.0, false);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0.85, 0.8, 0.9);
  camera->Zoom(3.0);
  scene.Renderer->ResetCameraClippingRange();
  vtkNew<vtkPlaneCollection> planes;
  const std::string what = std::string(nonConvex ? "grooved block, " : "") +
    (centroid ? "centroid order" : "MPVO order") + ": ";
  for (int step = 0; step < 2; ++step)
  {
    const std::string name =
      what + (step == 0 ? "a zoom on a corner" : "a zoom and a clipping plane");
    if (step == 1)
    {
      vtkNew<vtkPlane> plane;
      plane->SetOrigin(0.8, 0.8, 0.8);
      plane->SetNormal(1.0, 0.3, 0.2); // keeps the corner's far side
      planes->AddItem(plane);
      mapper->SetClippingPlanes(planes);
    }
    vtkNew<vtkHAVSReferenceRenderer> reference;
    reference->SetInputData(grid);
    reference->SetProperty(property);
    reference->SetCamera(camera);
    reference->SetSize(kSize, kSize);
    reference->SetClippingPlanes(step == 1 ? planes.Get() : nullptr);
    reference->Render();
    vtkFloatArray* image = reference->GetImage();
    const std::vector<float> exact(image->GetPointer(0), image->GetPointer(0) + 4 * kSize * kSize);

    mapper->SkipOffscreenCellsOn();
    scene.Window->Render();
    vtkHAVSFrameStatistics* stats = mapper->GetLastFrameStatistics();
    const vtkIdType culled = stats->GetCulledCells(), faces = stats->GetFacesDrawn();
    const vtkIdType ordered = stats->GetFacesOrdered();
    const std::vector<float> skipped = havstest::FloatResult(mapper);
    const auto d = havstest::Compare(skipped, exact, 5);
    mapper->SkipOffscreenCellsOff();
    scene.Window->Render();
    const vtkIdType allFaces = stats->GetFacesDrawn(), allOrdered = stats->GetFacesOrdered();
    const std::vector<float> everyCell = havstest::FloatResult(mapper);
    const auto same = havstest::Compare(everyCell, skipped);
    const auto full = havstest::Compare(everyCell, exact, 5);
    std::printf("%s: %lld of %lld cells culled, %lld of %lld faces drawn, %lld of %lld ordered; "
                "RMSE %.6f max %.5f (every cell drawn: RMSE %.6f max %.5f); against every cell "
                "drawn: max %.2g\n",
      name.c_str(), static_cast<long long>(culled),
      static_cast<long long>(grid->GetNumberOfCells()), static_cast<long long>(faces),
      static_cast<long long>(allFaces), static_cast<long long>(ordered),
      static_cast<long long>(allOrdered), d.RMSE, d.Max, full.RMSE, full.Max, same.Max);
    havstest::Check(culled >= 0.3 * grid->GetNumberOfCells() && faces < allFaces,
      name + ": the cells the frame cannot see are culled");
    havstest::Check(ordered > 0 && ordered < allOrdered && allOrdered >= allFaces,
      name + ": the culled cells' faces are not ordered");
    havstest::Check(stats->GetCulledCells() == 0, name + ": nothing culled with the skip off");
    if (centroid)
    {
      // The centroid order is not exact here; with the culled faces left out
      // of the sort it is the full order without them: the same image.
      havstest::Check(same.Max == 0.0, name + ": the same image as with every cell drawn");
    }
    else
    {
      havstest::Check(Exact(d), name + ": exact with the culled cells skipped");
      havstest::Check(same.Max < 1e-4, name + ": the same image as with every cell drawn");
    }
  }
}

int TestHAVSSkips(int, char*[])
{
  TestSaturatedPixels(false);
  TestSaturatedPixels(true);
  TestOffscreenCells(vtkHAVSVolumeMapper::VisibilityOrderMPVO, false);
  TestOffscreenCells(vtkHAVSVolumeMapper::VisibilityOrderCentroid, false);
  TestOffscreenCells(vtkHAVSVolumeMapper::VisibilityOrderMPVO, true);
  TestInvisibleCells(false, false);
  TestInvisibleCells(false, true);
  TestInvisibleCells(true, false);
  return havstest::Result();
}
