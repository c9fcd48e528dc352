/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSExactOrder.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Exact visibility orders on real and non-convex meshes (issue 8).
//
// Usage: TestHAVSExactOrder <scene> [size]
//   scenes: bluntfin, loxpost (PLOT3D, tetrahedralized), combustor: 14 views
//           (the 6 axis directions and the 8 cube diagonals, perspective);
//           wavelet, hollowsphere, twoblocks, torus (non-convex): the same
//           views turned by a few degrees (see below);
//           cycle: three sticks in cyclic overlap (a visibility cycle), see CycleScene.
//
// Per view, the exact reference's fragments (vtkHAVSReferenceRenderer) run
// through the software k-buffer in each draw order (k analysis): the centroid
// sort, MPVO alone, MPVO with the convexification, MPVO with the boundary
// layers. On the GPU (vtkHAVSVolumeMapper, k = 2, framebuffer fetch) each
// order's image against the exact one, and its order-violation count.
// Required, for both non-convex methods on the test meshes and for the
// boundary layers (the default) on the data sets: every pixel needs k <= 2,
// no order violation at k = 2, the image within the first-light bounds (RMSE
// < 0.0005, max < 0.01, leaving out up to 0.05 % of the pixels: centres on a
// face edge, covered differently by rasterizer and rays whatever the order).
// Pixels whose exact ray passes through a folded cell (an inverted cell and
// the one it overlaps: the combustor has some) have no exact order: they are
// left out and counted, and the logged violations must lie next to them.
// Negative controls that must fail: on the real data sets the centroid order
// at k = 2; on the non-convex test meshes MPVO alone. Automatic must take MPVO
// in every view where the centroid order overflowed, and be exact.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSSoftwareKBuffer.h"
#include "vtkHAVSVisibilityOrder.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
// The 14 views: azimuth and elevation (degrees) of the 6 axis directions and
// the 8 cube diagonals, seen from the grid's centre.
const double kViews[14][2] = { { 0, 0 }, { 90, 0 }, { 180, 0 }, { 270, 0 }, { 0, 89.9 },
  { 0, -89.9 }, { 45, 35.26 }, { 135, 35.26 }, { 225, 35.26 }, { 315, 35.26 }, { 45, -35.26 },
  { 135, -35.26 }, { 225, -35.26 }, { 315, -35.26 } };

/// A visibility cycle by construction: three long thin tetrahedra ("sticks",
/// 2.4 long) along the sides of a triangle, each rising from z = -0.18 to
/// +0.18 so that at one crossing it lies above its neighbour and at the other
/// below the other one: seen from +z, 0 hides 1, 1 hides 2, 2 hides 0, with
/// no order of the three cells right everywhere.
vtkSmartPointer<vtkUnstructuredGrid> ThreeSticks()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  // One stick in its own frame: an edge across it at the low end, an upright
  // edge at the high end (the tetrahedron twists between them).
  const double stick[4][3] = { { -1.2, -0.12, -0.18 }, { -1.2, 0.12, -0.18 }, { 1.2, 0.0, 0.13 },
    { 1.2, 0.0, 0.23 } };
  for (int i = 0; i < 3; ++i)
  {
    const double a = i * 2.0 * M_PI / 3.0;
    vtkIdType ids[4];
    for (int v = 0; v < 4; ++v)
    {
      const double x = stick[v][0], y = stick[v][1] - 0.35; // on the line y = -0.35
      ids[v] = points->InsertNextPoint(
        std::cos(a) * x - std::sin(a) * y, std::sin(a) * x + std::cos(a) * y, stick[v][2]);
      s->InsertNextValue(v < 2 ? 0.2 : 1.0);
    }
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(s);
  return grid;
}

