/*=========================================================================

  Project:   vtkHAVS
  Module:    havs_view.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_view: an interactive viewer for unstructured volumes with HAVS.
//
// A GLFW window (vtkHAVSGLFWRenderWindow) shows one mesh with
// vtkHAVSVolumeMapper at its exact defaults; the trackball turns it (the
// level of detail while the mouse moves, the full image when it stops); the
// strip at the bottom edits the transfer function; keys switch k, the order,
// the mapper (HAVS, the cell projection, VTK's PT, ZSweep and ray cast) and
// the blend mode; `s` writes a screenshot without the overlay and, beside it,
// the scene's state (the test renders the exact reference from it).
// --play replays a script of input (havsViewScript.h) through the same paths.
#include "havsViewData.h"
#include "havsViewInput.h"
#include "havsViewScene.h"
#include "havsViewScript.h"

#include "vtkHAVSGLFWRenderWindow.h"
#include "vtkHAVSRenderWindowFactory.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
struct Options
{
  havsview::DataSource Source;
  int Width = 960;
  int Height = 720;
  std::string Mapper = "havs";
  int KBufferSize = 0; // 0: the mapper's default
  std::string Order;   // empty: the mapper's default
  std::string Play;
  bool StayAfterScript = false;
  std::string ScreenshotDirectory = ".";
  double InteractiveSeconds = 0.1;
  bool Contexts = false;
};

void Usage(std::ostream& out)
{
  out << "usage: havs_view [options] MESH\n"
         "  An interactive volume viewer for unstructured meshes with HAVS.\n"
         "  MESH: "
      << havsview::DescribeSources()
      << "\n"
         "options:\n"
         "  --array NAME        the scalar array (default: the active or first one)\n"
         "  --q FILE            PLOT3D solution file;  --function N  its scalar (100)\n"
         "  --size WxH          window size (960x720)\n"
         "  --mapper NAME       havs, cellprojection, pt, zsweep, raycast, tetraycast (havs)\n"
         "  --k N               HAVS k (default: the mapper's, 2)\n"
         "  --order NAME        centroid, mpvo, automatic (default: the mapper's, MPVO)\n"
         "  --interactive S     frame time aimed at while the camera moves (0.1 s)\n"
         "  --play FILE         replay scripted input (see Apps/View/havsViewScript.h),\n"
         "                      then quit (--stay: keep the window open)\n"
         "  --screenshots DIR   where `s` writes havs_view_NNN.png (.)\n"
         "  --contexts          print which OpenGL contexts this build can make, and exit\n"
         "  --help              this text\n"
         "keys and mouse:\n"
      << havsview::Scene::KeyHelp()
      << "\n"
         "Needs a window system (X, or Xvfb); $HAVS_DATA_DIR is the data directory.\n";
}

bool ParseSize(const std::string& text, int& width, int& height)
{
  const size_t x = text.find('x');
  if (x == std::string::npos)
  {
    return false;
  }
  width = std::atoi(text.substr(0, x).c_str());
  height = std::atoi(text.substr(x + 1).c_str());
  return width > 0 && height > 0;
}

/// 0: parsed; 1: exit with success (--help); 2: exit with an error.
int Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](std::string& into)
    {
      if (i + 1 >= argc)
      {
        std::cerr << "havs_view: " << arg << " needs a value" << std::endl;
        return false;
      }
      into = argv[++i];
      return true;
    };
    std::string text;
    if (arg == "--help" || arg == "-h")
    {
      Usage(std::cout);
      return 1;
    }
    else if (arg == "--contexts")
    {
      o.Contexts = true;
    }
    else if (arg == "--stay")
    {
      o.StayAfterScript = true;
    }
    else if (arg == "--array")
    {
      if (!value(o.Source.Array))
        return 2;
    }
    else if (arg == "--q")
    {
      if (!value(o.Source.Solution))
        return 2;
    }
    else if (arg == "--function")
    {
      if (!value(text))
        return 2;
      o.Source.Function = std::atoi(text.c_str());
    }
    else if (arg == "--size")
    {
      if (!value(text) || !ParseSize(text, o.Width, o.Height))
      {
        std::cerr << "havs_view: --size wants WxH, e.g. 800x600" << std::endl;
        return 2;
      }
    }
    else if (arg == "--mapper")
    {
      if (!value(o.Mapper))
        return 2;
    }
    else if (arg == "--k")
    {
      if (!value(text))
        return 2;
      o.KBufferSize = std::atoi(text.c_str());
    }
    else if (arg == "--order")
    {
      if (!value(o.Order))
        return 2;
    }
    else if (arg == "--interactive")
    {
      if (!value(text))
        return 2;
      o.InteractiveSeconds = std::atof(text.c_str());
    }
    else if (arg == "--play")
    {
      if (!value(o.Play))
        return 2;
    }
    else if (arg == "--screenshots")
    {
      if (!value(o.ScreenshotDirectory))
        return 2;
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      std::cerr << "havs_view: unknown option " << arg << " (--help)" << std::endl;
      return 2;
    }
    else
    {
      o.Source.Name = arg;
    }
  }
  if (o.Source.Name.empty() && !o.Contexts)
  {
    std::cerr << "havs_view: no mesh given (--help)" << std::endl;
    return 2;
  }
  return 0;
}

int MapperKind(const std::string& name)
{
  if (name == "havs")
    return havsview::Scene::MapperHAVS;
  if (name == "cellprojection")
    return havsview::Scene::MapperCellProjection;
  if (name == "pt")
    return havsview::Scene::MapperPT;
  if (name == "zsweep")
    return havsview::Scene::MapperZSweep;
  if (name == "raycast")
    return havsview::Scene::MapperRayCast;
  if (name == "tetraycast")
    return havsview::Scene::MapperTetRayCast;
  return -1;
}

havsview::Input* InputOf(GLFWwindow* window)
{
  return static_cast<havsview::Input*>(glfwGetWindowUserPointer(window));
}

int ButtonOf(int glfwButton)
{
  switch (glfwButton)
  {
    case GLFW_MOUSE_BUTTON_LEFT:
      return havsview::Input::Left;
    case GLFW_MOUSE_BUTTON_MIDDLE:
      return havsview::Input::Middle;
    case GLFW_MOUSE_BUTTON_RIGHT:
      return havsview::Input::Right;
    default:
      return -1;
  }
}

void InstallCallbacks(GLFWwindow* window, havsview::Input* input)
{
  glfwSetWindowUserPointer(window, input);
  glfwSetCharCallback(window,
    [](GLFWwindow* w, unsigned int codepoint)
    {
      if (codepoint < 128)
      {
        InputOf(w)->Key(std::string(1, static_cast<char>(codepoint)));
      }
    });
  glfwSetKeyCallback(window,
    [](GLFWwindow* w, int key, int, int action, int)
    {
      if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS)
      {
        InputOf(w)->Key("escape");
      }
    });
  glfwSetMouseButtonCallback(window,
    [](GLFWwindow* w, int button, int action, int mods)
    {
      double x, y;
      glfwGetCursorPos(w, &x, &y);
      InputOf(w)->MouseButton(ButtonOf(button), action == GLFW_PRESS, x, y,
        (mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_CONTROL) != 0);
    });
  glfwSetCursorPosCallback(
    window, [](GLFWwindow* w, double x, double y) { InputOf(w)->CursorMove(x, y); });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) { InputOf(w)->Scroll(dy); });
  glfwSetFramebufferSizeCallback(
    window, [](GLFWwindow* w, int width, int height) { InputOf(w)->Resize(width, height); });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { InputOf(w)->Render(); });
}
}

int main(int argc, char* argv[])
{
  Options o;
  const int parsed = Parse(argc, argv, o);
  if (parsed != 0)
  {
    return parsed == 1 ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  if (o.Contexts)
  {
    std::cout << vtkHAVSRenderWindowFactory::DescribeBackends();
    return EXIT_SUCCESS;
  }
  const int mapperKind = MapperKind(o.Mapper);
  if (mapperKind < 0)
  {
    std::cerr << "havs_view: unknown mapper " << o.Mapper << " (--help)" << std::endl;
    return EXIT_FAILURE;
  }
  havsview::Script script;
  std::string error;
  if (!o.Play.empty() && !script.Load(o.Play, error))
  {
    std::cerr << "havs_view: " << error << std::endl;
    return EXIT_FAILURE;
  }
  if (!vtkHAVSGLFWRenderWindow::IsAvailable())
  {
    std::cerr << "havs_view: no window can be opened: "
              << vtkHAVSGLFWRenderWindow::GetUnavailableReason()
              << "\n(it needs an X server; headless, run it under xvfb-run)" << std::endl;
    return EXIT_FAILURE;
  }

  std::cout << "havs_view: loading " << o.Source.Name << std::endl;
  vtkSmartPointer<vtkUnstructuredGrid> grid = havsview::LoadMesh(o.Source, error);
  if (!grid)
  {
    std::cerr << "havs_view: " << error << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "havs_view: " << grid->GetNumberOfCells() << " tetrahedra" << std::endl;

  vtkNew<vtkHAVSGLFWRenderWindow> window;
  window->SetSize(o.Width, o.Height);
  window->SetWindowName(("havs_view: " + o.Source.Name).c_str());
  window->SetMultiSamples(0);
  havsview::Scene scene;
  scene.AddToWindow(window);
  scene.SetMapper(mapperKind);
  scene.SetMesh(grid, o.Source.Name);
  if (o.KBufferSize > 0)
  {
    scene.SetKBufferSize(o.KBufferSize);
  }
  if (!o.Order.empty())
  {
    scene.SetOrder(o.Order);
  }
  window->Initialize();
  if (!window->GetGLFWWindow())
  {
    std::cerr << "havs_view: the window could not be created" << std::endl;
    return EXIT_FAILURE;
  }

  int exitCode = EXIT_SUCCESS;
  {
    havsview::Input input(scene, window);
    input.SetInteractiveSeconds(o.InteractiveSeconds);
    input.SetScreenshotDirectory(o.ScreenshotDirectory);
    InstallCallbacks(window->GetGLFWWindow(), &input);
    input.Render();

    bool scripted = !o.Play.empty();
    while (!window->GetShouldClose() && !input.GetQuit())
    {
      if (scripted)
      {
        glfwPollEvents();
        if (!script.Step(input, scene))
        {
          scripted = false;
          if (script.GetFailed())
          {
            std::cerr << "havs_view: script: " << script.GetError() << std::endl;
            exitCode = EXIT_FAILURE;
            break;
          }
          if (!o.StayAfterScript)
          {
            break;
          }
        }
      }
      else
      {
        glfwWaitEventsTimeout(0.25);
      }
    }
    std::printf("havs_view: %d frames, %d with a level of detail (the least drew %.1f %% of "
                "the full frame's detail)\n",
      input.GetFrames(), input.GetLevelOfDetailFrames(), 100.0 * input.GetSmallestLevelOfDetail());
    glfwSetWindowUserPointer(window->GetGLFWWindow(), nullptr);
  }
  window->Finalize();
  return exitCode;
}
