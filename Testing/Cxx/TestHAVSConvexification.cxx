/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSConvexification.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSConvexification (seed 004, section 6): imaginary convex cells as the
// OUT leaves of a solid-leaf BSP tree of the boundary triangles. On a convex
// box, a U-shaped solid, a rotated square torus, a rotated random voxel blob
// (cavities, coplanar faces, edge-touching voxels), a bumpy sphere of ~20k
// triangles and a convex sphere of 25k (the deepest tree: a chain):
// - FindCell(x) == -1 exactly where x is inside the solid by brute-force
//   ray parity, for random points in the root box (misses only within 1e-9
//   of the surface are forgiven);
// - every triangle has a cell on its outer side; for an unsplit triangle the
//   point just outside its centroid (1e-10 of the root box diagonal: thin
//   triangles near a pole have neighbours at tiny dihedral angles) is in
//   that cell; every cell touches the mesh;
// - every portal joins two distinct valid cells, Cells[0] just behind its
//   centre, Cells[1] just in front (1e-10 diagonal: portals can be slivers);
// - internal double walls (coincident faces of opposite orientations, as a
//   mesh cut with duplicated points gives): two cubes face to face, with
//   crossing diagonals, axis-aligned and rotated, and two boxes touching in
//   part: inside on both sides, the wall triangles without cell;
// - negative control: the U-shape wound inward must mismatch;
// - Build time of the large surfaces (< 20 s) and bad input;
// - e) the MPVO order with the convexification (vtkHAVSVisibilityOrder) is
//   exact, on the CPU: on the thresholded wavelet, the hollow sphere, the
//   torus, the two blocks and the wavelet turned by a generic rotation with
//   float points (its coplanar faces are coplanar only up to float rounding,
//   as in the torus, whose points are multiples of 1/24 in float), the exact
//   fragments of every pixel (vtkHAVSReferenceRenderer, 96^2, 12 perspective
//   views off the axes) in MPVO's face order need k <= 2 in the software
//   k-buffer, and the sort breaks no cycle; negative control: without the
//   convexification (NonConvexIgnore) the wavelet needs k > 2.
//   `TestHAVSConvexification order <mesh>...` prints the figures per view
//   (meshes: the four above, a data set name, "<mesh> rotated").
#include "havsTestChecks.h"

#include "vtkHAVSDataSets.h"

#include "vtkCamera.h"
#include "vtkHAVSConvexification.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSSoftwareKBuffer.h"
#include "vtkHAVSVisibilityOrder.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace
{
using Vec = std::array<double, 3>;

struct Surface
{
  std::string Name;
  std::vector<double> Points;
  std::vector<uint32_t> Triangles;

  Vec Point(uint32_t id) const
  {
    return { this->Points[3 * id], this->Points[3 * id + 1], this->Points[3 * id + 2] };
  }
  size_t NumberOfTriangles() const { return this->Triangles.size() / 3; }
};

Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The boundary of a union of unit voxels: two triangles per exposed face, wound outward.
Surface Voxels(const std::string& name, const std::set<std::array<int, 3>>& voxels)
{
  Surface s;
  s.Name = name;
  std::map<std::array<int, 3>, uint32_t> ids;
  auto id = [&](const std::array<int, 3>& corner)
  {
    auto it = ids.find(corner);
    if (it != ids.end())
    {
      return it->second;
    }
    const uint32_t n = static_cast<uint32_t>(ids.size());
    ids[corner] = n;
    s.Points.insert(s.Points.end(), { double(corner[0]), double(corner[1]), double(corner[2]) });
    return n;
  };
  for (const auto& v : voxels)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (int dir = -1; dir <= 1; dir += 2)
      {
        auto neighbour = v;
        neighbour[a] += dir;
        if (voxels.count(neighbour))
        {
          continue;
        }
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const int offsets[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
        uint32_t q[4];
        for (int i = 0; i < 4; ++i)
        {
          auto corner = v;
          corner[a] += dir > 0 ? 1 : 0;
          corner[b] += offsets[i][0];
          corner[c] += offsets[i][1];
          q[i] = id(corner);
        }
        if (dir < 0)
        {
          std::swap(q[1], q[3]); // e_b x e_c = e_a: reversed for the -a face
        }
        s.Triangles.insert(s.Triangles.end(), { q[0], q[1], q[2], q[0], q[2], q[3] });
      }
    }
  }
  return s;
}

