/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSRenderWindow.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// The render-window factory gives a working headless window: an opaque
// sphere renders (pixels differ from the background), the backend is the one
// asked for, and the window survives a resize and a second window.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestScenes.h"

#include "vtkActor.h"
#include "vtkHAVSEGLRenderWindow.h"
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cstdlib>
#include <iostream>

namespace
{
int CountLitPixels(vtkRenderWindow* window)
{
  std::vector<float> rgba = havstest::ReadRGBA(window);
  int lit = 0;
  for (size_t p = 0; p < rgba.size() / 4; ++p)
  {
    lit += rgba[4 * p] > 0.5f ? 1 : 0; // background is black, the sphere red
  }
  return lit;
}
}

int TestHAVSRenderWindow(int, char*[])
{
  const std::string backend = vtkHAVSRenderWindowFactory::GetSelectedBackend();
  std::cout << "selected backend: " << backend << std::endl;
  havstest::Check(!backend.empty(), "a backend is available");

  auto window = havstest::MakeWindow(120, 80);
  if (!havstest::Check(window != nullptr, "factory made a window"))
  {
    return EXIT_FAILURE;
  }
  havstest::Check(backend == vtkHAVSRenderWindowFactory::GetBackendName(window),
    "the window is of the selected backend");
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1, 0, 0);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  renderer->AddActor(actor);
  window->Render();
  const int lit = CountLitPixels(window);
  std::cout << "lit pixels at 120x80: " << lit << std::endl;
  havstest::Check(lit > 1000 && lit < 120 * 80, "the sphere is drawn");

  window->SetSize(200, 150);
  window->Render();
  const int litResized = CountLitPixels(window);
  std::cout << "lit pixels at 200x150: " << litResized << std::endl;
  havstest::Check(litResized > lit, "the sphere grows with the window");

  if (auto* egl = vtkHAVSEGLRenderWindow::SafeDownCast(window))
  {
    std::cout << "EGL platform: " << egl->GetPlatformName() << std::endl;
    havstest::Check(!egl->GetPlatformName().empty(), "EGL platform known");
  }

  // A second window at the same time renders too.
  auto second = havstest::MakeWindow(64, 64);
  vtkNew<vtkRenderer> renderer2;
  second->AddRenderer(renderer2);
  vtkNew<vtkPolyDataMapper> mapper2;
  mapper2->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor2;
  actor2->SetMapper(mapper2);
  actor2->SetProperty(actor->GetProperty());
  renderer2->AddActor(actor2);
  second->Render();
  havstest::Check(CountLitPixels(second) > 500, "a second window renders");
  window->Render();
  const int litAgain = CountLitPixels(window);
  std::cout << "lit pixels at 200x150 after the second window: " << litAgain << std::endl;
  havstest::Check(litAgain == litResized, "the first window still renders the same");

  return havstest::Result();
}
