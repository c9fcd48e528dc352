/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSBadInput.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Bad input gets a clear error or warning and a defined result: no crash, no
// NaN pixel, and a good input afterwards renders correctly (no corrupted
// later frame). The defined result of a frame with an error is nothing: the
// window shows the background and no float result is kept; a frame without
// one keeps a finite float result and draws something. Controls: AllFinite
// sees a NaN, and the background check fails on a drawn frame.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkHAVSVisibilityOrder.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkHexahedron.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>

namespace
{
struct Outcome
{
  int Errors = 0;
  int Warnings = 0;
  std::vector<float> Window;
  std::vector<float> Result;
  std::string Text;
  vtkIdType Degenerate = 0; ///< the mapper's GetNumberOfDegenerateTetrahedra()
};

bool AllZeroAlphaBackground(const std::vector<float>& rgba)
{
  for (size_t p = 0; p < rgba.size() / 4; ++p)
  {
    if (rgba[4 * p] != 0.0f || rgba[4 * p + 1] != 0.0f || rgba[4 * p + 2] != 0.0f)
    {
      return false;
    }
  }
  return true;
}

/// A frame with an error draws nothing and keeps no result; a frame without
/// one keeps a finite result and draws something.
void CheckDefinedResult(int errors, const std::vector<float>& window,
  const std::vector<float>& result, const std::string& name)
{
  if (errors > 0)
  {
    havstest::Check(AllZeroAlphaBackground(window) && result.empty(),
      name + ": after the error nothing is drawn and no result kept");
  }
  else
  {
    havstest::Check(
      !result.empty() && havstest::AllFinite(result), name + ": a finite float result");
    havstest::Check(!AllZeroAlphaBackground(window), name + ": something drawn");
  }
}

Outcome RenderOnce(vtkUnstructuredGrid* grid, const std::string& name)
{
  auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.3);
  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->KeepFloatResultOn();
  havstest::Messages* messages = havstest::CountMessages(mapper);
  auto scene = havstest::MakeScene(grid, mapper, property, 48, 48);
  scene.Renderer->GetActiveCamera();
  scene.Renderer->ResetCamera(0, 1, 0, 1, 0, 1);
  scene.Window->Render();
  Outcome out;
  out.Errors = messages->Errors;
  out.Warnings = messages->Warnings;
  out.Text = messages->Text;
  out.Window = havstest::ReadRGBA(scene.Window);
  out.Result = havstest::FloatResult(mapper);
  out.Degenerate = mapper->GetNumberOfDegenerateTetrahedra();
  std::cout << name << ": " << out.Errors << " errors, " << out.Warnings
            << " warnings: " << out.Text << std::endl;
  CheckDefinedResult(messages->Errors, out.Window, out.Result, name);

  // The exact orders on the same input: no crash, the same defined result.
  const char* orders[3] = { "MPVO + convexification", "MPVO + boundary layers", "Automatic" };
  for (int o = 0; o < 3; ++o)
  {
    vtkNew<vtkHAVSVolumeMapper> exact;
    exact->KeepFloatResultOn();
    havstest::Messages* exactMessages = havstest::CountMessages(exact);
    if (o < 2)
    {
      exact->SetVisibilityOrderToMPVO();
      exact->SetNonConvexMethod(o == 0 ? vtkHAVSVisibilityOrder::NonConvexConvexification
                                       : vtkHAVSVisibilityOrder::NonConvexBoundaryLayers);
    }
    else
    {
      exact->SetVisibilityOrderToAutomatic();
    }
    auto other = havstest::MakeScene(grid, exact, property, 48, 48);
    other.Renderer->ResetCamera(0, 1, 0, 1, 0, 1);
    other.Window->Render();
    CheckDefinedResult(exactMessages->Errors, havstest::ReadRGBA(other.Window),
      havstest::FloatResult(exact), name + ", " + orders[o]);
  }
  return out;
}

bool Contains(const std::string& text, const std::string& what)
{
  return text.find(what) != std::string::npos;
}

}

