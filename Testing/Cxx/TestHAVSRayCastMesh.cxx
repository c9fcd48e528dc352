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
// vtkHAVSCellGeometry's face windings from one mirrored bit a tetrahedron
// (control: the bits flipped), and the split of the cell records into buffers.
#include "havsTestChecks.h"

#include "vtkHAVSCellGeometry.h"
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

    // vtkHAVSCellGeometry's windings from one bit a tetrahedron (what the cell
    // projection's vertex shader winds the faces by): every face j from
    // FaceCorners and the mirrored bit is Compute's face j, wound outward
    // (its normal away from vertex j). Control: the bits flipped wind every
    // face inward.
    std::vector<float> records;
    std::vector<uint32_t> faces, mirrored;
    vtkHAVSCellGeometry::Compute(points, scalars, tets, records, &faces);
    vtkHAVSCellGeometry::ComputeMirrored(points, tets, mirrored);
    size_t unlike = 0, wrongWay = 0, flippedOutward = 0, mirroredCount = 0;
    for (size_t t = 0; t < count; ++t)
    {
      const bool m = ((mirrored[t / 32] >> (t % 32)) & 1u) != 0;
      mirroredCount += m ? 1 : 0;
      for (int flip = 0; flip < 2; ++flip)
      {
        for (int j = 0; j < 4; ++j)
        {
          int c[3];
          vtkHAVSCellGeometry::FaceCorners(j, m != (flip == 1), c[0], c[1], c[2]);
          double x[3][3], opposite[3], e1[3], e2[3], n[3], out[3];
          for (int v = 0; v < 3; ++v)
          {
            grid->GetPoint(tets[4 * t + c[v]], x[v]);
            unlike += flip == 0 && faces[12 * t + 3 * j + v] != tets[4 * t + c[v]] ? 1 : 0;
          }
          grid->GetPoint(tets[4 * t + j], opposite);
          vtkMath::Subtract(x[1], x[0], e1);
          vtkMath::Subtract(x[2], x[0], e2);
          vtkMath::Cross(e1, e2, n);
          vtkMath::Subtract(x[0], opposite, out);
          const bool outward = vtkMath::Dot(n, out) > 0.0;
          wrongWay += flip == 0 && !outward ? 1 : 0;
          flippedOutward += flip == 1 && outward ? 1 : 0;
        }
      }
    }
    std::printf("%s: %zu of %zu tetrahedra mirrored; faces unlike Compute's %zu, inward %zu; "
                "control, the bits flipped: %zu of %zu faces outward\n",
      name.c_str(), mirroredCount, count, unlike, wrongWay, flippedOutward, 4 * count);
    havstest::Check(unlike == 0 && wrongWay == 0,
      name + ": faces wound from one bit a tetrahedron are Compute's, outward");
    havstest::Check(flippedOutward == 0, name + ": negative control, the bits flipped wind inward");
  }

  // The cell records' buffers (vtkHAVSGLCellRecords): 80 bytes a record, at
  // most 4 buffers; the least largest buffer spreads them over the 4, and a
  // limit one byte under it takes 5 (refused).
  const size_t n = 49691875;
  const size_t least = vtkHAVSCellGeometry::LargestRecordBufferNeed(n);
  havstest::Check(vtkHAVSCellGeometry::RecordBuffers(n, 2147483647) == 2 &&
      vtkHAVSCellGeometry::CellsPerRecordBuffer(2147483647) == 26843545 &&
      least == 80 * ((n + 3) / 4) && vtkHAVSCellGeometry::RecordBuffers(n, least) == 4 &&
      vtkHAVSCellGeometry::RecordBuffers(n, least - 1) == 5 &&
      vtkHAVSCellGeometry::RecordBuffers(0, 80) == 1 &&
      vtkHAVSCellGeometry::RecordBuffers(5, 1) == 5,
    "record buffers: 49.7M tetrahedra in 2 under 2^31 bytes, in 4 at the least largest, 5 under "
    "it");
  return havstest::Result();
}
