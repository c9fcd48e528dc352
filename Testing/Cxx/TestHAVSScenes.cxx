/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSScenes.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// What a VTK user expects of a mapper, each against an independent answer:
// - the volume's matrix: rendering a grid under a rotation+scale matrix equals
//   rendering the grid transformed beforehand with an identity matrix;
// - a window resize: the image at the new size equals a fresh window's;
// - ReleaseGraphicsResources and a new window: the next render rebuilds;
// - one mapper shown in two windows;
// - two disjoint volumes in one renderer: each as when alone;
// - several renderers (viewports) in one window: each the closed form;
// - an opaque actor intersecting the volume: rays end at its surface, the
//   last segment cut there (closed form for a constant slab);
// - maximum / minimum intensity blend: the extremal scalar's colour;
// - unchanged work: a still camera redraws without a sort, a table build or an
//   upload; a transfer-function edit rebuilds and uploads the table only (and
//   the image changes at once); a camera move sorts and uploads the order
//   only; a new time step uploads the scalars only. Each counter is also seen
//   set where its input changed, so a counter stuck at either value fails.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include <algorithm>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
const double kColor[3] = { 0.2, 0.6, 0.9 };

/// Orthographic view of the unit box along -z, the view spanning [-0.3, 1.3].
void ViewBoxAlongZ(vtkRenderer* renderer, double zCentre)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.5, 0.5, zCentre);
  camera->SetPosition(0.5, 0.5, zCentre + 10.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(0.8);
  renderer->ResetCameraClippingRange();
}

/// A volume of `grid` through its own HAVS mapper (float result kept, early
/// ray termination off) added to `renderer`.
vtkSmartPointer<vtkVolume> AddExactVolume(
  vtkRenderer* renderer, vtkUnstructuredGrid* grid, vtkVolumeProperty* property)
{
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->SetInputData(grid);
  mapper->KeepFloatResultOn();
  mapper->SetEarlyRayTerminationOpacity(1.0);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  return volume;
}

float PixelAlpha(const std::vector<float>& rgba, int width, int i, int j)
{
  return rgba[4 * (j * width + i) + 3];
}

void TestVolumeMatrix()
{
  auto grid = vtkHAVSDataSets::MakeBox(6, 6, 6, 1.0 / 6, 0.0, 1.0);
  auto property = havstest::MakeRampProperty(0.0, 1.0, 0.7, 0.4);
  vtkNew<vtkTransform> transform;
  transform->Translate(0.3, -0.2, 0.1);
  transform->RotateWXYZ(35.0, 1.0, 2.0, 0.5);
  transform->Scale(1.5, 0.8, 1.2);

  vtkNew<vtkHAVSVolumeMapper> mapperA;
  mapperA->KeepFloatResultOn();
  auto a = havstest::MakeScene(grid, mapperA, property, 80, 80);
  a.Volume->SetUserTransform(transform);
  havstest::PlaceCamera(a.Renderer, 20, 10, false);
  a.Window->Render();

  vtkNew<vtkTransformFilter> moved;
  moved->SetInputData(grid);
  moved->SetTransform(transform);
  moved->Update();
  vtkNew<vtkHAVSVolumeMapper> mapperB;
  mapperB->KeepFloatResultOn();
  auto b = havstest::MakeScene(
    vtkUnstructuredGrid::SafeDownCast(moved->GetOutput()), mapperB, property, 80, 80);
  b.Renderer->SetActiveCamera(a.Renderer->GetActiveCamera());
  b.Window->Render();
  const auto d = havstest::Compare(havstest::FloatResult(mapperA), havstest::FloatResult(mapperB));
  std::cout << "volume matrix vs transformed grid: RMSE " << d.RMSE << ", max " << d.Max
            << std::endl;
  havstest::Check(d.RMSE < 2e-4 && d.Max < 4.0 / 255, "the volume's matrix is applied");
}

