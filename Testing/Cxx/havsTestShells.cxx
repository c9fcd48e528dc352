/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestShells.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestShells.h"

#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestScenes.h"

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSTetrahedralizer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCell.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkLagrangeHexahedron.h"
#include "vtkPointData.h"
#include "vtkQuadraticHexahedron.h"
#include "vtkQuadraticWedge.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTetra.h"
#include "vtkTriQuadraticHexahedron.h"
#include "vtkTriQuadraticPyramid.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <functional>
#include <vector>

namespace havstest
{
namespace cells
{
namespace
{
/// The shell sector rho in [1, 2], theta in [0, pi/2], z in [0, 1] on a
/// lattice of (2 m[a] + 1) points per axis mapped onto the cylinder.
vtkSmartPointer<vtkPoints> ShellPoints(const int m[3])
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (int c = 0; c <= 2 * m[2]; ++c)
  {
    for (int b = 0; b <= 2 * m[1]; ++b)
    {
      for (int a = 0; a <= 2 * m[0]; ++a)
      {
        const double rho = kInner + (kOuter - kInner) * a / (2.0 * m[0]);
        const double theta = kQuarter * b / (2.0 * m[1]);
        points->InsertNextPoint(
          rho * std::cos(theta), rho * std::sin(theta), kHeight * c / (2.0 * m[2]));
      }
    }
  }
  return points;
}

}

//------------------------------------------------------------------------------
void OrientPositive(std::array<Param, 4>& v)
{
  double d[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      d[r][c] = v[r + 1][c] - v[0][c];
    }
  }
  const double det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
    d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
    d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
  if (det < 0)
  {
    std::swap(v[1], v[2]);
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> SplitControl(
  vtkDataSet* grid, int split, vtkIdType refinedSurface, vtkIdType* boundary)
{
  auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(grid, nullptr, 2, split);
  *boundary = BoundaryTriangles(tets);
  std::printf("  control (%s, level 2): boundary triangles %lld (refined surface %lld)\n",
    split == vtkHAVSTetrahedralizer::SplitLocalOrder ? "local order" : "points not merged",
    static_cast<long long>(*boundary), static_cast<long long>(refinedSurface));
  return tets;
}

namespace
{
/// A quadratic tetrahedron (10 nodes) on the corners `v` (box-lattice parameters), positively
/// oriented in parameter space.
void AddQuadraticTetra(vtkUnstructuredGrid* grid, ShellNodes& nodes, std::array<Param, 4> v)
{
  OrientPositive(v);
  auto at = [&](int a) { return nodes.Id(v[a][0], v[a][1], v[a][2]); };
  auto mid = [&](int a, int b)
  { return nodes.Id((v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2); };
  const vtkIdType q[10] = { at(0), at(1), at(2), at(3), mid(0, 1), mid(1, 2), mid(2, 0), mid(0, 3),
    mid(1, 3), mid(2, 3) };
  grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, q);
}

/// A cell's volume by Gauss quadrature (6 points per axis, each axis cut in
/// `pieces`) of its Jacobian, the Jacobian by central differences of its own
/// interpolation (vtkCell::EvaluateLocation) over the unit cube mapped onto
/// its parametric space: `toParametric` (a pyramid: the collapsed cube).
double QuadratureVolume(
  vtkCell* cell, const std::function<void(const double*, double*)>& toParametric, int pieces)
{
  static const double gx[6] = { 0.033765242898423986, 0.16939530676686776, 0.38069040695840156,
    0.61930959304159844, 0.83060469323313224, 0.96623475710157601 };
  static const double gw[6] = { 0.085662246189585173, 0.18038078652406930, 0.23395696728634552,
    0.23395696728634552, 0.18038078652406930, 0.085662246189585173 };
  std::vector<double> weights(static_cast<size_t>(cell->GetNumberOfPoints()));
  auto position = [&](const double u[3], double x[3])
  {
    double p[3];
    toParametric(u, p);
    int sub = 0;
    cell->EvaluateLocation(sub, p, x, weights.data());
  };
  const double h = 1e-6;
  double volume = 0.0;
  const int n = 6 * pieces;
  for (int a = 0; a < n; ++a)
  {
    for (int b = 0; b < n; ++b)
    {
      for (int c = 0; c < n; ++c)
      {
        const int g[3] = { a, b, c };
        double u[3], w = 1.0;
        for (int d = 0; d < 3; ++d)
        {
          u[d] = (g[d] / 6 + gx[g[d] % 6]) / pieces;
          w *= gw[g[d] % 6] / pieces;
        }
        double j[3][3];
        for (int d = 0; d < 3; ++d)
        {
          double up[3] = { u[0], u[1], u[2] }, down[3] = { u[0], u[1], u[2] }, xp[3], xm[3];
          up[d] += h;
          down[d] -= h;
          position(up, xp);
          position(down, xm);
          for (int r = 0; r < 3; ++r)
          {
            j[r][d] = (xp[r] - xm[r]) / (2 * h);
          }
        }
        volume += w *
          (j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
            j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
            j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]));
      }
    }
  }
  return volume;
}

/// The unit cube onto a cell type's parametric space.
std::function<void(const double*, double*)> ParametricMapOf(int type)
{
  switch (type)
  {
    case VTK_TRIQUADRATIC_PYRAMID: // VTK 9.2: a pyramid, base at t = 0.5, apex (0.5, 0.5, 1)
      return [](const double* u, double* p)
      {
        p[0] = u[0] * (1 - u[2]) + 0.5 * u[2];
        p[1] = u[1] * (1 - u[2]) + 0.5 * u[2];
        p[2] = 0.5 + 0.5 * u[2];
      };
    case VTK_QUADRATIC_TETRA:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_BEZIER_TETRAHEDRON: // the collapsed cube
      return [](const double* u, double* p)
      {
        p[0] = u[0];
        p[1] = u[1] * (1 - u[0]);
        p[2] = u[2] * (1 - u[0]) * (1 - u[1]);
      };
    default: // hexahedra, and vtkQuadraticPyramid's collapsed cube itself
      return [](const double* u, double* p) { std::copy_n(u, 3, p); };
  }
}
}

