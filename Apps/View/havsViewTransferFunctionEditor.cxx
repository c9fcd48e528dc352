/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewTransferFunctionEditor.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsViewTransferFunctionEditor.h"

#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkCoordinate.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper2D.h"
#include "vtkProperty2D.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

namespace havsview
{
namespace
{
// The editor's strip (normalized window coordinates) and, inside it, the
// plot area of the opacity function and the colour bar (normalized viewport).
const double kStripHeight = 0.25;
const double kPlotLeft = 0.04, kPlotRight = 0.96, kPlotBottom = 0.22, kPlotTop = 0.92;
const double kBarBottom = 0.05, kBarTop = 0.16;
const int kBarSteps = 128;
const double kPickPixels = 8.0;

struct ColorNode
{
  double T, R, G, B;
};
struct ColorPreset
{
  const char* Name;
  ColorNode Nodes[6];
  int Count;
};
// Colour maps by control points on [0, 1]; "ramp" is the tests' default
// (havsTestProperties' MakeRampProperty), the others approximate the
// well-known maps of the same names.
const ColorPreset kPresets[] = {
  { "ramp",
    { { 0.0, 0.1, 0.2, 1.0 }, { 0.3, 0.16, 0.68, 0.58 }, { 0.5, 0.2, 1.0, 0.3 },
      { 1.0, 1.0, 0.3, 0.1 } },
    4 },
  { "cool to warm",
    { { 0.0, 0.23, 0.30, 0.75 }, { 0.5, 0.87, 0.87, 0.87 }, { 1.0, 0.71, 0.02, 0.15 } }, 3 },
  { "viridis",
    { { 0.0, 0.27, 0.00, 0.33 }, { 0.25, 0.23, 0.32, 0.55 }, { 0.5, 0.13, 0.57, 0.55 },
      { 0.75, 0.37, 0.79, 0.38 }, { 1.0, 0.99, 0.91, 0.14 } },
    5 },
  { "black body",
    { { 0.0, 0.0, 0.0, 0.0 }, { 0.4, 0.9, 0.0, 0.0 }, { 0.8, 0.9, 0.9, 0.0 },
      { 1.0, 1.0, 1.0, 1.0 } },
    4 },
  { "grayscale", { { 0.0, 0.0, 0.0, 0.0 }, { 1.0, 1.0, 1.0, 1.0 } }, 2 },
};
const int kNumberOfPresets = static_cast<int>(sizeof(kPresets) / sizeof(kPresets[0]));

/// A 2D mapper of points in normalized viewport coordinates; with `colors`,
/// the points' RGB scalars are the colours, else the actor's colour is.
vtkSmartPointer<vtkPolyDataMapper2D> NormalizedViewportMapper(vtkPolyData* data, bool colors)
{
  vtkNew<vtkCoordinate> coordinate;
  coordinate->SetCoordinateSystemToNormalizedViewport();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputData(data);
  mapper->SetTransformCoordinate(coordinate);
  mapper->SetScalarVisibility(colors ? 1 : 0);
  mapper->SetColorModeToDirectScalars();
  return mapper;
}
}

//------------------------------------------------------------------------------
TransferFunctionEditor::TransferFunctionEditor()
{
  // On the volume's layer, drawn after it: the strip is cleared to its own
  // dark background (a translucent backdrop on a layer above would not keep
  // the curve above it).
  this->Renderer->SetLayer(0);
  this->Renderer->SetViewport(0.0, 0.0, 1.0, kStripHeight);
  this->Renderer->SetBackground(0.09, 0.09, 0.11);
  this->Renderer->InteractiveOff();

  struct Layer
  {
    vtkPolyData* Data;
    vtkActor2D* Actor;
  };
  for (const Layer& layer : { Layer{ this->ColorBar, this->ColorBarActor },
         Layer{ this->Curve, this->CurveActor }, Layer{ this->Nodes, this->NodesActor } })
  {
    layer.Actor->SetMapper(NormalizedViewportMapper(layer.Data, layer.Data == this->ColorBar));
    this->Renderer->AddViewProp(layer.Actor);
  }
  this->CurveActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  this->CurveActor->GetProperty()->SetLineWidth(2.0);
  this->NodesActor->GetProperty()->SetColor(1.0, 0.85, 0.2);
  this->NodesActor->GetProperty()->SetPointSize(9.0);
}

//------------------------------------------------------------------------------
TransferFunctionEditor::~TransferFunctionEditor() = default;

//------------------------------------------------------------------------------
void TransferFunctionEditor::SetProperty(vtkVolumeProperty* property, const double range[2])
{
  this->Property = property;
  this->Range[0] = range[0];
  this->Range[1] = range[1] > range[0] ? range[1] : range[0] + 1.0;
  this->Update();
}

//------------------------------------------------------------------------------
vtkRenderer* TransferFunctionEditor::GetRenderer() const
{
  return this->Renderer;
}

//------------------------------------------------------------------------------
void TransferFunctionEditor::SetVisible(bool visible)
{
  this->Visible = visible;
  this->Renderer->SetDraw(visible ? 1 : 0);
  if (!visible)
  {
    this->DragNode = -1;
  }
}

//------------------------------------------------------------------------------
bool TransferFunctionEditor::Contains(int x, int y) const
{
  if (!this->Visible)
  {
    return false;
  }
  const int* origin = this->Renderer->GetOrigin();
  const int* size = this->Renderer->GetSize();
  return x >= origin[0] && x < origin[0] + size[0] && y >= origin[1] && y < origin[1] + size[1];
}

//------------------------------------------------------------------------------
void TransferFunctionEditor::ToFunction(int x, int y, double& scalar, double& opacity) const
{
  const int* origin = this->Renderer->GetOrigin();
  const int* size = this->Renderer->GetSize();
  const double u = (x - origin[0] + 0.5) / std::max(1, size[0]);
  const double v = (y - origin[1] + 0.5) / std::max(1, size[1]);
  const double t = std::min(1.0, std::max(0.0, (u - kPlotLeft) / (kPlotRight - kPlotLeft)));
  scalar = this->Range[0] + t * (this->Range[1] - this->Range[0]);
  opacity = std::min(1.0, std::max(0.0, (v - kPlotBottom) / (kPlotTop - kPlotBottom)));
}

//------------------------------------------------------------------------------
void TransferFunctionEditor::ToWindow(double scalar, double opacity, double& x, double& y) const
{
  const int* origin = this->Renderer->GetOrigin();
  const int* size = this->Renderer->GetSize();
  const double t = (scalar - this->Range[0]) / (this->Range[1] - this->Range[0]);
  x = origin[0] + (kPlotLeft + t * (kPlotRight - kPlotLeft)) * size[0];
  y = origin[1] + (kPlotBottom + opacity * (kPlotTop - kPlotBottom)) * size[1];
}

//------------------------------------------------------------------------------
bool TransferFunctionEditor::GetNodePosition(int node, double& x, double& y) const
{
  vtkPiecewiseFunction* opacity = this->Property ? this->Property->GetScalarOpacity() : nullptr;
  if (!opacity || node < 0 || node >= opacity->GetSize())
  {
    return false;
  }
  double value[4];
  opacity->GetNodeValue(node, value);
  this->ToWindow(value[0], value[1], x, y);
  return true;
}

//------------------------------------------------------------------------------
void TransferFunctionEditor::GetPlotPosition(double t, double opacity, double& x, double& y) const
{
  this->ToWindow(this->Range[0] + t * (this->Range[1] - this->Range[0]), opacity, x, y);
}

//------------------------------------------------------------------------------
int TransferFunctionEditor::NodeAt(int x, int y) const
{
  vtkPiecewiseFunction* opacity = this->Property ? this->Property->GetScalarOpacity() : nullptr;
  if (!opacity)
  {
    return -1;
  }
  int best = -1;
  double bestDistance = kPickPixels;
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double node[4];
    opacity->GetNodeValue(i, node);
    double nx, ny;
    this->ToWindow(node[0], node[1], nx, ny);
    const double distance = std::hypot(nx - x, ny - y);
    if (distance <= bestDistance)
    {
      bestDistance = distance;
      best = i;
    }
  }
  return best;
}

