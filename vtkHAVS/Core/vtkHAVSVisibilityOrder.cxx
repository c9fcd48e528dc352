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
bool vtkHAVSVisibilityOrder::Build(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid)
{
  this->FaceCells.clear();
  this->FacePlanes.clear();
  this->CellFaces.clear();
  this->TetrahedronCells.clear();
  this->Order.clear();
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
  if (!faces || !grid || !grid->GetPoints())
  {
    vtkErrorMacro("Build needs a face set and its grid.");
    return false;
  }
  const std::vector<uint32_t>& vertices = faces->GetFaceVertices();
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const size_t numberOfFaces = vertices.size() / 3;
  const size_t numberOfTets = tets.size() / 4;
  if (numberOfTets > static_cast<size_t>(std::numeric_limits<int32_t>::max()))
  {
    vtkErrorMacro("Build: " << numberOfTets << " tetrahedra; the order holds at most 2^31 - 1.");
    return false;
  }

  // Faces by their sorted point ids.
  std::vector<std::pair<Key, uint32_t>> keys(numberOfFaces);
  for (size_t f = 0; f < numberOfFaces; ++f)
  {
    keys[f] = { SortedKey(vertices[3 * f], vertices[3 * f + 1], vertices[3 * f + 2]),
      static_cast<uint32_t>(f) };
  }
  std::sort(keys.begin(), keys.end());

  this->FaceCells.assign(2 * numberOfFaces, -1);
  this->CellFaces.resize(4 * numberOfTets);
  this->TetrahedronCells = faces->GetTetrahedronCells();
  std::vector<uint32_t> farPoint(2 * numberOfFaces, 0); // each cell's vertex off the face
  for (size_t t = 0; t < numberOfTets; ++t)
  {
    const uint32_t* p = &tets[4 * t];
    for (int j = 0; j < 4; ++j)
    {
      const Key key = SortedKey(p[(j + 1) % 4], p[(j + 2) % 4], p[(j + 3) % 4]);
      const auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key, 0u));
      if (it == keys.end() || it->first != key)
      {
        vtkErrorMacro("A face of tetrahedron " << t << " is not in the face set.");
        this->FaceCells.clear();
        return false;
      }
      const uint32_t f = it->second;
      this->CellFaces[4 * t + j] = f;
      if (this->FaceCells[2 * f] < 0)
      {
        this->FaceCells[2 * f] = static_cast<int32_t>(t);
        farPoint[2 * f] = p[j];
      }
      else
      {
        this->FaceCells[2 * f + 1] = static_cast<int32_t>(t);
        farPoint[2 * f + 1] = p[j];
      }
    }
  }

  // Planes, oriented away from cell 0 (outward for a boundary face).
  vtkPoints* points = grid->GetPoints();
  this->FacePlanes.resize(4 * numberOfFaces);
  std::vector<uint8_t> folded(numberOfFaces, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numberOfFaces),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        double v[3][3], x[3];
        for (int i = 0; i < 3; ++i)
        {
          points->GetPoint(vertices[3 * f + i], v[i]);
        }
        points->GetPoint(farPoint[2 * f], x);
        const double e1[3] = { v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2] };
        const double e2[3] = { v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2] };
        double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
          e1[0] * e2[1] - e1[1] * e2[0] };
        double d = -(n[0] * v[0][0] + n[1] * v[0][1] + n[2] * v[0][2]);
        if (n[0] * x[0] + n[1] * x[1] + n[2] * x[2] + d > 0.0)
        {
          n[0] = -n[0];
          n[1] = -n[1];
          n[2] = -n[2];
          d = -d;
        }
        double* plane = &this->FacePlanes[4 * f];
        plane[0] = n[0];
        plane[1] = n[1];
        plane[2] = n[2];
        plane[3] = d;
        if (this->FaceCells[2 * f + 1] >= 0)
        {
          // Folded: the second cell lies on the first's side too (an inverted cell).
          points->GetPoint(farPoint[2 * f + 1], x);
          folded[f] = n[0] * x[0] + n[1] * x[1] + n[2] * x[2] + d < 0.0 ? 1 : 0;
        }
      }
    });
  this->NumberOfFoldedFaces = std::count(folded.begin(), folded.end(), 1);
  this->FoldedFaces.swap(folded);
  if (this->NumberOfFoldedFaces > 0)
  {
    vtkWarningMacro(<< this->NumberOfFoldedFaces
                    << " internal faces have both their tetrahedra on one side (inverted or "
                       "overlapping cells): no visibility order is exact there.");
  }

  // What the non-convex methods need: the points and the boundary faces.
  this->MeshConvex = faces->IsConvex();
  this->Points.resize(3 * static_cast<size_t>(points->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->GetPoint(i, &this->Points[3 * i]);
  }
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
    const double* p = &this->FacePlanes[4 * static_cast<size_t>(this->BoundaryFaces[a])];
    const double* q = &this->FacePlanes[4 * static_cast<size_t>(this->BoundaryFaces[b])];
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
    entry[b] = EyeSide(&this->FacePlanes[4 * static_cast<size_t>(this->BoundaryFaces[b])], eye,
                 direction, parallel) > 0.0;
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
  const size_t numberOfFaces = this->FacePlanes.size() / 4;
  const size_t numberOfTets = this->CellFaces.size() / 4;
  this->Order.clear();
  this->Order.reserve(numberOfFaces);
  this->CellOrder.clear();
  this->CellOrder.reserve(numberOfTets);
  this->NumberOfCycleBreaks = 0;
  this->NumberOfBoundaryRelations = 0;
  this->NumberOfSkippedFaces = 0;
  auto side = [&](const double* p) { return EyeSide(p, eye, direction, parallel); };

  // The skipped tetrahedra (SetSkippedCells): visited before the sort starts,
  // so nothing waits for them and none is ordered.
  std::vector<uint8_t> skip;
  if (this->Skipped && this->TetrahedronCells.size() == numberOfTets)
  {
    skip.assign(numberOfTets, 0);
    const std::vector<uint8_t>& cells = *this->Skipped;
    for (size_t t = 0; t < numberOfTets; ++t)
    {
      const uint32_t c = this->TetrahedronCells[t];
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
        back[f] =
          static_cast<int32_t>(side(&this->FacePlanes[4 * f]) > 0.0 ? this->FaceCells[2 * f]
                                                                    : this->FaceCells[2 * f + 1]);
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
    if (side(&this->FacePlanes[4 * a]) > 0.0)
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
      if (side(&this->FacePlanes[4 * static_cast<size_t>(f)]) > 0.0)
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
  os << indent << "Faces: " << this->FacePlanes.size() / 4
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
  return vtkHAVSMemory::Bytes(this->FaceCells, this->FacePlanes, this->CellFaces,
           this->TetrahedronCells, this->Order, this->CellOrder, this->Points, this->BoundaryFaces,
           this->BoundaryFaceVertices, this->SeamFaces, this->FoldedFaces) +
    (this->Convexification ? this->Convexification->GetMemoryBytes() : 0);
}

VTK_ABI_NAMESPACE_END
