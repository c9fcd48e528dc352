/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSBadCells.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Badly shaped and bad cells (issue 20), each through both mappers against
// the exact reference at three views, finite, with a control that fails:
//   sliver, needle, cap and wedge tetrahedra (a dense medium, so that the
//   thin cells show; control: the reference of the cell made twice as thick);
//   inverted orientation (every other cell's points listed the other way:
//   the same cells, the same image; control: those cells removed);
//   duplicate cells (every 7th written twice: intended, one copy drawn, with
//   a warning; control: those cells removed);
//   unused points (100 points no cell uses, with a scalar far outside the
//   used range: the same image; control: half the cells removed);
//   zero-volume cells (40 flat tetrahedra on existing points: dropped with a
//   warning, the same image; control: the reference of a half unit distance);
//   non-manifold meshes (two boxes sharing one edge, and one vertex, point
//   ids shared: exact; control: one box alone).
// Each control is the exact image of the control scene seen from the case's
// own camera.
// (havsTestStress.h: "exact", the edge pixels left out, the variants). One
// view in the default suite, three with "full" (`long`).
//
// Usage: TestHAVSBadCells [full]   (full: three views)
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"
#include "havsTestStress.h"

#include "vtkAppendFilter.h"
#include "vtkCell.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkHAVSDataSets.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace havstest::stress;

