/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSConvexification.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSConvexification.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <unordered_map>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSConvexification);

namespace
{
// Child codes: >= 0 an internal node, InLeaf inside the mesh, <= -2 the
// imaginary cell -2 - code.
constexpr int32_t InLeaf = -1;
inline int32_t OutLeaf(vtkIdType cell)
{
  return static_cast<int32_t>(-2 - cell);
}
inline uint32_t CellOf(int32_t code)
{
  return static_cast<uint32_t>(-2 - code);
}

enum Side
{
  On = 0,
  Front = 1,
  Back = 2,
  Spanning = 3
};

inline double Distance(const double plane[4], const double* p)
{
  return plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3];
}

/// A convex polygon (3 doubles per vertex) and a sphere around it.
struct Polygon
{
  std::vector<double> V;
  double C[3] = { 0.0, 0.0, 0.0 };
  double R = 0.0;
  int32_t Class = -1; // the plane class it lies in (-1: none)
  size_t Size() const { return this->V.size() / 3; }
};

/// Vertex average and largest distance to it.
void BoundingSphere(const double* v, size_t n, double c[3], double& r)
{
  c[0] = c[1] = c[2] = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += v[3 * i + k];
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    c[k] /= static_cast<double>(n);
  }
  double r2 = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    const double dx = v[3 * i] - c[0], dy = v[3 * i + 1] - c[1], dz = v[3 * i + 2] - c[2];
    r2 = std::max(r2, dx * dx + dy * dy + dz * dz);
  }
  r = std::sqrt(r2) * (1.0 + 1e-12);
}

void Bound(Polygon& p)
{
  BoundingSphere(p.V.data(), p.Size(), p.C, p.R);
}

/**
 * The side of a convex polygon: the bounding sphere first, then the vertices
 * (within eps of the plane: on it). Fills dist when it looks at the vertices
 * (always for Spanning).
 */
int Classify(const double plane[4], const double* v, size_t n, const double c[3], double r,
  double eps, std::vector<double>& dist)
{
  const double s = Distance(plane, c);
  if (s - r > eps)
  {
    return Front;
  }
  if (s + r < -eps)
  {
    return Back;
  }
  dist.resize(n);
  bool front = false, back = false;
  for (size_t i = 0; i < n; ++i)
  {
    const double d = Distance(plane, v + 3 * i);
    dist[i] = d;
    front = front || d > eps;
    back = back || d < -eps;
  }
  if (front && back)
  {
    return Spanning;
  }
  return front ? Front : (back ? Back : On);
}

/**
 * Splits a spanning convex polygon (dist from Classify). Vertices within eps
 * of the plane are snapped onto it and go to both parts; edges are cut only
 * between vertices farther than eps on either side.
 */
void Split(const double plane[4], const double* v, size_t n, const std::vector<double>& dist,
  double eps, std::vector<double>& front, std::vector<double>& back)
{
  front.clear();
  back.clear();
  for (size_t i = 0; i < n; ++i)
  {
    const size_t j = (i + 1) % n;
    const double* a = v + 3 * i;
    const double* b = v + 3 * j;
    const double da = dist[i], db = dist[j];
    if (da > eps)
    {
      front.insert(front.end(), a, a + 3);
    }
    else if (da < -eps)
    {
      back.insert(back.end(), a, a + 3);
    }
    else
    {
      const double p[3] = { a[0] - da * plane[0], a[1] - da * plane[1], a[2] - da * plane[2] };
      front.insert(front.end(), p, p + 3);
      back.insert(back.end(), p, p + 3);
    }
    if ((da > eps && db < -eps) || (da < -eps && db > eps))
    {
      const double t = da / (da - db);
      const double p[3] = { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
        a[2] + t * (b[2] - a[2]) };
      front.insert(front.end(), p, p + 3);
      back.insert(back.end(), p, p + 3);
    }
  }
}

/// Area of a planar polygon (fan from its first vertex).
double Area(const double* v, size_t n)
{
  double s[3] = { 0.0, 0.0, 0.0 };
  for (size_t i = 1; i + 1 < n; ++i)
  {
    const double a[3] = { v[3 * i] - v[0], v[3 * i + 1] - v[1], v[3 * i + 2] - v[2] };
    const double b[3] = { v[3 * i + 3] - v[0], v[3 * i + 4] - v[1], v[3 * i + 5] - v[2] };
    s[0] += a[1] * b[2] - a[2] * b[1];
    s[1] += a[2] * b[0] - a[0] * b[2];
    s[2] += a[0] * b[1] - a[1] * b[0];
  }
  return 0.5 * std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
}

inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
}

struct vtkHAVSConvexification::vtkInternals
{
  struct Node
  {
    double Plane[4];     // unit normal (the triangle's outer side is in front), d
    int32_t Class;       // its plane class
    double Eps;          // its on-plane tolerance
    int32_t Child[2];    // back, front (codes above)
    int32_t Parent;      // -1 for the root
    int32_t Side;        // which child of Parent this node is (0 back, 1 front)
    uint32_t PieceBegin; // pieces stored at the node: NodePieces[PieceBegin, PieceEnd)
    uint32_t PieceEnd;
  };
  struct Piece
  {
    uint32_t Triangle;
    uint32_t First; // first vertex in PieceVertices
    uint32_t Count;
    double Center[3];
    double Radius;
  };

