/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceSet.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSFaceSet.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkHAVSVTKCompat.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <tuple>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSFaceSet);

namespace
{
/// Local point indices of the four faces of a tetrahedron; the last entry is
/// the point opposite the face.
constexpr int TetrahedronFaces[4][4] = { { 0, 1, 2, 3 }, { 0, 1, 3, 2 }, { 0, 2, 3, 1 },
  { 1, 2, 3, 0 } };

enum CellStatus : uint8_t
{
  NotATetrahedron,
  GhostCell,
  DegenerateTetrahedron,
  InvalidPointIndex, ///< a point id < 0 or >= the number of points
  DuplicateTetrahedron,
  UsedTetrahedron
};

/// Every cell as four point ids (meaningful for tetrahedra only) and a status.
struct CellTable
{
  std::vector<uint32_t> PointIds;
  std::vector<uint8_t> Status;
};

/// What ReadCells found; also the per-thread partial result.
struct CellCounts
{
  vtkIdType Used = 0;
  vtkIdType Skipped = 0;
  vtkIdType Degenerate = 0;
  vtkIdType Invalid = 0;
  vtkIdType Ghost = 0;
  vtkIdType Thin = 0;      ///< of Degenerate: thinner than the relative bound (DropThinCells)
  vtkIdType Collapsed = 0; ///< of Degenerate: a point id repeated (a collapsed cell's piece)
  double LongestEdgeSquared = 0.0;
  double Bounds[6] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
    std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
    std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest() };
};

/// One face of a used tetrahedron, filed under its smallest point id: the two
/// other ids ascending, the tetrahedron's fourth point (to orient the face)
/// and the tetrahedron's cell id in the grid.
struct FaceUse
{
  uint32_t Middle;
  uint32_t Largest;
  uint32_t Opposite;
  uint32_t Cell;

  bool operator<(const FaceUse& other) const
  {
    return std::tie(this->Middle, this->Largest, this->Opposite) <
      std::tie(other.Middle, other.Largest, other.Opposite);
  }
  bool SameFace(const FaceUse& other) const
  {
    return this->Middle == other.Middle && this->Largest == other.Largest;
  }
};

/// The end of the run of uses of `run`'s face in a sorted bucket.
const FaceUse* EndOfFace(const FaceUse* run, const FaceUse* last)
{
  const FaceUse* end = run + 1;
  while (end != last && end->SameFace(*run))
  {
    ++end;
  }
  return end;
}

/// Face uses grouped by smallest point id: bucket p is Uses[Start[p], Start[p + 1]).
struct FaceUseBuckets
{
  std::vector<vtkIdType> Start;
  std::vector<FaceUse> Uses;
};

/// Boundary and non-manifold faces, also per thread.
struct FaceCounts
{
  vtkIdType Boundary = 0;
  vtkIdType NonManifold = 0;
  vtkIdType RepeatedUses = 0; // two uses with the same opposite point: duplicate cells
};

/// Face `face` of the tetrahedron `ids`: its ids ascending, then the opposite point.
void SortedFace(const uint32_t* ids, int face, uint32_t out[4])
{
  const int* local = TetrahedronFaces[face];
  uint32_t a = ids[local[0]], b = ids[local[1]], c = ids[local[2]];
  if (a > b)
  {
    std::swap(a, b);
  }
  if (b > c)
  {
    std::swap(b, c);
  }
  if (a > b)
  {
    std::swap(a, b);
  }
  out[0] = a;
  out[1] = b;
  out[2] = c;
  out[3] = ids[local[3]];
}

/// |x1 - x0|.
double EdgeLength(const double* x0, const double* x1)
{
  const double d[3] = { x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2] };
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/// ((x1 - x0) x (x2 - x0)) . (x3 - x0): six times the signed volume of the
/// tetrahedron x0 x1 x2 x3, positive when x3 lies on the side the normal of
/// the triangle x0 x1 x2 points to.
double TripleProduct(const double* x0, const double* x1, const double* x2, const double* x3)
{
  double a[3], b[3], d[3];
  for (int k = 0; k < 3; ++k)
  {
    a[k] = x1[k] - x0[k];
    b[k] = x2[k] - x0[k];
    d[k] = x3[k] - x0[k];
  }
  return d[0] * (a[1] * b[2] - a[2] * b[1]) + d[1] * (a[2] * b[0] - a[0] * b[2]) +
    d[2] * (a[0] * b[1] - a[1] * b[0]);
}

