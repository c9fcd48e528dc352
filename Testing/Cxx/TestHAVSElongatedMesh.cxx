/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSElongatedMesh.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// A mesh 1e6 times longer than wide (issue 20): [0, 3e6] x [0, 3] x [0, 3]
// in 3^3 boxes of 5 tetrahedra, every cell 1e6 long and 1 wide, points as
// double, s = (z + x / 1e6) / 6. Seen along its axis orthographically (every
// ray through the whole length, a clipping range of 6e6 : 1; HAVS only), and
// from the side, where rays cross the needles' long faces: the middle from
// 10 away in perspective, the middle orthographically 45 degrees off the
// axis, and near one end in perspective (unit distance 5; HAVS and the cell
// projection). Each against the exact reference, finite, no message; the
// axis view exact (RMSE < 5e-4, max < 0.01), the side views within RMSE
// 1e-3, max 0.01 (measured: HAVS 4.2e-4 to 6.0e-4, max up to 5.6e-3; the
// same views of a slab of unit cubes at the same place give 4.5e-5 to
// 1.0e-4: the rest is the float positions across triangles 1e6 long).
// Control: the reference of the view turned by 25 degrees. The reference
// itself was checked on the middle views: the slab [1.5e6 - 12, 1.5e6 + 12]
// x [0, 3] x [0, 3] in unit cubes with the same linear field holds every
// ray's part inside the mesh, and its reference image is bit-identical to
// the elongated mesh's. (Before this case the face set dropped every such
// cell as degenerate, and the reference renderer's missing image crashed the
// test. An earlier session measured the side views at RMSE 0.16 and 0.098 and
// left them out; which change since made them pass was not traced: the
// table's logarithmic length axis and the parallel camera's eye moved near
// the volume are the candidates.)
//
// Limit this mesh shows: the cell projection along the axis, where rays on
// the pixel diagonals run within 1e-6 (relative) of the needles' diagonal
// faces over their whole 1e6 length: RMSE 5.8e-3, max 0.14 (0.19 before its
// parallel-face bound was lowered). Checked against a stated bound, RMSE
// 1e-2 and max 0.2 (the turned view's control: RMSE 0.35, max 0.83).
// (havsTestStress.h: the variants; on the cell-data path CheckViewOnJumps.)
//
// Usage: TestHAVSElongatedMesh
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"
#include "havsTestStress.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <string>

using namespace havstest::stress;

int TestHAVSElongatedMesh(int, char*[])
{
  const double length = 1e6;
  auto grid = MakeElongated(length);
  double bounds[6];
  grid->GetBounds(bounds);
  std::printf("elongated mesh: %lld tetrahedra, %.3g x %.3g x %.3g (length / width %.0e)\n",
    static_cast<long long>(grid->GetNumberOfCells()), bounds[1] - bounds[0], bounds[3] - bounds[2],
    bounds[5] - bounds[4], (bounds[1] - bounds[0]) / (bounds[3] - bounds[2]));
  struct View
  {
    const char* Name;
    bool Parallel;
    double Position[3];
    double Focal[3];
    double UnitDistance;
    bool CellProjection; // checked for the cell projection too
    double Far;          // the far clipping plane
    double RMSEBound;    // against the exact reference (max 0.01 for all)
  };
  const double m = 1.5e6; // the middle
  const View views[] = {
    { "along the axis, orthographic", true, { -10.0, 1.5, 1.5 }, { 3e6, 1.5, 1.5 }, length, true,
      3.1 * length + 20.0, 5e-4 },
    { "the middle from 10 away, perspective", false, { m, -10.0, 1.5 }, { m, 1.5, 1.5 }, 5.0, true,
      30.0, 1e-3 },
    { "the middle, orthographic 45 degrees off the axis", true, { m - 8.0, -8.0, 1.5 },
      { m, 1.5, 1.5 }, 5.0, true, 30.0, 1e-3 },
    { "near one end, perspective", false, { -6.0, -8.0, 1.5 }, { 4.0, 1.5, 1.5 }, 5.0, true, 40.0,
      1e-3 },
  };

  const int size = kPairSize;
  for (const View& view : views)
  {
    auto property = havstest::MakeRampProperty(0.0, 1.0, 0.8, view.UnitDistance);
    for (bool cells : { false, true })
    {
      if (cells && !view.CellProjection)
      {
        continue;
      }
      auto mapper = MakeMapper(cells);
      havstest::Messages* messages = havstest::CountMessages(mapper);
      auto sc = havstest::MakeScene(OnPath(grid), mapper, property, size, size);
      vtkCamera* camera = sc.Renderer->GetActiveCamera();
      camera->SetParallelProjection(view.Parallel ? 1 : 0);
      camera->SetPosition(view.Position);
      camera->SetFocalPoint(view.Focal);
      camera->SetViewUp(0.0, 0.0, 1.0);
      camera->SetParallelScale(2.0);
      // Explicit: VTK's reset would put the near plane 1e-3 of the far one
      // away, in front of which these views look.
      camera->SetClippingRange(0.5, view.Far);
      sc.Window->Render();
      const std::string what = std::string(Name(cells)) + ", elongated, " + view.Name;
      std::printf("  clipping range %.3g .. %.3g\n", camera->GetClippingRange()[0],
        camera->GetClippingRange()[1]);
      // The cell projection along the axis: a stated bound (see above).
      const bool axis = &view == &views[0];
      const bool axisCells = cells && axis;
      if (Path() == StressPath::CellData && !cells && axis)
      {
        // Cell scalars, along the axis: rays on the faces that contain the
        // axis direction run along the scalar's jumps (see CheckViewOnJumps).
        // A stated bound: the rays on the pixel diagonals, which pass
        // exactly through the needles' long diagonal edges (the locus of the
        // cell projection's error above), are off by up to 0.06 at 71 of
        // 9216 pixels (outside every nudged reference's value; RMSE 9.3e-4
        // over the pixels where the nudged references agree). With point
        // scalars the field is linear, so a missed face there costs nothing
        // and HAVS is exact (4.3e-5); with cell scalars a missed crossing
        // changes which cell a segment reads. Cause not traced. Bound: at
        // most 1.5 % of the pixels outside, RMSE 2e-3, max 0.1; the control
        // (another view) puts 5184 outside.
        CheckViewOnJumps(what, havstest::FloatResult(mapper), grid, property, camera, size,
          size * size * 3 / 200, { 2e-3, 0.1 });
      }
      else
      {
        CheckView(what, DrewSubset(mapper), havstest::FloatResult(mapper), grid, property, camera,
          size, size * size / 20, axisCells ? 1e-2 : view.RMSEBound, axisCells ? 0.2 : 0.01);
      }
      havstest::Check(messages->Errors == 0 && messages->Warnings == 0, what + ": no message");
    }
  }
  return havstest::Result();
}
