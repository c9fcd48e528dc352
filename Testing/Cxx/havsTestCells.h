/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestCells.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestCells.h
 * @brief What the tests of the cells and scalars a user brings (issue 19) share.
 *
 * Both mappers at their defaults (vtkHAVSVolumeMapper: MPVO with the boundary
 * layers, k = 2; vtkHAVSCellProjectionMapper: the MPVO cell order), float
 * results, 96^2, three perspective views and a parallel one; "exact" is
 * MISSION's RMSE < 5e-4 and max < 0.01, leaving out 0.05 % (5) edge pixels as
 * the other exactness tests. The unit cube in cells of every linear and
 * quadratic type carrying the linear field s = x + 2y + 3z, whose exact image
 * is a closed form (the cube in the project's own tetrahedra).
 *
 * Used by TestHAVSCellTypes, TestHAVSCellScalars, TestHAVSVectorModes,
 * TestHAVSCompositeInput, TestHAVSTimeSteps, TestHAVSStructuredBluntFin and,
 * through havsTestShells, the subdivision tests.
 */
#ifndef havsTestCells_h
#define havsTestCells_h

#include "havsTestImages.h" // ImageDifference
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

class vtkDataObject;
class vtkDataSet;
class vtkHAVSReferenceRenderer;
class vtkPoints;
class vtkStructuredGrid;
class vtkUnstructuredGrid;
class vtkUnstructuredGridVolumeMapper;
class vtkVolumeProperty;

namespace havstest
{
namespace cells
{
/// The images' size (square) and the edge pixels left out of a comparison.
constexpr int kSize = 96;
constexpr size_t kEdge = 5; // 0.05 % of 96^2
// HAVS with cell scalars: the standard 5 (it was 7). Near a projected edge
// or vertex a ray crosses a chain of faces at nearly one distance, and the
// fragment that leaves last gives the next segment its cell; the k-buffer
// keeps the draw order among such internal near-ties (HAVS_CELL_TIE). The
// interpolated fragment distances differ by more than 3e-5 (relative) there:
// with that tie, 0 to 3 interior pixels a view of the box of tetrahedra
// were off by up to 0.17 (none at the silhouette); with 3e-4 none.
// What remains (1 to 3 pixels a view of the hollow sphere, at k = 2) are
// ties with a boundary fragment of its cavity, which keep the rank order.
// The cell projection integrates each cell on its own.
constexpr size_t kEdgeCellScalars = 5;

/// A view: azimuth, elevation, parallel.
struct View
{
  double Azimuth, Elevation;
  bool Parallel;
};
/// The views: three perspective ones and a parallel one (kViews[3]).
inline constexpr View kViews[] = { { 30, 20, false }, { 125, -35, false }, { 250, 50, false },
  { 60, 10, true } };

/// RMSE < 5e-4 and max < 0.01.
bool Exact(const havstest::ImageDifference& d);

/// Prints a difference under a name.
void Print(const std::string& what, const havstest::ImageDifference& d);

/// The linear field x + 2y + 3z.
double Linear(const double* x);

/// Sets the point array "s" = Linear(point) as the active scalars.
void SetLinearField(vtkDataSet* data);

/// The (n + 1)^3 points of an n^3 lattice on the unit cube, interior points
/// moved by up to `warp` cells (deterministically): warped cells.
vtkSmartPointer<vtkPoints> LatticePoints(int n, double warp);

/// How a cube of the lattice is cut into cells.
enum class CubeAs
{
  Hexahedron,
  Wedges,
  Pyramids,
  Voxel,
  FixedFiveTetrahedra // the control: neighbours disagree on shared diagonals
};

/// The unit cube in n^3 cubes, each cut as `as(i, j, k)` says; the linear field.
vtkSmartPointer<vtkUnstructuredGrid> CubeGrid(
  int n, double warp, const std::function<CubeAs(int, int, int)>& as);

/// Quadratic tetrahedra: the box's tetrahedra with a node at each edge's middle (shared).
vtkSmartPointer<vtkUnstructuredGrid> QuadraticTetrahedra(int n);

/// The unit cube in n^3 quadratic (20-node) or triquadratic (27-node)
/// hexahedra whose nodes lie on a lattice of 2n + 1 points per axis (shared).
vtkSmartPointer<vtkUnstructuredGrid> QuadraticHexahedra(int n, bool triquadratic);

/// A mapper at its defaults, its float result kept (HAVS without early termination).
vtkSmartPointer<vtkUnstructuredGridVolumeMapper> MakeMapper(bool cells);

/// "HAVS" or "cell projection".
const char* Name(bool cells);

/// What one frame gave: the mapper's image, the reference of `exactOf` seen
/// from the same camera, the mapper's messages.
struct Frame
{
  std::vector<float> Image;
  std::vector<float> Exact;
  int Errors = 0;
  int Warnings = 0;
  std::string Text; ///< the messages
};

/// `data` through `mapper` from `view`; the exact image of `exactOf` (the
/// same scene, or another grid standing for it) from the same camera.
Frame RenderAndReference(vtkDataObject* data, vtkUnstructuredGridVolumeMapper* mapper,
  vtkVolumeProperty* property, const View& view, vtkDataSet* exactOf,
  const std::function<void(vtkHAVSReferenceRenderer*)>& configure = nullptr);

/// Boundary triangles of `data` split into tetrahedra.
vtkIdType BoundaryTriangles(vtkDataSet* data);

/// The worst difference over the views and both mappers (or HAVS alone) of
/// `data` against the exact image of `exactOf`. `allViews`: every view, else
/// one perspective view and the parallel one; of those, unless `everyView`
/// (the `long` variants' "full"), HAVS draws the perspective view and the cell
/// projection the parallel one (the default suite, for its time).
havstest::ImageDifference WorstOverViews(const std::string& what, vtkDataSet* data,
  vtkDataSet* exactOf, vtkVolumeProperty* property, bool bothMappers = true,
  size_t havsEdge = kEdge, bool allViews = true, bool everyView = false);

/// `data` with a cell array "c" from its cells' centres, the active cell scalars; no point scalars.
vtkSmartPointer<vtkUnstructuredGrid> WithCellField(vtkUnstructuredGrid* data);
vtkSmartPointer<vtkStructuredGrid> WithCellField(vtkStructuredGrid* data);
}
}

#endif
