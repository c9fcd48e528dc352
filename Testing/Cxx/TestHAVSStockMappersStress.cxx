/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSStockMappersStress.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// The stock mappers beside HAVS (issue 20: "reported, not asserted"): each
// stress scene below rendered by HAVS, vtkProjectedTetrahedraMapper,
// vtkUnstructuredGridVolumeZSweepMapper and
// vtkUnstructuredGridVolumeRayCastMapper (linear integrator, every pixel), each
// in a process of its own (this driver again, `one`), so that a mapper
// that crashes or hangs is reported as such. Every mapper's window colour
// (8-bit, over black) against the exact reference's colour.
// HAVS's rows are asserted exact (8-bit window colour: RMSE < 0.004, max
// < 0.03); control: a child that aborts is reported as crashed.
//
// Usage: TestHAVSStockMappersStress [one <scene> <mapper>]   (one: the child process)
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"
#include "havsTestStress.h"

#include "vtkCamera.h"
#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

using namespace havstest::stress;

namespace
{
/// A stress scene: its name, its window's size, how its grid, property and camera are made.
struct StockScene
{
  const char* Name;
  int Width;
  int Height;
  std::function<void(
    vtkSmartPointer<vtkUnstructuredGrid>&, vtkSmartPointer<vtkVolumeProperty>&, vtkCamera*)>
    Make;
};

std::vector<StockScene> StockScenes()
{
  auto sphere = [](vtkSmartPointer<vtkUnstructuredGrid>& grid,
                  vtkSmartPointer<vtkVolumeProperty>& property, double factor, double offset)
  {
    auto base = vtkHAVSDataSets::Load("hollowsphere");
    property = havstest::MakeRampPropertyFor(base);
    property->SetScalarOpacityUnitDistance(property->GetScalarOpacityUnitDistance() * factor);
    grid = Moved(
      base, [=](double x) { return x * factor + offset; }, true);
  };
  auto scalars = [](vtkSmartPointer<vtkUnstructuredGrid>& grid,
                   vtkSmartPointer<vtkVolumeProperty>& property,
                   const std::function<double(vtkIdType, double)>& f, double scale)
  {
    auto base = vtkHAVSDataSets::Load("hollowsphere");
    double range[2];
    base->GetPointData()->GetScalars()->GetRange(range);
    grid = WithScalars(base,
      [&](vtkIdType i, double v) { return f(i, (v - range[0]) / (range[1] - range[0])) * scale; });
    property = havstest::MakeRampProperty(0.0, scale, 0.8, grid->GetLength() / 8.0);
  };
  auto view = [](vtkCamera* camera, vtkUnstructuredGrid* grid, double azimuth, double elevation)
  {
    vtkNew<vtkRenderer> r;
    r->SetActiveCamera(camera);
    r->ResetCamera(grid->GetBounds());
    camera->Azimuth(azimuth);
    camera->Elevation(elevation);
    camera->OrthogonalizeViewUp();
    r->ResetCamera(grid->GetBounds());
  };
  std::vector<StockScene> scenes;
  scenes.push_back({ "hollow sphere (as is)", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1.0, 0.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "coordinates x 1e-8", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1e-8, 0.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "coordinates x 1e8", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1e8, 0.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "moved by 1e9 (double points)", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1.0, 1e9);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "NaN at a tenth of the scalars", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType i, double v) { return i % 10 == 3 ? std::nan("") : v; }, 1.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "+Inf at a tenth of the scalars", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType i, double v) { return i % 10 == 3 ? HUGE_VAL : v; }, 1.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "scalars x 1e30", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1e30);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "opacity spike narrower than a table bin", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1.0);
      vtkPiecewiseFunction* o = p->GetScalarOpacity();
      o->RemoveAllPoints();
      o->AddPoint(0.0, 0.0);
      o->AddPoint(0.499, 0.0);
      o->AddPoint(0.5, 1.0);
      o->AddPoint(0.501, 0.0);
      o->AddPoint(1.0, 0.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "fully opaque", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1.0);
      p->GetScalarOpacity()->RemoveAllPoints();
      p->GetScalarOpacity()->AddPoint(0.0, 1.0);
      p->GetScalarOpacity()->AddPoint(1.0, 1.0);
      p->SetScalarOpacityUnitDistance(g->GetLength() * 1e-3);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "box, orthographic exactly along -x", 65, 65,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      g = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
      p = havstest::MakeRampPropertyFor(g);
      c->SetParallelProjection(1);
      c->SetPosition(5.0, 0.5, 0.5);
      c->SetFocalPoint(0.5, 0.5, 0.5);
      c->SetViewUp(0, 0, 1);
      c->SetParallelScale(0.5 * 65 * 0.025);
      c->SetClippingRange(1.0, 10.0);
    } });
  scenes.push_back({ "mesh 1e6 x longer than wide, along its axis", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      g = MakeElongated(1e6);
      p = havstest::MakeRampProperty(0.0, 1.0, 0.8, 1e6);
      c->SetParallelProjection(1);
      c->SetPosition(-10.0, 1.5, 1.5);
      c->SetFocalPoint(3e6, 1.5, 1.5);
      c->SetViewUp(0, 0, 1);
      c->SetParallelScale(2.0);
      c->SetClippingRange(0.5, 3.1e6 + 20.0);
    } });
  scenes.push_back({ "-Inf at a tenth of the scalars", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType i, double v) { return i % 10 == 3 ? -HUGE_VAL : v; }, 1.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "denormal scalars (x 1e-310)", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1e-310);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "cell scalars", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1.0);
      g = CellScalarCopy(g);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "cell scalars, opacity spike at a cell's value", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1.0);
      g = CellScalarCopy(g);
      const double at = g->GetCellData()->GetScalars()->GetTuple1(g->GetNumberOfCells() / 2);
      vtkPiecewiseFunction* o = p->GetScalarOpacity();
      o->RemoveAllPoints();
      o->AddPoint(0.0, 0.0);
      o->AddPoint(at - 0.001, 0.0);
      o->AddPoint(at, 1.0);
      o->AddPoint(at + 0.001, 0.0);
      o->AddPoint(1.0, 0.0);
      view(c, g, 30, 20);
    } });
  auto box = [](vtkSmartPointer<vtkUnstructuredGrid>& g, vtkSmartPointer<vtkVolumeProperty>& p)
  {
    g = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
    p = havstest::MakeRampPropertyFor(g);
  };
  scenes.push_back({ "box, every other cell inverted", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      box(g, p);
      g = Cells(
        g, [](vtkIdType) { return true; },
        [](vtkIdType cell, vtkIdType* ids)
        {
          if (cell % 2)
          {
            std::swap(ids[0], ids[1]);
          }
        });
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "box, duplicate and zero-volume cells", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      box(g, p);
      auto base = g;
      g = Cells(
        base, [](vtkIdType) { return true; }, [](vtkIdType, vtkIdType*) {});
      for (vtkIdType cell = 0; cell < base->GetNumberOfCells(); cell += 7)
      {
        g->InsertNextCell(VTK_TETRA, base->GetCell(cell)->GetPointIds());
      }
      // A flat cell: the first cell's points with one repeated.
      vtkIdList* first = base->GetCell(0)->GetPointIds();
      const vtkIdType repeated[4] = { first->GetId(0), first->GetId(1), first->GetId(2),
        first->GetId(2) };
      g->InsertNextCell(VTK_TETRA, 4, repeated);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "sliver tetrahedron", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      g =
        MakeTets({ { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0.01 }, { 0, 1, 0.01 } }, { { 0, 1, 2, 3 } });
      double range[2];
      g->GetPointData()->GetScalars()->GetRange(range);
      p = havstest::MakeRampProperty(range[0] - 0.1, range[1] + 0.1, 0.9, 0.5);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "1 x 1 window", 1, 1,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1.0, 0.0);
      view(c, g, 30, 20);
      double f[3], e[3];
      c->GetFocalPoint(f);
      c->GetPosition(e);
      const double d = 0.017 * g->GetLength();
      c->SetFocalPoint(f[0] + d, f[1] + d, f[2]);
      c->SetPosition(e[0] + d, e[1] + d, e[2]);
    } });
  return scenes;
}

