/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSPointGradients.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSPointGradients.h"

#include "vtkMath.h"
#include "vtkSMPTools.h"

#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

namespace
{
/// A tetrahedron's corners (double) and its edge matrix (rows x_i - x_0);
/// false for a point id out of range.
template <class T>
bool Corners(const std::vector<T>& points, size_t numberOfPoints, const uint32_t* ids,
  double x[4][3], double e[3][3])
{
  for (int v = 0; v < 4; ++v)
  {
    if (ids[v] >= numberOfPoints)
    {
      return false;
    }
  }
  for (int v = 0; v < 4; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      x[v][k] = static_cast<double>(points[3 * static_cast<size_t>(ids[v]) + k]);
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      e[i][k] = x[i + 1][k] - x[0][k];
    }
  }
  return true;
}

/// Whether a tetrahedron with edge matrix `e` has a volume worth solving
/// with (relative to its longest edge, as vtkHAVSCellGeometry judges planes).
bool Solvable(const double e[3][3], double det)
{
  double longest = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    longest = std::max(longest, vtkMath::Dot(e[i], e[i]));
  }
  return std::isfinite(det) && std::fabs(det) > 1e-12 * longest * std::sqrt(longest);
}

template <class T>
void ComputeGradients(const std::vector<T>& points, const std::vector<T>& scalars,
  const std::vector<uint32_t>& tets, std::vector<double>& gradients)
{
  const size_t numberOfPoints = points.size() / 3;
  const vtkIdType numberOfTets = static_cast<vtkIdType>(tets.size() / 4);
  // Each tetrahedron's gradient times its volume (the weight beside it).
  std::vector<double> weighted(4 * static_cast<size_t>(numberOfTets), 0.0);
  vtkSMPTools::For(0, numberOfTets,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const uint32_t* ids = &tets[4 * static_cast<size_t>(t)];
        double x[4][3], e[3][3];
        if (!Corners(points, numberOfPoints, ids, x, e))
        {
          continue;
        }
        const double det = vtkMath::Determinant3x3(e);
        if (!Solvable(e, det))
        {
          continue;
        }
        const double s0 = static_cast<double>(scalars[ids[0]]);
        double ds[3];
        for (int i = 0; i < 3; ++i)
        {
          ds[i] = static_cast<double>(scalars[ids[i + 1]]) - s0;
        }
        // e g = ds.
        double inverse[3][3], g[3];
        vtkMath::Invert3x3(e, inverse);
        vtkMath::Multiply3x3(inverse, ds, g);
        const double volume = std::fabs(det) / 6.0;
        double* out = &weighted[4 * static_cast<size_t>(t)];
        for (int k = 0; k < 3; ++k)
        {
          out[k] = g[k] * volume;
        }
        out[3] = volume;
      }
    });
  std::vector<double> weights(numberOfPoints, 0.0);
  gradients.assign(3 * numberOfPoints, 0.0);
  for (vtkIdType t = 0; t < numberOfTets; ++t)
  {
    const double* w = &weighted[4 * static_cast<size_t>(t)];
    if (!(w[3] > 0.0))
    {
      continue;
    }
    for (int v = 0; v < 4; ++v)
    {
      const size_t p = tets[4 * static_cast<size_t>(t) + v];
      for (int k = 0; k < 3; ++k)
      {
        gradients[3 * p + k] += w[k];
      }
      weights[p] += w[3];
    }
  }
  for (size_t p = 0; p < numberOfPoints; ++p)
  {
    for (int k = 0; k < 3; ++k)
    {
      gradients[3 * p + k] = weights[p] > 0.0 ? gradients[3 * p + k] / weights[p] : 0.0;
    }
  }
}
}

//------------------------------------------------------------------------------
void vtkHAVSPointGradients::Compute(const std::vector<float>& points,
  const std::vector<float>& scalars, const std::vector<uint32_t>& tets,
  std::vector<double>& gradients)
{
  ComputeGradients(points, scalars, tets, gradients);
}

//------------------------------------------------------------------------------
void vtkHAVSPointGradients::Compute(const std::vector<double>& points,
  const std::vector<double>& scalars, const std::vector<uint32_t>& tets,
  std::vector<double>& gradients)
{
  ComputeGradients(points, scalars, tets, gradients);
}