int TestHAVSBadInput(int, char*[])
{
  // Controls: the checks of a defined result can fail.
  havstest::Check(!havstest::AllFinite({ 0.5f, std::numeric_limits<float>::quiet_NaN() }),
    "control: AllFinite sees a NaN");
  havstest::Check(!AllZeroAlphaBackground({ 0.0f, 0.0f, 0.0f, 1.0f, 0.2f, 0.0f, 0.0f, 1.0f }),
    "control: a drawn pixel is not background");
  // Empty grid.
  {
    vtkNew<vtkUnstructuredGrid> empty;
    Outcome o = RenderOnce(empty, "empty grid");
    havstest::Check(o.Errors == 1 && Contains(o.Text, "empty"), "empty grid: one clear error");
    havstest::Check(AllZeroAlphaBackground(o.Window), "empty grid: nothing drawn");
  }
  // No scalars.
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    grid->GetPointData()->SetScalars(nullptr);
    grid->GetPointData()->RemoveArray("s");
    Outcome o = RenderOnce(grid, "no scalars");
    havstest::Check(o.Errors == 1 && Contains(o.Text, "no scalars"), "no scalars: clear error");
    havstest::Check(AllZeroAlphaBackground(o.Window), "no scalars: nothing drawn");
  }
  // NaN and infinite scalars.
  {
    auto grid = vtkHAVSDataSets::MakeBox(3, 3, 3, 1.0 / 3, 0.0, 1.0);
    vtkDataArray* s = grid->GetPointData()->GetScalars();
    s->SetComponent(0, 0, std::numeric_limits<double>::quiet_NaN());
    s->SetComponent(5, 0, std::numeric_limits<double>::infinity());
    s->SetComponent(7, 0, -std::numeric_limits<double>::infinity());
    Outcome o = RenderOnce(grid, "NaN/Inf scalars");
    havstest::Check(o.Warnings >= 1 && Contains(o.Text, "NaN"), "NaN scalars: warning");
    havstest::Check(!o.Result.empty(), "NaN scalars: still rendered");
  }
  // All scalars NaN.
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    vtkDataArray* s = grid->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
    {
      s->SetComponent(i, 0, std::numeric_limits<double>::quiet_NaN());
    }
    Outcome o = RenderOnce(grid, "all-NaN scalars");
    havstest::Check(o.Errors == 1, "all-NaN scalars: error");
  }
  // A polygon next to tetrahedra: skipped with a warning; only polygons: error.
  // (A hexahedron is split into tetrahedra: TestHAVSCellTypes.)
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    vtkIdType quad[4] = { 0, 1, 4, 3 };
    grid->InsertNextCell(VTK_QUAD, 4, quad);
    Outcome o = RenderOnce(grid, "tets + a quadrilateral");
    havstest::Check(o.Warnings >= 1 && Contains(o.Text, "not 3D"), "quad: warning");
    havstest::Check(!o.Result.empty(), "quad: the tetrahedra still render");

    vtkNew<vtkUnstructuredGrid> quadOnly;
    quadOnly->SetPoints(grid->GetPoints());
    quadOnly->GetPointData()->ShallowCopy(grid->GetPointData());
    quadOnly->Allocate(1);
    quadOnly->InsertNextCell(VTK_QUAD, 4, quad);
    Outcome h = RenderOnce(quadOnly, "only a quadrilateral");
    havstest::Check(h.Errors >= 1 && Contains(h.Text, "No 3D cells"), "only polygons: error");
  }
  // Degenerate (flat) tetrahedra among good ones.
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    vtkIdType flat[4] = { 0, 1, 2, 2 }; // repeated point
    grid->InsertNextCell(VTK_TETRA, 4, flat);
    vtkIdType coplanar[4] = { 0, 1, 3, 4 }; // four points in the plane z = 0
    grid->InsertNextCell(VTK_TETRA, 4, coplanar);
    Outcome o = RenderOnce(grid, "degenerate tetrahedra");
    // 2 of 42: more than vtkHAVSMesh::DegenerateWarningShare (1 %), a broken mesh.
    havstest::Check(o.Warnings >= 1 && Contains(o.Text, "degenerate") && o.Degenerate == 2,
      "degenerate, 2 of 42: counted (" + std::to_string(o.Degenerate) + ") and warned");
  }
  // Collapsed tetrahedra (a point id repeated: what a wedge with two corners
  // merged gives, as ParaView's split at its kd cuts leaves) are dropped and
  // counted but say nothing about the mesh: no warning, even at 7 %.
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    const vtkIdType collapsed[3][4] = { { 0, 1, 2, 2 }, { 3, 3, 4, 5 }, { 6, 7, 6, 8 } };
    for (const auto& cell : collapsed)
    {
      grid->InsertNextCell(VTK_TETRA, 4, cell);
    }
    Outcome o = RenderOnce(grid, "collapsed tetrahedra");
    havstest::Check(o.Warnings == 0 && o.Degenerate == 3 && !o.Result.empty(),
      "collapsed, 3 of 43: counted (" + std::to_string(o.Degenerate) + "), no warning (" +
        std::to_string(o.Warnings) + ")");
  }
  // One zero-volume tetrahedron among 1,080 (a mesher's sliver, as the blunt
  // fin's 77 of 187,395): counted, no warning; the image as without it.
  {
    auto grid = vtkHAVSDataSets::MakeBox(6, 6, 6, 1.0 / 6, 0.0, 1.0);
    Outcome clean = RenderOnce(grid, "1,080 good tetrahedra");
    vtkIdType coplanar[4] = { 0, 1, 7, 8 }; // four points in the plane z = 0
    grid->InsertNextCell(VTK_TETRA, 4, coplanar);
    Outcome o = RenderOnce(grid, "one degenerate tetrahedron among 1,080");
    const double off = havstest::Compare(o.Result, clean.Result).Max;
    havstest::Check(o.Warnings == 0 && o.Degenerate == 1 && off == 0.0,
      "degenerate, 1 of 1,081: counted (" + std::to_string(o.Degenerate) + "), " +
        std::to_string(o.Warnings) + " warnings, the image unchanged (max " + std::to_string(off) +
        ")");
  }
  // Point ids out of range (a corrupt file's cells): skipped with a warning,
  // their points never read; the rest renders. Tetrahedra go to the face set
  // directly, other cells through the split (VTK's would read past the points).
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    const vtkIdType n = grid->GetNumberOfPoints();
    vtkIdType past[4] = { 0, 1, 2, n + 1000000 };
    grid->InsertNextCell(VTK_TETRA, 4, past);
    vtkIdType negative[4] = { 0, 1, -5, 3 };
    grid->InsertNextCell(VTK_TETRA, 4, negative);
    Outcome o = RenderOnce(grid, "tetrahedra with point ids out of range");
    havstest::Check(
      o.Warnings >= 1 && Contains(o.Text, "2 cells refer to points that do not exist"),
      "point ids out of range (tetrahedra): a warning that counts them");
  }
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    const vtkIdType n = grid->GetNumberOfPoints();
    vtkIdType hexahedron[8] = { 0, 1, 4, 3, 9, 10, 13, -7 };
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, hexahedron);
    vtkIdType wedge[6] = { 0, 1, 3, 9, 10, n };
    grid->InsertNextCell(VTK_WEDGE, 6, wedge);
    Outcome o = RenderOnce(grid, "other cells with point ids out of range");
    havstest::Check(
      o.Warnings >= 1 && Contains(o.Text, "2 cells refer to points that do not exist"),
      "point ids out of range (cells to split): a warning that counts them");
  }
  // Cell scalars render (their accuracy: TestHAVSCellScalars); field data: a clear error.
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    vtkNew<vtkDoubleArray> cellScalars;
    cellScalars->SetName("c");
    cellScalars->SetNumberOfTuples(grid->GetNumberOfCells());
    cellScalars->Fill(0.5);
    grid->GetPointData()->SetScalars(nullptr);
    grid->GetPointData()->RemoveArray("s");
    grid->GetCellData()->SetScalars(cellScalars);
    Outcome o = RenderOnce(grid, "cell scalars");
    havstest::Check(o.Errors == 0 && !o.Result.empty(), "cell scalars: rendered");

    vtkNew<vtkDoubleArray> field;
    field->SetName("f");
    field->SetNumberOfTuples(grid->GetNumberOfCells());
    field->Fill(0.5);
    grid->GetCellData()->SetScalars(nullptr);
    grid->GetCellData()->RemoveArray("c");
    grid->GetFieldData()->AddArray(field);
    vtkNew<vtkHAVSVolumeMapper> mapper;
    mapper->SetScalarMode(VTK_SCALAR_MODE_USE_FIELD_DATA);
    mapper->SelectScalarArray("f");
    havstest::Messages* messages = havstest::CountMessages(mapper);
    auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.3);
    auto scene = havstest::MakeScene(grid, mapper, property, 48, 48);
    scene.Window->Render();
    havstest::Check(messages->Errors >= 1 && Contains(messages->Text, "Field-data"),
      "field-data scalars: clear error");
  }
  // Unsupported property features: one warning each, not one per frame.
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.3);
    property->ShadeOn();
    property->GetGradientOpacity()->AddPoint(0.0, 0.2);
    property->GetGradientOpacity()->AddPoint(1.0, 1.0);
    vtkNew<vtkHAVSVolumeMapper> mapper;
    havstest::Messages* messages = havstest::CountMessages(mapper);
    auto scene = havstest::MakeScene(grid, mapper, property, 32, 32);
    scene.Window->Render();
    scene.Window->Render();
    std::cout << "shading + gradient opacity: " << messages->Warnings
              << " warnings: " << messages->Text << std::endl;
    havstest::Check(messages->Warnings == 2 && Contains(messages->Text, "Shading") &&
        Contains(messages->Text, "Gradient opacity"),
      "shading and gradient opacity: one warning each");
  }
  // Huge coordinates: the box moved by 1e7 renders as the box at the origin.
  {
    auto grid = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
    auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.3);
    vtkNew<vtkHAVSVolumeMapper> near, far;
    near->KeepFloatResultOn();
    far->KeepFloatResultOn();
    auto a = havstest::MakeScene(grid, near, property, 48, 48);
    havstest::PlaceCamera(a.Renderer, 30, 20, false);
    a.Window->Render();
    vtkNew<vtkUnstructuredGrid> moved;
    moved->DeepCopy(grid);
    // Double-precision points: a float cannot hold 1e7 + 0.25.
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToDouble();
    pts->SetNumberOfPoints(grid->GetNumberOfPoints());
    for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i)
    {
      double x[3];
      grid->GetPoint(i, x);
      pts->SetPoint(i, x[0] + 1e7, x[1] - 1e7, x[2] + 1e7);
    }
    moved->SetPoints(pts);
    auto b = havstest::MakeScene(moved, far, property, 48, 48);
    vtkCamera* ca = a.Renderer->GetActiveCamera();
    vtkCamera* cb = b.Renderer->GetActiveCamera();
    double p[3], f[3];
    ca->GetPosition(p);
    ca->GetFocalPoint(f);
    cb->SetPosition(p[0] + 1e7, p[1] - 1e7, p[2] + 1e7);
    cb->SetFocalPoint(f[0] + 1e7, f[1] - 1e7, f[2] + 1e7);
    cb->SetViewUp(ca->GetViewUp());
    cb->SetViewAngle(ca->GetViewAngle());
    cb->SetClippingRange(ca->GetClippingRange());
    b.Window->Render();
    const auto d = havstest::Compare(havstest::FloatResult(near), havstest::FloatResult(far));
    std::cout << "huge coordinates (1e7 offset): RMSE " << d.RMSE << ", max " << d.Max << std::endl;
    havstest::Check(d.RMSE < 5e-3, "huge coordinates render as at the origin");
  }
  // A zero-size viewport: nothing happens, no error.
  {
    auto grid = vtkHAVSDataSets::MakeBox(2, 2, 2, 0.5, 0.0, 1.0);
    auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, 0.3);
    vtkNew<vtkHAVSVolumeMapper> mapper;
    havstest::Messages* messages = havstest::CountMessages(mapper);
    auto scene = havstest::MakeScene(grid, mapper, property, 48, 48);
    scene.Renderer->SetViewport(0.2, 0.2, 0.2, 0.2);
    scene.Window->Render();
    havstest::Check(messages->Errors == 0, "zero-size viewport: no error");
  }
  // After bad input, a good input renders correctly with the same mapper.
  {
    auto property = havstest::MakeConstantProperty(0.2, 0.6, 0.9, 0.5, 0.5);
    vtkNew<vtkHAVSVolumeMapper> mapper;
    mapper->KeepFloatResultOn();
    mapper->SetEarlyRayTerminationOpacity(1.0);
    vtkNew<vtkUnstructuredGrid> empty;
    havstest::CountMessages(mapper);
    auto scene = havstest::MakeScene(empty, mapper, property, 48, 48);
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(0.5, 0.5, 0.5);
    camera->SetPosition(0.5, 0.5, 10.0);
    camera->SetParallelScale(0.8);
    scene.Renderer->ResetCameraClippingRange();
    scene.Window->Render();
    auto good = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.5, 0.0);
    mapper->SetInputData(good);
    scene.Window->Render();
    const std::vector<float> result = havstest::FloatResult(mapper);
    const float alpha = result.empty() ? -1.0f : result[4 * (24 * 48 + 24) + 3];
    std::cout << "good input after bad: centre alpha " << alpha << std::endl;
    havstest::Check(std::fabs(alpha - (1.0 - std::exp(-1.0))) < 1e-3,
      "a good input after a bad one renders the closed form");
  }
  return havstest::Result();
}
