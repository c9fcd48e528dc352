/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSMultisample.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Opaque geometry in an ordinary X window, where VTK asks for a multisampled
// framebuffer (issue 20): the mapper resolves the multisampled depth (a blit
// into a single-sample depth texture) so that an opaque sphere inside the
// volume still ends its rays. Run under Xvfb (CMake does), with the mapper's
// default settings, an 8-sample window, three views; each frame against the
// exact reference cut at the window's own depth. Checked: the depth came
// from a multisampled framebuffer and was captured, no warning, the image
// matches the reference.
//
// Negative controls: the reference through the surface (the sphere ignored,
// which is what the mapper drew before the fix) is clearly wrong; a
// single-sample window reports its depth as not multisampled (the flag is
// not always on).
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
const int kSize = 96;

std::vector<float> Reference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkRenderer* renderer, vtkFloatArray* depth)
{
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(renderer->GetActiveCamera());
  reference->SetSize(kSize, kSize);
  reference->SetOpaqueDepth(depth);
  reference->Render();
  vtkFloatArray* image = reference->GetImage();
  return std::vector<float>(image->GetPointer(0), image->GetPointer(0) + 4 * kSize * kSize);
}

void Print(const std::string& what, const havstest::ImageDifference& d)
{
  std::printf("%-48s RMSE %.6f  max %.6f  pixels > 1/255 %.2f %%\n", what.c_str(), d.RMSE, d.Max,
    100.0 * d.FractionOver1);
}

/// One X window with `samples` samples: the box, an opaque sphere inside it.
struct XScene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
};

void Build(XScene& scene, vtkUnstructuredGrid* grid, vtkHAVSVolumeMapper* mapper,
  vtkVolumeProperty* property, int samples)
{
  scene.Window->SetMultiSamples(samples);
  scene.Window->SetSize(kSize, kSize);
  scene.Window->AddRenderer(scene.Renderer);
  mapper->SetInputDataObject(grid);
  mapper->KeepFloatResultOn();
  mapper->SetEarlyRayTerminationOpacity(1.0);
  scene.Volume->SetMapper(mapper);
  scene.Volume->SetProperty(property);
  scene.Renderer->AddVolume(scene.Volume);
  havstest::AddOpaqueSphere(scene.Renderer);
}
}

int TestHAVSMultisample(int, char*[])
{
  const char* display = std::getenv("DISPLAY");
  if (!havstest::Check(display && *display, "an X display (the test runs under Xvfb)"))
  {
    return EXIT_FAILURE;
  }
  auto grid = vtkHAVSDataSets::MakeBox(10, 10, 10, 0.1, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(grid);

  XScene scene;
  vtkNew<vtkHAVSVolumeMapper> mapper; // the defaults: what a user gets
  Build(scene, grid, mapper, property, 8);
  havstest::Messages* messages = havstest::CountMessages(mapper);
  const double views[3][2] = { { 25.0, 15.0 }, { -40.0, 30.0 }, { 120.0, -20.0 } };
  for (int v = 0; v < 3; ++v)
  {
    havstest::PlaceCamera(scene.Renderer, views[v][0], views[v][1], v == 2);
    scene.Window->Render();
    const std::string view = "view " + std::to_string(v) + (v == 2 ? " (parallel)" : "");
    vtkHAVSFrameStatistics* stats = mapper->GetLastFrameStatistics();
    havstest::Check(stats->GetOpaqueGeometry(), view + ": the opaque sphere is seen");
    havstest::Check(stats->GetOpaqueDepthMultisampled(),
      view + ": the window's framebuffer is multisampled (" +
        std::to_string(scene.Window->GetMultiSamples()) + " samples asked)");
    havstest::Check(stats->GetOpaqueDepthCaptured(), view + ": its depth was resolved");
    const auto havs = havstest::FloatResult(mapper);
    vtkNew<vtkFloatArray> depth;
    scene.Window->GetZbufferData(0, 0, kSize - 1, kSize - 1, depth);
    const auto exact = Reference(grid, property, scene.Renderer, depth);
    const auto through = Reference(grid, property, scene.Renderer, nullptr);
    const auto d = havstest::Compare(havs, exact);
    const auto control = havstest::Compare(through, exact);
    Print(view + ": HAVS vs reference cut at the surface", d);
    Print(view + ": reference through the surface", control);
    havstest::WritePNG(havs, kSize, kSize, "multisample_view" + std::to_string(v) + ".png");
    havstest::Check(d.RMSE < 2e-3 && d.FractionOver1 < 0.02,
      view + ": the rays end at the opaque surface (matches the reference)");
    havstest::Check(control.RMSE > 10.0 * d.RMSE && control.RMSE > 1e-3 &&
        (control.Max > 0.05 || control.FractionOver1 > 0.05),
      view + ": negative control, the surface matters (through it is clearly wrong)");
  }
  havstest::Check(messages->Warnings == 0 && messages->Errors == 0,
    "no warning and no error over the three frames (" + std::to_string(messages->Warnings) +
      " warnings: " + messages->Text + ")");

  // Control: a single-sample window's depth is not reported as multisampled.
  XScene single;
  vtkNew<vtkHAVSVolumeMapper> singleMapper;
  Build(single, grid, singleMapper, property, 0);
  havstest::PlaceCamera(single.Renderer, views[0][0], views[0][1], false);
  single.Window->Render();
  havstest::Check(!singleMapper->GetLastFrameStatistics()->GetOpaqueDepthMultisampled() &&
      singleMapper->GetLastFrameStatistics()->GetOpaqueDepthCaptured(),
    "control: a single-sample window's depth is copied, not resolved");
  return havstest::Result();
}
