/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestCells.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestCells.h"

#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestScenes.h"

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSTetrahedralizer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace havstest
{
namespace cells
{
namespace
{
/// The lattice point (i, j, k) of an n^3 grid on the unit cube, interior
/// points moved by up to `warp` cells (deterministically): warped cells.
void LatticePoint(int n, int i, int j, int k, double warp, double x[3])
{
  const int idx[3] = { i, j, k };
  for (int c = 0; c < 3; ++c)
  {
    x[c] = static_cast<double>(idx[c]) / n;
  }
  if (warp > 0.0 && i > 0 && i < n && j > 0 && j < n && k > 0 && k < n)
  {
    x[0] += warp / n * std::sin(12.9898 * i + 78.233 * j + 37.719 * k);
    x[1] += warp / n * std::sin(4.1414 * i + 11.3 * j + 93.989 * k);
    x[2] += warp / n * std::sin(63.7 * i + 5.1 * j + 17.17 * k);
  }
}

vtkIdType LatticeId(int n, int i, int j, int k)
{
  return i + (n + 1) * (j + (n + 1) * k);
}

/// The eight corners of cube (i, j, k), hexahedron order (bottom ccw, top ccw).
void HexCorners(int n, int i, int j, int k, vtkIdType ids[8])
{
  ids[0] = LatticeId(n, i, j, k);
  ids[1] = LatticeId(n, i + 1, j, k);
  ids[2] = LatticeId(n, i + 1, j + 1, k);
  ids[3] = LatticeId(n, i, j + 1, k);
  for (int v = 0; v < 4; ++v)
  {
    ids[v + 4] = ids[v] + (n + 1) * (n + 1);
  }
}

/// One cube as the cells `as` says; pyramids add the cube's centre point.
void AddCube(vtkUnstructuredGrid* grid, vtkPoints* points, int n, int i, int j, int k, CubeAs as)
{
  vtkIdType h[8];
  HexCorners(n, i, j, k, h);
  switch (as)
  {
    case CubeAs::Hexahedron:
      grid->InsertNextCell(VTK_HEXAHEDRON, 8, h);
      break;
    case CubeAs::Wedges:
    {
      vtkIdType a[6] = { h[0], h[1], h[2], h[4], h[5], h[6] };
      vtkIdType b[6] = { h[0], h[2], h[3], h[4], h[6], h[7] };
      grid->InsertNextCell(VTK_WEDGE, 6, a);
      grid->InsertNextCell(VTK_WEDGE, 6, b);
      break;
    }
    case CubeAs::Pyramids:
    {
      double c[3] = { 0, 0, 0 };
      for (vtkIdType id : h)
      {
        double x[3];
        points->GetPoint(id, x);
        for (int d = 0; d < 3; ++d)
        {
          c[d] += x[d] / 8.0;
        }
      }
      const vtkIdType apex = points->InsertNextPoint(c);
      const int faces[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 },
        { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };
      for (const auto& f : faces)
      {
        vtkIdType p[5] = { h[f[0]], h[f[1]], h[f[2]], h[f[3]], apex };
        grid->InsertNextCell(VTK_PYRAMID, 5, p);
      }
      break;
    }
    case CubeAs::Voxel:
    {
      vtkIdType v[8] = { h[0], h[1], h[3], h[2], h[4], h[5], h[7], h[6] };
      grid->InsertNextCell(VTK_VOXEL, 8, v);
      break;
    }
    case CubeAs::FixedFiveTetrahedra:
    {
      const int tets[5][4] = { { 0, 1, 3, 4 }, { 1, 2, 3, 6 }, { 1, 4, 5, 6 }, { 3, 4, 6, 7 },
        { 1, 3, 4, 6 } };
      for (const auto& t : tets)
      {
        vtkIdType p[4] = { h[t[0]], h[t[1]], h[t[2]], h[t[3]] };
        grid->InsertNextCell(VTK_TETRA, 4, p);
      }
      break;
    }
  }
}

template <typename T>
vtkSmartPointer<T> CellFieldOf(T* data)
{
  auto out = vtkSmartPointer<T>::New();
  out->DeepCopy(data);
  vtkNew<vtkDoubleArray> c;
  c->SetName("c");
  c->SetNumberOfTuples(out->GetNumberOfCells());
  for (vtkIdType i = 0; i < out->GetNumberOfCells(); ++i)
  {
    double centre[3] = { 0, 0, 0 };
    vtkIdList* ids = out->GetCell(i)->GetPointIds();
    for (vtkIdType v = 0; v < ids->GetNumberOfIds(); ++v)
    {
      double x[3];
      out->GetPoint(ids->GetId(v), x);
      for (int d = 0; d < 3; ++d)
      {
        centre[d] += x[d] / ids->GetNumberOfIds();
      }
    }
    // Jumps from cell to cell: a field no point data can stand for.
    c->SetValue(i,
      0.5 +
        0.5 * std::sin(7.0 * centre[0] + 3.0 * centre[1]) * std::cos(5.0 * centre[2]) *
          ((i % 3) ? 1.0 : -0.6));
  }
  out->GetPointData()->SetScalars(nullptr);
  while (out->GetPointData()->GetNumberOfArrays() > 0)
  {
    out->GetPointData()->RemoveArray(0);
  }
  out->GetCellData()->SetScalars(c);
  return out;
}
}

bool Exact(const havstest::ImageDifference& d)
{
  return d.RMSE < 5e-4 && d.Max < 0.01;
}

void Print(const std::string& what, const havstest::ImageDifference& d)
{
  std::printf("  %-66s RMSE %.2e  max %.2e\n", what.c_str(), d.RMSE, d.Max);
}

double Linear(const double* x)
{
  return x[0] + 2.0 * x[1] + 3.0 * x[2];
}

void SetLinearField(vtkDataSet* data)
{
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  s->SetNumberOfTuples(data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double x[3];
    data->GetPoint(i, x);
    s->SetValue(i, Linear(x));
  }
  data->GetPointData()->SetScalars(s);
}

vtkSmartPointer<vtkPoints> LatticePoints(int n, double warp)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        double x[3];
        LatticePoint(n, i, j, k, warp, x);
        points->InsertNextPoint(x);
      }
    }
  }
  return points;
}

