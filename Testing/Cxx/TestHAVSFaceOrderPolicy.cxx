/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSFaceOrderPolicy.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSFaceOrderPolicy without OpenGL: which order a frame draws, and that
// each order is made again exactly when what it depends on changed.
// - Centroid: the same view twice reuses the order (nothing sorted, nothing
//   gathered, the draw-order version unchanged); a new eye sorts again, and
//   the draw triangles are the centroid sorter's order.
// - MPVO: the same; a view along the other diagonal gives another order; a
//   new mesh build makes a new one; its order is front to back (the first
//   face drawn is nearer the eye than the last).
// - Switching Centroid -> MPVO -> Centroid with the view unchanged sorts
//   nothing again (each order is kept), it only gathers.
// - Automatic: a probe in the centroid order; a clean probe keeps it, a
//   probe with violations makes MPVO the order (no probe after that) for
//   this mesh, k and path; another k probes again.
// - No order needed (extremum blend modes): Order -1, the faces once.
// - Every draw order is a permutation of the mesh's faces.
// - Culled cells (those wholly on the outside of a plane) are neither
//   ordered nor drawn: the centroid order keys only the other faces and is
//   the full order with the culled-only faces taken out; the exact order
//   visits only the kept tetrahedra, every internal face between two of
//   them has its front cell visited first, and each face with a kept cell
//   is ordered once.
// Controls: Invalidate() makes the same view sort again (the reuse check can
// fail), the reversed centroid order fails the front-to-back check, and the
// reversed exact cell order fails the front-cell-first check.
#include "havsTestChecks.h"
#include "havsTestViews.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceOrderPolicy.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSViewFrame.h"
#include "vtkHAVSVisibilityOrder.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace
{

/// The faces (as sorted point triples) of the draw triangles.
std::vector<std::array<uint32_t, 3>> Faces(const std::vector<uint32_t>& triangles)
{
  std::vector<std::array<uint32_t, 3>> faces;
  for (size_t i = 0; i + 2 < triangles.size(); i += 3)
  {
    std::array<uint32_t, 3> f = { triangles[i], triangles[i + 1], triangles[i + 2] };
    std::sort(f.begin(), f.end());
    faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

/// Distance from the eye to a draw triangle's centroid.
double Distance(
  vtkHAVSMesh* mesh, const std::vector<uint32_t>& triangles, size_t t, const double eye[3])
{
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    double c = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      c += mesh->GetPoints()[3 * triangles[3 * t + i] + k] + mesh->GetShift()[k];
    }
    d2 += (c / 3.0 - eye[k]) * (c / 3.0 - eye[k]);
  }
  return std::sqrt(d2);
}

/// Internal faces between two kept tetrahedra whose front tetrahedron (the
/// one on the eye's side of the face) comes after its back one in `cells`
/// (a cell order: tetrahedron indices). Kept: not `culled` (per grid cell).
int FrontAfterBack(vtkHAVSFaceSet* faces, vtkHAVSVisibilityOrder* order, vtkPoints* points,
  const std::vector<uint32_t>& cells, const std::vector<uint8_t>& culled, const double eye[3])
{
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const std::vector<uint32_t>& tetCells = faces->GetTetrahedronCells();
  std::vector<int64_t> rank(tets.size() / 4, -1);
  for (size_t i = 0; i < cells.size(); ++i)
  {
    rank[cells[i]] = static_cast<int64_t>(i);
  }
  const std::vector<uint32_t>& fv = faces->GetFaceVertices();
  int wrong = 0;
  for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
  {
    vtkIdType t[2];
    order->GetFaceTetrahedra(f, t);
    if (t[0] < 0 || t[1] < 0 || culled[tetCells[t[0]]] || culled[tetCells[t[1]]])
    {
      continue;
    }
    double p[3][3], far[3];
    for (int i = 0; i < 3; ++i)
    {
      points->GetPoint(fv[3 * f + i], p[i]);
    }
    // The far vertex of tetrahedron 0: the one not on the face.
    for (int j = 0; j < 4; ++j)
    {
      const uint32_t v = tets[4 * t[0] + j];
      if (v != fv[3 * f] && v != fv[3 * f + 1] && v != fv[3 * f + 2])
      {
        points->GetPoint(v, far);
      }
    }
    double u[3], w[3], n[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = p[1][k] - p[0][k];
      w[k] = p[2][k] - p[0][k];
    }
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    double sideEye = 0.0, sideFar = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      sideEye += n[k] * (eye[k] - p[0][k]);
      sideFar += n[k] * (far[k] - p[0][k]);
    }
    const vtkIdType front = (sideEye > 0.0) == (sideFar > 0.0) ? t[0] : t[1];
    const vtkIdType back = front == t[0] ? t[1] : t[0];
    if (rank[front] < 0 || rank[back] < 0 || rank[front] > rank[back])
    {
      ++wrong;
    }
  }
  return wrong;
}
}

