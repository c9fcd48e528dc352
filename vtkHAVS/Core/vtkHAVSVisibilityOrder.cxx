/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSVisibilityOrder.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSVisibilityOrder.h"

#include "vtkHAVSViewFrame.h"

#include "vtkHAVSConvexification.h"
#include "vtkHAVSFaceRasterizer.h"
#include "vtkHAVSFaceSet.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSVisibilityOrder);

//------------------------------------------------------------------------------
vtkHAVSVisibilityOrder::vtkHAVSVisibilityOrder()
  : Rasterizer(vtkSmartPointer<vtkHAVSFaceRasterizer>::New())
{
}

//------------------------------------------------------------------------------
vtkHAVSVisibilityOrder::~vtkHAVSVisibilityOrder() = default;

namespace
{
using Key = std::array<uint32_t, 3>;

/// Which side of plane p (n, d) the eye is on: > 0 on the side n points to;
/// a parallel projection decides by the direction of projection alone.
double EyeSide(const double* p, const double eye[3], const double direction[3], bool parallel)
{
  return parallel ? -(p[0] * direction[0] + p[1] * direction[1] + p[2] * direction[2])
                  : p[0] * eye[0] + p[1] * eye[1] + p[2] * eye[2] + p[3];
}

Key SortedKey(uint32_t a, uint32_t b, uint32_t c)
{
  Key k = { a, b, c };
  std::sort(k.begin(), k.end());
  return k;
}
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::FacePlane(size_t f, double plane[4]) const
{
  const uint32_t* ids = &this->Faces->GetFaceVertices()[3 * f];
  const double* v0 = &this->Points[3 * static_cast<size_t>(ids[0])];
  const double* v1 = &this->Points[3 * static_cast<size_t>(ids[1])];
  const double* v2 = &this->Points[3 * static_cast<size_t>(ids[2])];
  const double e1[3] = { v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2] };
  const double e2[3] = { v2[0] - v0[0], v2[1] - v0[1], v2[2] - v0[2] };
  plane[0] = e1[1] * e2[2] - e1[2] * e2[1];
  plane[1] = e1[2] * e2[0] - e1[0] * e2[2];
  plane[2] = e1[0] * e2[1] - e1[1] * e2[0];
  plane[3] = -(plane[0] * v0[0] + plane[1] * v0[1] + plane[2] * v0[2]);
  if (this->FaceFlags[f] & FaceFlipped)
  {
    for (int i = 0; i < 4; ++i)
    {
      plane[i] = -plane[i];
    }
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSVisibilityOrder::FacesUnchanged()
{
  if (this->Faces && this->Faces->GetBuildTime() == this->FacesBuildTime)
  {
    return true;
  }
  vtkErrorMacro("The face set was built again after this order's Build(): no order is made.");
  return false;
}

//------------------------------------------------------------------------------
bool vtkHAVSVisibilityOrder::Build(
  vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid, const std::function<void(double)>& progress)
{
  this->FaceCells.clear();
  this->CellFaces.clear();
  this->FaceFlags.clear();
  this->Faces = nullptr;
  this->FacesBuildTime = 0;
  this->Order.clear();
  this->CellOrder.clear();
  this->Points.clear();
  this->BoundaryFaces.clear();
  this->BoundaryFaceVertices.clear();
  this->SeamFaces.clear();
  this->MeshConvex = true;
  this->NumberOfFoldedFaces = 0;
  this->Convexification = nullptr;
  this->ConvexificationBuilt = false;
  this->NumberOfImaginaryCells = 0;
  this->ConvexificationSeconds = 0.0;
  auto report = [&](double p)
  {
    if (progress)
    {
      progress(p);
    }
  };
  if (!faces || !grid || !grid->GetPoints())
  {
    vtkErrorMacro("Build needs a face set and its grid.");
    return false;
  }
  report(0.0);
  const std::vector<uint32_t>& vertices = faces->GetFaceVertices();
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const size_t numberOfFaces = vertices.size() / 3;
  const size_t numberOfTets = tets.size() / 4;
  vtkPoints* points = grid->GetPoints();
  const vtkIdType numberOfPoints = points->GetNumberOfPoints();
  if (numberOfTets > static_cast<size_t>(std::numeric_limits<int32_t>::max()) ||
    numberOfFaces > static_cast<size_t>(std::numeric_limits<uint32_t>::max()))
  {
    vtkErrorMacro("Build: " << numberOfTets << " tetrahedra, " << numberOfFaces
                            << " faces; the order holds at most 2^31 - 1 and 2^32 - 1.");
    return false;
  }

  // The points in double precision (the planes and the boundary layers read them).
  this->Points.resize(3 * static_cast<size_t>(numberOfPoints));
  vtkSMPTools::For(0, numberOfPoints,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        points->GetPoint(i, &this->Points[3 * i]);
      }
    });