//------------------------------------------------------------------------------
void vtkHAVSPointGradients::ComputeFields(const std::vector<float>& points,
  const std::vector<uint32_t>& tets, const std::vector<double>& gradients,
  std::vector<float>& fields)
{
  const size_t numberOfPoints = std::min(points.size() / 3, gradients.size() / 3);
  const vtkIdType numberOfTets = static_cast<vtkIdType>(tets.size() / 4);
  fields.assign(FloatsPerCell * static_cast<size_t>(numberOfTets), 0.0f);
  vtkSMPTools::For(0, numberOfTets,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const uint32_t* ids = &tets[4 * static_cast<size_t>(t)];
        double x[4][3], e[3][3], g[4][3];
        if (!Corners(points, numberOfPoints, ids, x, e))
        {
          continue;
        }
        for (int v = 0; v < 4; ++v)
        {
          for (int k = 0; k < 3; ++k)
          {
            g[v][k] = gradients[3 * static_cast<size_t>(ids[v]) + k];
          }
        }
        double m[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
        double c[3];
        const double det = vtkMath::Determinant3x3(e);
        if (Solvable(e, det))
        {
          // p - x0 = E^T lambda (lambda: the weights of corners 1..3), so
          // lambda = B (p - x0) with B = (E^T)^-1 = (E^-1)^T, and
          // G(p) = g0 + D lambda, D's columns g_i - g0: M = D B, c = g0 - M x0.
          double inverse[3][3];
          vtkMath::Invert3x3(e, inverse);
          for (int r = 0; r < 3; ++r)
          {
            for (int col = 0; col < 3; ++col)
            {
              double sum = 0.0;
              for (int i = 0; i < 3; ++i)
              {
                // D[r][i] = g[i+1][r] - g[0][r]; B[i][col] = inverse[col][i].
                sum += (g[i + 1][r] - g[0][r]) * inverse[col][i];
              }
              m[r][col] = sum;
            }
            c[r] = g[0][r] - vtkMath::Dot(m[r], x[0]);
          }
        }
        else
        {
          for (int r = 0; r < 3; ++r)
          {
            c[r] = 0.25 * (g[0][r] + g[1][r] + g[2][r] + g[3][r]);
          }
        }
        float* out = &fields[FloatsPerCell * static_cast<size_t>(t)];
        for (int r = 0; r < 3; ++r)
        {
          for (int col = 0; col < 3; ++col)
          {
            out[4 * r + col] = static_cast<float>(m[r][col]);
          }
          out[4 * r + 3] = static_cast<float>(c[r]);
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkHAVSPointGradients::InterpolateInCells(const std::vector<float>& points,
  const std::vector<uint32_t>& tets, const std::vector<float>& gradients,
  const std::vector<float>& positions, const std::vector<uint32_t>& cells, std::vector<float>& out)
{
  const size_t numberOfPoints = std::min(points.size() / 3, gradients.size() / 3);
  const size_t numberOfTets = tets.size() / 4;
  const vtkIdType triangles = static_cast<vtkIdType>(std::min(cells.size(), positions.size() / 9));
  out.assign(positions.size(), 0.0f);
  vtkSMPTools::For(0, triangles,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const uint32_t cell = cells[static_cast<size_t>(t)];
        double x[4][3], e[3][3];
        if (cell >= numberOfTets || !Corners(points, numberOfPoints, &tets[4 * cell], x, e))
        {
          continue;
        }
        const uint32_t* ids = &tets[4 * cell];
        const double det = vtkMath::Determinant3x3(e);
        const bool solvable = Solvable(e, det);
        double inverse[3][3];
        if (solvable)
        {
          vtkMath::Invert3x3(e, inverse);
        }
        for (int v = 0; v < 3; ++v)
        {
          const size_t at = 9 * static_cast<size_t>(t) + 3 * v;
          // The barycentric weights: lambda = (E^T)^-1 (p - x0) for corners
          // 1..3, the rest for corner 0; a flat tetrahedron's mean.
          double w[4] = { 0.25, 0.25, 0.25, 0.25 };
          if (solvable)
          {
            double d[3];
            for (int k = 0; k < 3; ++k)
            {
              d[k] = static_cast<double>(positions[at + k]) - x[0][k];
            }
            w[0] = 1.0;
            for (int i = 0; i < 3; ++i)
            {
              // ((E^T)^-1)[i][k] = inverse[k][i].
              w[i + 1] = inverse[0][i] * d[0] + inverse[1][i] * d[1] + inverse[2][i] * d[2];
              w[0] -= w[i + 1];
            }
          }
          for (int k = 0; k < 3; ++k)
          {
            double g = 0.0;
            for (int i = 0; i < 4; ++i)
            {
              g += w[i] * static_cast<double>(gradients[3 * static_cast<size_t>(ids[i]) + k]);
            }
            out[at + k] = static_cast<float>(g);
          }
        }
      }
    });
}

VTK_ABI_NAMESPACE_END
