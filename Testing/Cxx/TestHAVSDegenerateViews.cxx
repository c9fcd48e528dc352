/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSDegenerateViews.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Degenerate views (issue 20) of an axis-aligned box of 4^3 cubes (5
// tetrahedra each, s = z): orthographic views exactly along +z, +x and -y
// with pixel centres on the grid lines (every face parallel to the view
// direction is seen edge-on, rays run along internal faces); perspective
// views with the eye exactly on a face plane, on an edge and on a vertex of
// the lattice (outside the box, looking at it). Each through both mappers
// against the exact reference, finite; control: the reference of the view
// turned by 25 degrees.
// (havsTestStress.h: "exact", the edge pixels left out, the variants; on the
// cell-data path CheckViewOnJumps.)
//
// Usage: TestHAVSDegenerateViews
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"
#include "havsTestStress.h"

#include "vtkCamera.h"
#include "vtkHAVSDataSets.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <string>

using namespace havstest::stress;

int TestHAVSDegenerateViews(int, char*[])
{
  auto box = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(box);
  const int size = 65; // odd: with the scale below, pixel centres fall on the grid lines
  struct View
  {
    const char* Name;
    bool Parallel;
    double Position[3];
    double Up[3];
  };
  const View views[] = {
    { "orthographic along -z", true, { 0.5, 0.5, 5.0 }, { 0, 1, 0 } },
    { "orthographic along -x", true, { 5.0, 0.5, 0.5 }, { 0, 0, 1 } },
    { "orthographic along +y", true, { 0.5, -5.0, 0.5 }, { 0, 0, 1 } },
    { "eye on a face plane (x = 0.5)", false, { 0.5, -1.3, 0.37 }, { 0, 0, 1 } },
    { "eye on an edge (x = 0.5, z = 0.75)", false, { 0.5, -1.3, 0.75 }, { 0, 0, 1 } },
    { "eye on a vertex line (x = 0.25, y = 0.75, z = 1.5)", false, { 0.25, 0.75, 1.5 },
      { 0, 1, 0 } },
  };
  for (const View& view : views)
  {
    for (bool cells : { false, true })
    {
      auto mapper = MakeMapper(cells);
      auto s = havstest::MakeScene(OnPath(box), mapper, property, size, size);
      vtkCamera* camera = s.Renderer->GetActiveCamera();
      camera->SetParallelProjection(view.Parallel ? 1 : 0);
      camera->SetPosition(view.Position);
      // Perspective: look at a lattice point so that the eye's plane, edge or
      // vertex line passes through the view; parallel: at the box's centre.
      if (view.Parallel)
      {
        camera->SetFocalPoint(0.5, 0.5, 0.5);
      }
      else
      {
        camera->SetFocalPoint(view.Position[0], 0.5, view.Position[1] < 0 ? view.Position[2] : 0.5);
      }
      camera->SetViewUp(view.Up);
      camera->SetViewAngle(50.0);
      // 0.025 per pixel: the grid lines (every 0.25) every 10 pixels, and
      // an odd window's pixel centres on the centre line, so on the lines.
      camera->SetParallelScale(0.5 * size * 0.025);
      s.Renderer->ResetCameraClippingRange();
      s.Window->Render();
      const std::string what = std::string(Name(cells)) + ", " + view.Name;
      if (Path() == StressPath::CellData)
      {
        CheckViewOnJumps(what, havstest::FloatResult(mapper), box, property, camera, size);
      }
      else
      {
        CheckView(what, DrewSubset(mapper), havstest::FloatResult(mapper), box, property, camera,
          size, size * size / 10);
      }
    }
  }
  return havstest::Result();
}
