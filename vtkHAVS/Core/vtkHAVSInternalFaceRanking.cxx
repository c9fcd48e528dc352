/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSInternalFaceRanking.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSInternalFaceRanking.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMesh.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSInternalFaceRanking);

namespace
{
constexpr int kFieldBins = 128;

/// The radical inverse of i in base 2: 0, 1/2, 1/4, 3/4, 1/8, ... (an even
/// spread of the first n of 0, 1, 2, ...).
double RadicalInverse(uint32_t i)
{
  double r = 0.0, f = 0.5;
  while (i)
  {
    r += f * (i & 1u);
    i >>= 1;
    f *= 0.5;
  }
  return r;
}

/// The cross product (p1 - p0) x (p2 - p0) of a face: its normal times twice its area.
void FaceCross(const float* p, const uint32_t* v, double n[3])
{
  const float* a = p + 3 * static_cast<size_t>(v[0]);
  const float* b = p + 3 * static_cast<size_t>(v[1]);
  const float* c = p + 3 * static_cast<size_t>(v[2]);
  const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
}
}

//------------------------------------------------------------------------------
const char* vtkHAVSInternalFaceRanking::GetStrategyName(int strategy)
{
  switch (strategy)
  {
    case Topology:
      return "Topology";
    case ViewAligned:
      return "ViewAligned";
    case Field:
      return "Field";
    case Area:
      return "Area";
    case Random:
      return "Random";
    default:
      return "Unknown";
  }
}

//------------------------------------------------------------------------------
int vtkHAVSInternalFaceRanking::NormalCluster(const double n[3])
{
  int axis = 0;
  for (int i = 1; i < 3; ++i)
  {
    if (std::abs(n[i]) > std::abs(n[axis]))
    {
      axis = i;
    }
  }
  const double major = std::abs(n[axis]);
  if (!(major > 0.0))
  {
    return 0;
  }
  const int side = 2 * axis + (n[axis] < 0.0 ? 1 : 0);
  const double u = n[(axis + 1) % 3] / major, v = n[(axis + 2) % 3] / major; // in [-1, 1]
  const int iu = std::min(3, std::max(0, static_cast<int>((u + 1.0) * 2.0)));
  const int iv = std::min(3, std::max(0, static_cast<int>((v + 1.0) * 2.0)));
  return side * 16 + iu * 4 + iv;
}

