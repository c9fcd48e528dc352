/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSQuadraticSubdivision.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Higher-order subdivision (issue 19), through both mappers at their defaults
// against the exact reference (havsTestCells.h: the views, the image size,
// "exact", the edge pixels left out): quadratic cells refined
// (SetHigherOrderSubdivision): a cylindrical shell sector in curved quadratic
// hexahedra (every other cell's node order turned a quarter), in curved
// quadratic tetrahedra, mid-edge nodes on the arcs, and (levels 1 and 2) in
// triquadratic and Lagrange hexahedra, quadratic wedges and a mix of hexahedra
// and wedges. The tessellation's volume converges to the cells' own volume
// (Gauss quadrature of the Jacobian), the error falling at every level; a
// linear field (curved cells) and a quadratic one (sheared straight cells) are
// reproduced exactly at every new point; no cracks: the boundary triangles are
// the refined surface's (controls: pieces split by their local order, points
// not merged, give more); HAVS and the cell projection at level 2 against the
// reference at level 2; control: the reference at level 0 differs beyond the
// bound (the curvature shows).
//
// Usage: TestHAVSQuadraticSubdivision
#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"
#include "havsTestShells.h"

#include "vtkCell.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSTetrahedralizer.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace havstest::cells;

namespace
{
/// One refinement level of a shell of `quads` surface quads, printed.
struct Level
{
  vtkHAVSTetrahedralizer::Report Report;
  double Error = 0.0;      ///< relative volume error against `exact`
  vtkIdType Boundary = 0;  ///< boundary triangles
  vtkIdType Expected = 0;  ///< the refined surface's triangles
  double FieldError = 0.0; ///< the linear field at the new points
};
Level Refine(vtkUnstructuredGrid* shell, int level, double exact, vtkIdType quads)
{
  Level l;
  auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(shell, &l.Report, level);
  l.Error = std::fabs(TetrahedraVolume(tets) - exact) / exact;
  l.Boundary = BoundaryTriangles(tets);
  l.Expected = 2 * quads << (2 * level);
  l.FieldError = FieldError(tets, shell->GetNumberOfPoints(), Linear);
  std::printf("  level %d: %lld tetrahedra, %lld points added, volume error %.3e, "
              "boundary triangles %lld (refined surface %lld), linear field error %.1e, "
              "%.3f s\n",
    level, static_cast<long long>(tets->GetNumberOfCells()),
    static_cast<long long>(l.Report.AddedPoints), l.Error, static_cast<long long>(l.Boundary),
    static_cast<long long>(l.Expected), l.FieldError, l.Report.Seconds);
  return l;
}

/// The volume of a non-linear cell: its Jacobian's determinant by Gauss
/// quadrature (6 points per axis; a tetrahedron through the collapsed cube).
double CellVolume(vtkCell* cell, bool tetrahedron, bool wedge = false)
{
  static const double gx[6] = { 0.033765242898423986, 0.16939530676686776, 0.38069040695840156,
    0.61930959304159844, 0.83060469323313224, 0.96623475710157601 };
  static const double gw[6] = { 0.085662246189585173, 0.18038078652406930, 0.23395696728634552,
    0.23395696728634552, 0.18038078652406930, 0.085662246189585173 };
  const int nodes = static_cast<int>(cell->GetNumberOfPoints());
  std::vector<double> derivs(3 * nodes);
  double volume = 0.0;
  for (int a = 0; a < 6; ++a)
  {
    for (int b = 0; b < 6; ++b)
    {
      for (int c = 0; c < 6; ++c)
      {
        double p[3] = { gx[a], gx[b], gx[c] };
        double w = gw[a] * gw[b] * gw[c];
        if (tetrahedron)
        {
          const double u = gx[a], v = gx[b], t = gx[c];
          p[0] = u;
          p[1] = v * (1 - u);
          p[2] = t * (1 - u) * (1 - v);
          w *= (1 - u) * (1 - u) * (1 - v);
        }
        if (wedge)
        {
          p[1] = gx[b] * (1 - gx[a]);
          w *= 1 - gx[a];
        }
        cell->InterpolateDerivs(p, derivs.data());
        double j[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
        for (int n = 0; n < nodes; ++n)
        {
          double x[3];
          cell->GetPoints()->GetPoint(n, x);
          for (int r = 0; r < 3; ++r)
          {
            for (int q = 0; q < 3; ++q)
            {
              j[r][q] += derivs[q * nodes + n] * x[r];
            }
          }
        }
        const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
          j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
          j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
        volume += w * det;
      }
    }
  }
  return volume;
}
}

int TestHAVSQuadraticSubdivision(int, char*[])
{
  const int m[3] = { 2, 3, 2 };
  const vtkIdType quads = 2 * (m[0] * m[1] + m[0] * m[2] + m[1] * m[2]);
  for (bool tetrahedra : { false, true })
  {
    auto shell = CurvedShell(m, tetrahedra ? ShellTetrahedra10 : ShellHexahedra20);
    const char* what = tetrahedra ? "quadratic tetrahedra" : "quadratic hexahedra";
    double exact = 0.0;
    vtkNew<vtkGenericCell> cell;
    for (vtkIdType c = 0; c < shell->GetNumberOfCells(); ++c)
    {
      shell->GetCell(c, cell);
      exact += CellVolume(cell, tetrahedra);
    }
    std::printf("%s (%lld cells): volume by quadrature %.9f (the cylinder's sector %.9f)\n", what,
      static_cast<long long>(shell->GetNumberOfCells()), exact,
      kQuarter / 2.0 * (kOuter * kOuter - kInner * kInner) * kHeight);
    double previous = 1e30;
    for (int level = 0; level <= 3; ++level)
    {
      const Level l = Refine(shell, level, exact, quads);
      const vtkHAVSTetrahedralizer::Report& report = l.Report;
      const double error = l.Error, fieldError = l.FieldError;
      const vtkIdType boundary = l.Boundary, expected = l.Expected;
      // Level 1 of a quadratic tetrahedron is its canonical eight, which level 0 is too.
      if (level >= 2 || !tetrahedra)
      {
        havstest::Check(error < (level >= 2 ? previous / 3.0 : previous),
          std::string(what) + ": volume error falls at level " + std::to_string(level));
      }
      else
      {
        havstest::Check(error <= previous, std::string(what) + ": level 1 no worse than 0");
      }
      previous = error;
      if (level >= 1)
      {
        havstest::Check(report.RefinedCells == shell->GetNumberOfCells(),
          std::string(what) + ": every cell refined");
        havstest::Check(boundary == expected,
          std::string(what) + ": no cracks at level " + std::to_string(level));
        havstest::Check(
          fieldError < 1e-12, std::string(what) + ": the linear field exact at the new points");
      }
      if (level == 3)
      {
        havstest::Check(error < 1e-3, std::string(what) + ": volume within 1e-3 at level 3");
      }
    }
    // Controls: the pieces split by their local order; the points not merged.
    for (int split :
      { vtkHAVSTetrahedralizer::SplitLocalOrder, vtkHAVSTetrahedralizer::SplitUnmerged })
    {
      vtkIdType boundary = 0;
      SplitControl(shell, split, 2 * quads << 4, &boundary);
      if (!tetrahedra || split == vtkHAVSTetrahedralizer::SplitUnmerged)
      {
        havstest::Check(boundary > (2 * quads << 4), std::string(what) + ": the control cracks");
      }
    }
  }

  // The other families, levels 0 to 2: triquadratic and Lagrange (order 2)
  // hexahedra, quadratic wedges (two per box: shared diagonal faces).
  // (The Lagrange hexahedron of order 2 interpolates in the triquadratic
  // one's space: the same nodes give the same cells, so its volume is the
  // triquadratic one's by quadrature.)
  double triquadraticVolume = 0.0;
  for (int kind : { ShellHexahedra27, ShellLagrangeHexahedra, ShellWedges15, ShellMixed })
  {
    auto shell = CurvedShell(m, kind);
    const char* what = kind == ShellHexahedra27 ? "triquadratic hexahedra"
      : kind == ShellWedges15                   ? "quadratic wedges"
      : kind == ShellMixed                      ? "20-node hexahedra and quadratic wedges"
                                                : "Lagrange hexahedra (order 2)";
    double exact = 0.0;
    vtkNew<vtkGenericCell> cell;
    for (vtkIdType c = 0; kind != ShellLagrangeHexahedra && c < shell->GetNumberOfCells(); ++c)
    {
      shell->GetCell(c, cell);
      exact += CellVolume(cell, false, shell->GetCellType(c) == VTK_QUADRATIC_WEDGE);
    }
    if (kind == ShellHexahedra27)
    {
      triquadraticVolume = exact;
    }
    if (kind == ShellLagrangeHexahedra)
    {
      exact = triquadraticVolume;
    }
    std::printf("%s (%lld cells): volume by quadrature %.9f\n", what,
      static_cast<long long>(shell->GetNumberOfCells()), exact);
    double previous = 1e30;
    for (int level = 1; level <= 2; ++level)
    {
      const Level l = Refine(shell, level, exact, quads);
      havstest::Check(l.Report.RefinedCells == shell->GetNumberOfCells() &&
          l.Boundary == l.Expected && l.FieldError < 1e-12,
        std::string(what) + ": refined, no cracks, the linear field exact");
      havstest::Check(l.Error < previous / 3.0, std::string(what) + ": volume error falls");
      previous = l.Error;
    }
    havstest::Check(previous < 5e-3, std::string(what) + ": volume within 5e-3 at level 2");
  }

  // A quadratic field on straight (sheared) quadratic cells: exact at every new point.
  for (bool tetrahedra : { false, true })
  {
    auto grid = tetrahedra ? QuadraticTetrahedra(2) : QuadraticHexahedra(2, false);
    for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    {
      double x[3];
      grid->GetPoint(i, x);
      grid->GetPoints()->SetPoint(
        i, x[0] + 0.3 * x[1], 0.8 * x[1] - 0.2 * x[2], 1.1 * x[2] + 0.25 * x[0]);
    }
    vtkNew<vtkDoubleArray> q;
    q->SetName("q");
    q->SetNumberOfTuples(grid->GetNumberOfPoints());
    for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    {
      double x[3];
      grid->GetPoint(i, x);
      q->SetValue(i, Quadratic(x));
    }
    grid->GetPointData()->SetScalars(q);
    vtkHAVSTetrahedralizer::Report report;
    auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(grid, &report, 2);
    const double e = FieldError(tets, grid->GetNumberOfPoints(), Quadratic);
    // Control: the field of the level-0 split at the same points (linear per tetrahedron).
    std::printf("sheared %s, level 2: quadratic field error %.2e at %lld new points\n",
      tetrahedra ? "quadratic tetrahedra" : "quadratic hexahedra", e,
      static_cast<long long>(report.AddedPoints));
    havstest::Check(report.AddedPoints > 0 && e < 1e-12, "the quadratic field exact at new points");
  }

  // Rendering: both mappers at level 2 against the reference at level 2;
  // control: the reference at level 0.
  auto shell = CurvedShell(m, ShellHexahedra20);
  auto property = havstest::MakeRampProperty(0.0, 9.0, 0.8, 0.5);
  for (bool cells : { false, true })
  {
    auto mapper = MakeMapper(cells);
    if (auto* h = vtkHAVSVolumeMapper::SafeDownCast(mapper))
    {
      h->SetHigherOrderSubdivision(2);
    }
    if (auto* p = vtkHAVSCellProjectionMapper::SafeDownCast(mapper))
    {
      p->SetHigherOrderSubdivision(2);
    }
    const View& view = kViews[cells ? 3 : 0];
    havstest::Messages* messages = havstest::CountMessages(mapper);
    auto scene = havstest::MakeScene(shell, mapper, property, kSize, kSize);
    havstest::PlaceCamera(scene.Renderer, view.Azimuth, view.Elevation, view.Parallel);
    scene.Window->Render();
    const std::vector<float> image = havstest::FloatResult(mapper);
    havstest::Check(messages->Errors == 0 && !image.empty(),
      std::string(Name(cells)) + " at level 2: rendered without errors");
    std::vector<float> exact[2];
    for (int level : { 2, 0 })
    {
      vtkNew<vtkHAVSReferenceRenderer> r;
      r->SetInputData(shell);
      r->SetHigherOrderSubdivision(level);
      r->SetProperty(property);
      r->SetCamera(scene.Renderer->GetActiveCamera());
      r->SetSize(kSize, kSize);
      if (r->Render())
      {
        vtkFloatArray* out = r->GetImage();
        exact[level / 2].assign(out->GetPointer(0), out->GetPointer(0) + 4 * kSize * kSize);
      }
    }
    if (image.empty() || exact[0].empty() || exact[1].empty())
    {
      havstest::Check(false, "the references rendered");
      continue;
    }
    const auto d = havstest::Compare(image, exact[1], kEdge);
    Print(std::string(Name(cells)) + " level 2 vs reference level 2", d);
    havstest::Check(Exact(d), std::string(Name(cells)) + ": exact at level 2");
    const auto c = havstest::Compare(image, exact[0], kEdge);
    Print(std::string("control: ") + Name(cells) + " level 2 vs reference level 0", c);
    havstest::Check(!Exact(c), "control: level 0 differs (the curvature shows)");
    // The level changed on the same mapper: the mesh is tessellated again.
    if (auto* h = vtkHAVSVolumeMapper::SafeDownCast(mapper))
    {
      h->SetHigherOrderSubdivision(0);
    }
    if (auto* p = vtkHAVSCellProjectionMapper::SafeDownCast(mapper))
    {
      p->SetHigherOrderSubdivision(0);
    }
    scene.Window->Render();
    const auto again = havstest::Compare(havstest::FloatResult(mapper), exact[0], kEdge);
    Print(std::string(Name(cells)) + " set to level 0 vs reference level 0", again);
    havstest::Check(Exact(again), std::string(Name(cells)) + ": a new level re-tessellates");
  }
  return havstest::Result();
}