  // The face set's faces come sorted by their sorted point ids: the faces
  // whose smallest id is p are firstFace[p] .. firstFace[p + 1] - 1.
  auto keyOf = [&](size_t f)
  { return SortedKey(vertices[3 * f], vertices[3 * f + 1], vertices[3 * f + 2]); };
  std::vector<uint32_t> firstFace(static_cast<size_t>(numberOfPoints) + 1, 0);
  {
    Key previous = { 0, 0, 0 };
    size_t next = 0; // the first point whose firstFace is not yet known
    for (size_t f = 0; f < numberOfFaces; ++f)
    {
      const Key key = keyOf(f);
      if ((f > 0 && !(previous < key)) || key[2] >= static_cast<uint32_t>(numberOfPoints))
      {
        vtkErrorMacro("The face set's faces are not sorted by their point ids (face "
          << f << "): it was not built on this grid.");
        return false;
      }
      for (; next <= key[0]; ++next)
      {
        firstFace[next] = static_cast<uint32_t>(f);
      }
      previous = key;
    }
    for (; next <= static_cast<size_t>(numberOfPoints); ++next)
    {
      firstFace[next] = static_cast<uint32_t>(numberOfFaces);
    }
  }
  report(0.2);

  // Each tetrahedron's four faces (face j leaves out point j), in parallel.
  this->CellFaces.resize(4 * numberOfTets);
  std::atomic<size_t> missing(numberOfTets); // the first tetrahedron with a face not found
  vtkSMPTools::For(0, static_cast<vtkIdType>(numberOfTets),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const uint32_t* p = &tets[4 * t];
        for (int j = 0; j < 4; ++j)
        {
          const Key key = SortedKey(p[(j + 1) % 4], p[(j + 2) % 4], p[(j + 3) % 4]);
          const bool inRange = key[2] < static_cast<uint32_t>(numberOfPoints);
          uint32_t lo = inRange ? firstFace[key[0]] : 0;
          const uint32_t last = inRange ? firstFace[key[0] + 1] : 0;
          uint32_t hi = last;
          while (lo < hi)
          {
            const uint32_t mid = lo + (hi - lo) / 2;
            if (keyOf(mid) < key)
            {
              lo = mid + 1;
            }
            else
            {
              hi = mid;
            }
          }
          if (lo == last || keyOf(lo) != key)
          {
            size_t seen = missing.load();
            while (static_cast<size_t>(t) < seen &&
              !missing.compare_exchange_weak(seen, static_cast<size_t>(t)))
            {
            }
            this->CellFaces[4 * t + j] = 0;
            continue;
          }
          this->CellFaces[4 * t + j] = lo;
        }
      }
    });
  if (missing.load() < numberOfTets)
  {
    vtkErrorMacro("A face of tetrahedron " << missing.load() << " is not in the face set.");
    this->CellFaces.clear();
    return false;
  }
  report(0.5);

  // The two tetrahedra of each face, the first (in tetrahedron order) first,
  // and the point of each off the face.
  this->FaceCells.assign(2 * numberOfFaces, -1);
  std::vector<uint32_t> farPoint(2 * numberOfFaces, 0);
  for (size_t t = 0; t < numberOfTets; ++t)
  {
    for (int j = 0; j < 4; ++j)
    {
      const uint32_t f = this->CellFaces[4 * t + j];
      const int slot = this->FaceCells[2 * f] < 0 ? 0 : 1;
      this->FaceCells[2 * f + slot] = static_cast<int32_t>(t);
      farPoint[2 * f + slot] = tets[4 * t + j];
    }
  }
  report(0.7);

  // Planes, oriented away from cell 0 (outward for a boundary face): only
  // the flip is kept (FacePlane makes the plane again).
  this->Faces = faces;
  this->FacesBuildTime = faces->GetBuildTime();
  this->FaceFlags.assign(numberOfFaces, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numberOfFaces),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        double n[4];
        this->FacePlane(f, n);
        const double* x = &this->Points[3 * static_cast<size_t>(farPoint[2 * f])];
        uint8_t flags = 0;
        if (n[0] * x[0] + n[1] * x[1] + n[2] * x[2] + n[3] > 0.0)
        {
          flags = FaceFlipped;
          for (double& c : n)
          {
            c = -c;
          }
        }
        if (this->FaceCells[2 * f + 1] >= 0)
        {
          // Folded: the second cell lies on the first's side too (an inverted cell).
          x = &this->Points[3 * static_cast<size_t>(farPoint[2 * f + 1])];
          flags |= n[0] * x[0] + n[1] * x[1] + n[2] * x[2] + n[3] < 0.0 ? FaceFolded : 0;
        }
        this->FaceFlags[f] = flags;
      }
    });
  std::vector<uint32_t>().swap(farPoint);
  this->NumberOfFoldedFaces = std::count_if(this->FaceFlags.begin(), this->FaceFlags.end(),
    [](uint8_t flags) { return (flags & FaceFolded) != 0; });
  if (this->NumberOfFoldedFaces > 0)
  {
    vtkWarningMacro(<< this->NumberOfFoldedFaces
                    << " internal faces have both their tetrahedra on one side (inverted or "
                       "overlapping cells): no visibility order is exact there.");
  }
  report(0.9);

  // What the non-convex methods need: the boundary faces.
  this->MeshConvex = faces->IsConvex();
  for (size_t f = 0; f < numberOfFaces; ++f)
  {
    if (this->FaceCells[2 * f + 1] < 0)
    {
      this->BoundaryFaces.push_back(static_cast<uint32_t>(f));
      this->BoundaryFaceVertices.insert(
        this->BoundaryFaceVertices.end(), &vertices[3 * f], &vertices[3 * f] + 3);
    }
  }

  // Seams: boundary faces of two tetrahedra facing each other at the same
  // place, on a cut whose points are duplicated: the same three points by
  // coordinates, or the two triangles of the same quadrilateral split by the
  // other diagonal. Points are first merged by their coordinates.
  const size_t numberOfBoundary = this->BoundaryFaces.size();
  std::vector<uint32_t> canonical(3 * numberOfBoundary);
  {
    std::vector<std::pair<std::array<double, 3>, uint32_t>> corners(3 * numberOfBoundary);
    for (size_t i = 0; i < corners.size(); ++i)
    {
      const double* x = &this->Points[3 * static_cast<size_t>(this->BoundaryFaceVertices[i])];
      corners[i] = { { x[0], x[1], x[2] }, static_cast<uint32_t>(i) };
    }
    std::sort(corners.begin(), corners.end());
    uint32_t id = 0;
    for (size_t i = 0; i < corners.size(); ++i)
    {
      id += (i > 0 && corners[i].first != corners[i - 1].first) ? 1 : 0;
      canonical[corners[i].second] = id;
    }
  }
  auto normalsOppose = [&](uint32_t a, uint32_t b)
  {
    double p[4], q[4];
    this->FacePlane(this->BoundaryFaces[a], p);
    this->FacePlane(this->BoundaryFaces[b], q);
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2] < 0.0;
  };
  auto addSeam = [&](uint32_t a, uint32_t b)
  {
    const uint32_t fa = this->BoundaryFaces[a], fb = this->BoundaryFaces[b];
    if (this->FaceCells[2 * static_cast<size_t>(fa)] !=
        this->FaceCells[2 * static_cast<size_t>(fb)] &&
      normalsOppose(a, b))
    {
      this->SeamFaces.push_back(fa);
      this->SeamFaces.push_back(fb);
    }
  };
  // The same triangle.
  std::vector<std::pair<std::array<uint32_t, 3>, uint32_t>> triangles(numberOfBoundary);
  for (size_t b = 0; b < numberOfBoundary; ++b)
  {
    std::array<uint32_t, 3> t = { canonical[3 * b], canonical[3 * b + 1], canonical[3 * b + 2] };
    std::sort(t.begin(), t.end());
    triangles[b] = { t, static_cast<uint32_t>(b) };
  }
  std::sort(triangles.begin(), triangles.end());
  for (size_t i = 0; i + 1 < triangles.size(); ++i)
  {
    if (triangles[i].first == triangles[i + 1].first)
    {
      addSeam(triangles[i].second, triangles[i + 1].second);
    }
  }
  // The same quadrilateral, split by the other diagonal: pairs of boundary
  // faces of one tetrahedron side sharing an edge, keyed by their four corners.
  std::vector<std::pair<std::array<uint32_t, 2>, uint32_t>> edges;
  edges.reserve(3 * numberOfBoundary);
  for (size_t b = 0; b < numberOfBoundary; ++b)
  {
    for (int i = 0; i < 3; ++i)
    {
      const uint32_t u = canonical[3 * b + i], v = canonical[3 * b + (i + 1) % 3];
      edges.push_back({ { std::min(u, v), std::max(u, v) }, static_cast<uint32_t>(b) });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<std::array<uint32_t, 4>, std::array<uint32_t, 2>>> quads;
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first)
    {
      ++j;
    }
    for (size_t a = i; a < j; ++a)
    {
      for (size_t b = a + 1; b < j; ++b)
      {
        const uint32_t fa = edges[a].second, fb = edges[b].second;
        if (normalsOppose(fa, fb))
        {
          continue; // a quadrilateral's two triangles face the same way
        }
        std::array<uint32_t, 4> corners = { canonical[3 * fa], canonical[3 * fa + 1],
          canonical[3 * fa + 2], 0 };
        for (int k = 0; k < 3; ++k)
        {
          const uint32_t c = canonical[3 * fb + k];
          if (c != edges[a].first[0] && c != edges[a].first[1])
          {
            corners[3] = c;
          }
        }
        std::sort(corners.begin(), corners.end());
        quads.push_back({ corners, { fa, fb } });
      }
    }
    i = j;
  }
  std::sort(quads.begin(), quads.end());
  for (size_t i = 0; i < quads.size();)
  {
    size_t j = i;
    while (j < quads.size() && quads[j].first == quads[i].first)
    {
      ++j;
    }
    for (size_t a = i; a < j; ++a)
    {
      for (size_t b = a + 1; b < j; ++b)
      {
        // Two splits of one quadrilateral (on two sides of the cut): every
        // triangle of one overlaps every triangle of the other.
        const auto& x = quads[a].second;
        const auto& y = quads[b].second;
        auto sameTriangle = [&](uint32_t u, uint32_t v)
        {
          std::array<uint32_t, 3> tu = { canonical[3 * u], canonical[3 * u + 1],
            canonical[3 * u + 2] };
          std::array<uint32_t, 3> tv = { canonical[3 * v], canonical[3 * v + 1],
            canonical[3 * v + 2] };
          std::sort(tu.begin(), tu.end());
          std::sort(tv.begin(), tv.end());
          return tu == tv;
        };
        if (x[0] == y[0] || x[0] == y[1] || x[1] == y[0] || x[1] == y[1] ||
          sameTriangle(x[0], y[0]) || sameTriangle(x[0], y[1]))
        {
          continue; // the same pair, or the same split (seams of the same triangles, above)
        }
        for (uint32_t fx : x)
        {
          for (uint32_t fy : y)
          {
            addSeam(fx, fy);
          }
        }
      }
    }
    i = j;
  }
  report(1.0);
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::SetViewSampling(const double modelToClip[16], int width, int height)
{
  std::copy(modelToClip, modelToClip + 16, this->ModelToClip);
  this->SampleSize[0] = width;
  this->SampleSize[1] = height;
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::BuildConvexification()
{
  this->ConvexificationBuilt = true;
  this->Convexification = vtkSmartPointer<vtkHAVSConvexification>::New();
  if (!this->Convexification->Build(this->Points, this->BoundaryFaceVertices))
  {
    vtkWarningMacro("The mesh could not be convexified; its order is exact only where no ray "
                    "re-enters it.");
    this->Convexification = nullptr;
    return;
  }
  this->NumberOfImaginaryCells = this->Convexification->GetNumberOfImaginaryCells();
  this->ConvexificationSeconds = this->Convexification->GetBuildSeconds();
  // The solid BSP needs a closed, consistently wound boundary: inverted cells
  // (folded faces) or boundary pieces that end inside the solid mean it is not.
  if (this->NumberOfFoldedFaces > 0 || this->Convexification->GetNumberOfInLeafPieces() > 0)
  {
    vtkWarningMacro("The mesh's boundary is not closed and consistently wound ("
      << this->NumberOfFoldedFaces << " folded faces, "
      << this->Convexification->GetNumberOfInLeafPieces()
      << " boundary pieces inside the solid): its convexification cannot order it; using "
         "the boundary layers instead.");
    this->Convexification = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::BoundaryLayerRelations(const double eye[3], const double direction[3],
  bool parallel, std::vector<std::pair<uint32_t, uint32_t>>& relations)
{
  const double start = vtkTimerLog::GetUniversalTime();
  relations.clear();
  const int width = this->SampleSize[0], height = this->SampleSize[1];
  const size_t numberOfBoundary = this->BoundaryFaces.size();
  if (width <= 0 || height <= 0 || numberOfBoundary == 0)
  {
    this->LastBoundaryLayerSeconds = 0.0;
    return;
  }

  // The boundary faces at the frame's pixel centres, each pixel's hits in
  // depth order (vtkHAVSFaceRasterizer, as the exact reference sees them);
  // whether a face is an entry follows from its plane and the eye.
  std::vector<uint8_t> entry(numberOfBoundary);
  for (size_t b = 0; b < numberOfBoundary; ++b)
  {
    double plane[4];
    this->FacePlane(this->BoundaryFaces[b], plane);
    entry[b] = EyeSide(plane, eye, direction, parallel) > 0.0;
  }
  this->Rasterizer->SetView(this->ModelToClip, eye, direction, parallel, width, height);
  this->Rasterizer->Rasterize(
    this->Points, this->BoundaryFaceVertices.data(), static_cast<vtkIdType>(numberOfBoundary));
  const std::vector<vtkIdType>& pixelStart = this->Rasterizer->GetPixelStart();
  const std::vector<vtkHAVSFaceRasterizer::Hit>& hits = this->Rasterizer->GetHits();

  // An exit followed by an entry orders the cell left before the cell entered.
  using Relations = std::vector<std::pair<uint32_t, uint32_t>>;
  vtkSMPThreadLocal<Relations> local;
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  vtkSMPTools::For(0, pixels,
    [&](vtkIdType begin, vtkIdType end)
    {
      Relations& out = local.Local();
      auto cellOf = [&](const vtkHAVSFaceRasterizer::Hit& h)
      {
        return static_cast<uint32_t>(
          this->FaceCells[2 * static_cast<size_t>(this->BoundaryFaces[h.Triangle])]);
      };
      for (vtkIdType p = begin; p < end; ++p)
      {
        for (vtkIdType i = pixelStart[p]; i + 1 < pixelStart[p + 1]; ++i)
        {
          const vtkHAVSFaceRasterizer::Hit& a = hits[i];
          const vtkHAVSFaceRasterizer::Hit& b = hits[i + 1];
          const bool aEntry = entry[a.Triangle] != 0, bEntry = entry[b.Triangle] != 0;
          if (aEntry == bEntry)
          {
            continue;
          }
          // An exit then an entry; also an entry then an exit at the same depth
          // up to rounding (two different triangles through the same point, as
          // on a seam whose quadrilaterals are split by different diagonals).
          const vtkHAVSFaceRasterizer::Hit& exit = aEntry ? b : a;
          const vtkHAVSFaceRasterizer::Hit& in = aEntry ? a : b;
          const double tie = 1e-9 * std::max(std::abs(a.Distance), std::abs(b.Distance));
          if ((!aEntry || b.Distance - a.Distance <= tie) && cellOf(exit) != cellOf(in))
          {
            out.emplace_back(cellOf(exit), cellOf(in));
          }
        }
      }
    });
  this->Rasterizer->ReleaseHits();
  for (Relations& r : local)
  {
    relations.insert(relations.end(), r.begin(), r.end());
  }
  std::sort(relations.begin(), relations.end());
  relations.erase(std::unique(relations.begin(), relations.end()), relations.end());
  this->LastBoundaryLayerSeconds = vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::Sort(const double eye[3], const double direction[3], bool parallel)
{
  if (!this->MeshConvex && this->NonConvexMethod == NonConvexConvexification &&
    !this->ConvexificationBuilt)
  {
    this->BuildConvexification(); // once per mesh, timed on its own
  }
  const double start = vtkTimerLog::GetUniversalTime();
  this->Order.clear();
  this->CellOrder.clear();
  this->NumberOfCycleBreaks = 0;
  this->NumberOfBoundaryRelations = 0;
  this->NumberOfSkippedFaces = 0;
  if (this->FaceFlags.empty() || !this->FacesUnchanged())
  {
    this->LastSortSeconds = 0.0;
    return;
  }
  const size_t numberOfFaces = this->FaceCells.size() / 2;
  const size_t numberOfTets = this->CellFaces.size() / 4;
  this->Order.reserve(numberOfFaces);
  this->CellOrder.reserve(numberOfTets);
  auto side = [&](const double* p) { return EyeSide(p, eye, direction, parallel); };
  auto faceSide = [&](size_t f)
  {
    double plane[4];
    this->FacePlane(f, plane);
    return side(plane);
  };
  const std::vector<uint32_t>& tetrahedronCells = this->Faces->GetTetrahedronCells();

  // The skipped tetrahedra (SetSkippedCells): visited before the sort starts,
  // so nothing waits for them and none is ordered.
  std::vector<uint8_t> skip;
  if (this->Skipped && tetrahedronCells.size() == numberOfTets)
  {
    skip.assign(numberOfTets, 0);
    const std::vector<uint8_t>& cells = *this->Skipped;
    for (size_t t = 0; t < numberOfTets; ++t)
    {
      const uint32_t c = tetrahedronCells[t];
      skip[t] = c < cells.size() && cells[c] != 0;
    }
  }
  auto skipped = [&](int32_t t) { return t >= 0 && !skip.empty() && skip[t] != 0; };

  // Each face's back cell: the one the ray enters through it (-1: it leaves
  // the mesh there). cell 1 lies on the positive side of the plane.
  std::vector<int32_t> back(numberOfFaces);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numberOfFaces),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        back[f] = faceSide(f) > 0.0 ? this->FaceCells[2 * f] : this->FaceCells[2 * f + 1];
      }
    });

  // Relations across the outside of a non-convex mesh (from -> to: from is
  // in front). Nodes numberOfTets.. are the imaginary cells.
  std::vector<std::pair<uint32_t, uint32_t>> extra;
  size_t numberOfNodes = numberOfTets;
  for (size_t i = 0; i < this->SeamFaces.size(); i += 2)
  {
    // As an internal face: the tetrahedron on the eye's side first.
    const size_t a = this->SeamFaces[i], b = this->SeamFaces[i + 1];
    const auto ta = static_cast<uint32_t>(this->FaceCells[2 * a]);
    const auto tb = static_cast<uint32_t>(this->FaceCells[2 * b]);
    if (faceSide(a) > 0.0)
    {
      extra.emplace_back(tb, ta);
    }
    else
    {
      extra.emplace_back(ta, tb);
    }
  }
  if (!this->MeshConvex && this->NonConvexMethod == NonConvexConvexification &&
    this->Convexification)
  {
    const auto tets = static_cast<uint32_t>(numberOfTets);
    numberOfNodes += static_cast<size_t>(this->NumberOfImaginaryCells);
    for (const auto& tc : this->Convexification->GetTriangleCells())
    {
      const uint32_t f = this->BoundaryFaces[tc.first];
      const auto t = static_cast<uint32_t>(this->FaceCells[2 * static_cast<size_t>(f)]);
      if (faceSide(f) > 0.0)
      {
        extra.emplace_back(tets + tc.second, t);
      }
      else
      {
        extra.emplace_back(t, tets + tc.second);
      }
    }
    for (const auto& portal : this->Convexification->GetPortals())
    {
      if (side(portal.Plane) > 0.0)
      {
        extra.emplace_back(tets + portal.Cells[1], tets + portal.Cells[0]);
      }
      else
      {
        extra.emplace_back(tets + portal.Cells[0], tets + portal.Cells[1]);
      }
    }
  }
  else if (!this->MeshConvex &&
    (this->NonConvexMethod == NonConvexBoundaryLayers ||
      this->NonConvexMethod == NonConvexConvexification)) // a convexification that failed
  {
    std::vector<std::pair<uint32_t, uint32_t>> layers;
    this->BoundaryLayerRelations(eye, direction, parallel, layers);
    this->NumberOfBoundaryRelations = static_cast<vtkIdType>(layers.size());
    extra.insert(extra.end(), layers.begin(), layers.end());
  }
  std::vector<uint32_t> extraStart(numberOfNodes + 1, 0), extraTo(extra.size());
  for (const auto& e : extra)
  {
    ++extraStart[e.first + 1];
  }
  for (size_t n = 0; n < numberOfNodes; ++n)
  {
    extraStart[n + 1] += extraStart[n];
  }
  {
    std::vector<uint32_t> cursor(extraStart.begin(), extraStart.end() - 1);
    for (const auto& e : extra)
    {
      extraTo[cursor[e.first]++] = e.second;
    }
  }

  std::vector<int32_t> waiting(numberOfNodes, 0); // cells in front not visited yet
  for (size_t f = 0; f < numberOfFaces; ++f)
  {
    if (back[f] >= 0 && this->FaceCells[2 * f + 1] >= 0)
    {
      const int32_t front =
        this->FaceCells[2 * f] == back[f] ? this->FaceCells[2 * f + 1] : this->FaceCells[2 * f];
      if (!skipped(front))
      {
        ++waiting[static_cast<size_t>(back[f])];
      }
    }
    if (!skip.empty() && (this->FaceCells[2 * f] < 0 || skipped(this->FaceCells[2 * f])) &&
      (this->FaceCells[2 * f + 1] < 0 || skipped(this->FaceCells[2 * f + 1])))
    {
      ++this->NumberOfSkippedFaces;
    }
  }
  for (const auto& e : extra)
  {
    if (e.first >= numberOfTets || !skipped(e.first))
    {
      ++waiting[e.second];
    }
  }
  // The ready queue: each node enters it once when its last cell in front is
  // visited, or at a cycle break (a plain vector read from the front).
  std::vector<uint32_t> ready;
  ready.reserve(numberOfNodes);
  size_t readyHead = 0;
  for (size_t n = 0; n < numberOfNodes; ++n)
  {
    if (waiting[n] == 0)
    {
      ready.push_back(static_cast<uint32_t>(n));
    }
  }
  std::vector<uint8_t> visited(numberOfNodes, 0);
  size_t visitedCount = 0;
  for (size_t t = 0; t < skip.size(); ++t)
  {
    visited[t] = skip[t];
    visitedCount += skip[t];
  }
  size_t scan = 0;
  auto release = [&](size_t behind)
  {
    if (--waiting[behind] == 0 && !visited[behind])
    {
      ready.push_back(static_cast<uint32_t>(behind));
    }
  };
  while (visitedCount < numberOfNodes)
  {
    if (readyHead == ready.size())
    {
      // A cycle: take an unvisited cell with the fewest cells still in front
      // (the first with one only, searching on from the last break: cycles
      // are local, and a full scan per break would be quadratic).
      size_t best = numberOfNodes;
      for (size_t n = 0; n < numberOfNodes; ++n)
      {
        const size_t c = (scan + n) % numberOfNodes;
        if (!visited[c] && (best == numberOfNodes || waiting[c] < waiting[best]))
        {
          best = c;
          if (waiting[c] <= 1)
          {
            break;
          }
        }
      }
      scan = best;
      ready.push_back(static_cast<uint32_t>(best));
      ++this->NumberOfCycleBreaks;
    }
    const uint32_t c = ready[readyHead++];
    if (visited[c])
    {
      continue;
    }
    visited[c] = 1;
    ++visitedCount;
    if (c < numberOfTets)
    {
      this->CellOrder.push_back(c);
      const uint32_t* cellFaces = &this->CellFaces[4 * static_cast<size_t>(c)];
      // Entries (the faces behind which c lies), then the mesh's exits from c.
      for (int j = 0; j < 4; ++j)
      {
        if (back[cellFaces[j]] == static_cast<int32_t>(c))
        {
          this->Order.push_back(cellFaces[j]);
        }
      }
      for (int j = 0; j < 4; ++j)
      {
        const uint32_t f = cellFaces[j];
        if (back[f] < 0 || (back[f] != static_cast<int32_t>(c) && skipped(back[f])))
        {
          this->Order.push_back(f); // it leaves the mesh, or the cells the frame sees
        }
        else if (back[f] != static_cast<int32_t>(c))
        {
          release(static_cast<size_t>(back[f])); // c is in front of the cell behind f
        }
      }
    }
    for (uint32_t e = extraStart[c]; e < extraStart[c + 1]; ++e)
    {
      release(extraTo[e]);
    }
  }
  this->LastSortSeconds = vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::SetSkippedCells(
  const std::vector<uint8_t>* skipped, vtkMTimeType version)
{
  this->Skipped = skipped;
  this->SkippedVersion = skipped ? version : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Faces: " << this->FaceCells.size() / 2
     << ", tetrahedra: " << this->CellFaces.size() / 4 << "\n";
  os << indent << "Mesh convex: " << (this->MeshConvex ? "yes" : "no") << ", NonConvexMethod: "
     << (this->NonConvexMethod == NonConvexConvexification
            ? "Convexification"
            : (this->NonConvexMethod == NonConvexBoundaryLayers ? "BoundaryLayers" : "Ignore"))
     << "\n";
  os << indent << "Seam face pairs: " << this->SeamFaces.size() / 2 << "\n";
  os << indent << "NumberOfImaginaryCells: " << this->NumberOfImaginaryCells << " (convexified in "
     << this->ConvexificationSeconds << " s)\n";
  os << indent << "NumberOfBoundaryRelations: " << this->NumberOfBoundaryRelations << " ("
     << this->LastBoundaryLayerSeconds << " s)\n";
  os << indent << "NumberOfCycleBreaks: " << this->NumberOfCycleBreaks << "\n";
  os << indent << "Skipped cells: " << (this->Skipped ? "set" : "none")
     << ", NumberOfSkippedFaces: " << this->NumberOfSkippedFaces << "\n";
  os << indent << "LastSortSeconds: " << this->LastSortSeconds << "\n";
}

//------------------------------------------------------------------------------
vtkHAVSVisibilityOrder::ViewKey vtkHAVSVisibilityOrder::MakeViewKey(
  vtkMTimeType meshTime, const vtkHAVSViewFrame& view, int method) const
{
  ViewKey key;
  key.Mesh = meshTime;
  std::copy(view.EyeGrid, view.EyeGrid + 3, key.Eye.begin());
  std::copy(view.DirectionGrid, view.DirectionGrid + 3, key.Direction.begin());
  key.Parallel = view.Parallel;
  key.Method = method;
  key.Skip = this->SkippedVersion;
  if (method == NonConvexBoundaryLayers && !this->MeshConvex)
  {
    // The boundary layers are sampled at this frame's pixels.
    std::copy(view.GridToClip, view.GridToClip + 16, key.GridToClip.begin());
    key.Width = view.Width;
    key.Height = view.Height;
  }
  return key;
}

//------------------------------------------------------------------------------
size_t vtkHAVSVisibilityOrder::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(this->FaceCells, this->CellFaces, this->Order, this->CellOrder,
           this->Points, this->BoundaryFaces, this->BoundaryFaceVertices, this->SeamFaces,
           this->FaceFlags) +
    (this->Convexification ? this->Convexification->GetMemoryBytes() : 0);
}

VTK_ABI_NAMESPACE_END
