/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSHigherOrderSubdivision.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Higher-order subdivision of order-3 cells (issue 19), through both mappers at
// their defaults against the exact reference (havsTestCells.h: the views, the
// image size, "exact", the edge pixels left out): Lagrange and Bezier hexahedra
// and tetrahedra of order 3 on TestHAVSQuadraticSubdivision's shell likewise
// (levels 0 to 2; the tetrahedra at level 0 split on their nodes' lattice: no
// cracks, control: VTK's split of them cracks); straight cells: the volume a
// closed form, a cubic field exact on Lagrange cells; both mappers at level 2
// against the reference (control: the Bezier cells of the same nodes).
//
// Usage: TestHAVSHigherOrderSubdivision
#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestProperties.h"
#include "havsTestShells.h"

#include "vtkCellType.h"
#include "vtkGenericCell.h"
#include "vtkHAVSTetrahedralizer.h"
#include "vtkHigherOrderHexahedron.h"
#include "vtkIdList.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace havstest::cells;

namespace
{
/// The curved shell in order-`order` Lagrange or Bezier hexahedra (one per
/// box) or tetrahedra (six per box, Kuhn's split), nodes at their
/// parametric points mapped onto the cylinder (a Bezier cell's control points
/// likewise: a curved cell of its own).
vtkSmartPointer<vtkUnstructuredGrid> HigherOrderShell(
  const int m[3], int order, bool tetrahedra, bool bezier)
{
  ShellNodes nodes(m);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  const int type = tetrahedra ? (bezier ? VTK_BEZIER_TETRAHEDRON : VTK_LAGRANGE_TETRAHEDRON)
                              : (bezier ? VTK_BEZIER_HEXAHEDRON : VTK_LAGRANGE_HEXAHEDRON);
  const int count = tetrahedra ? (order + 1) * (order + 2) * (order + 3) / 6
                               : (order + 1) * (order + 1) * (order + 1);
  vtkNew<vtkGenericCell> cell;
  cell->SetCellType(type);
  cell->GetPointIds()->SetNumberOfIds(count);
  cell->GetPoints()->SetNumberOfPoints(count);
  if (auto* hex = vtkHigherOrderHexahedron::SafeDownCast(cell->GetRepresentativeCell()))
  {
    hex->SetUniformOrderFromNumPoints(count);
  }
  cell->Initialize();
  const std::vector<double> pc(
    cell->GetParametricCoords(), cell->GetParametricCoords() + 3 * count);
  for (int k = 0; k < m[2]; ++k)
  {
    for (int j = 0; j < m[1]; ++j)
    {
      for (int i = 0; i < m[0]; ++i)
      {
        std::vector<vtkIdType> ids(count);
        if (!tetrahedra)
        {
          for (int v = 0; v < count; ++v)
          {
            ids[v] = nodes.Id(i + pc[3 * v], j + pc[3 * v + 1], k + pc[3 * v + 2]);
          }
          grid->InsertNextCell(type, count, ids.data());
          continue;
        }
        int axes[3] = { 0, 1, 2 };
        do
        {
          std::array<Param, 4> v;
          v[0] = { double(i), double(j), double(k) };
          for (int s = 0; s < 3; ++s)
          {
            v[s + 1] = v[s];
            v[s + 1][axes[s]] += 1.0;
          }
          OrientPositive(v);
          for (int n = 0; n < count; ++n)
          {
            const double r = pc[3 * n], s = pc[3 * n + 1], t = pc[3 * n + 2];
            Param p;
            for (int a = 0; a < 3; ++a)
            {
              p[a] = v[0][a] + r * (v[1][a] - v[0][a]) + s * (v[2][a] - v[0][a]) +
                t * (v[3][a] - v[0][a]);
            }
            ids[n] = nodes.Id(p[0], p[1], p[2]);
          }
          grid->InsertNextCell(type, count, ids.data());
        } while (std::next_permutation(axes, axes + 3));
      }
    }
  }
  grid->SetPoints(nodes.Points);
  SetLinearField(grid);
  return grid;
}

double Cubic(const double* x)
{
  return x[0] * x[0] * x[0] - 2.0 * x[0] * x[1] * x[2] + 0.5 * x[2] * x[2] * x[1] + x[1] * x[1] -
    x[2];
}
}