const char* const StockMapperNames[] = { "HAVS", "PT", "ZSweep", "RayCast" };

/// One scene, one mapper (the child process): prints one STOCK line.
int StockOne(int scene, const std::string& mapperName)
{
  if (scene < 0)
  {
    std::abort(); // the harness' control: a mapper that crashes
  }
  const auto scenes = StockScenes();
  if (!havstest::Check(scene < static_cast<int>(scenes.size()), "a known stock scene"))
  {
    return havstest::Result();
  }
  const StockScene& sc = scenes[scene];
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  vtkSmartPointer<vtkVolumeProperty> property;
  vtkNew<vtkCamera> camera;
  sc.Make(grid, property, camera);
  vtkSmartPointer<vtkAbstractVolumeMapper> mapper;
  if (mapperName == "PT")
  {
    mapper = vtkSmartPointer<vtkProjectedTetrahedraMapper>::New();
  }
  else if (mapperName == "ZSweep")
  {
    mapper = vtkSmartPointer<vtkUnstructuredGridVolumeZSweepMapper>::New();
  }
  else if (mapperName == "RayCast")
  {
    auto ray = vtkSmartPointer<vtkUnstructuredGridVolumeRayCastMapper>::New();
    ray->SetImageSampleDistance(1.0);
    ray->AutoAdjustSampleDistancesOff();
    vtkNew<vtkUnstructuredGridLinearRayIntegrator> integrator;
    ray->SetRayIntegrator(integrator);
    mapper = ray;
  }
  else
  {
    auto havs = vtkSmartPointer<vtkHAVSVolumeMapper>::New();
    ConfigureOrder(havs);
    mapper = havs;
  }
  havstest::Messages* messages = havstest::CountMessages(mapper);
  auto s = havstest::MakeScene(grid, mapper, property, sc.Width, sc.Height);
  s.Renderer->GetActiveCamera()->DeepCopy(camera);
  const double start = vtkTimerLog::GetUniversalTime();
  s.Window->Render();
  const double seconds = vtkTimerLog::GetUniversalTime() - start;
  std::vector<float> image = havstest::ReadRGBA(s.Window);
  std::vector<float> exact = ReferenceImage(grid, property, camera, sc.Width, sc.Height);
  // Colour over black: the window's alpha means nothing here.
  for (size_t i = 3; i < image.size() && image.size() == exact.size(); i += 4)
  {
    image[i] = exact[i] = 0.0f;
  }
  const size_t edge = static_cast<size_t>(sc.Width) * sc.Height / 2000;
  const auto d = havstest::Compare(image, exact, edge);
  std::printf(
    "STOCK %.6g %.6g %.4f %d %d\n", d.RMSE, d.Max, seconds, messages->Errors, messages->Warnings);
  return EXIT_SUCCESS;
}

