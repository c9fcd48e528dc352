/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSCellOptics.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSCellOptics and the cell codes of vtkHAVSMesh (issue 20: a cell's
// segment takes the transfer function at the cell's value):
// - every code index * 2^-21, also + 2 and + 4 (the k-buffer's tags), is
//   exact in a float and decodes to its index; codes are ordered as the
//   indices; control: with 2^23 codes the tagged ones no longer decode;
// - the optics of a property with a spike, HSV colour and a grey channel
//   equal its functions at each value (colour, tau = opacity / unit, s, tau s);
//   the closed-form segment from them matches the adaptive integral of a
//   constant scalar to 1e-6, where the table's diagonal misses the spike
//   (control: it must differ by more than 0.5);
// - NeedsRebuild follows the property and the values;
// - a grid with cell scalars (duplicates, NaN): the distinct values sorted,
//   each tetrahedron's code decodes to its cell's value; more distinct values
//   than codes are rounded to the grid of 2^21 values with a warning.
#include "havsTestChecks.h"

#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkHAVSCellOptics.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace
{
/// Whether code + tag decodes to `index` with `bits` bits (as the shaders do:
/// int(code * 2^bits + 0.5) after the tag is taken off).
bool Decodes(uint32_t index, int bits, float tag)
{
  const float code = std::ldexp(static_cast<float>(index), -bits);
  const float tagged = code + tag;
  const float back = tagged - tag;
  return static_cast<uint32_t>(std::ldexp(back, bits) + 0.5f) == index;
}

vtkSmartPointer<vtkVolumeProperty> Spike(double at, bool grey)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(at - 0.001, 0.0);
  opacity->AddPoint(at, 1.0);
  opacity->AddPoint(at + 0.001, 0.0);
  opacity->AddPoint(1.0, 0.2);
  property->SetScalarOpacity(opacity);
  if (grey)
  {
    vtkNew<vtkPiecewiseFunction> g;
    g->AddPoint(0.0, 0.1);
    g->AddPoint(1.0, 0.9);
    property->SetColor(g);
  }
  else
  {
    vtkNew<vtkColorTransferFunction> color;
    color->SetColorSpaceToHSV();
    color->AddRGBPoint(0.0, 0.0, 0.0, 1.0);
    color->AddRGBPoint(1.0, 1.0, 0.2, 0.0);
    property->SetColor(color);
  }
  property->SetScalarOpacityUnitDistance(0.25);
  return property;
}

void CheckCodes()
{
  const int bits = vtkHAVSCellOptics::CodeBits;
  bool exact = true, ordered = true;
  float previous = -1.0f;
  for (uint32_t i = 0; i < vtkHAVSCellOptics::MaximumValues; i += (i < 4096 ? 1 : 997))
  {
    for (float tag : { 0.0f, 2.0f, 4.0f })
    {
      exact = exact && Decodes(i, bits, tag);
    }
    const float code = vtkHAVSCellOptics::CodeOf(i);
    ordered = ordered && code > previous && code == std::ldexp(static_cast<float>(i), -bits);
    previous = code;
  }
  const uint32_t last = vtkHAVSCellOptics::MaximumValues - 1;
  exact = exact && Decodes(last, bits, 4.0f) && Decodes(last, bits, 2.0f);
  havstest::Check(exact, "every code, tagged + 0, + 2, + 4, decodes to its index");
  havstest::Check(ordered, "codes are ordered as the indices");
  havstest::Check(vtkHAVSCellOptics::CodeOf(last) < 1.0f, "the largest code is below 1");
  // Control: 2^23 codes do not survive the entry tag (+ 4).
  bool lost = false;
  for (uint32_t i = 1; i < 64; ++i)
  {
    lost = lost || !Decodes(i, 23, 4.0f);
  }
  havstest::Check(lost, "control: with 23 bits an entry-tagged code is lost");
}

void CheckOptics()
{
  const double range[2] = { 0.0, 1.0 };
  const double at = 0.4843;
  for (bool grey : { false, true })
  {
    auto property = Spike(at, grey);
    const std::vector<double> values = { 0.0, 0.1, at - 0.0005, at, 0.7, 1.0 };
    vtkNew<vtkHAVSCellOptics> optics;
    havstest::Check(optics->NeedsRebuild(property, 0, 7), "needs a build at first");
    havstest::Check(optics->Build(property, 0, values, range, 7), "built");
    havstest::Check(optics->GetNumberOfValues() == values.size(), "one entry per value");
    const std::vector<float>& o = optics->GetOptics();
    double worst = 0.0, worstSegment = 0.0, diagonalMiss = 0.0;
    vtkNew<vtkHAVSPreIntegrationTable> table;
    table->Build(property, 0, range, 2.0);
    for (size_t i = 0; i < values.size(); ++i)
    {
      const double s = values[i];
      double color[3];
      if (grey)
      {
        color[0] = color[1] = color[2] = property->GetGrayTransferFunction()->GetValue(s);
      }
      else
      {
        property->GetRGBTransferFunction()->GetColor(s, color);
      }
      const double opacity = property->GetScalarOpacity()->GetValue(s);
      const double tau = opacity / 0.25;
      const float* e = &o[vtkHAVSCellOptics::FloatsPerValue * i];
      const double expected[8] = { color[0], color[1], color[2], tau, s, opacity, tau * s, 0.0 };
      for (int c = 0; c < 8; ++c)
      {
        worst =
          std::max(worst, std::fabs(e[c] - expected[c]) / std::max(1.0, std::fabs(expected[c])));
      }
      // The closed-form segment (havsCellSegment) against the adaptive
      // integral of a constant scalar, and the table's diagonal against it.
      for (double length : { 0.01, 0.1, 1.0 })
      {
        const double alpha = 1.0 - std::exp(-e[3] * length);
        double exact[4], diagonal[4];
        vtkHAVSPreIntegrationTable::IntegrateSegment(property, 0, s, s, length, exact);
        table->Lookup(s, s, length, diagonal);
        for (int c = 0; c < 4; ++c)
        {
          const double closed = c < 3 ? e[c] * alpha : alpha;
          worstSegment = std::max(worstSegment, std::fabs(closed - exact[c]));
          if (s == at)
          {
            diagonalMiss = std::max(diagonalMiss, std::fabs(diagonal[c] - exact[c]));
          }
        }
      }
    }
    const std::string who = grey ? "grey: " : "HSV colour: ";
    std::printf("%soptics vs the functions %.2e, closed-form segments vs the adaptive integral "
                "%.2e, the table's diagonal at the spike %.3f\n",
      who.c_str(), worst, worstSegment, diagonalMiss);
    havstest::Check(worst < 1e-6, who + "the optics are the functions at each value");
    havstest::Check(worstSegment < 1e-6, who + "closed-form segments are exact");
    havstest::Check(diagonalMiss > 0.5, who + "control: the table's diagonal misses the spike");
    havstest::Check(!optics->NeedsRebuild(property, 0, 7), who + "no rebuild when unchanged");
    havstest::Check(optics->NeedsRebuild(property, 0, 8), who + "rebuild for other values");
    property->GetScalarOpacity()->AddPoint(0.9, 0.5);
    havstest::Check(optics->NeedsRebuild(property, 0, 7), who + "rebuild after a function edit");
  }
  // Bad input: no property, a unit distance of 0.
  vtkNew<vtkHAVSCellOptics> optics;
  const std::vector<double> one = { 0.5 };
  optics->GlobalWarningDisplayOff();
  havstest::Check(!optics->Build(nullptr, 0, one, range, 1) && optics->GetNumberOfValues() == 0,
    "no property: an error, no values");
  auto zero = Spike(0.5, false);
  zero->SetScalarOpacityUnitDistance(0.0);
  havstest::Check(!optics->Build(zero, 0, one, range, 1) && optics->GetNumberOfValues() == 0,
    "a unit distance of 0: an error, no values");
  optics->GlobalWarningDisplayOn();
}

/// `grid` with cell scalars value(c) only.
vtkSmartPointer<vtkUnstructuredGrid> WithCellScalars(
  vtkUnstructuredGrid* grid, double (*value)(vtkIdType))
{
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->ShallowCopy(grid);
  out->GetPointData()->Initialize();
  vtkNew<vtkDoubleArray> s;
  s->SetName("c");
  s->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    s->SetValue(c, value(c));
  }
  out->GetCellData()->SetScalars(s);
  return out;
}

