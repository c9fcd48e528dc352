/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSTimeSteps.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Time steps (issue 19), through both mappers at their defaults against the
// exact reference (havsTestCells.h: the views, the image size, "exact", the
// edge pixels left out): a new time step on the same mesh (new arrays, same
// contents, new scalars, point and cell data): only the scalars are mapped and
// uploaded again, the order is reused, the image is exact and changed; control:
// the points moved make the mesh again; the same on meshes the mappers
// tessellate (mixed linear cells, refined 20-node hexahedra and 13-node
// pyramids: the scalars go through the tessellation's source map); the costs of
// both paths are printed (the blunt fin, a refined curved mesh).
//
// Usage: TestHAVSTimeSteps
#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"
#include "havsTestShells.h"

#include "vtkCamera.h"
#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFrameStatistics.h"
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

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace havstest::cells;

namespace
{
/// The exact reference image of `grid` (refined to `level`) seen by `camera`, kSize².
std::vector<float> ExactImage(
  vtkUnstructuredGrid* grid, int level, vtkVolumeProperty* property, vtkCamera* camera)
{
  vtkNew<vtkHAVSReferenceRenderer> r;
  r->SetInputData(grid);
  r->SetHigherOrderSubdivision(level);
  r->SetProperty(property);
  r->SetCamera(camera);
  r->SetSize(kSize, kSize);
  r->Render();
  return std::vector<float>(
    r->GetImage()->GetPointer(0), r->GetImage()->GetPointer(0) + 4 * kSize * kSize);
}

/// `grid`'s geometry in new arrays (as a reader gives each time step), with
/// the point array "s" = f(point) (or the cell array "c" = f(cell centre)).
vtkSmartPointer<vtkUnstructuredGrid> TimeStep(vtkUnstructuredGrid* grid,
  const std::function<double(const double*)>& f, bool cellData, double scale = 1.0)
{
  auto step = vtkSmartPointer<vtkUnstructuredGrid>::New();
  step->DeepCopy(grid); // new points and cells with the same contents
  if (scale != 1.0)
  {
    for (vtkIdType i = 0; i < step->GetNumberOfPoints(); ++i)
    {
      double x[3];
      step->GetPoint(i, x);
      step->GetPoints()->SetPoint(i, scale * x[0], scale * x[1], scale * x[2]);
    }
  }
  vtkNew<vtkDoubleArray> values;
  values->SetName(cellData ? "c" : "s");
  const vtkIdType n = cellData ? step->GetNumberOfCells() : step->GetNumberOfPoints();
  values->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3] = { 0, 0, 0 };
    if (cellData)
    {
      double pcoords[3];
      std::vector<double> weights(static_cast<size_t>(step->GetMaxCellSize()));
      int sub = step->GetCell(i)->GetParametricCenter(pcoords);
      step->GetCell(i)->EvaluateLocation(sub, pcoords, x, weights.data());
    }
    else
    {
      step->GetPoint(i, x);
    }
    values->SetValue(i, f(x));
  }
  step->GetPointData()->Initialize();
  step->GetCellData()->Initialize();
  if (cellData)
  {
    step->GetCellData()->SetScalars(values);
  }
  else
  {
    step->GetPointData()->SetScalars(values);
  }
  return step;
}

