/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSStress.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Numerical stress (issue 20, first cases), each through both mappers at
// their defaults (vtkHAVSVolumeMapper: MPVO with the boundary layers, k = 2;
// vtkHAVSCellProjectionMapper: the MPVO cell order), float results:
//   scale      the hollow sphere's coordinates times 1e-8 and 1e8, the opacity
//              unit distance scaled alike: the image equals the unscaled one;
//              control: the unit distance left unscaled changes it;
//   translate  the coordinates moved by 1e6 and 1e9, points stored as double:
//              the image equals the unmoved one; control: at 1e9 stored as
//              float (the mesh collapses to a few representable values) it
//              does not;
//   resize     a new window size every frame (1x1, 2x3, 17x5, 64x64,
//              200x120, 96x96) against the exact reference at each size
//              (the camera a little off the mesh's centre, so that the 1x1
//              window's ray is not on a vertex); control: the reference of
//              another view.
//   scalars, cells, views, elongated, stock: see their functions below.
// Required: RMSE < 5e-4 and max < 0.01 (MISSION's "exact"), leaving out up
// to 0.05 % (at least 1) edge pixels where a size allows.
//
// Variants (environment; the `long` label runs each case through each):
// HAVS_STRESS_ORDER=convexification|automatic (HAVS's other exact orders),
// HAVS_STRESS_PATH=celldata|lod (cell scalars; the level of detail at half of
// the internal faces, against stated bounds). See ConfigureOrder and Path.
//
// Usage: TestHAVSStress <case>
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSOpenGL.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkAppendFilter.h"
#include "vtkCamera.h"
#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace
{
/// Issue 20: every case also through HAVS's other exact orders. The `long`
/// variants' ctest entries set HAVS_STRESS_ORDER: unset, HAVS's defaults (MPVO
/// with the boundary layers, k = 2); "convexification" (MPVO, the mesh's gaps
/// filled by imaginary cells); "automatic" (the automatic order and k). The
/// cell projection keeps its one order.
void ConfigureOrder(vtkHAVSVolumeMapper* m)
{
  const char* order = std::getenv("HAVS_STRESS_ORDER");
  if (!order || !*order)
  {
    return;
  }
  const std::string o = order;
  if (o == "convexification")
  {
    m->SetNonConvexMethodToConvexification();
  }
  else if (o == "automatic")
  {
    m->SetVisibilityOrderToAutomatic();
  }
  else
  {
    std::printf("unknown HAVS_STRESS_ORDER '%s'\n", order);
    std::exit(EXIT_FAILURE);
  }
}

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

StressPath Path()
{
  const char* path = std::getenv("HAVS_STRESS_PATH");
  if (!path || !*path)
  {
    return StressPath::Default;
  }
  const std::string p = path;
  if (p == "celldata")
  {
    return StressPath::CellData;
  }
  if (p == "lod")
  {
    return StressPath::LevelOfDetail;
  }
  std::printf("unknown HAVS_STRESS_PATH '%s'\n", path);
  std::exit(EXIT_FAILURE);
}

/// The level-of-detail path's bound against the exact reference (half of the
/// internal faces skipped: segments across two or more cells, interpolated
/// linearly, read from the long-segment table).
constexpr double kLodRMSE = 0.01;
constexpr double kLodMax = 0.15;

/// `grid` with its point scalars replaced by cell scalars, each cell the mean
/// of its points' scalars (NaN and +-Inf propagate), the rest shared.
vtkSmartPointer<vtkUnstructuredGrid> CellScalarCopy(vtkUnstructuredGrid* grid)
{
  vtkDataArray* pointScalars = grid->GetPointData()->GetScalars();
  auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
  copy->ShallowCopy(grid);
  copy->GetPointData()->Initialize();
  copy->GetCellData()->Initialize();
  if (pointScalars)
  {
    vtkNew<vtkDoubleArray> cellScalars;
    cellScalars->SetName(pointScalars->GetName() ? pointScalars->GetName() : "s");
    cellScalars->SetNumberOfTuples(grid->GetNumberOfCells());
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      grid->GetCellPoints(c, ids);
      double sum = 0.0;
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
      {
        sum += pointScalars->GetTuple1(ids->GetId(i));
      }
      cellScalars->SetValue(c, ids->GetNumberOfIds() > 0 ? sum / ids->GetNumberOfIds() : 0.0);
    }
    copy->GetCellData()->SetScalars(cellScalars);
  }
  return copy;
}

/// The grid the mappers and the reference see on this run's path (see
/// Path()): `grid` itself, or its CellScalarCopy, made once per grid and
/// modification time (the original is held, so that its address is not
/// reused while the copy is cached).
vtkUnstructuredGrid* OnPath(vtkUnstructuredGrid* grid)
{
  if (Path() != StressPath::CellData || !grid)
  {
    return grid;
  }
  struct Entry
  {
    vtkSmartPointer<vtkUnstructuredGrid> Original;
    vtkMTimeType Time = 0;
    vtkSmartPointer<vtkUnstructuredGrid> Copy;
  };
  static std::map<const vtkUnstructuredGrid*, Entry> cache;
  Entry& entry = cache[grid];
  if (!entry.Copy || entry.Time != grid->GetMTime())
  {
    entry.Original = grid;
    entry.Time = grid->GetMTime();
    entry.Copy = CellScalarCopy(grid);
  }
  return entry.Copy;
}

/// A mapper at its defaults, its float result kept: cell projection or HAVS
/// (every fragment composited: no early ray termination; ConfigureOrder; on
/// the level-of-detail path half of the internal faces).
vtkSmartPointer<vtkUnstructuredGridVolumeMapper> MakeMapper(bool cells)
{
  if (cells)
  {
    auto m = vtkSmartPointer<vtkHAVSCellProjectionMapper>::New();
    m->KeepFloatResultOn();
    return m;
  }
  auto m = vtkSmartPointer<vtkHAVSVolumeMapper>::New();
  m->KeepFloatResultOn();
  m->SetEarlyRayTerminationOpacity(1.0);
  ConfigureOrder(m);
  if (Path() == StressPath::LevelOfDetail)
  {
    m->SetLevelOfDetailFraction(0.5);
  }
  return m;
}

/// True when `mapper`'s last frame drew a subset of the internal faces (HAVS
/// on the level-of-detail path, on a mesh with internal faces; a mesh without
/// them, such as one tetrahedron, is drawn whole and stays exact).
bool DrewSubset(vtkUnstructuredGridVolumeMapper* mapper)
{
  auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper);
  return havs && havs->GetLastFrameStatistics()->GetLevelOfDetailFraction() < 1.0;
}

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
bool Accurate(const havstest::ImageDifference& d, bool subset, Bound lod = kLodBound)
{
  if (subset)
  {
    return d.RMSE < lod.RMSE && d.Max < lod.Max;
  }
  return d.RMSE < 5e-4 && d.Max < 0.01;
}

/// The float result of `grid` through MakeMapper(cells), camera from (30, 20)
/// degrees; `subset` (if given): whether the frame drew a subset of the faces.
std::vector<float> Render(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, bool cells,
  int width, int height, bool* subset = nullptr)
{
  auto mapper = MakeMapper(cells);
  auto s = havstest::MakeScene(OnPath(grid), mapper, property, width, height);
  havstest::PlaceCamera(s.Renderer, 30.0, 20.0, false);
  s.Window->Render();
  if (subset)
  {
    *subset = DrewSubset(mapper);
  }
  return havstest::FloatResult(mapper);
}

/// `grid` with its points mapped by f, stored as double or float.
vtkSmartPointer<vtkUnstructuredGrid> Moved(
  vtkUnstructuredGrid* grid, const std::function<double(double)>& f, bool asDouble)
{
  auto moved = vtkSmartPointer<vtkUnstructuredGrid>::New();
  moved->DeepCopy(grid);
  vtkNew<vtkPoints> points;
  points->SetDataType(asDouble ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[3];
    grid->GetPoint(i, p);
    points->SetPoint(i, f(p[0]), f(p[1]), f(p[2]));
  }
  moved->SetPoints(points);
  return moved;
}