/// x -> R S x + t with a generic rotation R and a positive diagonal S (winding kept).
void Transform(Surface& s, const Vec& scale, const Vec& axis, double angle, const Vec& t)
{
  const double l = std::sqrt(Dot(axis, axis));
  const Vec k = { axis[0] / l, axis[1] / l, axis[2] / l };
  for (size_t p = 0; p < s.Points.size() / 3; ++p)
  {
    const Vec x = { s.Points[3 * p] * scale[0], s.Points[3 * p + 1] * scale[1],
      s.Points[3 * p + 2] * scale[2] };
    const Vec kx = Cross(k, x);
    const double kd = Dot(k, x);
    for (int i = 0; i < 3; ++i) // Rodrigues
    {
      s.Points[3 * p + i] = x[i] * std::cos(angle) + kx[i] * std::sin(angle) +
        k[i] * kd * (1.0 - std::cos(angle)) + t[i];
    }
  }
}

/// A UV sphere of radius 1 + bump * sin(5 theta) cos(4 phi), wound outward.
Surface Sphere(const std::string& name, int rings, int sectors, double bump)
{
  Surface s;
  s.Name = name;
  const double pi = std::acos(-1.0);
  auto add = [&](double theta, double phi)
  {
    const double r = 1.0 + bump * std::sin(5.0 * theta) * std::cos(4.0 * phi);
    s.Points.insert(s.Points.end(),
      { r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
        r * std::cos(theta) });
  };
  add(0.0, 0.0); // north pole: 0
  for (int i = 1; i < rings; ++i)
  {
    for (int j = 0; j < sectors; ++j)
    {
      add(pi * i / rings, 2.0 * pi * j / sectors);
    }
  }
  add(pi, 0.0); // south pole
  const uint32_t south = static_cast<uint32_t>(s.Points.size() / 3 - 1);
  auto ring = [&](int i, int j)
  { return static_cast<uint32_t>(1 + (i - 1) * sectors + j % sectors); };
  for (int j = 0; j < sectors; ++j)
  {
    s.Triangles.insert(s.Triangles.end(), { 0u, ring(1, j), ring(1, j + 1) });
    for (int i = 1; i + 1 < rings; ++i)
    {
      const uint32_t a = ring(i, j), b = ring(i, j + 1), c = ring(i + 1, j + 1), d = ring(i + 1, j);
      s.Triangles.insert(s.Triangles.end(), { a, d, c, a, c, b });
    }
    s.Triangles.insert(s.Triangles.end(), { south, ring(rings - 1, j + 1), ring(rings - 1, j) });
  }
  return s;
}

/// Two surfaces in one (their points kept apart: where they touch, an internal double wall).
Surface Concatenate(const std::string& name, const Surface& a, const Surface& b)
{
  Surface s = a;
  s.Name = name;
  const uint32_t offset = static_cast<uint32_t>(a.Points.size() / 3);
  s.Points.insert(s.Points.end(), b.Points.begin(), b.Points.end());
  for (uint32_t id : b.Triangles)
  {
    s.Triangles.push_back(id + offset);
  }
  return s;
}

/// Divergence theorem: the enclosed volume (> 0 for outward winding).
double SignedVolume(const Surface& s)
{
  double v = 0.0;
  for (size_t t = 0; t < s.NumberOfTriangles(); ++t)
  {
    const Vec a = s.Point(s.Triangles[3 * t]), b = s.Point(s.Triangles[3 * t + 1]),
              c = s.Point(s.Triangles[3 * t + 2]);
    v += Dot(a, Cross(b, c)) / 6.0;
  }
  return v;
}

/// Crossings of the ray x + s d (s > 0) with the triangles (Moller-Trumbore).
int Crossings(const Surface& s, const Vec& x, const Vec& d)
{
  int count = 0;
  for (size_t t = 0; t < s.NumberOfTriangles(); ++t)
  {
    const Vec a = s.Point(s.Triangles[3 * t]);
    const Vec e1 = Sub(s.Point(s.Triangles[3 * t + 1]), a);
    const Vec e2 = Sub(s.Point(s.Triangles[3 * t + 2]), a);
    const Vec p = Cross(d, e2);
    const double det = Dot(e1, p);
    if (det == 0.0)
    {
      continue;
    }
    const Vec tv = Sub(x, a);
    const double u = Dot(tv, p) / det;
    if (u < 0.0 || u > 1.0)
    {
      continue;
    }
    const Vec q = Cross(tv, e1);
    const double v = Dot(d, q) / det;
    if (v < 0.0 || u + v > 1.0)
    {
      continue;
    }
    count += Dot(e2, q) / det > 0.0 ? 1 : 0;
  }
  return count;
}