/// Time steps on meshes the mappers tessellate: a new step re-maps only the
/// scalars through the tessellation's source map (update kind 2, the order
/// reused), exact against the reference of the new step; control: its image
/// differs from the first step's (the new scalars arrived); moved points
/// make the mesh again.
void TessellatedTimeSteps(vtkVolumeProperty* property,
  const std::function<double(const double*)>& rising,
  const std::function<double(const double*)>& falling)
{
  const int m[3] = { 2, 3, 2 };
  auto scaled = [](vtkUnstructuredGrid* grid)
  {
    // Into the unit box the fields are made for.
    auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
    copy->DeepCopy(grid);
    for (vtkIdType i = 0; i < copy->GetNumberOfPoints(); ++i)
    {
      double x[3];
      copy->GetPoint(i, x);
      copy->GetPoints()->SetPoint(i, 0.5 * x[0], 0.5 * x[1], x[2]);
    }
    return copy;
  };
  // Mixed linear cells in slabs along x (every shared face the same on both sides).
  auto mixed = CubeGrid(4, 0.0,
    [](int i, int, int)
    {
      return i < 1 ? CubeAs::Voxel
                   : (i < 2 ? CubeAs::Hexahedron : (i < 3 ? CubeAs::Wedges : CubeAs::Pyramids));
    });
  auto hexahedra = scaled(CurvedShell(m, ShellHexahedra20));
  auto pyramids = scaled(PyramidShell(m, false, true));
  struct Case
  {
    std::string Name;
    vtkUnstructuredGrid* Grid;
    int Level;
    bool CellData;
    bool CellProjection;
    bool Control; ///< moved points too
  };
  const Case cases[] = { { "mixed linear cells", mixed, 0, true, false, false },
    { "20-node hexahedra at level 2", hexahedra, 2, false, false, false },
    { "20-node hexahedra at level 2", hexahedra, 2, true, false, true },
    { "20-node hexahedra at level 2", hexahedra, 2, true, true, false },
    { "13-node pyramids, tetrahedra, hexahedra at level 2", pyramids, 2, true, false, false } };
  for (const Case& c : cases)
  {
    const std::string name = c.Name + ", " + (c.CellData ? "cell scalars" : "point scalars") +
      " (" + Name(c.CellProjection) + ")";
    auto mapper = MakeMapper(c.CellProjection);
    if (auto* h = vtkHAVSVolumeMapper::SafeDownCast(mapper))
    {
      h->SetHigherOrderSubdivision(c.Level);
    }
    if (auto* p = vtkHAVSCellProjectionMapper::SafeDownCast(mapper))
    {
      p->SetHigherOrderSubdivision(c.Level);
    }
    auto first = TimeStep(c.Grid, rising, c.CellData);
    auto s = havstest::MakeScene(first, mapper, property, kSize, kSize);
    havstest::PlaceCamera(s.Renderer, 30.0, 20.0, false);
    // The update kind of the frame just drawn (2: the scalars only, the order reused).
    auto update = [&]()
    {
      if (c.CellProjection)
      {
        return static_cast<vtkHAVSCellProjectionMapper*>(mapper.Get())->GetLastOrderReused() ? 2
                                                                                             : 1;
      }
      vtkHAVSFrameStatistics* stats =
        static_cast<vtkHAVSVolumeMapper*>(mapper.Get())->GetLastFrameStatistics();
      std::printf("    mesh update %d in %.4f s, order reused %d\n", stats->GetMeshUpdate(),
        stats->GetMeshSeconds(), stats->GetOrderReused() ? 1 : 0);
      return stats->GetOrderReused() == (stats->GetMeshUpdate() == 2) ? stats->GetMeshUpdate() : -1;
    };
    s.Window->Render();
    const auto one = havstest::FloatResult(mapper);
    havstest::Check(update() == 1, name + ": the first step makes the mesh");
    auto second = TimeStep(c.Grid, falling, c.CellData);
    mapper->SetInputData(second);
    s.Window->Render();
    const auto two = havstest::FloatResult(mapper);
    havstest::Check(update() == 2, name + ": a new step maps the scalars only");
    const std::vector<float> exact =
      ExactImage(second, c.Level, property, s.Renderer->GetActiveCamera());
    const auto d =
      havstest::Compare(two, exact, c.CellProjection || !c.CellData ? kEdge : kEdgeCellScalars);
    Print(name + ", second step", d);
    havstest::Check(Exact(d), name + ": the second step exact");
    const auto changed = havstest::Compare(one, two);
    Print("control: " + name + ", the first step's image", changed);
    havstest::Check(changed.Max > 0.05, name + ": the second step's image changed");
    if (c.Control)
    {
      mapper->SetInputData(TimeStep(c.Grid, falling, c.CellData, 1.05));
      s.Window->Render();
      havstest::Check(update() == 1, name + ": control: moved points make the mesh again");
    }
  }

  // What each path costs on a larger curved mesh (printed, not asserted):
  // 20-node hexahedra at level 2, point and cell scalars.
  const int big[3] = { 6, 8, 6 };
  auto shell = scaled(CurvedShell(big, ShellHexahedra20));
  for (bool cellData : { false, true })
  {
    vtkNew<vtkHAVSVolumeMapper> mapper;
    mapper->SetHigherOrderSubdivision(2);
    auto first = TimeStep(shell, rising, cellData);
    auto s = havstest::MakeScene(first, mapper, property, 256, 256);
    havstest::PlaceCamera(s.Renderer, 30.0, 20.0, false);
    s.Window->Render();
    const double full = mapper->GetLastFrameStatistics()->GetMeshSeconds();
    vtkHAVSTetrahedralizer::Report report;
    vtkHAVSTetrahedralizer::Tetrahedralize(first, &report, 2);
    const vtkIdType tets = report.OutputTetrahedra;
    mapper->SetInputData(TimeStep(shell, falling, cellData));
    s.Window->Render();
    vtkHAVSFrameStatistics* stats = mapper->GetLastFrameStatistics();
    std::printf("  %lld 20-node hexahedra at level 2 (%lld tetrahedra), %s, 256^2: the first "
                "step's mesh %.3f s; a new step's scalars %.3f s (update kind %d)\n",
      static_cast<long long>(shell->GetNumberOfCells()), static_cast<long long>(tets),
      cellData ? "cell scalars" : "point scalars", full, stats->GetMeshSeconds(),
      stats->GetMeshUpdate());
    havstest::Check(
      stats->GetMeshUpdate() == 2, "large curved mesh: a new step maps the scalars only");
  }
}
}

