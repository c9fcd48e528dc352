/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewInput.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsViewInput.h"

#include "havsViewScene.h"

#include "vtkCommand.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSMapperBase.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace havsview
{
//------------------------------------------------------------------------------
Input::Input(Scene& scene, vtkRenderWindow* window)
  : TheScene(scene)
  , Window(window)
{
  this->Interactor->SetRenderWindow(window);
  this->Interactor->SetInteractorStyle(this->Style);
  this->Interactor->SetDesiredUpdateRate(10.0); // 0.1 s while the camera moves
  this->Interactor->SetStillUpdateRate(0.0001);
  this->Interactor->Initialize();
  this->Interactor->Enable();

  // The status line shows the previous frame's time: set before each render,
  // measured around it.
  this->StartObserver = window->AddObserver(vtkCommand::StartEvent, this, &Input::OnRenderStart);
  this->EndObserver = window->AddObserver(vtkCommand::EndEvent, this, &Input::OnRenderEnd);
}

//------------------------------------------------------------------------------
void Input::OnRenderStart()
{
  this->TheScene.UpdateStatus(this->LastFrameSeconds);
  this->FrameStart = vtkTimerLog::GetUniversalTime();
}

//------------------------------------------------------------------------------
void Input::OnRenderEnd()
{
  this->LastFrameSeconds = vtkTimerLog::GetUniversalTime() - this->FrameStart;
  ++this->Frames;
  // A level-of-detail frame: a reduced image or (HAVS) a face subset; its
  // share of the full frame's detail.
  if (auto* base = vtkHAVSMapperBase::SafeDownCast(this->TheScene.GetMapper()))
  {
    const double detail = base->GetLastDetail();
    if (detail < 1.0)
    {
      ++this->LevelOfDetailFrames;
      this->SmallestLevelOfDetail = std::min(this->SmallestLevelOfDetail, detail);
    }
  }
}

//------------------------------------------------------------------------------
Input::~Input()
{
  this->Window->RemoveObserver(this->StartObserver);
  this->Window->RemoveObserver(this->EndObserver);
  this->Interactor->SetRenderWindow(nullptr);
}

//------------------------------------------------------------------------------
void Input::SetInteractiveSeconds(double seconds)
{
  this->Interactor->SetDesiredUpdateRate(seconds > 0.0 ? 1.0 / seconds : 10.0);
}

//------------------------------------------------------------------------------
int Input::FlipY(double y) const
{
  return this->Window->GetSize()[1] - 1 - static_cast<int>(y);
}

//------------------------------------------------------------------------------
void Input::Render()
{
  this->Window->Render();
}

//------------------------------------------------------------------------------
void Input::Key(const std::string& key)
{
  std::string action;
  if (key == "q" || key == "escape")
  {
    this->Quit = true;
    return;
  }
  if (key == "k")
  {
    action = this->TheScene.NextKBufferSize();
  }
  else if (key == "K")
  {
    action = this->TheScene.ToggleAutomaticK();
  }
  else if (key == "o")
  {
    action = this->TheScene.NextOrder();
  }
  else if (key == "m")
  {
    action = this->TheScene.NextMapper();
  }
  else if (key == "b")
  {
    action = this->TheScene.NextBlendMode();
  }
  else if (key == "l")
  {
    action = this->TheScene.ToggleLevelOfDetail();
  }
  else if (key == "i")
  {
    action = this->TheScene.ToggleIsoSurfacesInComposite();
  }
  else if (key == "p")
  {
    action = this->TheScene.ToggleTranslucentPlane();
  }
  else if (key == "g")
  {
    action = this->TheScene.ToggleShading();
  }
  else if (key == "v")
  {
    action = this->TheScene.ToggleViolationCount();
  }
  else if (key == "c")
  {
    action = this->TheScene.NextColorPreset();
  }
  else if (key == "t")
  {
    action = this->TheScene.ToggleOverlay();
  }
  else if (key == "h")
  {
    action = this->TheScene.ToggleHelp();
  }
  else if (key == "r")
  {
    this->TheScene.GetRenderer()->ResetCamera();
    action = "camera reset";
  }
  else if (key == "s")
  {
    this->Screenshot();
    return;
  }
  else
  {
    return;
  }
  if (!action.empty())
  {
    std::cout << "havs_view: " << action << std::endl;
  }
  this->TheScene.SetLastAction(action);
  this->Render();
}

//------------------------------------------------------------------------------
bool Input::Screenshot(const std::string& path, bool overlay)
{
  std::string file = path;
  if (file.empty())
  {
    char name[64];
    std::snprintf(name, sizeof(name), "havs_view_%03d.png", this->ScreenshotCount++);
    file = this->ScreenshotDirectory + "/" + name;
  }
  std::string error;
  const bool ok = this->TheScene.Screenshot(this->Window, file, error, overlay);
  const std::string action = ok ? "screenshot: " + file : "screenshot failed: " + error;
  std::cout << "havs_view: " << action << std::endl;
  this->TheScene.SetLastAction(action);
  this->Render();
  return ok;
}

//------------------------------------------------------------------------------
void Input::MouseButton(int button, bool press, double x, double y, bool shift, bool control)
{
  const int yUp = this->FlipY(y);
  TransferFunctionEditor& editor = this->TheScene.GetEditor();
  if (press && this->PressedButton < 0 && editor.Contains(static_cast<int>(x), yUp))
  {
    this->PressedButton = button;
    this->EditorDrag = true;
    if (editor.Press(button, static_cast<int>(x), yUp))
    {
      this->Render();
    }
    return;
  }
  if (!press && this->EditorDrag && button == this->PressedButton)
  {
    editor.Release(static_cast<int>(x), yUp);
    this->EditorDrag = false;
    this->PressedButton = -1;
    this->Render();
    return;
  }
  if (this->EditorDrag)
  {
    return;
  }

  this->Interactor->SetEventInformationFlipY(
    static_cast<int>(x), static_cast<int>(y), control ? 1 : 0, shift ? 1 : 0);
  unsigned long event = vtkCommand::NoEvent;
  switch (button)
  {
    case Left:
      event = press ? vtkCommand::LeftButtonPressEvent : vtkCommand::LeftButtonReleaseEvent;
      break;
    case Middle:
      event = press ? vtkCommand::MiddleButtonPressEvent : vtkCommand::MiddleButtonReleaseEvent;
      break;
    case Right:
      event = press ? vtkCommand::RightButtonPressEvent : vtkCommand::RightButtonReleaseEvent;
      break;
    default:
      return;
  }
  this->PressedButton = press ? button : -1;
  this->Interactor->InvokeEvent(event, nullptr);
}

//------------------------------------------------------------------------------
void Input::CursorMove(double x, double y)
{
  if (this->EditorDrag)
  {
    if (this->TheScene.GetEditor().Move(static_cast<int>(x), this->FlipY(y)))
    {
      this->Render();
    }
    return;
  }
  this->Interactor->SetEventInformationFlipY(static_cast<int>(x), static_cast<int>(y),
    this->Interactor->GetControlKey(), this->Interactor->GetShiftKey());
  this->Interactor->InvokeEvent(vtkCommand::MouseMoveEvent, nullptr);
}

//------------------------------------------------------------------------------
void Input::Scroll(double delta)
{
  this->Interactor->InvokeEvent(
    delta > 0 ? vtkCommand::MouseWheelForwardEvent : vtkCommand::MouseWheelBackwardEvent, nullptr);
}

//------------------------------------------------------------------------------
void Input::Resize(int width, int height)
{
  if (width <= 0 || height <= 0)
  {
    return;
  }
  this->Window->SetSize(width, height);
  this->Interactor->UpdateSize(width, height);
  this->TheScene.GetEditor().Update();
  this->Render();
}
}