/// The point coordinates as doubles, three per point.
std::vector<double> CopyCoordinates(vtkPoints* points)
{
  vtkDataArray* data = points->GetData();
  std::vector<double> coordinates(3 * static_cast<size_t>(points->GetNumberOfPoints()));
  vtkSMPTools::For(0, points->GetNumberOfPoints(),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        data->GetTuple(i, &coordinates[3 * i]);
      }
    });
  return coordinates;
}

/// Fills a CellTable from the grid's cells, whatever the storage type of the
/// cell array: tetrahedra with repeated points or a volume within the
/// rounding of its own computation (|6 V| <= 16 eps |a| |b| |d|, the edges from
/// the first point; eps of double) are degenerate. Scale-free and shape-free:
/// a needle 1e6 times longer than wide keeps its volume (relative 1e-12),
/// four points of one plane do not.
struct ReadCells
{
  template <typename CellStateT>
  void operator()(CellStateT& state, const unsigned char* types, const unsigned char* ghosts,
    const double* coordinates, vtkIdType numberOfPoints, CellTable& table,
    vtkSMPThreadLocal<CellCounts>& counts) const
  {
    using ValueType = typename CellStateT::ValueType;
    const ValueType* offsets = state.GetOffsets()->GetPointer(0);
    const ValueType* connectivity = state.GetConnectivity()->GetPointer(0);
    vtkSMPTools::For(0, state.GetNumberOfCells(),
      [&](vtkIdType begin, vtkIdType end)
      {
        CellCounts& local = counts.Local();
        for (vtkIdType cell = begin; cell < end; ++cell)
        {
          const ValueType first = offsets[cell];
          if (ghosts &&
            (ghosts[cell] &
              (vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL)) != 0)
          {
            table.Status[cell] = GhostCell; // another piece draws it (or it is hidden)
            ++local.Ghost;
            continue;
          }
          if (types[cell] != VTK_TETRA || offsets[cell + 1] - first != 4)
          {
            table.Status[cell] = NotATetrahedron;
            ++local.Skipped;
            continue;
          }
          uint32_t* ids = &table.PointIds[4 * cell];
          const double* x[4];
          bool valid = true;
          for (int i = 0; i < 4; ++i)
          {
            const ValueType id = connectivity[first + i];
            valid = valid && id >= 0 && static_cast<vtkIdType>(id) < numberOfPoints;
            ids[i] = valid ? static_cast<uint32_t>(id) : 0u;
            x[i] = coordinates + 3 * static_cast<size_t>(ids[i]);
          }
          if (!valid)
          {
            // A corrupt file's cell: never read past the points.
            table.Status[cell] = InvalidPointIndex;
            ++local.Invalid;
            continue;
          }
          const double sixVolume = TripleProduct(x[0], x[1], x[2], x[3]);
          const double rounding = 16.0 * std::numeric_limits<double>::epsilon() *
            EdgeLength(x[0], x[1]) * EdgeLength(x[0], x[2]) * EdgeLength(x[0], x[3]);
          const bool repeated = ids[0] == ids[1] || ids[0] == ids[2] || ids[0] == ids[3] ||
            ids[1] == ids[2] || ids[1] == ids[3] || ids[2] == ids[3];
          // Written so that a NaN volume is degenerate too.
          if (repeated || !(std::fabs(sixVolume) > rounding))
          {
            table.Status[cell] = DegenerateTetrahedron;
            ++local.Degenerate;
            local.Collapsed += repeated ? 1 : 0;
            continue;
          }
          table.Status[cell] = UsedTetrahedron;
          ++local.Used;
          for (int i = 0; i < 4; ++i)
          {
            for (int k = 0; k < 3; ++k)
            {
              local.Bounds[2 * k] = std::min(local.Bounds[2 * k], x[i][k]);
              local.Bounds[2 * k + 1] = std::max(local.Bounds[2 * k + 1], x[i][k]);
            }
          }
        }
      });
  }
};