  std::vector<Node> Nodes;
  // 4 per triangle (0 for a degenerate one): the plane of its class, oriented
  // like the triangle.
  std::vector<double> TrianglePlanes;
  std::vector<int32_t> TriangleClass; // -1 for a degenerate one
  std::vector<double> ClassPlanes;    // 4 per class
  std::vector<double> ClassEps;       // on-plane tolerance of each class plane
  std::vector<Piece> Pieces;
  std::vector<double> PieceVertices;
  std::vector<uint32_t> NodePieces;
  double Box[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  double BoxDiagonal = 0.0;
  double Eps = 0.0;
  double DegenerateArea = 0.0; // triangles at most this large are left out
  double TinyArea = 0.0;       // pieces at most this large do not count
  size_t NumberOfTriangles = 0;

  uint32_t AddPiece(uint32_t triangle, const std::vector<double>& v)
  {
    Piece p;
    p.Triangle = triangle;
    p.First = static_cast<uint32_t>(this->PieceVertices.size() / 3);
    p.Count = static_cast<uint32_t>(v.size() / 3);
    this->PieceVertices.insert(this->PieceVertices.end(), v.begin(), v.end());
    BoundingSphere(v.data(), p.Count, p.Center, p.Radius);
    this->Pieces.push_back(p);
    return static_cast<uint32_t>(this->Pieces.size() - 1);
  }

  Polygon PiecePolygon(uint32_t id) const
  {
    const Piece& p = this->Pieces[id];
    Polygon poly;
    poly.V.assign(this->PieceVertices.begin() + 3 * static_cast<size_t>(p.First),
      this->PieceVertices.begin() + 3 * static_cast<size_t>(p.First + p.Count));
    std::copy(p.Center, p.Center + 3, poly.C);
    poly.R = p.Radius;
    poly.Class = this->TriangleClass[p.Triangle];
    return poly;
  }

  /// The side of a polygon of a plane class: On for the node's own class.
  int Side(const Node& node, const double* v, size_t n, const double c[3], double r,
    int32_t polygonClass, std::vector<double>& dist) const
  {
    if (polygonClass >= 0 && polygonClass == node.Class)
    {
      return On;
    }
    return Classify(node.Plane, v, n, c, r, node.Eps, dist);
  }

  void BuildPlaneClasses(const std::vector<double>& points, const std::vector<uint32_t>& triangles);

  /**
   * Pushes a convex polygon down from `child`, splitting it by the planes it
   * straddles, and calls emit(leaf code, piece) for every piece reaching a
   * leaf. A polygon lying in a node's plane goes to the side `look` points to.
   */
  template <typename Emit>
  void Push(int32_t child, Polygon&& poly, const double look[3], Emit&& emit) const
  {
    if (child < 0)
    {
      emit(child, poly);
      return;
    }
    std::vector<std::pair<int32_t, Polygon>> stack;
    std::vector<double> dist, front, back;
    stack.emplace_back(child, std::move(poly));
    while (!stack.empty())
    {
      int32_t c = stack.back().first;
      Polygon p = std::move(stack.back().second);
      stack.pop_back();
      while (c >= 0) // follow unsplit polygons without the stack
      {
        const Node& node = this->Nodes[c];
        const int side = this->Side(node, p.V.data(), p.Size(), p.C, p.R, p.Class, dist);
        if (side == Front)
        {
          c = node.Child[1];
        }
        else if (side == Back)
        {
          c = node.Child[0];
        }
        else if (side == On)
        {
          c = node.Child[Dot(node.Plane, look) > 0.0 ? 1 : 0];
        }
        else
        {
          Split(node.Plane, p.V.data(), p.Size(), dist, node.Eps, front, back);
          Polygon b;
          b.V = back;
          b.Class = p.Class;
          Bound(b);
          stack.emplace_back(node.Child[0], std::move(b));
          p.V = front;
          Bound(p);
          c = node.Child[1];
        }
      }
      emit(c, p);
    }
  }

  /**
   * Appends to `out` the parts of the pieces `a` outside all the pieces `b`
   * (coplanar with them, either orientation): the piece itself when no b
   * overlaps it, else new convex pieces; counts the overlaps dropped.
   */
  void Subtract(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b,
    std::vector<uint32_t>& out, vtkIdType& overlaps)
  {
    std::vector<Polygon> fragments, next;
    std::vector<double> dist, front, back;
    for (uint32_t aid : a)
    {
      fragments.assign(1, this->PiecePolygon(aid));
      bool changed = false;
      for (uint32_t bid : b)
      {
        const Piece& pb = this->Pieces[bid];
        const double* vb = &this->PieceVertices[3 * static_cast<size_t>(pb.First)];
        const double* nb = &this->TrianglePlanes[4 * static_cast<size_t>(pb.Triangle)];
        next.clear();
        for (Polygon& rest : fragments)
        {
          const double dc[3] = { rest.C[0] - pb.Center[0], rest.C[1] - pb.Center[1],
            rest.C[2] - pb.Center[2] };
          if (std::sqrt(Dot(dc, dc)) > rest.R + pb.Radius + this->Eps)
          {
            next.push_back(std::move(rest));
            continue;
          }
          // Clip by the outward edge planes of b: what lies outside an edge is kept.
          bool inside = true;
          for (uint32_t i = 0; i < pb.Count && inside; ++i)
          {
            const double* e0 = vb + 3 * i;
            const double* e1 = vb + 3 * ((i + 1) % pb.Count);
            const double e[3] = { e1[0] - e0[0], e1[1] - e0[1], e1[2] - e0[2] };
            double edge[4] = { e[1] * nb[2] - e[2] * nb[1], e[2] * nb[0] - e[0] * nb[2],
              e[0] * nb[1] - e[1] * nb[0], 0.0 };
            const double length = std::sqrt(Dot(edge, edge));
            if (!(length > this->Eps))
            {
              continue;
            }
            for (int k = 0; k < 3; ++k)
            {
              edge[k] /= length;
            }
            edge[3] = -Dot(edge, e0);
            const int side =
              Classify(edge, rest.V.data(), rest.Size(), rest.C, rest.R, this->Eps, dist);
            if (side == Front)
            {
              next.push_back(std::move(rest));
              inside = false;
            }
            else if (side == Spanning)
            {
              Split(edge, rest.V.data(), rest.Size(), dist, this->Eps, front, back);
              Polygon outside;
              outside.V = front;
              Bound(outside);
              next.push_back(std::move(outside));
              rest.V = back;
              Bound(rest);
              changed = true;
            }
          }
          if (inside)
          {
            ++overlaps; // rest overlaps b: dropped
            changed = true;
          }
        }
        fragments.swap(next);
      }
      if (!changed)
      {
        out.push_back(aid);
        continue;
      }
      const uint32_t triangle = this->Pieces[aid].Triangle;
      for (const Polygon& f : fragments)
      {
        if (Area(f.V.data(), f.Size()) > this->TinyArea)
        {
          out.push_back(this->AddPiece(triangle, f.V));
        }
      }
    }
  }

  /// Keeps the part of poly on one side of the plane; false when nothing is left.
  bool Clip(Polygon& poly, const double plane[4], double eps, int32_t planeClass, bool keepFront,
    std::vector<double>& dist, std::vector<double>& front, std::vector<double>& back) const
  {
    const int side = poly.Class >= 0 && poly.Class == planeClass
      ? On
      : Classify(plane, poly.V.data(), poly.Size(), poly.C, poly.R, eps, dist);
    if (side == On)
    {
      return true;
    }
    if (side == Front)
    {
      return keepFront;
    }
    if (side == Back)
    {
      return !keepFront;
    }
    Split(plane, poly.V.data(), poly.Size(), dist, eps, front, back);
    poly.V = keepFront ? front : back;
    Bound(poly);
    return true;
  }
};

//------------------------------------------------------------------------------
void vtkHAVSConvexification::vtkInternals::BuildPlaneClasses(
  const std::vector<double>& points, const std::vector<uint32_t>& triangles)
{
  const size_t n = this->NumberOfTriangles;
  this->TriangleClass.assign(n, -1);
  this->ClassPlanes.clear();
  this->ClassEps.clear();
  auto vertex = [&](size_t t, int i)
  { return &points[3 * static_cast<size_t>(triangles[3 * t + i])]; };

  // Largest triangles first: a class starts with the plane of its largest one.
  std::vector<double> area(n, 0.0);
  std::vector<uint32_t> order;
  for (size_t t = 0; t < n; ++t)
  {
    const double* plane = &this->TrianglePlanes[4 * t];
    if (plane[0] == 0.0 && plane[1] == 0.0 && plane[2] == 0.0)
    {
      continue; // degenerate
    }
    const double* p0 = vertex(t, 0);
    const double* p1 = vertex(t, 1);
    const double* p2 = vertex(t, 2);
    const double a[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
    const double b[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
    const double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0] };
    area[t] = 0.5 * std::sqrt(Dot(c, c));
    order.push_back(static_cast<uint32_t>(t));
  }
  std::stable_sort(
    order.begin(), order.end(), [&](uint32_t x, uint32_t y) { return area[x] > area[y]; });

  // A triangle joins the class whose first plane has all its vertices within
  // joinTolerance (the closest such), else starts one. Classes are filed by
  // the cell of their normal (and of its opposite) on a grid of 1/256; a
  // triangle looks in its normal's cell and the nearest neighbours.
  const double joinTolerance = 16.0 * this->Eps;
  const double cell = 1.0 / 256.0;
  auto key = [](const int c[3])
  {
    return static_cast<uint64_t>(c[0] + 1024) | (static_cast<uint64_t>(c[1] + 1024) << 16) |
      (static_cast<uint64_t>(c[2] + 1024) << 32);
  };
  std::unordered_map<uint64_t, std::vector<int32_t>> buckets;
  std::vector<double> first; // 4 per class: the plane of its first triangle
  for (uint32_t t : order)
  {
    const double* plane = &this->TrianglePlanes[4 * static_cast<size_t>(t)];
    int base[3], next[3];
    for (int k = 0; k < 3; ++k)
    {
      const double q = plane[k] / cell;
      base[k] = static_cast<int>(std::floor(q));
      next[k] = q - base[k] < 0.5 ? base[k] - 1 : base[k] + 1;
    }
    int32_t best = -1;
    double bestDistance = joinTolerance;
    for (int corner = 0; corner < 8; ++corner)
    {
      const int c[3] = { corner & 1 ? next[0] : base[0], corner & 2 ? next[1] : base[1],
        corner & 4 ? next[2] : base[2] };
      const auto it = buckets.find(key(c));
      if (it == buckets.end())
      {
        continue;
      }
      for (int32_t candidate : it->second)
      {
        const double* p = &first[4 * static_cast<size_t>(candidate)];
        if (std::fabs(Dot(p, plane)) < 0.5)
        {
          continue;
        }
        double worst = 0.0;
        for (int i = 0; i < 3; ++i)
        {
          worst = std::max(worst, std::fabs(Distance(p, vertex(t, i))));
        }
        if (worst <= bestDistance)
        {
          bestDistance = worst;
          best = candidate;
        }
      }
    }
    if (best < 0)
    {
      best = static_cast<int32_t>(first.size() / 4);
      first.insert(first.end(), plane, plane + 4);
      for (int s = 1; s >= -1; s -= 2)
      {
        int c[3];
        for (int k = 0; k < 3; ++k)
        {
          c[k] = static_cast<int>(std::floor(s * plane[k] / cell));
        }
        buckets[key(c)].push_back(best);
      }
    }
    this->TriangleClass[t] = best;
  }

  // Each class's plane: the least-squares plane of its triangles' vertices
  // (area-weighted), oriented like its first plane; its tolerance covers the
  // vertices' distances to it.
  const size_t classes = first.size() / 4;
  std::vector<double> weight(classes, 0.0), sum(3 * classes, 0.0), square(9 * classes, 0.0);
  std::vector<int> members(classes, 0);
  for (uint32_t t : order)
  {
    const size_t c = static_cast<size_t>(this->TriangleClass[t]);
    ++members[c];
    for (int i = 0; i < 3; ++i)
    {
      const double* v = vertex(t, i);
      weight[c] += area[t];
      for (int k = 0; k < 3; ++k)
      {
        sum[3 * c + k] += area[t] * v[k];
      }
    }
  }
  std::vector<double> mean(3 * classes, 0.0);
  for (size_t c = 0; c < classes; ++c)
  {
    for (int k = 0; k < 3; ++k)
    {
      mean[3 * c + k] = sum[3 * c + k] / weight[c];
    }
  }
  for (uint32_t t : order)
  {
    const size_t c = static_cast<size_t>(this->TriangleClass[t]);
    if (members[c] < 2)
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      const double* v = vertex(t, i);
      const double d[3] = { v[0] - mean[3 * c], v[1] - mean[3 * c + 1], v[2] - mean[3 * c + 2] };
      for (int r = 0; r < 3; ++r)
      {
        for (int k = 0; k < 3; ++k)
        {
          square[9 * c + 3 * r + k] += area[t] * d[r] * d[k];
        }
      }
    }
  }
  this->ClassPlanes.assign(4 * classes, 0.0);
  for (size_t c = 0; c < classes; ++c)
  {
    double* plane = &this->ClassPlanes[4 * c];
    std::copy(&first[4 * c], &first[4 * c] + 4, plane);
    if (members[c] < 2)
    {
      continue; // the triangle's own plane
    }
    double a[3][3], vectors[3][3], values[3];
    for (int r = 0; r < 3; ++r)
    {
      for (int k = 0; k < 3; ++k)
      {
        a[r][k] = square[9 * c + 3 * r + k];
      }
    }
    double* rows[3] = { a[0], a[1], a[2] };
    double* columns[3] = { vectors[0], vectors[1], vectors[2] };
    vtkMath::Jacobi(rows, values, columns); // eigenvalues decreasing, vectors in columns
    double normal[3] = { vectors[0][2], vectors[1][2], vectors[2][2] };
    const double length = std::sqrt(Dot(normal, normal));
    if (!(length > 0.0))
    {
      continue;
    }
    const double sign = Dot(normal, plane) < 0.0 ? -1.0 : 1.0;
    for (int k = 0; k < 3; ++k)
    {
      normal[k] *= sign / length;
    }
    if (Dot(normal, plane) < 0.999)
    {
      continue; // not a plane: keep the first one
    }
    std::copy(normal, normal + 3, plane);
    plane[3] = -Dot(normal, &mean[3 * c]);
  }
  this->ClassEps.assign(classes, this->Eps);
  for (uint32_t t : order)
  {
    const size_t c = static_cast<size_t>(this->TriangleClass[t]);
    const double* plane = &this->ClassPlanes[4 * c];
    for (int i = 0; i < 3; ++i)
    {
      this->ClassEps[c] =
        std::max(this->ClassEps[c], 1.5 * std::fabs(Distance(plane, vertex(t, i))));
    }
    // The triangle's plane from now on: its class's, oriented like it.
    double* own = &this->TrianglePlanes[4 * static_cast<size_t>(t)];
    const double sign = Dot(own, plane) < 0.0 ? -1.0 : 1.0;
    for (int k = 0; k < 4; ++k)
    {
      own[k] = sign * plane[k];
    }
  }
}

