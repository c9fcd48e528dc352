/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSPyramidSubdivision.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Higher-order subdivision of pyramids (issue 19), through both mappers at
// their defaults against the exact reference (havsTestCells.h: the views, the
// image size, "exact", the edge pixels left out): as
// TestHAVSQuadraticSubdivision for 13- and 19-node pyramids (four per box of
// the shell, apex at its centre) meeting quadratic tetrahedra on triangles,
// pyramids on both, 20-node hexahedra on their bases: volume against the cells'
// own falling, no cracks (also: no boundary face inside the sector; 19-node
// pyramids at level 0 too, control: VTK's split of their 19 nodes cracks), the
// linear field exact; straight cells: the volume a closed form, the quadratic
// field exact on 19-node ones; both mappers at level 2 against the reference
// (control: level 0).
//
// Usage: TestHAVSPyramidSubdivision
#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestProperties.h"
#include "havsTestShells.h"

#include "vtkCellType.h"
#include "vtkHAVSTetrahedralizer.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace havstest::cells;

int TestHAVSPyramidSubdivision(int, char*[])
{
  const int m[3] = { 2, 3, 2 };
  const vtkIdType quads = 2 * (m[0] * m[1] + m[0] * m[2] + m[1] * m[2]);
  for (int variant = 0; variant < 3; ++variant)
  {
    const bool triquadratic = variant == 1;
    const bool hexahedra = variant == 2;
    auto shell = PyramidShell(m, triquadratic, hexahedra);
    const std::string what = std::string(triquadratic ? "19-node" : "13-node") +
      " pyramids and quadratic tetrahedra" + (hexahedra ? " and 20-node hexahedra" : "");
    const double exact = GridQuadratureVolume(shell, 2);
    const double check = GridQuadratureVolume(shell, 1);
    std::printf("%s (%lld cells): volume by quadrature %.9f (coarser quadrature %.9f; the "
                "cylinder's sector %.9f)\n",
      what.c_str(), static_cast<long long>(shell->GetNumberOfCells()), exact, check,
      kQuarter / 2.0 * (kOuter * kOuter - kInner * kInner) * kHeight);
    havstest::Check(std::fabs(exact - check) < 1e-7 * exact, what + ": the quadrature converged");
    // (Level 0 of a 19-node pyramid is level 1's lattice of 14 of its nodes:
    // the same pieces, so level 1 is not compared with 0.)
    CheckRefinement(
      what, shell, exact, quads, variant == 0 ? 3 : 2, triquadratic ? 0.0 : 1.0 + 1e-9, true, 0.01);
    if (triquadratic)
    {
      // Control: VTK's own split of the 19 nodes at level 0 (the testing
      // hook SplitLocalOrder keeps it) cracks.
      auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(
        shell, nullptr, 0, vtkHAVSTetrahedralizer::SplitLocalOrder);
      const vtkIdType inner = InnerBoundaryTriangles(tets, 0.01);
      std::printf("  control (VTK's split of the 19 nodes, level 0): boundary triangles %lld, "
                  "inside the sector %lld\n",
        static_cast<long long>(BoundaryTriangles(tets)), static_cast<long long>(inner));
      havstest::Check(inner > 0, what + ": control: VTK's split at level 0 cracks");
    }
  }

  // Straight (sheared) cells: the volume exact at every level (a closed
  // form: the sheared box's); at every new point the quadratic field on the
  // 19-node pyramids (they interpolate every quadratic), the linear one on the
  // 13-node pyramids (they do not: measured 3e-2 off a quadratic).
  for (bool triquadratic : { false, true })
  {
    auto grid = PyramidShell(m, triquadratic, false);
    double (*field)(const double*) = triquadratic ? Quadratic : Linear;
    ShearBack(grid, field);
    const double volume = kShearedVolume;
    for (int level = 0; level <= 2; ++level)
    {
      vtkHAVSTetrahedralizer::Report report;
      auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(grid, &report, level);
      const double error = std::fabs(TetrahedraVolume(tets) - volume) / volume;
      const double e = FieldError(tets, grid->GetNumberOfPoints(), field);
      std::printf("sheared straight %s pyramids, level %d: volume error %.2e (closed form %.3f), "
                  "%s field error %.2e at %lld new points\n",
        triquadratic ? "19-node" : "13-node", level, error, volume,
        triquadratic ? "quadratic" : "linear", e, static_cast<long long>(report.AddedPoints));
      havstest::Check(error < 1e-12, "straight pyramids: the volume exact");
      if (level >= 1)
      {
        havstest::Check(
          report.AddedPoints > 0 && e < 1e-9, "straight pyramids: the field exact at new points");
      }
    }
  }

  // Lagrange and Bezier pyramids (VTK 9.2 has no cell class for them): the
  // 13-node shell's pyramids retyped, taken as the linear pyramids of their
  // corners. Level 0: the same tetrahedra as the shell with linear pyramids
  // (the same volume to rounding); levels 1 and 2: refined with their
  // neighbours, no cracks (boundary triangles: the refined surface's);
  // counted at every level; control: points not merged crack.
  for (int type : { VTK_LAGRANGE_PYRAMID, VTK_BEZIER_PYRAMID })
  {
    auto quadratic = PyramidShell(m, false, false);
    auto retyped = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto linear = vtkSmartPointer<vtkUnstructuredGrid>::New();
    vtkIdType pyramids = 0;
    for (auto* g : { retyped.Get(), linear.Get() })
    {
      g->SetPoints(quadratic->GetPoints());
      g->GetPointData()->ShallowCopy(quadratic->GetPointData());
      g->Allocate(quadratic->GetNumberOfCells());
    }
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < quadratic->GetNumberOfCells(); ++c)
    {
      quadratic->GetCellPoints(c, ids);
      if (quadratic->GetCellType(c) != VTK_QUADRATIC_PYRAMID)
      {
        retyped->InsertNextCell(quadratic->GetCellType(c), ids);
        linear->InsertNextCell(quadratic->GetCellType(c), ids);
        continue;
      }
      ++pyramids;
      retyped->InsertNextCell(type, ids);
      ids->SetNumberOfIds(5);
      linear->InsertNextCell(VTK_PYRAMID, ids);
    }
    const std::string what = type == VTK_LAGRANGE_PYRAMID ? "Lagrange pyramids" : "Bezier pyramids";
    const double linearVolume =
      TetrahedraVolume(vtkHAVSTetrahedralizer::Tetrahedralize(linear, nullptr));
    for (int level = 0; level <= 2; ++level)
    {
      vtkHAVSTetrahedralizer::Report report;
      auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(retyped, &report, level);
      const double volume = TetrahedraVolume(tets);
      const vtkIdType boundary = BoundaryTriangles(tets);
      const vtkIdType inner = InnerBoundaryTriangles(tets);
      std::printf("  %s (%lld of %lld cells), level %d: %lld tetrahedra, volume %.9f (linear "
                  "pyramids at level 0: %.9f), boundary triangles %lld (refined surface %lld; "
                  "inside the sector %lld), %lld taken as their corners\n",
        what.c_str(), static_cast<long long>(pyramids),
        static_cast<long long>(retyped->GetNumberOfCells()), level,
        static_cast<long long>(tets->GetNumberOfCells()), volume, linearVolume,
        static_cast<long long>(boundary), static_cast<long long>(2 * quads << (2 * level)),
        static_cast<long long>(inner), static_cast<long long>(report.CornerPyramids));
      havstest::Check(report.CornerPyramids == pyramids, what + ": counted");
      if (level == 0)
      {
        havstest::Check(std::fabs(volume - linearVolume) < 1e-12 * linearVolume,
          what + ": level 0 is the linear pyramids' split");
      }
      else
      {
        // (Their refined faces are flat: on the shell's outside some
        // boundary triangles lie off the cylinder, counted "inside".)
        havstest::Check(boundary == 2 * quads << (2 * level),
          what + ": no cracks at level " + std::to_string(level));
      }
    }
    auto unmerged = vtkHAVSTetrahedralizer::Tetrahedralize(
      retyped, nullptr, 2, vtkHAVSTetrahedralizer::SplitUnmerged);
    std::printf("  control (%s, points not merged, level 2): boundary triangles %lld\n",
      what.c_str(), static_cast<long long>(BoundaryTriangles(unmerged)));
    havstest::Check(BoundaryTriangles(unmerged) > 2 * quads << 4, what + ": the control cracks");
    if (type == VTK_LAGRANGE_PYRAMID)
    {
      // Both mappers at level 2 (one warning: the pyramids taken as their
      // corners) against the reference at level 2; control: level 0.
      RenderRefined(
        what, retyped, havstest::MakeRampProperty(0.0, 9.0, 0.8, 0.5), 2, retyped, 0, 1);
    }
  }

  // Rendering: both mappers at level 2 against the reference at level 2;
  // control: the reference at level 0 (the curvature shows).
  auto shell = PyramidShell(m, false, true);
  auto property = havstest::MakeRampProperty(0.0, 9.0, 0.8, 0.5);
  RenderRefined("13-node pyramids, tetrahedra, hexahedra", shell, property, 2, shell, 0);
  return havstest::Result();
}