vtkSmartPointer<vtkUnstructuredGrid> CurvedShell(const int m[3], int kind)
{
  const bool tetrahedra = kind == ShellTetrahedra10;
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(ShellPoints(m));
  auto id = [&](int a, int b, int c)
  { return static_cast<vtkIdType>(a + (2 * m[0] + 1) * (b + (2 * m[1] + 1) * c)); };
  vtkNew<vtkQuadraticHexahedron> hex;
  vtkNew<vtkTriQuadraticHexahedron> hex27;
  vtkNew<vtkLagrangeHexahedron> lagrange;
  lagrange->GetPointIds()->SetNumberOfIds(27);
  lagrange->GetPoints()->SetNumberOfPoints(27);
  lagrange->SetUniformOrderFromNumPoints(27);
  lagrange->Initialize();
  vtkNew<vtkQuadraticWedge> wedge;
  const bool twenty = kind == ShellHexahedra20 || kind == ShellMixed;
  const int nodes = twenty ? 20 : 27;
  const int type = twenty      ? VTK_QUADRATIC_HEXAHEDRON
    : kind == ShellHexahedra27 ? VTK_TRIQUADRATIC_HEXAHEDRON
                               : VTK_LAGRANGE_HEXAHEDRON;
  const double* pc = twenty    ? hex->GetParametricCoords()
    : kind == ShellHexahedra27 ? hex27->GetParametricCoords()
                               : lagrange->GetParametricCoords();
  for (int k = 0; k < m[2]; ++k)
  {
    for (int j = 0; j < m[1]; ++j)
    {
      for (int i = 0; i < m[0]; ++i)
      {
        if (kind == ShellWedges15 || (kind == ShellMixed && i > 0))
        {
          // The box's two prisms: triangles (0,0) (2,0) (0,2) and (2,0) (2,2) (0,2).
          const double* wp = wedge->GetParametricCoords();
          for (int half = 0; half < 2; ++half)
          {
            vtkIdType ids[15];
            for (int v = 0; v < 15; ++v)
            {
              const double r = wp[3 * v], q = wp[3 * v + 1], t = wp[3 * v + 2];
              const double a = half ? 2.0 - 2.0 * q : 2.0 * r;
              const double b = half ? 2.0 * r + 2.0 * q : 2.0 * q;
              ids[v] = id(2 * i + static_cast<int>(std::lround(a)),
                2 * j + static_cast<int>(std::lround(b)),
                2 * k + static_cast<int>(std::lround(2 * t)));
            }
            grid->InsertNextCell(VTK_QUADRATIC_WEDGE, 15, ids);
          }
          continue;
        }
        if (!tetrahedra)
        {
          vtkIdType ids[27];
          const bool turned = (i + j + k) % 2 == 1 && kind != ShellMixed;
          for (int v = 0; v < nodes; ++v)
          {
            int o[3] = { static_cast<int>(std::lround(2 * pc[3 * v])),
              static_cast<int>(std::lround(2 * pc[3 * v + 1])),
              static_cast<int>(std::lround(2 * pc[3 * v + 2])) };
            if (turned)
            {
              const int a = o[0];
              o[0] = o[1];
              o[1] = 2 - a;
            }
            ids[v] = id(2 * i + o[0], 2 * j + o[1], 2 * k + o[2]);
          }
          grid->InsertNextCell(type, nodes, ids);
          continue;
        }
        int axes[3] = { 0, 1, 2 };
        do
        {
          std::array<std::array<int, 3>, 4> v;
          v[0] = { 2 * i, 2 * j, 2 * k };
          for (int s = 0; s < 3; ++s)
          {
            v[s + 1] = v[s];
            v[s + 1][axes[s]] += 2;
          }
          // Positive orientation in the parameter box (the map keeps it).
          const double d[3][3] = { { double(v[1][0] - v[0][0]), double(v[1][1] - v[0][1]),
                                     double(v[1][2] - v[0][2]) },
            { double(v[2][0] - v[0][0]), double(v[2][1] - v[0][1]), double(v[2][2] - v[0][2]) },
            { double(v[3][0] - v[0][0]), double(v[3][1] - v[0][1]), double(v[3][2] - v[0][2]) } };
          const double det = d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
            d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
            d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
          if (det < 0)
          {
            std::swap(v[1], v[2]);
          }
          auto at = [&](int a) { return id(v[a][0], v[a][1], v[a][2]); };
          auto mid = [&](int a, int b)
          { return id((v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2); };
          // vtkQuadraticTetra: corners, then the edges 01, 12, 20, 03, 13, 23.
          const vtkIdType q[10] = { at(0), at(1), at(2), at(3), mid(0, 1), mid(1, 2), mid(2, 0),
            mid(0, 3), mid(1, 3), mid(2, 3) };
          grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, q);
        } while (std::next_permutation(axes, axes + 3));
      }
    }
  }
  SetLinearField(grid);
  return grid;
}