void TestResizeReleaseAndTwoWindows()
{
  auto grid = vtkHAVSDataSets::MakeBox(5, 5, 5, 0.2, 0.0, 1.0);
  auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.3);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  auto a = havstest::MakeScene(grid, mapper, property, 64, 64);
  havstest::PlaceCamera(a.Renderer, 40, 30, false);
  a.Window->Render();
  a.Window->SetSize(100, 70);
  a.Window->Render();
  const std::vector<float> resized = havstest::FloatResult(mapper);
  havstest::Check(resized.size() == 100 * 70 * 4, "the result follows the window size");

  // A fresh window of that size, another mapper, the same camera.
  vtkNew<vtkHAVSVolumeMapper> fresh;
  fresh->KeepFloatResultOn();
  auto b = havstest::MakeScene(grid, fresh, property, 100, 70);
  b.Renderer->SetActiveCamera(a.Renderer->GetActiveCamera());
  b.Window->Render();
  const std::vector<float> reference = havstest::FloatResult(fresh);
  auto d = havstest::Compare(resized, reference);
  std::cout << "resized vs fresh window: RMSE " << d.RMSE << std::endl;
  havstest::Check(d.Max < 1e-5, "a resized window renders as a fresh one");

  // Release everything; the next render rebuilds it.
  mapper->ReleaseGraphicsResources(a.Window);
  a.Window->Render();
  d = havstest::Compare(havstest::FloatResult(mapper), reference);
  havstest::Check(d.Max < 1e-5, "render after ReleaseGraphicsResources");

  // The same mapper (and volume) shown in a second window, then the first again.
  auto second = havstest::MakeWindow(100, 70);
  vtkNew<vtkRenderer> renderer2;
  second->AddRenderer(renderer2);
  renderer2->AddVolume(a.Volume);
  renderer2->SetActiveCamera(a.Renderer->GetActiveCamera());
  second->Render();
  d = havstest::Compare(havstest::FloatResult(mapper), reference);
  havstest::Check(d.Max < 1e-5, "one mapper in a second window");
  a.Window->Render();
  d = havstest::Compare(havstest::FloatResult(mapper), reference);
  havstest::Check(d.Max < 1e-5, "and back in the first window");

  // A third window shows the volume, lets it go, and is deleted while the
  // mapper's resources live in it (the window cannot tell the mapper): the
  // mapper must not touch the dead context afterwards.
  {
    auto third = havstest::MakeWindow(50, 40);
    vtkNew<vtkRenderer> renderer3;
    third->AddRenderer(renderer3);
    renderer3->AddVolume(a.Volume);
    renderer3->SetActiveCamera(a.Renderer->GetActiveCamera());
    third->Render();
    renderer3->RemoveVolume(a.Volume);
  }
  second->Render();
  d = havstest::Compare(havstest::FloatResult(mapper), reference);
  havstest::Check(d.Max < 1e-5, "after a window holding its resources was deleted");

  // The first window goes away; the mapper renders on in the second.
  a.Window->RemoveRenderer(a.Renderer);
  a.Window = nullptr;
  second->Render();
  d = havstest::Compare(havstest::FloatResult(mapper), reference);
  havstest::Check(d.Max < 1e-5, "after the first window is deleted");
}

void TestTwoVolumesAndViewports()
{
  auto grid = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.5, 0.0);
  auto property = havstest::MakeConstantProperty(kColor[0], kColor[1], kColor[2], 0.5, 0.5);
  const float expected = static_cast<float>(1.0 - std::exp(-1.0));

  // Two boxes side by side in one renderer: [0,1] and [1.5,2.5] in x.
  auto window = havstest::MakeWindow(128, 64);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  auto v1 = AddExactVolume(renderer, grid, property);
  auto v2 = AddExactVolume(renderer, grid, property);
  v2->SetPosition(1.5, 0.0, 0.0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(1.25, 0.5, 0.5);
  camera->SetPosition(1.25, 0.5, 10.0);
  camera->SetParallelScale(0.8);
  renderer->ResetCameraClippingRange();
  window->Render();
  std::vector<float> rgba = havstest::ReadRGBA(window);
  // x = 0.5 and x = 2.0 are the two boxes' centres: pixel columns.
  const auto column = [](double x) { return static_cast<int>((x - (1.25 - 1.6)) / 3.2 * 128); };
  const float a1 = PixelAlpha(rgba, 128, column(0.5), 32);
  const float a2 = PixelAlpha(rgba, 128, column(2.0), 32);
  const float gap = PixelAlpha(rgba, 128, column(1.25), 32);
  std::cout << "two volumes: alpha " << a1 << ", " << a2 << " (expected " << expected << "), gap "
            << gap << std::endl;
  havstest::Check(std::fabs(a1 - expected) < 2.0 / 255 && std::fabs(a2 - expected) < 2.0 / 255,
    "two volumes in one renderer");
  havstest::Check(gap < 1.0 / 255, "nothing between them");

  // Two renderers (viewports) in one window, each with its own mapper.
  auto split = havstest::MakeWindow(128, 64);
  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  split->AddRenderer(left);
  split->AddRenderer(right);
  auto* m3 = vtkHAVSVolumeMapper::SafeDownCast(AddExactVolume(left, grid, property)->GetMapper());
  auto* m4 = vtkHAVSVolumeMapper::SafeDownCast(AddExactVolume(right, grid, property)->GetMapper());
  ViewBoxAlongZ(left, 0.5);
  ViewBoxAlongZ(right, 0.5);
  right->GetActiveCamera()->SetParallelScale(1.2);
  split->Render();
  const std::vector<float> r3 = havstest::FloatResult(m3);
  const std::vector<float> r4 = havstest::FloatResult(m4);
  havstest::Check(r3.size() == 64 * 64 * 4 && r4.size() == 64 * 64 * 4, "viewport-sized results");
  if (r3.size() == 64 * 64 * 4 && r4.size() == 64 * 64 * 4)
  {
    std::cout << "viewports: centre alpha " << PixelAlpha(r3, 64, 32, 32) << ", "
              << PixelAlpha(r4, 64, 32, 32) << std::endl;
    havstest::Check(std::fabs(PixelAlpha(r3, 64, 32, 32) - expected) < 1e-3 &&
        std::fabs(PixelAlpha(r4, 64, 32, 32) - expected) < 1e-3,
      "each viewport gets the closed form");
    std::vector<float> window3 = havstest::ReadRGBA(split);
    // The right viewport's box is smaller on screen (scale 1.2): at 75 % of its
    // width from the left edge of the window, x maps outside [0,1] there.
    havstest::Check(std::fabs(window3[4 * (32 * 128 + 32) + 3] - expected) < 2.0 / 255 &&
        std::fabs(window3[4 * (32 * 128 + 96) + 3] - expected) < 2.0 / 255,
      "both viewports composited into their place in the window");
  }
}

