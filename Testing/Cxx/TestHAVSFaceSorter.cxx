/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSFaceSorter.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSFaceSorter: the order is a permutation whose keys, recomputed in
// double from the grid's points, ascend, for perspective and parallel
// projections, under a scale + translate model-to-world matrix and far from
// the origin; an unchanged camera reuses the sort and any change (eye,
// direction, projection, matrix, face set, Invalidate) re-sorts; block
// reversal moves each face at most block - 1 places. Negative controls: an
// order made for other keys fails the ascending check.
#include "havsTestChecks.h"
#include "havsTestMessages.h"

#include "vtkDataSetTriangleFilter.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
/// A camera and volume matrix, as vtkHAVSFaceSorter::Sort takes them.
struct View
{
  double ModelToWorld[16];
  double Eye[3];
  double Direction[3];
  bool Parallel;
};

bool Sort(vtkHAVSFaceSorter* sorter, vtkHAVSFaceSet* faces, const View& view)
{
  return sorter->Sort(faces, view.ModelToWorld, view.Eye, view.Direction, view.Parallel);
}

/// The key of face f, in double from the grid's points: squared distance from
/// the eye to the world-space centroid, or its depth along the direction.
double Key(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid, vtkIdType f, const View& view)
{
  double c[3] = { 0, 0, 0 };
  for (int i = 0; i < 3; ++i)
  {
    double p[3];
    grid->GetPoint(faces->GetFaceVertices()[3 * f + i], p);
    for (int k = 0; k < 3; ++k)
    {
      c[k] += p[k] / 3.0;
    }
  }
  const double* m = view.ModelToWorld;
  double w[3];
  for (int r = 0; r < 3; ++r)
  {
    w[r] = m[4 * r] * c[0] + m[4 * r + 1] * c[1] + m[4 * r + 2] * c[2] + m[4 * r + 3] - view.Eye[r];
  }
  const double* d = view.Direction;
  return view.Parallel ? w[0] * d[0] + w[1] * d[1] + w[2] * d[2]
                       : w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
}

/// True when `order` is a permutation of the faces along which Key ascends,
/// up to the rounding of float keys.
bool Ascending(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid, const std::vector<uint32_t>& order,
  const View& view)
{
  std::vector<uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 0; i < sorted.size(); ++i)
  {
    if (sorted[i] != i)
    {
      return false;
    }
  }
  if (static_cast<vtkIdType>(order.size()) != faces->GetNumberOfFaces())
  {
    return false;
  }
  for (size_t i = 1; i < order.size(); ++i)
  {
    const double a = Key(faces, grid, order[i - 1], view);
    const double b = Key(faces, grid, order[i], view);
    if (a > b + 1e-6 * std::max(1.0, std::fabs(b)))
    {
      return false;
    }
  }
  return true;
}

/// A block of nx x ny x nz voxels of size h from `origin`, 5 tets per voxel.
vtkSmartPointer<vtkUnstructuredGrid> Block(int nx, int ny, int nz, double h, const double origin[3])
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx + 1, ny + 1, nz + 1);
  image->SetSpacing(h, h, h);
  image->SetOrigin(origin[0], origin[1], origin[2]);
  vtkNew<vtkDataSetTriangleFilter> tetrahedralize;
  tetrahedralize->SetInputData(image);
  tetrahedralize->Update();
  return tetrahedralize->GetOutput();
}
}

