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
//
// Usage: TestHAVSCellProjection <scene> [size] [views]
#include "havsTestChecks.h"
#include "havsTestImages.h"
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

/// The exact image (clipped by `planes`, cut at the window depth `depth`, when given).
std::vector<float> Reference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkCamera* camera, int size, vtkPlaneCollection* planes = nullptr, vtkFloatArray* depth = nullptr)
{
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(size, size);
  reference->SetClippingPlanes(planes);
  reference->SetOpaqueDepth(depth);
  reference->Render();
  vtkFloatArray* image = reference->GetImage();
  return std::vector<float>(image->GetPointer(0), image->GetPointer(0) + 4 * size * size);
}

void Print(const std::string& what, const havstest::ImageDifference& d)
{
  std::printf("  %-58s RMSE %.6f  max %.6f  px > 1/255 %.3f %%\n", what.c_str(), d.RMSE, d.Max,
    100.0 * d.FractionOver1);
}

/// Clipping planes (one, then two; perspective and parallel) on the hollow
/// sphere, against the reference clipped alike; control: the mapper without
/// the planes against the clipped reference.
int ClipScene(int size)
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  auto property = havstest::MakeRampPropertyFor(grid);
  vtkNew<vtkHAVSCellProjectionMapper> mapper;
  mapper->KeepFloatResultOn();
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  double bounds[6], centre[3];
  grid->GetBounds(bounds);
  grid->GetCenter(centre);
  vtkNew<vtkPlane> first, second;
  first->SetOrigin(centre[0] + 0.1 * (bounds[1] - bounds[0]), centre[1], centre[2]);
  first->SetNormal(-0.8, 0.2, 0.3);
  second->SetOrigin(centre);
  second->SetNormal(0.1, -0.3, 1.0);
  const size_t edgePixels = static_cast<size_t>(size) * size / 2000;
  for (int n = 1; n <= 2; ++n)
  {
    vtkNew<vtkPlaneCollection> planes;
    planes->AddItem(first);
    if (n == 2)
    {
      planes->AddItem(second);
    }
    for (bool parallel : { false, true })
    {
      havstest::PlaceCamera(s.Renderer, 30.0, 20.0, parallel);
      mapper->SetClippingPlanes(planes);
      s.Window->Render();
      const auto clipped = havstest::FloatResult(mapper);
      const auto exact = Reference(grid, property, s.Renderer->GetActiveCamera(), size, planes);
      // (Not RemoveAllClippingPlanes: that would empty `planes` itself.)
      mapper->SetClippingPlanes(static_cast<vtkPlaneCollection*>(nullptr));
      s.Window->Render();
      const auto whole = havstest::FloatResult(mapper);
      const std::string name = std::to_string(n) + (n == 1 ? " plane, " : " planes, ") +
        (parallel ? "parallel" : "perspective");
      const auto d = havstest::Compare(clipped, exact, edgePixels);
      const auto control = havstest::Compare(whole, exact, edgePixels);
      Print("clipping, " + name, d);
      Print("clipping, " + name + ": control, without the planes", control);
      havstest::Check(d.RMSE < 5e-4 && d.Max < 0.01, "clipping, " + name + ": exact");
      havstest::Check(control.Max > 0.05, "clipping, " + name + ": control, the planes matter");
    }
  }
  return havstest::Result();
}

/// An opaque sphere inside a box: the rays end at its surface, the last
/// segment cut (against the reference cut at the window's depth); control:
/// the reference through the surface.
int OpaqueScene(int size)
{
  auto grid = vtkHAVSDataSets::MakeBox(10, 10, 10, 0.1, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(grid);
  vtkNew<vtkHAVSCellProjectionMapper> mapper;
  mapper->KeepFloatResultOn();
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  havstest::AddOpaqueSphere(s.Renderer);
  havstest::PlaceCamera(s.Renderer, 25.0, 15.0, false);
  s.Window->Render();
  const auto image = havstest::FloatResult(mapper);
  vtkNew<vtkFloatArray> depth;
  s.Window->GetZbufferData(0, 0, size - 1, size - 1, depth);
  const auto exact = Reference(grid, property, s.Renderer->GetActiveCamera(), size, nullptr, depth);
  const auto d = havstest::Compare(image, exact, static_cast<size_t>(size) * size / 2000);
  const auto control =
    havstest::Compare(Reference(grid, property, s.Renderer->GetActiveCamera(), size), exact);
  Print("opaque sphere: vs the reference cut at the surface", d);
  Print("opaque sphere: control, the reference through it", control);
  havstest::Check(d.RMSE < 5e-4 && d.Max < 0.01, "opaque sphere: the rays end at its surface");
  havstest::Check(control.RMSE > 10.0 * d.RMSE && control.Max > 0.05,
    "opaque sphere: negative control, the surface matters");
  return havstest::Result();
}
}

