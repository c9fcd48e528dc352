/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSInternalFaceRanking.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSInternalFaceRanking without OpenGL, on the generated block (8^3
// voxels split into tetrahedra, unit cube):
// - every strategy ranks exactly the internal faces, each once (boundary
//   faces NoRank), and the same seed gives the same ranking;
// - Topology: peeling the block removes one voxel layer per step, so it has
//   4 layers and the faces of layer L lie on the surface of the block inset
//   by L/8 (every vertex at that distance from the boundary); whole layers
//   come in radical-inverse order (1, 3, 2);
// - Field: a prefix of r rounds holds min(r, bin size) faces of every scalar bin
//   (control: the Random order's prefix does not);
// - Area: the first tenth has larger faces on average than Random's;
// - ViewAligned: after UpdateView the first tenth faces the view more
//   squarely than the whole; the same view changes nothing, another view
//   re-ranks.
#include "havsTestChecks.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSInternalFaceRanking.h"
#include "vtkHAVSMesh.h"

#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
constexpr int kCells = 8;

double FaceArea(vtkUnstructuredGrid* grid, const uint32_t* v, double normal[3])
{
  double a[3], b[3], c[3];
  grid->GetPoint(v[0], a);
  grid->GetPoint(v[1], b);
  grid->GetPoint(v[2], c);
  const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
    e1[0] * e2[1] - e1[1] * e2[0] };
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int i = 0; i < 3; ++i)
  {
    normal[i] = l > 0 ? n[i] / l : 0.0;
  }
  return 0.5 * l;
}

/// Per internal face of `order`'s first `count`: the mean of `value`.
template <typename F>
double PrefixMean(const std::vector<uint32_t>& order, size_t count, F value)
{
  double sum = 0.0;
  for (size_t i = 0; i < count; ++i)
  {
    sum += value(order[i]);
  }
  return count ? sum / count : 0.0;
}
}

