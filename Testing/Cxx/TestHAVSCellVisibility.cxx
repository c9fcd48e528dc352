/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSCellVisibility.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSCellVisibility and the gather that skips invisible cells, without
// OpenGL, on the generated block (sin(6x) cos(5y) + z) under a transfer
// function with zero opacity over the middle of the range:
// - every tetrahedron whose scalars lie inside the zero band, more than one
//   table node from its ends, is invisible; every one that reaches the
//   visible bands is visible (from the cells' own scalars, computed here);
// - Update() again with nothing changed does nothing; a transfer-function
//   edit (a new table) changes the set; the edit that shows the band hides
//   no cell;
// - the gather (vtkHAVSFaceOrderPolicy) keeps exactly the faces with a
//   visible cell, in the order's sequence; the faces between a visible and an
//   invisible cell are boundary faces whose normal points out of the visible
//   cell (away from its centroid), flag 2 exactly where the face set's
//   winding was reversed.
// Control: opacity 1e-4 instead of 0 in the band hides nothing (the test of
// zero cannot pass on a near-zero function).
// vtkHAVSViewCulling: a plane culls exactly the cells wholly beyond it
// (control: culling by the centroid would differ), and the identity's frustum
// around the block culls nothing.
#include "havsTestChecks.h"
#include "havsTestViews.h"

#include "vtkHAVSCellVisibility.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceOrderPolicy.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSViewCulling.h"
#include "vtkHAVSViewFrame.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
/// Opacity `inside` over [0.3, 0.7] of the normalized range, 0.8 at the ends.
vtkSmartPointer<vtkVolumeProperty> BandProperty(const double range[2], double inside)
{
  const double lo = range[0], span = range[1] - range[0];
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.1, 0.3, 1.0);
  color->AddRGBPoint(range[1], 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> alpha;
  alpha->AddPoint(lo, 0.8);
  alpha->AddPoint(lo + 0.3 * span, inside);
  alpha->AddPoint(lo + 0.7 * span, inside);
  alpha->AddPoint(range[1], 0.8);
  property->SetColor(color);
  property->SetScalarOpacity(alpha);
  property->SetScalarOpacityUnitDistance(0.2);
  return property;
}

}

