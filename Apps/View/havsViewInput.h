/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewInput.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   havsview::Input
 * @brief   havs_view's input: keys, mouse and resizes, from GLFW or a script.
 *
 * The GLFW callbacks and the script player (havsview::Script) call the same
 * functions, so a scripted session goes through exactly the paths a person's
 * does. The mouse goes to the transfer-function editor when pressed on it,
 * else to VTK's trackball camera (a vtkGenericRenderWindowInteractor), whose
 * interaction sets the window's desired update rate: HAVS draws its level of
 * detail within the interactive frame time while the camera moves and the
 * full image when the button is released.
 *
 * Positions are window pixels with y down (as the window system gives them).
 */
#ifndef havsViewInput_h
#define havsViewInput_h

#include "vtkGenericRenderWindowInteractor.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <string>

namespace havsview
{
class Scene;

class Input
{
public:
  enum Buttons
  {
    Left = 0,
    Middle = 1,
    Right = 2
  };

  Input(Scene& scene, vtkRenderWindow* window);
  ~Input();

  ///@{
  /// Events. Key(): one character ("k", "K", …) or "escape".
  void Key(const std::string& key);
  void MouseButton(int button, bool press, double x, double y, bool shift, bool control);
  void CursorMove(double x, double y);
  void Scroll(double delta);
  void Resize(int width, int height);
  ///@}

  /// Renders a frame (the status line shows the previous frame's time).
  void Render();

  /// Takes a screenshot into `path` (or the next havs_view_NNN.png); with
  /// `overlay`, the window as shown (Scene::Screenshot).
  bool Screenshot(const std::string& path = std::string(), bool overlay = false);

  ///@{
  /// The interactive frame time (seconds) the level of detail aims at.
  void SetInteractiveSeconds(double seconds);
  ///@}

  /// The directory screenshots without a path go to.
  void SetScreenshotDirectory(const std::string& directory)
  {
    this->ScreenshotDirectory = directory;
  }

  /// Whether q or Esc was pressed.
  bool GetQuit() const { return this->Quit; }

  /// Frames rendered, and those where HAVS drew a level of detail (a subset of
  /// its faces, while the camera moved), and the smallest share it drew.
  int GetFrames() const { return this->Frames; }
  int GetLevelOfDetailFrames() const { return this->LevelOfDetailFrames; }
  double GetSmallestLevelOfDetail() const { return this->SmallestLevelOfDetail; }

  /// Seconds the last frame took (wall clock around the window's Render()).
  double GetLastFrameSeconds() const { return this->LastFrameSeconds; }

private:
  Input(const Input&) = delete;
  void operator=(const Input&) = delete;

  int FlipY(double y) const;
  void OnRenderStart();
  void OnRenderEnd();

  Scene& TheScene;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkGenericRenderWindowInteractor> Interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> Style;
  bool EditorDrag = false;
  int PressedButton = -1;
  bool Quit = false;
  int ScreenshotCount = 0;
  std::string ScreenshotDirectory = ".";
  double FrameStart = 0.0;
  double LastFrameSeconds = 0.0;
  int Frames = 0;
  int LevelOfDetailFrames = 0;
  double SmallestLevelOfDetail = 1.0;
  unsigned long StartObserver = 0;
  unsigned long EndObserver = 0;
};
}

#endif
