/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSGLTableBuilder.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// The pre-integrated table built on the GPU (vtkHAVSGLTableBuilder, issue 45):
// - for six tables (the tests' ramp at 64^3, the benchmark's function at 128 x
//   64, a narrow opacity peak between the fine samples at 96 x 32, a grey
//   function, a thick one whose length axis is logarithmic, the smallest
//   table, 2 x 2), every entry equals the CPU's build of the same quadrature
//   within 5e-6 (single against double precision; measured: at most 1.8e-6) and is finite; control:
//   the GPU's table of the ramp with one opacity node moved by 1 % of the
//   range misses that bound against the CPU's table of the ramp;
// - each mapper with PreIntegrationOnGPU on builds its table on the GPU
//   (GetLastTableBuiltOnGPU), and its image is exact against the reference,
//   before and after a transfer-function edit (one opacity node moved, the
//   table built on the GPU again); control: the image after the edit misses
//   the reference of the function before it.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMapperScenes.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkColorTransferFunction.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSGLTableBuilder.h"
#include "vtkHAVSMapperBase.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
/// The largest difference between two tables' entries (infinite where they
/// differ in size or either is not finite).
double LargestDifference(vtkHAVSPreIntegrationTable* a, vtkHAVSPreIntegrationTable* b)
{
  const size_t n = static_cast<size_t>(a->GetBuiltScalarResolution()) *
    a->GetBuiltScalarResolution() * a->GetBuiltLengthResolution() * 4;
  if (b->GetBuiltScalarResolution() != a->GetBuiltScalarResolution() ||
    b->GetBuiltLengthResolution() != a->GetBuiltLengthResolution())
  {
    return INFINITY;
  }
  double largest = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    const double d = std::fabs(static_cast<double>(a->GetTable()[i]) - b->GetTable()[i]);
    largest = std::max(largest, std::isfinite(d) ? d : INFINITY);
  }
  return largest;
}

/// `property`'s table built on the CPU and on the GPU (in `window`); their
/// largest difference, or -1 where the GPU did not build it.
double CompareBuilds(vtkOpenGLRenderWindow* window, vtkHAVSGLTableBuilder* builder,
  vtkVolumeProperty* cpuProperty, vtkVolumeProperty* gpuProperty, int ns, int nl, double maxLength,
  double range[2], bool* logarithmic = nullptr)
{
  vtkNew<vtkHAVSPreIntegrationTable> cpu, gpu;
  for (vtkHAVSPreIntegrationTable* t : { cpu.Get(), gpu.Get() })
  {
    t->SetScalarResolution(ns);
    t->SetLengthResolution(nl);
  }
  gpu->SetEntryBuilder([&](const vtkHAVSPreIntegrationTable::Quadrature& inputs, float* table)
    { return builder->Build(window, inputs, table); });
  cpu->Build(cpuProperty, 0, range, maxLength);
  gpu->Build(gpuProperty, 0, range, maxLength);
  if (logarithmic)
  {
    *logarithmic = cpu->GetLengthLogScale() > 0.0;
  }
  std::printf("    GPU build %.2f ms (compute %.2f ms, read back %.2f ms), CPU build %.2f ms\n",
    1000.0 * gpu->GetLastBuildSeconds(), 1000.0 * builder->GetLastComputeSeconds(),
    1000.0 * builder->GetLastReadSeconds(), 1000.0 * cpu->GetLastBuildSeconds());
  return gpu->GetLastBuiltByEntryBuilder() ? LargestDifference(cpu, gpu) : -1.0;
}

/// Each mapper with PreIntegrationOnGPU: built there, exact, before and after an edit.
void MapperCase(const std::string& name)
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  auto property = havstest::MakeBenchmarkPropertyFor(grid);
  auto mapper = havstest::MakeMapperNamed(name);
  mapper->PreIntegrationOnGPUOn();
  mapper->KeepFloatResultOn();
  const int size = 96;
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  havstest::PlaceCamera(s.Renderer, 30.0, 20.0, false);
  const size_t edge = static_cast<size_t>(size) * size / 2000;
  s.Window->Render();
  havstest::Check(mapper->GetLastTableBuiltOnGPU(), name + ": the table was built on the GPU");
  auto before = havstest::ReferenceImage(grid, property, s.Renderer->GetActiveCamera(), size);
  auto d = havstest::Compare(havstest::FloatResult(mapper), before, edge);
  havstest::PrintDifference(name + ", GPU table", d);
  havstest::Check(havstest::WithinExactBound(d), name + ": exact with the GPU's table");

  // The edit: the 30 % opacity node up to 0.4 (a table rebuilt on the GPU).
  double range[2];
  grid->GetScalarRange(range);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  opacity->RemovePoint(range[0] + 0.3 * (range[1] - range[0]));
  opacity->AddPoint(range[0] + 0.3 * (range[1] - range[0]), 0.4);
  s.Window->Render();
  havstest::Check(
    mapper->GetLastTableBuiltOnGPU(), name + ": the edit's table was built on the GPU");
  const auto image = havstest::FloatResult(mapper);
  auto after = havstest::ReferenceImage(grid, property, s.Renderer->GetActiveCamera(), size);
  d = havstest::Compare(image, after, edge);
  havstest::PrintDifference(name + ", GPU table after an edit", d);
  havstest::Check(
    havstest::WithinExactBound(d) && havstest::AllFinite(image), name + ": exact after the edit");
  const auto control = havstest::Compare(image, before, edge);
  havstest::PrintDifference(name + ", control: the reference before the edit", control);
  havstest::Check(!havstest::WithinExactBound(control), name + ": control fails");
}
}

