/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSHostileFiles.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Hostile files (issue 20): truncated, corrupt and absurd mesh files through
// vtkHAVSDataSets::ReadFile (what the apps read with) and havs_view. Each
// either is refused with a warning that names the file (nullptr, and the
// viewer exits with a message and status 1), or reads into a grid that the
// mapper renders with a defined result (warnings for what it skipped, no NaN,
// nothing drawn after an error). Nothing crashes: the viewer is run as a
// child process and must not die by a signal.
//
// Controls: the good file reads, renders something and matches the exact
// reference; the expected refusals are checked to be refusals (a reader that
// took a truncated file for a mesh fails the test).
//
// Argument: the havs_view executable (under Xvfb), or nothing to skip the
// viewer part.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const char* const kGoodVTK = "# vtk DataFile Version 3.0\n"
                             "two tetrahedra\n"
                             "ASCII\n"
                             "DATASET UNSTRUCTURED_GRID\n"
                             "POINTS 5 float\n"
                             "0 0 0 1 0 0 0 1 0 0 0 1 1 1 1\n"
                             "CELLS 2 10\n"
                             "4 0 1 2 3\n"
                             "4 1 2 3 4\n"
                             "CELL_TYPES 2\n"
                             "10 10\n"
                             "POINT_DATA 5\n"
                             "SCALARS s float 1\n"
                             "LOOKUP_TABLE default\n"
                             "0 0.25 0.5 0.75 1\n";

std::string Replace(std::string text, const std::string& from, const std::string& to)
{
  const size_t at = text.find(from);
  if (at != std::string::npos)
  {
    text.replace(at, from.size(), to);
  }
  return text;
}

