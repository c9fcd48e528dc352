/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSPlaneSection.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSPlaneSection.h"

#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <utility>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSPlaneSection);

namespace
{
/// The point where edge (a, b) crosses the plane (signed distances da, db of
/// opposite signs), and its scalar.
void CutEdge(const float* points, const float* scalars, uint32_t a, uint32_t b, double da,
  double db, float* out, float* scalar)
{
  if (a > b) // the same arithmetic for both tetrahedra that share the edge
  {
    std::swap(a, b);
    std::swap(da, db);
  }
  const double t = da / (da - db);
  for (int k = 0; k < 3; ++k)
  {
    const double pa = points[3 * static_cast<size_t>(a) + k];
    const double pb = points[3 * static_cast<size_t>(b) + k];
    out[k] = static_cast<float>(pa + t * (pb - pa));
  }
  const double sa = scalars[a], sb = scalars[b];
  *scalar = static_cast<float>(sa + t * (sb - sa));
}

/// The section triangles of one tetrahedron, appended to the outputs.
int CutTetrahedron(const uint32_t* ids, const float* points, const float* scalars,
  const double plane[4], float* outPoints, float* outScalars)
{
  double d[4];
  int above[4], numberAbove = 0;
  for (int i = 0; i < 4; ++i)
  {
    const float* p = points + 3 * static_cast<size_t>(ids[i]);
    d[i] = plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3];
    above[i] = d[i] >= 0.0 ? 1 : 0;
    numberAbove += above[i];
  }
  if (numberAbove == 0 || numberAbove == 4)
  {
    return 0;
  }
  if (numberAbove == 1 || numberAbove == 3)
  {
    // One vertex alone on its side: a triangle on its three edges.
    int lone = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (above[i] == (numberAbove == 1 ? 1 : 0))
      {
        lone = i;
      }
    }
    int corner = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (i != lone)
      {
        CutEdge(points, scalars, ids[lone], ids[i], d[lone], d[i], outPoints + 3 * corner,
          outScalars + corner);
        ++corner;
      }
    }
    return 1;
  }
  // Two on each side (a, b above; c, e below): the quadrilateral on edges
  // ac, ae, be, bc, in that cyclic order, as two triangles.
  int a = -1, b = -1, c = -1, e = -1;
  for (int i = 0; i < 4; ++i)
  {
    if (above[i])
    {
      (a < 0 ? a : b) = i;
    }
    else
    {
      (c < 0 ? c : e) = i;
    }
  }
  float quad[4][3], quadScalars[4];
  CutEdge(points, scalars, ids[a], ids[c], d[a], d[c], quad[0], &quadScalars[0]);
  CutEdge(points, scalars, ids[a], ids[e], d[a], d[e], quad[1], &quadScalars[1]);
  CutEdge(points, scalars, ids[b], ids[e], d[b], d[e], quad[2], &quadScalars[2]);
  CutEdge(points, scalars, ids[b], ids[c], d[b], d[c], quad[3], &quadScalars[3]);
  const int corners[6] = { 0, 1, 2, 0, 2, 3 };
  for (int i = 0; i < 6; ++i)
  {
    std::copy(quad[corners[i]], quad[corners[i]] + 3, outPoints + 3 * i);
    outScalars[i] = quadScalars[corners[i]];
  }
  return 2;
}
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSPlaneSection::Compute(const std::vector<uint32_t>& tetrahedra,
  const std::vector<float>& points, const std::vector<float>& scalars, const double plane[4],
  std::vector<float>& sectionPoints, std::vector<float>& sectionScalars,
  std::vector<uint32_t>* sectionCells)
{
  const double start = vtkTimerLog::GetUniversalTime();
  const vtkIdType numberOfTetrahedra = static_cast<vtkIdType>(tetrahedra.size() / 4);
  // Fixed blocks: each block's triangles are counted, then written at its
  // offset, so the output does not depend on the threads.
  const vtkIdType blockSize = 4096;
  const vtkIdType blocks = (numberOfTetrahedra + blockSize - 1) / blockSize;
  std::vector<vtkIdType> counts(static_cast<size_t>(blocks) + 1, 0);
  vtkSMPTools::For(0, blocks,
    [&](vtkIdType begin, vtkIdType end)
    {
      float p[18], s[6];
      for (vtkIdType block = begin; block < end; ++block)
      {
        vtkIdType count = 0;
        const vtkIdType last = std::min(numberOfTetrahedra, (block + 1) * blockSize);
        for (vtkIdType t = block * blockSize; t < last; ++t)
        {
          count += CutTetrahedron(
            &tetrahedra[4 * static_cast<size_t>(t)], points.data(), scalars.data(), plane, p, s);
        }
        counts[block + 1] = count;
      }
    });
  for (vtkIdType block = 0; block < blocks; ++block)
  {
    counts[block + 1] += counts[block];
  }
  const vtkIdType triangles = counts[blocks];
  sectionPoints.resize(9 * static_cast<size_t>(triangles));
  sectionScalars.resize(3 * static_cast<size_t>(triangles));
  if (sectionCells)
  {
    sectionCells->resize(static_cast<size_t>(triangles));
  }
  vtkSMPTools::For(0, blocks,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType block = begin; block < end; ++block)
      {
        vtkIdType at = counts[block];
        const vtkIdType last = std::min(numberOfTetrahedra, (block + 1) * blockSize);
        for (vtkIdType t = block * blockSize; t < last; ++t)
        {
          const int made = CutTetrahedron(&tetrahedra[4 * static_cast<size_t>(t)], points.data(),
            scalars.data(), plane, &sectionPoints[9 * static_cast<size_t>(at)],
            &sectionScalars[3 * static_cast<size_t>(at)]);
          for (int i = 0; sectionCells && i < made; ++i)
          {
            (*sectionCells)[static_cast<size_t>(at) + i] = static_cast<uint32_t>(t);
          }
          at += made;
        }
      }
    });
  this->LastSeconds = vtkTimerLog::GetUniversalTime() - start;
  return triangles;
}

//------------------------------------------------------------------------------
bool vtkHAVSPlaneSection::CutsBox(const double plane[4], const double bounds[6])
{
  bool positive = false, negative = false;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x = bounds[corner & 1 ? 1 : 0];
    const double y = bounds[corner & 2 ? 3 : 2];
    const double z = bounds[corner & 4 ? 5 : 4];
    const double d = plane[0] * x + plane[1] * y + plane[2] * z + plane[3];
    positive = positive || d >= 0.0;
    negative = negative || d < 0.0;
  }
  return positive && negative;
}

//------------------------------------------------------------------------------
void vtkHAVSPlaneSection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastSeconds: " << this->LastSeconds << "\n";
}

VTK_ABI_NAMESPACE_END