int TestHAVSFaceSorter(int, char*[])
{
  const double zero[3] = { 0, 0, 0 };
  auto grid = Block(6, 5, 4, 0.2, zero);
  vtkNew<vtkHAVSFaceSet> faces;
  havstest::Check(faces->Build(grid), "face set builds");
  vtkNew<vtkHAVSFaceSorter> sorter;
  const havstest::Messages* messages = havstest::CountMessages(sorter);

  const double s = 1.0 / std::sqrt(3.0);
  const View perspective = { { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 }, { 3.0, -2.0, 4.0 },
    { -s, s, -s }, false };
  View parallel = perspective;
  parallel.Parallel = true;

  // Perspective and parallel orders ascend in their own keys, and differ:
  // each fails the other's keys.
  havstest::Check(Sort(sorter, faces, perspective), "first sort sorts");
  const std::vector<uint32_t> perspectiveOrder = sorter->GetOrder();
  havstest::Check(Ascending(faces, grid, perspectiveOrder, perspective), "perspective order");
  havstest::Check(Sort(sorter, faces, parallel), "a parallel projection re-sorts");
  havstest::Check(Ascending(faces, grid, sorter->GetOrder(), parallel), "parallel order");
  havstest::Check(!Ascending(faces, grid, perspectiveOrder, parallel),
    "negative control: the perspective order fails the parallel keys");

  // Scale and translate: the key follows the matrix.
  View scaled = perspective;
  const double scaleTranslate[16] = { 1, 0, 0, 0.5, 0, 3, 0, -1, 0, 0, 0.5, 2, 0, 0, 0, 1 };
  std::copy(scaleTranslate, scaleTranslate + 16, scaled.ModelToWorld);
  havstest::Check(Sort(sorter, faces, scaled), "a new matrix re-sorts");
  havstest::Check(Ascending(faces, grid, sorter->GetOrder(), scaled), "scaled order");
  havstest::Check(!Ascending(faces, grid, perspectiveOrder, scaled),
    "negative control: the unscaled order fails the scaled keys");
  View scaledParallel = scaled;
  scaledParallel.Parallel = true;
  Sort(sorter, faces, scaledParallel);
  havstest::Check(
    Ascending(faces, grid, sorter->GetOrder(), scaledParallel), "scaled parallel order");

  // Reuse: nothing changed, nothing sorted; any change sorts.
  Sort(sorter, faces, perspective);
  const vtkIdType sorts = sorter->GetNumberOfSorts();
  havstest::Check(!Sort(sorter, faces, perspective) && sorter->GetNumberOfSorts() == sorts,
    "an unchanged camera reuses the sort");
  havstest::Check(sorter->GetOrder() == perspectiveOrder, "the reused order is kept");
  View moved = perspective;
  moved.Eye[2] = 4.5;
  havstest::Check(
    Sort(sorter, faces, moved) && sorter->GetNumberOfSorts() == sorts + 1, "a moved eye re-sorts");
  havstest::Check(Ascending(faces, grid, sorter->GetOrder(), moved), "moved eye order");
  View turned = moved;
  turned.Direction[0] = 0.0;
  havstest::Check(Sort(sorter, faces, turned), "a new direction re-sorts");
  havstest::Check(!Sort(sorter, faces, turned), "and is then reused");
  sorter->Invalidate();
  havstest::Check(Sort(sorter, faces, turned), "Invalidate forces a sort");
  faces->Build(grid);
  havstest::Check(Sort(sorter, faces, turned), "a rebuilt face set re-sorts");
  havstest::Check(sorter->GetLastSortSeconds() >= 0.0, "sort time measured");

  // Far from the origin (float model coordinates would lose the order here).
  const double far[3] = { 1.0e5, -1.0e5, 5.0e4 };
  auto farGrid = Block(6, 5, 4, 0.2, far);
  vtkNew<vtkHAVSFaceSet> farFaces;
  farFaces->Build(farGrid);
  View farView = perspective;
  for (int k = 0; k < 3; ++k)
  {
    farView.Eye[k] += far[k];
  }
  Sort(sorter, farFaces, farView);
  havstest::Check(Ascending(farFaces, farGrid, sorter->GetOrder(), farView), "far order");

  // Block reversal: each face at most block - 1 places from its sorted place.
  Sort(sorter, faces, scaled);
  const std::vector<uint32_t> exact = sorter->GetOrder();
  sorter->SetBlockReversal(7);
  havstest::Check(Sort(sorter, faces, scaled), "a new block reversal re-sorts");
  std::vector<size_t> place(exact.size());
  for (size_t i = 0; i < exact.size(); ++i)
  {
    place[exact[i]] = i;
  }
  size_t maxMove = 0;
  for (size_t i = 0; i < exact.size(); ++i)
  {
    const size_t p = place[sorter->GetOrder()[i]];
    maxMove = std::max(maxMove, p > i ? p - i : i - p);
  }
  havstest::Check(maxMove == 6, "block reversal of 7 moves faces by up to 6 places");

  havstest::Check(messages->Errors == 0, "no error so far");
  havstest::Check(!sorter->Sort(nullptr, perspective.ModelToWorld, perspective.Eye,
                    perspective.Direction, false) &&
      messages->Errors == 1 && sorter->GetOrder().empty(),
    "a null face set is an error");
  std::cout << faces->GetNumberOfFaces() << " faces, last sort " << sorter->GetLastSortSeconds()
            << " s" << std::endl;
  return havstest::Result();
}