/// The table of every scene through every mapper, each in its own process.
int Table()
{
  char self[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", self, sizeof(self) - 1);
  if (!havstest::Check(n > 0, "this driver's path"))
  {
    return havstest::Result();
  }
  struct Outcome
  {
    std::string Text;
    bool Ran = false;
    double RMSE = 0.0;
    double Max = 0.0;
  };
  auto run = [&](int scene, const std::string& mapper)
  {
    const std::string command = std::string("timeout 300 '") + self +
      "' TestHAVSStockMappersStress one " + std::to_string(scene) + " " + mapper + " 2>&1";
    Outcome out;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe)
    {
      out.Text = "not started";
      return out;
    }
    char line[1024];
    double rmse = 0, max = 0, seconds = 0;
    int errors = 0, warnings = 0;
    bool found = false;
    while (std::fgets(line, sizeof(line), pipe))
    {
      found = found ||
        std::sscanf(line, "STOCK %lf %lf %lf %d %d", &rmse, &max, &seconds, &errors, &warnings) ==
          5;
    }
    const int status = pclose(pipe);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    char text[160];
    if (code == 124)
    {
      std::snprintf(text, sizeof(text), "hung (killed after 300 s)");
    }
    else if (code > 128 || code < 0)
    {
      std::snprintf(text, sizeof(text), "crashed (signal %d)", code > 128 ? code - 128 : -1);
    }
    else if (!found)
    {
      std::snprintf(text, sizeof(text), "no result (exit %d)", code);
    }
    else
    {
      out.Ran = true;
      out.RMSE = rmse;
      out.Max = max;
      std::snprintf(text, sizeof(text), "RMSE %.4f max %.3f, %.2f s%s%s", rmse, max, seconds,
        errors ? ", errors" : "", warnings ? ", warnings" : "");
    }
    out.Text = text;
    return out;
  };

  // The harness' control: a child that aborts is reported as crashed.
  const Outcome crash = run(-1, "HAVS");
  std::printf("control, a child that aborts: %s\n", crash.Text.c_str());
  havstest::Check(!crash.Ran && crash.Text.rfind("crashed", 0) == 0,
    "control: a crashing child is reported as crashed");

  const auto scenes = StockScenes();
  std::printf("\n| scene | %s | %s | %s | %s |\n|---|---|---|---|---|\n", StockMapperNames[0],
    StockMapperNames[1], StockMapperNames[2], StockMapperNames[3]);
  for (size_t i = 0; i < scenes.size(); ++i)
  {
    std::string row = std::string("| ") + scenes[i].Name;
    for (const char* mapper : StockMapperNames)
    {
      const Outcome o = run(static_cast<int>(i), mapper);
      row += " | " + o.Text;
      if (std::string(mapper) == "HAVS")
      {
        // HAVS through the window's 8-bit colour: within quantization.
        havstest::Check(o.Ran && o.RMSE < 0.004 && o.Max < 0.03,
          std::string(scenes[i].Name) + ": HAVS exact (8-bit window colour)");
      }
    }
    std::printf("%s |\n", row.c_str());
    std::fflush(stdout);
  }
  return havstest::Result();
}
}

int TestHAVSStockMappersStress(int argc, char* argv[])
{
  if (argc > 1 && std::string(argv[1]) == "one")
  {
    if (argc > 3)
    {
      return StockOne(std::atoi(argv[2]), argv[3]);
    }
    havstest::Check(false, "one <scene> <mapper>");
    return havstest::Result();
  }
  return Table();
}