int TestHAVSCellProjection(int argc, char* argv[])
{
  const std::string scene = argc > 1 ? argv[1] : "hollowsphere";
  const int size = argc > 2 ? std::atoi(argv[2]) : 128;
  const int views = argc > 3 ? std::atoi(argv[3]) : 6;
  if (scene == "opaque")
  {
    return OpaqueScene(size);
  }
  if (scene == "clip")
  {
    return ClipScene(size);
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
    vtkHAVSStandardViews::PlaceCamera(camera, grid, parallel ? 3 : v);
    camera->SetParallelProjection(parallel ? 1 : 0);
    if (turned)
    {
      camera->Azimuth(7.0);
      camera->Elevation(5.0);
      camera->OrthogonalizeViewUp();
    }
    s.Renderer->ResetCameraClippingRange();
    if (parallel)
    {
      camera->Azimuth(11.0);
      camera->Elevation(7.0);
      camera->OrthogonalizeViewUp();
      s.Renderer->ResetCamera();
      s.Renderer->ResetCameraClippingRange();
    }
    const std::string name = "view " + std::to_string(v) + (parallel ? " (parallel)" : "");
    const auto exact = Reference(grid, property, camera, size);
    for (int method : methods)
    {
      mapper->SetCellOrderToMPVO();
      mapper->SetNonConvexMethod(method);
      s.Window->Render();
      const auto d = havstest::Compare(havstest::FloatResult(mapper), exact, edgePixels);
      cycleBreaks += mapper->GetLastCycleBreaks();
      Print(name +
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
      const auto denseExact = Reference(grid, dense, camera, size);
      s.Window->Render();
      const auto denseMPVO =
        havstest::Compare(havstest::FloatResult(mapper), denseExact, edgePixels);
      Print(name + ": denser medium, MPVO", denseMPVO);
      havstest::Check(bound.Exact(denseMPVO), name + ": denser medium, MPVO exact");
      mapper->SetCellOrderToCentroid();
      s.Window->Render();
      const auto centroid =
        havstest::Compare(havstest::FloatResult(mapper), denseExact, edgePixels);
      Print(name + ": control, denser medium, centroid cell order", centroid);
      centroidFailed += bound.Exact(centroid) ? 0 : 1;
      mapper->SetCellOrderToMPVO();
      mapper->SetReverseOrderForTesting(true);
      s.Window->Render();
      const auto reversed =
        havstest::Compare(havstest::FloatResult(mapper), denseExact, edgePixels);
      Print(name + ": control, denser medium, MPVO reversed", reversed);
      reversedFailed += bound.Exact(reversed) ? 0 : 1;
      mapper->SetReverseOrderForTesting(false);
      s.Volume->SetProperty(property);
      mapper->SetCellOrderToMPVO();
      mapper->SetWrongExitForTesting(true);
      s.Window->Render();
      const auto wrong = havstest::Compare(havstest::FloatResult(mapper), exact, edgePixels);
      Print(name + ": control, the farthest exit plane", wrong);
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
  const auto d = havstest::Compare(
    havstest::FloatResult(mapper), Reference(movedGrid, property, camera, size), edgePixels);
  Print("volume matrix (rotated, stretched) vs the transformed grid", d);
  havstest::Check(bound.Exact(d), "the volume's matrix: exact");
  return havstest::Result();
}