int TestHAVSBadCells(int argc, char* argv[])
{
  const bool allViews = argc > 1 && std::string(argv[1]) == "full";
  // One view here (the suite's time); three for `cells full` (long).
  std::vector<std::pair<double, double>> views = { { 30.0, 20.0 }, { 100.0, -35.0 },
    { 200.0, 60.0 } };
  if (!allViews)
  {
    views.resize(1);
  }
  const size_t edge = kPairSize * kPairSize / 2000;
  auto exactEverywhere = [&](const std::string& what, vtkUnstructuredGrid* grid,
                           vtkVolumeProperty* property, vtkUnstructuredGrid* control,
                           vtkVolumeProperty* controlProperty, bool expectWarning)
  {
    // The references of this case, shared by both mappers; a control is
    // the control's exact image from the case's own camera.
    PairReferences references;
    for (bool cells : { false, true })
    {
      int controlsFailed = 0;
      for (const auto& view : views)
      {
        const Pair p =
          RenderWithReference(grid, property, cells, references, view.first, view.second);
        const size_t covered = CoveredPixels(p.Exact);
        const auto d = havstest::Compare(p.Image, p.Exact, edge);
        const auto wrong =
          havstest::Compare(p.Image, references.Get(control, controlProperty, p.Camera), edge);
        char name[160];
        std::snprintf(name, sizeof(name), "%s, %s, view (%.0f, %.0f)", Name(cells), what.c_str(),
          view.first, view.second);
        Print(std::string(name) + ": vs reference", d);
        Print(std::string(name) + ": control", wrong);
        havstest::Check(Accurate(d, p.Subset),
          std::string(name) + (p.Subset ? ": within the level-of-detail bound" : ": exact"));
        havstest::Check(covered >= 9, std::string(name) + ": the cells show");
        havstest::Check(havstest::AllFinite(p.Image), std::string(name) + ": finite");
        havstest::Check(p.Errors == 0 && (p.Warnings > 0) == expectWarning,
          std::string(name) + (expectWarning ? ": warned" : ": no warning"));
        controlsFailed += Accurate(wrong, p.Subset) ? 0 : 1;
      }
      havstest::Check(controlsFailed > 0,
        std::string(Name(cells)) + ", " + what + ": the control fails at a view at least");
    }
  };

  // Badly shaped single tetrahedra in a dense medium.
  {
    struct Shape
    {
      const char* Name;
      std::vector<std::array<double, 3>> Points;
      std::vector<std::array<double, 3>> Thicker;
    };
    const std::vector<Shape> shapes = {
      { "sliver", { { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0.01 }, { 0, 1, 0.01 } },
        { { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0.02 }, { 0, 1, 0.02 } } },
      { "needle", { { 0, 0, 0 }, { 0.05, 0, 0 }, { 0, 0.05, 0 }, { 0.3, 0.3, 1 } },
        { { 0, 0, 0 }, { 0.1, 0, 0 }, { 0, 0.1, 0 }, { 0.3, 0.3, 1 } } },
      { "cap", { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.9, 0 }, { 0.5, 0.3, 0.01 } },
        { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.9, 0 }, { 0.5, 0.3, 0.02 } } },
      { "wedge", { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.8, 0.3 }, { 0.51, 0.8, 0.28 } },
        { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.8, 0.3 }, { 0.52, 0.8, 0.26 } } },
    };
    for (const Shape& shape : shapes)
    {
      auto grid = MakeTets(shape.Points, { { 0, 1, 2, 3 } });
      auto thicker = MakeTets(shape.Thicker, { { 0, 1, 2, 3 } });
      double range[2];
      grid->GetPointData()->GetScalars()->GetRange(range);
      // Optical depth about 2 along the cells' longest chords: the thin cells
      // show, and the table's length axis (its interpolation) is not what is
      // measured here.
      auto dense = havstest::MakeRampProperty(range[0] - 0.1, range[1] + 0.1, 0.9, 0.5);
      exactEverywhere(std::string(shape.Name) + " tetrahedron", grid, dense, thicker, dense, false);
    }
  }

  auto box = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(box);
  auto all = [](vtkIdType) { return true; };
  auto asIs = [](vtkIdType, vtkIdType*) {};
  // Inverted orientation.
  {
    auto flipped = Cells(box, all,
      [](vtkIdType c, vtkIdType* ids)
      {
        if (c % 2)
        {
          std::swap(ids[0], ids[1]);
        }
      });
    auto without = Cells(
      box, [](vtkIdType c) { return c % 2 == 0; }, asIs);
    exactEverywhere("inverted orientation", flipped, property, without, property, false);
  }
  // Duplicate cells.
  {
    auto doubled = Cells(box, all, asIs);
    for (vtkIdType c = 0; c < box->GetNumberOfCells(); c += 7)
    {
      doubled->InsertNextCell(VTK_TETRA, box->GetCell(c)->GetPointIds());
    }
    auto without = Cells(
      box, [](vtkIdType c) { return c % 7 != 0; }, asIs);
    exactEverywhere("duplicate cells", doubled, property, without, property, true);
  }
  // Unused points: 100 points no cell uses, inside the bounds (which frame
  // the camera), with a scalar far outside the used range (which would
  // squeeze the table if it counted).
  {
    auto extra = Cells(box, all, asIs);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->DeepCopy(box->GetPoints());
    vtkNew<vtkDoubleArray> scalars;
    scalars->DeepCopy(box->GetPointData()->GetScalars());
    for (int i = 0; i < 100; ++i)
    {
      points->InsertNextPoint(0.01 * i, 0.5, 0.3);
      scalars->InsertNextValue(1e6);
    }
    extra->SetPoints(points);
    extra->GetPointData()->SetScalars(scalars);
    auto without = Cells(
      box, [](vtkIdType c) { return c % 2 == 0; }, asIs);
    exactEverywhere("unused points", extra, property, without, property, false);
  }
  // Zero-volume cells on existing points (four of a cube face's corners).
  {
    auto flat = Cells(box, all, asIs);
    // The lattice point (i, j, k) of the box (spacing 0.25), found by position.
    std::map<std::array<int, 3>, vtkIdType> lattice;
    for (vtkIdType i = 0; i < box->GetNumberOfPoints(); ++i)
    {
      double x[3];
      box->GetPoint(i, x);
      lattice[{ static_cast<int>(std::lround(4 * x[0])), static_cast<int>(std::lround(4 * x[1])),
        static_cast<int>(std::lround(4 * x[2])) }] = i;
    }
    int added = 0;
    for (int k = 0; k <= 4 && added < 40; ++k)
    {
      for (int j = 0; j < 4 && added < 40; ++j)
      {
        for (int i = 0; i < 4 && added < 40; i += 2)
        {
          // Four corners of a lattice square in the plane z = k / 4.
          const vtkIdType ids[4] = { lattice.at({ i, j, k }), lattice.at({ i + 1, j, k }),
            lattice.at({ i, j + 1, k }), lattice.at({ i + 1, j + 1, k }) };
          flat->InsertNextCell(VTK_TETRA, 4, ids);
          ++added;
        }
      }
    }
    auto halfUnit = havstest::MakeRampPropertyFor(box);
    halfUnit->SetScalarOpacityUnitDistance(0.5 * property->GetScalarOpacityUnitDistance());
    exactEverywhere("zero-volume cells", flat, property, box, halfUnit, true);
  }
  // Non-manifold: two boxes sharing an edge, and a vertex.
  for (bool vertex : { false, true })
  {
    auto second = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
    auto moved = Moved(
      second, [](double x) { return x; }, true);
    vtkPoints* p = moved->GetPoints();
    for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
    {
      double x[3];
      p->GetPoint(i, x);
      p->SetPoint(i, x[0] + 1.0, x[1] + 1.0, x[2] + (vertex ? 1.0 : 0.0));
    }
    vtkNew<vtkAppendFilter> append;
    append->MergePointsOn();
    append->AddInputData(box);
    append->AddInputData(moved);
    append->Update();
    auto both = vtkSmartPointer<vtkUnstructuredGrid>::New();
    both->DeepCopy(append->GetOutput());
    const vtkIdType shared = 2 * box->GetNumberOfPoints() - both->GetNumberOfPoints();
    std::printf("two boxes sharing %s: %lld shared points\n", vertex ? "a vertex" : "an edge",
      static_cast<long long>(shared));
    havstest::Check(shared == (vertex ? 1 : 5), "the boxes share their points there");
    exactEverywhere(vertex ? "boxes sharing a vertex" : "boxes sharing an edge", both, property,
      box, property, false);
  }
  return havstest::Result();
}