/// Brute-force point in solid: ray parity, majority of three odd directions.
bool Inside(const Surface& s, const Vec& x, bool quick)
{
  const Vec dirs[3] = { { 0.5773, 0.6271, 0.5229 }, { -0.3119, 0.8123, -0.4927 },
    { 0.7411, -0.2207, -0.6341 } };
  const bool first = Crossings(s, x, dirs[0]) % 2 == 1;
  if (quick)
  {
    return first;
  }
  const int votes = (first ? 1 : 0) + Crossings(s, x, dirs[1]) % 2 + Crossings(s, x, dirs[2]) % 2;
  return votes >= 2;
}

/// Distance from x to triangle abc (Ericson, closest point on triangle).
double TriangleDistance(const Vec& p, const Vec& a, const Vec& b, const Vec& c)
{
  const Vec ab = Sub(b, a), ac = Sub(c, a), ap = Sub(p, a);
  auto dist = [&](const Vec& q)
  {
    const Vec d = Sub(p, q);
    return std::sqrt(Dot(d, d));
  };
  auto along = [](const Vec& o, const Vec& e, double t) -> Vec {
    return { o[0] + t * e[0], o[1] + t * e[1], o[2] + t * e[2] };
  };
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return dist(a);
  }
  const Vec bp = Sub(p, b);
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return dist(b);
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    return dist(along(a, ab, d1 / (d1 - d3)));
  }
  const Vec cp = Sub(p, c);
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return dist(c);
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    return dist(along(a, ac, d2 / (d2 - d6)));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    return dist(along(b, Sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  const Vec q = { a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w,
    a[2] + ab[2] * v + ac[2] * w };
  return dist(q);
}

double SurfaceDistance(const Surface& s, const Vec& x)
{
  double best = 1e300;
  for (size_t t = 0; t < s.NumberOfTriangles(); ++t)
  {
    best = std::min(best,
      TriangleDistance(x, s.Point(s.Triangles[3 * t]), s.Point(s.Triangles[3 * t + 1]),
        s.Point(s.Triangles[3 * t + 2])));
  }
  return best;
}

/// FindCell against ray parity on random points of the root box; the mismatches.
int InsideOutsideMismatches(
  vtkHAVSConvexification* cvx, const Surface& s, int samples, unsigned seed, bool print)
{
  double box[6];
  cvx->GetRootBounds(box);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int mismatches = 0, forgiven = 0, inside = 0, invalid = 0;
  std::set<vtkIdType> cellsHit;
  for (int i = 0; i < samples; ++i)
  {
    Vec x;
    for (int k = 0; k < 3; ++k)
    {
      x[k] = box[2 * k] + unit(random) * (box[2 * k + 1] - box[2 * k]);
    }
    const vtkIdType cell = cvx->FindCell(x.data());
    invalid += cell >= cvx->GetNumberOfImaginaryCells() ? 1 : 0;
    bool in = Inside(s, x, true);
    if (in != (cell == -1))
    {
      in = Inside(s, x, false); // three rays before calling it a mismatch
    }
    inside += in ? 1 : 0;
    if (cell >= 0)
    {
      cellsHit.insert(cell);
    }
    if (in != (cell == -1))
    {
      if (SurfaceDistance(s, x) <= 1e-9)
      {
        ++forgiven;
      }
      else
      {
        ++mismatches;
      }
    }
  }
  if (print)
  {
    std::printf("  %s: %d random points of the root box, %d inside, %d outside in %zu distinct "
                "cells; mismatches %d (+%d within 1e-9 of the surface), invalid cells %d\n",
      s.Name.c_str(), samples, inside, samples - inside, cellsHit.size(), mismatches, forgiven,
      invalid);
  }
  return mismatches + invalid;
}

/// Builds and checks one closed outward surface (`withoutCell` triangles
/// wholly inside internal double walls are expected to have no cell).
void CheckSurface(const Surface& s, int samples, double maxSeconds, long withoutCellExpected = 0)
{
  vtkNew<vtkHAVSConvexification> cvx;
  const bool built = cvx->Build(s.Points, s.Triangles);
  havstest::Check(built, s.Name + ": Build");
  if (!built)
  {
    return;
  }
  const vtkIdType cells = cvx->GetNumberOfImaginaryCells();
  const auto& pairs = cvx->GetTriangleCells();
  const auto& portals = cvx->GetPortals();
  std::printf("%s: %zu triangles (volume %.4f) -> %lld imaginary cells, %lld BSP nodes (depth "
              "%lld), %lld triangle pieces (%lld double-wall overlaps dropped), %zu "
              "triangle-cell pairs, %zu portals, %.3f s\n",
    s.Name.c_str(), s.NumberOfTriangles(), SignedVolume(s), static_cast<long long>(cells),
    static_cast<long long>(cvx->GetNumberOfNodes()), static_cast<long long>(cvx->GetMaximumDepth()),
    static_cast<long long>(cvx->GetNumberOfTrianglePieces()),
    static_cast<long long>(cvx->GetNumberOfOverlappingPieces()), pairs.size(), portals.size(),
    cvx->GetBuildSeconds());
  havstest::Check(SignedVolume(s) > 0.0, s.Name + ": the surface is wound outward");
  havstest::Check(cells > 0, s.Name + ": imaginary cells");
  havstest::Check(cvx->GetBuildSeconds() < maxSeconds,
    s.Name + ": Build within " + std::to_string(maxSeconds) + " s");
  havstest::Check(cvx->GetNumberOfDegenerateTriangles() == 0, s.Name + ": no degenerate triangle");
  havstest::Check(cvx->GetNumberOfInLeafPieces() == 0,
    s.Name + ": no triangle piece reaches an IN leaf on its outer side (" +
      std::to_string(cvx->GetNumberOfInLeafPieces()) + ")");
  havstest::Check(cvx->GetNumberOfTrianglesWithoutCell() == withoutCellExpected,
    s.Name + ": triangles without cell (" + std::to_string(cvx->GetNumberOfTrianglesWithoutCell()) +
      ", expected " + std::to_string(withoutCellExpected) + ")");

  // Triangle-cell pairs: every triangle and every cell; the cell just outside
  // an unsplit triangle's centroid.
  std::vector<int> perTriangle(s.NumberOfTriangles(), 0);
  std::vector<char> cellTouches(static_cast<size_t>(cells), 0);
  bool validPairs = true;
  for (const auto& tc : pairs)
  {
    validPairs = validPairs && tc.first < s.NumberOfTriangles() && tc.second < cells;
    if (validPairs)
    {
      ++perTriangle[tc.first];
      cellTouches[tc.second] = 1;
    }
  }
  havstest::Check(validPairs, s.Name + ": triangle-cell pairs in range");
  const auto withoutCell = std::count(perTriangle.begin(), perTriangle.end(), 0);
  const auto untouched = std::count(cellTouches.begin(), cellTouches.end(), 0);
  double box[6];
  cvx->GetRootBounds(box);
  const double diagonal = std::sqrt((box[1] - box[0]) * (box[1] - box[0]) +
    (box[3] - box[2]) * (box[3] - box[2]) + (box[5] - box[4]) * (box[5] - box[4]));
  int unsplit = 0, wrongCell = 0, covered = 0;
  for (const auto& tc : pairs)
  {
    if (perTriangle[tc.first] != 1)
    {
      continue;
    }
    ++unsplit;
    const Vec a = s.Point(s.Triangles[3 * tc.first]), b = s.Point(s.Triangles[3 * tc.first + 1]),
              c = s.Point(s.Triangles[3 * tc.first + 2]);
    Vec n = Cross(Sub(b, a), Sub(c, a));
    const double l = std::sqrt(Dot(n, n));
    Vec x;
    for (int k = 0; k < 3; ++k)
    {
      x[k] = (a[k] + b[k] + c[k]) / 3.0 + 1e-10 * diagonal * n[k] / l;
    }
    if (cvx->FindCell(x.data()) == static_cast<vtkIdType>(tc.second))
    {
      continue;
    }
    if (Inside(s, x, false))
    {
      ++covered; // the centroid lies on a double wall, the cell touches the rest
      continue;
    }
    ++wrongCell;
  }
  std::printf("  %s: triangles without cell %lld, cells touching no triangle %lld; %d unsplit "
              "triangles (%d centroids on a double wall), %d with the point 1e-10 diagonal "
              "outside the centroid in another cell\n",
    s.Name.c_str(), static_cast<long long>(withoutCell), static_cast<long long>(untouched), unsplit,
    covered, wrongCell);
  havstest::Check(withoutCell == withoutCellExpected, s.Name + ": every triangle has a cell");
  havstest::Check(untouched == 0, s.Name + ": every cell touches a triangle");
  havstest::Check(wrongCell == 0, s.Name + ": cell just outside unsplit triangles");

  // Portals: distinct valid cells, on the right sides of the plane.
  int badPortal = 0, wrongSide = 0;
  std::set<std::pair<uint32_t, uint32_t>> pairsSeen;
  // Portal pieces can be thin slivers: the side points stay close to the plane.
  const double delta = 1e-10 * diagonal;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(portals.size()); ++i)
  {
    const auto& p = portals[i];
    if (p.Cells[0] == p.Cells[1] || p.Cells[0] >= cells || p.Cells[1] >= cells)
    {
      ++badPortal;
      continue;
    }
    pairsSeen.insert({ std::min(p.Cells[0], p.Cells[1]), std::max(p.Cells[0], p.Cells[1]) });
    double c[3];
    cvx->GetPortalCenter(i, c);
    const double onPlane = p.Plane[0] * c[0] + p.Plane[1] * c[1] + p.Plane[2] * c[2] + p.Plane[3];
    double behind[3], before[3];
    for (int k = 0; k < 3; ++k)
    {
      behind[k] = c[k] - delta * p.Plane[k];
      before[k] = c[k] + delta * p.Plane[k];
    }
    if (std::fabs(onPlane) > 1e-9 * diagonal || cvx->FindCell(behind) != p.Cells[0] ||
      cvx->FindCell(before) != p.Cells[1])
    {
      ++wrongSide;
    }
  }
  std::printf("  %s: %zu portals (%zu cell pairs), %d with equal or invalid cells, %d whose "
              "centre +-1e-10 diagonal is not in Cells[1] / Cells[0]\n",
    s.Name.c_str(), portals.size(), pairsSeen.size(), badPortal, wrongSide);
  havstest::Check(badPortal == 0, s.Name + ": portal cells distinct and valid");
  havstest::Check(wrongSide == 0, s.Name + ": portal sides");

  const int mismatches = InsideOutsideMismatches(cvx, s, samples, 7u, true);
  havstest::Check(mismatches == 0, s.Name + ": FindCell == -1 exactly inside the solid");
}
/// The views of the order check: the 8 cube diagonals and 4 directions near
/// the axes (turned by 7 and 5 degrees: the synthetic meshes are voxel grids,
/// from an axis the eye would lie on their face planes).
std::vector<Vec> OrderViews()
{
  std::vector<Vec> views;
  for (int i = 0; i < 8; ++i)
  {
    views.push_back({ i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0 });
  }
  const double a = 7.0 * M_PI / 180.0, b = 5.0 * M_PI / 180.0;
  views.push_back({ std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b) });
  views.push_back({ std::sin(b), -std::cos(a) * std::cos(b), std::sin(a) * std::cos(b) });
  views.push_back({ -std::sin(a) * std::cos(b), std::sin(b), std::cos(a) * std::cos(b) });
  views.push_back({ -std::cos(a) * std::cos(b), -std::sin(b), -std::sin(a) * std::cos(b) });
  return views;
}