int TestHAVSInternalFaceRanking(int, char*[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::MakeGenerated(kCells);
  vtkNew<vtkHAVSMesh> mesh;
  vtkHAVSMesh::ScalarSelection selection;
  havstest::Check(mesh->Build(grid, selection), "mesh built: " + mesh->GetError());
  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const std::vector<uint8_t>& boundary = faces->GetBoundaryFlags();
  const std::vector<uint32_t>& fv = faces->GetFaceVertices();
  const size_t numFaces = boundary.size();
  const size_t internal = numFaces - static_cast<size_t>(faces->GetNumberOfBoundaryFaces());
  std::printf("%zu faces, %zu internal\n", numFaces, internal);

  std::vector<uint32_t> orders[5];
  for (int s = 0; s < 5; ++s)
  {
    const std::string name = vtkHAVSInternalFaceRanking::GetStrategyName(s);
    vtkNew<vtkHAVSInternalFaceRanking> ranking;
    ranking->SetStrategy(s);
    double lastProgress = -1.0;
    bool monotone = true;
    havstest::Check(ranking->Update(mesh,
                      [&](double p)
                      {
                        monotone = monotone && p >= lastProgress;
                        lastProgress = p;
                      }),
      name + ": ranked");
    havstest::Check(monotone && lastProgress == 1.0, name + ": progress runs up to 1");
    havstest::Check(!ranking->Update(mesh), name + ": nothing changed, nothing ranked again");
    const std::vector<uint32_t>& ranks = ranking->GetRanks();
    const std::vector<uint32_t>& order = ranking->GetOrder();
    bool permutation = ranks.size() == numFaces && order.size() == internal;
    std::vector<uint8_t> seen(internal, 0);
    for (size_t f = 0; permutation && f < numFaces; ++f)
    {
      const uint32_t r = ranks[f];
      if (boundary[f])
      {
        permutation = r == vtkHAVSInternalFaceRanking::NoRank;
      }
      else
      {
        permutation = r < internal && !seen[r] && order[r] == f;
        if (permutation)
        {
          seen[r] = 1;
        }
      }
    }
    havstest::Check(permutation, name + ": every internal face ranked once, boundary faces not");
    vtkNew<vtkHAVSInternalFaceRanking> again;
    again->SetStrategy(s);
    again->Update(mesh);
    havstest::Check(again->GetOrder() == order, name + ": the same seed, the same ranking");
    std::printf("%s: %.4f s, %zu bytes\n", name.c_str(), ranking->GetLastSeconds(),
      ranking->GetMemoryBytes());
    orders[s] = order;

    if (s == vtkHAVSInternalFaceRanking::Topology)
    {
      const std::vector<int>& layers = ranking->GetFaceLayers();
      havstest::Check(ranking->GetNumberOfLayers() == kCells / 2,
        "Topology: " + std::to_string(ranking->GetNumberOfLayers()) + " layers peeled, 4 expected");
      bool inset = true;
      for (size_t f = 0; f < numFaces && inset; ++f)
      {
        const int l = layers[f];
        if (boundary[f] && l != 0)
        {
          inset = false;
        }
        for (int i = 0; i < 3 && l >= 0 && inset; ++i)
        {
          double x[3];
          grid->GetPoint(fv[3 * f + i], x);
          const double d = std::min({ x[0], 1 - x[0], x[1], 1 - x[1], x[2], 1 - x[2] });
          inset = std::abs(d - static_cast<double>(l) / kCells) < 1e-9;
        }
      }
      havstest::Check(inset, "Topology: layer L lies on the block inset by L/8");
      // Whole layers in radical-inverse order: 1, 3, 2, then the unreached.
      std::vector<int> sequence;
      for (uint32_t f : order)
      {
        if (sequence.empty() || sequence.back() != layers[f])
        {
          sequence.push_back(layers[f]);
        }
      }
      havstest::Check(sequence.size() >= 3 && sequence[0] == 1 && sequence[1] == 3 &&
          sequence[2] == 2 && (sequence.size() == 3 || (sequence.size() == 4 && sequence[3] < 0)),
        "Topology: whole layers in the order 1, 3, 2, the unreached last");
    }
    if (s == vtkHAVSInternalFaceRanking::ViewAligned)
    {
      const double view[3] = { 0.3, 0.2, 1.0 };
      havstest::Check(ranking->UpdateView(view), "ViewAligned: a view ranks the clusters");
      havstest::Check(!ranking->UpdateView(view), "ViewAligned: the same view changes nothing");
      const std::vector<uint32_t>& viewOrder = ranking->GetOrder();
      const double l = std::sqrt(0.09 + 0.04 + 1.0);
      auto facing = [&](uint32_t f)
      {
        double n[3];
        FaceArea(grid, &fv[3 * static_cast<size_t>(f)], n);
        return std::abs(n[0] * view[0] + n[1] * view[1] + n[2] * view[2]) / l;
      };
      const double top = PrefixMean(viewOrder, internal / 10, facing);
      const double all = PrefixMean(viewOrder, internal, facing);
      std::printf("ViewAligned: |n.v| first tenth %.3f, all %.3f\n", top, all);
      havstest::Check(top > all + 0.1, "ViewAligned: the first tenth faces the view");
      const double side[3] = { 1.0, 0.0, 0.1 };
      havstest::Check(ranking->UpdateView(side), "ViewAligned: another view re-ranks");
    }
  }

  // Field: stratified over the histogram of the faces' mean scalar.
  const std::vector<float>& scalars = mesh->GetScalars();
  auto bin = [&](uint32_t f)
  {
    const double m =
      (scalars[fv[3 * f]] + scalars[fv[3 * f + 1]] + static_cast<double>(scalars[fv[3 * f + 2]])) /
      3.0;
    return std::min(127, std::max(0, static_cast<int>(m * 128)));
  };
  std::vector<size_t> binSize(128, 0);
  for (uint32_t f : orders[vtkHAVSInternalFaceRanking::Field])
  {
    ++binSize[bin(f)];
  }
  // The first r rounds take min(bin size, r) faces from every bin.
  const size_t rounds = 6;
  size_t nonempty = 0, prefix = 0;
  for (size_t b : binSize)
  {
    nonempty += b ? 1 : 0;
    prefix += std::min(b, rounds);
  }
  auto stratified = [&](const std::vector<uint32_t>& order)
  {
    std::vector<size_t> count(128, 0);
    for (size_t i = 0; i < prefix; ++i)
    {
      ++count[bin(order[i])];
    }
    for (int b = 0; b < 128; ++b)
    {
      if (count[b] != std::min(binSize[b], rounds))
      {
        return false;
      }
    }
    return true;
  };
  std::printf("Field: %zu bins hold faces, %zu rounds\n", nonempty, rounds);
  havstest::Check(nonempty > 20, "Field: the block's faces spread over the bins");
  havstest::Check(stratified(orders[vtkHAVSInternalFaceRanking::Field]),
    "Field: the first rounds take the same number of faces from every bin");
  havstest::Check(!stratified(orders[vtkHAVSInternalFaceRanking::Random]),
    "Field: control: a random order is not stratified");

  // Area: larger faces first (on average) than at random.
  auto area = [&](uint32_t f)
  {
    double n[3];
    return FaceArea(grid, &fv[3 * static_cast<size_t>(f)], n);
  };
  const double areaTop = PrefixMean(orders[vtkHAVSInternalFaceRanking::Area], internal / 10, area);
  const double randomTop =
    PrefixMean(orders[vtkHAVSInternalFaceRanking::Random], internal / 10, area);
  std::printf("Area: mean area of the first tenth %.5f, at random %.5f\n", areaTop, randomTop);
  havstest::Check(areaTop > 1.05 * randomTop, "Area: the first tenth favours large faces");
  return havstest::Result();
}