void Write(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

std::string Read(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Counts the warnings and errors any VTK object prints while it lives.
class CaptureOutput : public vtkOutputWindow
{
public:
  static CaptureOutput* New() { return new CaptureOutput; }
  void DisplayText(const char* text) override { this->Text += text ? text : ""; }
  void DisplayErrorText(const char* text) override
  {
    ++this->Count;
    this->Text += text ? text : "";
  }
  void DisplayWarningText(const char* text) override
  {
    ++this->Count;
    this->Text += text ? text : "";
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  int Count = 0;
  std::string Text;
};

struct Case
{
  std::string Name;
  bool MustRead; ///< false: must be refused
};

/// Renders `grid` with the mapper's defaults at 48^2: a defined result.
void RenderDefined(vtkUnstructuredGrid* grid, const std::string& name)
{
  double range[2] = { 0.0, 1.0 };
  if (grid->GetPointData()->GetScalars())
  {
    grid->GetPointData()->GetScalars()->GetRange(range);
  }
  auto property = havstest::MakeRampProperty(range[0], range[1], 0.8, 0.5);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  havstest::Messages* messages = havstest::CountMessages(mapper);
  auto scene = havstest::MakeScene(grid, mapper, property, 48, 48);
  scene.Renderer->ResetCamera(0, 1, 0, 1, 0, 1);
  scene.Window->Render();
  const auto result = havstest::FloatResult(mapper);
  std::printf("  %s rendered: %d errors, %d warnings: %s\n", name.c_str(), messages->Errors,
    messages->Warnings, messages->Text.c_str());
  if (messages->Errors > 0)
  {
    havstest::Check(result.empty(), name + ": after the mapper's error no result is kept");
  }
  else
  {
    havstest::Check(
      !result.empty() && havstest::AllFinite(result), name + ": rendered, the float result finite");
  }
}
}

int TestHAVSHostileFiles(int argc, char* argv[])
{
  const std::string viewer = argc > 1 ? argv[1] : "";
  const std::string dir = havstest::OutputDir() + "/hostile";
  std::system(("mkdir -p '" + dir + "'").c_str());

  // --- The files ------------------------------------------------------------
  const std::string good = kGoodVTK;
  Write(dir + "/good.vtk", good);
  Write(dir + "/empty.vtk", "");
  Write(dir + "/truncated.vtk", good.substr(0, 150));
  Write(dir + "/header-only.vtk", good.substr(0, good.find("CELLS")));
  Write(dir + "/negative-count.vtk", Replace(good, "POINTS 5 float", "POINTS -5 float"));
  Write(dir + "/absurd-count.vtk", Replace(good, "CELLS 2 10", "CELLS 2000000000 10"));
  Write(dir + "/index-past-end.vtk", Replace(good, "4 1 2 3 4", "4 1 2 3 400000"));
  Write(dir + "/negative-index.vtk", Replace(good, "4 1 2 3 4", "4 1 2 -3 4"));
  Write(dir + "/nan-point-text.vtk", Replace(good, "1 1 1\n", "nan 1 1\n"));
  Write(dir + "/wrong-cell-type.vtk", Replace(good, "10 10\n", "10 200\n"));
  Write(dir + "/hexahedron-bad-index.vtk",
    Replace(Replace(Replace(good, "CELLS 2 10", "CELLS 2 14"), "4 1 2 3 4", "8 0 1 2 3 4 0 1 -9"),
      "10 10\n", "10 12\n"));
  std::string garbage(3000, '\0');
  for (size_t i = 0; i < garbage.size(); ++i)
  {
    garbage[i] = static_cast<char>((i * 2654435761u) >> 13);
  }
  Write(dir + "/garbage.vtu", garbage);
  Write(dir + "/garbage-after-header.vtu",
    "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
    "version=\"0.1\">\n" +
      garbage);
  // A good binary .vtu (NaN in a point), and its first half.
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName((dir + "/box.vtu").c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToBinary();
    writer->Write();
    const std::string bytes = Read(dir + "/box.vtu");
    Write(dir + "/truncated.vtu", bytes.substr(0, bytes.size() / 2));
    grid->GetPoints()->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
    writer->SetFileName((dir + "/nan-point.vtu").c_str());
    writer->Write();
  }

  const std::vector<Case> cases = {
    { "good.vtk", true },
    { "box.vtu", true },
    { "empty.vtk", false },
    { "truncated.vtk", false },
    { "header-only.vtk", false },
    { "negative-count.vtk", false },
    { "absurd-count.vtk", false },
    { "index-past-end.vtk", true },
    { "negative-index.vtk", true },
    { "nan-point-text.vtk", false },
    { "wrong-cell-type.vtk", true },
    { "hexahedron-bad-index.vtk", true },
    { "garbage.vtu", false },
    { "garbage-after-header.vtu", false },
    { "truncated.vtu", false },
    { "nan-point.vtu", true },
  };

  // --- ReadFile, then the mapper ------------------------------------------
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  for (const Case& c : cases)
  {
    vtkNew<CaptureOutput> capture;
    vtkOutputWindow::SetInstance(capture);
    vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::ReadFile(dir + "/" + c.Name);
    vtkOutputWindow::SetInstance(previous);
    std::printf("%s: %s (%d messages)\n", c.Name.c_str(),
      grid ? ("read, " + std::to_string(grid->GetNumberOfCells()) + " cells").c_str() : "refused",
      capture->Count);
    if (c.Name == "wrong-cell-type.vtk" || c.Name == "hexahedron-bad-index.vtk")
    {
      havstest::Check(capture->Count > 0 && capture->Text.find(c.Name) != std::string::npos,
        c.Name + ": a warning naming the file says what was left out (" + capture->Text + ")");
    }
    if (c.MustRead)
    {
      if (havstest::Check(grid != nullptr, c.Name + ": read (the mapper decides what to skip)"))
      {
        RenderDefined(grid, c.Name);
      }
    }
    else
    {
      havstest::Check(
        grid == nullptr && capture->Count > 0 && capture->Text.find(c.Name) != std::string::npos,
        c.Name + ": refused with a warning naming the file");
    }
  }

  // Control: the good file is the exact image of its two tetrahedra.
  {
    auto grid = vtkHAVSDataSets::ReadFile(dir + "/good.vtk");
    auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.5);
    vtkNew<vtkHAVSVolumeMapper> mapper;
    mapper->KeepFloatResultOn();
    auto scene = havstest::MakeScene(grid, mapper, property, 48, 48);
    havstest::PlaceCamera(scene.Renderer, 30.0, 20.0, false);
    scene.Window->Render();
    vtkNew<vtkHAVSReferenceRenderer> reference;
    reference->SetInputData(grid);
    reference->SetProperty(property);
    reference->SetCamera(scene.Renderer->GetActiveCamera());
    reference->SetSize(48, 48);
    reference->Render();
    const float* exact = reference->GetImage()->GetPointer(0);
    const auto d = havstest::Compare(
      havstest::FloatResult(mapper), std::vector<float>(exact, exact + 4 * 48 * 48), 2);
    std::printf("good.vtk vs the exact reference: RMSE %.6f max %.6f\n", d.RMSE, d.Max);
    havstest::Check(d.RMSE < 1e-3, "control: the good file renders the exact image");
  }

  // --- havs_view on every file: a message and status 1, or a screenshot ---
  if (viewer.empty())
  {
    std::printf("havs_view: not given, its part not run\n");
    return havstest::Result();
  }
  Write(dir + "/play.txt", "screenshot shot.png\nquit\n");
  for (const Case& c : cases)
  {
    std::remove((dir + "/shot.png").c_str());
    const std::string command = "cd '" + dir + "' && '" + viewer +
      "' --size 48x48 --play play.txt '" + c.Name + "' > viewer.log 2>&1";
    const int status = std::system(command.c_str());
    const std::string log = Read(dir + "/viewer.log");
    const bool signalled =
      status == -1 || (WIFEXITED(status) == 0) || (WIFEXITED(status) && WEXITSTATUS(status) > 125);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::printf("havs_view %s: exit %d%s\n", c.Name.c_str(), code, signalled ? " (signal)" : "");
    havstest::Check(!signalled, "havs_view " + c.Name + ": no crash");
    if (c.MustRead)
    {
      havstest::Check(code == 0 && !Read(dir + "/shot.png").empty(),
        "havs_view " + c.Name + ": opened, a screenshot taken");
    }
    else
    {
      havstest::Check(code == 1 && log.find("havs_view: ") != std::string::npos &&
          log.find(c.Name) != std::string::npos,
        "havs_view " + c.Name + ": a message naming the file, status 1 (" +
          log.substr(0, std::min<size_t>(log.size(), 300)) + ")");
    }
  }
  return havstest::Result();
}