double TetrahedraVolume(vtkUnstructuredGrid* tets)
{
  double volume = 0.0;
  for (vtkIdType c = 0; c < tets->GetNumberOfCells(); ++c)
  {
    vtkIdType npts = 0;
    const vtkIdType* p = nullptr;
    tets->GetCellPoints(c, npts, p);
    double x[4][3];
    for (int v = 0; v < 4; ++v)
    {
      tets->GetPoint(p[v], x[v]);
    }
    volume += std::fabs(vtkTetra::ComputeVolume(x[0], x[1], x[2], x[3]));
  }
  return volume;
}

double Quadratic(const double* x)
{
  return x[0] * x[0] - 2.0 * x[1] * x[2] + 0.5 * x[2] * x[2] + x[0] * x[1] + x[1];
}

void ShearBack(vtkUnstructuredGrid* grid, double (*field)(const double*))
{
  vtkNew<vtkDoubleArray> q;
  q->SetName("q");
  q->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    const double a = (std::sqrt(x[0] * x[0] + x[1] * x[1]) - kInner) / (kOuter - kInner);
    const double b = std::atan2(x[1], x[0]) / kQuarter;
    const double c = x[2] / kHeight;
    const double y[3] = { a + 0.3 * b, 0.8 * b - 0.2 * c, 1.1 * c + 0.25 * a };
    grid->GetPoints()->SetPoint(i, y);
    grid->GetPoint(i, x); // as stored
    q->SetValue(i, field(x));
  }
  grid->GetPointData()->SetScalars(q);
}

