/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestShells.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestShells.h
 * @brief The subdivision tests' meshes and checks (issue 19): a cylindrical
 * shell sector (rho in [1, 2], theta in [0, pi/2], z in [0, 1]) in curved
 * higher-order cells; their volume by quadrature; the checks of their
 * tessellation (SetHigherOrderSubdivision: the volume converging, no cracks,
 * the fields exact at the new points) and of their rendering at a level.
 *
 * Used by TestHAVSQuadraticSubdivision, TestHAVSPyramidSubdivision,
 * TestHAVSHigherOrderSubdivision and TestHAVSTimeSteps (time steps on
 * tessellated meshes).
 */
#ifndef havsTestShells_h
#define havsTestShells_h

#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

class vtkDataSet;
class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace havstest
{
namespace cells
{
/// The shell sector: radii, height, its angle.
constexpr double kInner = 1.0, kOuter = 2.0, kHeight = 1.0;
constexpr double kQuarter = 1.5707963267948966;

/// The curved shell in m[0] x m[1] x m[2] quadratic hexahedra (every other
/// cell's node order turned a quarter about its third axis, so neighbours
/// see a shared face in different local frames) or in six quadratic
/// tetrahedra per box (Kuhn's split of the parameter box: conforming).
enum ShellCells
{
  ShellHexahedra20,
  ShellTetrahedra10,
  ShellHexahedra27,
  ShellWedges15,
  ShellLagrangeHexahedra,
  ShellMixed ///< 20-node hexahedra at i = 0, quadratic wedges elsewhere
};

vtkSmartPointer<vtkUnstructuredGrid> CurvedShell(const int m[3], int kind);

/// The summed volumes of a grid of tetrahedra.
double TetrahedraVolume(vtkUnstructuredGrid* tets);

/// A quadratic field (a sheared straight cell's quadratic interpolation reproduces it).
double Quadratic(const double* x);

/// The straight cells' test: the curved shell's points mapped back onto its
/// parameters (the cylinder undone) and sheared, a box of volume 0.865 (the
/// shear's determinant); point scalars "q" = `field`.
constexpr double kShearedVolume = 0.865;
void ShearBack(vtkUnstructuredGrid* grid, double (*field)(const double*));

/// The largest difference between the active point scalars of `grid`'s
/// points from `first` on and `field` at their positions.
double FieldError(vtkDataSet* grid, vtkIdType first, double (*field)(const double*));

/// The shell sector's nodes placed at any box-lattice parameter (multiples of
/// 1/24 of a box), shared by the cells that name them.
class ShellNodes
{
public:
  explicit ShellNodes(const int m[3])
  {
    std::copy_n(m, 3, this->M);
    this->Points->SetDataTypeToDouble();
  }
  /// The point at box-lattice parameters (a, b, c) in [0, m].
  vtkIdType Id(double a, double b, double c)
  {
    const std::array<long long, 3> key = { std::llround(24.0 * a), std::llround(24.0 * b),
      std::llround(24.0 * c) };
    auto found = this->Ids.find(key);
    if (found != this->Ids.end())
    {
      return found->second;
    }
    const double rho = kInner + (kOuter - kInner) * key[0] / (24.0 * this->M[0]);
    const double theta = kQuarter * key[1] / (24.0 * this->M[1]);
    const vtkIdType id = this->Points->InsertNextPoint(
      rho * std::cos(theta), rho * std::sin(theta), kHeight * key[2] / (24.0 * this->M[2]));
    this->Ids.emplace(key, id);
    return id;
  }
  vtkNew<vtkPoints> Points;

private:
  int M[3];
  std::map<std::array<long long, 3>, vtkIdType> Ids;
};

using Param = std::array<double, 3>;

/// The corners `v` of a tetrahedron (box-lattice parameters) reordered, if
/// needed, to be positively oriented (v[1] and v[2] swapped).
void OrientPositive(std::array<Param, 4>& v);

/// A level-2 control of the refinement (`split`: vtkHAVSTetrahedralizer's
/// SplitLocalOrder or SplitUnmerged): `grid` tetrahedralized that way, its
/// boundary triangles into `boundary`, printed beside `refinedSurface`.
vtkSmartPointer<vtkUnstructuredGrid> SplitControl(
  vtkDataSet* grid, int split, vtkIdType refinedSurface, vtkIdType* boundary);

/// The curved shell in pyramids: each box (m[0] x m[1] x m[2]) as four
/// quadratic (13-node) or triquadratic (19-node) pyramids on its faces
/// across y and z, apex at the box's centre, and four quadratic tetrahedra
/// on its faces across x (each split along the diagonal of increasing y and
/// z: neighbours agree); pyramids meet pyramids on their bases (across
/// boxes) and on triangles, and tetrahedra on triangles. `withHexahedra`:
/// the boxes at j = 0 are 20-node hexahedra instead (a hexahedron's face
/// against a pyramid's base). Every other box's pyramids start their base a
/// corner further (other local frames across shared faces).
vtkSmartPointer<vtkUnstructuredGrid> PyramidShell(
  const int m[3], bool triquadratic, bool withHexahedra);

/// The summed volumes of `grid`'s cells by Gauss quadrature (6 points per
/// axis, each axis cut in `pieces`) of their Jacobians, the Jacobian by
/// central differences of the cell's own interpolation
/// (vtkCell::EvaluateLocation) over the unit cube mapped onto its parametric
/// space (a pyramid or a tetrahedron: the collapsed cube).
double GridQuadratureVolume(vtkUnstructuredGrid* grid, int pieces);

/// Boundary triangles of `tets` (a tessellated shell sector) whose corners
/// are not all on one of the sector's six surfaces: the faces of cracks.
/// (A point the refinement adds on a curved surface lies on the cells'
/// polynomial, off the cylinder by less than `off`: 0.01 for interpolating
/// cells, 0.05 for Bezier cells, whose surfaces pass inside their control
/// points; the lattice's inner points lie at least 0.06 from it up to level
/// 3, 0.125 up to 2.)
vtkIdType InnerBoundaryTriangles(vtkUnstructuredGrid* tets, double off = 0.01);

/// Levels 0 … `top` of `grid`: the volume error against `exact` falling,
/// no cracks (boundary triangles = `surfaceQuads` refined, when > 0; levels
/// >= 1, or from `firstCrackFree`), the linear field exact at the new points;
/// the level-2 controls (local-order split, points not merged) crack.
void CheckRefinement(const std::string& what, vtkUnstructuredGrid* grid, double exact,
  vtkIdType surfaceQuads, int top, double levelOneFactor, bool localOrderControlCracks,
  double off = 0.01, bool levelZeroCrackFree = true);

/// `grid` through both mappers at `level` against the reference at `level`
/// (exact); control: the mapper's image against `control` (a reference
/// configured otherwise) is not.
void RenderRefined(const std::string& what, vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  int level, vtkDataSet* controlData, int controlLevel, int expectedWarnings = 0);
}
}

#endif
