/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestStress.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestStress.h"

#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestScenes.h"

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace havstest
{
namespace stress
{
namespace
{
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
}

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

bool DrewSubset(vtkUnstructuredGridVolumeMapper* mapper)
{
  auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper);
  return havs && havs->GetLastFrameStatistics()->GetLevelOfDetailFraction() < 1.0;
}

bool Accurate(const havstest::ImageDifference& d, bool subset, Bound lod)
{
  if (subset)
  {
    return d.RMSE < lod.RMSE && d.Max < lod.Max;
  }
  return d.RMSE < 5e-4 && d.Max < 0.01;
}

std::vector<float> Render(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, bool cells,
  int width, int height, bool* subset)
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

std::vector<float> ReferenceImage(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkCamera* camera, int width, int height, double azimuth)
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

size_t CoveredPixels(const std::vector<float>& rgba)
{
  size_t covered = 0;
  for (size_t i = 3; i < rgba.size(); i += 4)
  {
    covered += rgba[i] > 1e-3f ? 1 : 0;
  }
  return covered;
}

const std::vector<float>& PairReferences::Get(
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
      this->Images.emplace(key, ReferenceImage(grid, property, camera, kPairSize, kPairSize)).first;
  }
  return found->second;
}

Pair RenderWithReference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, bool cells,
  PairReferences& references, double azimuth, double elevation)
{
  return RenderWithReference(grid, property, MakeMapper(cells), references, azimuth, elevation);
}

Pair RenderWithReference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkUnstructuredGridVolumeMapper* mapper, PairReferences& references, double azimuth,
  double elevation)
{
  const int size = kPairSize;
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

void CheckView(const std::string& what, bool subset, const std::vector<float>& image,
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int size,
  int minCovered, double rmseBound, double maxBound)
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

void CheckViewOnJumps(const std::string& what, const std::vector<float>& image,
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int size,
  size_t maxOutside, Bound defined)
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
}
}