//------------------------------------------------------------------------------
bool TransferFunctionEditor::Press(int button, int x, int y)
{
  if (!this->Contains(x, y) || !this->Property)
  {
    return false;
  }
  vtkPiecewiseFunction* opacity = this->Property->GetScalarOpacity();
  const int node = this->NodeAt(x, y);
  if (button == 2)
  {
    // Remove the node under the pointer; two always stay.
    if (node >= 0 && opacity->GetSize() > 2)
    {
      double value[4];
      opacity->GetNodeValue(node, value);
      opacity->RemovePoint(value[0]);
      this->Update();
      return true;
    }
    return true;
  }
  if (button != 0)
  {
    return true;
  }
  if (node >= 0)
  {
    this->DragNode = node;
    return true;
  }
  double scalar, alpha;
  this->ToFunction(x, y, scalar, alpha);
  this->DragNode = opacity->AddPoint(scalar, alpha);
  this->Update();
  return true;
}

//------------------------------------------------------------------------------
bool TransferFunctionEditor::Move(int x, int y)
{
  if (this->DragNode < 0 || !this->Property)
  {
    return false;
  }
  vtkPiecewiseFunction* opacity = this->Property->GetScalarOpacity();
  const int n = opacity->GetSize();
  if (this->DragNode >= n)
  {
    this->DragNode = -1;
    return false;
  }
  double scalar, alpha;
  this->ToFunction(x, y, scalar, alpha);
  // Between the neighbours (a node cannot pass another): keeps the index.
  const double span = this->Range[1] - this->Range[0];
  const double gap = 1e-4 * span;
  double lo = this->Range[0], hi = this->Range[1];
  double neighbour[4];
  if (this->DragNode > 0)
  {
    opacity->GetNodeValue(this->DragNode - 1, neighbour);
    lo = neighbour[0] + gap;
  }
  if (this->DragNode + 1 < n)
  {
    opacity->GetNodeValue(this->DragNode + 1, neighbour);
    hi = neighbour[0] - gap;
  }
  scalar = std::min(hi, std::max(lo, scalar));
  double value[4];
  opacity->GetNodeValue(this->DragNode, value);
  value[0] = scalar;
  value[1] = alpha;
  opacity->SetNodeValue(this->DragNode, value);
  this->Update();
  return true;
}