/// The second look at the used tetrahedra, once the used cells' bounds are
/// known: a tetrahedron whose smallest height (|6 V| over |n|, n the cross
/// product of its largest face) is at most `relative` times the mesh's extent
/// along n (sum over the axes of |n_k| / |n| times the bounds' extent: what the
/// float coordinates, shifted by the bounds' centre, resolve in that
/// direction) is dropped as degenerate (counted in Thin too). Also the longest
/// edge of the tetrahedra kept.
void DropThinCells(CellTable& table, const double* coordinates, double relative,
  const double extent[3], vtkSMPThreadLocal<CellCounts>& counts)
{
  const vtkIdType numberOfCells = static_cast<vtkIdType>(table.Status.size());
  vtkSMPTools::For(0, numberOfCells,
    [&](vtkIdType begin, vtkIdType end)
    {
      CellCounts& local = counts.Local();
      for (vtkIdType cell = begin; cell < end; ++cell)
      {
        if (table.Status[cell] != UsedTetrahedron)
        {
          continue;
        }
        const uint32_t* ids = &table.PointIds[4 * cell];
        const double* x[4];
        for (int i = 0; i < 4; ++i)
        {
          x[i] = coordinates + 3 * static_cast<size_t>(ids[i]);
        }
        double longestSquared = 0.0;
        for (int i = 0; i < 4; ++i)
        {
          for (int j = i + 1; j < 4; ++j)
          {
            const double d[3] = { x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2] };
            longestSquared = std::max(longestSquared, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
          }
        }
        double largestDoubleArea = 0.0;
        double alongNormal = 0.0; // sum |n_k| extent_k of the largest face's n
        for (const int* face : TetrahedronFaces)
        {
          const double* p = x[face[0]];
          const double* q = x[face[1]];
          const double* r = x[face[2]];
          const double a[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
          const double b[3] = { r[0] - p[0], r[1] - p[1], r[2] - p[2] };
          const double n[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0] };
          const double doubleArea = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
          if (doubleArea > largestDoubleArea)
          {
            largestDoubleArea = doubleArea;
            alongNormal = std::fabs(n[0]) * extent[0] + std::fabs(n[1]) * extent[1] +
              std::fabs(n[2]) * extent[2];
          }
        }
        const double sixVolume = std::fabs(TripleProduct(x[0], x[1], x[2], x[3]));
        if (sixVolume <= relative * alongNormal)
        {
          table.Status[cell] = DegenerateTetrahedron;
          ++local.Thin;
          continue;
        }
        local.LongestEdgeSquared = std::max(local.LongestEdgeSquared, longestSquared);
      }
    });
}

/// Files the four faces of every used tetrahedron under their smallest point id
/// (a counting sort: count per bucket, prefix sum, scatter).
FaceUseBuckets FileFaceUses(const CellTable& table, vtkIdType numberOfPoints)
{
  const vtkIdType numberOfCells = static_cast<vtkIdType>(table.Status.size());
  std::vector<std::atomic<vtkIdType>> cursor(static_cast<size_t>(numberOfPoints));
  auto forEachFaceUse = [&](auto&& visit)
  {
    vtkSMPTools::For(0, numberOfCells,
      [&](vtkIdType begin, vtkIdType end)
      {
        uint32_t face[4];
        for (vtkIdType cell = begin; cell < end; ++cell)
        {
          if (table.Status[cell] != UsedTetrahedron)
          {
            continue;
          }
          for (int f = 0; f < 4; ++f)
          {
            SortedFace(&table.PointIds[4 * cell], f, face);
            visit(face, static_cast<uint32_t>(cell));
          }
        }
      });
  };

  forEachFaceUse([&](const uint32_t* face, uint32_t)
    { cursor[face[0]].fetch_add(1, std::memory_order_relaxed); });
  FaceUseBuckets buckets;
  buckets.Start.resize(static_cast<size_t>(numberOfPoints) + 1);
  buckets.Start[0] = 0;
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    buckets.Start[p + 1] = buckets.Start[p] + cursor[p].load(std::memory_order_relaxed);
    cursor[p].store(buckets.Start[p], std::memory_order_relaxed);
  }
  buckets.Uses.resize(static_cast<size_t>(buckets.Start[numberOfPoints]));
  forEachFaceUse(
    [&](const uint32_t* face, uint32_t cell)
    {
      const vtkIdType at = cursor[face[0]].fetch_add(1, std::memory_order_relaxed);
      buckets.Uses[at] = FaceUse{ face[1], face[2], face[3], cell };
    });
  return buckets;
}