int TestHAVSCellVisibility(int, char*[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::MakeGenerated(8);
  vtkNew<vtkHAVSMesh> mesh;
  vtkHAVSMesh::ScalarSelection selection;
  havstest::Check(mesh->Build(grid, selection), "mesh built: " + mesh->GetError());
  const double* range = mesh->GetScalarRange();
  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const std::vector<uint32_t>& tetCells = faces->GetTetrahedronCells();
  const std::vector<float>& scalars = mesh->GetScalars(); // normalized to [0, 1]

  vtkNew<vtkHAVSPreIntegrationTable> table;
  table->SetScalarResolution(64);
  table->SetLengthResolution(16);
  auto property = BandProperty(range, 0.0);
  table->Build(property, 0, range, 0.3);
  vtkNew<vtkHAVSCellVisibility> visibility;
  havstest::Check(visibility->Update(mesh, table, 1), "the first update computes a set");
  const std::vector<uint8_t>& visible = visibility->GetVisible();

  // Against the cells' own scalars: one table node (1/63) of margin.
  const double node = 1.0 / 63.0;
  vtkIdType inside = 0, reaching = 0, wrong = 0;
  for (size_t t = 0; t < tetCells.size(); ++t)
  {
    float lo = 1.0f, hi = 0.0f;
    for (int v = 0; v < 4; ++v)
    {
      lo = std::min(lo, scalars[tets[4 * t + v]]);
      hi = std::max(hi, scalars[tets[4 * t + v]]);
    }
    if (lo > 0.3 + node && hi < 0.7 - node)
    {
      ++inside;
      wrong += visible[tetCells[t]] ? 1 : 0;
    }
    else if (lo < 0.3 || hi > 0.7)
    {
      ++reaching;
      wrong += visible[tetCells[t]] ? 0 : 1;
    }
  }
  std::printf("%zu tets: %lld inside the band, %lld reaching the visible bands; invisible %lld; "
              "wrong %lld\n",
    tetCells.size(), static_cast<long long>(inside), static_cast<long long>(reaching),
    static_cast<long long>(visibility->GetNumberOfInvisibleCells()), static_cast<long long>(wrong));
  havstest::Check(inside > 100 && reaching > 100, "the band splits the cells");
  havstest::Check(wrong == 0, "inside the band invisible, reaching the visible bands visible");
  havstest::Check(visibility->GetNumberOfInvisibleCells() >= inside &&
      visibility->GetNumberOfInvisibleCells() <= static_cast<vtkIdType>(tetCells.size()) - reaching,
    "the count of invisible cells");

  // Nothing changed: nothing done; a new table: a new set.
  const vtkMTimeType version = visibility->GetVisibilityVersion();
  havstest::Check(
    !visibility->Update(mesh, table, 1) && visibility->GetVisibilityVersion() == version,
    "an unchanged table and mesh: nothing recomputed");
  property->GetScalarOpacity()->AddPoint(range[0] + 0.5 * (range[1] - range[0]), 0.4);
  table->Build(property, 0, range, 0.3);
  havstest::Check(visibility->Update(mesh, table, 2) &&
      visibility->GetVisibilityVersion() != version && visibility->GetNumberOfInvisibleCells() == 0,
    "an edit showing the band: every cell visible");

  // Control: a near-zero band is not zero.
  auto faint = BandProperty(range, 1e-4);
  table->Build(faint, 0, range, 0.3);
  visibility->Update(mesh, table, 3);
  havstest::Check(visibility->GetNumberOfInvisibleCells() == 0,
    "control: opacity 1e-4 in the band hides no cell");

  // The gather.
  table->Build(BandProperty(range, 0.0), 0, range, 0.3);
  visibility->Update(mesh, table, 4);
  vtkNew<vtkHAVSFaceOrderPolicy> policy;
  policy->SetVisibilityOrder(vtkHAVSVolumeMapper::VisibilityOrderCentroid);
  const double eye[3] = { 3.0, 2.5, 2.0 }, centre[3] = { 0.5, 0.5, 0.5 };
  const vtkHAVSViewFrame view = havstest::PerspectiveView(eye, centre);
  vtkHAVSFaceOrderPolicy::Plan plan = policy->Begin(mesh, 2, 1, true, false);
  policy->Prepare(plan, mesh, grid, view);
  const size_t allDrawn = policy->GetDrawTriangles().size() / 3;
  policy->SetCellVisibility(&visibility->GetVisible(), visibility->GetVisibilityVersion());
  policy->Prepare(plan, mesh, grid, view);
  havstest::Check(policy->GetLastReused(), "a new visible set gathers without a new sort");
  const std::vector<uint32_t>& drawn = policy->GetDrawTriangles();
  const std::vector<uint8_t>& flags = policy->GetDrawBoundaryFlags();
  const std::vector<uint32_t>& faceVertices = faces->GetFaceVertices();
  const std::vector<uint32_t>& faceCells = faces->GetFaceCells();
  const std::vector<float>& points = mesh->GetPoints();
  // Each grid cell's centroid (the tetrahedra's).
  std::vector<double> centroid(3 * visible.size(), 0.0);
  for (size_t t = 0; t < tetCells.size(); ++t)
  {
    for (int v = 0; v < 4; ++v)
    {
      for (int k = 0; k < 3; ++k)
      {
        centroid[3 * tetCells[t] + k] += 0.25 * points[3 * tets[4 * t + v] + k];
      }
    }
  }
  auto isVisible = [&](uint32_t c) { return c != vtkHAVSFaceSet::NoCell && visible[c] != 0; };
  size_t expected = 0;
  for (size_t f = 0; f < faceCells.size() / 2; ++f)
  {
    expected += isVisible(faceCells[2 * f]) || isVisible(faceCells[2 * f + 1]) ? 1 : 0;
  }
  // Match the drawn faces to the face set's by their sorted point ids.
  std::vector<std::pair<std::array<uint32_t, 3>, size_t>> byIds;
  for (size_t f = 0; f < faceCells.size() / 2; ++f)
  {
    std::array<uint32_t, 3> ids = { faceVertices[3 * f], faceVertices[3 * f + 1],
      faceVertices[3 * f + 2] };
    std::sort(ids.begin(), ids.end());
    byIds.emplace_back(ids, f);
  }
  std::sort(byIds.begin(), byIds.end());
  size_t badFlag = 0, badNormal = 0, hiddenDrawn = 0, boundaries = 0;
  for (size_t i = 0; i < drawn.size() / 3; ++i)
  {
    std::array<uint32_t, 3> ids = { drawn[3 * i], drawn[3 * i + 1], drawn[3 * i + 2] };
    std::sort(ids.begin(), ids.end());
    auto it = std::lower_bound(byIds.begin(), byIds.end(), std::make_pair(ids, size_t(0)));
    if (it == byIds.end() || it->first != ids)
    {
      ++hiddenDrawn;
      continue;
    }
    const size_t f = it->second;
    const bool a = isVisible(faceCells[2 * f]), b = isVisible(faceCells[2 * f + 1]);
    hiddenDrawn += (a || b) ? 0 : 1;
    const uint8_t want = a == b ? 0 : (a ? 2 : 1);
    badFlag += flags[i] == want ? 0 : 1;
    if (a != b)
    {
      ++boundaries;
      const uint32_t cell = a ? faceCells[2 * f] : faceCells[2 * f + 1];
      const float* p0 = &points[3 * drawn[3 * i]];
      const float* p1 = &points[3 * drawn[3 * i + 1]];
      const float* p2 = &points[3 * drawn[3 * i + 2]];
      const double e1[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
      const double e2[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
      const double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0] };
      double toCell = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        toCell += n[k] * (centroid[3 * cell + k] - p0[k]);
      }
      badNormal += toCell < 0.0 ? 0 : 1;
    }
  }
  std::printf("gather: %zu of %zu faces drawn (expected %zu), %zu boundary; wrong flags %zu, "
              "normals into the visible cell %zu, faces of hidden cells %zu\n",
    drawn.size() / 3, allDrawn, expected, boundaries, badFlag, badNormal, hiddenDrawn);
  havstest::Check(drawn.size() / 3 == expected && expected < allDrawn,
    "the gather keeps the faces with a visible cell");
  havstest::Check(hiddenDrawn == 0 && badFlag == 0 && badNormal == 0 && boundaries > 0,
    "faces next to invisible cells: boundary faces wound out of the visible cell");

  // vtkHAVSViewCulling: the plane x <= 0 (model coordinates: the block's
  // centre is the origin) culls exactly the cells wholly beyond it.
  vtkNew<vtkHAVSViewCulling> culling;
  const std::vector<std::array<double, 4>> half = { { -1.0, 0.0, 0.0, 0.0 } };
  culling->Update(mesh, half);
  const std::vector<uint8_t>& culled = culling->GetCulled();
  size_t wrongCulled = 0, centroidWrong = 0, culledCount = 0;
  for (size_t t = 0; t < tetCells.size(); ++t)
  {
    int beyond = 0;
    double cx = 0.0;
    for (int v = 0; v < 4; ++v)
    {
      const float x = points[3 * tets[4 * t + v]];
      beyond += x > 0.0f ? 1 : 0;
      cx += 0.25 * x;
    }
    const bool wholly = beyond == 4;
    culledCount += culled[tetCells[t]];
    wrongCulled += (culled[tetCells[t]] != 0) != wholly ? 1 : 0;
    // Control: culling by the centroid would drop cells reaching the kept side.
    centroidWrong += (cx > 0.0) != wholly ? 1 : 0;
  }
  std::printf("culling by x <= 0: %zu culled (%lld counted), %zu wrong; by the centroid %zu "
              "would be wrong\n",
    culledCount, static_cast<long long>(culling->GetNumberOfCulledCells()), wrongCulled,
    centroidWrong);
  havstest::Check(culledCount > 0 && wrongCulled == 0 &&
      culling->GetNumberOfCulledCells() == static_cast<vtkIdType>(culledCount),
    "culling: exactly the cells wholly beyond the plane");
  havstest::Check(centroidWrong > 0, "control: the centroid rule differs from the whole-cell one");
  // The frustum of the identity matrix: -1 <= x, y, z <= 1 holds the block.
  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  culling->Update(mesh, vtkHAVSViewCulling::FrustumPlanes(identity));
  havstest::Check(culling->GetNumberOfCulledCells() == 0, "a frustum holding the block culls none");
  return havstest::Result();
}