vtkSmartPointer<vtkUnstructuredGrid> CubeGrid(
  int n, double warp, const std::function<CubeAs(int, int, int)>& as)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = LatticePoints(n, warp);
  grid->Allocate(6 * n * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        AddCube(grid, points, n, i, j, k, as(i, j, k));
      }
    }
  }
  grid->SetPoints(points);
  SetLinearField(grid);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> QuadraticTetrahedra(int n)
{
  auto box = vtkHAVSDataSets::MakeBox(n, n, n, 1.0 / n, 0.0, 1.0);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(box->GetPoints());
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> middle;
  auto mid = [&](vtkIdType a, vtkIdType b)
  {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = middle.find(key);
    if (it != middle.end())
    {
      return it->second;
    }
    double x[3], y[3];
    points->GetPoint(a, x);
    points->GetPoint(b, y);
    const vtkIdType id =
      points->InsertNextPoint(0.5 * (x[0] + y[0]), 0.5 * (x[1] + y[1]), 0.5 * (x[2] + y[2]));
    middle[key] = id;
    return id;
  };
  grid->Allocate(box->GetNumberOfCells());
  for (vtkIdType c = 0; c < box->GetNumberOfCells(); ++c)
  {
    vtkIdType npts = 0;
    const vtkIdType* p = nullptr;
    box->GetCellPoints(c, npts, p);
    // vtkQuadraticTetra: corners 0-3, then the edges 01, 12, 20, 03, 13, 23.
    vtkIdType q[10] = { p[0], p[1], p[2], p[3], mid(p[0], p[1]), mid(p[1], p[2]), mid(p[2], p[0]),
      mid(p[0], p[3]), mid(p[1], p[3]), mid(p[2], p[3]) };
    grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, q);
  }
  grid->SetPoints(points);
  SetLinearField(grid);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> QuadraticHexahedra(int n, bool triquadratic)
{
  const int m = 2 * n;
  auto points = LatticePoints(m, 0.0);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  // Corners, edge middles (vtkQuadraticHexahedron's order), then for the
  // triquadratic one the face centres and the centre.
  const int nodes[27][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 2, 0 }, { 0, 2, 0 }, { 0, 0, 2 },
    { 2, 0, 2 }, { 2, 2, 2 }, { 0, 2, 2 }, { 1, 0, 0 }, { 2, 1, 0 }, { 1, 2, 0 }, { 0, 1, 0 },
    { 1, 0, 2 }, { 2, 1, 2 }, { 1, 2, 2 }, { 0, 1, 2 }, { 0, 0, 1 }, { 2, 0, 1 }, { 2, 2, 1 },
    { 0, 2, 1 }, { 0, 1, 1 }, { 2, 1, 1 }, { 1, 0, 1 }, { 1, 2, 1 }, { 1, 1, 0 }, { 1, 1, 2 },
    { 1, 1, 1 } };
  const int count = triquadratic ? 27 : 20;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        vtkIdType ids[27];
        for (int v = 0; v < count; ++v)
        {
          ids[v] = LatticeId(m, 2 * i + nodes[v][0], 2 * j + nodes[v][1], 2 * k + nodes[v][2]);
        }
        grid->InsertNextCell(
          triquadratic ? VTK_TRIQUADRATIC_HEXAHEDRON : VTK_QUADRATIC_HEXAHEDRON, count, ids);
      }
    }
  }
  SetLinearField(grid);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGridVolumeMapper> MakeMapper(bool cells)
{
  if (cells)
  {
    auto m = vtkSmartPointer<vtkHAVSCellProjectionMapper>::New();
    m->KeepFloatResultOn();
    return m;
  }
  auto m = vtkSmartPointer<vtkHAVSVolumeMapper>::New();
  m->KeepFloatResultOn();
  m->SetEarlyRayTerminationOpacity(1.0);
  return m;
}