/// Sorts every bucket (so that equal faces are adjacent and the order does not
/// depend on the scatter's thread interleaving) and fills faceStart: the faces
/// of bucket p are numbered faceStart[p] .. faceStart[p + 1] - 1.
FaceCounts SortBuckets(FaceUseBuckets& buckets, std::vector<vtkIdType>& faceStart)
{
  const vtkIdType numberOfBuckets = static_cast<vtkIdType>(buckets.Start.size()) - 1;
  faceStart.assign(buckets.Start.size(), 0);
  vtkSMPThreadLocal<FaceCounts> counts;
  vtkSMPTools::For(0, numberOfBuckets,
    [&](vtkIdType begin, vtkIdType end)
    {
      FaceCounts& local = counts.Local();
      for (vtkIdType p = begin; p < end; ++p)
      {
        FaceUse* first = buckets.Uses.data() + buckets.Start[p];
        FaceUse* last = buckets.Uses.data() + buckets.Start[p + 1];
        std::sort(first, last);
        vtkIdType faces = 0;
        for (const FaceUse* run = first; run != last;)
        {
          const FaceUse* runEnd = EndOfFace(run, last);
          const auto uses = runEnd - run;
          local.Boundary += uses == 1 ? 1 : 0;
          local.NonManifold += uses > 2 ? 1 : 0;
          for (const FaceUse* u = run + 1; u != runEnd; ++u)
          {
            local.RepeatedUses += u->Opposite == (u - 1)->Opposite ? 1 : 0;
          }
          ++faces;
          run = runEnd;
        }
        faceStart[p + 1] = faces;
      }
    });
  for (vtkIdType p = 0; p < numberOfBuckets; ++p)
  {
    faceStart[p + 1] += faceStart[p];
  }
  FaceCounts total;
  for (const FaceCounts& local : counts)
  {
    total.Boundary += local.Boundary;
    total.NonManifold += local.NonManifold;
    total.RepeatedUses += local.RepeatedUses;
  }
  return total;
}

/// Marks every used tetrahedron with the same four points as an earlier one
/// (in cell order) a duplicate; returns how many. Only called when a face
/// had two uses with the same opposite point, which duplicates cause.
vtkIdType MarkDuplicateCells(CellTable& table)
{
  std::vector<std::pair<std::array<uint32_t, 4>, vtkIdType>> keys;
  for (size_t c = 0; c < table.Status.size(); ++c)
  {
    if (table.Status[c] == UsedTetrahedron)
    {
      std::array<uint32_t, 4> ids;
      std::copy_n(&table.PointIds[4 * c], 4, ids.begin());
      std::sort(ids.begin(), ids.end());
      keys.emplace_back(ids, static_cast<vtkIdType>(c));
    }
  }
  vtkSMPTools::Sort(keys.begin(), keys.end());
  vtkIdType duplicates = 0;
  for (size_t i = 1; i < keys.size(); ++i)
  {
    if (keys[i].first == keys[i - 1].first)
    {
      table.Status[keys[i].second] = DuplicateTetrahedron; // (the first in cell order is kept)
      ++duplicates;
    }
  }
  return duplicates;
}