void vtkHAVSInternalFaceRanking::ClusterDirection(int cluster, double d[3])
{
  const int side = cluster / 16, iu = (cluster % 16) / 4, iv = cluster % 4;
  const int axis = side / 2;
  d[axis] = (side % 2) ? -1.0 : 1.0;
  d[(axis + 1) % 3] = -1.0 + (iu + 0.5) * 0.5;
  d[(axis + 2) % 3] = -1.0 + (iv + 0.5) * 0.5;
  const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (int i = 0; i < 3; ++i)
  {
    d[i] /= l;
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSInternalFaceRanking::Update(vtkHAVSMesh* mesh, const ProgressCallback& progress)
{
  if (!mesh || !mesh->IsValid())
  {
    return false;
  }
  const bool scalarsMatter = this->Strategy == Field;
  if (this->MeshVersion == mesh->GetBuildTime() && this->RankedStrategy == this->Strategy &&
    this->RankedSeed == this->Seed &&
    (!scalarsMatter || this->ScalarVersion == mesh->GetScalarTime()))
  {
    return false;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  if (progress)
  {
    progress(0.0);
  }
  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const std::vector<uint8_t>& boundary = faces->GetBoundaryFlags();
  std::vector<uint32_t> internal;
  internal.reserve(boundary.size());
  this->NumberOfFaces = boundary.size();
  for (size_t f = 0; f < boundary.size(); ++f)
  {
    if (!boundary[f])
    {
      internal.push_back(static_cast<uint32_t>(f));
    }
  }
  this->NumberOfLayers = 0;
  this->FaceLayers.clear();
  this->ClusterStart.clear();
  this->ClusterFaces.clear();
  this->ViewRanked = false;
  switch (this->Strategy)
  {
    case Topology:
      this->RankTopology(mesh, internal, progress);
      break;
    case ViewAligned:
      this->ClusterNormals(mesh, internal);
      break;
    case Field:
      this->RankField(mesh, internal);
      break;
    case Area:
      this->RankArea(mesh, internal);
      break;
    default:
    {
      std::mt19937 random(this->Seed);
      std::shuffle(internal.begin(), internal.end(), random);
      this->Order = std::move(internal);
      break;
    }
  }
  this->RanksFromOrder();
  this->MeshVersion = mesh->GetBuildTime();
  this->ScalarVersion = mesh->GetScalarTime();
  this->RankedStrategy = this->Strategy;
  this->RankedSeed = this->Seed;
  this->LastSeconds = vtkTimerLog::GetUniversalTime() - start;
  if (progress)
  {
    progress(1.0);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSInternalFaceRanking::RanksFromOrder()
{
  this->Ranks.assign(this->NumberOfFaces, NoRank);
  const uint32_t* order = this->Order.data();
  uint32_t* ranks = this->Ranks.data();
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Order.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        ranks[order[i]] = static_cast<uint32_t>(i);
      }
    });
  this->RankTime.Modified();
}

//------------------------------------------------------------------------------
void vtkHAVSInternalFaceRanking::RankTopology(
  vtkHAVSMesh* mesh, const std::vector<uint32_t>& internal, const ProgressCallback& progress)
{
  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const std::vector<uint32_t>& faceVertices = faces->GetFaceVertices();
  const std::vector<uint32_t>& faceCells = faces->GetFaceCells();
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const std::vector<uint32_t>& tetCells = faces->GetTetrahedronCells();
  const size_t numFaces = faces->GetBoundaryFlags().size();
  const size_t numTets = tetCells.size();
  const size_t numPoints = mesh->GetPoints().size() / 3;

  // Grid cell -> tetrahedron, tetrahedron -> its faces, point -> its tetrahedra.
  std::vector<int32_t> cellToTet(mesh->GetGrid()->GetNumberOfCells(), -1);
  for (size_t t = 0; t < numTets; ++t)
  {
    if (tetCells[t] < cellToTet.size())
    {
      cellToTet[tetCells[t]] = static_cast<int32_t>(t);
    }
  }
  auto tetOf = [&](uint32_t cell) -> int32_t
  { return cell < cellToTet.size() ? cellToTet[cell] : -1; };
  std::vector<int32_t> tetFaces(4 * numTets, -1);
  std::vector<uint8_t> tetFaceCount(numTets, 0);
  for (size_t f = 0; f < numFaces; ++f)
  {
    for (int side = 0; side < 2; ++side)
    {
      const int32_t t = tetOf(faceCells[2 * f + side]);
      if (t >= 0 && tetFaceCount[t] < 4)
      {
        tetFaces[4 * static_cast<size_t>(t) + tetFaceCount[t]++] = static_cast<int32_t>(f);
      }
    }
  }
  std::vector<uint32_t> pointStart(numPoints + 1, 0);
  for (uint32_t p : tets)
  {
    if (p < numPoints)
    {
      ++pointStart[p + 1];
    }
  }
  std::partial_sum(pointStart.begin(), pointStart.end(), pointStart.begin());
  std::vector<uint32_t> pointTets(pointStart.back());
  {
    std::vector<uint32_t> fill(pointStart.begin(), pointStart.end() - 1);
    for (size_t i = 0; i < tets.size(); ++i)
    {
      if (tets[i] < numPoints)
      {
        pointTets[fill[tets[i]]++] = static_cast<uint32_t>(i / 4);
      }
    }
  }

  // Peel (EXTRACT_LAYERS): the faces with exactly one remaining cell are the
  // current layer; every remaining cell sharing a vertex with them goes.
  std::vector<uint8_t> remaining(numTets, 1);
  auto remainingCells = [&](size_t f)
  {
    int n = 0;
    for (int side = 0; side < 2; ++side)
    {
      const int32_t t = tetOf(faceCells[2 * f + side]);
      n += (t >= 0 && remaining[t]) ? 1 : 0;
    }
    return n;
  };
  this->FaceLayers.assign(numFaces, -1);
  std::vector<uint32_t> frontier;
  for (size_t f = 0; f < numFaces; ++f)
  {
    if (remainingCells(f) == 1)
    {
      frontier.push_back(static_cast<uint32_t>(f));
      this->FaceLayers[f] = 0;
    }
  }
  std::vector<uint8_t> pointMarked(numPoints, 0);
  std::vector<uint32_t> peeled;
  size_t peeledTotal = 0;
  int layer = 0;
  while (!frontier.empty())
  {
    peeled.clear();
    for (uint32_t f : frontier)
    {
      for (int i = 0; i < 3; ++i)
      {
        const uint32_t p = faceVertices[3 * static_cast<size_t>(f) + i];
        if (p >= numPoints || pointMarked[p])
        {
          continue;
        }
        pointMarked[p] = 1;
        for (uint32_t j = pointStart[p]; j < pointStart[p + 1]; ++j)
        {
          const uint32_t t = pointTets[j];
          if (remaining[t])
          {
            remaining[t] = 0;
            peeled.push_back(t);
          }
        }
      }
    }
    ++layer;
    frontier.clear();
    for (uint32_t t : peeled)
    {
      for (int i = 0; i < tetFaceCount[t]; ++i)
      {
        const int32_t f = tetFaces[4 * static_cast<size_t>(t) + i];
        if (this->FaceLayers[f] < 0 && remainingCells(f) == 1)
        {
          this->FaceLayers[f] = layer;
          frontier.push_back(static_cast<uint32_t>(f));
        }
      }
    }
    peeledTotal += peeled.size();
    if (progress && numTets > 0)
    {
      progress(0.9 * static_cast<double>(peeledTotal) / numTets);
    }
  }
  this->NumberOfLayers = layer;

  // Whole layers in an even spread (radical-inverse order of the layer
  // index), random order within each; the faces no layer reached last.
  std::mt19937 random(this->Seed);
  std::vector<std::vector<uint32_t>> byLayer(static_cast<size_t>(layer) + 1);
  std::vector<uint32_t> unreached;
  for (uint32_t f : internal)
  {
    const int l = this->FaceLayers[f];
    (l > 0 ? byLayer[l] : unreached).push_back(f);
  }
  std::vector<int> layers;
  for (int l = 1; l <= layer; ++l)
  {
    if (!byLayer[l].empty())
    {
      layers.push_back(l);
    }
  }
  std::stable_sort(layers.begin(), layers.end(),
    [](int a, int b)
    {
      return RadicalInverse(static_cast<uint32_t>(a - 1)) <
        RadicalInverse(static_cast<uint32_t>(b - 1));
    });
  this->Order.clear();
  this->Order.reserve(internal.size());
  for (int l : layers)
  {
    std::shuffle(byLayer[l].begin(), byLayer[l].end(), random);
    this->Order.insert(this->Order.end(), byLayer[l].begin(), byLayer[l].end());
  }
  std::shuffle(unreached.begin(), unreached.end(), random);
  this->Order.insert(this->Order.end(), unreached.begin(), unreached.end());
}

//------------------------------------------------------------------------------
void vtkHAVSInternalFaceRanking::RankField(vtkHAVSMesh* mesh, const std::vector<uint32_t>& internal)
{
  const std::vector<uint32_t>& faceVertices = mesh->GetFaceSet()->GetFaceVertices();
  const std::vector<float>& scalars = mesh->GetScalars();
  std::vector<uint8_t> bin(internal.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(internal.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const size_t f = internal[i];
        double mean = 0.0;
        for (int j = 0; j < 3; ++j)
        {
          const uint32_t p = faceVertices[3 * f + j];
          mean += p < scalars.size() ? scalars[p] : 0.0;
        }
        mean /= 3.0;
        const int b = (mean >= 0.0) ? static_cast<int>(mean * kFieldBins) : 0; // NaN -> 0
        bin[i] = static_cast<uint8_t>(std::min(kFieldBins - 1, b));
      }
    });
  std::vector<std::vector<uint32_t>> bins(kFieldBins);
  for (size_t i = 0; i < internal.size(); ++i)
  {
    bins[bin[i]].push_back(internal[i]);
  }
  std::mt19937 random(this->Seed);
  size_t longest = 0;
  for (auto& b : bins)
  {
    std::shuffle(b.begin(), b.end(), random);
    longest = std::max(longest, b.size());
  }
  // Stratified: one face from every bin that has one left, round after round.
  this->Order.clear();
  this->Order.reserve(internal.size());
  for (size_t r = 0; r < longest; ++r)
  {
    for (const auto& b : bins)
    {
      if (r < b.size())
      {
        this->Order.push_back(b[r]);
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSInternalFaceRanking::RankArea(vtkHAVSMesh* mesh, const std::vector<uint32_t>& internal)
{
  const std::vector<uint32_t>& faceVertices = mesh->GetFaceSet()->GetFaceVertices();
  const float* p = mesh->GetPoints().data();
  std::vector<double> key(internal.size());
  std::mt19937 random(this->Seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double& k : key)
  {
    k = uniform(random);
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(internal.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double n[3];
        FaceCross(p, faceVertices.data() + 3 * static_cast<size_t>(internal[i]), n);
        key[i] *= 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      }
    });
  std::vector<uint32_t> index(internal.size());
  std::iota(index.begin(), index.end(), 0u);
  vtkSMPTools::Sort(index.begin(), index.end(),
    [&](uint32_t a, uint32_t b) { return key[a] > key[b] || (key[a] == key[b] && a < b); });
  this->Order.resize(internal.size());
  for (size_t i = 0; i < index.size(); ++i)
  {
    this->Order[i] = internal[index[i]];
  }
}

//------------------------------------------------------------------------------
void vtkHAVSInternalFaceRanking::ClusterNormals(
  vtkHAVSMesh* mesh, const std::vector<uint32_t>& internal)
{
  const std::vector<uint32_t>& faceVertices = mesh->GetFaceSet()->GetFaceVertices();
  const float* p = mesh->GetPoints().data();
  std::vector<uint8_t> cluster(internal.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(internal.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double n[3];
        FaceCross(p, faceVertices.data() + 3 * static_cast<size_t>(internal[i]), n);
        cluster[i] = static_cast<uint8_t>(NormalCluster(n)); // needs no unit length
      }
    });
  this->ClusterStart.assign(NumberOfClusters + 1, 0);
  for (uint8_t c : cluster)
  {
    ++this->ClusterStart[c + 1];
  }
  std::partial_sum(
    this->ClusterStart.begin(), this->ClusterStart.end(), this->ClusterStart.begin());
  this->ClusterFaces.resize(internal.size());
  std::vector<uint32_t> fill(this->ClusterStart.begin(), this->ClusterStart.end() - 1);
  for (size_t i = 0; i < internal.size(); ++i)
  {
    this->ClusterFaces[fill[cluster[i]]++] = internal[i];
  }
  std::mt19937 random(this->Seed);
  for (int c = 0; c < NumberOfClusters; ++c)
  {
    std::shuffle(this->ClusterFaces.begin() + this->ClusterStart[c],
      this->ClusterFaces.begin() + this->ClusterStart[c + 1], random);
  }
  // Until a view ranks them: the clusters in index order.
  this->Order = this->ClusterFaces;
  std::iota(this->ClusterOrder.begin(), this->ClusterOrder.end(), 0);
}

//------------------------------------------------------------------------------
bool vtkHAVSInternalFaceRanking::UpdateView(const double direction[3])
{
  if (this->RankedStrategy != ViewAligned || this->ClusterStart.empty())
  {
    return false;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  const double l = std::sqrt(
    direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  if (!(l > 0.0))
  {
    return false;
  }
  // The clusters by how squarely they face the view (either side).
  double score[NumberOfClusters];
  for (int c = 0; c < NumberOfClusters; ++c)
  {
    double d[3];
    ClusterDirection(c, d);
    score[c] = std::abs(d[0] * direction[0] + d[1] * direction[1] + d[2] * direction[2]) / l;
  }
  std::array<int, NumberOfClusters> order;
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return score[a] > score[b]; });
  if (this->ViewRanked && order == this->ClusterOrder)
  {
    this->LastViewSeconds = 0.0;
    return false;
  }
  this->ClusterOrder = order;
  this->ViewRanked = true;
  this->Order.clear();
  for (int c : order)
  {
    this->Order.insert(this->Order.end(), this->ClusterFaces.begin() + this->ClusterStart[c],
      this->ClusterFaces.begin() + this->ClusterStart[c + 1]);
  }
  this->RanksFromOrder();
  this->LastViewSeconds = vtkTimerLog::GetUniversalTime() - start;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSInternalFaceRanking::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Strategy: " << GetStrategyName(this->Strategy) << ", seed " << this->Seed
     << "\n";
  os << indent << "Internal faces ranked: " << this->Order.size();
  if (this->RankedStrategy == Topology)
  {
    os << " (" << this->NumberOfLayers << " layers)";
  }
  os << ", " << this->LastSeconds << " s, " << this->GetMemoryBytes() << " bytes\n";
}

//------------------------------------------------------------------------------
size_t vtkHAVSInternalFaceRanking::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(
    this->Ranks, this->Order, this->FaceLayers, this->ClusterStart, this->ClusterFaces);
}

VTK_ABI_NAMESPACE_END