bool Exact(const havstest::ImageDifference& d)
{
  return d.RMSE < 5e-4 && d.Max < 0.01;
}

void Print(const std::string& what, const havstest::ImageDifference& d)
{
  std::printf("  %-62s RMSE %.2e  max %.2e\n", what.c_str(), d.RMSE, d.Max);
}

const char* Name(bool cells)
{
  return cells ? "cell projection" : "HAVS";
}

int Scale()
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  auto property = havstest::MakeRampPropertyFor(grid);
  const double unit = property->GetScalarOpacityUnitDistance();
  const size_t edge = 8;
  for (bool cells : { false, true })
  {
    bool subset = false;
    const auto plain = Render(grid, property, cells, 128, 128, &subset);
    if (!cells && Path() == StressPath::LevelOfDetail)
    {
      // The path's images are only worth comparing if it skips faces.
      havstest::Check(subset, "HAVS on the level-of-detail path draws a subset of the faces");
    }
    for (double factor : { 1e-8, 1e8 })
    {
      auto scaled = Moved(
        grid, [factor](double x) { return x * factor; }, true);
      property->SetScalarOpacityUnitDistance(unit * factor);
      const auto image = Render(scaled, property, cells, 128, 128);
      property->SetScalarOpacityUnitDistance(unit);
      const auto control = Render(scaled, property, cells, 128, 128);
      const auto d = havstest::Compare(image, plain, edge);
      const auto c = havstest::Compare(control, plain, edge);
      char what[96];
      std::snprintf(what, sizeof(what), "%s, coordinates x %.0e", Name(cells), factor);
      Print(std::string(what) + ": vs unscaled", d);
      Print(std::string(what) + ": control, unit distance unscaled", c);
      havstest::Check(Exact(d), std::string(what) + ": equals the unscaled image");
      havstest::Check(!Exact(c), std::string(what) + ": control, the unit distance matters");
      havstest::Check(havstest::AllFinite(image), std::string(what) + ": finite");
    }
  }
  return havstest::Result();
}

int Translate()
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  auto property = havstest::MakeRampPropertyFor(grid);
  const size_t edge = 8;
  for (bool cells : { false, true })
  {
    const auto plain = Render(grid, property, cells, 128, 128);
    for (double offset : { 1e6, 1e9 })
    {
      auto moved = Moved(
        grid, [offset](double x) { return x + offset; }, true);
      const auto image = Render(moved, property, cells, 128, 128);
      const auto d = havstest::Compare(image, plain, edge);
      char what[96];
      std::snprintf(what, sizeof(what), "%s, moved by %.0e (double points)", Name(cells), offset);
      Print(std::string(what) + ": vs unmoved", d);
      havstest::Check(Exact(d), std::string(what) + ": equals the unmoved image");
      havstest::Check(havstest::AllFinite(image), std::string(what) + ": finite");
    }
    // Control: at 1e9 as float the points collapse (spacing 64 at 1e9).
    auto collapsed = Moved(
      grid, [](double x) { return x + 1e9; }, false);
    const auto bad = Render(collapsed, property, cells, 128, 128);
    const auto c = havstest::Compare(bad, plain, edge);
    Print(std::string(Name(cells)) + ", moved by 1e9 as float: control", c);
    havstest::Check(!Exact(c), std::string(Name(cells)) + ": control, float points at 1e9 fail");
  }
  return havstest::Result();
}

/// The exact image of `grid` seen by `camera` turned by `azimuth` degrees.
std::vector<float> ReferenceImage(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkCamera* camera, int width, int height, double azimuth = 0.0)
{
  vtkNew<vtkCamera> turned;
  turned->DeepCopy(camera);
  turned->Azimuth(azimuth);
  vtkNew<vtkHAVSReferenceRenderer> r;
  r->SetInputData(OnPath(grid));
  r->SetProperty(property);
  r->SetCamera(turned);
  r->SetSize(width, height);
  r->Render();
  vtkFloatArray* out = r->GetImage();
  const size_t values = 4 * static_cast<size_t>(width) * height;
  if (!out || static_cast<size_t>(out->GetNumberOfValues()) < values)
  {
    // No reference (it reported why): an empty image, which the checks of
    // coverage and of the controls do not accept.
    std::printf("  the reference rendered no image\n");
    return std::vector<float>(values, 0.0f);
  }
  return std::vector<float>(out->GetPointer(0), out->GetPointer(0) + values);
}

/// Pixels of an image whose opacity exceeds 1e-3 (the scene is seen there).
size_t CoveredPixels(const std::vector<float>& rgba)
{
  size_t covered = 0;
  for (size_t i = 3; i < rgba.size(); i += 4)
  {
    covered += rgba[i] > 1e-3f ? 1 : 0;
  }
  return covered;
}

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
    vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera)
  {
    Key key;
    key.Grid = grid;
    key.Property = property;
    camera->GetPosition(key.View.data());
    camera->GetFocalPoint(key.View.data() + 3);
    camera->GetViewUp(key.View.data() + 6);
    auto found = this->Images.find(key);
    if (found == this->Images.end())
    {
      found =
        this->Images.emplace(key, ReferenceImage(grid, property, camera, kPairSize, kPairSize))
          .first;
    }
    return found->second;
  }

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
  PairReferences& references, double azimuth = 30.0, double elevation = 20.0)
{
  const int size = kPairSize;
  auto mapper = MakeMapper(cells);
  havstest::Messages* messages = havstest::CountMessages(mapper);
  auto s = havstest::MakeScene(OnPath(grid), mapper, property, size, size);
  havstest::PlaceCamera(s.Renderer, azimuth, elevation, false);
  s.Window->Render();
  Pair out;
  out.Image = havstest::FloatResult(mapper);
  out.Warnings = messages->Warnings;
  out.Errors = messages->Errors;
  out.Subset = DrewSubset(mapper);
  out.Camera = vtkSmartPointer<vtkCamera>::New();
  out.Camera->DeepCopy(s.Renderer->GetActiveCamera());
  out.Exact = references.Get(grid, property, out.Camera);
  return out;
}

/// `grid` with the point scalars f(point id, scalar) (a double array).
vtkSmartPointer<vtkUnstructuredGrid> WithScalars(
  vtkUnstructuredGrid* grid, const std::function<double(vtkIdType, double)>& f)
{
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->DeepCopy(grid);
  vtkDataArray* old = grid->GetPointData()->GetScalars();
  vtkNew<vtkDoubleArray> values;
  values->SetName("stress");
  values->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    values->SetValue(i, f(i, old->GetTuple1(i)));
  }
  out->GetPointData()->SetScalars(values);
  return out;
}

/// A ramp property over [0, 1] with its scalar axis scaled by `scale`.
vtkSmartPointer<vtkVolumeProperty> RampScaled(double scale, double unit)
{
  auto property = havstest::MakeRampProperty(0.0, scale, 0.8, unit);
  return property;
}