void TestOpaqueGeometry()
{
  // Constant slab [0,1]^3 seen from +z; an opaque plane at z = 0.5 covers x < 0.5.
  auto grid = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.5, 0.0);
  auto property = havstest::MakeConstantProperty(kColor[0], kColor[1], kColor[2], 0.5, 0.5);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  mapper->SetEarlyRayTerminationOpacity(1.0);
  auto scene = havstest::MakeScene(grid, mapper, property, 64, 64);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.5, -0.5, 0.5);
  plane->SetPoint1(0.5, -0.5, 0.5);
  plane->SetPoint2(-0.5, 1.5, 0.5);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> planeActor;
  planeActor->SetMapper(planeMapper);
  planeActor->GetProperty()->SetColor(1.0, 1.0, 0.0);
  planeActor->GetProperty()->SetAmbient(1.0);
  planeActor->GetProperty()->SetDiffuse(0.0);
  scene.Renderer->AddActor(planeActor);
  ViewBoxAlongZ(scene.Renderer, 0.5);
  scene.Window->Render();
  const std::vector<float> result = havstest::FloatResult(mapper);
  // Pixel columns: x = 0.25 (plane, half the slab in front), x = 0.75 (full slab).
  const auto column = [](double x) { return static_cast<int>((x + 0.3) / 1.6 * 64); };
  const float cut = PixelAlpha(result, 64, column(0.25), 32);
  const float full = PixelAlpha(result, 64, column(0.75), 32);
  const float expectedCut = static_cast<float>(1.0 - std::exp(-0.5));
  const float expectedFull = static_cast<float>(1.0 - std::exp(-1.0));
  std::cout << "opaque plane: alpha in front of it " << cut << " (expected " << expectedCut
            << "), beside it " << full << " (expected " << expectedFull << ")" << std::endl;
  havstest::Check(std::fabs(cut - expectedCut) < 1e-3, "the ray ends at the opaque surface");
  havstest::Check(std::fabs(full - expectedFull) < 1e-3, "beside it the full slab");
  // The window: the plane's yellow seen through the volume.
  std::vector<float> rgba = havstest::ReadRGBA(scene.Window);
  const float* p = &rgba[4 * (32 * 64 + column(0.25))];
  const double red = kColor[0] * expectedCut + (1.0 - expectedCut) * 1.0;
  havstest::Check(std::fabs(p[0] - red) < 2.0 / 255, "the volume is composited over the plane");
}

