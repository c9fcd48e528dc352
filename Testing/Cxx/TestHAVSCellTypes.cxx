/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSCellTypes.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Every cell type a user brings (issue 19), through both mappers at their
// defaults against the exact reference (havsTestCells.h: the views, the image
// size, "exact", the edge pixels left out): hexahedra (interior points moved:
// warped cells), wedges, pyramids, voxels, a block mixing the four, quadratic
// tetrahedra, quadratic and triquadratic hexahedra, and vtkImageData,
// vtkRectilinearGrid and vtkStructuredGrid fed as they are, each carrying the
// linear field s = x + 2y + 3z on the unit cube. A linear field is integrated
// exactly by any tessellation of the cube, so every image must equal the exact
// image of the cube cut into the project's own tetrahedra (a closed form
// independent of how the cells were split); and no cracks: after the split, the
// number of boundary triangles is that of the cube's surface (2 per boundary
// quadrilateral). Control: hexahedra split by one fixed five-tetrahedron
// pattern (neighbours disagree on the shared diagonals: cracks) fail both.
//
// Usage: TestHAVSCellTypes [full]   (full: every view for the warped and mixed cells)
#include "havsTestCells.h"
#include "havsTestChecks.h"
#include "havsTestProperties.h"

#include "vtkDoubleArray.h"
#include "vtkHAVSDataSets.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkRectilinearGrid.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>
#include <string>

using namespace havstest::cells;

int TestHAVSCellTypes(int argc, char* argv[])
{
  const bool everyView = argc > 1 && std::string(argv[1]) == "full";
  const int n = 4;
  // The closed form: the cube in the project's own tetrahedra, the same field.
  auto cube = vtkHAVSDataSets::MakeBox(6, 6, 6, 1.0 / 6, 0.0, 1.0);
  SetLinearField(cube);
  auto property = havstest::MakeRampProperty(0.0, 6.0, 0.8, 0.25);
  const vtkIdType surface = 6 * 2 * n * n;

  auto hexes = CubeGrid(n, 0.25, [](int, int, int) { return CubeAs::Hexahedron; });
  auto wedges = CubeGrid(n, 0.25, [](int, int, int) { return CubeAs::Wedges; });
  auto pyramids = CubeGrid(n, 0.25, [](int, int, int) { return CubeAs::Pyramids; });
  auto voxels = CubeGrid(n, 0.0, [](int, int, int) { return CubeAs::Voxel; });
  // Slabs along x, so that every shared face is a quadrilateral on both
  // sides (a wedge's triangles only meet wedges): a conforming mixed mesh.
  auto mixed = CubeGrid(n, 0.0,
    [](int i, int, int)
    {
      return i < 1 ? CubeAs::Voxel
                   : (i < 2 ? CubeAs::Hexahedron : (i < 3 ? CubeAs::Wedges : CubeAs::Pyramids));
    });
  auto quadratic = QuadraticTetrahedra(3);
  auto quadraticHexes = QuadraticHexahedra(3, false);
  auto triquadraticHexes = QuadraticHexahedra(3, true);

  vtkNew<vtkImageData> image;
  image->SetDimensions(n + 1, n + 1, n + 1);
  image->SetSpacing(1.0 / n, 1.0 / n, 1.0 / n);
  SetLinearField(image);
  vtkNew<vtkRectilinearGrid> rectilinear;
  rectilinear->SetDimensions(n + 1, n + 1, n + 1);
  {
    const double xs[] = { 0.0, 0.1, 0.35, 0.7, 1.0 };
    vtkNew<vtkDoubleArray> x, y, z;
    for (double v : xs)
    {
      x->InsertNextValue(v);
      y->InsertNextValue(v * v);
      z->InsertNextValue(std::sqrt(v));
    }
    rectilinear->SetXCoordinates(x);
    rectilinear->SetYCoordinates(y);
    rectilinear->SetZCoordinates(z);
  }
  SetLinearField(rectilinear);
  vtkNew<vtkStructuredGrid> structured;
  structured->SetDimensions(n + 1, n + 1, n + 1);
  structured->SetPoints(LatticePoints(n, 0.25));
  SetLinearField(structured);

  struct Case
  {
    const char* Name;
    vtkDataSet* Data;
    vtkIdType Surface;
  };
  // The quadratic box's faces are each split in 4 (at the mid-edge nodes).
  const Case cases[] = { { "warped hexahedra", hexes, surface }, { "wedges", wedges, surface },
    { "pyramids", pyramids, surface }, { "voxels", voxels, surface },
    { "mixed: voxels, hexahedra, wedges, pyramids", mixed, surface },
    { "quadratic tetrahedra", quadratic, 4 * 6 * 2 * 3 * 3 },
    // VTK's split: a 20-node face into 6 triangles, a 27-node face into 8.
    { "quadratic hexahedra (20 nodes)", quadraticHexes, 6 * 3 * 3 * 6 },
    { "triquadratic hexahedra (27 nodes)", triquadraticHexes, 6 * 3 * 3 * 8 },
    { "vtkImageData as it is", image, surface },
    { "vtkRectilinearGrid as it is", rectilinear, surface },
    { "vtkStructuredGrid (warped) as it is", structured, surface } };
  for (const Case& c : cases)
  {
    const vtkIdType boundary = BoundaryTriangles(c.Data);
    std::printf("  %-66s boundary triangles %lld (cube surface %lld)\n", c.Name,
      static_cast<long long>(boundary), static_cast<long long>(c.Surface));
    havstest::Check(boundary == c.Surface, std::string(c.Name) + ": no cracks after the split");
    // Every view for the warped and mixed cells, two for the others (the suite's time).
    const bool allViews = everyView && (c.Data == hexes || c.Data == mixed);
    const auto d = WorstOverViews(c.Name, c.Data, cube, property, true, kEdge, allViews, everyView);
    Print(std::string(c.Name) + ": worst vs the closed form", d);
    havstest::Check(Exact(d), std::string(c.Name) + ": exact");
  }

  // Control: a split that neighbours do not agree on leaves cracks.
  auto cracked = CubeGrid(n, 0.25, [](int, int, int) { return CubeAs::FixedFiveTetrahedra; });
  const vtkIdType boundary = BoundaryTriangles(cracked);
  std::printf("  %-66s boundary triangles %lld (cube surface %lld)\n",
    "control: one fixed 5-tetrahedron split", static_cast<long long>(boundary),
    static_cast<long long>(surface));
  havstest::Check(boundary > surface, "control: the fixed split has cracks (counted)");
  const auto c = WorstOverViews("control: fixed split", cracked, cube, property, false);
  Print("control: one fixed 5-tetrahedron split, worst vs the closed form", c);
  havstest::Check(!Exact(c), "control: the fixed split's cracks show");
  return havstest::Result();
}