const char* Name(bool cells)
{
  return cells ? "cell projection" : "HAVS";
}

Frame RenderAndReference(vtkDataObject* data, vtkUnstructuredGridVolumeMapper* mapper,
  vtkVolumeProperty* property, const View& view, vtkDataSet* exactOf,
  const std::function<void(vtkHAVSReferenceRenderer*)>& configure)
{
  havstest::Messages* messages = havstest::CountMessages(mapper);
  auto s = havstest::MakeScene(data, mapper, property, kSize, kSize);
  havstest::PlaceCamera(s.Renderer, view.Azimuth, view.Elevation, view.Parallel);
  s.Window->Render();
  Frame f;
  f.Image = havstest::FloatResult(mapper);
  f.Errors = messages->Errors;
  f.Warnings = messages->Warnings;
  f.Text = messages->Text;
  vtkNew<vtkHAVSReferenceRenderer> r;
  r->SetInputData(exactOf);
  r->SetProperty(property);
  r->SetCamera(s.Renderer->GetActiveCamera());
  if (mapper->GetClippingPlanes())
  {
    r->SetClippingPlanes(mapper->GetClippingPlanes());
  }
  if (configure)
  {
    configure(r);
  }
  r->SetSize(kSize, kSize);
  if (r->Render())
  {
    vtkFloatArray* out = r->GetImage();
    f.Exact.assign(out->GetPointer(0), out->GetPointer(0) + 4 * kSize * kSize);
  }
  return f;
}

vtkIdType BoundaryTriangles(vtkDataSet* data)
{
  auto tets = vtkHAVSTetrahedralizer::Tetrahedralize(data, nullptr);
  vtkNew<vtkHAVSFaceSet> faces;
  faces->Build(tets);
  return faces->GetNumberOfBoundaryFaces();
}

havstest::ImageDifference WorstOverViews(const std::string& what, vtkDataSet* data,
  vtkDataSet* exactOf, vtkVolumeProperty* property, bool bothMappers, size_t havsEdge,
  bool allViews, bool everyView)
{
  havstest::ImageDifference worst;
  for (bool cells : { false, true })
  {
    if (cells && !bothMappers)
    {
      continue;
    }
    for (const View& view : kViews)
    {
      if (!allViews && &view != &kViews[0] && &view != &kViews[3])
      {
        continue; // one perspective and the parallel view
      }
      if (!allViews && !everyView && &view != &kViews[cells ? 3 : 0])
      {
        continue; // the default suite: HAVS the perspective view, the cell projection the parallel
                  // one
      }
      auto mapper = MakeMapper(cells);
      const Frame f = RenderAndReference(data, mapper, property, view, exactOf);
      havstest::Check(f.Errors == 0 && !f.Image.empty() && !f.Exact.empty(),
        what + " (" + Name(cells) + "): rendered without errors");
      if (f.Image.empty() || f.Exact.empty())
      {
        worst.Max = 1.0;
        continue;
      }
      havstest::Check(havstest::AllFinite(f.Image), what + ": finite");
      const auto d = havstest::Compare(f.Image, f.Exact, cells ? kEdge : havsEdge);
      worst.RMSE = std::max(worst.RMSE, d.RMSE);
      worst.Max = std::max(worst.Max, d.Max);
    }
  }
  return worst;
}

vtkSmartPointer<vtkUnstructuredGrid> WithCellField(vtkUnstructuredGrid* data)
{
  return CellFieldOf(data);
}

vtkSmartPointer<vtkStructuredGrid> WithCellField(vtkStructuredGrid* data)
{
  return CellFieldOf(data);
}
}
}