/// Scalars (issue 20): constant; NaN and +-Inf at a tenth of the points
/// (intended: replaced by the lowest finite value, with a warning; the
/// reference does the same); denormal and 1e30 ranges (the image equals the
/// [0, 1] one with the transfer function scaled alike); a transfer-function
/// spike narrower than one table bin; fully transparent; fully opaque. Each
/// against the exact reference, finite, with a control that fails.
int Scalars()
{
  auto base = vtkHAVSDataSets::Load("hollowsphere");
  double range[2];
  base->GetPointData()->GetScalars()->GetRange(range);
  // The scalars mapped to [0, 1].
  auto grid =
    WithScalars(base, [&](vtkIdType, double v) { return (v - range[0]) / (range[1] - range[0]); });
  const double unit = grid->GetLength() / 8.0;
  const size_t edge = kPairSize * kPairSize / 2000;
  auto ramp = RampScaled(1.0, unit);

  // Every grid and transfer function first (kept alive: the references are
  // cached by address and shared by both mappers).
  auto constant = WithScalars(grid, [](vtkIdType, double) { return 0.37; });
  auto other = WithScalars(grid, [](vtkIdType, double) { return 0.8; });
  struct Broken
  {
    std::string What;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
    vtkSmartPointer<vtkUnstructuredGrid> High;
  };
  std::vector<Broken> broken;
  for (double bad : { std::nan(""), HUGE_VAL, -HUGE_VAL })
  {
    broken.push_back(
      { std::isnan(bad) ? "NaN scalars" : (bad > 0 ? "+Inf scalars" : "-Inf scalars"),
        WithScalars(grid, [&](vtkIdType i, double v) { return i % 10 == 3 ? bad : v; }),
        WithScalars(grid, [&](vtkIdType i, double v) { return i % 10 == 3 ? 1.0 : v; }) });
  }
  struct Scaled
  {
    double Scale;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
    vtkSmartPointer<vtkVolumeProperty> Ramp;
  };
  std::vector<Scaled> scaled;
  for (double scale : { 1e-310, 1e30 })
  {
    scaled.push_back({ scale, WithScalars(grid, [&](vtkIdType, double v) { return v * scale; }),
      RampScaled(scale, unit) });
  }
  // A spike of opacity 1 and half-width 1e-3 (a table bin is 1/127), zero
  // elsewhere; nothing at all; fully opaque (opacity 1 at a unit distance of
  // 1e-3 of the mesh). The spike is at 0.5, or, on the cell-data path, at the
  // cell scalar nearest 0.5 (constant scalars meet a spike only at their own
  // values: at 0.5 itself no cell would show, and the control, the empty
  // image, would not fail).
  double spikeAt = 0.5;
  if (Path() == StressPath::CellData)
  {
    vtkDataArray* cellScalars = OnPath(grid)->GetCellData()->GetScalars();
    double nearest = 1.0;
    for (vtkIdType c = 0; c < cellScalars->GetNumberOfTuples(); ++c)
    {
      const double v = cellScalars->GetTuple1(c);
      if (std::fabs(v - 0.5) < std::fabs(nearest - 0.5))
      {
        nearest = v;
      }
    }
    spikeAt = nearest;
    std::printf("the spike at the cell scalar %.9g\n", spikeAt);
  }
  auto spike = havstest::MakeRampProperty(0.0, 1.0, 0.8, unit);
  spike->GetScalarOpacity()->RemoveAllPoints();
  spike->GetScalarOpacity()->AddPoint(0.0, 0.0);
  spike->GetScalarOpacity()->AddPoint(spikeAt - 0.001, 0.0);
  spike->GetScalarOpacity()->AddPoint(spikeAt, 1.0);
  spike->GetScalarOpacity()->AddPoint(spikeAt + 0.001, 0.0);
  spike->GetScalarOpacity()->AddPoint(1.0, 0.0);
  auto none = havstest::MakeRampProperty(0.0, 1.0, 0.8, unit);
  none->GetScalarOpacity()->RemoveAllPoints();
  none->GetScalarOpacity()->AddPoint(0.0, 0.0);
  none->GetScalarOpacity()->AddPoint(1.0, 0.0);
  auto opaque = havstest::MakeRampProperty(0.0, 1.0, 1.0, grid->GetLength() * 1e-3);
  opaque->GetScalarOpacity()->RemoveAllPoints();
  opaque->GetScalarOpacity()->AddPoint(0.0, 1.0);
  opaque->GetScalarOpacity()->AddPoint(1.0, 1.0);

  PairReferences references;
  for (bool cells : { false, true })
  {
    const std::string who = Name(cells);
    auto render = [&](vtkUnstructuredGrid* g, vtkVolumeProperty* property)
    { return RenderWithReference(g, property, cells, references); };
    auto check = [&](const std::string& what, const Pair& p, vtkUnstructuredGrid* controlGrid,
                   vtkVolumeProperty* controlProperty, bool expectWarning, Bound lod = kLodBound)
    {
      const auto d = havstest::Compare(p.Image, p.Exact, edge);
      const auto c =
        havstest::Compare(p.Image, references.Get(controlGrid, controlProperty, p.Camera), edge);
      Print(who + ", " + what + ": vs reference", d);
      Print(who + ", " + what + ": control", c);
      havstest::Check(Accurate(d, p.Subset, lod),
        who + ", " + what + (p.Subset ? ": within the level-of-detail bound" : ": exact"));
      havstest::Check(havstest::AllFinite(p.Image), who + ", " + what + ": finite");
      havstest::Check(!Accurate(c, p.Subset, lod), who + ", " + what + ": control fails");
      havstest::Check(p.Errors == 0 && (p.Warnings > 0) == expectWarning,
        who + ", " + what + (expectWarning ? ": one warning" : ": no warning"));
    };
    // Constant: every scalar 0.37 (control: the reference at 0.8).
    check("constant scalar", render(constant, ramp), other, ramp, false);
    // NaN, +Inf, -Inf at every tenth point: replaced by the lowest finite
    // value (control: the reference with them replaced by the highest).
    for (const Broken& b : broken)
    {
      check(b.What, render(b.Grid, ramp), b.High, ramp, true);
    }
    // Denormal and 1e30 ranges: equal to the [0, 1] image with the transfer
    // function scaled alike (control: the transfer function left at [0, 1]).
    const Pair plain = render(grid, ramp);
    for (const Scaled& sc : scaled)
    {
      const Pair p = render(sc.Grid, sc.Ramp);
      const auto same = havstest::Compare(p.Image, plain.Image, edge);
      char what[64];
      std::snprintf(what, sizeof(what), "scalars x %.0e", sc.Scale);
      Print(who + ", " + what + ": vs the [0, 1] image", same);
      havstest::Check(Exact(same), who + ", " + what + ": equals the [0, 1] image");
      check(what, p, sc.Grid, ramp, false);
    }
    // The spike (control: the reference without it, empty). On the cell-data
    // path a cell's segment takes the transfer function at the cell's value
    // itself (vtkHAVSCellOptics), which meets the spike exactly; it read the
    // table's diagonal (s, s) before, interpolated between nodes, and missed
    // it (RMSE 3.3e-2, max 0.26; the image within 2.5e-3 of the empty one, so
    // the control below is the one that fails for that defect). Level of
    // detail: its own bound (measured RMSE 2.2e-4, max 3.0e-3; the control,
    // the empty image, 1.5e-3, 6.7e-3).
    check(
      "spike narrower than a table bin", render(grid, spike), grid, none, false, { 1e-3, 0.01 });
    // Fully transparent: nothing at all (control: the ramp's reference).
    const Pair empty = render(grid, none);
    check("fully transparent", empty, grid, ramp, false);
    double largest = 0.0;
    for (float v : empty.Image)
    {
      largest = std::max(largest, static_cast<double>(std::fabs(v)));
    }
    havstest::Check(largest == 0.0, who + ", fully transparent: every pixel exactly 0");
    // Fully opaque (control: the ramp's reference).
    check("fully opaque", render(grid, opaque), grid, ramp, false);
  }
  return havstest::Result();
}

vtkSmartPointer<vtkUnstructuredGrid> MakeTets(const std::vector<std::array<double, 3>>& points,
  const std::vector<std::array<vtkIdType, 4>>& tets)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  for (const auto& x : points)
  {
    p->InsertNextPoint(x.data());
    scalars->InsertNextValue(x[0] + 2.0 * x[1] + 0.5 * x[2]);
  }
  grid->SetPoints(p);
  grid->GetPointData()->SetScalars(scalars);
  for (const auto& t : tets)
  {
    grid->InsertNextCell(VTK_TETRA, 4, t.data());
  }
  return grid;
}

