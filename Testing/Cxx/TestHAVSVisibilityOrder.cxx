/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSVisibilityOrder.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSVisibilityOrder (MPVO): on a convex mesh of thin, anisotropic
// tetrahedra, the MPVO face order lets every pixel's fragments leave a
// k-buffer in depth order with k <= 2 (k analysis of the exact reference's
// fragments), for perspective and parallel views; the centroid order of the
// same faces needs more (negative control); a cycle-free convex mesh needs
// no cycle breaks. On the GPU, vtkHAVSVolumeMapper with SetVisibilityOrderToMPVO
// at k = 1 matches the exact reference; the centroid order at k = 1 does not.
// The order keeps no face planes: a face set built again after its Build()
// gives no order and an error, until the order is built again (with
// progress from 0 to 1).
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestScenes.h"

#include "vtkCamera.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSSoftwareKBuffer.h"
#include "vtkHAVSVisibilityOrder.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> ThinCells()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(12, 10, 8);
  image->SetSpacing(1.0, 0.15, 0.04); // long, flat cells: centroids far from the hit points
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    image->GetPoint(p, x);
    s->InsertNextValue(x[0] + 3 * x[2]);
  }
  image->GetPointData()->SetScalars(s);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(image);
  tets->Update();
  return tets->GetOutput();
}

int MaximumRequiredK(
  vtkUnstructuredGrid* grid, vtkCamera* camera, const std::vector<uint32_t>& order)
{
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetCamera(camera);
  reference->SetSize(96, 96);
  reference->ComputeFragments();
  vtkNew<vtkHAVSSoftwareKBuffer> software;
  software->SetFaceOrder(order);
  vtkNew<vtkIntArray> requiredK;
  software->Analyze(reference, requiredK, nullptr);
  return software->GetMaximumRequiredK();
}
}

int TestHAVSVisibilityOrder(int, char*[])
{
  auto grid = ThinCells();
  vtkNew<vtkHAVSFaceSet> faces;
  havstest::Check(faces->Build(grid), "face set");
  vtkNew<vtkHAVSVisibilityOrder> mpvo;
  havstest::Check(mpvo->Build(faces, grid), "MPVO adjacency");
  vtkNew<vtkHAVSFaceSorter> centroid;
  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  double bounds[6];
  grid->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double views[3][3] = { { 0.3, -1.0, 0.8 }, { -0.7, 0.4, 1.0 }, { 0.2, 0.3, -1.0 } };
  int worstCentroid = 0;
  for (int parallel = 0; parallel <= 1; ++parallel)
  {
    for (const auto& v : views)
    {
      vtkNew<vtkCamera> camera;
      camera->SetFocalPoint(centre);
      camera->SetPosition(centre[0] + 14 * v[0], centre[1] + 14 * v[1], centre[2] + 14 * v[2]);
      camera->SetViewUp(0, 0, 1);
      camera->SetParallelProjection(parallel);
      camera->SetParallelScale(7.0);
      camera->SetViewAngle(50.0);
      camera->SetClippingRange(1.0, 40.0);
      double eye[3], direction[3];
      camera->GetPosition(eye);
      camera->GetDirectionOfProjection(direction);
      mpvo->Sort(eye, direction, parallel != 0);
      havstest::Check(mpvo->GetOrder().size() == static_cast<size_t>(faces->GetNumberOfFaces()),
        "MPVO orders every face once");
      havstest::Check(mpvo->GetNumberOfCycleBreaks() == 0, "no cycle in a convex grid");
      centroid->Invalidate();
      centroid->Sort(faces, identity, eye, direction, parallel != 0);
      const int kMPVO = MaximumRequiredK(grid, camera, mpvo->GetOrder());
      const int kCentroid = MaximumRequiredK(grid, camera, centroid->GetOrder());
      worstCentroid = std::max(worstCentroid, kCentroid);
      std::printf(
        "%s view (%g, %g, %g): max required k: MPVO %d, centroid %d (MPVO sort %.2f ms)\n",
        parallel ? "parallel" : "perspective", v[0], v[1], v[2], kMPVO, kCentroid,
        1000.0 * mpvo->GetLastSortSeconds());
      havstest::Check(kMPVO <= 2, "MPVO: k <= 2 suffices");
    }
  }
  havstest::Check(worstCentroid > 2, "negative control: the centroid order needs k > 2");

  // The planes are made from the face set's vertices: a face set built again
  // (even on the same grid) is refused until the order is built again.
  {
    const double eye[3] = { centre[0] + 3, centre[1] - 12, centre[2] + 9 };
    const double direction[3] = { -3, 12, -9 };
    mpvo->Sort(eye, direction, false);
    const std::vector<uint32_t> before = mpvo->GetOrder();
    havstest::Messages* messages = havstest::CountMessages(mpvo);
    faces->Build(grid);
    mpvo->Sort(eye, direction, false);
    havstest::Check(mpvo->GetOrder().empty() && messages->Errors == 1,
      "a face set built again: no order, one error");
    std::vector<double> progress;
    havstest::Check(
      mpvo->Build(faces, grid, [&](double p) { progress.push_back(p); }), "built again");
    mpvo->Sort(eye, direction, false);
    havstest::Check(mpvo->GetOrder() == before && messages->Errors == 1,
      "built again: the same order as before, no error");
    havstest::Check(progress.size() >= 3 && progress.front() == 0.0 && progress.back() == 1.0 &&
        std::is_sorted(progress.begin(), progress.end()),
      "Build reports progress from 0 to 1");
  }

  // The mapper at k = 1: MPVO against the centroid order.
  auto property = havstest::MakeRampPropertyFor(grid);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  mapper->SetEarlyRayTerminationOpacity(1.0);
  mapper->SetKBufferSize(1);
  auto scene = havstest::MakeScene(grid, mapper, property, 96, 96);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] - 9.8, centre[1] + 5.6, centre[2] + 14.0);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(50.0);
  camera->SetClippingRange(1.0, 40.0);
  mapper->SetVisibilityOrderToMPVO();
  scene.Window->Render();
  const auto mpvoImage = havstest::FloatResult(mapper);
  havstest::Check(
    mapper->GetLastFrameStatistics()->GetCycleBreaks() == 0, "mapper: no cycle breaks");
  mapper->SetVisibilityOrderToCentroid();
  scene.Window->Render();
  const auto centroidImage = havstest::FloatResult(mapper);
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(96, 96);
  reference->Render();
  vtkFloatArray* exactImage = reference->GetImage();
  const std::vector<float> exact(
    exactImage->GetPointer(0), exactImage->GetPointer(0) + 4 * 96 * 96);
  const auto a = havstest::Compare(mpvoImage, exact);
  const auto b = havstest::Compare(centroidImage, exact);
  std::printf("k = 1, MPVO vs reference: RMSE %.6f, max %.4f; centroid: RMSE %.6f, max %.4f\n",
    a.RMSE, a.Max, b.RMSE, b.Max);
  havstest::Check(a.RMSE < 1e-3 && a.FractionOver1 < 0.01, "MPVO at k = 1 matches the reference");
  havstest::Check(
    b.RMSE > 5 * a.RMSE && b.Max > 0.02, "negative control: the centroid order at k = 1 does not");
  return havstest::Result();
}