double FieldError(vtkDataSet* grid, vtkIdType first, double (*field)(const double*))
{
  vtkDataArray* s = grid->GetPointData()->GetScalars();
  double worst = s ? 0.0 : 1e30;
  for (vtkIdType i = first; s && i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    worst = std::max(worst, std::fabs(s->GetTuple1(i) - field(x)));
  }
  return worst;
}

vtkSmartPointer<vtkUnstructuredGrid> PyramidShell(
  const int m[3], bool triquadratic, bool withHexahedra)
{
  ShellNodes nodes(m);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkTriQuadraticPyramid> pyramid19; // its parametric coordinates: a pyramid
  const double* pp = pyramid19->GetParametricCoords();
  const int count = triquadratic ? 19 : 13;
  vtkNew<vtkQuadraticHexahedron> hex;
  const double* hp = hex->GetParametricCoords();
  for (int k = 0; k < m[2]; ++k)
  {
    for (int j = 0; j < m[1]; ++j)
    {
      for (int i = 0; i < m[0]; ++i)
      {
        const Param o = { double(i), double(j), double(k) };
        auto corner = [&](int x, int y, int z) { return Param{ o[0] + x, o[1] + y, o[2] + z }; };
        if (withHexahedra && j == 0)
        {
          vtkIdType ids[20];
          for (int v = 0; v < 20; ++v)
          {
            ids[v] = nodes.Id(o[0] + hp[3 * v], o[1] + hp[3 * v + 1], o[2] + hp[3 * v + 2]);
          }
          grid->InsertNextCell(VTK_QUADRATIC_HEXAHEDRON, 20, ids);
          continue;
        }
        const Param centre = { o[0] + 0.5, o[1] + 0.5, o[2] + 0.5 };
        // The faces across y and z: pyramids.
        const int faces[4][4][3] = { { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 1 }, { 0, 0, 1 } },
          { { 0, 1, 0 }, { 1, 1, 0 }, { 1, 1, 1 }, { 0, 1, 1 } },
          { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } },
          { { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } } };
        const int turn = (i + j + k) % 4;
        for (const auto& f : faces)
        {
          std::array<Param, 4> b;
          for (int v = 0; v < 4; ++v)
          {
            const int* c = f[(v + turn) % 4];
            b[v] = corner(c[0], c[1], c[2]);
          }
          // The base wound so that its normal points to the apex.
          double e1[3], e2[3], n[3], toApex = 0.0;
          for (int a = 0; a < 3; ++a)
          {
            e1[a] = b[1][a] - b[0][a];
            e2[a] = b[3][a] - b[0][a];
          }
          n[0] = e1[1] * e2[2] - e1[2] * e2[1];
          n[1] = e1[2] * e2[0] - e1[0] * e2[2];
          n[2] = e1[0] * e2[1] - e1[1] * e2[0];
          for (int a = 0; a < 3; ++a)
          {
            toApex += n[a] * (centre[a] - b[0][a]);
          }
          if (toApex < 0)
          {
            std::swap(b[1], b[3]);
          }
          Param baseCentre = { 0, 0, 0 };
          for (int a = 0; a < 3; ++a)
          {
            baseCentre[a] = 0.25 * (b[0][a] + b[1][a] + b[2][a] + b[3][a]);
          }
          // Each node from vtkTriQuadraticPyramid's parametric point (x, y, t),
          // base at t = 0.5, apex (0.5, 0.5, 1); its first 13 nodes are
          // vtkQuadraticPyramid's.
          vtkIdType ids[19];
          for (int v = 0; v < count; ++v)
          {
            const double x = pp[3 * v], y = pp[3 * v + 1], t = 2.0 * pp[3 * v + 2] - 1.0;
            Param p;
            for (int a = 0; a < 3; ++a)
            {
              p[a] = b[0][a] + x * (b[1][a] - b[0][a]) + y * (b[3][a] - b[0][a]) +
                t * (centre[a] - baseCentre[a]);
            }
            ids[v] = nodes.Id(p[0], p[1], p[2]);
          }
          grid->InsertNextCell(
            triquadratic ? VTK_TRIQUADRATIC_PYRAMID : VTK_QUADRATIC_PYRAMID, count, ids);
        }
        // The faces across x: two tetrahedra each, split along (y0, z0)-(y1, z1).
        for (int x : { 0, 1 })
        {
          AddQuadraticTetra(
            grid, nodes, { corner(x, 0, 0), corner(x, 1, 0), corner(x, 1, 1), centre });
          AddQuadraticTetra(
            grid, nodes, { corner(x, 0, 0), corner(x, 1, 1), corner(x, 0, 1), centre });
        }
      }
    }
  }
  grid->SetPoints(nodes.Points);
  SetLinearField(grid);
  return grid;
}