int TestHAVSFaceOrderPolicy(int, char*[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::MakeBox(6, 5, 4, 0.2, 0.0, 1.0);
  vtkNew<vtkHAVSMesh> mesh;
  vtkHAVSMesh::ScalarSelection selection;
  havstest::Check(mesh->Build(grid, selection), "mesh built: " + mesh->GetError());
  const auto allFaces = Faces(mesh->GetFaceSet()->GetFaceVertices());
  const double centre[3] = { 0.6, 0.5, 0.4 };
  const double eyeA[3] = { 4.0, 3.0, 2.5 }, eyeB[3] = { -3.0, -2.0, -2.5 };
  const vtkHAVSViewFrame viewA = havstest::PerspectiveView(eyeA, centre),
                         viewB = havstest::PerspectiveView(eyeB, centre);
  const int centroid = vtkHAVSVolumeMapper::VisibilityOrderCentroid;
  const int mpvo = vtkHAVSVolumeMapper::VisibilityOrderMPVO;

  vtkNew<vtkHAVSFaceOrderPolicy> policy;
  vtkHAVSFaceSorter* sorter = policy->GetCentroidSorter();

  // Centroid: made once per view.
  policy->SetVisibilityOrder(centroid);
  vtkHAVSFaceOrderPolicy::Plan plan = policy->Begin(mesh, 2, 1, true, true);
  havstest::Check(
    plan.Order == centroid && !plan.Probe, "Centroid: the plan is the centroid order");
  policy->Prepare(plan, mesh, grid, viewA);
  const vtkMTimeType first = policy->GetDrawOrderVersion();
  const vtkIdType sorts = sorter->GetNumberOfSorts();
  havstest::Check(!policy->GetLastReused() && policy->GetLastOrder() == centroid,
    "Centroid: the first frame sorts");
  havstest::Check(Faces(policy->GetDrawTriangles()) == allFaces,
    "Centroid: the draw order is a permutation of the faces");
  policy->Prepare(plan, mesh, grid, viewA);
  havstest::Check(policy->GetLastReused() && policy->GetDrawOrderVersion() == first &&
      sorter->GetNumberOfSorts() == sorts,
    "Centroid: the same view reuses the order (nothing sorted or gathered)");
  policy->Invalidate();
  policy->Prepare(plan, mesh, grid, viewA);
  havstest::Check(!policy->GetLastReused() && sorter->GetNumberOfSorts() == sorts + 1,
    "control: after Invalidate() the same view sorts again");
  const std::vector<uint32_t> centroidA = policy->GetDrawTriangles();
  const size_t n = centroidA.size() / 3;
  havstest::Check(Distance(mesh, centroidA, 0, eyeA) < Distance(mesh, centroidA, n - 1, eyeA),
    "Centroid: front to back (first face nearer than the last)");
  policy->Prepare(plan, mesh, grid, viewB);
  havstest::Check(!policy->GetLastReused() && policy->GetDrawTriangles() != centroidA,
    "Centroid: a new eye sorts again, into another order");
  havstest::Check(Distance(mesh, centroidA, 0, eyeB) > Distance(mesh, centroidA, n - 1, eyeB),
    "control: the order made for the other eye is back to front from this one");

  // MPVO: made once per view, front to back.
  policy->SetVisibilityOrder(mpvo);
  plan = policy->Begin(mesh, 2, 1, true, true);
  havstest::Check(plan.Order == mpvo && !plan.Probe, "MPVO: the plan is the exact order");
  havstest::Check(policy->Prepare(plan, mesh, grid, viewA), "MPVO: the order is made");
  const std::vector<uint32_t> exactA = policy->GetDrawTriangles();
  const vtkMTimeType exactVersion = policy->GetDrawOrderVersion();
  havstest::Check(
    policy->GetLastOrder() == mpvo && !policy->GetLastReused() && Faces(exactA) == allFaces,
    "MPVO: a permutation of the faces, newly made");
  havstest::Check(
    Distance(mesh, exactA, 0, eyeA) < Distance(mesh, exactA, n - 1, eyeA), "MPVO: front to back");
  policy->Prepare(plan, mesh, grid, viewA);
  havstest::Check(policy->GetLastReused() && policy->GetDrawOrderVersion() == exactVersion,
    "MPVO: the same view reuses the order");
  policy->Prepare(plan, mesh, grid, viewB);
  havstest::Check(!policy->GetLastReused() && policy->GetDrawTriangles() != exactA,
    "MPVO: the opposite view makes another order");

  // Switching orders with the view unchanged gathers, sorts nothing again.
  policy->Prepare(plan, mesh, grid, viewA);
  policy->SetVisibilityOrder(centroid);
  const vtkIdType sortsBefore = sorter->GetNumberOfSorts();
  policy->Prepare(policy->Begin(mesh, 2, 1, true, true), mesh, grid, viewB);
  policy->Prepare(policy->Begin(mesh, 2, 1, true, true), mesh, grid, viewA);
  havstest::Check(
    sorter->GetNumberOfSorts() == sortsBefore + 1 && policy->GetDrawTriangles() == centroidA,
    "switching back to the centroid order for a view it was made for only gathers");

  // A new mesh build: a new order.
  grid->Modified();
  havstest::Check(mesh->NeedsBuild(grid, selection), "a modified grid needs a new mesh");
  mesh->Build(grid, selection);
  policy->SetVisibilityOrder(mpvo);
  policy->Prepare(policy->Begin(mesh, 2, 1, true, true), mesh, grid, viewA);
  havstest::Check(!policy->GetLastReused(), "MPVO: a new mesh makes its order again");

  // Automatic.
  policy->SetVisibilityOrder(vtkHAVSVolumeMapper::VisibilityOrderAutomatic);
  plan = policy->Begin(mesh, 2, 1, true, true);
  havstest::Check(plan.Order == centroid && plan.Probe, "Automatic: a centroid probe first");
  havstest::Check(policy->ProbeResult(0).Order == -1, "Automatic: a clean probe is the frame");
  plan = policy->Begin(mesh, 2, 1, true, true);
  havstest::Check(
    plan.Order == centroid && plan.Probe, "Automatic: still probing the centroid order");
  const vtkHAVSFaceOrderPolicy::Plan again = policy->ProbeResult(7);
  havstest::Check(again.Order == mpvo && !again.Probe,
    "Automatic: a probe with violations is drawn again in the exact order");
  plan = policy->Begin(mesh, 2, 1, true, true);
  havstest::Check(
    plan.Order == mpvo && !plan.Probe, "Automatic: MPVO stays for this mesh, k, path");
  plan = policy->Begin(mesh, 3, 1, true, true);
  havstest::Check(plan.Order == centroid && plan.Probe, "Automatic: another k probes again");
  plan = policy->Begin(mesh, 3, 1, true, false);
  havstest::Check(!plan.Probe, "Automatic: no probe where none may be drawn (raster bound)");

  // Culled cells: those wholly on the outside of the plane x = 0.45 (kept
  // where x >= 0.45), as vtkHAVSViewCulling marks them.
  {
    vtkHAVSFaceSet* faces = mesh->GetFaceSet();
    const std::vector<uint32_t>& tets = faces->GetTetrahedra();
    const std::vector<uint32_t>& tetCells = faces->GetTetrahedronCells();
    std::vector<uint8_t> culled(grid->GetNumberOfCells(), 0);
    size_t keptTets = 0;
    for (size_t t = 0; t < tetCells.size(); ++t)
    {
      bool outside = true;
      for (int j = 0; j < 4; ++j)
      {
        outside = outside && grid->GetPoints()->GetPoint(tets[4 * t + j])[0] < 0.45;
      }
      culled[tetCells[t]] = outside;
      keptTets += !outside;
    }
    const std::vector<uint32_t>& faceCells = faces->GetFaceCells();
    auto kept = [&](uint32_t c) { return c != vtkHAVSFaceSet::NoCell && !culled[c]; };
    std::vector<uint32_t> unculled;
    for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
    {
      if (kept(faceCells[2 * f]) || kept(faceCells[2 * f + 1]))
      {
        unculled.push_back(static_cast<uint32_t>(f));
      }
    }
    havstest::Check(keptTets > 0 && keptTets < tetCells.size() &&
        unculled.size() < static_cast<size_t>(faces->GetNumberOfFaces()),
      "culling: the plane culls some tetrahedra, not all");
    auto unculledOnly = [&](const std::vector<uint32_t>& triangles)
    {
      std::vector<std::array<uint32_t, 3>> all = Faces(triangles), expected;
      for (uint32_t f : unculled)
      {
        std::array<uint32_t, 3> v = { faces->GetFaceVertices()[3 * f],
          faces->GetFaceVertices()[3 * f + 1], faces->GetFaceVertices()[3 * f + 2] };
        std::sort(v.begin(), v.end());
        expected.push_back(v);
      }
      std::sort(expected.begin(), expected.end());
      return all == expected;
    };

    // Centroid: the full order, then the culled one.
    policy->SetCellCulling(nullptr, 0);
    policy->SetVisibilityOrder(centroid);
    policy->Prepare(policy->Begin(mesh, 2, 1, true, true), mesh, grid, viewA);
    const std::vector<uint32_t> full = sorter->GetOrder();
    policy->SetCellCulling(&culled, 1);
    const vtkIdType sortsCulled = sorter->GetNumberOfSorts();
    policy->Prepare(policy->Begin(mesh, 2, 1, true, true), mesh, grid, viewA);
    std::vector<uint32_t> filtered;
    std::copy_if(full.begin(), full.end(), std::back_inserter(filtered),
      [&](uint32_t f) { return std::binary_search(unculled.begin(), unculled.end(), f); });
    havstest::Check(sorter->GetNumberOfSorts() == sortsCulled + 1 &&
        policy->GetLastOrderedFaces() == static_cast<vtkIdType>(unculled.size()) &&
        sorter->GetOrder() == filtered,
      "culling, centroid: only the faces with a kept cell are sorted, in the full order's "
      "sequence");
    havstest::Check(unculledOnly(policy->GetDrawTriangles()),
      "culling, centroid: the faces with a kept cell are drawn, each once");
    policy->Prepare(policy->Begin(mesh, 2, 1, true, true), mesh, grid, viewA);
    havstest::Check(sorter->GetNumberOfSorts() == sortsCulled + 1 && policy->GetLastReused(),
      "culling, centroid: the same view and culling sort nothing again");

    // MPVO: only the kept tetrahedra are visited, front cells first.
    policy->SetVisibilityOrder(mpvo);
    havstest::Check(policy->Prepare(policy->Begin(mesh, 2, 1, true, true), mesh, grid, viewA),
      "culling, MPVO: the order is made");
    vtkHAVSVisibilityOrder* exact = policy->GetExactOrder();
    const std::vector<uint32_t> cells = exact->GetCellOrder();
    havstest::Check(cells.size() == keptTets &&
        policy->GetLastOrderedFaces() == static_cast<vtkIdType>(unculled.size()) &&
        unculledOnly(policy->GetDrawTriangles()),
      "culling, MPVO: the kept tetrahedra only; each face with a kept cell ordered once (" +
        std::to_string(policy->GetLastOrderedFaces()) + " of " +
        std::to_string(faces->GetNumberOfFaces()) + " faces, " + std::to_string(keptTets) + " of " +
        std::to_string(tetCells.size()) + " tetrahedra)");
    const int wrong = FrontAfterBack(faces, exact, grid->GetPoints(), cells, culled, eyeA);
    havstest::Check(wrong == 0,
      "culling, MPVO: every face between kept cells has its front cell first (" +
        std::to_string(wrong) + " do not)");
    const std::vector<uint32_t> reversed(cells.rbegin(), cells.rend());
    havstest::Check(FrontAfterBack(faces, exact, grid->GetPoints(), reversed, culled, eyeA) > 0,
      "control: the reversed cell order has faces with the front cell last");
    policy->SetCellCulling(nullptr, 0);
    policy->Prepare(policy->Begin(mesh, 2, 1, true, true), mesh, grid, viewA);
    havstest::Check(exact->GetCellOrder().size() == tetCells.size() &&
        policy->GetLastOrderedFaces() == faces->GetNumberOfFaces(),
      "culling off, MPVO: every tetrahedron and face ordered again");
  }

  // No order needed.
  plan = policy->Begin(mesh, 2, 1, false, true);
  havstest::Check(plan.Order == -1 && !plan.Probe, "extremum: no order");
  policy->Prepare(plan, mesh, grid, viewB);
  havstest::Check(policy->GetLastOrder() == -1 && Faces(policy->GetDrawTriangles()) == allFaces,
    "extremum: the faces in some order, -1 reported");
  return havstest::Result();
}