/// `grid` with the cells `keep` accepts (by index), the points shared.
vtkSmartPointer<vtkUnstructuredGrid> Cells(vtkUnstructuredGrid* grid,
  const std::function<bool(vtkIdType)>& keep,
  const std::function<void(vtkIdType, vtkIdType*)>& edit)
{
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->SetPoints(grid->GetPoints());
  out->GetPointData()->ShallowCopy(grid->GetPointData());
  out->Allocate(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (!keep(c))
    {
      continue;
    }
    vtkIdType ids[4];
    for (int i = 0; i < 4; ++i)
    {
      ids[i] = grid->GetCell(c)->GetPointId(i);
    }
    edit(c, ids);
    out->InsertNextCell(VTK_TETRA, 4, ids);
  }
  return out;
}

/// Badly shaped and bad cells (issue 20), each through both mappers against
/// the exact reference at three views, finite, with a control that fails:
///   sliver, needle, cap and wedge tetrahedra (a dense medium, so that the
///   thin cells show; control: the reference of the cell made twice as thick);
///   inverted orientation (every other cell's points listed the other way:
///   the same cells, the same image; control: those cells removed);
///   duplicate cells (every 7th written twice: intended, one copy drawn, with
///   a warning; control: those cells removed);
///   unused points (100 points no cell uses, with a scalar far outside the
///   used range: the same image; control: half the cells removed);
///   zero-volume cells (40 flat tetrahedra on existing points: dropped with a
///   warning, the same image; control: the reference of a half unit distance);
///   non-manifold meshes (two boxes sharing one edge, and one vertex, point
///   ids shared: exact; control: one box alone).
/// Each control is the exact image of the control scene seen from the case's
/// own camera.
int BadCells(bool allViews)
{
  // One view here (the suite's time); three for `cells full` (long).
  std::vector<std::pair<double, double>> views = { { 30.0, 20.0 }, { 100.0, -35.0 },
    { 200.0, 60.0 } };
  if (!allViews)
  {
    views.resize(1);
  }
  const size_t edge = kPairSize * kPairSize / 2000;
  auto exactEverywhere = [&](const std::string& what, vtkUnstructuredGrid* grid,
                           vtkVolumeProperty* property, vtkUnstructuredGrid* control,
                           vtkVolumeProperty* controlProperty, bool expectWarning)
  {
    // The references of this case, shared by both mappers; a control is
    // the control's exact image from the case's own camera.
    PairReferences references;
    for (bool cells : { false, true })
    {
      int controlsFailed = 0;
      for (const auto& view : views)
      {
        const Pair p =
          RenderWithReference(grid, property, cells, references, view.first, view.second);
        const size_t covered = CoveredPixels(p.Exact);
        const auto d = havstest::Compare(p.Image, p.Exact, edge);
        const auto wrong =
          havstest::Compare(p.Image, references.Get(control, controlProperty, p.Camera), edge);
        char name[160];
        std::snprintf(name, sizeof(name), "%s, %s, view (%.0f, %.0f)", Name(cells), what.c_str(),
          view.first, view.second);
        Print(std::string(name) + ": vs reference", d);
        Print(std::string(name) + ": control", wrong);
        havstest::Check(Accurate(d, p.Subset),
          std::string(name) + (p.Subset ? ": within the level-of-detail bound" : ": exact"));
        havstest::Check(covered >= 9, std::string(name) + ": the cells show");
        havstest::Check(havstest::AllFinite(p.Image), std::string(name) + ": finite");
        havstest::Check(p.Errors == 0 && (p.Warnings > 0) == expectWarning,
          std::string(name) + (expectWarning ? ": warned" : ": no warning"));
        controlsFailed += Accurate(wrong, p.Subset) ? 0 : 1;
      }
      havstest::Check(controlsFailed > 0,
        std::string(Name(cells)) + ", " + what + ": the control fails at a view at least");
    }
  };

  // Badly shaped single tetrahedra in a dense medium.
  {
    struct Shape
    {
      const char* Name;
      std::vector<std::array<double, 3>> Points;
      std::vector<std::array<double, 3>> Thicker;
    };
    const std::vector<Shape> shapes = {
      { "sliver", { { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0.01 }, { 0, 1, 0.01 } },
        { { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0.02 }, { 0, 1, 0.02 } } },
      { "needle", { { 0, 0, 0 }, { 0.05, 0, 0 }, { 0, 0.05, 0 }, { 0.3, 0.3, 1 } },
        { { 0, 0, 0 }, { 0.1, 0, 0 }, { 0, 0.1, 0 }, { 0.3, 0.3, 1 } } },
      { "cap", { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.9, 0 }, { 0.5, 0.3, 0.01 } },
        { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.9, 0 }, { 0.5, 0.3, 0.02 } } },
      { "wedge", { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.8, 0.3 }, { 0.51, 0.8, 0.28 } },
        { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.8, 0.3 }, { 0.52, 0.8, 0.26 } } },
    };
    for (const Shape& shape : shapes)
    {
      auto grid = MakeTets(shape.Points, { { 0, 1, 2, 3 } });
      auto thicker = MakeTets(shape.Thicker, { { 0, 1, 2, 3 } });
      double range[2];
      grid->GetPointData()->GetScalars()->GetRange(range);
      // Optical depth about 2 along the cells' longest chords: the thin cells
      // show, and the table's length axis (its interpolation) is not what is
      // measured here.
      auto dense = havstest::MakeRampProperty(range[0] - 0.1, range[1] + 0.1, 0.9, 0.5);
      exactEverywhere(std::string(shape.Name) + " tetrahedron", grid, dense, thicker, dense, false);
    }
  }

  auto box = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(box);
  auto all = [](vtkIdType) { return true; };
  auto asIs = [](vtkIdType, vtkIdType*) {};
  // Inverted orientation.
  {
    auto flipped = Cells(box, all,
      [](vtkIdType c, vtkIdType* ids)
      {
        if (c % 2)
        {
          std::swap(ids[0], ids[1]);
        }
      });
    auto without = Cells(
      box, [](vtkIdType c) { return c % 2 == 0; }, asIs);
    exactEverywhere("inverted orientation", flipped, property, without, property, false);
  }
  // Duplicate cells.
  {
    auto doubled = Cells(box, all, asIs);
    for (vtkIdType c = 0; c < box->GetNumberOfCells(); c += 7)
    {
      doubled->InsertNextCell(VTK_TETRA, box->GetCell(c)->GetPointIds());
    }
    auto without = Cells(
      box, [](vtkIdType c) { return c % 7 != 0; }, asIs);
    exactEverywhere("duplicate cells", doubled, property, without, property, true);
  }
  // Unused points: 100 points no cell uses, inside the bounds (which frame
  // the camera), with a scalar far outside the used range (which would
  // squeeze the table if it counted).
  {
    auto extra = Cells(box, all, asIs);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->DeepCopy(box->GetPoints());
    vtkNew<vtkDoubleArray> scalars;
    scalars->DeepCopy(box->GetPointData()->GetScalars());
    for (int i = 0; i < 100; ++i)
    {
      points->InsertNextPoint(0.01 * i, 0.5, 0.3);
      scalars->InsertNextValue(1e6);
    }
    extra->SetPoints(points);
    extra->GetPointData()->SetScalars(scalars);
    auto without = Cells(
      box, [](vtkIdType c) { return c % 2 == 0; }, asIs);
    exactEverywhere("unused points", extra, property, without, property, false);
  }
  // Zero-volume cells on existing points (four of a cube face's corners).
  {
    auto flat = Cells(box, all, asIs);
    // The lattice point (i, j, k) of the box (spacing 0.25), found by position.
    std::map<std::array<int, 3>, vtkIdType> lattice;
    for (vtkIdType i = 0; i < box->GetNumberOfPoints(); ++i)
    {
      double x[3];
      box->GetPoint(i, x);
      lattice[{ static_cast<int>(std::lround(4 * x[0])), static_cast<int>(std::lround(4 * x[1])),
        static_cast<int>(std::lround(4 * x[2])) }] = i;
    }
    int added = 0;
    for (int k = 0; k <= 4 && added < 40; ++k)
    {
      for (int j = 0; j < 4 && added < 40; ++j)
      {
        for (int i = 0; i < 4 && added < 40; i += 2)
        {
          // Four corners of a lattice square in the plane z = k / 4.
          const vtkIdType ids[4] = { lattice.at({ i, j, k }), lattice.at({ i + 1, j, k }),
            lattice.at({ i, j + 1, k }), lattice.at({ i + 1, j + 1, k }) };
          flat->InsertNextCell(VTK_TETRA, 4, ids);
          ++added;
        }
      }
    }
    auto halfUnit = havstest::MakeRampPropertyFor(box);
    halfUnit->SetScalarOpacityUnitDistance(0.5 * property->GetScalarOpacityUnitDistance());
    exactEverywhere("zero-volume cells", flat, property, box, halfUnit, true);
  }
  // Non-manifold: two boxes sharing an edge, and a vertex.
  for (bool vertex : { false, true })
  {
    auto second = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
    auto moved = Moved(
      second, [](double x) { return x; }, true);
    vtkPoints* p = moved->GetPoints();
    for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
    {
      double x[3];
      p->GetPoint(i, x);
      p->SetPoint(i, x[0] + 1.0, x[1] + 1.0, x[2] + (vertex ? 1.0 : 0.0));
    }
    vtkNew<vtkAppendFilter> append;
    append->MergePointsOn();
    append->AddInputData(box);
    append->AddInputData(moved);
    append->Update();
    auto both = vtkSmartPointer<vtkUnstructuredGrid>::New();
    both->DeepCopy(append->GetOutput());
    const vtkIdType shared = 2 * box->GetNumberOfPoints() - both->GetNumberOfPoints();
    std::printf("two boxes sharing %s: %lld shared points\n", vertex ? "a vertex" : "an edge",
      static_cast<long long>(shared));
    havstest::Check(shared == (vertex ? 1 : 5), "the boxes share their points there");
    exactEverywhere(vertex ? "boxes sharing a vertex" : "boxes sharing an edge", both, property,
      box, property, false);
  }
  return havstest::Result();
}

