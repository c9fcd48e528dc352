/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSRayCastMesh.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSRayCastMesh (issue 21), the compact layout the GPU ray caster walks,
// alone (no OpenGL) on the box and the non-convex test meshes: the neighbour
// table is symmetric (t's face j leads to n, and one of n's faces leads back
// to t over the same three points); its boundary faces are as many as
// vtkHAVSFaceSet's; each boundary face is wound outward (its normal points
// away from its tetrahedron's fourth vertex) and stands for the face of the
// tetrahedron behind it; 96 bytes per tetrahedron. Negative control: the
// table rotated per cell (BreakNeighboursForTesting) fails the symmetry check.
#include "havsTestChecks.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSRayCastMesh.h"

#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
std::array<uint32_t, 3> FaceOf(const std::vector<uint32_t>& tets, size_t t, int j)
{
  std::array<uint32_t, 3> f = { tets[4 * t + (j + 1) % 4], tets[4 * t + (j + 2) % 4],
    tets[4 * t + (j + 3) % 4] };
  std::sort(f.begin(), f.end());
  return f;
}

/// Pairs of the table that do not lead back over the same face.
size_t Asymmetric(const std::vector<uint32_t>& tets, const std::vector<int32_t>& table)
{
  size_t bad = 0;
  for (size_t t = 0; t < table.size() / 4; ++t)
  {
    for (int j = 0; j < 4; ++j)
    {
      const int32_t n = table[4 * t + j];
      if (n < 0)
      {
        continue;
      }
      bool back = false;
      for (int k = 0; k < 4 && !back; ++k)
      {
        back = table[4 * static_cast<size_t>(n) + k] == static_cast<int32_t>(t) &&
          FaceOf(tets, n, k) == FaceOf(tets, t, j);
      }
      bad += back ? 0 : 1;
    }
  }
  return bad;
}
}

int TestHAVSRayCastMesh(int, char*[])
{
  for (const std::string name : { "box", "hollowsphere", "torus", "twoblocks" })
  {
    auto grid = name == "box" ? vtkHAVSDataSets::MakeBox(5, 6, 7, 0.2, 0.0, 1.0)
                              : vtkHAVSDataSets::Load(name);
    vtkNew<vtkHAVSFaceSet> faceSet;
    if (!havstest::Check(grid && faceSet->Build(grid), name + ": the face set builds"))
    {
      continue;
    }
    const std::vector<uint32_t>& tets = faceSet->GetTetrahedra();
    std::vector<float> points(3 * static_cast<size_t>(grid->GetNumberOfPoints()));
    for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
    {
      double x[3];
      grid->GetPoint(p, x);
      for (int i = 0; i < 3; ++i)
      {
        points[3 * p + i] = static_cast<float>(x[i]);
      }
    }
    std::vector<float> scalars(grid->GetNumberOfPoints(), 0.5f);
    vtkHAVSRayCastMesh mesh;
    mesh.Build(points, scalars, tets);
    const size_t count = mesh.GetNumberOfTetrahedra();
    const size_t bytes =
      mesh.GetCells().size() * sizeof(float) + mesh.GetNeighbours().size() * sizeof(int32_t);
    const size_t asymmetric = Asymmetric(tets, mesh.GetNeighbours());
    // Boundary faces outward, and each is its tetrahedron's face.
    size_t inward = 0, foreign = 0;
    for (size_t f = 0; f < mesh.GetNumberOfBoundaryFaces(); ++f)
    {
      const uint32_t* ids = &mesh.GetBoundaryFaces()[3 * f];
      const uint32_t t = mesh.GetBoundaryCells()[f];
      double x[3][3], opposite[3] = { 0, 0, 0 };
      for (int v = 0; v < 3; ++v)
      {
        grid->GetPoint(ids[v], x[v]);
      }
      int fourth = -1;
      for (int v = 0; v < 4; ++v)
      {
        const uint32_t id = tets[4 * t + v];
        if (id != ids[0] && id != ids[1] && id != ids[2])
        {
          fourth = v;
          grid->GetPoint(id, opposite);
        }
      }
      if (fourth < 0 || mesh.GetNeighbours()[4 * t + fourth] != -1)
      {
        ++foreign;
        continue;
      }
      double e1[3], e2[3], n[3], out[3];
      vtkMath::Subtract(x[1], x[0], e1);
      vtkMath::Subtract(x[2], x[0], e2);
      vtkMath::Cross(e1, e2, n);
      vtkMath::Subtract(x[0], opposite, out);
      inward += vtkMath::Dot(n, out) > 0.0 ? 0 : 1;
    }
    vtkHAVSRayCastMesh broken = mesh;
    broken.BreakNeighboursForTesting();
    const size_t brokenAsymmetric = Asymmetric(tets, broken.GetNeighbours());
    std::printf("%s: %zu tetrahedra, %zu boundary faces (face set: %lld), %zu bytes per "
                "tetrahedron (the seed: 144); asymmetric pairs %zu, inward boundary faces %zu, "
                "foreign %zu; control, the table rotated: %zu asymmetric pairs\n",
      name.c_str(), count, mesh.GetNumberOfBoundaryFaces(),
      static_cast<long long>(faceSet->GetNumberOfBoundaryFaces()), count ? bytes / count : 0,
      asymmetric, inward, foreign, brokenAsymmetric);
    havstest::Check(count == tets.size() / 4 && count > 0, name + ": one entry per tetrahedron");
    havstest::Check(bytes == count * vtkHAVSRayCastMesh::BytesPerTetrahedron &&
        vtkHAVSRayCastMesh::BytesPerTetrahedron == 96,
      name + ": 96 bytes per tetrahedron");
    havstest::Check(asymmetric == 0, name + ": the neighbour table is symmetric");
    havstest::Check(static_cast<vtkIdType>(mesh.GetNumberOfBoundaryFaces()) ==
        faceSet->GetNumberOfBoundaryFaces(),
      name + ": as many boundary faces as the face set");
    havstest::Check(inward == 0 && foreign == 0, name + ": boundary faces outward, of their cell");
    havstest::Check(brokenAsymmetric > count, name + ": negative control, a broken table fails");
  }
  return havstest::Result();
}