struct OrderFigures
{
  int MaxK = 0;
  long long PixelsOver2 = 0;
  long long CycleBreaks = 0;
  long long Cells = 0;
  double BuildSeconds = 0.0;
};

/// The exactness of the MPVO order (vtkHAVSVisibilityOrder with `method`):
/// per view, the exact fragments of every pixel (vtkHAVSReferenceRenderer,
/// 96^2, perspective, view angle 30) through the software k-buffer in that
/// face order; the largest k needed and the cycle breaks over all views.
OrderFigures OrderExactness(vtkUnstructuredGrid* grid, int method, bool verbose)
{
  OrderFigures figures;
  vtkNew<vtkHAVSFaceSet> faces;
  havstest::Check(faces->Build(grid), "face set");
  vtkNew<vtkHAVSVisibilityOrder> order;
  order->SetNonConvexMethod(method);
  havstest::Check(order->Build(faces, grid), "MPVO adjacency");
  double bounds[6];
  grid->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double radius = 0.5 *
    std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double distance = radius / std::sin(15.0 * M_PI / 180.0);
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetSize(96, 96);
  vtkNew<vtkHAVSSoftwareKBuffer> analysis;
  vtkNew<vtkIntArray> requiredK;
  int v = 0;
  for (const Vec& view : OrderViews())
  {
    const double l = std::sqrt(Dot(view, view));
    vtkNew<vtkCamera> camera;
    camera->SetFocalPoint(centre);
    camera->SetPosition(centre[0] + distance * view[0] / l, centre[1] + distance * view[1] / l,
      centre[2] + distance * view[2] / l);
    camera->SetViewUp(
      std::fabs(view[2]) > 0.9 * l ? 1.0 : 0.0, 0.0, std::fabs(view[2]) > 0.9 * l ? 0.0 : 1.0);
    camera->OrthogonalizeViewUp();
    camera->SetViewAngle(30.0);
    camera->SetClippingRange(0.5 * (distance - radius), distance + 2.0 * radius);
    double eye[3], direction[3];
    camera->GetPosition(eye);
    camera->GetDirectionOfProjection(direction);
    order->Sort(eye, direction, false);
    reference->SetCamera(camera);
    havstest::Check(reference->ComputeFragments(), "reference fragments");
    analysis->SetFaceOrder(order->GetOrder());
    analysis->Analyze(reference, requiredK, nullptr);
    const int k = analysis->GetMaximumRequiredK();
    if (verbose)
    {
      std::printf("    view %d (%.2f, %.2f, %.2f): max k %d, %lld pixels k > 2, %lld cycle "
                  "breaks\n",
        v, view[0], view[1], view[2], k, static_cast<long long>(analysis->GetPixelsOverK2()),
        static_cast<long long>(order->GetNumberOfCycleBreaks()));
    }
    figures.MaxK = std::max(figures.MaxK, k);
    figures.PixelsOver2 += analysis->GetPixelsOverK2();
    figures.CycleBreaks += order->GetNumberOfCycleBreaks();
    ++v;
  }
  figures.Cells = order->GetNumberOfImaginaryCells();
  figures.BuildSeconds = order->GetConvexificationSeconds();
  return figures;
}