/// The cycle scene: detected by both non-convex methods (the sort stalls,
/// cycle breaks counted and reported by the mapper), and rendered exactly by
/// a k-buffer as deep as the k analysis says the broken order needs; at k = 1
/// the order violations show that the image is not exact (negative control).
int CycleScene(int size)
{
  auto grid = ThreeSticks();
  auto property = havstest::MakeRampProperty(0.0, 1.0, 1.0, 0.08);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->CountOrderViolationsOn();
  mapper->KeepFloatResultOn();
  mapper->SetEarlyRayTerminationOpacity(1.0);
  mapper->SetKBufferPathToFramebufferFetch();
  mapper->SetVisibilityOrderToMPVO();
  auto view = havstest::MakeScene(grid, mapper, property, size, size);
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  havstest::PlaceCamera(view.Renderer, 0.0, 0.0, false); // from +z: above

  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(size, size);
  havstest::Check(reference->ComputeFragments(), "reference fragments");
  reference->Render();
  vtkFloatArray* exactImage = reference->GetImage();
  const std::vector<float> exact(
    exactImage->GetPointer(0), exactImage->GetPointer(0) + 4 * size * size);
  double eye[3], dop[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(dop);
  vtkNew<vtkMatrix4x4> toClip;
  toClip->DeepCopy(camera->GetCompositeProjectionTransformMatrix(1.0, -1, 1));
  vtkNew<vtkHAVSSoftwareKBuffer> analysis;
  vtkNew<vtkIntArray> requiredK;
  const int methods[2] = { vtkHAVSVisibilityOrder::NonConvexConvexification,
    vtkHAVSVisibilityOrder::NonConvexBoundaryLayers };
  const char* names[2] = { "convexification", "boundary layers" };
  std::printf("three sticks: %lld tetrahedra, %d^2, seen from above\n",
    static_cast<long long>(grid->GetNumberOfCells()), size);
  for (int m = 0; m < 2; ++m)
  {
    vtkNew<vtkHAVSVisibilityOrder> order;
    order->SetNonConvexMethod(methods[m]);
    havstest::Check(order->Build(reference->GetFaceSet(), grid), "MPVO adjacency");
    order->SetViewSampling(toClip->GetData(), size, size);
    order->Sort(eye, dop, false);
    analysis->SetFaceOrder(order->GetOrder());
    analysis->Analyze(reference, requiredK, nullptr);
    const int needed = analysis->GetMaximumRequiredK();

    mapper->SetNonConvexMethod(methods[m]);
    mapper->SetKBufferSize(1);
    view.Window->Render();
    const auto k1 = havstest::Compare(havstest::FloatResult(mapper), exact);
    const vtkIdType k1Violations = mapper->GetLastOrderViolations();
    const vtkIdType reported = mapper->GetLastFrameStatistics()->GetCycleBreaks();
    mapper->SetKBufferSize(std::max(needed, 2));
    view.Window->Render();
    const auto kn = havstest::Compare(havstest::FloatResult(mapper), exact);
    const vtkIdType knViolations = mapper->GetLastOrderViolations();
    std::printf("MPVO + %s: %lld cycle breaks (mapper reports %lld); the broken order needs k = "
                "%d (%lld pixels k > 2)\n  k = 1: RMSE %.6f max %.4f, %lld order violations; "
                "k = %d: RMSE %.6f max %.4f, %lld order violations\n",
      names[m], static_cast<long long>(order->GetNumberOfCycleBreaks()),
      static_cast<long long>(reported), needed, static_cast<long long>(analysis->GetPixelsOverK2()),
      k1.RMSE, k1.Max, static_cast<long long>(k1Violations), std::max(needed, 2), kn.RMSE, kn.Max,
      static_cast<long long>(knViolations));
    const std::string what = std::string("cycle, ") + names[m] + ": ";
    havstest::Check(order->GetNumberOfCycleBreaks() > 0 && reported > 0,
      what + "the cycle is detected and reported");
    havstest::Check(needed <= 14, what + "the k-buffer can absorb the broken order (k <= 14)");
    havstest::Check(kn.RMSE < 0.0005 && kn.Max < 0.01 && knViolations == 0,
      what + "rendered exactly at that k (RMSE < 0.0005, max < 0.01), no order violation");
    havstest::Check(k1Violations > 0 && k1.Max > 0.01,
      what + "negative control: k = 1 is not exact (max > 0.01) and says so");
  }
  return havstest::Result();
}

/// Diagnostics: a pixel's exact fragments, each with its face's draw rank in
/// `order` and its tetrahedra.
void PrintPixel(vtkHAVSReferenceRenderer* reference, const std::vector<uint32_t>& order,
  vtkHAVSVisibilityOrder* mpvo, vtkIdType p)
{
  std::vector<uint32_t> rank(order.size());
  for (size_t i = 0; i < order.size(); ++i)
  {
    rank[order[i]] = static_cast<uint32_t>(i);
  }
  for (auto* f = reference->GetPixelFragmentsBegin(p); f != reference->GetPixelFragmentsEnd(p); ++f)
  {
    vtkIdType c[2];
    mpvo->GetFaceTetrahedra(f->Face, c);
    std::printf("   distance %.9f face %u%s drawn %u-th, tetrahedra %lld %lld\n", f->Distance,
      f->Face, f->Boundary ? (f->Exit ? " (exit)" : " (entry)") : "", rank[f->Face],
      static_cast<long long>(c[0]), static_cast<long long>(c[1]));
  }
}

struct OrderResult
{
  const char* Name;
  int MaxK = 0;
  long long PixelsOver2 = 0;
  long long Violations = 0;
  double WorstRMSE = 0.0, WorstMax = 0.0, WorstOver1 = 0.0;
  int ViewsMissingBounds = 0;
  double SortSeconds = 0.0;
  long long UnexplainedViolations = 0; // neither next to folded cells nor rasterization
  long long RasterViolations = 0;      // at pixels whose exact fragments arrive in order
};

}