//------------------------------------------------------------------------------
vtkHAVSConvexification::vtkHAVSConvexification()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkHAVSConvexification::~vtkHAVSConvexification() = default;

//------------------------------------------------------------------------------
void vtkHAVSConvexification::Reset()
{
  this->Internals.reset(new vtkInternals);
  this->TriangleCells.clear();
  this->Portals.clear();
  this->PortalCenters.clear();
  this->NumberOfImaginaryCells = 0;
  this->NumberOfTrianglePieces = 0;
  this->NumberOfNodes = 0;
  this->MaximumDepth = 0;
  this->NumberOfDegenerateTriangles = 0;
  this->NumberOfInLeafPieces = 0;
  this->NumberOfTrianglesWithoutCell = 0;
  this->NumberOfOverlappingPieces = 0;
}

//------------------------------------------------------------------------------
bool vtkHAVSConvexification::Build(
  const std::vector<double>& points, const std::vector<uint32_t>& triangles)
{
  const double start = vtkTimerLog::GetUniversalTime();
  this->Reset();
  this->BuildSeconds = 0.0;
  if (points.size() % 3 != 0 || triangles.size() % 3 != 0)
  {
    vtkErrorMacro("Points need 3 coordinates and triangles 3 point ids each (got "
      << points.size() << " coordinates, " << triangles.size() << " ids).");
    return false;
  }
  const size_t numPoints = points.size() / 3;
  for (double x : points)
  {
    if (!std::isfinite(x))
    {
      vtkErrorMacro("A point coordinate is not finite.");
      return false;
    }
  }
  for (uint32_t id : triangles)
  {
    if (id >= numPoints)
    {
      vtkErrorMacro("Point id " << id << " out of range (" << numPoints << " points).");
      return false;
    }
  }
  if (triangles.empty())
  {
    this->BuildSeconds = vtkTimerLog::GetUniversalTime() - start;
    return true;
  }

  vtkInternals& in = *this->Internals;
  double bounds[6] = { points[0], points[0], points[1], points[1], points[2], points[2] };
  for (size_t p = 0; p < numPoints; ++p)
  {
    for (int k = 0; k < 3; ++k)
    {
      bounds[2 * k] = std::min(bounds[2 * k], points[3 * p + k]);
      bounds[2 * k + 1] = std::max(bounds[2 * k + 1], points[3 * p + k]);
    }
  }
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  for (int k = 0; k < 3; ++k)
  {
    in.Box[2 * k] = bounds[2 * k] - 0.1 * diagonal;
    in.Box[2 * k + 1] = bounds[2 * k + 1] + 0.1 * diagonal;
  }
  in.BoxDiagonal = std::sqrt((in.Box[1] - in.Box[0]) * (in.Box[1] - in.Box[0]) +
    (in.Box[3] - in.Box[2]) * (in.Box[3] - in.Box[2]) +
    (in.Box[5] - in.Box[4]) * (in.Box[5] - in.Box[4]));
  // The on-plane tolerance: 1e-9 of the box diagonal, or 16 rounding errors
  // of the coordinates where they are single precision (all of them exactly
  // floats, as VTK's float points give: 1/24 is then off by up to 3e-9 and a
  // plane through three such points tilts), at most 1e-5 of the diagonal.
  bool singlePrecision = true;
  double largest = 0.0;
  for (double x : points)
  {
    singlePrecision = singlePrecision && static_cast<double>(static_cast<float>(x)) == x;
    largest = std::max(largest, std::fabs(x));
  }
  const double rounding = (singlePrecision ? std::ldexp(1.0, -24) : std::ldexp(1.0, -53)) * largest;
  in.Eps = std::min(std::max(1e-9 * in.BoxDiagonal, 16.0 * rounding), 1e-5 * in.BoxDiagonal);
  in.DegenerateArea = 1e-12 * in.BoxDiagonal * in.BoxDiagonal;
  in.TinyArea = 1e-18 * in.BoxDiagonal * in.BoxDiagonal;

  // Planes from the input points; every non-degenerate triangle is a piece.
  in.NumberOfTriangles = triangles.size() / 3;
  in.TrianglePlanes.assign(4 * in.NumberOfTriangles, 0.0);
  std::vector<double> tri(9);
  for (size_t t = 0; t < in.NumberOfTriangles; ++t)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        tri[3 * i + k] = points[3 * static_cast<size_t>(triangles[3 * t + i]) + k];
      }
    }
    const double a[3] = { tri[3] - tri[0], tri[4] - tri[1], tri[5] - tri[2] };
    const double b[3] = { tri[6] - tri[0], tri[7] - tri[1], tri[8] - tri[2] };
    double n[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0] };
    const double length = std::sqrt(Dot(n, n));
    if (!(0.5 * length > in.DegenerateArea))
    {
      ++this->NumberOfDegenerateTriangles;
      continue;
    }
    double* plane = &in.TrianglePlanes[4 * t];
    for (int k = 0; k < 3; ++k)
    {
      plane[k] = n[k] / length;
    }
    const double c[3] = { (tri[0] + tri[3] + tri[6]) / 3.0, (tri[1] + tri[4] + tri[7]) / 3.0,
      (tri[2] + tri[5] + tri[8]) / 3.0 };
    plane[3] = -Dot(plane, c);
  }
  in.BuildPlaneClasses(points, triangles);
  for (size_t t = 0; t < in.NumberOfTriangles; ++t)
  {
    if (in.TriangleClass[t] < 0)
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        tri[3 * i + k] = points[3 * static_cast<size_t>(triangles[3 * t + i]) + k];
      }
    }
    in.AddPiece(static_cast<uint32_t>(t), tri);
  }

  this->BuildTree();
  this->BuildTriangleCells();
  this->BuildPortals();
  this->BuildSeconds = vtkTimerLog::GetUniversalTime() - start;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSConvexification::BuildTree()
{
  vtkInternals& in = *this->Internals;
  using Piece = vtkInternals::Piece;
  using Node = vtkInternals::Node;
  if (in.Pieces.empty())
  {
    return;
  }
  struct Task
  {
    int32_t Parent;
    int32_t Side;
    vtkIdType Depth;
    std::vector<uint32_t> List;
  };
  std::vector<Task> stack(1);
  stack[0].Parent = -1;
  stack[0].Side = 1;
  stack[0].Depth = 1;
  stack[0].List.resize(in.Pieces.size());
  std::iota(stack[0].List.begin(), stack[0].List.end(), 0u);

  std::mt19937 random(4u); // candidates at random, reproducibly
  std::vector<double> dist, front, back, source;
  std::vector<uint32_t> sameOn, oppositeOn;
  while (!stack.empty())
  {
    Task task = std::move(stack.back());
    stack.pop_back();
    std::vector<uint32_t>& list = task.List;

    // The splitter: up to 8 candidates, each scored on a sample of at most
    // ~256 pieces; the fewest straddled pieces, then the most balanced cut.
    uint32_t splitter = list[0];
    if (list.size() > 1)
    {
      const size_t candidates = std::min<size_t>(8, list.size());
      const size_t step = std::max<size_t>(1, list.size() / 256);
      size_t bestStraddling = std::numeric_limits<size_t>::max();
      size_t bestBalance = 0;
      for (size_t c = 0; c < candidates; ++c)
      {
        const uint32_t candidate = list[list.size() <= 8 ? c : random() % list.size()];
        const uint32_t candidateTriangle = in.Pieces[candidate].Triangle;
        Node probe;
        std::copy(&in.TrianglePlanes[4 * static_cast<size_t>(candidateTriangle)],
          &in.TrianglePlanes[4 * static_cast<size_t>(candidateTriangle)] + 4, probe.Plane);
        probe.Class = in.TriangleClass[candidateTriangle];
        probe.Eps = in.ClassEps[probe.Class];
        size_t straddling = 0, inFront = 0, behind = 0;
        for (size_t k = 0; k < list.size(); k += step)
        {
          const Piece& p = in.Pieces[list[k]];
          switch (in.Side(probe, &in.PieceVertices[3 * static_cast<size_t>(p.First)], p.Count,
            p.Center, p.Radius, in.TriangleClass[p.Triangle], dist))
          {
            case Front:
              ++inFront;
              break;
            case Back:
              ++behind;
              break;
            case Spanning:
              ++straddling;
              break;
            default:
              break;
          }
        }
        const size_t balance = std::min(inFront, behind);
        if (straddling < bestStraddling || (straddling == bestStraddling && balance > bestBalance))
        {
          bestStraddling = straddling;
          bestBalance = balance;
          splitter = candidate;
        }
      }
    }

    const uint32_t splitTriangle = in.Pieces[splitter].Triangle;
    const double* plane = &in.TrianglePlanes[4 * static_cast<size_t>(splitTriangle)];
    Node node;
    std::copy(plane, plane + 4, node.Plane);
    node.Class = in.TriangleClass[splitTriangle];
    node.Eps = in.ClassEps[node.Class];
    node.Child[0] = node.Child[1] = InLeaf;
    node.Parent = task.Parent;
    node.Side = task.Side;
    node.PieceBegin = static_cast<uint32_t>(in.NodePieces.size());
    const int32_t id = static_cast<int32_t>(in.Nodes.size());
    if (task.Parent >= 0)
    {
      in.Nodes[task.Parent].Child[task.Side] = id;
    }
    this->MaximumDepth = std::max(this->MaximumDepth, task.Depth);

    // Partition: the back list in place, the front list new.
    std::vector<uint32_t> frontList;
    sameOn.clear();
    oppositeOn.clear();
    size_t kept = 0;
    for (size_t i = 0; i < list.size(); ++i)
    {
      const uint32_t pid = list[i];
      const Piece p = in.Pieces[pid]; // a copy: AddPiece may reallocate
      const double* v = &in.PieceVertices[3 * static_cast<size_t>(p.First)];
      const int side =
        in.Side(node, v, p.Count, p.Center, p.Radius, in.TriangleClass[p.Triangle], dist);
      if (side == On)
      {
        // Coplanar: the orientation of its class plane (within eps of the
        // node's plane but of another class: the sign of the normals' dot).
        if (Dot(&in.TrianglePlanes[4 * static_cast<size_t>(p.Triangle)], plane) > 0.0)
        {
          sameOn.push_back(pid); // coplanar, same orientation: stays here
        }
        else
        {
          oppositeOn.push_back(pid); // coplanar, opposite orientation: its outside is behind
        }
      }
      else if (side == Front)
      {
        frontList.push_back(pid);
      }
      else if (side == Back)
      {
        list[kept++] = pid;
      }
      else
      {
        source.assign(v, v + 3 * static_cast<size_t>(p.Count));
        Split(plane, source.data(), p.Count, dist, node.Eps, front, back);
        frontList.push_back(in.AddPiece(p.Triangle, front));
        list[kept++] = in.AddPiece(p.Triangle, back);
      }
    }
    list.resize(kept);
    if (oppositeOn.empty())
    {
      in.NodePieces.insert(in.NodePieces.end(), sameOn.begin(), sameOn.end());
    }
    else if (sameOn.empty())
    {
      list.insert(list.end(), oppositeOn.begin(), oppositeOn.end());
    }
    else
    {
      // Where coplanar pieces of both orientations overlap, the mesh lies on
      // both sides (an internal double wall, e.g. a cut whose points are
      // duplicated): the overlap bounds nothing and is dropped from both.
      // Otherwise the opposite pieces behind would mark the mesh there as out.
      in.Subtract(sameOn, oppositeOn, in.NodePieces, this->NumberOfOverlappingPieces);
      in.Subtract(oppositeOn, sameOn, list, this->NumberOfOverlappingPieces);
    }
    node.PieceEnd = static_cast<uint32_t>(in.NodePieces.size());
    if (frontList.empty())
    {
      // Nothing in front: outside, unless all this node's pieces were
      // double walls (then the mesh lies on both sides).
      node.Child[1] =
        node.PieceEnd > node.PieceBegin ? OutLeaf(this->NumberOfImaginaryCells++) : InLeaf;
    }
    in.Nodes.push_back(node);
    if (!list.empty())
    {
      stack.push_back(Task{ id, 0, task.Depth + 1, std::move(list) });
    }
    if (!frontList.empty())
    {
      stack.push_back(Task{ id, 1, task.Depth + 1, std::move(frontList) });
    }
  }
  this->NumberOfNodes = static_cast<vtkIdType>(in.Nodes.size());
  this->NumberOfTrianglePieces = static_cast<vtkIdType>(in.NodePieces.size());
}