int TestHAVSHigherOrderSubdivision(int, char*[])
{
  const int m[3] = { 2, 3, 2 };
  const vtkIdType quads = 2 * (m[0] * m[1] + m[0] * m[2] + m[1] * m[2]);
  // The tetrahedra's volume is the hexahedra's: the map is linear in the
  // radius and the height, so both interpolate (or Bernstein-approximate)
  // the surfaces of constant radius and angle alike, and the flat faces of
  // constant height are bounded by the same curves (measured for the
  // Lagrange cells by quadrature: 2.356248124 both; a Bezier tetrahedron's
  // de Casteljau evaluation is too slow for the quadrature here).
  for (bool bezier : { false, true })
  {
    double exact = 0.0;
    for (bool tetrahedra : { false, true })
    {
      auto shell = HigherOrderShell(m, 3, tetrahedra, bezier);
      const std::string what = std::string(bezier ? "Bezier" : "Lagrange") +
        (tetrahedra ? " tetrahedra" : " hexahedra") + " (order 3)";
      if (!tetrahedra)
      {
        exact = GridQuadratureVolume(shell, 2);
        const double check = GridQuadratureVolume(shell, 1);
        havstest::Check(
          std::fabs(exact - check) < 1e-7 * exact, what + ": the quadrature converged");
      }
      std::printf("%s (%lld cells, %lld nodes): volume by quadrature %.9f\n", what.c_str(),
        static_cast<long long>(shell->GetNumberOfCells()),
        static_cast<long long>(shell->GetNumberOfPoints()), exact);
      // (Level 0 is VTK's split of the 3 segments per edge the nodes make,
      // level 1 has 2; every cell has one local frame: the points-not-merged
      // control only.)
      CheckRefinement(what, shell, exact, quads, 2, 0.0, false, bezier ? 0.05 : 0.01);
      if (tetrahedra)
      {
        // Control: VTK's own split of the nodes (level 0) cracks.
        auto vtkSplit = vtkHAVSTetrahedralizer::Tetrahedralize(
          shell, nullptr, 0, vtkHAVSTetrahedralizer::SplitLocalOrder);
        const vtkIdType inner = InnerBoundaryTriangles(vtkSplit, bezier ? 0.05 : 0.01);
        std::printf("  control (VTK's split, level 0): %lld boundary triangles inside the sector\n",
          static_cast<long long>(inner));
        havstest::Check(inner > 0, what + ": the control (VTK's split at level 0) cracks");
      }
    }
  }

  // Straight (sheared) cells: the volume a closed form at every level, a cubic
  // field exact at every new point of the Lagrange cells (they interpolate
  // every cubic; Bezier cells hold their control points' values: linear only).
  for (bool bezier : { false, true })
  {
    for (bool tetrahedra : { false, true })
    {
      auto grid = HigherOrderShell(m, 3, tetrahedra, bezier);
      double (*field)(const double*) = bezier ? Linear : Cubic;
      ShearBack(grid, field);
      const double volume = kShearedVolume;
      vtkHAVSTetrahedralizer::Report report;
      auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(grid, &report, 2);
      const double error = std::fabs(TetrahedraVolume(tets) - volume) / volume;
      const double e = FieldError(tets, grid->GetNumberOfPoints(), field);
      std::printf("sheared straight %s %s (order 3), level 2: volume error %.2e (closed form "
                  "%.3f), %s field error %.2e at %lld new points\n",
        bezier ? "Bezier" : "Lagrange", tetrahedra ? "tetrahedra" : "hexahedra", error, volume,
        bezier ? "linear" : "cubic", e, static_cast<long long>(report.AddedPoints));
      havstest::Check(error < 1e-12 && report.AddedPoints > 0 && e < 1e-11,
        "straight order-3 cells: the volume and the field exact");
    }
  }

  // Rendering: both mappers at level 2 against the reference at level 2;
  // control: the Bezier cells of the same nodes (another geometry).
  auto property = havstest::MakeRampProperty(0.0, 9.0, 0.8, 0.5);
  auto lagrange = HigherOrderShell(m, 3, false, false);
  auto bezier = HigherOrderShell(m, 3, false, true);
  RenderRefined("Lagrange hexahedra (order 3)", lagrange, property, 2, bezier, 2);
  auto tetrahedra = HigherOrderShell(m, 3, true, false);
  auto bezierTetrahedra = HigherOrderShell(m, 3, true, true);
  RenderRefined("Lagrange tetrahedra (order 3)", tetrahedra, property, 2, bezierTetrahedra, 2);
  return havstest::Result();
}