/// A square view's float result against the exact reference from the same
/// camera, finite, the reference covering more than `minCovered` pixels;
/// control: the reference of the view turned by 25 degrees must differ.
void CheckView(const std::string& what, bool subset, const std::vector<float>& image,
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int size,
  int minCovered, double rmseBound = 5e-4, double maxBound = 0.01)
{
  if (subset)
  {
    rmseBound = std::max(rmseBound, kLodRMSE);
    maxBound = std::max(maxBound, kLodMax);
  }
  const auto exact = ReferenceImage(grid, property, camera, size, size);
  const size_t covered = CoveredPixels(exact);
  const size_t edge = static_cast<size_t>(size) * size / 2000;
  const auto d = havstest::Compare(image, exact, edge);
  const auto c =
    havstest::Compare(image, ReferenceImage(grid, property, camera, size, size, 25.0), edge);
  Print(what + ": vs reference", d);
  Print(what + ": control, the view turned", c);
  std::printf("    %zu pixels covered\n", covered);
  havstest::Check(covered > static_cast<size_t>(minCovered), what + ": the mesh is seen");
  auto within = [&](const havstest::ImageDifference& e)
  { return e.RMSE < rmseBound && e.Max < maxBound; };
  havstest::Check(within(d) && havstest::AllFinite(image),
    what + ": within RMSE " + std::to_string(rmseBound) + ", max " + std::to_string(maxBound) +
      ", and finite");
  havstest::Check(!within(c), what + ": control, another view fails");
}

/// How `image` meets the references of the same view with the camera moved a
/// hair (1e-3 of a pixel) in eight directions across the view (`nudged`):
/// pixels outside every channel's range of the nudged images widened by 0.01
/// (`Outside`); pixels where those images agree to 1e-3 (`Defined`) and the
/// difference from the unmoved reference there.
struct Envelope
{
  size_t Outside = 0;
  size_t Defined = 0;
  double DefinedRMSE = 0.0;
  double DefinedMax = 0.0;
};

Envelope CompareWithEnvelope(const std::vector<float>& image, const std::vector<float>& exact,
  const std::vector<std::vector<float>>& nudged)
{
  Envelope e;
  double sum = 0.0;
  size_t values = 0;
  for (size_t p = 0; p + 3 < exact.size(); p += 4)
  {
    bool outside = false;
    bool defined = true;
    for (size_t c = p; c < p + 4; ++c)
    {
      float lo = exact[c];
      float hi = exact[c];
      for (const auto& n : nudged)
      {
        lo = std::min(lo, n[c]);
        hi = std::max(hi, n[c]);
      }
      outside = outside || !(image[c] >= lo - 0.01f && image[c] <= hi + 0.01f);
      defined = defined && hi - lo < 1e-3f;
    }
    e.Outside += outside ? 1 : 0;
    if (defined)
    {
      ++e.Defined;
      for (size_t c = p; c < p + 4; ++c)
      {
        const double d = std::fabs(static_cast<double>(image[c]) - exact[c]);
        sum += d * d;
        e.DefinedMax = std::max(e.DefinedMax, std::isfinite(d) ? d : 1e30);
        ++values;
      }
    }
  }
  e.DefinedRMSE = values ? std::sqrt(sum / values) : 0.0;
  return e;
}

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
  size_t maxOutside = 0, Bound defined = { 5e-4, 0.01 })
{
  const auto exact = ReferenceImage(grid, property, camera, size, size);
  double right[3], up[3];
  vtkNew<vtkCamera> c;
  c->DeepCopy(camera);
  c->OrthogonalizeViewUp();
  c->GetViewUp(up);
  const double* plane = c->GetViewPlaneNormal();
  vtkMath::Cross(up, plane, right);
  const double pixel = camera->GetParallelProjection() ? 2.0 * camera->GetParallelScale() / size
                                                       : 2.0 * camera->GetDistance() *
      std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2) / size;
  std::vector<std::vector<float>> nudged;
  for (int k = 0; k < 8; ++k)
  {
    const double a = k * vtkMath::Pi() / 4.0;
    const double step = 1e-3 * pixel;
    double shift[3];
    for (int i = 0; i < 3; ++i)
    {
      shift[i] = step * (std::cos(a) * right[i] + std::sin(a) * up[i]);
    }
    vtkNew<vtkCamera> moved;
    moved->DeepCopy(camera);
    const double* pos = camera->GetPosition();
    const double* focal = camera->GetFocalPoint();
    moved->SetPosition(pos[0] + shift[0], pos[1] + shift[1], pos[2] + shift[2]);
    moved->SetFocalPoint(focal[0] + shift[0], focal[1] + shift[1], focal[2] + shift[2]);
    nudged.push_back(ReferenceImage(grid, property, moved, size, size));
  }
  const size_t edge = std::max<size_t>({ 1, static_cast<size_t>(size) * size / 2000, maxOutside });
  const Envelope e = CompareWithEnvelope(image, exact, nudged);
  const Envelope c25 =
    CompareWithEnvelope(ReferenceImage(grid, property, camera, size, size, 25.0), exact, nudged);
  std::printf("  %-62s %zu of %d pixels on jumps; outside the sides' range: %zu (control %zu); "
              "elsewhere RMSE %.2e max %.2e\n",
    what.c_str(), static_cast<size_t>(size) * size - e.Defined, size * size, e.Outside, c25.Outside,
    e.DefinedRMSE, e.DefinedMax);
  havstest::Check(e.Outside <= edge && havstest::AllFinite(image),
    what + ": every pixel within its sides' range, finite");
  havstest::Check(e.DefinedRMSE < defined.RMSE && e.DefinedMax < defined.Max,
    what + ": within RMSE " + std::to_string(defined.RMSE) + ", max " +
      std::to_string(defined.Max) + " where defined");
  havstest::Check(c25.Outside > edge, what + ": control, another view fails");
}

