/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceRasterizer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSFaceRasterizer.h"

#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSFaceRasterizer);

namespace
{
/// A ray with Woop et al.'s shear into its frame: the dominant axis last.
struct ShearedRay
{
  vtkHAVSFaceRasterizer::Ray Ray;
  int Kx, Ky, Kz;
  double Sx, Sy, Sz;
};

ShearedRay Shear(const vtkHAVSFaceRasterizer::Ray& ray)
{
  ShearedRay s;
  s.Ray = ray;
  s.Kz = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (std::fabs(ray.Direction[k]) > std::fabs(ray.Direction[s.Kz]))
    {
      s.Kz = k;
    }
  }
  s.Kx = (s.Kz + 1) % 3;
  s.Ky = (s.Kx + 1) % 3;
  s.Sx = ray.Direction[s.Kx] / ray.Direction[s.Kz];
  s.Sy = ray.Direction[s.Ky] / ray.Direction[s.Kz];
  s.Sz = 1.0 / ray.Direction[s.Kz];
  return s;
}

/// A vertex in the ray's sheared frame.
struct Sheared
{
  double X, Y, Z;
};

Sheared ToRayFrame(const ShearedRay& r, const double v[3])
{
  const double* o = r.Ray.Origin;
  const double a[3] = { v[0] - o[0], v[1] - o[1], v[2] - o[2] };
  return { a[r.Kx] - r.Sx * a[r.Kz], a[r.Ky] - r.Sy * a[r.Kz], r.Sz * a[r.Kz] };
}

/// Edge function of the directed edge a -> b at the ray (the origin of the
/// sheared frame).
double EdgeFunction(const Sheared& a, const Sheared& b)
{
  return a.X * b.Y - a.Y * b.X;
}

/// The edge function's sign under the symbolic perturbation (e, e^2).
int PerturbedSign(const Sheared& a, const Sheared& b, double e0)
{
  if (e0 != 0.0)
  {
    return e0 > 0.0 ? 1 : -1;
  }
  const double first = a.Y - b.Y; // coefficient of e
  if (first != 0.0)
  {
    return first > 0.0 ? 1 : -1;
  }
  const double second = b.X - a.X; // coefficient of e^2
  if (second != 0.0)
  {
    return second > 0.0 ? 1 : -1;
  }
  return 0;
}

/// Watertight ray-triangle test; on a hit, the distance along the ray and
/// the barycentric weights.
bool Intersect(const ShearedRay& ray, const double* v0, const double* v1, const double* v2,
  double& t, double w[3])
{
  const Sheared a = ToRayFrame(ray, v0), b = ToRayFrame(ray, v1), c = ToRayFrame(ray, v2);
  const double u = EdgeFunction(b, c), v = EdgeFunction(c, a), x = EdgeFunction(a, b);
  const int su = PerturbedSign(b, c, u), sv = PerturbedSign(c, a, v), sx = PerturbedSign(a, b, x);
  if (su == 0 || su != sv || sv != sx)
  {
    return false;
  }
  const double det = u + v + x;
  if (det == 0.0)
  {
    return false; // the ray lies in the triangle's plane
  }
  t = (u * a.Z + v * b.Z + x * c.Z) / det;
  w[0] = u / det;
  w[1] = v / det;
  w[2] = x / det;
  return t > 0.0;
}