/// Whether each tetrahedron's code decodes to its cell's value (`rounded`:
/// to within half a grid step of it).
bool CodesDecode(vtkHAVSMesh* mesh, vtkUnstructuredGrid* grid, bool rounded)
{
  const std::vector<double>& values = mesh->GetCellValues();
  const std::vector<float>& codes = mesh->GetTetrahedronCodes();
  const std::vector<uint32_t>& cells = mesh->GetFaceSet()->GetTetrahedronCells();
  vtkDataArray* s = grid->GetCellData()->GetScalars();
  const double* range = mesh->GetScalarRange();
  const double step = (range[1] - range[0]) / (vtkHAVSCellOptics::MaximumValues - 1);
  bool ok = codes.size() == cells.size();
  for (size_t t = 0; ok && t < cells.size(); ++t)
  {
    const uint32_t index = static_cast<uint32_t>(std::ldexp(codes[t], 21) + 0.5f);
    double v = s->GetTuple1(cells[t]);
    v = std::isfinite(v) ? v : range[0];
    ok = index < values.size() &&
      (rounded ? std::fabs(values[index] - v) <= 0.5 * step * (1 + 1e-9) : values[index] == v);
  }
  return ok;
}

void CheckMesh()
{
  auto box = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
  auto grid = WithCellScalars(box,
    [](vtkIdType c) { return c % 17 == 5 ? std::nan("") : static_cast<double>((c * 7) % 13) / 3; });
  vtkNew<vtkHAVSMesh> mesh;
  vtkHAVSMesh::ScalarSelection selection;
  havstest::Check(mesh->Build(grid, selection), "cell-scalar box built: " + mesh->GetError());
  havstest::Check(mesh->HasCellScalars(), "the scalars are the cells'");
  const std::vector<double>& values = mesh->GetCellValues();
  bool sorted = true;
  for (size_t i = 1; i < values.size(); ++i)
  {
    sorted = sorted && values[i - 1] < values[i];
  }
  std::printf("box: %zu tetrahedra, %zu distinct cell values\n", mesh->GetTetrahedronCodes().size(),
    values.size());
  havstest::Check(values.size() == 13 && sorted, "13 distinct values, sorted");
  havstest::Check(CodesDecode(mesh, grid, false), "every tetrahedron's code is its cell's value");
  // Control: the codes of another grid's values do not decode to these.
  auto other = WithCellScalars(box, [](vtkIdType c) { return static_cast<double>(c % 13) / 3; });
  havstest::Check(!CodesDecode(mesh, other, false), "control: another grid's values differ");

  // More distinct values than codes: rounded to the grid, with a warning.
  auto large = vtkHAVSDataSets::MakeBox(74, 74, 80, 0.01, 0.0, 1.0);
  auto many = WithCellScalars(large, [](vtkIdType c) { return std::sqrt(static_cast<double>(c)); });
  vtkNew<vtkHAVSMesh> big;
  havstest::Check(big->Build(many, selection), "large cell-scalar box built: " + big->GetError());
  bool warned = false;
  for (const std::string& w : big->GetWarnings())
  {
    warned = warned || w.find("distinct cell values") != std::string::npos;
  }
  std::printf("large box: %lld cells, %zu values after rounding to the grid\n",
    static_cast<long long>(many->GetNumberOfCells()), big->GetCellValues().size());
  havstest::Check(
    many->GetNumberOfCells() > static_cast<vtkIdType>(vtkHAVSCellOptics::MaximumValues),
    "more cells than codes");
  havstest::Check(warned, "rounding the values is warned about");
  havstest::Check(big->GetCellValues().size() <= vtkHAVSCellOptics::MaximumValues,
    "at most MaximumValues values");
  havstest::Check(CodesDecode(big, many, true), "every code within half a grid step of its value");
  havstest::Check(!CodesDecode(big, many, false), "control: not every value exactly (rounded)");
}
}

int TestHAVSCellOptics(int, char*[])
{
  CheckCodes();
  CheckOptics();
  CheckMesh();
  return havstest::Result();
}