/// Degenerate views (issue 20) of an axis-aligned box of 4^3 cubes (5
/// tetrahedra each, s = z): orthographic views exactly along +z, +x and -y
/// with pixel centres on the grid lines (every face parallel to the view
/// direction is seen edge-on, rays run along internal faces); perspective
/// views with the eye exactly on a face plane, on an edge and on a vertex of
/// the lattice (outside the box, looking at it). Each through both mappers
/// against the exact reference, finite; control: the reference of the view
/// turned by 25 degrees.
int DegenerateViews()
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

/// [0, 3 length] x [0, 3] x [0, 3] in 3^3 boxes of 5 tetrahedra (every
/// cell `length` long and 1 wide), points as double, s = (z + x / length) / 6.
vtkSmartPointer<vtkUnstructuredGrid> MakeElongated(double length)
{
  auto box = vtkHAVSDataSets::MakeBox(3, 3, 3, 1.0, 0.0, 1.0);
  auto grid = Moved(
    box, [](double v) { return v; }, true);
  vtkPoints* points = grid->GetPoints();
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  s->SetNumberOfTuples(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    s->SetValue(i, (x[2] + x[0]) / 6.0);
    points->SetPoint(i, x[0] * length, x[1], x[2]);
  }
  grid->GetPointData()->SetScalars(s);
  return grid;
}

/// A mesh 1e6 times longer than wide (issue 20): [0, 3e6] x [0, 3] x [0, 3]
/// in 3^3 boxes of 5 tetrahedra, every cell 1e6 long and 1 wide, points as
/// double, s = (z + x / 1e6) / 6. Seen along its axis orthographically (every
/// ray through the whole length, a clipping range of 6e6 : 1; HAVS only), and
/// from the side, where rays cross the needles' long faces: the middle from
/// 10 away in perspective, the middle orthographically 45 degrees off the
/// axis, and near one end in perspective (unit distance 5; HAVS and the cell
/// projection). Each against the exact reference, finite, no message; the
/// axis view exact (RMSE < 5e-4, max < 0.01), the side views within RMSE
/// 1e-3, max 0.01 (measured: HAVS 4.2e-4 to 6.0e-4, max up to 5.6e-3; the
/// same views of a slab of unit cubes at the same place give 4.5e-5 to
/// 1.0e-4: the rest is the float positions across triangles 1e6 long).
/// Control: the reference of the view turned by 25 degrees. The reference
/// itself was checked on the middle views: the slab [1.5e6 - 12, 1.5e6 + 12]
/// x [0, 3] x [0, 3] in unit cubes with the same linear field holds every
/// ray's part inside the mesh, and its reference image is bit-identical to
/// the elongated mesh's. (Before this case the face set dropped every such
/// cell as degenerate, and the reference renderer's missing image crashed the
/// test. An earlier session measured the side views at RMSE 0.16 and 0.098 and
/// left them out; which change since made them pass was not traced: the
/// table's logarithmic length axis and the parallel camera's eye moved near
/// the volume are the candidates.)
///
/// Limit this mesh shows: the cell projection along the axis, where rays on
/// the pixel diagonals run within 1e-6 (relative) of the needles' diagonal
/// faces over their whole 1e6 length: RMSE 5.8e-3, max 0.14 (0.19 before its
/// parallel-face bound was lowered). Checked against a stated bound, RMSE
/// 1e-2 and max 0.2 (the turned view's control: RMSE 0.35, max 0.83).
int Elongated()
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

/// The stock mappers beside HAVS (issue 20: "reported, not asserted"): each
/// stress scene below rendered by HAVS, vtkProjectedTetrahedraMapper,
/// vtkUnstructuredGridVolumeZSweepMapper and
/// vtkUnstructuredGridVolumeRayCastMapper (linear integrator, every pixel), each
/// in a process of its own (this driver again, `stock-one`), so that a mapper
/// that crashes or hangs is reported as such. Every mapper's window colour
/// (8-bit, over black) against the exact reference's colour.
struct StockScene
{
  const char* Name;
  int Width;
  int Height;
  std::function<void(
    vtkSmartPointer<vtkUnstructuredGrid>&, vtkSmartPointer<vtkVolumeProperty>&, vtkCamera*)>
    Make;
};

