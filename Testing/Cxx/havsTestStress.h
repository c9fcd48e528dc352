/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestStress.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestStress.h
 * @brief What the numerical stress tests (issue 20) share: their mappers, the
 * variants they run through, the exact reference of a view, the meshes more
 * than one of them uses.
 *
 * Each case goes through both mappers at their defaults (vtkHAVSVolumeMapper:
 * MPVO with the boundary layers, k = 2; vtkHAVSCellProjectionMapper: the MPVO
 * cell order), float results. Required: RMSE < 5e-4 and max < 0.01 (MISSION's
 * "exact"), leaving out up to 0.05 % (at least 1) edge pixels where a size
 * allows.
 *
 * Variants (environment; the `long` label runs each case through each):
 * HAVS_STRESS_ORDER=convexification|automatic (HAVS's other exact orders),
 * HAVS_STRESS_PATH=celldata|lod (cell scalars; the level of detail at half of
 * the internal faces, against stated bounds). See ConfigureOrder and Path.
 *
 * Used by TestHAVSScaledCoordinates, TestHAVSTranslatedCoordinates,
 * TestHAVSWindowResize, TestHAVSExtremeScalars, TestHAVSBadCells,
 * TestHAVSDegenerateViews, TestHAVSElongatedMesh, TestHAVSNearDegenerate and
 * TestHAVSStockMappersStress
 * (the ctest entries TestHAVSStress.*).
 */
#ifndef havsTestStress_h
#define havsTestStress_h

#include "havsTestImages.h" // ImageDifference
#include "vtkCamera.h"      // Pair holds one
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

class vtkHAVSVolumeMapper;
class vtkUnstructuredGrid;
class vtkUnstructuredGridVolumeMapper;
class vtkVolumeProperty;

namespace havstest
{
namespace stress
{
/// Issue 20: every case also through HAVS's other exact orders. The `long`
/// variants' ctest entries set HAVS_STRESS_ORDER: unset, HAVS's defaults (MPVO
/// with the boundary layers, k = 2); "convexification" (MPVO, the mesh's gaps
/// filled by imaginary cells); "automatic" (the automatic order and k). The
/// cell projection keeps its one order.
void ConfigureOrder(vtkHAVSVolumeMapper* m);

/// Issue 20: every case also through the cell-data and level-of-detail paths.
/// HAVS_STRESS_PATH unset: point scalars, every face drawn. "celldata": every
/// grid (for the mappers and the reference alike) has its point scalars
/// replaced by cell scalars, each cell the mean of its points' scalars (a
/// non-finite point scalar makes its cells' scalars non-finite: they are
/// replaced as non-finite point scalars are). "lod": HAVS draws half of the
/// internal faces (LevelOfDetailFraction 0.5, the Area ranking, the
/// long-segment table): images of the same scene under a change the ranking
/// does not see (scale, translation, scalar range) must still be equal to
/// the exact bound; against the exact reference a stated bound (kLodRMSE,
/// kLodMax) replaces the exact one, and the controls must fail that bound.
enum class StressPath
{
  Default,
  CellData,
  LevelOfDetail
};

/// This run's path, from HAVS_STRESS_PATH (an unknown one exits).
StressPath Path();

/// The level-of-detail path's bound against the exact reference (half of the
/// internal faces skipped: segments across two or more cells, interpolated
/// linearly, read from the long-segment table).
constexpr double kLodRMSE = 0.01;
constexpr double kLodMax = 0.15;

/// `grid` with its point scalars replaced by cell scalars, each cell the mean
/// of its points' scalars (NaN and +-Inf propagate), the rest shared.
vtkSmartPointer<vtkUnstructuredGrid> CellScalarCopy(vtkUnstructuredGrid* grid);

/// The grid the mappers and the reference see on this run's path (see
/// Path()): `grid` itself, or its CellScalarCopy, made once per grid and
/// modification time (the original is held, so that its address is not
/// reused while the copy is cached).
vtkUnstructuredGrid* OnPath(vtkUnstructuredGrid* grid);

/// A mapper at its defaults, its float result kept: cell projection or HAVS
/// (every fragment composited: no early ray termination; ConfigureOrder; on
/// the level-of-detail path half of the internal faces).
vtkSmartPointer<vtkUnstructuredGridVolumeMapper> MakeMapper(bool cells);

/// True when `mapper`'s last frame drew a subset of the internal faces (HAVS
/// on the level-of-detail path, on a mesh with internal faces; a mesh without
/// them, such as one tetrahedron, is drawn whole and stays exact).
bool DrewSubset(vtkUnstructuredGridVolumeMapper* mapper);

/// A bound against the exact reference.
struct Bound
{
  double RMSE;
  double Max;
};
constexpr Bound kLodBound = { kLodRMSE, kLodMax };

/// Against the exact reference: exact (RMSE < 5e-4, max < 0.01), or, for a
/// frame that drew a subset of the faces, within the level-of-detail bound
/// (the case's own where it states one, else kLodRMSE and kLodMax).
bool Accurate(const havstest::ImageDifference& d, bool subset, Bound lod = kLodBound);

/// The float result of `grid` through MakeMapper(cells), camera from (30, 20)
/// degrees; `subset` (if given): whether the frame drew a subset of the faces.
std::vector<float> Render(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, bool cells,
  int width, int height, bool* subset = nullptr);

/// `grid` with its points mapped by f, stored as double or float.
vtkSmartPointer<vtkUnstructuredGrid> Moved(
  vtkUnstructuredGrid* grid, const std::function<double(double)>& f, bool asDouble);

/// RMSE < 5e-4 and max < 0.01.
bool Exact(const havstest::ImageDifference& d);

/// Prints a difference under a name.
void Print(const std::string& what, const havstest::ImageDifference& d);

/// "HAVS" or "cell projection".
const char* Name(bool cells);

/// The exact image of `grid` seen by `camera` turned by `azimuth` degrees.
std::vector<float> ReferenceImage(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkCamera* camera, int width, int height, double azimuth = 0.0);

/// Pixels of an image whose opacity exceeds 1e-3 (the scene is seen there).
size_t CoveredPixels(const std::vector<float>& rgba);

/// The size (square) of the pair scenes.
constexpr int kPairSize = 96;

/// Exact references of the pair scenes (kPairSize^2), each (grid, property,
/// camera) rendered once: the reference does not depend on the mapper, so
/// both mappers' checks and the controls share it. The grids and properties
/// must stay alive and unchanged while the cache is used (their addresses are
/// the key).
class PairReferences
{
public:
  const std::vector<float>& Get(
    vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera);

private:
  struct Key
  {
    const void* Grid = nullptr;
    const void* Property = nullptr;
    std::array<double, 9> View{};
    bool operator<(const Key& o) const
    {
      return std::tie(this->Grid, this->Property, this->View) <
        std::tie(o.Grid, o.Property, o.View);
    }
  };
  std::map<Key, std::vector<float>> Images;
};

/// A mapper's frame beside the exact reference of the same scene (RenderWithReference).
struct Pair
{
  std::vector<float> Image;
  std::vector<float> Exact;
  vtkSmartPointer<vtkCamera> Camera;
  int Warnings = 0;
  int Errors = 0;
  bool Subset = false; ///< a subset of the faces drawn (DrewSubset)
};

/// The mapper's float result and the exact reference of the same scene
/// (camera from (azimuth, elevation) degrees, kPairSize^2), with the mapper's
/// messages and the camera (for the controls' references).
Pair RenderWithReference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, bool cells,
  PairReferences& references, double azimuth = 30.0, double elevation = 20.0);

/// The same through a given mapper (its float result kept: KeepFloatResultOn).
Pair RenderWithReference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkUnstructuredGridVolumeMapper* mapper, PairReferences& references, double azimuth = 30.0,
  double elevation = 20.0);

/// `grid` with the point scalars f(point id, scalar) (a double array).
vtkSmartPointer<vtkUnstructuredGrid> WithScalars(
  vtkUnstructuredGrid* grid, const std::function<double(vtkIdType, double)>& f);

/// A grid of the tetrahedra `tets` on `points` (double), point scalars
/// "s" = x + 2y + z / 2.
vtkSmartPointer<vtkUnstructuredGrid> MakeTets(const std::vector<std::array<double, 3>>& points,
  const std::vector<std::array<vtkIdType, 4>>& tets);

/// `grid` with the cells `keep` accepts (by index), the points shared.
vtkSmartPointer<vtkUnstructuredGrid> Cells(vtkUnstructuredGrid* grid,
  const std::function<bool(vtkIdType)>& keep,
  const std::function<void(vtkIdType, vtkIdType*)>& edit);

/// A square view's float result against the exact reference from the same
/// camera, finite, the reference covering more than `minCovered` pixels;
/// control: the reference of the view turned by 25 degrees must differ.
void CheckView(const std::string& what, bool subset, const std::vector<float>& image,
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int size,
  int minCovered, double rmseBound = 5e-4, double maxBound = 0.01);

/// The cell-data path's check of a degenerate view (rays exactly on faces
/// between cells of different constant scalars, where the field jumps and no
/// single exact image exists). Intended result: each such pixel shows one of
/// its sides: it lies within the range of the references of the camera moved
/// a hair in eight directions (to 0.01; up to 0.05 % of the pixels, at least
/// 1, left out as edge pixels); where those references agree (the reference
/// is defined) the image is exact (RMSE < 5e-4, max < 0.01). Control: the
/// reference of the view turned by 25 degrees fails the same check.
void CheckViewOnJumps(const std::string& what, const std::vector<float>& image,
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int size,
  size_t maxOutside = 0, Bound defined = { 5e-4, 0.01 });

/// [0, 3 length] x [0, 3] x [0, 3] in 3^3 boxes of 5 tetrahedra (every
/// cell `length` long and 1 wide), points as double, s = (z + x / length) / 6.
vtkSmartPointer<vtkUnstructuredGrid> MakeElongated(double length);
}
}

#endif