/// Writes one face per run of the sorted buckets: ids (boundary faces wound
/// away from their tetrahedron's fourth point, internal ones ascending),
/// boundary flag, centroid minus `origin`, and the cells on either side (the
/// one the winding's normal points into first). The arrays are already sized.
void WriteFaces(const FaceUseBuckets& buckets, const std::vector<vtkIdType>& faceStart,
  const std::vector<double>& coordinates, std::vector<uint32_t>& vertices,
  std::vector<uint8_t>& boundaryFlags, std::vector<uint32_t>& faceCells)
{
  const vtkIdType numberOfBuckets = static_cast<vtkIdType>(buckets.Start.size()) - 1;
  auto point = [&](uint32_t id) { return &coordinates[3 * static_cast<size_t>(id)]; };
  vtkSMPTools::For(0, numberOfBuckets,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        const FaceUse* run = buckets.Uses.data() + buckets.Start[p];
        const FaceUse* last = buckets.Uses.data() + buckets.Start[p + 1];
        for (vtkIdType face = faceStart[p]; run != last; ++face)
        {
          const FaceUse* runEnd = EndOfFace(run, last);
          uint32_t ids[3] = { static_cast<uint32_t>(p), run->Middle, run->Largest };
          const bool boundary = runEnd - run == 1;
          // Outward: (x1 - x0) x (x2 - x0) must point away from the fourth point.
          if (boundary &&
            TripleProduct(point(ids[0]), point(ids[1]), point(ids[2]), point(run->Opposite)) > 0.0)
          {
            std::swap(ids[1], ids[2]);
          }
          boundaryFlags[face] = boundary ? 1 : 0;
          // The cells on either side: a use whose fourth point lies on the
          // normal's side is the cell the normal points into. (A non-manifold
          // face keeps one use per side.)
          uint32_t* sides = &faceCells[2 * face];
          sides[0] = sides[1] = vtkHAVSFaceSet::NoCell;
          for (const FaceUse* u = run; u != runEnd; ++u)
          {
            const bool normalSide =
              TripleProduct(point(ids[0]), point(ids[1]), point(ids[2]), point(u->Opposite)) > 0.0;
            uint32_t& side = sides[normalSide ? 0 : 1];
            if (side == vtkHAVSFaceSet::NoCell)
            {
              side = u->Cell;
            }
          }
          for (int k = 0; k < 3; ++k)
          {
            vertices[3 * face + k] = ids[k];
          }
          run = runEnd;
        }
      }
    });
}

/// Whether the outward-wound boundary faces form one closed, connected,
/// 2-manifold surface, locally convex at every edge (see IsConvex()).
bool BoundaryIsConvex(const std::vector<uint32_t>& faceVertices,
  const std::vector<uint8_t>& boundaryFlags, const std::vector<double>& coordinates,
  double tolerance)
{
  struct EdgeUse
  {
    uint64_t Key;      // the edge's two point ids, smaller first
    uint32_t Face;     // index among the boundary faces
    uint32_t Opposite; // the face's third point
  };
  std::vector<uint32_t> faces; // the boundary faces' indices
  for (size_t f = 0; f < boundaryFlags.size(); ++f)
  {
    if (boundaryFlags[f])
    {
      faces.push_back(static_cast<uint32_t>(f));
    }
  }
  if (faces.size() < 4)
  {
    return false;
  }
  std::vector<EdgeUse> uses;
  uses.reserve(3 * faces.size());
  for (uint32_t b = 0; b < faces.size(); ++b)
  {
    const uint32_t* v = &faceVertices[3 * static_cast<size_t>(faces[b])];
    for (int e = 0; e < 3; ++e)
    {
      const uint64_t p = v[e], q = v[(e + 1) % 3];
      uses.push_back({ p < q ? (p << 32 | q) : (q << 32 | p), b, v[(e + 2) % 3] });
    }
  }
  std::sort(
    uses.begin(), uses.end(), [](const EdgeUse& a, const EdgeUse& b) { return a.Key < b.Key; });

  // Union-find over the boundary faces: one component.
  std::vector<uint32_t> parent(faces.size());
  for (uint32_t i = 0; i < parent.size(); ++i)
  {
    parent[i] = i;
  }
  auto root = [&](uint32_t i)
  {
    while (parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  // The far point lies on the inner side of the face's plane.
  auto inside = [&](uint32_t b, uint32_t point)
  {
    const uint32_t* v = &faceVertices[3 * static_cast<size_t>(faces[b])];
    const double* a = &coordinates[3 * static_cast<size_t>(v[0])];
    const double* c1 = &coordinates[3 * static_cast<size_t>(v[1])];
    const double* c2 = &coordinates[3 * static_cast<size_t>(v[2])];
    const double* x = &coordinates[3 * static_cast<size_t>(point)];
    const double e1[3] = { c1[0] - a[0], c1[1] - a[1], c1[2] - a[2] };
    const double e2[3] = { c2[0] - a[0], c2[1] - a[1], c2[2] - a[2] };
    double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0] };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length == 0.0)
    {
      return false;
    }
    const double d = (n[0] * (x[0] - a[0]) + n[1] * (x[1] - a[1]) + n[2] * (x[2] - a[2])) / length;
    return d <= tolerance;
  };
  size_t components = faces.size();
  for (size_t i = 0; i < uses.size();)
  {
    size_t j = i;
    while (j < uses.size() && uses[j].Key == uses[i].Key)
    {
      ++j;
    }
    if (j - i != 2)
    {
      return false; // an open or non-manifold boundary
    }
    const EdgeUse& u = uses[i];
    const EdgeUse& w = uses[i + 1];
    if (!inside(u.Face, w.Opposite) || !inside(w.Face, u.Opposite))
    {
      return false; // a concave (reflex) edge
    }
    const uint32_t ru = root(u.Face), rw = root(w.Face);
    if (ru != rw)
    {
      parent[ru] = rw;
      --components;
    }
    i = j;
  }
  return components == 1;
}
}

//------------------------------------------------------------------------------
void vtkHAVSFaceSet::Clear()
{
  this->Tetrahedra.clear();
  this->Convex = false;
  this->NumberOfGhostCells = 0;
  this->FaceVertices.clear();
  this->FaceCells.clear();
  this->TetrahedronCells.clear();
  this->BoundaryFlags.clear();
  this->Centroids.clear();
  this->BuiltPoints = nullptr;
  this->NumberOfBoundaryFaces = 0;
  this->NumberOfNonManifoldFaces = 0;
  this->NumberOfTetrahedra = 0;
  this->NumberOfSkippedCells = 0;
  this->NumberOfDegenerateTetrahedra = 0;
  this->NumberOfCollapsedTetrahedra = 0;
  this->NumberOfThinTetrahedra = 0;
  this->NumberOfInvalidCells = 0;
  this->NumberOfDuplicateTetrahedra = 0;
  this->LongestEdge = 0.0;
  std::fill(this->CentroidOrigin, this->CentroidOrigin + 3, 0.0);
}

//------------------------------------------------------------------------------
const std::vector<float>& vtkHAVSFaceSet::GetCentroids() const
{
  const size_t numberOfFaces = this->FaceVertices.size() / 3;
  if (this->Centroids.size() == 3 * numberOfFaces || !this->BuiltPoints)
  {
    return this->Centroids;
  }
  // In double from the points, in the faces' vertex order, then relative to
  // the origin in float.
  const std::vector<double> coordinates = CopyCoordinates(this->BuiltPoints);
  this->Centroids.resize(3 * numberOfFaces);
  const uint32_t* vertices = this->FaceVertices.data();
  const double* origin = this->CentroidOrigin;
  float* centroids = this->Centroids.data();
  vtkSMPTools::For(0, static_cast<vtkIdType>(numberOfFaces),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        const double* p[3];
        for (int v = 0; v < 3; ++v)
        {
          p[v] = &coordinates[3 * static_cast<size_t>(vertices[3 * f + v])];
        }
        for (int k = 0; k < 3; ++k)
        {
          centroids[3 * f + k] =
            static_cast<float>((p[0][k] + p[1][k] + p[2][k]) / 3.0 - origin[k]);
        }
      }
    });
  return this->Centroids;
}