double GridQuadratureVolume(vtkUnstructuredGrid* grid, int pieces)
{
  double volume = 0.0;
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCell(c, cell);
    volume += QuadratureVolume(cell, ParametricMapOf(grid->GetCellType(c)), pieces);
  }
  return volume;
}

vtkIdType InnerBoundaryTriangles(vtkUnstructuredGrid* tets, double off)
{
  vtkNew<vtkHAVSFaceSet> faces;
  faces->Build(tets);
  const std::vector<uint32_t>& vertices = faces->GetFaceVertices();
  const std::vector<uint32_t>& sides = faces->GetFaceCells();
  vtkIdType inner = 0;
  for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
  {
    if (sides[2 * f] != vtkHAVSFaceSet::NoCell && sides[2 * f + 1] != vtkHAVSFaceSet::NoCell)
    {
      continue;
    }
    int on = 0x3F; // the surfaces every corner is on
    for (int v = 0; v < 3; ++v)
    {
      double x[3];
      tets->GetPoint(vertices[3 * f + v], x);
      const double rho = std::sqrt(x[0] * x[0] + x[1] * x[1]);
      const double surface[6] = { rho - kInner, rho - kOuter, x[1], x[0], x[2], x[2] - kHeight };
      int here = 0;
      for (int s = 0; s < 6; ++s)
      {
        here |= std::fabs(surface[s]) < (s < 2 ? off : 1e-9) ? 1 << s : 0;
      }
      on &= here;
    }
    inner += on == 0 ? 1 : 0;
  }
  return inner;
}

