/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSLargeMesh.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// A large mesh within memory (issue 20; `long` label): gen10M (a block of
// 127^3 cubes, 10.2M tetrahedra) rendered with the mapper's defaults at
// 256^2. Reported: the process' peak resident memory (VmHWM) after the grid
// was made and after the first frame, and the mapper's share per tetrahedron
// against the thesis' claim that HAVS keeps close to no data beyond the mesh
// (faces, order, GPU copies). Checked: no error, progress reported during the
// preparation (ProgressEvent from 0 to 1, several steps), a finite image
// with something drawn, and the peak under half of the machine's memory.
//
// Arguments: data set (gen10M), size.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
struct Progress
{
  std::vector<double> Values;
};
}

int TestHAVSLargeMesh(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "gen10M";
  const int size = argc > 2 ? std::atoi(argv[2]) : 256;
  const double t0 = vtkTimerLog::GetUniversalTime();
  auto grid = vtkHAVSDataSets::Load(name);
  if (!havstest::Check(grid != nullptr, "the mesh " + name))
  {
    return EXIT_FAILURE;
  }
  const double tets = static_cast<double>(grid->GetNumberOfCells());
  const long long rssGrid = havstest::ProcessStatusBytes("VmRSS");
  std::printf("%s: %.0f tetrahedra, %lld points, made in %.1f s; VmRSS %.0f MB (the grid: %.0f "
              "bytes a tetrahedron in VTK's arrays)\n",
    name.c_str(), tets, static_cast<long long>(grid->GetNumberOfPoints()),
    vtkTimerLog::GetUniversalTime() - t0, rssGrid / 1048576.0,
    grid->GetActualMemorySize() * 1024.0 / tets);

  auto property = havstest::MakeRampPropertyFor(grid);
  vtkNew<vtkHAVSVolumeMapper> mapper; // the defaults
  mapper->KeepFloatResultOn();
  havstest::Messages* messages = havstest::CountMessages(mapper);
  Progress progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* client, void* call)
    { static_cast<Progress*>(client)->Values.push_back(*static_cast<double*>(call)); });
  mapper->AddObserver(vtkCommand::ProgressEvent, onProgress);
  auto scene = havstest::MakeScene(grid, mapper, property, size, size);
  havstest::PlaceCamera(scene.Renderer, 30.0, 20.0, false);
  const double t1 = vtkTimerLog::GetUniversalTime();
  scene.Window->Render();
  const double first = vtkTimerLog::GetUniversalTime() - t1;
  const double t2 = vtkTimerLog::GetUniversalTime();
  havstest::PlaceCamera(scene.Renderer, 60.0, 10.0, false);
  scene.Window->Render();
  const double second = vtkTimerLog::GetUniversalTime() - t2;
  const long long peak = havstest::ProcessStatusBytes("VmHWM");
  const long long rssAfter = havstest::ProcessStatusBytes("VmRSS");
  const double machine = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
  std::printf("first frame %.1f s (preparation included), second frame %.1f s (vtkSMPTools %s)\n",
    first, second,
    std::getenv("VTK_SMP_BACKEND_IN_USE") ? std::getenv("VTK_SMP_BACKEND_IN_USE") : "Sequential");
  std::printf("peak VmHWM %.0f MB, VmRSS after %.0f MB; beyond the grid: peak %.0f bytes a "
              "tetrahedron, kept %.0f bytes a tetrahedron (machine: %.0f GB)\n",
    peak / 1048576.0, rssAfter / 1048576.0, (peak - rssGrid) / tets, (rssAfter - rssGrid) / tets,
    machine / 1073741824.0);
  std::printf("progress events during the preparation: %zu (first %.3f, last %.3f)\n",
    progress.Values.size(), progress.Values.empty() ? -1.0 : progress.Values.front(),
    progress.Values.empty() ? -1.0 : progress.Values.back());

  havstest::Check(messages->Errors == 0, "no error (" + messages->Text + ")");
  havstest::Check(progress.Values.size() >= 5 && progress.Values.front() <= 0.01 &&
      progress.Values.back() >= 0.99,
    "progress is reported during the preparation, from 0 to 1");
  const auto result = havstest::FloatResult(mapper);
  double covered = 0.0;
  for (size_t p = 3; p < result.size(); p += 4)
  {
    covered += result[p] > 0.01f ? 1.0 : 0.0;
  }
  havstest::Check(!result.empty() && havstest::AllFinite(result) && covered > 0.1 * size * size,
    "a finite image with the mesh drawn (" + std::to_string(covered) + " pixels)");
  havstest::Check(
    peak > 0 && peak < 0.5 * machine, "the peak stays under half of the machine's memory");
  return havstest::Result();
}