/// Screen tiles of TileSize x TileSize pixels: each tile computes its pixels'
/// rays once and tests the triangles binned to it.
constexpr int TileSize = 32;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceRasterizer::SetView(const double pointsToClip[16], const double eye[3],
  const double direction[3], bool parallel, int width, int height)
{
  std::copy(pointsToClip, pointsToClip + 16, this->PointsToClip);
  vtkMatrix4x4::Invert(this->PointsToClip, this->ClipToPoints);
  std::copy(eye, eye + 3, this->Eye);
  std::copy(direction, direction + 3, this->Direction);
  vtkMath::Normalize(this->Direction);
  this->Parallel = parallel;
  this->Width = width;
  this->Height = height;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceRasterizer::Unproject(double x, double y, double z, double out[3]) const
{
  const double* m = this->ClipToPoints;
  double p[4];
  for (int r = 0; r < 4; ++r)
  {
    p[r] = m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
  }
  for (int r = 0; r < 3; ++r)
  {
    out[r] = p[r] / p[3];
  }
}

//------------------------------------------------------------------------------
vtkHAVSFaceRasterizer::Ray vtkHAVSFaceRasterizer::GetPixelRay(int i, int j) const
{
  const double x = (i + 0.5) / this->Width * 2.0 - 1.0;
  const double y = (j + 0.5) / this->Height * 2.0 - 1.0;
  double nearPoint[3], farPoint[3];
  this->Unproject(x, y, -1.0, nearPoint);
  this->Unproject(x, y, 1.0, farPoint);
  Ray ray;
  for (int k = 0; k < 3; ++k)
  {
    ray.Direction[k] = farPoint[k] - nearPoint[k];
  }
  vtkMath::Normalize(ray.Direction);
  if (this->Parallel)
  {
    std::copy(nearPoint, nearPoint + 3, ray.Origin);
    double d[3];
    vtkMath::Subtract(nearPoint, this->Eye, d);
    ray.Offset = vtkMath::Dot(d, this->Direction);
  }
  else
  {
    std::copy(this->Eye, this->Eye + 3, ray.Origin);
    ray.Offset = 0.0;
  }
  return ray;
}

//------------------------------------------------------------------------------
bool vtkHAVSFaceRasterizer::Project(const double p[3], double& px, double& py) const
{
  const double* m = this->PointsToClip;
  double c[4];
  for (int r = 0; r < 4; ++r)
  {
    c[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
  }
  if (!(c[3] > 0.0))
  {
    return false;
  }
  px = (c[0] / c[3] + 1.0) * 0.5 * this->Width - 0.5;
  py = (c[1] / c[3] + 1.0) * 0.5 * this->Height - 0.5;
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSFaceRasterizer::ScreenBox(const double* v[3], int box[4]) const
{
  const int width = this->Width, height = this->Height;
  box[0] = 0;
  box[1] = width - 1;
  box[2] = 0;
  box[3] = height - 1;
  double lo[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max() };
  double hi[2] = { std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest() };
  for (int k = 0; k < 3; ++k)
  {
    double px, py;
    if (!this->Project(v[k], px, py))
    {
      return true; // a point behind the eye: the whole image
    }
    lo[0] = std::min(lo[0], px);
    lo[1] = std::min(lo[1], py);
    hi[0] = std::max(hi[0], px);
    hi[1] = std::max(hi[1], py);
  }
  // One pixel of margin: the exact test decides. Clamped before the
  // conversion (points near the eye project far away).
  auto clampTo = [](double value, double limit)
  { return std::min(std::max(value, -2.0), limit + 2.0); };
  box[0] = std::max(box[0], static_cast<int>(std::floor(clampTo(lo[0], width))) - 1);
  box[1] = std::min(box[1], static_cast<int>(std::ceil(clampTo(hi[0], width))) + 1);
  box[2] = std::max(box[2], static_cast<int>(std::floor(clampTo(lo[1], height))) - 1);
  box[3] = std::min(box[3], static_cast<int>(std::ceil(clampTo(hi[1], height))) + 1);
  return box[0] <= box[1] && box[2] <= box[3];
}

//------------------------------------------------------------------------------
void vtkHAVSFaceRasterizer::Rasterize(const std::vector<double>& points, const uint32_t* triangles,
  vtkIdType numberOfTriangles, const std::function<bool(vtkIdType)>& skip)
{
  const int width = this->Width, height = this->Height;
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  this->Hits.clear();
  this->PixelStart.assign(static_cast<size_t>(pixels) + 1, 0);
  if (pixels <= 0)
  {
    return;
  }
  auto vertices = [&](vtkIdType f, const double* v[3])
  {
    const uint32_t* ids = &triangles[3 * f];
    for (int k = 0; k < 3; ++k)
    {
      v[k] = &points[3 * static_cast<size_t>(ids[k])];
    }
  };

  // 1. Bin the triangles to the screen tiles their boxes overlap.
  const int tilesX = (width + TileSize - 1) / TileSize;
  const int tilesY = (height + TileSize - 1) / TileSize;
  const vtkIdType tiles = static_cast<vtkIdType>(tilesX) * tilesY;
  using Binned = std::pair<uint32_t, uint32_t>; // (tile, triangle)
  vtkSMPThreadLocal<std::vector<Binned>> localBins;
  vtkSMPTools::For(0, numberOfTriangles,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<Binned>& bins = localBins.Local();
      for (vtkIdType f = begin; f < end; ++f)
      {
        const double* v[3];
        vertices(f, v);
        int box[4];
        if ((skip && skip(f)) || !this->ScreenBox(v, box))
        {
          continue;
        }
        for (int ty = box[2] / TileSize; ty <= box[3] / TileSize; ++ty)
        {
          for (int tx = box[0] / TileSize; tx <= box[1] / TileSize; ++tx)
          {
            bins.emplace_back(static_cast<uint32_t>(ty * tilesX + tx), static_cast<uint32_t>(f));
          }
        }
      }
    });
  std::vector<vtkIdType> binStart(static_cast<size_t>(tiles) + 1, 0);
  for (const std::vector<Binned>& bins : localBins)
  {
    for (const Binned& b : bins)
    {
      ++binStart[b.first + 1];
    }
  }
  for (vtkIdType t = 0; t < tiles; ++t)
  {
    binStart[t + 1] += binStart[t];
  }
  std::vector<uint32_t> binned(static_cast<size_t>(binStart[tiles]));
  {
    std::vector<vtkIdType> cursor(binStart.begin(), binStart.end() - 1);
    for (std::vector<Binned>& bins : localBins)
    {
      for (const Binned& b : bins)
      {
        binned[cursor[b.first]++] = b.second;
      }
      std::vector<Binned>().swap(bins);
    }
  }

  // 2. Per tile: its pixels' rays once, every binned triangle tested at the
  // pixel centres of its box, the hits bucketed by pixel and sorted by
  // distance (ties by triangle index).
  std::vector<std::vector<Hit>> tileHits(static_cast<size_t>(tiles));
  vtkSMPThreadLocal<std::vector<ShearedRay>> localRays;
  vtkSMPThreadLocal<std::vector<std::pair<int, Hit>>> localFound;
  vtkSMPTools::For(0, tiles,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<ShearedRay>& rays = localRays.Local();
      std::vector<std::pair<int, Hit>>& found = localFound.Local();
      rays.resize(TileSize * TileSize);
      for (vtkIdType t = begin; t < end; ++t)
      {
        const int x0 = static_cast<int>(t % tilesX) * TileSize;
        const int y0 = static_cast<int>(t / tilesX) * TileSize;
        const int x1 = std::min(x0 + TileSize, width) - 1;
        const int y1 = std::min(y0 + TileSize, height) - 1;
        if (binStart[t] == binStart[t + 1])
        {
          continue;
        }
        for (int j = y0; j <= y1; ++j)
        {
          for (int i = x0; i <= x1; ++i)
          {
            rays[(j - y0) * TileSize + (i - x0)] = Shear(this->GetPixelRay(i, j));
          }
        }
        found.clear();
        for (vtkIdType b = binStart[t]; b < binStart[t + 1]; ++b)
        {
          const vtkIdType f = binned[b];
          const double* v[3];
          vertices(f, v);
          int box[4];
          this->ScreenBox(v, box);
          double normal[3], e1[3], e2[3];
          vtkMath::Subtract(v[1], v[0], e1);
          vtkMath::Subtract(v[2], v[0], e2);
          vtkMath::Cross(e1, e2, normal);
          for (int j = std::max(box[2], y0); j <= std::min(box[3], y1); ++j)
          {
            for (int i = std::max(box[0], x0); i <= std::min(box[1], x1); ++i)
            {
              const int local = (j - y0) * TileSize + (i - x0);
              const ShearedRay& ray = rays[local];
              double distance, w[3];
              if (!Intersect(ray, v[0], v[1], v[2], distance, w))
              {
                continue;
              }
              Hit hit;
              hit.Distance = ray.Ray.Offset + distance;
              std::copy(w, w + 3, hit.Weights);
              hit.Triangle = static_cast<uint32_t>(f);
              hit.FrontFacing = vtkMath::Dot(normal, ray.Ray.Direction) < 0.0;
              found.emplace_back(local, hit);
            }
          }
        }
        // Bucketed by pixel (a counting sort), then each pixel's few hits
        // sorted by distance.
        int count[TileSize * TileSize + 1] = {};
        for (const std::pair<int, Hit>& h : found)
        {
          ++count[h.first + 1];
        }
        for (int l = 0; l < TileSize * TileSize; ++l)
        {
          const vtkIdType p = static_cast<vtkIdType>(y0 + l / TileSize) * width + x0 + l % TileSize;
          if (count[l + 1] > 0)
          {
            this->PixelStart[p + 1] = count[l + 1]; // each pixel is in one tile: no race
          }
          count[l + 1] += count[l];
        }
        std::vector<Hit>& out = tileHits[t];
        out.resize(found.size());
        for (const std::pair<int, Hit>& h : found)
        {
          out[count[h.first]++] = h.second;
        }
        auto nearer = [](const Hit& a, const Hit& b) {
          return a.Distance < b.Distance || (a.Distance == b.Distance && a.Triangle < b.Triangle);
        };
        for (int l = 0, first = 0; l < TileSize * TileSize; ++l)
        {
          // count[l] is now the end of pixel l's hits.
          std::sort(out.begin() + first, out.begin() + count[l], nearer);
          first = count[l];
        }
      }
    });
  std::vector<uint32_t>().swap(binned);

  // 3. Per-pixel lists: the counts' prefix sum, then each tile's hits copied
  // to its pixels' places (pixel by pixel in the tile's order).
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    this->PixelStart[p + 1] += this->PixelStart[p];
  }
  this->Hits.resize(static_cast<size_t>(this->PixelStart[pixels]));
  vtkSMPTools::For(0, tiles,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        std::vector<Hit>& in = tileHits[t];
        if (in.empty())
        {
          continue;
        }
        const int x0 = static_cast<int>(t % tilesX) * TileSize;
        const int y0 = static_cast<int>(t / tilesX) * TileSize;
        const int x1 = std::min(x0 + TileSize, width) - 1;
        const int y1 = std::min(y0 + TileSize, height) - 1;
        size_t next = 0;
        for (int j = y0; j <= y1; ++j)
        {
          for (int i = x0; i <= x1; ++i)
          {
            const vtkIdType p = static_cast<vtkIdType>(j) * width + i;
            for (vtkIdType h = this->PixelStart[p]; h < this->PixelStart[p + 1]; ++h)
            {
              this->Hits[h] = in[next++];
            }
          }
        }
        std::vector<Hit>().swap(in);
      }
    });
}

//------------------------------------------------------------------------------
void vtkHAVSFaceRasterizer::ReleaseHits()
{
  std::vector<Hit>().swap(this->Hits);
  std::vector<vtkIdType>().swap(this->PixelStart);
}

//------------------------------------------------------------------------------
void vtkHAVSFaceRasterizer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Width << " x " << this->Height
     << (this->Parallel ? ", parallel" : ", perspective") << ", hits " << this->Hits.size() << "\n";
}

VTK_ABI_NAMESPACE_END