void TestExtremumBlend()
{
  // s = z over [0, 1]: the maximum along every ray through the box is 1, the minimum 0.
  auto grid = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
  auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.3);
  // Opaque enough at both ends that neither answer is zero.
  property->GetScalarOpacity()->RemoveAllPoints();
  property->GetScalarOpacity()->AddPoint(0.0, 0.3);
  property->GetScalarOpacity()->AddPoint(1.0, 0.8);
  float centreAlpha[2] = { -1.0f, -1.0f };
  std::vector<float> untaggedMinimum;
  for (int run = 0; run < 3; ++run)
  {
    // Run 2: the minimum with boundary tagging forced on (the boundary faces
    // are then drawn with vertices of their own, scalar + 2: the extremum pass
    // must read the scalar through that; the minimum 0 lies on a boundary face).
    const int minimum = run > 0 ? 1 : 0;
    vtkNew<vtkHAVSVolumeMapper> mapper;
    mapper->KeepFloatResultOn();
    if (run == 2)
    {
      mapper->SetBoundaryModeToTagging();
    }
    if (minimum)
    {
      mapper->SetBlendModeToMinimumIntensity();
    }
    else
    {
      mapper->SetBlendModeToMaximumIntensity();
    }
    auto scene = havstest::MakeScene(grid, mapper, property, 48, 48);
    ViewBoxAlongZ(scene.Renderer, 0.5);
    scene.Window->Render();
    const std::vector<float> result = havstest::FloatResult(mapper);
    const double s = minimum ? 0.0 : 1.0;
    double rgb[3];
    property->GetRGBTransferFunction()->GetColor(s, rgb);
    const double a = property->GetScalarOpacity()->GetValue(s);
    const float* p = &result[4 * (24 * 48 + 24)];
    std::cout << (minimum ? "minimum" : "maximum") << (run == 2 ? " (tagged)" : "")
              << " intensity: " << p[0] << " " << p[1] << " " << p[2] << " " << p[3]
              << " (expected " << rgb[0] * a << " " << rgb[1] * a << " " << rgb[2] * a << " " << a
              << ")" << std::endl;
    havstest::Check(
      std::fabs(p[3] - a) < 1e-2 && std::fabs(p[0] - rgb[0] * a) < 1e-2, "extremum blend colour");
    havstest::Check(mapper->GetActiveKBufferSize() == 0, "extremum blend needs no k-buffer");
    if (run == 1)
    {
      untaggedMinimum = result;
    }
    else if (run == 2)
    {
      double worst = 0.0;
      for (size_t i = 0; i < result.size() && result.size() == untaggedMinimum.size(); ++i)
      {
        worst = std::max(worst, std::fabs(double(result[i]) - untaggedMinimum[i]));
      }
      std::cout << "minimum with tagging against without: max difference " << worst << std::endl;
      havstest::Check(mapper->GetLastFrameStatistics()->GetTagging() &&
          result.size() == untaggedMinimum.size() && worst < 2e-3,
        "extremum blend with the tagged boundary vertices: the same image");
    }
    centreAlpha[minimum] = p[3];
  }
  havstest::Check(std::fabs(centreAlpha[0] - centreAlpha[1]) > 0.4,
    "maximum and minimum intensity differ (0.8 against 0.3)");
}
}

/// What the last frame did again, as one line: table built, uploads of
/// geometry, scalars, order and table, order reused (1 or 0 each).
std::string WorkDone(vtkHAVSVolumeMapper* mapper)
{
  vtkHAVSFrameStatistics* s = mapper->GetLastFrameStatistics();
  std::string line;
  for (bool b : { s->GetTableRebuilt(), s->GetGeometryUploaded(), s->GetScalarsUploaded(),
         s->GetOrderUploaded(), s->GetTableUploaded(), s->GetOrderReused() })
  {
    line += b ? '1' : '0';
  }
  return line;
}

void TestUnchangedWork()
{
  auto grid = vtkHAVSDataSets::MakeBox(5, 5, 5, 0.2, 0.0, 1.0);
  auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.3);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  auto scene = havstest::MakeScene(grid, mapper, property, 48, 48);
  havstest::PlaceCamera(scene.Renderer, 30, 20, false);
  // Each step: what changed, and the expected line (table built, geometry,
  // scalars, order, table uploaded, order reused).
  auto step = [&](const std::string& what, const std::string& expected)
  {
    scene.Window->Render();
    const std::string done = WorkDone(mapper);
    std::cout << "unchanged work, " << what << ": " << done << " (expected " << expected << ")"
              << std::endl;
    havstest::Check(done == expected, "unchanged work: " + what);
  };
  step("first frame", "110110");
  step("the same frame again", "000001");
  const std::vector<float> before = havstest::FloatResult(mapper);
  property->GetScalarOpacity()->AddPoint(0.5, 0.05);
  step("a transfer-function edit", "100011");
  const auto d = havstest::Compare(before, havstest::FloatResult(mapper));
  havstest::Check(d.Max > 0.01, "a transfer-function edit changes the image at once");
  step("the same frame after the edit", "000001");
  scene.Renderer->GetActiveCamera()->Azimuth(25.0);
  scene.Renderer->ResetCameraClippingRange();
  step("a camera move", "000100");
  auto next = vtkSmartPointer<vtkUnstructuredGrid>::New();
  next->DeepCopy(grid);
  vtkDataArray* values = next->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    values->SetComponent(i, 0, 1.0 - values->GetComponent(i, 0));
  }
  mapper->SetInputData(next);
  step("a new time step on the same mesh", "001101");
}

int TestHAVSScenes(int, char*[])
{
  TestUnchangedWork();
  TestVolumeMatrix();
  TestResizeReleaseAndTwoWindows();
  TestTwoVolumesAndViewports();
  TestOpaqueGeometry();
  TestExtremumBlend();
  return havstest::Result();
}
