/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSVectorModes.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Vector arrays (issue 19), through both mappers at their defaults against the
// exact reference (havsTestCells.h: the views, the image size, "exact", the
// edge pixels left out): a 3-component array: the magnitude and component 2
// (vector mode) against the reference of the same scalar stored alone; control:
// component 0 against component 2's reference.
//
// Usage: TestHAVSVectorModes
#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <functional>
#include <string>

using namespace havstest::cells;

int TestHAVSVectorModes(int, char*[])
{
  auto grid = vtkHAVSDataSets::MakeBox(5, 5, 5, 0.2, 0.0, 1.0);
  vtkNew<vtkDoubleArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    v->SetTuple3(i, x[0] - 0.2, std::sin(4.0 * x[1]), 1.0 - x[2] * x[0]);
  }
  grid->GetPointData()->AddArray(v);
  // The reference of one scalar derived from the vector, stored alone.
  auto alone = [&](const std::function<double(const double*)>& f)
  {
    auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
    g->DeepCopy(grid);
    vtkNew<vtkDoubleArray> s;
    s->SetName("alone");
    s->SetNumberOfTuples(g->GetNumberOfPoints());
    for (vtkIdType i = 0; i < g->GetNumberOfPoints(); ++i)
    {
      s->SetValue(i, f(v->GetTuple3(i)));
    }
    g->GetPointData()->SetScalars(s);
    return g;
  };
  auto magnitude =
    alone([](const double* t) { return std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]); });
  auto second = alone([](const double* t) { return t[2]; });
  auto first = alone([](const double* t) { return t[0]; });

  struct Mode
  {
    const char* Name;
    int VectorMode, Component;
    vtkUnstructuredGrid* Exact;
    bool MustMatch;
  };
  const Mode modes[] = { { "magnitude", 0, 0, magnitude, true },
    { "component 2", 1, 2, second, true },
    { "control: component 0 against component 2's image", 1, 0, second, false },
    { "vector mode off: the first component", -1, 0, first, true } };
  for (const Mode& m : modes)
  {
    double range[2];
    m.Exact->GetPointData()->GetScalars()->GetRange(range);
    auto property = havstest::MakeRampProperty(range[0], range[1], 0.8, 0.2);
    for (bool cells : { false, true })
    {
      auto mapper = MakeMapper(cells);
      mapper->SetScalarModeToUsePointFieldData();
      mapper->SelectScalarArray("v");
      if (cells)
      {
        auto* c = static_cast<vtkHAVSCellProjectionMapper*>(mapper.Get());
        c->SetVectorMode(m.VectorMode);
        c->SetVectorComponent(m.Component);
      }
      else
      {
        auto* h = static_cast<vtkHAVSVolumeMapper*>(mapper.Get());
        h->SetVectorMode(m.VectorMode);
        h->SetVectorComponent(m.Component);
      }
      const Frame f = RenderAndReference(grid, mapper, property, kViews[0], m.Exact);
      const auto d = havstest::Compare(f.Image, f.Exact, kEdge);
      Print(std::string(m.Name) + " (" + Name(cells) + ")", d);
      havstest::Check(Exact(d) == m.MustMatch, std::string(m.Name) + " (" + Name(cells) + ")");
    }
  }
  return havstest::Result();
}
