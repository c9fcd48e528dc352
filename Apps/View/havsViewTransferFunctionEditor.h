/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewTransferFunctionEditor.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   havsview::TransferFunctionEditor
 * @brief   The transfer-function editor drawn in havs_view's window.
 *
 * A strip along the bottom of the window (a renderer of its own, drawn after
 * the volume's):
 * the colour map as a bar, the opacity function as a polyline through its
 * nodes over the scalar range. With the mouse: drag a node to move it (x
 * between its neighbours, opacity 0 … 1), press the left button on empty space
 * to add a node there and drag it, press the right button on a node to remove
 * it (two stay at least). NextColorPreset() cycles the colour maps. Every edit
 * changes the volume property's functions, so the next render redraws with
 * them (the mapper rebuilds its table then).
 *
 * Positions are window pixels with y up (VTK's display coordinates).
 */
#ifndef havsViewTransferFunctionEditor_h
#define havsViewTransferFunctionEditor_h

#include "vtkActor2D.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <string>

namespace havsview
{
class TransferFunctionEditor
{
public:
  TransferFunctionEditor();
  ~TransferFunctionEditor();

  /// The property edited and the scalar range its axis spans.
  void SetProperty(vtkVolumeProperty* property, const double range[2]);

  /// The editor's renderer (the bottom quarter of the window; add it after the volume's).
  vtkRenderer* GetRenderer() const;

  ///@{
  /// Shown or hidden (hidden: draws nothing, takes no input).
  void SetVisible(bool visible);
  bool GetVisible() const { return this->Visible; }
  ///@}

  /// Whether a window position lies on the editor (and it is shown).
  bool Contains(int x, int y) const;

  ///@{
  /**
   * Mouse input (button 0 left, 2 right). Press() returns true when the
   * editor takes the press; then Move() and Release() go to it too. Each
   * returns true when the transfer function changed.
   */
  bool Press(int button, int x, int y);
  bool Move(int x, int y);
  bool Release(int x, int y);
  bool IsDragging() const { return this->DragNode >= 0; }
  ///@}

  ///@{
  /// The colour maps: the one in use, and the next one.
  std::string GetColorPresetName() const;
  void NextColorPreset();
  void SetColorPreset(int index);
  static int GetNumberOfColorPresets();
  ///@}

  ///@{
  /// Window positions (y up) of an opacity node, and of a point of the plot
  /// (t in [0, 1] across the scalar range, an opacity); false when none.
  bool GetNodePosition(int node, double& x, double& y) const;
  void GetPlotPosition(double t, double opacity, double& x, double& y) const;
  ///@}

  /// Redraws the editor's geometry from the property's functions.
  void Update();

private:
  TransferFunctionEditor(const TransferFunctionEditor&) = delete;
  void operator=(const TransferFunctionEditor&) = delete;

  /// Window position -> (scalar, opacity); false outside the plot area.
  void ToFunction(int x, int y, double& scalar, double& opacity) const;
  /// Node -> window position.
  void ToWindow(double scalar, double opacity, double& x, double& y) const;
  int NodeAt(int x, int y) const;

  vtkSmartPointer<vtkVolumeProperty> Property;
  double Range[2] = { 0.0, 1.0 };
  bool Visible = true;
  int DragNode = -1;
  int Preset = 0;

  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkPolyData> ColorBar;
  vtkNew<vtkPolyData> Curve;
  vtkNew<vtkPolyData> Nodes;
  vtkNew<vtkActor2D> ColorBarActor;
  vtkNew<vtkActor2D> CurveActor;
  vtkNew<vtkActor2D> NodesActor;
};
}

#endif