/// The grid with its points mapped by x -> R (s x) + t (a generic rotation R
/// about `axis`) and stored as float: faces coplanar in the grid are coplanar
/// only up to float rounding afterwards.
vtkSmartPointer<vtkUnstructuredGrid> Transformed(
  vtkUnstructuredGrid* grid, double s, const Vec& axis, double angle, const Vec& t)
{
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->DeepCopy(grid);
  Surface points;
  points.Points.resize(3 * static_cast<size_t>(grid->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    grid->GetPoint(i, &points.Points[3 * i]);
  }
  Transform(points, { s, s, s }, axis, angle, t);
  vtkNew<vtkPoints> p;
  p->SetDataTypeToFloat();
  p->SetNumberOfPoints(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    p->SetPoint(i, &points.Points[3 * i]);
  }
  out->SetPoints(p);
  return out;
}

vtkSmartPointer<vtkUnstructuredGrid> OrderMesh(const std::string& name)
{
  const std::string rotated = " rotated";
  if (name.size() > rotated.size() &&
    name.compare(name.size() - rotated.size(), rotated.size(), rotated) == 0)
  {
    auto grid = OrderMesh(name.substr(0, name.size() - rotated.size()));
    return grid ? Transformed(grid, 0.37, { 0.3, -0.5, 0.8 }, 0.7, { 0.1, 0.2, -0.3 }) : grid;
  }
  return vtkHAVSDataSets::Load(name);
}

/// e) The order of MPVO with the convexification is exact on the non-convex
/// test meshes: k <= 2 and no cycle break in every view; without it (Ignore)
/// the wavelet needs k > 2 (negative control).
void CheckOrders(const std::vector<std::string>& meshes, bool verbose)
{
  for (const std::string& name : meshes)
  {
    auto grid = OrderMesh(name);
    if (!havstest::Check(grid && grid->GetNumberOfCells() > 0, name + ": loads"))
    {
      continue;
    }
    const double start = vtkTimerLog::GetUniversalTime();
    const OrderFigures f =
      OrderExactness(grid, vtkHAVSVisibilityOrder::NonConvexConvexification, verbose);
    std::printf("order %s: %lld tetrahedra, %lld imaginary cells (built in %.3f s), %zu views: "
                "max k %d, %lld pixels k > 2, %lld cycle breaks (%.1f s)\n",
      name.c_str(), static_cast<long long>(grid->GetNumberOfCells()), f.Cells, f.BuildSeconds,
      OrderViews().size(), f.MaxK, f.PixelsOver2, f.CycleBreaks,
      vtkTimerLog::GetUniversalTime() - start);
    havstest::Check(f.MaxK <= 2, name + ": convexification order needs k <= 2");
    havstest::Check(f.CycleBreaks == 0, name + ": convexification order without cycle breaks");
    if (name == "wavelet")
    {
      const OrderFigures g = OrderExactness(grid, vtkHAVSVisibilityOrder::NonConvexIgnore, false);
      std::printf("order %s without convexification (negative control): max k %d, %lld pixels "
                  "k > 2\n",
        name.c_str(), g.MaxK, g.PixelsOver2);
      havstest::Check(g.MaxK > 2, name + ": negative control: without convexification k > 2");
    }
  }
}
}