int TestHAVSTimeSteps(int, char*[])
{
  auto box = vtkHAVSDataSets::MakeBox(6, 6, 6, 1.0 / 6, 0.0, 1.0);
  auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.2);
  const std::function<double(const double*)> rising = [](const double* x)
  { return 0.5 * x[2] + 0.5 * x[0] * x[1]; };
  const std::function<double(const double*)> falling = [](const double* x)
  { return 1.0 - 0.7 * x[2] - 0.3 * x[0]; };
  for (bool cellData : { false, true })
  {
    const std::string kind = cellData ? "cell scalars" : "point scalars";
    for (bool cells : { false, true })
    {
      auto mapper = MakeMapper(cells);
      auto first = TimeStep(box, rising, cellData);
      auto s = havstest::MakeScene(first, mapper, property, kSize, kSize);
      havstest::PlaceCamera(s.Renderer, 30.0, 20.0, false);
      auto frame = [&](vtkUnstructuredGrid* grid, const std::string& what, int expectedUpdate)
      {
        mapper->SetInputData(grid);
        s.Window->Render();
        const auto image = havstest::FloatResult(mapper);
        const std::vector<float> exact =
          ExactImage(grid, 0, property, s.Renderer->GetActiveCamera());
        const auto d =
          havstest::Compare(image, exact, cells || !cellData ? kEdge : kEdgeCellScalars);
        const std::string name = kind + ", " + what + " (" + Name(cells) + ")";
        Print(name, d);
        havstest::Check(Exact(d), name + ": exact");
        if (!cells)
        {
          auto* havs = static_cast<vtkHAVSVolumeMapper*>(mapper.Get());
          vtkHAVSFrameStatistics* stats = havs->GetLastFrameStatistics();
          std::printf("    mesh update %d in %.4f s, order reused %d\n", stats->GetMeshUpdate(),
            stats->GetMeshSeconds(), stats->GetOrderReused() ? 1 : 0);
          havstest::Check(stats->GetMeshUpdate() == expectedUpdate, name + ": the mesh update");
          havstest::Check(
            stats->GetOrderReused() == (expectedUpdate == 2), name + ": the order reused or not");
        }
        else
        {
          auto* projection = static_cast<vtkHAVSCellProjectionMapper*>(mapper.Get());
          havstest::Check(projection->GetLastOrderReused() == (expectedUpdate == 2),
            name + ": the cell order reused or not");
        }
        return image;
      };
      const auto one = frame(first, "first step", 1);
      const auto two = frame(TimeStep(box, falling, cellData), "second step, same mesh", 2);
      const auto changed = havstest::Compare(one, two);
      havstest::Check(changed.Max > 0.05, kind + ": the second step's image changed");
      // Control: the points moved: the mesh is made again.
      frame(TimeStep(box, falling, cellData, 1.05), "control: points moved", 1);
    }
  }
  TessellatedTimeSteps(property, rising, falling);

  // What each costs on the blunt fin (187,395 tetrahedra): printed, not asserted.
  auto fin = vtkHAVSDataSets::Load("bluntfin");
  havstest::Check(fin != nullptr, "the blunt fin is read (HAVS_DATA_DIR)");
  if (fin)
  {
    double range[2];
    fin->GetPointData()->GetScalars()->GetRange(range);
    auto finProperty = havstest::MakeRampProperty(range[0], range[1], 0.8, fin->GetLength() / 8.0);
    vtkNew<vtkHAVSVolumeMapper> mapper;
    auto s = havstest::MakeScene(fin, mapper, finProperty, 256, 256);
    havstest::PlaceCamera(s.Renderer, 30.0, 20.0, false);
    s.Window->Render();
    const double full = mapper->GetLastFrameStatistics()->GetMeshSeconds();
    auto next = vtkSmartPointer<vtkUnstructuredGrid>::New();
    next->DeepCopy(fin);
    vtkDataArray* values = next->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      values->SetComponent(i, 0, range[1] + range[0] - values->GetComponent(i, 0));
    }
    mapper->SetInputData(next);
    s.Window->Render();
    vtkHAVSFrameStatistics* stats = mapper->GetLastFrameStatistics();
    std::printf("  blunt fin, 256^2: the first step's mesh %.3f s; a new step's scalars %.3f s "
                "(update kind %d), order reused %d\n",
      full, stats->GetMeshSeconds(), stats->GetMeshUpdate(), stats->GetOrderReused() ? 1 : 0);
    havstest::Check(stats->GetMeshUpdate() == 2, "blunt fin: a new step updates the scalars only");
  }
  return havstest::Result();
}
