/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellGeometry.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSCellGeometry.h"

#include "vtkMath.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
void vtkHAVSCellGeometry::Compute(const std::vector<float>& points,
  const std::vector<float>& scalars, const std::vector<uint32_t>& tets, std::vector<float>& cells,
  std::vector<uint32_t>* faces, const std::vector<float>* cellScalars)
{
  const size_t count = tets.size() / 4;
  cells.assign(count * FloatsPerCell, 0.0f);
  if (faces)
  {
    faces->assign(count * 12, 0);
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(count),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const uint32_t* ids = &tets[4 * static_cast<size_t>(t)];
        double x[4][3], s[4];
        for (int v = 0; v < 4; ++v)
        {
          for (int c = 0; c < 3; ++c)
          {
            x[v][c] = points[3 * static_cast<size_t>(ids[v]) + c];
          }
          s[v] = cellScalars ? (*cellScalars)[static_cast<size_t>(t)] : scalars[ids[v]];
        }
        float* out = &cells[static_cast<size_t>(t) * FloatsPerCell];
        const bool mirrored = Mirrored(x);
        for (int j = 0; j < 4; ++j)
        {
          int a, b, c;
          FaceCorners(j, mirrored, a, b, c);
          double e1[3], e2[3], n[3];
          vtkMath::Subtract(x[b], x[a], e1);
          vtkMath::Subtract(x[c], x[a], e2);
          vtkMath::Cross(e1, e2, n);
          const double length = vtkMath::Norm(n);
          if (length > 0.0)
          {
            vtkMath::MultiplyScalar(n, 1.0 / length);
          }
          for (int k = 0; k < 3; ++k)
          {
            out[4 * j + k] = static_cast<float>(n[k]);
          }
          out[4 * j + 3] = static_cast<float>(-vtkMath::Dot(n, x[a]));
          if (faces)
          {
            uint32_t* face = &(*faces)[12 * static_cast<size_t>(t)];
            face[3 * j] = ids[a];
            face[3 * j + 1] = ids[b];
            face[3 * j + 2] = ids[c];
          }
        }
        // s(x) = g.(x - x0) + s0: solve [x1-x0; x2-x0; x3-x0] g = [s1-s0; s2-s0; s3-s0].
        double m[3][3], rhs[3], g[3] = { 0, 0, 0 };
        for (int r = 0; r < 3; ++r)
        {
          vtkMath::Subtract(x[r + 1], x[0], m[r]);
          rhs[r] = s[r + 1] - s[0];
        }
        const double det = vtkMath::Determinant3x3(m);
        if (std::abs(det) > 0.0)
        {
          double inverse[3][3];
          vtkMath::Invert3x3(m, inverse);
          vtkMath::Multiply3x3(inverse, rhs, g);
        }
        for (int k = 0; k < 3; ++k)
        {
          out[16 + k] = static_cast<float>(g[k]);
        }
        out[19] = static_cast<float>(s[0] - vtkMath::Dot(g, x[0]));
      }
    });
}

//------------------------------------------------------------------------------
bool vtkHAVSCellGeometry::Mirrored(const double x[4][3])
{
  double e1[3], e2[3], e3[3], n[3];
  vtkMath::Subtract(x[1], x[0], e1);
  vtkMath::Subtract(x[2], x[0], e2);
  vtkMath::Subtract(x[3], x[0], e3);
  vtkMath::Cross(e1, e2, n);
  return vtkMath::Dot(n, e3) < 0.0;
}

//------------------------------------------------------------------------------
void vtkHAVSCellGeometry::ComputeMirrored(
  const std::vector<float>& points, const std::vector<uint32_t>& tets, std::vector<uint32_t>& bits)
{
  const size_t count = tets.size() / 4;
  bits.assign((count + 31) / 32, 0u);
  // A word of 32 tetrahedra per task: no two tasks write one word.
  vtkSMPTools::For(0, static_cast<vtkIdType>(bits.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType w = begin; w < end; ++w)
      {
        uint32_t word = 0;
        for (size_t t = 32 * static_cast<size_t>(w);
             t < std::min(count, 32 * static_cast<size_t>(w + 1)); ++t)
        {
          double x[4][3];
          for (int v = 0; v < 4; ++v)
          {
            for (int c = 0; c < 3; ++c)
            {
              x[v][c] = points[3 * static_cast<size_t>(tets[4 * t + v]) + c];
            }
          }
          word |= Mirrored(x) ? 1u << (t % 32) : 0u;
        }
        bits[static_cast<size_t>(w)] = word;
      }
    });
}

VTK_ABI_NAMESPACE_END