//------------------------------------------------------------------------------
bool vtkHAVSFaceSet::Build(vtkUnstructuredGrid* grid)
{
  this->Clear();
  this->BuildTime.Modified();
  if (!grid)
  {
    vtkErrorMacro("Build: no grid.");
    return false;
  }
  vtkPoints* points = grid->GetPoints();
  const vtkIdType numberOfPoints = points ? points->GetNumberOfPoints() : 0;
  if (numberOfPoints == 0)
  {
    vtkErrorMacro("Build: the grid has no points.");
    return false;
  }
  if (static_cast<uint64_t>(numberOfPoints) > std::numeric_limits<uint32_t>::max())
  {
    vtkErrorMacro("Build: " << numberOfPoints << " points do not fit 32-bit point ids.");
    return false;
  }
  if (static_cast<uint64_t>(grid->GetNumberOfCells()) >= std::numeric_limits<uint32_t>::max())
  {
    vtkErrorMacro("Build: " << grid->GetNumberOfCells() << " cells do not fit 32-bit cell ids.");
    return false;
  }

  // The cells: which are usable tetrahedra.
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  const std::vector<double> coordinates = CopyCoordinates(points);
  CellTable table;
  CellCounts cells;
  if (numberOfCells > 0)
  {
    table.PointIds.resize(4 * static_cast<size_t>(numberOfCells));
    table.Status.resize(static_cast<size_t>(numberOfCells));
    vtkSMPThreadLocal<CellCounts> counts;
    vtkUnsignedCharArray* ghostArray = grid->GetCellGhostArray();
    const vtkSmartPointer<vtkUnsignedCharArray> types = havs_vtk::CellTypeBytes(grid);
    if (!types || types->GetNumberOfTuples() < numberOfCells)
    {
      vtkErrorMacro("Build: the grid has " << numberOfCells << " cells but "
                                           << (types ? types->GetNumberOfTuples() : 0)
                                           << " cell types.");
      return false;
    }
    havs_vtk::VisitCells(grid->GetCells(), ReadCells{}, types->GetPointer(0),
      ghostArray ? ghostArray->GetPointer(0) : nullptr, coordinates.data(), numberOfPoints, table,
      counts);
    for (const CellCounts& local : counts)
    {
      cells.Used += local.Used;
      cells.Skipped += local.Skipped;
      cells.Degenerate += local.Degenerate;
      cells.Collapsed += local.Collapsed;
      cells.Invalid += local.Invalid;
      cells.Ghost += local.Ghost;
      for (int k = 0; k < 3; ++k)
      {
        cells.Bounds[2 * k] = std::min(cells.Bounds[2 * k], local.Bounds[2 * k]);
        cells.Bounds[2 * k + 1] = std::max(cells.Bounds[2 * k + 1], local.Bounds[2 * k + 1]);
      }
    }
    if (cells.Used > 0)
    {
      // Cells too thin for the float coordinates the GPU draws with.
      const double extent[3] = { cells.Bounds[1] - cells.Bounds[0],
        cells.Bounds[3] - cells.Bounds[2], cells.Bounds[5] - cells.Bounds[4] };
      vtkSMPThreadLocal<CellCounts> thin;
      DropThinCells(table, coordinates.data(), this->MinimumRelativeThickness, extent, thin);
      for (const CellCounts& local : thin)
      {
        cells.Thin += local.Thin;
        cells.LongestEdgeSquared = std::max(cells.LongestEdgeSquared, local.LongestEdgeSquared);
      }
      cells.Used -= cells.Thin;
      cells.Degenerate += cells.Thin;
    }
  }
  this->NumberOfSkippedCells = cells.Skipped;
  this->NumberOfDegenerateTetrahedra = cells.Degenerate;
  this->NumberOfThinTetrahedra = cells.Thin;
  this->NumberOfCollapsedTetrahedra = cells.Collapsed;
  this->NumberOfInvalidCells = cells.Invalid;
  this->NumberOfGhostCells = cells.Ghost;
  if (cells.Used == 0)
  {
    vtkErrorMacro("Build: no usable tetrahedra ("
      << numberOfCells << " cells, " << cells.Skipped << " not tetrahedra, " << cells.Degenerate
      << " degenerate, " << cells.Invalid << " with point ids out of range).");
    return false;
  }
  this->NumberOfTetrahedra = cells.Used;
  this->LongestEdge = std::sqrt(cells.LongestEdgeSquared);

  // The unique faces: equal runs of the sorted buckets. Duplicate cells (the
  // same four points twice) show as a face used twice from the same side:
  // they are dropped (one copy kept) and the faces filed again.
  FaceUseBuckets buckets = FileFaceUses(table, numberOfPoints);
  std::vector<vtkIdType> faceStart;
  FaceCounts faceCounts = SortBuckets(buckets, faceStart);
  if (faceCounts.RepeatedUses > 0)
  {
    this->NumberOfDuplicateTetrahedra = MarkDuplicateCells(table);
    cells.Used -= this->NumberOfDuplicateTetrahedra;
    this->NumberOfTetrahedra = cells.Used;
    buckets = FileFaceUses(table, numberOfPoints);
    faceCounts = SortBuckets(buckets, faceStart);
  }
  this->NumberOfBoundaryFaces = faceCounts.Boundary;
  this->NumberOfNonManifoldFaces = faceCounts.NonManifold;
  const size_t numberOfFaces = static_cast<size_t>(faceStart.back());
  this->FaceVertices.resize(3 * numberOfFaces);
  this->BoundaryFlags.resize(numberOfFaces);
  this->FaceCells.resize(2 * numberOfFaces);

  double bounds[6];
  points->GetBounds(bounds);
  for (int k = 0; k < 3; ++k)
  {
    this->CentroidOrigin[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
  }

  WriteFaces(
    buckets, faceStart, coordinates, this->FaceVertices, this->BoundaryFlags, this->FaceCells);
  this->BuiltPoints = points;

  this->Tetrahedra.reserve(4 * static_cast<size_t>(cells.Used));
  this->TetrahedronCells.reserve(static_cast<size_t>(cells.Used));
  for (size_t c = 0; c < table.Status.size(); ++c)
  {
    if (table.Status[c] == UsedTetrahedron)
    {
      this->TetrahedronCells.push_back(static_cast<uint32_t>(c));
      this->Tetrahedra.insert(
        this->Tetrahedra.end(), table.PointIds.begin() + 4 * c, table.PointIds.begin() + 4 * c + 4);
    }
  }
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  this->Convex = this->NumberOfNonManifoldFaces == 0 &&
    BoundaryIsConvex(this->FaceVertices, this->BoundaryFlags, coordinates, 1e-9 * diagonal);
  return true;
}

//------------------------------------------------------------------------------
std::vector<uint8_t> vtkHAVSFaceSet::GetPointUse(vtkIdType numberOfPoints) const
{
  std::vector<uint8_t> used(static_cast<size_t>(numberOfPoints), 0);
  for (uint32_t id : this->Tetrahedra)
  {
    used[id] = 1;
  }
  return used;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceSet::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfFaces: " << this->GetNumberOfFaces() << "\n";
  os << indent << "NumberOfBoundaryFaces: " << this->NumberOfBoundaryFaces << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "NumberOfSkippedCells: " << this->NumberOfSkippedCells << "\n";
  os << indent << "NumberOfCollapsedTetrahedra: " << this->NumberOfCollapsedTetrahedra << "\n";
  os << indent << "NumberOfDegenerateTetrahedra: " << this->NumberOfDegenerateTetrahedra
     << " (thinner than the bound: " << this->NumberOfThinTetrahedra << ")\n";
  os << indent << "MinimumRelativeThickness: " << this->MinimumRelativeThickness << "\n";
  os << indent << "NumberOfInvalidCells: " << this->NumberOfInvalidCells << "\n";
  os << indent << "NumberOfDuplicateTetrahedra: " << this->NumberOfDuplicateTetrahedra << "\n";
  os << indent << "LongestEdge: " << this->LongestEdge << "\n";
  os << indent << "CentroidOrigin: (" << this->CentroidOrigin[0] << ", " << this->CentroidOrigin[1]
     << ", " << this->CentroidOrigin[2] << ")\n";
}

//------------------------------------------------------------------------------
size_t vtkHAVSFaceSet::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(this->FaceVertices, this->BoundaryFlags, this->Centroids,
    this->Tetrahedra, this->TetrahedronCells, this->FaceCells);
}

VTK_ABI_NAMESPACE_END