int TestHAVSExactOrder(int argc, char* argv[])
{
  const std::string scene = argc > 1 ? argv[1] : "wavelet";
  const int size = argc > 2 ? std::atoi(argv[2]) : 128;
  // Views: all 14, or (third argument) that many spread over them: the
  // default suite's data-set cases take 5, their `.full` variants (long) 14.
  const int numberOfViews = argc > 3 ? std::max(1, std::min(14, std::atoi(argv[3]))) : 14;
  std::vector<bool> viewUsed(14, false);
  for (int i = 0; i < numberOfViews; ++i)
  {
    viewUsed[i * 14 / numberOfViews] = true;
  }
  if (scene == "cycle")
  {
    return CycleScene(size);
  }
  auto grid = vtkHAVSDataSets::Load(scene);
  if (!havstest::Check(grid && grid->GetNumberOfCells() > 0, "scene " + scene + " loads"))
  {
    return EXIT_FAILURE;
  }
  std::printf("%s: %lld tetrahedra, %d^2, %d of the 14 views\n", scene.c_str(),
    static_cast<long long>(grid->GetNumberOfCells()), size, numberOfViews);
  auto property = havstest::MakeRampPropertyFor(grid);
  const bool synthetic =
    scene == "wavelet" || scene == "hollowsphere" || scene == "twoblocks" || scene == "torus";
  // Meshes with face planes through their centre (the test meshes' voxel
  // grids; the LOX post's O-grid, symmetric about its axis planes): from
  // exactly the axis views the eye lies in such planes, and a whole line of
  // pixel rays grazes faces (rasterizer and rays then disagree along it,
  // whatever the order). They are seen turned by 7 and 5 degrees.
  const bool turned = synthetic || scene == "loxpost";
  // Pixels whose centre lies on a face edge within the rasterizer's sub-pixel
  // precision are covered differently by the GPU and by the exact rays (not an
  // order effect: the centroid order shows the same ones); up to 0.05 % of the
  // pixels (8 at 128^2) are left out of the image comparison.
  const size_t edgePixels = static_cast<size_t>(size) * size / 2000;

  // GPU scene (k = 2, framebuffer fetch; every fragment composited: no early termination).
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->CountOrderViolationsOn();
  mapper->KeepFloatResultOn();
  mapper->SetEarlyRayTerminationOpacity(1.0);
  mapper->SetKBufferSize(2);
  mapper->SetKBufferPathToFramebufferFetch();
  auto view = havstest::MakeScene(grid, mapper, property, size, size);
  vtkCamera* camera = view.Renderer->GetActiveCamera();

  // The software orders and the reference share the camera.
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(size, size);
  vtkNew<vtkHAVSFaceSorter> centroid;
  vtkNew<vtkHAVSVisibilityOrder> alone, convexified, layered;
  alone->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexIgnore);
  convexified->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexConvexification);
  layered->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexBoundaryLayers);
  vtkHAVSVisibilityOrder* mpvo[3] = { alone, convexified, layered };
  const int mapperMethods[3] = { vtkHAVSVisibilityOrder::NonConvexIgnore,
    vtkHAVSVisibilityOrder::NonConvexConvexification,
    vtkHAVSVisibilityOrder::NonConvexBoundaryLayers };
  vtkNew<vtkHAVSSoftwareKBuffer> analysis;
  vtkNew<vtkIntArray> requiredK;

  OrderResult results[4] = { { "centroid" }, { "MPVO alone" }, { "MPVO + convexification" },
    { "MPVO + boundary layers" } };
  vtkIdType cycleBreaks[4] = { 0, 0, 0, 0 };
  vtkIdType foldedPixels = 0;
  std::vector<uint8_t> foldedCell; // per tetrahedron: has a folded face
  int automaticWrong = 0, automaticMPVO = 0, automaticViolations = 0;
  // Diagnostics: HAVS_DEBUG_ORDER=1 prints the exact fragments of pixels that
  // need k > 2 or had an order violation; HAVS_ONLY_VIEW=n runs view n alone.
  const bool debug = std::getenv("HAVS_DEBUG_ORDER") != nullptr;
  const int onlyView =
    std::getenv("HAVS_ONLY_VIEW") ? std::atoi(std::getenv("HAVS_ONLY_VIEW")) : -1;
  for (int v = 0; v < 14; ++v)
  {
    if ((onlyView >= 0 && v != onlyView) || (onlyView < 0 && !viewUsed[v]))
      continue;
    const double tilt = turned ? 1.0 : 0.0;
    havstest::PlaceCamera(view.Renderer, kViews[v][0] + 7.0 * tilt,
      kViews[v][1] + (kViews[v][1] > 80.0 ? -5.0 : 5.0) * tilt, false);
    if (!reference->ComputeFragments())
    {
      havstest::Check(false, "reference fragments");
      return EXIT_FAILURE;
    }
    vtkHAVSFaceSet* faces = reference->GetFaceSet();
    double eye[3], dop[3];
    camera->GetPosition(eye);
    camera->GetDirectionOfProjection(dop);
    vtkNew<vtkMatrix4x4> toClip;
    toClip->DeepCopy(camera->GetCompositeProjectionTransformMatrix(1.0, -1, 1));
    const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    centroid->Invalidate();
    centroid->Sort(faces, identity, eye, dop, false);
    results[0].SortSeconds += centroid->GetLastSortSeconds();
    const std::vector<uint32_t>* orders[4] = { &centroid->GetOrder(), nullptr, nullptr, nullptr };
    std::vector<int> pixelK[4]; // required k per pixel, per order
    for (int m = 0; m < 3; ++m)
    {
      if (v == std::max(onlyView, 0))
      {
        havstest::Check(mpvo[m]->Build(faces, grid), "MPVO adjacency");
      }
      mpvo[m]->SetViewSampling(toClip->GetData(), size, size);
      mpvo[m]->Sort(eye, dop, false);
      cycleBreaks[m + 1] += mpvo[m]->GetNumberOfCycleBreaks();
      results[m + 1].SortSeconds += mpvo[m]->GetLastSortSeconds();
      orders[m + 1] = &mpvo[m]->GetOrder();
    }
    // Pixels whose exact ray passes through a folded cell (one of the two
    // tetrahedra of a folded face: an inverted cell and the cell it overlaps)
    // have no exact order; they are left out and counted.
    if (foldedCell.empty())
    {
      foldedCell.assign(static_cast<size_t>(grid->GetNumberOfCells()), 0);
      for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
      {
        if (layered->IsFaceFolded(f))
        {
          vtkIdType c[2];
          layered->GetFaceTetrahedra(f, c);
          foldedCell[c[0]] = foldedCell[c[1]] = 1;
        }
      }
    }
    std::vector<uint8_t> foldedPixel(static_cast<size_t>(size) * size, 0);
    for (vtkIdType p = 0; p < static_cast<vtkIdType>(size) * size; ++p)
    {
      for (auto* f = reference->GetPixelFragmentsBegin(p); f != reference->GetPixelFragmentsEnd(p);
           ++f)
      {
        vtkIdType c[2];
        layered->GetFaceTetrahedra(f->Face, c);
        foldedPixel[p] |= (foldedCell[c[0]] || (c[1] >= 0 && foldedCell[c[1]])) ? 1 : 0;
      }
      foldedPixels += foldedPixel[p];
    }
    for (int o = 0; o < 4; ++o)
    {
      analysis->SetFaceOrder(*orders[o]);
      analysis->Analyze(reference, requiredK, nullptr);
      pixelK[o].assign(requiredK->GetPointer(0), requiredK->GetPointer(0) + size * size);
      int maxK = 0;
      vtkIdType over2 = 0;
      for (vtkIdType p = 0; p < requiredK->GetNumberOfTuples(); ++p)
      {
        if (!foldedPixel[p])
        {
          maxK = std::max(maxK, requiredK->GetValue(p));
          over2 += requiredK->GetValue(p) > 2 ? 1 : 0;
        }
      }
      results[o].MaxK = std::max(results[o].MaxK, maxK);
      results[o].PixelsOver2 += over2;
      if (o > 1 && maxK > 2 && debug)
      {
        int shown = 0;
        for (vtkIdType p = 0; p < size * size && shown < 4; ++p)
        {
          if (requiredK->GetValue(p) > 2)
          {
            std::printf("view %d, %s: pixel (%d, %d) needs k = %d:\n", v, results[o].Name,
              static_cast<int>(p % size), static_cast<int>(p / size), requiredK->GetValue(p));
            PrintPixel(reference, *orders[o], mpvo[o - 1], p);
            ++shown;
          }
        }
      }
      if (o > 1 && maxK > 2)
      {
        std::printf("  view %d (%s): max k %d, %lld pixels k > 2\n", v, results[o].Name, maxK,
          static_cast<long long>(over2));
      }
    }

    // GPU, k = 2, against the exact image.
    reference->Render();
    vtkFloatArray* exactImage = reference->GetImage();
    std::vector<float> exact(
      exactImage->GetPointer(0), exactImage->GetPointer(0) + 4 * size * size);
    auto withoutFolded = [&](std::vector<float> image)
    {
      for (size_t p = 0; p < foldedPixel.size() && image.size() == exact.size(); ++p)
      {
        if (foldedPixel[p])
        {
          std::fill(image.begin() + 4 * p, image.begin() + 4 * p + 4, 0.0f);
        }
      }
      return image;
    };
    exact = withoutFolded(exact);
    // Near a folded pixel (within one pixel) the rasterizer may meet the folded cells too.
    auto nearFolded = [&](int x, int y)
    {
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          const int px = x + dx, py = y + dy;
          if (px >= 0 && py >= 0 && px < size && py < size && foldedPixel[py * size + px])
          {
            return true;
          }
        }
      }
      return false;
    };
    // The last frame's order violations: (unexplained, rasterization effects).
    // Each logged one (the first 16; more count as unexplained) must be next
    // to folded cells, or at a pixel whose exact fragments arrive in depth
    // order in the frame's draw order (required k <= 2, `k`): there the GPU met
    // a fragment the exact ray does not have (a rasterization effect at an
    // edge), the order itself is right.
    auto classifyViolations = [&](const std::vector<int>& k)
    {
      vtkNew<vtkIntArray> where;
      const int logged = mapper->GetLastFrameStatistics()->GetOrderViolationPixels(where);
      std::pair<long long, long long> counts(mapper->GetLastOrderViolations() - logged, 0);
      for (int i = 0; i < logged; ++i)
      {
        const int x = where->GetComponent(i, 0), y = where->GetComponent(i, 1);
        const bool orderRight = k[static_cast<size_t>(y) * size + x] <= 2;
        counts.first += nearFolded(x, y) || orderRight ? 0 : 1;
        counts.second += !nearFolded(x, y) && orderRight ? 1 : 0;
      }
      return counts;
    };
    vtkIdType centroidViolations = 0;
    for (int o = 0; o < 4; ++o)
    {
      if (o == 0)
      {
        mapper->SetVisibilityOrderToCentroid();
      }
      else
      {
        mapper->SetVisibilityOrderToMPVO();
        mapper->SetNonConvexMethod(mapperMethods[o - 1]);
      }
      view.Window->Render();
      const auto d =
        havstest::Compare(withoutFolded(havstest::FloatResult(mapper)), exact, edgePixels);
      OrderResult& r = results[o];
      r.Violations += mapper->GetLastOrderViolations();
      if (o > 1)
      {
        const auto sorted = classifyViolations(pixelK[o]);
        r.UnexplainedViolations += sorted.first;
        r.RasterViolations += sorted.second;
      }
      centroidViolations = o == 0 ? mapper->GetLastOrderViolations() : centroidViolations;
      r.WorstRMSE = std::max(r.WorstRMSE, d.RMSE);
      r.WorstMax = std::max(r.WorstMax, d.Max);
      r.WorstOver1 = std::max(r.WorstOver1, d.FractionOver1);
      const bool exactImage = d.RMSE < 0.0005 && d.Max < 0.01;
      r.ViewsMissingBounds += exactImage ? 0 : 1;
      if (o > 1 && mapper->GetLastOrderViolations() > 0 && debug)
      {
        vtkNew<vtkIntArray> where;
        for (int i = 0;
             i < std::min(mapper->GetLastFrameStatistics()->GetOrderViolationPixels(where), 3); ++i)
        {
          const int x = where->GetComponent(i, 0), y = where->GetComponent(i, 1);
          std::printf("view %d, %s: order violation at (%d, %d)%s:\n", v, r.Name, x, y,
            nearFolded(x, y) ? ", next to a folded cell" : "");
          PrintPixel(reference, *orders[o], mpvo[o - 1], static_cast<vtkIdType>(y) * size + x);
        }
      }
      if (o > 1 && !exactImage)
      {
        std::printf(
          "  view %d (%s): GPU k = 2 vs reference RMSE %.6f max %.4f\n", v, r.Name, d.RMSE, d.Max);
      }
    }
    // Automatic: MPVO as soon as the centroid order overflows k = 2.
    mapper->SetVisibilityOrderToAutomatic();
    mapper->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexBoundaryLayers); // the default
    view.Window->Render();
    const bool usedMPVO =
      mapper->GetLastVisibilityOrder() == vtkHAVSVolumeMapper::VisibilityOrderMPVO;
    automaticMPVO += usedMPVO ? 1 : 0;
    automaticWrong += centroidViolations > 0 && !usedMPVO ? 1 : 0;
    // The Automatic frames here are MPVO with the boundary layers, or centroid.
    automaticViolations += classifyViolations(pixelK[usedMPVO ? 3 : 0]).first > 0 ? 1 : 0;
  }

  std::printf("%lld folded internal faces (inverted cells); %lld pixel rays over the views "
              "pass through their cells and are left out\n",
    static_cast<long long>(convexified->GetNumberOfFoldedFaces()),
    static_cast<long long>(foldedPixels));
  std::printf("mesh %s; %lld seam face pairs; %lld imaginary cells (convexified in %.3f s); "
              "%lld boundary-layer relations in the last view (%.2f ms)\n",
    convexified->IsMeshConvex() ? "convex" : "non-convex",
    static_cast<long long>(convexified->GetNumberOfSeamFaces()),
    static_cast<long long>(convexified->GetNumberOfImaginaryCells()),
    convexified->GetConvexificationSeconds(),
    static_cast<long long>(layered->GetNumberOfBoundaryRelations()),
    1000.0 * layered->GetLastBoundaryLayerSeconds());
  std::printf("| order | max k | pixels k > 2 | cycle breaks | GPU k=2 order violations | worst "
              "RMSE | worst max | views off bounds | ms per sort |\n"
              "|---|---|---|---|---|---|---|---|---|\n");
  for (int o = 0; o < 4; ++o)
  {
    const OrderResult& r = results[o];
    std::printf("| %s | %d | %lld | %lld | %lld (rasterization %lld) | %.6f | %.4f | %d | %.2f |\n",
      r.Name, r.MaxK, r.PixelsOver2, static_cast<long long>(cycleBreaks[o]), r.Violations,
      r.RasterViolations, r.WorstRMSE, r.WorstMax, r.ViewsMissingBounds,
      1000.0 * r.SortSeconds / numberOfViews);
  }
  // Both non-convex methods on the test meshes; on the real data sets the
  // boundary layers (the convexification's figures are printed: the solid BSP
  // needs a closed, consistently wound boundary, which the combustor's folded
  // cells and the blunt fin's dropped degenerate cells break locally).
  for (int o = synthetic ? 2 : 3; o < 4; ++o)
  {
    const std::string name = results[o].Name;
    havstest::Check(results[o].MaxK <= 2, name + ": every pixel needs k <= 2");
    havstest::Check(results[o].UnexplainedViolations == 0,
      name +
        ": no order violation at k = 2 (but next to folded cells, or rasterization "
        "effects at pixels whose exact fragments arrive in order)");
    havstest::Check(results[o].ViewsMissingBounds == 0,
      name + ": k = 2 within the first-light bounds (RMSE < 0.0005, max < 0.01)");
  }
  // Negative controls. Real data: the centroid order at k = 2 is not exact
  // (the control). Non-convex test meshes: MPVO without a non-convex
  // method is not exact where rays re-enter the mesh.
  // (Of the combustor's 14 views at 128^2 the centroid order misses the
  // bounds in one (max 0.011); the 5 views of the shorter run
  // subset overflow, up to k = 4, and say so, but stay within them, max
  // 0.0012. There the control is the overflow alone.)
  const OrderResult& control = synthetic ? results[1] : results[0];
  const bool allViews = numberOfViews == 14;
  havstest::Check(
    control.MaxK > 2 && control.Violations > 0 && (control.ViewsMissingBounds > 0 || !allViews),
    std::string("negative control: ") + control.Name + " at k = 2 overflows, says so" +
      (allViews ? ", and misses the bounds" : " (the bounds: 14 views only)"));
  std::printf("Automatic: MPVO in %d of the views; views where the centroid order overflowed and "
              "Automatic kept it: %d; Automatic frames with order violations (but next to folded "
              "cells or rasterization effects): %d\n",
    automaticMPVO, automaticWrong, automaticViolations);
  havstest::Check(automaticWrong == 0 && automaticViolations == 0,
    "Automatic takes MPVO where the centroid order overflows, and its frames are exact");
  return havstest::Result();
}
