/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSDataSets.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSDataSets
 * @brief   The one catalogue of meshes the apps, tests and benchmark render.
 *
 * Every mesh comes back as a tetrahedral vtkUnstructuredGrid with its scalars
 * active, or nullptr with an error that says which file could not be read.
 *
 * Real data sets (../shared/data, or HAVS_DATA_DIR; see its README), read and
 * tetrahedralized with vtkDataSetTriangleFilter (5 tets per hexahedron):
 * - bluntfin: NASA blunt fin, PLOT3D, Density (function 100), 187,395 tets;
 * - loxpost: NASA liquid-oxygen post, PLOT3D, Pressure (110), 513,375 tets;
 * - combustor: PLOT3D, Density (100), 215,040 tets;
 * - loxpostvtk: post.vtk, already tetrahedral, Pressure, 8,750 tets.
 *
 * Meshes made here:
 * - gen1M, gen4M, gen10M: blocks of 60^3, 94^3, 127^3 cubes (1.08M, 4.15M,
 *   10.2M tets), field sin(6x) cos(5y) + z; block<N> (e.g. block24): the
 *   same block of N^3 cubes (vtkHAVSGeneratedBlock.h), for tests;
 * - box: a 8^3 block of the unit cube, field z;
 * - wavelet: vtkRTAnalyticSource (17^3) thresholded at RTData >= 160 (holes
 *   and pockets);
 * - hollowsphere (a cavity), torus (a hole), twoblocks (two blocks with a
 *   gap of 0.08 between them).
 *
 * ReadFile() reads any .vtu (XML), .vtk (legacy) file, Load() a name above.
 */
#ifndef vtkHAVSDataSets_h
#define vtkHAVSDataSets_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSValidationModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkActor;
class vtkDataSet;
class vtkUnstructuredGrid;

class VTKHAVSVALIDATION_EXPORT vtkHAVSDataSets : public vtkObject
{
public:
  static vtkHAVSDataSets* New();
  vtkTypeMacro(vtkHAVSDataSets, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// HAVS_DATA_DIR, else ../shared/data (relative to the working directory).
  static std::string GetDataDirectory();

  /// Every name Load() knows, real ones first.
  static std::vector<std::string> GetNames();
  /// Whether `name` is a real data set (a file of the data directory).
  static bool IsRealDataSet(const std::string& name);

  /// The mesh of that name; nullptr (with an error) when unknown or unreadable.
  static vtkSmartPointer<vtkUnstructuredGrid> Load(const std::string& name);

  /**
   * A mesh file: .vtu (XML) or .vtk (legacy); `array` (optional) becomes the
   * active point scalars, else the first point array when none is active.
   * Tetrahedralized. nullptr with an error when it cannot be read.
   */
  static vtkSmartPointer<vtkUnstructuredGrid> ReadFile(
    const std::string& path, const std::string& array = std::string());

  /// A PLOT3D grid and solution (block 0), scalar function `function`, tetrahedralized.
  static vtkSmartPointer<vtkUnstructuredGrid> ReadPlot3D(
    const std::string& xyzPath, const std::string& qPath, int function);

  /// Any data set as tetrahedra (vtkDataSetTriangleFilter); nullptr for nullptr.
  static vtkSmartPointer<vtkUnstructuredGrid> Tetrahedralize(vtkDataSet* data);

  /// [0, nx h] x [0, ny h] x [0, nz h] in cubes of 5 tets, point scalar "s" = a + b z.
  static vtkSmartPointer<vtkUnstructuredGrid> MakeBox(
    int nx, int ny, int nz, double h, double a, double b);
  /// The unit cube in n^3 cubes, point scalar "field" = sin(6x) cos(5y) + z.
  static vtkSmartPointer<vtkUnstructuredGrid> MakeGenerated(int n);
  /**
   * A lit translucent plane actor (colour (0.2, 0.8, 0.9), opacity 0.45)
   * through `data`'s centre, normal (0.3, 0.45, 1), a square 1.6 times its
   * diagonal wide in 8 x 8 quads, so that it cuts the whole data set: the
   * translucent actor of the benchmark's translucent-* rows, havs_view's key
   * p and TestHAVSIntermix's plane scene.
   */
  static vtkSmartPointer<vtkActor> MakeTranslucentPlane(vtkDataSet* data);
  /// The cells of `grid` whose centroid satisfies `keep`.
  static vtkSmartPointer<vtkUnstructuredGrid> KeepCells(
    vtkUnstructuredGrid* grid, const std::function<bool(const double*)>& keep);

protected:
  vtkHAVSDataSets() = default;
  ~vtkHAVSDataSets() override = default;

private:
  vtkHAVSDataSets(const vtkHAVSDataSets&) = delete;
  void operator=(const vtkHAVSDataSets&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif
