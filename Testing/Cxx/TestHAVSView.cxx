/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSView.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_view, the interactive viewer (issue 23), driven by scripted input
// under Xvfb: Testing/View/havs_view_session.txt turns the mesh with the
// trackball, edits the opacity function with the mouse on the editor,
// switches the mapper (HAVS cell projection, then round to HAVS) and k, and
// takes screenshots (overlay hidden). Each screenshot is checked against the
// exact reference rendered from the state file the viewer writes beside it
// (camera, transfer functions, size): the 8-bit window colour within
// quantization. The interactive budget is 1 ms, so the rotation's frames draw
// a level of detail (counted by the viewer), the still frames every face.
//
// Negative controls, each of which must fail the same bound: the last
// screenshot against the reference with the first screenshot's transfer
// function (the mouse edit reached the image), and with the first
// screenshot's camera (the rotation did); the state says which mapper drew.
//
// Arguments: the havs_view executable, the session script, the data set.
#include "havsTestChecks.h"
#include "havsTestImages.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSReferenceRenderer.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"
#if HAVS_TEST_HAS_EXODUS
#include "vtkExodusIIWriter.h"
#endif

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
/// The viewer's state file: a keyword, then numbers (or a name) per line.
struct ViewState
{
  std::map<std::string, std::vector<double>> Numbers;
  std::string DataSet;
  std::string Mapper;
  bool Read(const std::string& path)
  {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line))
    {
      std::istringstream words(line);
      std::string key;
      words >> key;
      if (key == "dataset")
      {
        words >> this->DataSet;
        continue;
      }
      if (key == "mapper")
      {
        double kind;
        words >> kind;
        std::getline(words, this->Mapper);
        this->Numbers[key] = { kind };
        continue;
      }
      std::vector<double> values;
      for (double v; words >> v;)
      {
        values.push_back(v);
      }
      this->Numbers[key] = values;
    }
    return !this->DataSet.empty() && this->Numbers.count("size") &&
      this->Numbers.count("opacity") && this->Numbers.count("color") &&
      this->Numbers.count("camera_position");
  }
  const std::vector<double>& Get(const std::string& key) const
  {
    static const std::vector<double> none(16, 0.0);
    auto it = this->Numbers.find(key);
    return it == this->Numbers.end() ? none : it->second;
  }
};

vtkSmartPointer<vtkVolumeProperty> PropertyOf(const ViewState& state)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  const auto& o = state.Get("opacity");
  for (size_t i = 0; i < static_cast<size_t>(o[0]); ++i)
  {
    opacity->AddPoint(o[1 + 4 * i], o[2 + 4 * i], o[3 + 4 * i], o[4 + 4 * i]);
  }
  vtkNew<vtkColorTransferFunction> color;
  const auto& c = state.Get("color");
  for (size_t i = 0; i < static_cast<size_t>(c[0]); ++i)
  {
    color->AddRGBPoint(
      c[1 + 6 * i], c[2 + 6 * i], c[3 + 6 * i], c[4 + 6 * i], c[5 + 6 * i], c[6 + 6 * i]);
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(state.Get("unit_distance")[0]);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  return property;
}

void PlaceCamera(vtkCamera* camera, const ViewState& state)
{
  const auto& p = state.Get("camera_position");
  const auto& f = state.Get("camera_focal_point");
  const auto& u = state.Get("camera_view_up");
  const auto& parallel = state.Get("camera_parallel");
  const auto& range = state.Get("camera_clipping_range");
  camera->SetPosition(p[0], p[1], p[2]);
  camera->SetFocalPoint(f[0], f[1], f[2]);
  camera->SetViewUp(u[0], u[1], u[2]);
  camera->SetViewAngle(state.Get("camera_view_angle")[0]);
  camera->SetParallelProjection(parallel[0] != 0.0);
  camera->SetParallelScale(parallel[1]);
  camera->SetClippingRange(range[0], range[1]);
}

/// The exact reference's RGB (alpha zeroed: the screenshot is RGB over black).
std::vector<float> Reference(vtkUnstructuredGrid* grid, const ViewState& cameraState,
  const ViewState& functionState, int width, int height)
{
  vtkNew<vtkCamera> camera;
  PlaceCamera(camera, cameraState);
  auto property = PropertyOf(functionState);
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(width, height);
  const double start = vtkTimerLog::GetUniversalTime();
  if (!reference->Render())
  {
    return {};
  }
  std::printf("exact reference: %.1f s\n", vtkTimerLog::GetUniversalTime() - start);
  const float* rgba = reference->GetImage()->GetPointer(0);
  std::vector<float> image(rgba, rgba + 4 * width * height);
  for (size_t p = 0; p < image.size() / 4; ++p)
  {
    image[4 * p + 3] = 0.0f;
  }
  return image;
}

