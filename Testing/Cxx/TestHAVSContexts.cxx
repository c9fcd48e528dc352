/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSContexts.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// The table of contexts (issue 23): vtkHAVSRenderWindowFactory says which
// backends this build has and which can be made here; every one that can
// renders the same small scene with the HAVS mapper at its default settings,
// checked against the exact reference. Run under Xvfb (CMake does), so that
// `display` is usable too.
//
// Checked: the table is consistent (usable => built, the status sentence
// says which); egl and display are usable here, osmesa wherever it is built;
// each usable backend's window is of that backend and its image matches the
// reference (RMSE < 1e-3, no warning); the windows, all alive, render the
// same again when used in turn on one thread (OSMesa, GLX and EGL share
// GLVND's one current context per thread).
//
// Negative controls: a backend asked for that cannot be made gives nullptr
// and a warning saying why (display without DISPLAY, also through
// HAVS_RENDER_WINDOW; glfw, not built; an unknown name); the reference of
// another view fails the bound.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace
{
const int kSize = 64;
const double kBound = 1e-3;

/// Records the text of VTK's warnings (vtkGenericWarningMacro has no object
/// to observe) while installed.
class CaptureOutputWindow : public vtkOutputWindow
{
public:
  static CaptureOutputWindow* New();
  vtkTypeMacro(CaptureOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override
  {
    this->Text += text ? text : "";
    ++this->Count;
  }
  std::string Text;
  int Count = 0;
};
vtkStandardNewMacro(CaptureOutputWindow);

/// The warning a call gives: the count and the text.
template <typename F>
std::string CaptureWarnings(F call, int* count)
{
  vtkNew<CaptureOutputWindow> capture;
  vtkOutputWindow* previous = vtkOutputWindow::GetInstance();
  previous->Register(nullptr);
  vtkOutputWindow::SetInstance(capture);
  call();
  vtkOutputWindow::SetInstance(previous);
  previous->UnRegister(nullptr);
  *count = capture->Count;
  return capture->Text;
}

bool StartsWith(const std::string& s, const std::string& prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

void Print(const std::string& what, const havstest::ImageDifference& d)
{
  std::printf("%-44s RMSE %.6f  max %.6f  pixels > 1/255 %.2f %%\n", what.c_str(), d.RMSE, d.Max,
    100.0 * d.FractionOver1);
}

std::vector<float> Reference(
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera)
{
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(kSize, kSize);
  reference->Render();
  vtkFloatArray* image = reference->GetImage();
  return std::vector<float>(image->GetPointer(0), image->GetPointer(0) + 4 * kSize * kSize);
}

/// One backend's window showing the box through a default HAVS mapper.
struct BackendScene
{
  std::string Backend;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkHAVSVolumeMapper> Mapper; // the defaults: what a user gets
  vtkNew<vtkVolume> Volume;
  havstest::Messages* Messages = nullptr;
  std::vector<float> Image;
};

std::unique_ptr<BackendScene> MakeScene(
  const std::string& backend, vtkUnstructuredGrid* grid, vtkVolumeProperty* property)
{
  auto scene = std::make_unique<BackendScene>();
  scene->Backend = backend;
  scene->Window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow(backend));
  if (!scene->Window)
  {
    return nullptr;
  }
  scene->Window->SetSize(kSize, kSize);
  scene->Window->SetMultiSamples(0);
  scene->Window->AddRenderer(scene->Renderer);
  scene->Mapper->SetInputDataObject(grid);
  scene->Mapper->KeepFloatResultOn();
  scene->Messages = havstest::CountMessages(scene->Mapper);
  scene->Volume->SetMapper(scene->Mapper);
  scene->Volume->SetProperty(property);
  scene->Renderer->AddVolume(scene->Volume);
  havstest::PlaceCamera(scene->Renderer, 25.0, 15.0, false);
  return scene;
}

/// Sets or unsets an environment variable for the scope, then restores it.
class ScopedEnv
{
public:
  ScopedEnv(const char* name, const char* value)
    : Name(name)
  {
    const char* old = std::getenv(name);
    this->HadValue = old != nullptr;
    this->Old = old ? old : "";
    if (value)
    {
      setenv(name, value, 1);
    }
    else
    {
      unsetenv(name);
    }
  }
  ~ScopedEnv()
  {
    if (this->HadValue)
    {
      setenv(this->Name.c_str(), this->Old.c_str(), 1);
    }
    else
    {
      unsetenv(this->Name.c_str());
    }
  }

private:
  std::string Name;
  std::string Old;
  bool HadValue = false;
};
}

int TestHAVSContexts(int, char*[])
{
  std::cout << "Contexts of this build, here:\n"
            << vtkHAVSRenderWindowFactory::DescribeBackends() << std::endl;

  // --- The table is consistent --------------------------------------------
  const std::vector<std::string> names = vtkHAVSRenderWindowFactory::GetBackendNames();
  havstest::Check(
    static_cast<int>(names.size()) == vtkHAVSRenderWindowFactory::GetNumberOfBackends(),
    "the backend list by index has the same length");
  for (const char* expected : { "egl", "display", "glfw", "osmesa" })
  {
    bool listed = false;
    for (const auto& n : names)
    {
      listed = listed || n == expected;
    }
    havstest::Check(listed, std::string("backend '") + expected + "' is listed");
  }
  for (const auto& name : names)
  {
    const bool built = vtkHAVSRenderWindowFactory::IsBackendBuilt(name);
    const bool available = vtkHAVSRenderWindowFactory::IsBackendAvailable(name);
    const std::string status = vtkHAVSRenderWindowFactory::GetBackendStatus(name);
    havstest::Check(!available || built, name + ": usable only when built");
    havstest::Check(available == StartsWith(status, "available: "),
      name + ": the status says usable exactly when it is ('" + status + "')");
    havstest::Check(built || StartsWith(status, "not built"),
      name + ": the status of a backend not built says so");
  }

  // --- What must be usable here --------------------------------------------
  const char* display = std::getenv("DISPLAY");
  havstest::Check(display && *display, "an X display (the test runs under Xvfb)");
  havstest::Check(vtkHAVSRenderWindowFactory::IsBackendAvailable("egl"),
    "egl is usable (Mesa's EGL surfaceless on llvmpipe)");
  havstest::Check(
    vtkHAVSRenderWindowFactory::IsBackendAvailable("display"), "display is usable (Xvfb)");
  if (vtkHAVSRenderWindowFactory::IsBackendBuilt("glfw"))
  {
    havstest::Check(vtkHAVSRenderWindowFactory::IsBackendAvailable("glfw"),
      "glfw, built, is usable (Xvfb; " + vtkHAVSRenderWindowFactory::GetBackendStatus("glfw") +
        ")");
  }
  if (vtkHAVSRenderWindowFactory::IsBackendBuilt("osmesa"))
  {
    havstest::Check(vtkHAVSRenderWindowFactory::IsBackendAvailable("osmesa"),
      "osmesa, built, is usable (" + vtkHAVSRenderWindowFactory::GetBackendStatus("osmesa") + ")");
  }

  // --- Every usable backend renders the reference ---------------------------
  auto grid = vtkHAVSDataSets::MakeBox(6, 6, 6, 1.0 / 6.0, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(grid);
  // Order: a window of each API after the other (egl, then OSMesa which
  // releases EGL, then GLX after OSMesa has handed the thread back).
  std::vector<std::unique_ptr<BackendScene>> scenes;
  for (const char* backend : { "egl", "osmesa", "display", "glfw" })
  {
    if (!vtkHAVSRenderWindowFactory::IsBackendAvailable(backend))
    {
      std::cout << backend << ": not rendered ("
                << vtkHAVSRenderWindowFactory::GetBackendStatus(backend) << ")" << std::endl;
      continue;
    }
    auto scene = MakeScene(backend, grid, property);
    if (!havstest::Check(scene != nullptr, std::string(backend) + ": the factory made a window"))
    {
      continue;
    }
    havstest::Check(
      backend == std::string(vtkHAVSRenderWindowFactory::GetBackendName(scene->Window)),
      std::string(backend) + ": the window (" + scene->Window->GetClassName() +
        ") is of that backend");
    scene->Window->Render();
    scene->Image = havstest::FloatResult(scene->Mapper);
    const auto exact = Reference(grid, property, scene->Renderer->GetActiveCamera());
    const auto d = havstest::Compare(scene->Image, exact);
    Print(std::string(backend) + ": HAVS vs the exact reference", d);
    havstest::WritePNG(scene->Image, kSize, kSize, std::string("contexts_") + backend + ".png");
    havstest::Check(havstest::AllFinite(scene->Image) && d.RMSE < kBound,
      std::string(backend) + ": the image matches the reference (RMSE < 1e-3)");
    havstest::Check(scene->Messages->Warnings == 0 && scene->Messages->Errors == 0,
      std::string(backend) + ": no warning and no error (" + scene->Messages->Text + ")");

    // Negative control: the reference of another view fails the bound.
    vtkNew<vtkRenderer> other;
    other->AddVolume(scene->Volume);
    havstest::PlaceCamera(other, 55.0, 15.0, false);
    const auto otherView = Reference(grid, property, other->GetActiveCamera());
    const auto control = havstest::Compare(scene->Image, otherView);
    Print(std::string(backend) + ": control, the reference at +30 deg", control);
    havstest::Check(control.RMSE > kBound && control.RMSE > 10.0 * d.RMSE,
      std::string(backend) + ": control, another view fails the bound");
    scenes.push_back(std::move(scene));
  }
  // The same scene gives the same image on every backend (one llvmpipe).
  for (size_t i = 1; i < scenes.size(); ++i)
  {
    const auto d = havstest::Compare(scenes[i]->Image, scenes[0]->Image);
    Print(scenes[i]->Backend + " vs " + scenes[0]->Backend, d);
    havstest::Check(d.RMSE < kBound, scenes[i]->Backend + " and " + scenes[0]->Backend + " agree");
  }

  // --- The windows, all alive, used in turn on this thread -----------------
  // Every order between the three APIs: each window takes the thread from the
  // one before (the EGL and OSMesa windows themselves, the display window when
  // it starts rendering), and the reads after a render (the mapper's kept
  // result, the window's pixels) find their own context.
  for (const char* backend :
    { "osmesa", "display", "osmesa", "egl", "display", "egl", "osmesa", "display" })
  {
    for (auto& scene : scenes)
    {
      if (scene->Backend != backend)
      {
        continue;
      }
      scene->Window->Render();
      const auto d = havstest::Compare(havstest::FloatResult(scene->Mapper), scene->Image);
      // The 8-bit read-back (VTK makes the window current for it) too.
      const auto rgba = havstest::ReadRGBA(scene->Window);
      double sum = 0.0;
      for (float v : rgba)
      {
        sum += v;
      }
      std::printf(
        "turn %-8s RMSE against its first frame %.2g, read-back sum %.1f\n", backend, d.RMSE, sum);
      havstest::Check(d.RMSE < 1e-6 && scene->Messages->Errors == 0,
        std::string(backend) + ": renders the same again after another API's window");
      havstest::Check(rgba.size() == 4u * kSize * kSize && sum > 0.0,
        std::string(backend) + ": pixels read back from the window");
    }
  }
  // Finalized: the display window after ReleaseCurrentContext() (libGLX cannot
  // take the thread from EGL or OSMesa itself), then the others.
  for (const char* backend : { "display", "egl", "osmesa" })
  {
    for (auto& scene : scenes)
    {
      if (scene->Backend == backend)
      {
        vtkHAVSRenderWindowFactory::ReleaseCurrentContext();
        scene->Window->Finalize();
      }
    }
  }
  scenes.clear();

  // --- Negative controls: asked for, cannot be made ----------------------
  {
    ScopedEnv noDisplay("DISPLAY", nullptr);
    havstest::Check(!vtkHAVSRenderWindowFactory::IsBackendAvailable("display") &&
        vtkHAVSRenderWindowFactory::GetBackendStatus("display") ==
          "unavailable: DISPLAY is not set",
      "control: display without DISPLAY is unavailable and says why");
    int count = 0;
    vtkRenderWindow* window = nullptr;
    std::string text = CaptureWarnings(
      [&] { window = vtkHAVSRenderWindowFactory::CreateRenderWindow("display"); }, &count);
    havstest::Check(
      window == nullptr && count > 0 && text.find("DISPLAY is not set") != std::string::npos,
      "control: display asked for without DISPLAY gives nullptr and a warning saying why ('" +
        text + "')");
    {
      ScopedEnv asked("HAVS_RENDER_WINDOW", "display");
      text =
        CaptureWarnings([&] { window = vtkHAVSRenderWindowFactory::CreateRenderWindow(); }, &count);
      havstest::Check(
        window == nullptr && count > 0 && text.find("DISPLAY is not set") != std::string::npos,
        "control: HAVS_RENDER_WINDOW=display without DISPLAY gives nullptr and a warning");
    }
    {
      ScopedEnv automatic("HAVS_RENDER_WINDOW", "auto");
      havstest::Check(std::string(vtkHAVSRenderWindowFactory::GetSelectedBackend()) == "egl",
        "auto without DISPLAY selects egl");
    }
  }
  {
    int count = 0;
    vtkRenderWindow* window = nullptr;
    if (!vtkHAVSRenderWindowFactory::IsBackendBuilt("glfw"))
    {
      const std::string text = CaptureWarnings(
        [&] { window = vtkHAVSRenderWindowFactory::CreateRenderWindow("glfw"); }, &count);
      havstest::Check(window == nullptr && count > 0 && text.find("not built") != std::string::npos,
        "control: glfw (not built) gives nullptr and a warning ('" + text + "')");
    }
    const std::string text = CaptureWarnings(
      [&] { window = vtkHAVSRenderWindowFactory::CreateRenderWindow("vulkan"); }, &count);
    havstest::Check(
      window == nullptr && count > 0 && text.find("unknown backend") != std::string::npos,
      "control: an unknown backend gives nullptr and a warning ('" + text + "')");
  }
  return havstest::Result();
}