//------------------------------------------------------------------------------
void vtkHAVSConvexification::BuildTriangleCells()
{
  vtkInternals& in = *this->Internals;
  for (const auto& node : in.Nodes)
  {
    for (uint32_t k = node.PieceBegin; k < node.PieceEnd; ++k)
    {
      const uint32_t pid = in.NodePieces[k];
      const uint32_t triangle = in.Pieces[pid].Triangle;
      in.Push(node.Child[1], in.PiecePolygon(pid), node.Plane,
        [&](int32_t leaf, const Polygon& piece)
        {
          if (Area(piece.V.data(), piece.Size()) <= in.TinyArea)
          {
            return;
          }
          if (leaf == InLeaf)
          {
            ++this->NumberOfInLeafPieces;
          }
          else
          {
            this->TriangleCells.emplace_back(triangle, CellOf(leaf));
          }
        });
    }
  }
  std::sort(this->TriangleCells.begin(), this->TriangleCells.end());
  this->TriangleCells.erase(
    std::unique(this->TriangleCells.begin(), this->TriangleCells.end()), this->TriangleCells.end());

  std::vector<char> hasCell(in.NumberOfTriangles, 0);
  for (const auto& tc : this->TriangleCells)
  {
    hasCell[tc.first] = 1;
  }
  for (size_t t = 0; t < in.NumberOfTriangles; ++t)
  {
    const double* plane = &in.TrianglePlanes[4 * t];
    const bool degenerate = plane[0] == 0.0 && plane[1] == 0.0 && plane[2] == 0.0;
    if (!degenerate && !hasCell[t])
    {
      ++this->NumberOfTrianglesWithoutCell;
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSConvexification::BuildPortals()
{
  vtkInternals& in = *this->Internals;
  struct Record
  {
    uint32_t Node, Back, Front;
    double Area;
    double Center[3];
  };
  std::vector<Record> records;
  std::vector<double> dist, front, back;
  const double boxCenter[3] = { 0.5 * (in.Box[0] + in.Box[1]), 0.5 * (in.Box[2] + in.Box[3]),
    0.5 * (in.Box[4] + in.Box[5]) };
  const double boxPlanes[6][4] = { { 1, 0, 0, -in.Box[0] }, { -1, 0, 0, in.Box[1] },
    { 0, 1, 0, -in.Box[2] }, { 0, -1, 0, in.Box[3] }, { 0, 0, 1, -in.Box[4] },
    { 0, 0, -1, in.Box[5] } };

  for (size_t n = 0; n < in.Nodes.size(); ++n)
  {
    const auto& node = in.Nodes[n];
    const double* normal = node.Plane;

    // The node's region cut by its plane: a big square on the plane, clipped
    // by the root box, then by the ancestors' half-spaces, nearest first.
    int axis = 0;
    for (int k = 1; k < 3; ++k)
    {
      axis = std::fabs(normal[k]) < std::fabs(normal[axis]) ? k : axis;
    }
    double e[3] = { 0.0, 0.0, 0.0 };
    e[axis] = 1.0;
    double u[3] = { normal[1] * e[2] - normal[2] * e[1], normal[2] * e[0] - normal[0] * e[2],
      normal[0] * e[1] - normal[1] * e[0] };
    const double ul = std::sqrt(Dot(u, u));
    for (double& x : u)
    {
      x /= ul;
    }
    const double v[3] = { normal[1] * u[2] - normal[2] * u[1], normal[2] * u[0] - normal[0] * u[2],
      normal[0] * u[1] - normal[1] * u[0] };
    const double s = Distance(node.Plane, boxCenter);
    const double c[3] = { boxCenter[0] - s * normal[0], boxCenter[1] - s * normal[1],
      boxCenter[2] - s * normal[2] };
    const double h = in.BoxDiagonal;
    Polygon poly;
    const double corners[4][2] = { { -h, -h }, { h, -h }, { h, h }, { -h, h } };
    for (const auto& corner : corners)
    {
      for (int k = 0; k < 3; ++k)
      {
        poly.V.push_back(c[k] + corner[0] * u[k] + corner[1] * v[k]);
      }
    }
    Bound(poly);
    poly.Class = node.Class;
    bool alive = true;
    for (int b = 0; b < 6 && alive; ++b)
    {
      alive = in.Clip(poly, boxPlanes[b], in.Eps, -1, true, dist, front, back);
    }
    for (int32_t child = static_cast<int32_t>(n); alive && in.Nodes[child].Parent >= 0;
         child = in.Nodes[child].Parent)
    {
      const auto& parent = in.Nodes[in.Nodes[child].Parent];
      alive = in.Clip(
        poly, parent.Plane, parent.Eps, parent.Class, in.Nodes[child].Side == 1, dist, front, back);
    }
    if (!alive || Area(poly.V.data(), poly.Size()) <= in.TinyArea)
    {
      continue;
    }

    // Its pieces in front, each pushed down behind: OUT leaves on both sides.
    const double lookBack[3] = { -normal[0], -normal[1], -normal[2] };
    in.Push(node.Child[1], std::move(poly), normal,
      [&](int32_t frontLeaf, Polygon& fragment)
      {
        if (frontLeaf == InLeaf || Area(fragment.V.data(), fragment.Size()) <= in.TinyArea)
        {
          return;
        }
        in.Push(node.Child[0], std::move(fragment), lookBack,
          [&](int32_t backLeaf, const Polygon& piece)
          {
            if (backLeaf == InLeaf)
            {
              return;
            }
            const double area = Area(piece.V.data(), piece.Size());
            if (area <= in.TinyArea)
            {
              return;
            }
            Record r;
            r.Node = static_cast<uint32_t>(n);
            r.Back = CellOf(backLeaf);
            r.Front = CellOf(frontLeaf);
            r.Area = area;
            double radius;
            BoundingSphere(piece.V.data(), piece.Size(), r.Center, radius); // vertex average
            records.push_back(r);
          });
      });
  }

  // One portal per (node, pair): the largest piece's centre.
  std::sort(records.begin(), records.end(),
    [](const Record& a, const Record& b)
    {
      if (a.Node != b.Node)
      {
        return a.Node < b.Node;
      }
      if (a.Back != b.Back)
      {
        return a.Back < b.Back;
      }
      if (a.Front != b.Front)
      {
        return a.Front < b.Front;
      }
      return a.Area > b.Area;
    });
  for (size_t i = 0; i < records.size(); ++i)
  {
    const Record& r = records[i];
    if (i > 0 && records[i - 1].Node == r.Node && records[i - 1].Back == r.Back &&
      records[i - 1].Front == r.Front)
    {
      continue;
    }
    Portal portal;
    portal.Cells[0] = r.Back;
    portal.Cells[1] = r.Front;
    std::copy(in.Nodes[r.Node].Plane, in.Nodes[r.Node].Plane + 4, portal.Plane);
    this->Portals.push_back(portal);
    this->PortalCenters.insert(this->PortalCenters.end(), r.Center, r.Center + 3);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSConvexification::GetPortalCenter(vtkIdType i, double center[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    center[k] = (i >= 0 && i < static_cast<vtkIdType>(this->Portals.size()))
      ? this->PortalCenters[3 * static_cast<size_t>(i) + k]
      : 0.0;
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSConvexification::FindCell(const double x[3]) const
{
  const vtkInternals& in = *this->Internals;
  if (in.Nodes.empty())
  {
    return -1;
  }
  for (int k = 0; k < 3; ++k)
  {
    if (!(x[k] >= in.Box[2 * k] && x[k] <= in.Box[2 * k + 1]))
    {
      return -1;
    }
  }
  int32_t c = 0;
  while (c >= 0)
  {
    const auto& node = in.Nodes[c];
    c = node.Child[Distance(node.Plane, x) >= 0.0 ? 1 : 0]; // on the plane: front
  }
  return c == InLeaf ? -1 : static_cast<vtkIdType>(CellOf(c));
}

//------------------------------------------------------------------------------
void vtkHAVSConvexification::GetRootBounds(double bounds[6]) const
{
  std::copy(this->Internals->Box, this->Internals->Box + 6, bounds);
}

//------------------------------------------------------------------------------
void vtkHAVSConvexification::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const vtkInternals& in = *this->Internals;
  os << indent << "NumberOfTriangles: " << in.NumberOfTriangles << "\n";
  os << indent << "NumberOfDegenerateTriangles: " << this->NumberOfDegenerateTriangles << "\n";
  os << indent << "RootBounds: (" << in.Box[0] << ", " << in.Box[1] << ", " << in.Box[2] << ", "
     << in.Box[3] << ", " << in.Box[4] << ", " << in.Box[5] << ")\n";
  os << indent << "NumberOfNodes: " << this->NumberOfNodes << "\n";
  os << indent << "MaximumDepth: " << this->MaximumDepth << "\n";
  os << indent << "NumberOfImaginaryCells: " << this->NumberOfImaginaryCells << "\n";
  os << indent << "NumberOfTrianglePieces: " << this->NumberOfTrianglePieces << "\n";
  os << indent << "NumberOfTriangleCells: " << this->TriangleCells.size() << "\n";
  os << indent << "NumberOfPortals: " << this->Portals.size() << "\n";
  os << indent << "NumberOfOverlappingPieces: " << this->NumberOfOverlappingPieces << "\n";
  os << indent << "NumberOfInLeafPieces: " << this->NumberOfInLeafPieces << "\n";
  os << indent << "NumberOfTrianglesWithoutCell: " << this->NumberOfTrianglesWithoutCell << "\n";
  os << indent << "BuildSeconds: " << this->BuildSeconds << "\n";
}

//------------------------------------------------------------------------------
size_t vtkHAVSConvexification::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(this->TriangleCells, this->Portals, this->PortalCenters);
}

VTK_ABI_NAMESPACE_END