int TestHAVSConvexification(int argc, char* argv[])
{
  if (argc > 1 && std::string(argv[1]) == "order")
  {
    // Diagnostics: TestHAVSConvexification order <mesh>... (per-view figures).
    CheckOrders(std::vector<std::string>(argv + 2, argv + argc), true);
    std::printf("%s\n", havstest::Failures() ? "FAILED" : "passed");
    return havstest::Result();
  }
  // a) A convex box.
  {
    Surface box = Voxels("box", { { 0, 0, 0 } });
    Transform(box, { 2.0, 1.0, 0.5 }, { 0, 0, 1 }, 0.0, { 0, 0, 0 });
    vtkNew<vtkHAVSConvexification> cvx;
    havstest::Check(cvx->Build(box.Points, box.Triangles), "box: Build");
    const double in[3] = { 1.0, 0.5, 0.25 }, out[3] = { 2.1, 0.5, 0.25 },
                 far[3] = { 100.0, 0.0, 0.0 };
    std::printf("box: 12 triangles -> %lld cells, %zu pairs, %zu portals; FindCell inside %lld, "
                "outside %lld, outside the root box %lld\n",
      static_cast<long long>(cvx->GetNumberOfImaginaryCells()), cvx->GetTriangleCells().size(),
      cvx->GetPortals().size(), static_cast<long long>(cvx->FindCell(in)),
      static_cast<long long>(cvx->FindCell(out)), static_cast<long long>(cvx->FindCell(far)));
    havstest::Check(box.NumberOfTriangles() == 12, "box: 12 triangles");
    havstest::Check(cvx->FindCell(in) == -1, "box: inside point");
    havstest::Check(cvx->FindCell(out) >= 0, "box: outside point");
    havstest::Check(cvx->FindCell(far) == -1, "box: outside the root box");
  }
  CheckSurface(Voxels("box", { { 0, 0, 0 } }), 20000, 20.0);

  // b) Non-convex solids.
  std::set<std::array<int, 3>> u;
  for (int z = 0; z < 2; ++z)
  {
    for (int x = 0; x < 3; ++x)
    {
      u.insert({ x, 0, z });
    }
    for (int y = 1; y < 3; ++y)
    {
      u.insert({ 0, y, z });
      u.insert({ 2, y, z });
    }
  }
  const Surface uShape = Voxels("U-shape", u);
  CheckSurface(uShape, 20000, 20.0);

  std::set<std::array<int, 3>> ring;
  for (int x = 0; x < 3; ++x)
  {
    for (int y = 0; y < 3; ++y)
    {
      if (x != 1 || y != 1)
      {
        ring.insert({ x, y, 0 });
      }
    }
  }
  Surface torus = Voxels("square torus (rotated)", ring);
  Transform(torus, { 1.0, 1.3, 0.7 }, { 0.3, -0.5, 0.8 }, 0.7, { 0.1, 0.2, -0.3 });
  CheckSurface(torus, 20000, 20.0);

  std::set<std::array<int, 3>> blob;
  std::mt19937 random(11u);
  for (int x = 0; x < 6; ++x)
  {
    for (int y = 0; y < 6; ++y)
    {
      for (int z = 0; z < 6; ++z)
      {
        if (random() % 100 < 55)
        {
          blob.insert({ x, y, z });
        }
      }
    }
  }
  Surface voxelBlob = Voxels("voxel blob (rotated)", blob);
  Transform(voxelBlob, { 1.0, 1.0, 1.0 }, { 1.0, 2.0, 3.0 }, 0.4, { 0.0, 0.0, 0.0 });
  CheckSurface(voxelBlob, 20000, 20.0);

  // Internal double walls (a cut whose points are duplicated): two cubes face
  // to face, their shared face triangulated along crossing diagonals, once
  // axis-aligned (the 4 wall triangles have no cell) and once rotated; and
  // two boxes whose faces overlap in part (every triangle keeps a cell).
  {
    const Surface a = Voxels("cube", { { 0, 0, 0 } });
    Surface b = a;
    Transform(b, { 1.0, 1.0, 1.0 }, { 1, 0, 0 }, std::acos(-1.0) / 2, { 1.0, 1.0, 0.0 });
    Surface cubes = Concatenate("two cubes face to face (double wall)", a, b);
    CheckSurface(cubes, 20000, 20.0, 4);
    Transform(cubes, { 1.0, 1.0, 1.0 }, { 0.2, 0.7, -0.4 }, 1.1, { 0.3, 0.0, 0.1 });
    cubes.Name = "two cubes face to face (double wall, rotated)";
    CheckSurface(cubes, 20000, 20.0, 4);
    Surface c = a;
    Transform(c, { 1.0, 1.0, 1.0 }, { 0, 0, 1 }, 0.0, { 1.0, 0.5, 0.25 });
    CheckSurface(Concatenate("two boxes, faces overlapping in part", a, c), 20000, 20.0, 0);
  }

  // c) Negative control: the U-shape wound inward mismatches.
  {
    Surface flipped = uShape;
    flipped.Name = "U-shape wound inward (negative control)";
    for (size_t t = 0; t < flipped.NumberOfTriangles(); ++t)
    {
      std::swap(flipped.Triangles[3 * t + 1], flipped.Triangles[3 * t + 2]);
    }
    vtkNew<vtkHAVSConvexification> cvx;
    havstest::Check(cvx->Build(flipped.Points, flipped.Triangles), "flipped: Build");
    const int mismatches = InsideOutsideMismatches(cvx, flipped, 2000, 3u, true);
    havstest::Check(mismatches > 0, "negative control: the inward-wound U-shape must mismatch");
  }

  // d) Scale: a bumpy (non-convex) sphere of ~20k triangles and a convex one
  // of 25k (a chain of BSP nodes).
  CheckSurface(Sphere("bumpy sphere", 100, 100, 0.1), 5000, 20.0);
  CheckSurface(Sphere("convex sphere", 101, 125, 0.0), 2000, 20.0);

  // Bad input and the empty list.
  {
    vtkNew<vtkHAVSConvexification> cvx;
    const std::vector<double> points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    std::printf("bad input (errors expected):\n");
    havstest::Check(!cvx->Build(points, { 0, 1, 7 }), "id out of range rejected");
    havstest::Check(!cvx->Build(points, { 0, 1 }), "incomplete triangle rejected");
    havstest::Check(!cvx->Build({ 0, 0 }, {}), "incomplete point rejected");
    havstest::Check(!cvx->Build({ 0, 0, NAN, 1, 0, 0, 0, 1, 0 }, { 0, 1, 2 }), "NaN rejected");
    // A degenerate triangle (repeated point) is left out, the rest is kept.
    const std::vector<uint32_t> withDegenerate = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 1, 1, 2 };
    const bool built = cvx->Build(points, withDegenerate);
    bool degenerateWithCell = false;
    for (const auto& tc : cvx->GetTriangleCells())
    {
      degenerateWithCell = degenerateWithCell || tc.first == 4;
    }
    const double inside[3] = { 0.1, 0.1, 0.1 }, outside[3] = { 0.6, 0.6, 0.6 };
    std::printf("tetrahedron + a degenerate triangle: %lld degenerate, %lld cells, %zu pairs, "
                "FindCell inside %lld, outside %lld\n",
      static_cast<long long>(cvx->GetNumberOfDegenerateTriangles()),
      static_cast<long long>(cvx->GetNumberOfImaginaryCells()), cvx->GetTriangleCells().size(),
      static_cast<long long>(cvx->FindCell(inside)),
      static_cast<long long>(cvx->FindCell(outside)));
    havstest::Check(built && cvx->GetNumberOfDegenerateTriangles() == 1 && !degenerateWithCell &&
        cvx->GetNumberOfTrianglesWithoutCell() == 0 && cvx->FindCell(inside) == -1 &&
        cvx->FindCell(outside) >= 0,
      "degenerate triangle left out");
    havstest::Check(cvx->Build(points, {}) && cvx->GetNumberOfImaginaryCells() == 0 &&
        cvx->GetPortals().empty() && cvx->GetTriangleCells().empty() &&
        cvx->FindCell(points.data()) == -1,
      "empty triangle list: no cells");
  }

  // e) The MPVO order with the convexification, on the non-convex test meshes.
  CheckOrders({ "wavelet", "hollowsphere", "torus", "twoblocks", "wavelet rotated" }, false);

  std::printf("%s\n", havstest::Failures() ? "FAILED" : "passed");
  return havstest::Result();
}