std::vector<float> Screenshot(const std::string& path, int& width, int& height)
{
  std::vector<float> image = havstest::ReadPNG(path, &width, &height);
  for (size_t p = 0; p < image.size() / 4; ++p)
  {
    image[4 * p + 3] = 0.0f;
  }
  return image;
}

/// Runs havs_view in `dir` with `arguments`, its output into `log`; the exit status.
int RunViewer(
  const std::string& viewer, const std::string& dir, const std::string& arguments, std::string& log)
{
  const std::string command = "mkdir -p '" + dir + "' && cd '" + dir + "' && '" + viewer + "' " +
    arguments + " > session.log 2>&1";
  std::printf("running: %s\n", command.c_str());
  std::fflush(stdout);
  const double start = vtkTimerLog::GetUniversalTime();
  const int status = std::system(command.c_str());
  std::printf("havs_view: %.1f s\n", vtkTimerLog::GetUniversalTime() - start);
  std::ifstream in(dir + "/session.log");
  std::ostringstream text;
  text << in.rdbuf();
  log = text.str();
  std::printf("--- havs_view's output ---\n%s--- end ---\n", log.c_str());
  return status;
}

void Print(const std::string& what, const havstest::ImageDifference& d)
{
  std::printf("%-58s RMSE %.6f  max %.4f  pixels > 1/255 %.2f %%\n", what.c_str(), d.RMSE, d.Max,
    100.0 * d.FractionOver1);
}
}