std::vector<StockScene> StockScenes()
{
  auto sphere = [](vtkSmartPointer<vtkUnstructuredGrid>& grid,
                  vtkSmartPointer<vtkVolumeProperty>& property, double factor, double offset)
  {
    auto base = vtkHAVSDataSets::Load("hollowsphere");
    property = havstest::MakeRampPropertyFor(base);
    property->SetScalarOpacityUnitDistance(property->GetScalarOpacityUnitDistance() * factor);
    grid = Moved(
      base, [=](double x) { return x * factor + offset; }, true);
  };
  auto scalars = [](vtkSmartPointer<vtkUnstructuredGrid>& grid,
                   vtkSmartPointer<vtkVolumeProperty>& property,
                   const std::function<double(vtkIdType, double)>& f, double scale)
  {
    auto base = vtkHAVSDataSets::Load("hollowsphere");
    double range[2];
    base->GetPointData()->GetScalars()->GetRange(range);
    grid = WithScalars(base,
      [&](vtkIdType i, double v) { return f(i, (v - range[0]) / (range[1] - range[0])) * scale; });
    property = havstest::MakeRampProperty(0.0, scale, 0.8, grid->GetLength() / 8.0);
  };
  auto view = [](vtkCamera* camera, vtkUnstructuredGrid* grid, double azimuth, double elevation)
  {
    vtkNew<vtkRenderer> r;
    r->SetActiveCamera(camera);
    r->ResetCamera(grid->GetBounds());
    camera->Azimuth(azimuth);
    camera->Elevation(elevation);
    camera->OrthogonalizeViewUp();
    r->ResetCamera(grid->GetBounds());
  };
  std::vector<StockScene> scenes;
  scenes.push_back({ "hollow sphere (as is)", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1.0, 0.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "coordinates x 1e-8", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1e-8, 0.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "coordinates x 1e8", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1e8, 0.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "moved by 1e9 (double points)", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1.0, 1e9);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "NaN at a tenth of the scalars", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType i, double v) { return i % 10 == 3 ? std::nan("") : v; }, 1.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "+Inf at a tenth of the scalars", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType i, double v) { return i % 10 == 3 ? HUGE_VAL : v; }, 1.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "scalars x 1e30", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1e30);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "opacity spike narrower than a table bin", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1.0);
      vtkPiecewiseFunction* o = p->GetScalarOpacity();
      o->RemoveAllPoints();
      o->AddPoint(0.0, 0.0);
      o->AddPoint(0.499, 0.0);
      o->AddPoint(0.5, 1.0);
      o->AddPoint(0.501, 0.0);
      o->AddPoint(1.0, 0.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "fully opaque", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1.0);
      p->GetScalarOpacity()->RemoveAllPoints();
      p->GetScalarOpacity()->AddPoint(0.0, 1.0);
      p->GetScalarOpacity()->AddPoint(1.0, 1.0);
      p->SetScalarOpacityUnitDistance(g->GetLength() * 1e-3);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "box, orthographic exactly along -x", 65, 65,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      g = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
      p = havstest::MakeRampPropertyFor(g);
      c->SetParallelProjection(1);
      c->SetPosition(5.0, 0.5, 0.5);
      c->SetFocalPoint(0.5, 0.5, 0.5);
      c->SetViewUp(0, 0, 1);
      c->SetParallelScale(0.5 * 65 * 0.025);
      c->SetClippingRange(1.0, 10.0);
    } });
  scenes.push_back({ "mesh 1e6 x longer than wide, along its axis", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      g = MakeElongated(1e6);
      p = havstest::MakeRampProperty(0.0, 1.0, 0.8, 1e6);
      c->SetParallelProjection(1);
      c->SetPosition(-10.0, 1.5, 1.5);
      c->SetFocalPoint(3e6, 1.5, 1.5);
      c->SetViewUp(0, 0, 1);
      c->SetParallelScale(2.0);
      c->SetClippingRange(0.5, 3.1e6 + 20.0);
    } });
  scenes.push_back({ "-Inf at a tenth of the scalars", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType i, double v) { return i % 10 == 3 ? -HUGE_VAL : v; }, 1.0);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "denormal scalars (x 1e-310)", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1e-310);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "cell scalars", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1.0);
      g = CellScalarCopy(g);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "cell scalars, opacity spike at a cell's value", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      scalars(
        g, p, [](vtkIdType, double v) { return v; }, 1.0);
      g = CellScalarCopy(g);
      const double at = g->GetCellData()->GetScalars()->GetTuple1(g->GetNumberOfCells() / 2);
      vtkPiecewiseFunction* o = p->GetScalarOpacity();
      o->RemoveAllPoints();
      o->AddPoint(0.0, 0.0);
      o->AddPoint(at - 0.001, 0.0);
      o->AddPoint(at, 1.0);
      o->AddPoint(at + 0.001, 0.0);
      o->AddPoint(1.0, 0.0);
      view(c, g, 30, 20);
    } });
  auto box = [](vtkSmartPointer<vtkUnstructuredGrid>& g, vtkSmartPointer<vtkVolumeProperty>& p)
  {
    g = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
    p = havstest::MakeRampPropertyFor(g);
  };
  scenes.push_back({ "box, every other cell inverted", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      box(g, p);
      g = Cells(
        g, [](vtkIdType) { return true; },
        [](vtkIdType cell, vtkIdType* ids)
        {
          if (cell % 2)
          {
            std::swap(ids[0], ids[1]);
          }
        });
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "box, duplicate and zero-volume cells", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      box(g, p);
      auto base = g;
      g = Cells(
        base, [](vtkIdType) { return true; }, [](vtkIdType, vtkIdType*) {});
      for (vtkIdType cell = 0; cell < base->GetNumberOfCells(); cell += 7)
      {
        g->InsertNextCell(VTK_TETRA, base->GetCell(cell)->GetPointIds());
      }
      // A flat cell: the first cell's points with one repeated.
      vtkIdList* first = base->GetCell(0)->GetPointIds();
      const vtkIdType repeated[4] = { first->GetId(0), first->GetId(1), first->GetId(2),
        first->GetId(2) };
      g->InsertNextCell(VTK_TETRA, 4, repeated);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "sliver tetrahedron", 64, 64,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      g =
        MakeTets({ { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0.01 }, { 0, 1, 0.01 } }, { { 0, 1, 2, 3 } });
      double range[2];
      g->GetPointData()->GetScalars()->GetRange(range);
      p = havstest::MakeRampProperty(range[0] - 0.1, range[1] + 0.1, 0.9, 0.5);
      view(c, g, 30, 20);
    } });
  scenes.push_back({ "1 x 1 window", 1, 1,
    [=](auto& g, auto& p, vtkCamera* c)
    {
      sphere(g, p, 1.0, 0.0);
      view(c, g, 30, 20);
      double f[3], e[3];
      c->GetFocalPoint(f);
      c->GetPosition(e);
      const double d = 0.017 * g->GetLength();
      c->SetFocalPoint(f[0] + d, f[1] + d, f[2]);
      c->SetPosition(e[0] + d, e[1] + d, e[2]);
    } });
  return scenes;
}

const char* const StockMapperNames[] = { "HAVS", "PT", "ZSweep", "RayCast" };

/// One scene, one mapper (the child process): prints one STOCK line.
int StockOne(int scene, const std::string& mapperName)
{
  if (scene < 0)
  {
    std::abort(); // the harness' control: a mapper that crashes
  }
  const auto scenes = StockScenes();
  if (!havstest::Check(scene < static_cast<int>(scenes.size()), "a known stock scene"))
  {
    return havstest::Result();
  }
  const StockScene& sc = scenes[scene];
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  vtkSmartPointer<vtkVolumeProperty> property;
  vtkNew<vtkCamera> camera;
  sc.Make(grid, property, camera);
  vtkSmartPointer<vtkAbstractVolumeMapper> mapper;
  if (mapperName == "PT")
  {
    mapper = vtkSmartPointer<vtkProjectedTetrahedraMapper>::New();
  }
  else if (mapperName == "ZSweep")
  {
    mapper = vtkSmartPointer<vtkUnstructuredGridVolumeZSweepMapper>::New();
  }
  else if (mapperName == "RayCast")
  {
    auto ray = vtkSmartPointer<vtkUnstructuredGridVolumeRayCastMapper>::New();
    ray->SetImageSampleDistance(1.0);
    ray->AutoAdjustSampleDistancesOff();
    vtkNew<vtkUnstructuredGridLinearRayIntegrator> integrator;
    ray->SetRayIntegrator(integrator);
    mapper = ray;
  }
  else
  {
    auto havs = vtkSmartPointer<vtkHAVSVolumeMapper>::New();
    ConfigureOrder(havs);
    mapper = havs;
  }
  havstest::Messages* messages = havstest::CountMessages(mapper);
  auto s = havstest::MakeScene(grid, mapper, property, sc.Width, sc.Height);
  s.Renderer->GetActiveCamera()->DeepCopy(camera);
  const double start = vtkTimerLog::GetUniversalTime();
  s.Window->Render();
  const double seconds = vtkTimerLog::GetUniversalTime() - start;
  std::vector<float> image = havstest::ReadRGBA(s.Window);
  std::vector<float> exact = ReferenceImage(grid, property, camera, sc.Width, sc.Height);
  // Colour over black: the window's alpha means nothing here.
  for (size_t i = 3; i < image.size() && image.size() == exact.size(); i += 4)
  {
    image[i] = exact[i] = 0.0f;
  }
  const size_t edge = static_cast<size_t>(sc.Width) * sc.Height / 2000;
  const auto d = havstest::Compare(image, exact, edge);
  std::printf(
    "STOCK %.6g %.6g %.4f %d %d\n", d.RMSE, d.Max, seconds, messages->Errors, messages->Warnings);
  return EXIT_SUCCESS;
}