void CheckRefinement(const std::string& what, vtkUnstructuredGrid* grid, double exact,
  vtkIdType surfaceQuads, int top, double levelOneFactor, bool localOrderControlCracks, double off,
  bool levelZeroCrackFree)
{
  double previous = 1e30;
  for (int level = 0; level <= top; ++level)
  {
    vtkHAVSTetrahedralizer::Report report;
    auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(grid, &report, level);
    const double error = std::fabs(TetrahedraVolume(tets) - exact) / exact;
    const vtkIdType boundary = BoundaryTriangles(tets);
    const vtkIdType expected = 2 * surfaceQuads << (2 * level);
    const double fieldError = FieldError(tets, grid->GetNumberOfPoints(), Linear);
    const vtkIdType inner = InnerBoundaryTriangles(tets, off);
    std::printf("  level %d: %lld tetrahedra, %lld points added, volume error %.3e, boundary "
                "triangles %lld (refined surface %lld; inside the sector %lld), linear field "
                "error %.1e, %.3f s\n",
      level, static_cast<long long>(tets->GetNumberOfCells()),
      static_cast<long long>(report.AddedPoints), error, static_cast<long long>(boundary),
      static_cast<long long>(expected), static_cast<long long>(inner), fieldError, report.Seconds);
    if (level == 0 && levelZeroCrackFree)
    {
      havstest::Check(inner == 0, what + ": no boundary faces inside at level 0");
    }
    if (level >= 1)
    {
      // Level 1 against VTK's split of the nodes (level 0) only where it uses no fewer points.
      if (level >= 2 || levelOneFactor > 0.0)
      {
        havstest::Check(error < previous * (level == 1 ? levelOneFactor : 1.0 / 3.0),
          what + ": volume error falls at level " + std::to_string(level));
      }
      havstest::Check(
        inner == 0, what + ": no boundary faces inside at level " + std::to_string(level));
      havstest::Check(
        report.RefinedCells == grid->GetNumberOfCells() && report.UnrefinedNonLinearCells == 0,
        what + ": every cell refined");
      havstest::Check(boundary == expected, what + ": no cracks at level " + std::to_string(level));
      havstest::Check(fieldError < 1e-12, what + ": the linear field exact at the new points");
    }
    previous = error;
  }
  for (int split :
    { vtkHAVSTetrahedralizer::SplitLocalOrder, vtkHAVSTetrahedralizer::SplitUnmerged })
  {
    vtkIdType boundary = 0;
    auto tets = SplitControl(grid, split, 2 * surfaceQuads << 4, &boundary);
    if (split == vtkHAVSTetrahedralizer::SplitUnmerged || localOrderControlCracks)
    {
      havstest::Check(boundary > (2 * surfaceQuads << 4) && InnerBoundaryTriangles(tets, off) > 0,
        what + ": the control cracks");
    }
  }
}

void RenderRefined(const std::string& what, vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  int level, vtkDataSet* controlData, int controlLevel, int expectedWarnings)
{
  for (bool cells : { false, true })
  {
    auto mapper = MakeMapper(cells);
    if (auto* h = vtkHAVSVolumeMapper::SafeDownCast(mapper))
    {
      h->SetHigherOrderSubdivision(level);
    }
    if (auto* p = vtkHAVSCellProjectionMapper::SafeDownCast(mapper))
    {
      p->SetHigherOrderSubdivision(level);
    }
    const View& view = kViews[cells ? 3 : 0];
    havstest::Messages* messages = havstest::CountMessages(mapper);
    auto scene = havstest::MakeScene(grid, mapper, property, kSize, kSize);
    havstest::PlaceCamera(scene.Renderer, view.Azimuth, view.Elevation, view.Parallel);
    scene.Window->Render();
    const std::vector<float> image = havstest::FloatResult(mapper);
    havstest::Check(
      messages->Errors == 0 && messages->Warnings == expectedWarnings && !image.empty(),
      what + " (" + Name(cells) + "): rendered without errors, " +
        std::to_string(expectedWarnings) + " warnings");
    std::vector<float> exact[2];
    for (int r = 0; r < 2; ++r)
    {
      vtkNew<vtkHAVSReferenceRenderer> ref;
      ref->SetInputData(r == 0 ? static_cast<vtkDataSet*>(grid) : controlData);
      ref->SetHigherOrderSubdivision(r == 0 ? level : controlLevel);
      ref->SetProperty(property);
      ref->SetCamera(scene.Renderer->GetActiveCamera());
      ref->SetSize(kSize, kSize);
      if (ref->Render())
      {
        vtkFloatArray* out = ref->GetImage();
        exact[r].assign(out->GetPointer(0), out->GetPointer(0) + 4 * kSize * kSize);
      }
    }
    if (image.empty() || exact[0].empty() || exact[1].empty())
    {
      havstest::Check(false, what + ": the references rendered");
      continue;
    }
    const auto d = havstest::Compare(image, exact[0], kEdge);
    Print(what + " (" + Name(cells) + ") level " + std::to_string(level) + " vs reference", d);
    havstest::Check(Exact(d), what + " (" + Name(cells) + "): exact");
    const auto c = havstest::Compare(image, exact[1], kEdge);
    Print("control: " + what + " (" + Name(cells) + ") vs the control reference", c);
    havstest::Check(!Exact(c), what + ": the control differs");
  }
}
}
}