int TestHAVSView(int argc, char* argv[])
{
  if (!havstest::Check(argc >= 4, "arguments: havs_view, the session script, the data set"))
  {
    return EXIT_FAILURE;
  }
  const std::string viewer = argv[1];
  const std::string script = argv[2];
  const std::string dataSet = argv[3];
  const std::string dir = havstest::OutputDir() + "/havs_view";
  std::remove((dir + "/view0.png").c_str());
  std::remove((dir + "/view1.png").c_str());
  std::remove((dir + "/view2.png").c_str());
  std::string log;
  const int status = RunViewer(
    viewer, dir, "--size 192x144 --interactive 0.001 --play '" + script + "' " + dataSet, log);
  if (!havstest::Check(status == 0, "havs_view ran the session and exited with 0"))
  {
    return EXIT_FAILURE;
  }
  // The drag's frames are interactive: with a 1 ms budget HAVS draws a level
  // of detail while the mouse moves; the screenshots (still frames, after the
  // release) are checked below to be the full, exact image.
  int frames = 0, lodFrames = 0;
  const size_t at = log.find("havs_view: ");
  const size_t summary = log.find(" frames, ");
  havstest::Check(at != std::string::npos && summary != std::string::npos &&
      std::sscanf(log.c_str() + log.rfind("havs_view: ", summary), "havs_view: %d frames, %d with",
        &frames, &lodFrames) == 2,
    "the session's frame summary is printed");
  std::printf("frames %d, with a level of detail %d\n", frames, lodFrames);
  havstest::Check(lodFrames > 0 && lodFrames < frames,
    "the rotation's frames drew a level of detail, the others every face");

  ViewState states[3];
  for (int i = 0; i < 3; ++i)
  {
    const std::string state = dir + "/view" + std::to_string(i) + ".png.txt";
    if (!havstest::Check(states[i].Read(state), "state file " + state))
    {
      return EXIT_FAILURE;
    }
  }
  havstest::Check(
    states[0].Mapper.find("HAVS") != std::string::npos && states[0].Get("mapper")[0] == 0.0,
    "view0 drawn by HAVS (state: " + states[0].Mapper + ")");
  havstest::Check(states[1].Get("mapper")[0] == 1.0,
    "view1 drawn by the HAVS cell projection after one `m` (state:" + states[1].Mapper + ")");
  havstest::Check(states[2].Get("mapper")[0] == 0.0,
    "view2 drawn by HAVS again after five more `m` (state:" + states[2].Mapper + ")");
  havstest::Check(states[2].Get("opacity")[0] == states[0].Get("opacity")[0] + 1,
    "the editor added one opacity node");

  auto grid = vtkHAVSDataSets::Load(states[0].DataSet);
  if (!havstest::Check(grid != nullptr, "data set " + states[0].DataSet))
  {
    return EXIT_FAILURE;
  }
  // 8-bit colour: quantization alone gives RMSE about 0.001 on covered pixels;
  // the worst 0.05 % of pixels (silhouette edges) are left out of the max.
  const double rmseBound = 0.004;
  const double maxBound = 0.03;
  int width = 0, height = 0;
  std::vector<float> shots[3];
  for (int i = 0; i < 3; ++i)
  {
    const std::string name = "view" + std::to_string(i);
    shots[i] = Screenshot(dir + "/" + name + ".png", width, height);
    const auto& size = states[i].Get("size");
    if (!havstest::Check(!shots[i].empty() && width == size[0] && height == size[1],
          name + ".png read, of the state's size"))
    {
      return EXIT_FAILURE;
    }
    const auto exact = Reference(grid, states[i], states[i], width, height);
    const size_t edge = static_cast<size_t>(0.0005 * width * height);
    const auto d = havstest::Compare(shots[i], exact, edge);
    Print(name + " (" + states[i].Mapper + " ) vs the exact reference", d);
    havstest::Check(d.RMSE < rmseBound && d.Max < maxBound,
      name + ": the screenshot is the exact image (overlay hidden)");
  }

  // Controls: the edit and the rotation each changed the image.
  const size_t edge = static_cast<size_t>(0.0005 * width * height);
  const auto oldFunctions = Reference(grid, states[2], states[0], width, height);
  const auto oldCamera = Reference(grid, states[0], states[2], width, height);
  const auto c1 = havstest::Compare(shots[2], oldFunctions, edge);
  const auto c2 = havstest::Compare(shots[2], oldCamera, edge);
  Print("control: view2 vs the reference with view0's functions", c1);
  Print("control: view2 vs the reference with view0's camera", c2);
  havstest::Check(!(c1.RMSE < rmseBound && c1.Max < maxBound),
    "control: the transfer-function edit changed the image (fails the bound)");
  havstest::Check(!(c2.RMSE < rmseBound && c2.Max < maxBound),
    "control: the rotation changed the image (fails the bound)");

#if HAVS_TEST_HAS_EXODUS
  // An Exodus II file (a 6^3 box, point scalars, one element block) opened
  // by havs_view: the screenshot is the exact image of the grid written.
  auto box = vtkHAVSDataSets::MakeBox(6, 6, 6, 1.0 / 6.0, 0.0, 1.0);
  vtkNew<vtkIntArray> block;
  block->SetName("ObjectId");
  block->SetNumberOfTuples(box->GetNumberOfCells());
  block->Fill(1);
  box->GetCellData()->AddArray(block);
  const std::string exodusDir = dir + "/exodus";
  std::system(("mkdir -p '" + exodusDir + "'").c_str());
  vtkNew<vtkExodusIIWriter> writer;
  writer->SetFileName((exodusDir + "/box.exo").c_str());
  writer->SetInputData(box);
  writer->WriteAllTimeStepsOff();
  writer->Write();
  {
    std::ofstream play(exodusDir + "/play.txt");
    play << "screenshot box.png\nquit\n";
  }
  const int exodusStatus =
    RunViewer(viewer, exodusDir, "--size 96x72 --play play.txt box.exo", log);
  ViewState exodusState;
  if (havstest::Check(exodusStatus == 0 && exodusState.Read(exodusDir + "/box.png.txt"),
        "havs_view opened the Exodus file and took its screenshot"))
  {
    int w = 0, h = 0;
    const auto shot = Screenshot(exodusDir + "/box.png", w, h);
    const auto exact = Reference(box, exodusState, exodusState, w, h);
    const auto d = havstest::Compare(shot, exact, static_cast<size_t>(0.0005 * w * h));
    Print("Exodus box.exo vs the exact reference of the grid written", d);
    havstest::Check(!shot.empty() && d.RMSE < rmseBound && d.Max < maxBound,
      "the Exodus file's screenshot is the exact image of the grid written");
  }
#else
  std::printf("Exodus: not checked (this VTK has no IOExodus module)\n");
#endif
  return havstest::Result();
}