/// The table of every scene through every mapper, each in its own process.
int Stock()
{
  char self[4096] = {};
  const ssize_t n = readlink("/proc/self/exe", self, sizeof(self) - 1);
  if (!havstest::Check(n > 0, "this driver's path"))
  {
    return havstest::Result();
  }
  struct Outcome
  {
    std::string Text;
    bool Ran = false;
    double RMSE = 0.0;
    double Max = 0.0;
  };
  auto run = [&](int scene, const std::string& mapper)
  {
    const std::string command = std::string("timeout 300 '") + self +
      "' TestHAVSStress stock-one " + std::to_string(scene) + " " + mapper + " 2>&1";
    Outcome out;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe)
    {
      out.Text = "not started";
      return out;
    }
    char line[1024];
    double rmse = 0, max = 0, seconds = 0;
    int errors = 0, warnings = 0;
    bool found = false;
    while (std::fgets(line, sizeof(line), pipe))
    {
      found = found ||
        std::sscanf(line, "STOCK %lf %lf %lf %d %d", &rmse, &max, &seconds, &errors, &warnings) ==
          5;
    }
    const int status = pclose(pipe);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    char text[160];
    if (code == 124)
    {
      std::snprintf(text, sizeof(text), "hung (killed after 300 s)");
    }
    else if (code > 128 || code < 0)
    {
      std::snprintf(text, sizeof(text), "crashed (signal %d)", code > 128 ? code - 128 : -1);
    }
    else if (!found)
    {
      std::snprintf(text, sizeof(text), "no result (exit %d)", code);
    }
    else
    {
      out.Ran = true;
      out.RMSE = rmse;
      out.Max = max;
      std::snprintf(text, sizeof(text), "RMSE %.4f max %.3f, %.2f s%s%s", rmse, max, seconds,
        errors ? ", errors" : "", warnings ? ", warnings" : "");
    }
    out.Text = text;
    return out;
  };

  // The harness' control: a child that aborts is reported as crashed.
  const Outcome crash = run(-1, "HAVS");
  std::printf("control, a child that aborts: %s\n", crash.Text.c_str());
  havstest::Check(!crash.Ran && crash.Text.rfind("crashed", 0) == 0,
    "control: a crashing child is reported as crashed");

  const auto scenes = StockScenes();
  std::printf("\n| scene | %s | %s | %s | %s |\n|---|---|---|---|---|\n", StockMapperNames[0],
    StockMapperNames[1], StockMapperNames[2], StockMapperNames[3]);
  for (size_t i = 0; i < scenes.size(); ++i)
  {
    std::string row = std::string("| ") + scenes[i].Name;
    for (const char* mapper : StockMapperNames)
    {
      const Outcome o = run(static_cast<int>(i), mapper);
      row += " | " + o.Text;
      if (std::string(mapper) == "HAVS")
      {
        // HAVS through the window's 8-bit colour: within quantization.
        havstest::Check(o.Ran && o.RMSE < 0.004 && o.Max < 0.03,
          std::string(scenes[i].Name) + ": HAVS exact (8-bit window colour)");
      }
    }
    std::printf("%s |\n", row.c_str());
    std::fflush(stdout);
  }
  return havstest::Result();
}

/// The largest width and height a framebuffer of this context may have: the
/// least of GL's viewport, texture and renderbuffer limits.
int LargestWindowDimension(vtkRenderWindow* window)
{
  window->MakeCurrent();
  GLint viewport[2] = { 0, 0 };
  GLint texture = 0;
  GLint renderbuffer = 0;
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  std::printf("context limits: viewport %d x %d, texture %d, renderbuffer %d\n", viewport[0],
    viewport[1], texture, renderbuffer);
  return std::min({ viewport[0], viewport[1], texture, renderbuffer });
}

int Resize()
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  auto property = havstest::MakeRampPropertyFor(grid);
  for (bool cells : { false, true })
  {
    auto mapper = MakeMapper(cells);
    auto s = havstest::MakeScene(OnPath(grid), mapper, property, 8, 8);
    s.Window->Render();
    // The sizes, ending with the largest width and the largest height the
    // context allows (a strip 2 high and a column 2 wide through the
    // sphere's middle; their coverage is their control, the exact reference
    // of another view there costs 20 s a time).
    const int largest = LargestWindowDimension(s.Window);
    std::vector<std::array<int, 2>> sizes = { { 1, 1 }, { 2, 3 }, { 17, 5 }, { 64, 64 },
      { 200, 120 }, { 96, 96 }, { largest, 2 }, { 2, largest } };
    // The column found a defect (issue 20): HAVS measured a parallel view's
    // distances from the camera, here 70 diagonals away, and float rounding
    // there swapped the entry and the exit of rays grazing a silhouette edge
    // (a gap filled: 5 x 1024 max 0.19). vtkHAVSViewFrame now measures them
    // from at most one diagonal in front of the volume.
    for (const auto& wh : sizes)
    {
      // Largest in one dimension: seen orthographically, the sphere spanning
      // the long side.
      const bool strip = wh[0] == largest || wh[1] == largest;
      s.Window->SetSize(wh[0], wh[1]);
      havstest::PlaceCamera(s.Renderer, 30.0, 20.0, strip);
      // Off the mesh's centre: a 1 x 1 window's one ray would otherwise run
      // through the centre vertex of the voxel-like mesh, where rasterizer
      // and rays may meet different faces (an edge pixel, and the only one).
      vtkCamera* camera = s.Renderer->GetActiveCamera();
      double focal[3], position[3];
      camera->GetFocalPoint(focal);
      camera->GetPosition(position);
      const double shift[3] = { 0.017 * grid->GetLength(), 0.011 * grid->GetLength(),
        0.007 * grid->GetLength() };
      camera->SetFocalPoint(focal[0] + shift[0], focal[1] + shift[1], focal[2] + shift[2]);
      camera->SetPosition(position[0] + shift[0], position[1] + shift[1], position[2] + shift[2]);
      if (strip)
      {
        camera->SetParallelScale(
          camera->GetParallelScale() * std::min(wh[0], wh[1]) / std::max(wh[0], wh[1]));
      }
      s.Renderer->ResetCameraClippingRange();
      s.Window->Render();
      const auto image = havstest::FloatResult(mapper);
      const std::string what =
        std::string(Name(cells)) + ", " + std::to_string(wh[0]) + " x " + std::to_string(wh[1]);
      if (!havstest::Check(image.size() == 4 * static_cast<size_t>(wh[0]) * wh[1],
            what + ": result kept at the window's size"))
      {
        continue;
      }
      auto reference = [&](double azimuth) {
        return ReferenceImage(grid, property, s.Renderer->GetActiveCamera(), wh[0], wh[1], azimuth);
      };
      const size_t edge = static_cast<size_t>(wh[0]) * wh[1] / 2000;
      const auto exact = reference(0.0);
      const auto d = havstest::Compare(image, exact, edge);
      Print(what + ": vs reference", d);
      havstest::Check(
        Accurate(d, DrewSubset(mapper)) && havstest::AllFinite(image), what + ": exact and finite");
      if (wh[0] == largest || wh[1] == largest)
      {
        const size_t covered = CoveredPixels(exact);
        std::printf(
          "    %zu of %lld pixels covered\n", covered, static_cast<long long>(wh[0]) * wh[1]);
        havstest::Check(
          covered > static_cast<size_t>(wh[0]) * wh[1] / 3, what + ": the sphere spans the window");
      }
      if (wh[0] * wh[1] >= 64 * 64 && wh[0] != largest && wh[1] != largest)
      {
        const auto c = havstest::Compare(image, reference(40.0), edge);
        Print(what + ": control, another view's reference", c);
        havstest::Check(!Accurate(c, DrewSubset(mapper)), what + ": control, another view fails");
      }
    }
  }
  return havstest::Result();
}
}

int TestHAVSStress(int argc, char* argv[])
{
  const std::string which = argc > 1 ? argv[1] : "scale";
  if (which == "scale")
  {
    return Scale();
  }
  if (which == "translate")
  {
    return Translate();
  }
  if (which == "resize")
  {
    return Resize();
  }
  if (which == "scalars")
  {
    return Scalars();
  }
  if (which == "cells")
  {
    return BadCells(argc > 2 && std::string(argv[2]) == "full");
  }
  if (which == "views")
  {
    return DegenerateViews();
  }
  if (which == "elongated")
  {
    return Elongated();
  }
  if (which == "stock")
  {
    return Stock();
  }
  if (which == "stock-one" && argc > 3)
  {
    return StockOne(std::atoi(argv[2]), argv[3]);
  }
  havstest::Check(
    false, "a known case: scale, translate, resize, scalars, cells, views, elongated, stock");
  return havstest::Result();
}