//------------------------------------------------------------------------------
bool TransferFunctionEditor::Release(int x, int y)
{
  const bool changed = this->Move(x, y);
  this->DragNode = -1;
  return changed;
}

//------------------------------------------------------------------------------
std::string TransferFunctionEditor::GetColorPresetName() const
{
  return kPresets[this->Preset].Name;
}

//------------------------------------------------------------------------------
int TransferFunctionEditor::GetNumberOfColorPresets()
{
  return kNumberOfPresets;
}

//------------------------------------------------------------------------------
void TransferFunctionEditor::NextColorPreset()
{
  this->SetColorPreset((this->Preset + 1) % kNumberOfPresets);
}

//------------------------------------------------------------------------------
void TransferFunctionEditor::SetColorPreset(int index)
{
  this->Preset = std::min(kNumberOfPresets - 1, std::max(0, index));
  if (!this->Property)
  {
    return;
  }
  vtkColorTransferFunction* color = this->Property->GetRGBTransferFunction();
  color->RemoveAllPoints();
  const ColorPreset& preset = kPresets[this->Preset];
  for (int i = 0; i < preset.Count; ++i)
  {
    const ColorNode& node = preset.Nodes[i];
    color->AddRGBPoint(
      this->Range[0] + node.T * (this->Range[1] - this->Range[0]), node.R, node.G, node.B);
  }
  this->Update();
}

//------------------------------------------------------------------------------
void TransferFunctionEditor::Update()
{
  if (!this->Property)
  {
    return;
  }
  // The colour bar: kBarSteps quads, each vertex coloured by the map.
  vtkColorTransferFunction* color = this->Property->GetRGBTransferFunction();
  vtkNew<vtkPoints> barPoints;
  vtkNew<vtkCellArray> barQuads;
  vtkNew<vtkUnsignedCharArray> barColors;
  barColors->SetNumberOfComponents(3);
  for (int i = 0; i <= kBarSteps; ++i)
  {
    const double t = static_cast<double>(i) / kBarSteps;
    const double u = kPlotLeft + t * (kPlotRight - kPlotLeft);
    double rgb[3];
    color->GetColor(this->Range[0] + t * (this->Range[1] - this->Range[0]), rgb);
    const unsigned char c[3] = { static_cast<unsigned char>(255.0 * rgb[0] + 0.5),
      static_cast<unsigned char>(255.0 * rgb[1] + 0.5),
      static_cast<unsigned char>(255.0 * rgb[2] + 0.5) };
    barPoints->InsertNextPoint(u, kBarBottom, 0.0);
    barPoints->InsertNextPoint(u, kBarTop, 0.0);
    barColors->InsertNextTypedTuple(c);
    barColors->InsertNextTypedTuple(c);
    if (i > 0)
    {
      const vtkIdType q[4] = { 2 * i - 2, 2 * i, 2 * i + 1, 2 * i - 1 };
      barQuads->InsertNextCell(4, q);
    }
  }
  this->ColorBar->SetPoints(barPoints);
  this->ColorBar->SetPolys(barQuads);
  this->ColorBar->GetPointData()->SetScalars(barColors);

  // The opacity function: a polyline through its nodes, and the nodes.
  vtkPiecewiseFunction* opacity = this->Property->GetScalarOpacity();
  vtkNew<vtkPoints> nodePoints;
  vtkNew<vtkCellArray> line;
  vtkNew<vtkCellArray> vertices;
  const int n = opacity->GetSize();
  line->InsertNextCell(n);
  for (int i = 0; i < n; ++i)
  {
    double node[4];
    opacity->GetNodeValue(i, node);
    const double t = (node[0] - this->Range[0]) / (this->Range[1] - this->Range[0]);
    nodePoints->InsertNextPoint(kPlotLeft + t * (kPlotRight - kPlotLeft),
      kPlotBottom + node[1] * (kPlotTop - kPlotBottom), 0.0);
    line->InsertCellPoint(i);
    const vtkIdType id = i;
    vertices->InsertNextCell(1, &id);
  }
  this->Curve->SetPoints(nodePoints);
  this->Curve->SetLines(line);
  this->Nodes->SetPoints(nodePoints);
  this->Nodes->SetVerts(vertices);
  for (vtkPolyData* data :
    { this->ColorBar.GetPointer(), this->Curve.GetPointer(), this->Nodes.GetPointer() })
  {
    data->Modified();
  }
}
}