int TestHAVSGLTableBuilder(int argc, char* argv[])
{
  const std::string only = argc > 1 ? argv[1] : "";
  auto window = havstest::MakeWindow(16, 16);
  window->Render();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!havstest::Check(gl != nullptr, "an OpenGL render window"))
  {
    return havstest::Result();
  }
  gl->MakeCurrent();
  vtkNew<vtkHAVSGLTableBuilder> builder;
  const double bound = 5e-6;

  if (only.empty() || only == "tables")
  {
    double unit[2] = { 0.0, 1.0 };
    struct Case
    {
      std::string Name;
      vtkSmartPointer<vtkVolumeProperty> Property;
      int NS, NL;
      double MaxLength;
      bool Logarithmic;
    };
    auto ramp = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.25);
    auto benchmark = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.25);
    benchmark->GetScalarOpacity()->AddPoint(0.3, 0.1);
    // A narrow peak between the fine samples of a 96-scalar table.
    auto peak = havstest::MakeRampProperty(0.0, 1.0, 0.0, 0.1);
    peak->GetScalarOpacity()->RemoveAllPoints();
    peak->GetScalarOpacity()->AddPoint(0.0, 0.0);
    peak->GetScalarOpacity()->AddPoint(0.4123, 0.0);
    peak->GetScalarOpacity()->AddPoint(0.4141, 1.0);
    peak->GetScalarOpacity()->AddPoint(0.4159, 0.0);
    peak->GetScalarOpacity()->AddPoint(1.0, 0.0);
    vtkNew<vtkPiecewiseFunction> grey;
    grey->AddPoint(0.0, 0.2);
    grey->AddPoint(0.6, 1.0);
    grey->AddPoint(1.0, 0.5);
    auto greyProperty = havstest::MakeRampProperty(0.0, 1.0, 0.6, 0.5);
    greyProperty->SetColor(grey);
    // Thick: the longest segment spans hundreds of optical lengths.
    auto thick = havstest::MakeRampProperty(0.0, 1.0, 1.0, 0.002);
    const Case cases[] = { { "ramp 64^3", ramp, 64, 64, 1.0, false },
      { "benchmark's function 128 x 64", benchmark, 128, 64, 0.7, false },
      { "narrow peak 96 x 32", peak, 96, 32, 1.0, false },
      { "grey function 64 x 16", greyProperty, 64, 16, 1.0, false },
      { "thick, logarithmic lengths 64 x 48", thick, 64, 48, 3.0, true },
      { "smallest 2 x 2", ramp, 2, 2, 1.0, false } };
    for (const Case& c : cases)
    {
      std::printf("%s:\n", c.Name.c_str());
      bool logarithmic = false;
      const double d = CompareBuilds(
        gl, builder, c.Property, c.Property, c.NS, c.NL, c.MaxLength, unit, &logarithmic);
      std::printf("    largest difference GPU - CPU %.3g (bound %g)\n", d, bound);
      havstest::Check(d >= 0.0, c.Name + ": built on the GPU");
      havstest::Check(d >= 0.0 && d <= bound, c.Name + ": the GPU's entries equal the CPU's");
      havstest::Check(logarithmic == c.Logarithmic, c.Name + ": the length axis as meant");
    }
    // Control: the ramp's middle opacity node (0.3) moved by 1 % of the range.
    auto moved = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.25);
    moved->GetScalarOpacity()->RemovePoint(0.3);
    moved->GetScalarOpacity()->AddPoint(0.31, 0.24);
    std::printf("control, the ramp's middle opacity node moved by 1 %% of the range:\n");
    const double control = CompareBuilds(gl, builder, ramp, moved, 64, 64, 1.0, unit);
    std::printf("    largest difference %.3g (must exceed %g)\n", control, bound);
    havstest::Check(control > bound, "control: a moved node misses the bound");
  }
  builder->ReleaseGraphicsResources(window);

  if (only.empty() || only == "mappers")
  {
    for (const char* name : { "havs", "raycast", "cellprojection" })
    {
      MapperCase(name);
    }
  }
  return havstest::Result();
}
