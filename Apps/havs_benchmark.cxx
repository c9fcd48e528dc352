/*=========================================================================

  Project:   vtkHAVS
  Module:    havs_benchmark.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_benchmark: run time against error, every mapper side by side.
//
//   havs_benchmark [--quick] [--size N | --sizes a,b] [--views N] [--repeats N]
//                  [--datasets a,b,...] [--configs a,b,...] [--output-dir DIR]
//                  [--cache-dir DIR] [--budget SECONDS] [--from-csv FILE]
//                  [--dump-case DIR [--dump-kinds a,b]] [--rounds N]
// (--rounds N: every configuration N times, round-robin, each time the median
// over the rounds: this machine's slow drifts hit every configuration alike.)
// (--dump-case DIR: only write view 0 of each data set, drawn by each mapper
// of --dump-kinds (havs_k2, havs_k6, cellprojection, raycast by default;
// table<N>: the pre-integrated table at N^3 built on the GPU, for issue 45;
// havs_k2_t43, havs_k6_t43: HAVS with the thesis' Table 4.3 settings),
// as frame cases for Apps/GPUBench/havs_gpu_bench, with the exact image.)
// (--from-csv a.csv,b.csv: only make the report again from earlier runs' CSVs;
// rows without a size column take --size.)
//
// Data sets: bluntfin, loxpost (PLOT3D), combustor, loxpostvtk (post.vtk) from
// ../shared/data (HAVS_DATA_DIR), and gen1M, gen4M, gen10M: tetrahedralized
// blocks of 60^3, 94^3 and 127^3 cubes (5 tets each: 1.08M, 4.15M, 10.2M tets)
// with the analytic field sin(6x) cos(5y) + z, made here. "<name>-band" (e.g.
// bluntfin-band): that data set with a transfer function that hides the middle
// 76 % of the range (opacity only in the lowest and highest 12 %): what
// skipping invisible cells saves; "<name>-opaque": opacity 0.5 to 1 and a unit
// distance ten times shorter, most rays ending early: what rejecting saturated
// pixels saves; "<name>-zoom": the standard function, each view zoomed 4x on a
// point between the centre and a corner of the bounds, so that most cells lie
// outside the view frustum: what culling off-screen cells saves.
// Configurations: HAVS at k = 1, 2, 4, 6, 8, 14 (128^3 table), HAVS k = 14 with
// 32^3 and 64^3 tables, HAVS k = 6 without boundary tagging (its cost and
// what it buys; -gaplength: VTK 5's heuristic), -mpvo (the MPVO face order instead of
// the centroid sort, with the boundary layers, e.g. havs-k2-mpvo; -mpvo-convex: with the
// convexification), -auto (the Automatic order; without -mpvo or -auto the centroid sort),
// -count (the order-violation counter on), -noterm (no early ray termination), -opaque (an
// opaque actor in the scene, so the opaque-depth cut runs), havs-default (the mapper with its
// default settings: what a user gets; havs-default-noskip: with every cell drawn,
// SkipInvisibleCells off; havs-default-sat: SkipSaturatedPixels on every path;
// havs-default-nocull: every cell ordered and drawn, SkipOffscreenCells off;
// havs-default-noclamp, with an iso- prefix: isosurface fragments as the rasterizer gives
// them, not placed on their faces, NoFaceClampForTesting), HAVS fragment lists
// (exact per-pixel sort), raster-bound (the same faces in the same order with a trivial shader: the
// lower bound of any face-based method; sort-bound is the sort alone),
// reference (the exact images, computed and cached in their own process before
// the timed configurations; always run first), cellproj (vtkHAVSCellProjectionMapper:
// the exact MPVO cell order, boundary layers; cellproj-convex: the convexification;
// cellproj-floatiso, with an iso- prefix: the isosurface frames' stretches in float,
// FloatIsoStretchesForTesting),
// tetraycast (vtkHAVSRayCastMapper: GPU ray casting through the tetrahedra, re-entries
// by depth peeling; its rows add the peeling passes, cells crossed per ray and
// the screen tiles used, medians over the views; tetraycast-nofolds: without its
// re-entries across folds of the boundary), and
// VTK's vtkProjectedTetrahedraMapper, vtkUnstructuredGridVolumeZSweepMapper and
// vtkUnstructuredGridVolumeRayCastMapper (ImageSampleDistance 1,
// AutoAdjustSampleDistances off, vtkUnstructuredGridLinearRayIntegrator).
// edit-<configuration> (e.g. edit-havs-default, edit-tetraycast, edit-cellproj,
// edit-pt): that configuration, then at view 0 still redraws and
// transfer-function edits (one opacity node moved), with the edit's parts
// (MeasureEdits); their own report section. <configuration>-gputable (e.g.
// edit-havs-default-gputable): a project mapper with its tables built on the
// GPU (vtkHAVSMapperBase::PreIntegrationOnGPU).
// lod-<percent>-<configuration> (e.g. lod-20-havs-default, lod-20-tetraycast,
// lod-20-cellproj; any configuration of a vtkHAVSMapperBase mapper): at view 0
// the full frame while the camera turns, then that share of it as the frame
// budget (vtkHAVSMapperBase::SetLevelOfDetailTargetSeconds) for 60 frames, the
// interactive frame's error and the still frame's (MeasureBudget); their own
// report section (frame budgets). floor-<configuration> (same mappers): the
// frame at fixed image scales 1, 0.1 and 0.01 over the budgets' views, with its
// parts (MeasureFloor): what no budget can go below, in the same section.
//
// Each (data set, configuration) runs in its own child process (peak memory
// only grows), renders the fixed viewpoints (the 6 axis directions and the 8
// cube diagonals; a warm-up frame first), waits for the GPU before the clock
// stops, and measures the colour seen in the window against the exact
// reference (vtkHAVSReferenceRenderer, cached on disk by data set, view and
// size); the project's mappers also draw each view once more, untimed, keeping
// their float result, which is what MISSION.md's "exact" is about (an 8-bit
// window rounds to 1/255 on its own). A configuration whose frames exceed the time budget stops
// early and says how many views it measured. Output: CSV, Markdown (with ratios) and, where
// matplotlib is installed, plots.
#include "havsAppOptions.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSGLTableBuilder.h"
#include "vtkHAVSGeneratedBlock.h"
#include "vtkHAVSImageMetrics.h"
#include "vtkHAVSIntermixPass.h"
#include "vtkHAVSInternalFaceRanking.h"
#include "vtkHAVSMapperBase.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkHAVSShaders.h"
#include "vtkHAVSStandardViews.h"
#include "vtkHAVSTranslucentLayers.h"
#include "vtkHAVSVisibilityOrder.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkOpenGLHAVSVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkCubeSource.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace
{
const char* const kPropertyVersion = "ramp1";

struct Options
{
  bool Quick = false;
  bool Worker = false;
  int Size = 512;
  std::vector<int> Sizes; // the coordinator's sizes (default: Size)
  int Views = 14;
  int Repeats = 2;
  int Rounds = 1; // --rounds N: every configuration N times, interleaved round-robin
  double Budget = 600.0;
  std::vector<std::string> DataSets;
  std::vector<std::string> Configs;
  std::string OutputDir = "Documentation";
  std::string CacheDir = "build/benchmark-cache";
  std::string DumpCase; // --dump-case DIR: the GPU program's input, then exit
  std::vector<std::string> DumpKinds = { "havs_k2", "havs_k6", "cellprojection", "raycast" };
  std::string Self;
};

/// The transfer-function variants a data set name may ask for ("<name>-band",
/// "<name>-opaque").
enum class Variant
{
  Standard,
  Band,
  Opaque,
  Zoom
};

/// Not empty, not opaque; every opacity node is a colour node (so that VTK's
/// linear ray integrator integrates it exactly). Band: opacity only in the
/// lowest and highest 12 % of the range, zero in between, so that most cells
/// are invisible (what skipping them saves). Opaque: the standard function
/// with opacity 0.5 to 1 and a unit distance ten times shorter, so that most
/// rays end early (what skipping saturated pixels saves).
vtkSmartPointer<vtkVolumeProperty> MakeProperty(
  vtkUnstructuredGrid* grid, Variant variant = Variant::Standard)
{
  const bool band = variant == Variant::Band;
  const bool opaque = variant == Variant::Opaque;
  double r[2];
  grid->GetPointData()->GetScalars()->GetRange(r);
  const double span = r[1] - r[0];
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(r[0], 0.1, 0.2, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  if (band)
  {
    color->AddRGBPoint(r[0] + 0.12 * span, 0.16, 0.68, 0.58);
    color->AddRGBPoint(r[0] + 0.88 * span, 0.2, 1.0, 0.3);
    opacity->AddPoint(r[0], 0.8);
    opacity->AddPoint(r[0] + 0.12 * span, 0.0);
    opacity->AddPoint(r[0] + 0.88 * span, 0.0);
    opacity->AddPoint(r[1], 0.8);
  }
  else
  {
    color->AddRGBPoint(r[0] + 0.3 * span, 0.16, 0.68, 0.58);
    color->AddRGBPoint(r[0] + 0.5 * span, 0.2, 1.0, 0.3);
    opacity->AddPoint(r[0], opaque ? 0.5 : 0.0);
    opacity->AddPoint(r[0] + 0.3 * span, opaque ? 0.6 : 0.1);
    opacity->AddPoint(r[1], opaque ? 1.0 : 0.8);
  }
  color->AddRGBPoint(r[1], 1.0, 0.3, 0.1);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(grid->GetLength() / (opaque ? 80.0 : 8.0));
  property->ShadeOff();
  return property;
}

/// A data set name with its transfer-function variant: "<name>-band" and
/// "<name>-opaque" load <name> with that function.
const char* const VariantSuffixes[] = { "", "-band", "-opaque", "-zoom" };

Variant VariantOf(const std::string& dataset)
{
  for (Variant v : { Variant::Band, Variant::Opaque, Variant::Zoom })
  {
    const std::string suffix = VariantSuffixes[static_cast<int>(v)];
    if (dataset.size() > suffix.size() &&
      dataset.compare(dataset.size() - suffix.size(), suffix.size(), suffix) == 0)
    {
      return v;
    }
  }
  return Variant::Standard;
}

vtkSmartPointer<vtkUnstructuredGrid> LoadDataSet(const std::string& dataset)
{
  const size_t suffix = std::string(VariantSuffixes[static_cast<int>(VariantOf(dataset))]).size();
  return vtkHAVSDataSets::Load(dataset.substr(0, dataset.size() - suffix));
}

/// A benchmark view: vtkHAVSStandardViews' view; for "<name>-zoom" moved (eye
/// and focal point alike) to look at the point 60 % of the way from the
/// bounds' centre to their lowest corner, and zoomed 4x.
void PlaceView(vtkCamera* camera, vtkUnstructuredGrid* grid, int view, const std::string& dataset)
{
  vtkHAVSStandardViews::PlaceCamera(camera, grid, view);
  if (VariantOf(dataset) != Variant::Zoom)
  {
    return;
  }
  double b[6], focal[3], eye[3], range[2];
  grid->GetBounds(b);
  camera->GetFocalPoint(focal);
  camera->GetPosition(eye);
  camera->GetClippingRange(range);
  for (int k = 0; k < 3; ++k)
  {
    const double shift = 0.6 * (b[2 * k] - 0.5 * (b[2 * k] + b[2 * k + 1]));
    focal[k] += shift;
    eye[k] += shift;
  }
  camera->SetFocalPoint(focal);
  camera->SetPosition(eye);
  camera->Zoom(4.0);
  // The moved eye may stand nearer the bounds: the near plane in front of them.
  const double length = grid->GetLength();
  camera->SetClippingRange(std::max(1e-3 * length, range[0] - length), range[1] + length);
}

double PeakMegabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

/// The isosurfaces of the iso-*, isomix-* and isoshade-* configurations:
/// none, the isosurface blend, isosurfaces inside the composite volume, or
/// the isosurface blend shaded (the property's ShadeOn, the renderer's light).
enum IsoMode
{
  NoIsoSurfaces = 0,
  IsoSurfaceBlend = 1,
  IsoSurfacesInComposite = 2,
  IsoSurfaceBlendShaded = 3
};

/// The isosurface mode a configuration's name asks for (iso-*, isomix-*,
/// isoshade-*) and, in `prefix`, the length of that prefix (0: none).
IsoMode IsoModeOf(const std::string& config, size_t* prefix = nullptr)
{
  const IsoMode mode = config.rfind("iso-", 0) == 0 ? IsoSurfaceBlend
    : config.rfind("isomix-", 0) == 0               ? IsoSurfacesInComposite
    : config.rfind("isoshade-", 0) == 0             ? IsoSurfaceBlendShaded
                                                    : NoIsoSurfaces;
  if (prefix)
  {
    *prefix = mode == IsoSurfaceBlend  ? 4
      : mode == IsoSurfacesInComposite ? 7
      : mode == IsoSurfaceBlendShaded  ? 9
                                       : 0;
  }
  return mode;
}

/// The translucent-* configurations (issue 46): that configuration with a
/// translucent plane through the data set's centre, intermixed
/// (vtkHAVSIntermixPass). The prefix's length, 0 when none.
size_t TranslucentPrefix(const std::string& config)
{
  return config.rfind("translucent-", 0) == 0 ? 12 : 0;
}

/// The exact image of a view, from the cache or computed and cached (with
/// `layers`, the translucent plane's peeled layers as events along the rays).
std::vector<float> ReferenceImage(const Options& o, const std::string& dataset,
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int view,
  bool* computed = nullptr, int iso = NoIsoSurfaces, vtkHAVSTranslucentLayers* layers = nullptr,
  vtkLightCollection* lights = nullptr)
{
  if (computed)
  {
    *computed = false;
  }
  const size_t values = static_cast<size_t>(o.Size) * o.Size * 4;
  std::ostringstream key;
  key << o.CacheDir << "/" << dataset << "_" << kPropertyVersion << "_v" << view << "_" << o.Size
      << (iso == IsoSurfaceBlend             ? "_iso"
             : iso == IsoSurfacesInComposite ? "_isomix"
             : iso == IsoSurfaceBlendShaded  ? "_isoshade"
                                             : "")
      << (layers ? "_translucent1" : "") << ".f32";
  std::vector<float> image(values);
  std::ifstream cached(key.str(), std::ios::binary);
  if (cached.read(reinterpret_cast<char*>(image.data()), values * sizeof(float)))
  {
    return image;
  }
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(o.Size, o.Size);
  if (iso == IsoSurfaceBlend || iso == IsoSurfaceBlendShaded)
  {
    reference->SetBlendMode(vtkHAVSMapperBase::ISOSURFACE_BLEND);
  }
  reference->SetIsoSurfacesInComposite(iso == IsoSurfacesInComposite);
  reference->SetLights(lights);
  for (int i = 0; layers && i < layers->GetNumberOfLayers(); ++i)
  {
    vtkNew<vtkFloatArray> depth, rgba;
    layers->ReadLayer(i, depth, rgba);
    reference->AddTranslucentLayer(depth, rgba);
  }
  reference->Render();
  if (computed)
  {
    *computed = true;
  }
  std::copy(reference->GetImage()->GetPointer(0), reference->GetImage()->GetPointer(0) + values,
    image.begin());
  std::system(("mkdir -p '" + o.CacheDir + "'").c_str());
  std::ofstream(key.str(), std::ios::binary)
    .write(reinterpret_cast<const char*>(image.data()), values * sizeof(float));
  return image;
}

/// MISSION.md: pixels whose exact ray crosses a folded cell (one of the two
/// tetrahedra of an internal face with both on one side: an inverted cell and
/// the cell it overlaps) have no exact image and are left out and counted.
/// The mask of a view (1 = left out), from the cache or computed from the
/// reference's fragments and cached (it does not depend on the transfer
/// function). `compute` false: only read the cache (empty when not there).
std::vector<uint8_t> FoldedPixels(const Options& o, const std::string& dataset,
  vtkUnstructuredGrid* grid, vtkCamera* camera, int view, bool compute)
{
  const size_t pixels = static_cast<size_t>(o.Size) * o.Size;
  std::ostringstream key;
  key << o.CacheDir << "/" << dataset << "_v" << view << "_" << o.Size << ".folded";
  std::vector<uint8_t> mask(pixels);
  std::ifstream cached(key.str(), std::ios::binary);
  if (cached.read(reinterpret_cast<char*>(mask.data()), pixels))
  {
    return mask;
  }
  if (!compute)
  {
    return {};
  }
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(MakeProperty(grid));
  reference->SetCamera(camera);
  reference->SetSize(o.Size, o.Size);
  reference->ComputeFoldedPixels(mask);
  std::system(("mkdir -p '" + o.CacheDir + "'").c_str());
  std::ofstream(key.str(), std::ios::binary)
    .write(reinterpret_cast<const char*>(mask.data()), pixels);
  return mask;
}

/// A GPU time the ray caster measured (timestamp queries; below 0 where the
/// context has no timer) in ms, NaN where not measured.
double TimerMs(double seconds)
{
  return seconds >= 0.0 ? 1000.0 * seconds : NAN;
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return NAN;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// A .havsmesh file (read by Apps/GPUBench/havs_gpu_cases): a text line,
/// then the points (doubles), the tetrahedra (4 uint32 ids each) and the
/// active point scalars (doubles). False when the grid is not all tetrahedra.
bool WriteMeshFile(vtkUnstructuredGrid* grid, const std::string& path)
{
  const vtkIdType points = grid->GetNumberOfPoints(), cells = grid->GetNumberOfCells();
  vtkDataArray* scalars = grid->GetPointData()->GetScalars();
  if (!scalars)
  {
    return false;
  }
  std::vector<double> xyz(3 * static_cast<size_t>(points)), values(static_cast<size_t>(points));
  for (vtkIdType i = 0; i < points; ++i)
  {
    grid->GetPoint(i, &xyz[3 * i]);
    values[i] = scalars->GetComponent(i, 0);
  }
  std::vector<uint32_t> ids(4 * static_cast<size_t>(cells));
  vtkNew<vtkIdList> cell;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    grid->GetCellPoints(c, cell);
    if (grid->GetCellType(c) != VTK_TETRA || cell->GetNumberOfIds() != 4)
    {
      return false;
    }
    for (int k = 0; k < 4; ++k)
    {
      ids[4 * c + k] = static_cast<uint32_t>(cell->GetId(k));
    }
  }
  std::ofstream out(path, std::ios::binary);
  out << "havsmesh 1 points " << points << " tetrahedra " << cells << " scalars point\n";
  out.write(
    reinterpret_cast<const char*>(xyz.data()), static_cast<std::streamsize>(xyz.size() * 8));
  out.write(
    reinterpret_cast<const char*>(ids.data()), static_cast<std::streamsize>(ids.size() * 4));
  out.write(
    reinterpret_cast<const char*>(values.data()), static_cast<std::streamsize>(values.size() * 8));
  return static_cast<bool>(out);
}

/// The lines of case.txt that let havs_gpu_cases render the same frame: the
/// mesh, the camera and the transfer functions, at full precision.
std::string FrameDescription(
  const std::string& mesh, vtkCamera* camera, vtkVolumeProperty* property)
{
  std::ostringstream d;
  d.precision(17);
  auto triple = [&d](const char* key, const double* v)
  { d << key << " " << v[0] << " " << v[1] << " " << v[2] << "\n"; };
  d << "mesh " << mesh << "\n";
  triple("camera_position", camera->GetPosition());
  triple("camera_focal_point", camera->GetFocalPoint());
  triple("camera_view_up", camera->GetViewUp());
  d << "camera_view_angle " << camera->GetViewAngle() << "\ncamera_parallel "
    << camera->GetParallelProjection() << "\ncamera_parallel_scale " << camera->GetParallelScale()
    << "\ncamera_clipping_range " << camera->GetClippingRange()[0] << " "
    << camera->GetClippingRange()[1] << "\n";
  vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  for (int i = 0; i < color->GetSize(); ++i)
  {
    double node[6];
    color->GetNodeValue(i, node);
    d << "tf_color " << node[0] << " " << node[1] << " " << node[2] << " " << node[3] << " "
      << node[4] << " " << node[5] << "\n";
  }
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double node[4];
    opacity->GetNodeValue(i, node);
    d << "tf_opacity " << node[0] << " " << node[1] << " " << node[2] << " " << node[3] << "\n";
  }
  d << "tf_color_space " << color->GetColorSpace() << "\ntf_clamping " << color->GetClamping()
    << "\ntf_unit_distance " << property->GetScalarOpacityUnitDistance() << "\ntf_shade "
    << property->GetShade() << "\ntf_interpolation " << property->GetInterpolationType() << "\n";
  return d.str();
}

/// <configuration>-gputable: a project mapper with PreIntegrationOnGPU (issue 45).
const std::string GPUTableSuffix = "-gputable";

/// Whether `config` ends with GPUTableSuffix (after more than it); then `base`
/// is the configuration without it.
bool StripGPUTable(const std::string& config, std::string& base)
{
  const size_t n = GPUTableSuffix.size();
  if (config.size() <= n || config.compare(config.size() - n, n, GPUTableSuffix) != 0)
  {
    return false;
  }
  base = config.substr(0, config.size() - n);
  return true;
}

/// --dump-case DIR: view 0 of each data set at --size, drawn by each mapper
/// of --dump-kinds with its defaults (HAVS at k = 2 and 6), written as frame
/// cases DIR/<data set>_<size>_<kind> (Apps/GPUBench/README.md) with the
/// exact reference's image and folded-pixel mask, for havs_gpu_bench.
int DumpCases(const Options& o)
{
  int failures = 0;
  for (const std::string& dataset : o.DataSets)
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = LoadDataSet(dataset);
    if (!grid || grid->GetNumberOfCells() == 0)
    {
      std::cerr << "cannot load " << dataset << std::endl;
      ++failures;
      continue;
    }
    auto property = MakeProperty(grid, VariantOf(dataset));
    vtkNew<vtkCamera> camera;
    PlaceView(camera, grid, 0, dataset);
    const std::vector<float> exact = ReferenceImage(o, dataset, grid, property, camera, 0);
    const std::vector<uint8_t> folded = FoldedPixels(o, dataset, grid, camera, 0, true);
    // The mesh, for havs_gpu_cases where the case travels without its arrays.
    std::string mesh = "generated " + std::to_string(vtkHAVSGeneratedBlock::CubesOf(dataset));
    if (!vtkHAVSGeneratedBlock::CubesOf(dataset))
    {
      mesh = dataset + ".havsmesh";
      std::system(("mkdir -p '" + o.DumpCase + "'").c_str());
      if (!WriteMeshFile(grid, o.DumpCase + "/" + mesh))
      {
        std::cerr << "cannot write " << o.DumpCase << "/" << mesh << " (tetrahedra and point "
                  << "scalars only)" << std::endl;
        ++failures;
        continue;
      }
    }
    for (const std::string& kind : o.DumpKinds)
    {
      if (kind.rfind("table", 0) == 0)
      {
        // table<N>: the pre-integrated table at N^3 of the data set's
        // function, range and longest edge, for the GPU's build against the
        // CPU's (issue 45; havs_gpu_cases makes its inputs and the CPU's table).
        const int resolution = std::atoi(kind.c_str() + 5);
        if (resolution < 2 || resolution > 1024)
        {
          std::cerr << "unknown case kind " << kind << " (table<N>, N from 2 to 1024)" << std::endl;
          ++failures;
          continue;
        }
        const std::string dir =
          o.DumpCase + "/" + dataset + "_" + std::to_string(o.Size) + "_" + kind;
        std::system(("mkdir -p '" + dir + "'").c_str());
        // The longest segment in a cell, as the mappers take it: their face set's longest edge.
        vtkNew<vtkHAVSFaceSet> faces;
        faces->Build(grid);
        double range[2];
        grid->GetPointData()->GetScalars()->GetRange(range);
        std::ofstream(dir + "/table.comp")
          << vtkHAVSShaders::TableComputeShader(resolution - 1, vtkHAVSGLTableBuilder::LocalSize);
        std::ofstream(dir + "/case.txt")
          << std::setprecision(17) << "format 2\nmapper table\nwidth " << resolution << "\nheight "
          << resolution << "\ntable " << resolution << " " << resolution << " " << resolution
          << "\nmax_length " << faces->GetLongestEdge() << "\nscalar_range " << range[0] << " "
          << range[1] << "\ndataset " << dataset << "\nview 0\n"
          << FrameDescription(mesh, camera, property);
        std::cout << "wrote " << dir << std::endl;
        continue;
      }
      vtkSmartPointer<vtkHAVSMapperBase> mapper;
      std::string settings; // what havs_gpu_cases sets beyond the defaults
      if (kind == "havs_k2" || kind == "havs_k6" || kind == "havs_k2_t43" || kind == "havs_k6_t43")
      {
        auto m = vtkSmartPointer<vtkOpenGLHAVSVolumeMapper>::New(); // the defaults
        m->SetKBufferSize(kind.rfind("havs_k2", 0) == 0 ? 2 : 6);
        if (kind.find("_t43") != std::string::npos)
        {
          // The thesis' Table 4.3 settings: a 128^3 table, early ray
          // termination off (the order stays the exact default).
          m->AutomaticTableResolutionOff();
          m->SetTableScalarResolution(128);
          m->SetTableLengthResolution(128);
          m->SetEarlyRayTerminationOpacity(1.0);
          settings = "havs_table_resolution 128\nhavs_termination_opacity 1\n";
        }
        mapper = m;
      }
      else if (kind == "cellprojection")
      {
        mapper = vtkSmartPointer<vtkHAVSCellProjectionMapper>::New();
      }
      else if (kind == "raycast")
      {
        mapper = vtkSmartPointer<vtkHAVSRayCastMapper>::New();
      }
      else
      {
        std::cerr << "unknown case kind " << kind << " (havs_k2, havs_k6, cellprojection, raycast)"
                  << std::endl;
        ++failures;
        continue;
      }
      vtkSmartPointer<vtkRenderWindow> window;
      window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow());
      if (!window)
      {
        std::cerr << "cannot make a window" << std::endl;
        return EXIT_FAILURE;
      }
      window->SetSize(o.Size, o.Size);
      vtkNew<vtkRenderer> renderer;
      renderer->SetBackground(0, 0, 0);
      window->AddRenderer(renderer);
      mapper->SetInputData(grid);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(property);
      renderer->AddVolume(volume);
      renderer->GetActiveCamera()->DeepCopy(camera);
      renderer->ResetCameraClippingRange();
      window->Render();
      const std::string dir =
        o.DumpCase + "/" + dataset + "_" + std::to_string(o.Size) + "_" + kind;
      mapper->SetCaptureDirectory(dir.c_str());
      window->Render();
      bool ok = mapper->GetLastCaptureSucceeded();
      if (ok)
      {
        // The exact image in 16-bit steps (1/65535: far below the exact
        // bound's 5e-4 RMSE), so that a bundle carries it small.
        std::vector<uint16_t> steps(exact.size());
        for (size_t i = 0; i < exact.size(); ++i)
        {
          const float v = std::isfinite(exact[i]) ? std::min(1.0f, std::max(0.0f, exact[i])) : 0.0f;
          steps[i] = static_cast<uint16_t>(std::lround(65535.0f * v));
        }
        std::ofstream(dir + "/reference.u16", std::ios::binary)
          .write(reinterpret_cast<const char*>(steps.data()),
            static_cast<std::streamsize>(steps.size() * sizeof(uint16_t)));
        if (!folded.empty())
        {
          std::ofstream(dir + "/folded.u8", std::ios::binary)
            .write(reinterpret_cast<const char*>(folded.data()),
              static_cast<std::streamsize>(folded.size()));
        }
        std::ofstream(dir + "/case.txt", std::ios::app)
          << "dataset " << dataset << "\nview 0\n"
          << FrameDescription(mesh, renderer->GetActiveCamera(), property) << settings;
      }
      std::cout << (ok ? "wrote " : "FAILED ") << dir << " (" << grid->GetNumberOfCells()
                << " cells)" << std::endl;
      failures += ok ? 0 : 1;
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

/// Frame times (or other values, in that format) joined by ';' ("-" for none).
std::string TraceText(const std::vector<double>& ms, const char* format = "%.0f")
{
  std::string text;
  for (double t : ms)
  {
    char value[32];
    std::snprintf(value, sizeof(value), format, t);
    text += (text.empty() ? "" : ";") + std::string(value);
  }
  return text.empty() ? "-" : text;
}

/// One frame, the GPU's work finished: its seconds.
double TimedFrame(vtkRenderWindow* window)
{
  const double t0 = vtkTimerLog::GetUniversalTime();
  window->Render();
  window->WaitForCompletion();
  return vtkTimerLog::GetUniversalTime() - t0;
}

/// The camera turned by `degrees` about the view up, and the clipping range
/// reset, as VTK's interactor styles do while you rotate
/// (AutoAdjustCameraClippingRange): a near plane left where it was would cut
/// the turned mesh, and the mappers would cut its section every frame.
void TurnCamera(vtkCamera* camera, vtkRenderWindow* window, double degrees)
{
  camera->Azimuth(degrees);
  if (vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer())
  {
    renderer->ResetCameraClippingRange();
  }
}

/// Whether `text` at `at` starts a frame-budget configuration, "lod-<percent>-"
/// (at the start or after a space or comma: not havs-lod-*).
bool StartsBudget(const std::string& text, size_t at)
{
  return text.compare(at, 4, "lod-") == 0 &&
    (at == 0 || text[at - 1] == ' ' || text[at - 1] == ',') && at + 4 < text.size() &&
    std::isdigit(static_cast<unsigned char>(text[at + 4]));
}

/// lod-<percent>-<configuration>: the percent and the configuration (false
/// for any other name, or one without a percent above 0 and a configuration).
bool ParseBudget(const std::string& rowConfig, double& percent, std::string& config)
{
  if (!StartsBudget(rowConfig, 0))
  {
    return false;
  }
  const size_t dash = rowConfig.find('-', 4);
  if (dash == std::string::npos || dash + 1 >= rowConfig.size())
  {
    return false;
  }
  percent = std::atof(rowConfig.substr(4, dash - 4).c_str());
  config = rowConfig.substr(dash + 1);
  return percent > 0.0;
}

/// The window's RGB against the exact image, as the per-view loop measures it
/// (pixels whose exact rays cross folded cells left out): RMSE and max in
/// units of 1/255.
void WindowError(const std::vector<float>& exact, const std::vector<uint8_t>& folded,
  vtkFloatArray* rgba, size_t pixels, double& rmse, double& max)
{
  double squares = 0.0, counted = 0.0;
  max = 0.0;
  for (size_t p = 0; p < pixels; ++p)
  {
    if (!folded.empty() && folded[p])
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double e = std::fabs(double(rgba->GetValue(4 * p + c)) - exact[4 * p + c]);
      squares += e * e;
      max = std::max(max, e);
    }
    counted += 1;
  }
  rmse = counted > 0 ? 255.0 * std::sqrt(squares / (3 * counted)) : NAN;
  max = counted > 0 ? 255.0 * max : NAN;
}

/// The camera turned 3 degrees a frame for 60 frames under a budget of
/// `budgetMs` (LevelOfDetailTargetSeconds, left set): `onFrame(ms,
/// settled)` after each frame, settled for the last 30; returns the share of
/// those within 25 % of the budget (havs-lod-rotate-*, lod-<percent>-*).
double TurnUnderBudget(vtkRenderWindow* window, vtkCamera* camera, vtkHAVSMapperBase* base,
  double budgetMs, const std::function<void(double, bool)>& onFrame)
{
  base->SetLevelOfDetailTargetSeconds(budgetMs / 1000.0);
  const int frames = 60, settled = 30;
  double within = 0.0;
  for (int i = 0; i < frames; ++i)
  {
    TurnCamera(camera, window, 3.0);
    const double ms = 1000.0 * TimedFrame(window);
    const bool isSettled = i >= frames - settled;
    onFrame(ms, isSettled);
    within += isSettled && std::abs(ms - budgetMs) <= 0.25 * budgetMs ? 1 : 0;
  }
  return within / settled;
}

/// lod-<percent>-*: at view 0 the camera turns 3 degrees a frame: 5 frames
/// with no budget (VTK's still rate: the full frame, their median), then 60
/// with the budget set to that share of the full frame (the last 30 settled:
/// their times, image scales and, for HAVS, shares of internal faces); then,
/// the budget still set, view 0 again for 3 frames (the controller keeps its
/// detail) and the last one's window against the exact image. The budget is
/// 0 again at the end (the caller's still frame).
struct BudgetRun
{
  double FullMs = NAN, BudgetMs = NAN, Within = NAN, RMSE = NAN, Max = NAN, ErrorScale = NAN;
  std::vector<double> Trace, Settled, Scales, Faces, ScaleTrace;
};

BudgetRun MeasureBudget(const Options& o, vtkRenderWindow* window, vtkCamera* camera,
  vtkUnstructuredGrid* grid, const std::string& dataset, vtkVolumeProperty* property,
  vtkHAVSMapperBase* base, double percent)
{
  BudgetRun run;
  auto* havs = vtkHAVSVolumeMapper::SafeDownCast(base);
  PlaceView(camera, grid, 0, dataset);
  base->SetLevelOfDetailTargetSeconds(0.0);
  std::vector<double> full;
  for (int i = 0; i < 5; ++i)
  {
    TurnCamera(camera, window, 3.0);
    full.push_back(1000.0 * TimedFrame(window));
  }
  run.FullMs = Median(full);
  run.BudgetMs = percent / 100.0 * run.FullMs;
  run.Within = TurnUnderBudget(window, camera, base, run.BudgetMs,
    [&](double ms, bool settled)
    {
      run.Trace.push_back(ms);
      run.ScaleTrace.push_back(base->GetLastImageScale());
      if (settled)
      {
        run.Settled.push_back(ms);
        run.Scales.push_back(base->GetLastImageScale());
        if (havs)
        {
          run.Faces.push_back(havs->GetLastFrameStatistics()->GetLevelOfDetailFraction());
        }
      }
    });
  PlaceView(camera, grid, 0, dataset);
  for (int i = 0; i < 3; ++i)
  {
    TimedFrame(window);
  }
  run.ErrorScale = base->GetLastImageScale();
  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, o.Size - 1, o.Size - 1, 0, rgba);
  WindowError(ReferenceImage(o, dataset, grid, property, camera, 0),
    FoldedPixels(o, dataset, grid, camera, 0, false), rgba, static_cast<size_t>(o.Size) * o.Size,
    run.RMSE, run.Max);
  base->SetLevelOfDetailTargetSeconds(0.0);
  return run;
}

/// floor-*: what a frame costs when it draws the fewest pixels, the part of
/// the frame that does not depend on the pixel count (the frame budgets'
/// misses name it). The camera takes the frame budgets' path (MeasureBudget)
/// with no budget, at three fixed image scales (SetImageScale): 1 over the
/// full frames' views (3 to 15 degrees from view 0), then 0.1 (the level of
/// detail's smallest image, 1 % of the pixels) and 0.01 (0.01 % of them: a
/// frame that costs as much as at 0.1 costs that for something other than
/// its pixels) each over the settled frames' 30 views (108 to 195 degrees),
/// after a warm-up frame. HAVS draws the same share of its internal faces as
/// of its pixels (SetLevelOfDetailFraction: 1 % at 0.1, as the level of
/// detail's smallest frame). The stage timers are on (each stage ends with the
/// GPU's work), so the parts of a frame at 0.1 are measured: the order (the
/// cell projection's cell order; HAVS's sort and gather), the draw, and the
/// ray caster's peeling and casting (GPU timestamps) and peeling passes.
/// Last, the same window's frame with the volume hidden (10 frames): what the
/// window costs without any mapper (clearing and showing its 512^2 pixels).
/// Medians.
struct FloorRun
{
  double FullMs = NAN, Ms = NAN, TinyMs = NAN, OrderMs = NAN, DrawMs = NAN, PeelMs = NAN,
         CastMs = NAN, Passes = NAN, EmptyMs = NAN;
};

FloorRun MeasureFloor(vtkRenderWindow* window, vtkCamera* camera, vtkUnstructuredGrid* grid,
  const std::string& dataset, vtkVolume* volume, vtkHAVSMapperBase* base)
{
  auto* havs = vtkHAVSVolumeMapper::SafeDownCast(base);
  auto* cellProjection = vtkHAVSCellProjectionMapper::SafeDownCast(base);
  auto* rayCast = vtkHAVSRayCastMapper::SafeDownCast(base);
  FloorRun run;
  base->SetLevelOfDetailTargetSeconds(0.0);
  // Without the edges' mask: a budget the smallest image misses drops it
  // (vtkHAVSMapperBase::EdgeUpsampling), so the floor is the frame without it.
  const bool edges = base->GetEdgeUpsampling();
  base->EdgeUpsamplingOff();
  for (const double scale : { 1.0, 0.1, 0.01 })
  {
    base->SetImageScale(scale);
    if (havs)
    {
      havs->SetLevelOfDetailFraction(scale * scale);
    }
    const bool full = scale == 1.0;
    PlaceView(camera, grid, 0, dataset);
    TurnCamera(camera, window, full ? 0.0 : 105.0);
    TimedFrame(window); // warm-up at the new scale
    std::vector<double> ms, order, draw, peel, cast, passes;
    for (int i = 0; i < (full ? 5 : 30); ++i)
    {
      TurnCamera(camera, window, 3.0);
      ms.push_back(1000.0 * TimedFrame(window));
      if (havs)
      {
        vtkHAVSFrameStatistics* stats = havs->GetLastFrameStatistics();
        order.push_back(1000.0 * (stats->GetSortSeconds() + stats->GetGatherSeconds()));
        draw.push_back(1000.0 * stats->GetDrawSeconds());
      }
      else if (cellProjection)
      {
        order.push_back(1000.0 * cellProjection->GetLastOrderSeconds());
        draw.push_back(1000.0 * cellProjection->GetLastDrawSeconds());
      }
      else if (rayCast)
      {
        draw.push_back(1000.0 * rayCast->GetLastDrawSeconds());
        peel.push_back(TimerMs(rayCast->GetLastPeelSeconds()));
        cast.push_back(TimerMs(rayCast->GetLastCastSeconds()));
        passes.push_back(rayCast->GetLastPeelPasses());
      }
    }
    if (full)
    {
      run.FullMs = Median(ms);
    }
    else if (scale == 0.01)
    {
      run.TinyMs = Median(ms);
    }
    else
    {
      run.Ms = Median(ms);
      run.OrderMs = Median(order);
      run.DrawMs = Median(draw);
      run.PeelMs = Median(peel);
      run.CastMs = Median(cast);
      run.Passes = Median(passes);
    }
  }
  base->SetImageScale(1.0);
  base->SetEdgeUpsampling(edges);
  if (havs)
  {
    havs->SetLevelOfDetailFraction(1.0);
  }
  volume->VisibilityOff();
  TimedFrame(window); // warm-up without the volume
  std::vector<double> empty;
  for (int i = 0; i < 10; ++i)
  {
    TurnCamera(camera, window, 3.0);
    empty.push_back(1000.0 * TimedFrame(window));
  }
  run.EmptyMs = Median(empty);
  volume->VisibilityOn();
  return run;
}

/// edit-*: at view 0, 15 frames that rebuild nothing (the still redraw; 7
/// where one takes a second or more), each followed by a transfer-function edit, one opacity node
/// (the middle one) moved by 10 % of its value and back, as a dragged node would, the camera still;
/// medians are taken by the caller. An edit's parts: the table (every
/// project mapper: GetLastTableSeconds), and HAVS's cell visibility, face
/// gather, uploads and draw (its stage times); the cell projection's and
/// the ray caster's draw (left empty where a mapper has no such part).
void MeasureEdits(vtkRenderWindow* window, vtkCamera* camera, vtkUnstructuredGrid* grid,
  const std::string& dataset, vtkVolumeProperty* property, vtkUnstructuredGridVolumeMapper* mapper,
  std::vector<double>& stillMs, std::vector<double>& editMs, std::vector<double>& table,
  std::vector<double>& visibility, std::vector<double>& gather, std::vector<double>& upload,
  std::vector<double>& draw)
{
  auto* base = vtkHAVSMapperBase::SafeDownCast(mapper);
  auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper);
  auto* cellProjection = vtkHAVSCellProjectionMapper::SafeDownCast(mapper);
  auto* rayCast = vtkHAVSRayCastMapper::SafeDownCast(mapper);
  PlaceView(camera, grid, 0, dataset);
  window->Render(); // the view, once: what the still frames then redraw
  window->WaitForCompletion();
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  const int node = opacity->GetSize() / 2;
  double value[4];
  opacity->GetNodeValue(node, value);
  const double original = value[1];
  // Each edit right after a still frame, so that the machine's drift (a
  // shared 2-core machine's frames differ by 10-20 % from one to the next)
  // weighs both alike; 15 pairs where a frame takes less than a second
  // (the table's few milliseconds are then a few per cent), else 7.
  int pairs = 7;
  for (int i = 0; i < pairs; ++i)
  {
    stillMs.push_back(1000.0 * TimedFrame(window));
    if (i == 0 && stillMs.back() < 1000.0)
    {
      pairs = 15;
    }
    value[1] = original * (i % 2 == 0 ? 0.9 : 1.0);
    opacity->SetNodeValue(node, value);
    editMs.push_back(1000.0 * TimedFrame(window));
    if (base)
    {
      table.push_back(1000.0 * base->GetLastTableSeconds());
    }
    if (havs)
    {
      vtkHAVSFrameStatistics* stats = havs->GetLastFrameStatistics();
      visibility.push_back(1000.0 * stats->GetVisibilitySeconds());
      gather.push_back(1000.0 * stats->GetGatherSeconds());
      upload.push_back(1000.0 * stats->GetUploadSeconds());
      draw.push_back(1000.0 * stats->GetDrawSeconds());
    }
    else if (cellProjection || rayCast)
    {
      draw.push_back(1000.0 *
        (cellProjection ? cellProjection->GetLastDrawSeconds() : rayCast->GetLastDrawSeconds()));
    }
  }
  value[1] = original;
  opacity->SetNodeValue(node, value);
}

/// One (data set, configuration): prints a RESULT line.
int RunWorker(const Options& o)
{
  // edit-<configuration>: that configuration, and transfer-function edits at
  // view 0; lod-<percent>-<configuration>: that configuration with a frame
  // budget of that share of its full frame (MeasureBudget).
  const std::string dataset = o.DataSets.at(0), rowConfig = o.Configs.at(0);
  const bool edits = rowConfig.rfind("edit-", 0) == 0;
  // floor-<configuration>: that configuration's frame at the smallest images
  // (MeasureFloor).
  const bool floorRun = rowConfig.rfind("floor-", 0) == 0;
  // iso-<configuration>: the isosurface blend; isomix-<configuration>: the
  // same isosurfaces inside the composite volume (issue 46).
  size_t isoPrefix = 0;
  const int iso = IsoModeOf(rowConfig, &isoPrefix);
  double budgetPercent = 0.0;
  // translucent-<configuration>: a translucent plane in the scene, intermixed.
  const size_t translucentPrefix = TranslucentPrefix(rowConfig);
  std::string config = rowConfig.substr(edits ? 5 : floorRun ? 6 : isoPrefix + translucentPrefix);
  if (rowConfig.rfind("lod-", 0) == 0 && !ParseBudget(rowConfig, budgetPercent, config))
  {
    std::cerr << "unknown configuration " << rowConfig << std::endl;
    return EXIT_FAILURE;
  }
  const bool gpuTable = StripGPUTable(config, config);
  vtkSmartPointer<vtkUnstructuredGrid> grid = LoadDataSet(dataset);
  if (!grid || grid->GetNumberOfCells() == 0 || !grid->GetPointData()->GetScalars())
  {
    std::cerr << "cannot load " << dataset << std::endl;
    return EXIT_FAILURE;
  }
  auto property = MakeProperty(grid, VariantOf(dataset));
  const vtkIdType tets = grid->GetNumberOfCells();
  if (iso != NoIsoSurfaces)
  {
    // Two isovalues, at 35 % and 65 % of the scalar range.
    double range[2];
    grid->GetPointData()->GetScalars()->GetRange(range);
    property->GetIsoSurfaceValues()->SetNumberOfContours(2);
    property->GetIsoSurfaceValues()->SetValue(0, range[0] + 0.35 * (range[1] - range[0]));
    property->GetIsoSurfaceValues()->SetValue(1, range[0] + 0.65 * (range[1] - range[0]));
    // isoshade-*: lit by the renderer's headlight (the property's default
    // coefficients but for the specular's).
    property->SetShade(iso == IsoSurfaceBlendShaded ? 1 : 0);
    property->SetSpecular(0.3);
  }

  std::vector<double> frame, sort, gather, draw, flush, composite, upload, readback, layers;
  double sumSquares = 0, maxError = 0;
  double over1 = 0, pixels = 0;
  // The float result's error (HAVS, cell projection, ray caster) and the 8-bit
  // window's floor (the exact image rounded to 1/255).
  double floatSquares = 0, floatMax = 0, floatPixels = 0, floorSquares = 0;
  double foldedPixels = 0; // left out: rays through folded cells (NaN: mask not cached)
  int viewsDone = 0;
  std::string tableText = "-";
  long long skipped = -1; // HAVS: the tetrahedra skipped as invisible
  long long culled = -1;  // HAVS: the tetrahedra culled off-screen (the last view)
  // The level of detail: the share of internal faces drawn per frame, the
  // ranking's preprocessing time and memory; the rotation's frame times, the
  // share of its settled frames within 25 % of the budget, the still frame's share.
  std::vector<double> lodFractions, lodTrace;
  double rankingSeconds = 0.0, rankingMB = 0.0, lodWithin = 0.0, lodStill = -1.0;
  double lodTarget = 0.0; // havs-lod-rotate-<ms>: the frame budget (s)
  // tetraycast, per view: the depth-peeling passes, the cells crossed per ray,
  // the share of the screen tiles in which rays started and their mean passes
  // (vtkHAVSRayCastMapper's last-frame counters).
  std::vector<double> peelPasses, cellsPerRay, tilesUsed, tilePasses, peelMs, castMs;
  // edit-*: at view 0, frames that rebuild nothing (still) and frames after
  // one opacity node moved (edit), and the edits' parts.
  std::vector<double> stillMs, editMs, editTable, editVisibility, editGather, editUpload, editDraw;
  // lod-<percent>-*: the budget's run, and the still frame's image scale.
  BudgetRun budget;
  double budgetStillScale = NAN;
  FloorRun floor; // floor-*
  if (config == "reference")
  {
    // The exact images of every view, computed once and cached before any
    // timed configuration runs (so no mapper's peak memory holds them); the
    // time is that of the exact renderer, where it was not in the cache.
    vtkNew<vtkCamera> camera;
    for (int view = 0; view < o.Views; ++view)
    {
      PlaceView(camera, grid, view, dataset);
      bool computed = false;
      const double t0 = vtkTimerLog::GetUniversalTime();
      ReferenceImage(o, dataset, grid, property, camera, view, &computed);
      if (computed)
      {
        frame.push_back(1000.0 * (vtkTimerLog::GetUniversalTime() - t0));
      }
      FoldedPixels(o, dataset, grid, camera, view, true);
      ++viewsDone;
    }
  }
  else if (config == "sort-bound")
  {
    // The centroid sort alone, for every view.
    vtkNew<vtkHAVSFaceSet> faces;
    faces->Build(grid);
    vtkNew<vtkHAVSFaceSorter> sorter;
    vtkNew<vtkCamera> camera;
    const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    for (int view = 0; view < o.Views; ++view)
    {
      PlaceView(camera, grid, view, dataset);
      double eye[3], dop[3];
      camera->GetPosition(eye);
      camera->GetDirectionOfProjection(dop);
      for (int r = 0; r < o.Repeats; ++r)
      {
        sorter->Invalidate();
        sorter->Sort(faces, identity, eye, dop, false);
        frame.push_back(1000.0 * sorter->GetLastSortSeconds());
      }
      ++viewsDone;
    }
  }
  else
  {
    vtkSmartPointer<vtkRenderWindow> window;
    window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow());
    if (!window)
    {
      return EXIT_FAILURE;
    }
    window->SetSize(o.Size, o.Size);
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0, 0, 0);
    window->AddRenderer(renderer);
    vtkSmartPointer<vtkUnstructuredGridVolumeMapper> mapper;
    vtkHAVSVolumeMapper* havs = nullptr;
    vtkHAVSCellProjectionMapper* cellProjection = nullptr;
    vtkHAVSRayCastMapper* tetRayCast = nullptr;
    vtkSmartPointer<vtkActor> opaqueActor; // -opaque: in the scene, behind the eye
    if (config.rfind("havs", 0) == 0 || config == "raster-bound")
    {
      auto m = vtkSmartPointer<vtkHAVSVolumeMapper>::New();
      m->MeasureStageTimesOn();
      m->SetEarlyRayTerminationOpacity(0.999);
      if (config == "havs-lists")
      {
        m->SetKBufferPathToFragmentLists();
      }
      else if (config == "raster-bound")
      {
        m->FaceRasterBoundModeOn();
        m->SetVisibilityOrderToCentroid();
      }
      else if (config == "havs-default")
      {
        // The mapper as a user gets it: nothing set but the stage timer.
        m->SetEarlyRayTerminationOpacity(
          vtkNew<vtkHAVSVolumeMapper>()->GetEarlyRayTerminationOpacity());
      }
      else if (config == "havs-default-noskip")
      {
        // The defaults with every cell drawn: what skipping invisible cells buys.
        m->SkipInvisibleCellsOff();
      }
      else if (config == "havs-default-nocull")
      {
        // The defaults with every cell ordered and drawn: what culling the
        // cells outside the view frustum buys.
        m->SkipOffscreenCellsOff();
      }
      else if (config == "havs-default-noclamp")
      {
        // The defaults with isosurface fragments not clamped to their faces
        // (with an iso- prefix: what the clamp costs and buys).
        m->SetNoFaceClampForTesting(true);
      }
      else if (config == "havs-default-sat")
      {
        // The defaults with saturated pixels rejected before the shader on
        // every path (Automatic: the interlock path only).
        m->SetSkipSaturatedPixels(vtkHAVSVolumeMapper::SkipSaturatedPixelsAlways);
      }
      else if (config.rfind("havs-lod-", 0) == 0)
      {
        // havs-lod-<strategy>-<percent>: the defaults drawing that share of the
        // internal faces (strategy: topology, view, field, area, random);
        // havs-lod-rotate-<ms>: the defaults with that frame budget while the
        // camera turns, then one still frame.
        const std::string rest = config.substr(9);
        const size_t dash = rest.rfind('-');
        const std::string what = rest.substr(0, dash);
        const double value = dash == std::string::npos ? 0.0 : std::atof(rest.c_str() + dash + 1);
        const char* const strategies[] = { "topology", "view", "field", "area", "random" };
        if (what == "rotate")
        {
          lodTarget = value / 1000.0;
          m->MeasureStageTimesOff(); // as a user's interactive frames
        }
        else
        {
          const auto it = std::find(std::begin(strategies), std::end(strategies), what);
          if (it == std::end(strategies) || !(value > 0.0))
          {
            std::cerr << "unknown configuration " << config << std::endl;
            return EXIT_FAILURE;
          }
          m->SetLevelOfDetailStrategy(static_cast<int>(it - std::begin(strategies)));
          m->SetLevelOfDetailFraction(value / 100.0);
        }
      }
      else if (config == "havs-default-table128")
      {
        // The defaults with the fixed 128^3 table: what the automatic table buys.
        m->AutomaticTableResolutionOff();
      }
      else
      {
        m->SetVisibilityOrderToCentroid(); // unless -mpvo or -auto says otherwise
        const size_t k = config.find("-k");
        m->SetKBufferSize(k == std::string::npos ? 6 : std::atoi(config.c_str() + k + 2));
        const size_t t = config.find("-table");
        const int table = t == std::string::npos ? 128 : std::atoi(config.c_str() + t + 6);
        m->AutomaticTableResolutionOff(); // the configurations name their table
        m->SetTableScalarResolution(table);
        m->SetTableLengthResolution(table);
        if (config.find("-mpvo") != std::string::npos)
        {
          m->SetVisibilityOrderToMPVO(); // exact object-space order (issue 8)
          m->SetNonConvexMethod(config.find("-convex") != std::string::npos
              ? vtkHAVSVisibilityOrder::NonConvexConvexification
              : vtkHAVSVisibilityOrder::NonConvexBoundaryLayers);
        }
        else if (config.find("-auto") != std::string::npos)
        {
          m->SetVisibilityOrderToAutomatic(); // centroid until it overflows, then MPVO
        }
        if (config.find("-count") != std::string::npos)
        {
          m->CountOrderViolationsOn(); // what the order-violation counter costs
        }
        if (config.find("-noterm") != std::string::npos)
        {
          m->SetEarlyRayTerminationOpacity(1.0); // what early ray termination saves
        }
        if (config.find("-untagged") != std::string::npos)
        {
          m->SetBoundaryModeToIgnore(); // what boundary tagging costs (and buys)
        }
        else if (config.find("-gaplength") != std::string::npos)
        {
          m->SetBoundaryModeToGapLength();
        }
      }
      havs = m;
      mapper = m;
    }
    else if (config == "pt")
    {
      mapper = vtkSmartPointer<vtkProjectedTetrahedraMapper>::New();
    }
    else if (config == "cellproj" || config == "cellproj-convex" || config == "cellproj-floatiso")
    {
      // vtkHAVSCellProjectionMapper (issue 22): the exact MPVO cell order.
      auto m = vtkSmartPointer<vtkHAVSCellProjectionMapper>::New();
      m->MeasureStageTimesOn();
      if (config == "cellproj-convex")
      {
        m->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexConvexification);
      }
      // (With an iso- prefix: what the exact stretches in double cost and buy.)
      m->SetFloatIsoStretchesForTesting(config == "cellproj-floatiso");
      cellProjection = m;
      mapper = m;
    }
    else if (config == "tetraycast" || config == "tetraycast-nofolds")
    {
      // vtkHAVSRayCastMapper (issue 21): GPU ray casting, depth-peeled re-entries
      // (-nofolds: without the re-entries across folds of the boundary).
      auto m = vtkSmartPointer<vtkHAVSRayCastMapper>::New();
      m->SetEarlyRayTerminationOpacity(0.999);
      m->SetFoldReentries(config == "tetraycast");
      tetRayCast = m;
      mapper = m;
    }
    else if (config == "zsweep" || config == "raycast")
    {
      if (config == "zsweep")
      {
        auto m = vtkSmartPointer<vtkUnstructuredGridVolumeZSweepMapper>::New();
        m->SetImageSampleDistance(1.0);
        m->AutoAdjustSampleDistancesOff();
        m->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());
        mapper = m;
      }
      else
      {
        auto m = vtkSmartPointer<vtkUnstructuredGridVolumeRayCastMapper>::New();
        m->SetImageSampleDistance(1.0);
        m->AutoAdjustSampleDistancesOff();
        m->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());
        mapper = m;
      }
    }
    else
    {
      std::cerr << "unknown configuration " << config << std::endl;
      return EXIT_FAILURE;
    }
    auto* base = vtkHAVSMapperBase::SafeDownCast(mapper);
    if ((iso != NoIsoSurfaces || budgetPercent > 0.0 || floorRun || gpuTable) && !base)
    {
      std::cerr << rowConfig
                << ": isosurfaces, frame budgets, floors and the GPU's table need a "
                   "vtkHAVSMapperBase mapper"
                << std::endl;
      return EXIT_FAILURE;
    }
    if (gpuTable)
    {
      base->PreIntegrationOnGPUOn();
    }
    if (iso != NoIsoSurfaces)
    {
      if (iso == IsoSurfaceBlend || iso == IsoSurfaceBlendShaded)
      {
        base->SetBlendMode(vtkHAVSMapperBase::ISOSURFACE_BLEND);
      }
      base->SetIsoSurfacesInComposite(iso == IsoSurfacesInComposite);
    }
    if (budgetPercent > 0.0)
    {
      // As a user's interactive frames: no stage timer finishing the GPU's work.
      if (havs)
      {
        havs->MeasureStageTimesOff();
      }
      if (cellProjection)
      {
        cellProjection->MeasureStageTimesOff();
      }
    }
    mapper->SetInputData(grid);
    if (config.find("-opaque") != std::string::npos)
    {
      // What the opaque cut costs: an opaque actor in the scene (behind the
      // camera, so the image is the same) makes the mapper copy the depth
      // and compile the cut into its shaders.
      vtkNew<vtkCubeSource> cube;
      vtkNew<vtkPolyDataMapper> cubeMapper;
      cubeMapper->SetInputConnection(cube->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(cubeMapper);
      actor->SetScale(1e-6 * grid->GetLength());
      renderer->AddActor(actor);
      opaqueActor = actor;
    }
    vtkNew<vtkHAVSIntermixPass> intermix;
    if (translucentPrefix > 0)
    {
      // A lit translucent plane through the centre, across the whole data
      // set, peeled and intermixed with the volume.
      renderer->AddActor(vtkHAVSDataSets::MakeTranslucentPlane(grid));
      renderer->SetPass(intermix);
    }
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    renderer->AddVolume(volume);
    vtkCamera* camera = renderer->GetActiveCamera();
    PlaceView(camera, grid, 0, dataset);
    window->Render(); // warm-up: faces, tables, shaders (twice: drivers compile lazily)
    if (havs)
    {
      // The level of detail ranks its faces in the first frame that draws a subset.
      rankingSeconds = havs->GetLastFrameStatistics()->GetRankingSeconds();
    }
    if (config != "zsweep" && config != "raycast")
    {
      window->Render(); // (the CPU mappers' second frame would only cost time)
    }
    double rendering = 0.0; // the budget counts rendering only, not the reference
    if (havs && lodTarget > 0.0)
    {
      // The camera turns 3 degrees a frame with a frame budget: the level of
      // detail's controller sets the share of internal faces drawn. Then the
      // still frame (the budget back to VTK's still rate) at view 0.
      vtkHAVSStandardViews::PlaceCamera(camera, grid, 0);
      lodWithin = TurnUnderBudget(window, camera, havs, 1000.0 * lodTarget,
        [&](double ms, bool settled)
        {
          lodTrace.push_back(ms);
          if (settled)
          {
            frame.push_back(ms);
            lodFractions.push_back(havs->GetLastFrameStatistics()->GetLevelOfDetailFraction());
          }
        });
      havs->SetLevelOfDetailTargetSeconds(0.0);
    }
    if (budgetPercent > 0.0)
    {
      budget = MeasureBudget(o, window, camera, grid, dataset, property, base, budgetPercent);
      frame = budget.Settled;
      lodTrace = budget.Trace;
      lodWithin = budget.Within;
    }
    if (floorRun)
    {
      floor = MeasureFloor(window, camera, grid, dataset, volume, base);
      frame.push_back(floor.Ms);
    }
    const bool stillFrameOnly = lodTarget > 0.0 || budgetPercent > 0.0 || floorRun;
    for (int view = 0; view < o.Views; ++view)
    {
      if (stillFrameOnly && view > 0)
      {
        break; // the rotation: only the still frame at view 0 is measured against the reference
      }
      PlaceView(camera, grid, view, dataset);
      if (opaqueActor)
      {
        // Behind the eye: in the scene, never in the picture.
        double eye[3], dop[3];
        camera->GetPosition(eye);
        camera->GetDirectionOfProjection(dop);
        const double back = 0.5 * grid->GetLength();
        opaqueActor->SetPosition(
          eye[0] - back * dop[0], eye[1] - back * dop[1], eye[2] - back * dop[2]);
      }
      for (int r = 0; r < o.Repeats; ++r)
      {
        if (havs)
        {
          havs->InvalidateFaceOrder(); // every frame orders its faces, as when the camera moves
        }
        const double seconds = TimedFrame(window);
        rendering += seconds;
        if (stillFrameOnly)
        {
          if (havs)
          {
            lodStill = havs->GetLastFrameStatistics()->GetLevelOfDetailFraction();
          }
          budgetStillScale = base ? base->GetLastImageScale() : NAN;
          break; // one still frame
        }
        frame.push_back(1000.0 * seconds);
        if (havs)
        {
          lodFractions.push_back(havs->GetLastFrameStatistics()->GetLevelOfDetailFraction());
          rankingSeconds =
            std::max(rankingSeconds, havs->GetLastFrameStatistics()->GetRankingSeconds());
          sort.push_back(1000.0 * havs->GetLastFrameStatistics()->GetSortSeconds());
          gather.push_back(1000.0 * havs->GetLastFrameStatistics()->GetGatherSeconds());
          draw.push_back(1000.0 * havs->GetLastFrameStatistics()->GetDrawSeconds());
          flush.push_back(1000.0 * havs->GetLastFrameStatistics()->GetFlushSeconds());
          composite.push_back(1000.0 * havs->GetLastFrameStatistics()->GetCompositeSeconds());
          upload.push_back(1000.0 * havs->GetLastFrameStatistics()->GetUploadSeconds());
          readback.push_back(1000.0 * havs->GetLastFrameStatistics()->GetReadbackSeconds());
          layers.push_back(1000.0 * havs->GetLastFrameStatistics()->GetBoundaryLayerSeconds());
        }
        else if (cellProjection)
        {
          sort.push_back(1000.0 * cellProjection->GetLastOrderSeconds());
          draw.push_back(1000.0 * cellProjection->GetLastDrawSeconds());
        }
        else if (tetRayCast)
        {
          sort.push_back(0.0); // (no order)
          draw.push_back(1000.0 * tetRayCast->GetLastDrawSeconds());
          const double rays = static_cast<double>(tetRayCast->GetLastRaysStarted());
          const std::vector<int>& perTile = tetRayCast->GetLastTilePasses();
          double used = 0.0, passesInUsed = 0.0;
          for (int passes : perTile)
          {
            used += passes > 0 ? 1.0 : 0.0;
            passesInUsed += passes;
          }
          peelPasses.push_back(tetRayCast->GetLastPeelPasses());
          peelMs.push_back(TimerMs(tetRayCast->GetLastPeelSeconds()));
          castMs.push_back(TimerMs(tetRayCast->GetLastCastSeconds()));
          cellsPerRay.push_back(
            rays > 0 ? static_cast<double>(tetRayCast->GetLastCellsCrossed()) / rays : 0.0);
          tilesUsed.push_back(perTile.empty() ? NAN : used / perTile.size());
          tilePasses.push_back(used > 0 ? passesInUsed / used : NAN);
          std::fprintf(stderr,
            "%s %s view %d: %d peel passes, %.0f rays, %.1f cells crossed per ray, %lld fold "
            "re-entries, tiles %d x %d: %.0f with rays, %.2f passes per such tile\n",
            config.c_str(), dataset.c_str(), view, tetRayCast->GetLastPeelPasses(), rays,
            cellsPerRay.back(), static_cast<long long>(tetRayCast->GetLastFoldReentries()),
            tetRayCast->GetLastTileGrid()[0], tetRayCast->GetLastTileGrid()[1], used,
            tilePasses.back());
        }
      }
      if (config != "raster-bound")
      {
        vtkNew<vtkFloatArray> rgba;
        window->GetRGBAPixelData(0, 0, o.Size - 1, o.Size - 1, 0, rgba);
        const std::vector<float> exact = ReferenceImage(o, dataset, grid, property, camera, view,
          nullptr, iso, translucentPrefix > 0 ? intermix->GetLayers() : nullptr,
          iso == IsoSurfaceBlendShaded ? renderer->GetLights() : nullptr);
        const std::vector<uint8_t> folded = FoldedPixels(o, dataset, grid, camera, view, false);
        if (folded.empty())
        {
          foldedPixels = NAN; // not known: nothing left out
        }
        auto leftOut = [&folded](size_t p) { return !folded.empty() && folded[p]; };
        for (size_t p = 0; p < static_cast<size_t>(o.Size) * o.Size; ++p)
        {
          if (leftOut(p))
          {
            foldedPixels += 1;
            continue;
          }
          double worst = 0;
          for (int c = 0; c < 3; ++c)
          {
            const double e = std::fabs(double(rgba->GetValue(4 * p + c)) - exact[4 * p + c]);
            sumSquares += e * e;
            worst = std::max(worst, e);
          }
          maxError = std::max(maxError, worst);
          over1 += worst > 1.0 / 255 ? 1 : 0;
          pixels += 1;
          for (int c = 0; c < 3; ++c)
          {
            // What an 8-bit window cannot avoid: the exact colour rounded to 1/255.
            const double q = std::round(255.0 * exact[4 * p + c]) / 255.0 - exact[4 * p + c];
            floorSquares += q * q;
          }
        }
        // MISSION.md's "exact" is about the float result, not the 8-bit window:
        // the project's mappers draw the view once more (not timed) keeping it.
        auto measureFloat = [&](auto* mapper)
        {
          mapper->SetKeepFloatResult(true);
          window->Render();
          vtkNew<vtkFloatArray> premultiplied;
          int resultSize[2] = { 0, 0 };
          if (mapper->GetFloatResult(premultiplied, resultSize) && resultSize[0] == o.Size &&
            resultSize[1] == o.Size)
          {
            double viewSquares = 0.0, viewMax = 0.0, viewPixels = 0.0;
            size_t worst = 0; // the pixel of the largest difference
            for (size_t p = 0; p < static_cast<size_t>(o.Size) * o.Size; ++p)
            {
              if (leftOut(p))
              {
                continue;
              }
              for (int c = 0; c < 3; ++c)
              {
                const double e =
                  std::fabs(double(premultiplied->GetValue(4 * p + c)) - exact[4 * p + c]);
                viewSquares += e * e;
                worst = e > viewMax ? p : worst;
                viewMax = std::max(viewMax, e);
              }
              viewPixels += 1;
            }
            floatSquares += viewSquares;
            floatMax = std::max(floatMax, viewMax);
            floatPixels += viewPixels;
            std::fprintf(stderr,
              "%s %s view %d: float RMSE %.6f max %.4f at pixel (%d, %d): rgba %.4f %.4f %.4f "
              "%.4f, exact %.4f %.4f %.4f %.4f\n",
              config.c_str(), dataset.c_str(), view,
              viewPixels > 0 ? std::sqrt(viewSquares / (3 * viewPixels)) : 0.0, viewMax,
              static_cast<int>(worst % o.Size), static_cast<int>(worst / o.Size),
              premultiplied->GetValue(4 * worst), premultiplied->GetValue(4 * worst + 1),
              premultiplied->GetValue(4 * worst + 2), premultiplied->GetValue(4 * worst + 3),
              exact[4 * worst], exact[4 * worst + 1], exact[4 * worst + 2], exact[4 * worst + 3]);
          }
          mapper->SetKeepFloatResult(false);
        };
        if (havs)
        {
          measureFloat(havs);
        }
        else if (cellProjection)
        {
          measureFloat(cellProjection);
        }
        else if (tetRayCast)
        {
          measureFloat(tetRayCast);
        }
      }
      ++viewsDone;
      if (rendering > o.Budget)
      {
        break;
      }
    }
    if (edits && config != "zsweep" && config != "raycast")
    {
      MeasureEdits(window, camera, grid, dataset, property, mapper, stillMs, editMs, editTable,
        editVisibility, editGather, editUpload, editDraw);
    }
    if (havs) // the table HAVS drew with: N (fixed) or N:error (chosen automatically)
    {
      skipped = static_cast<long long>(havs->GetLastFrameStatistics()->GetInvisibleCells());
      culled = static_cast<long long>(havs->GetLastFrameStatistics()->GetCulledCells());
      rankingMB = havs->GetLevelOfDetailRanking()->GetMemoryBytes() / 1048576.0;
      tableText = std::to_string(havs->GetLastTableScalarResolution());
      if (havs->GetAutomaticTableResolution())
      {
        char e[32];
        std::snprintf(e, sizeof(e), ":%.2g", havs->GetLastTableError());
        tableText += e;
      }
    }
  }
  const double rmse = pixels > 0 ? std::sqrt(sumSquares / (3 * pixels)) : NAN;
  const double floorRmse = pixels > 0 ? std::sqrt(floorSquares / (3 * pixels)) : NAN;
  const double floatRmse = floatPixels > 0 ? std::sqrt(floatSquares / (3 * floatPixels)) : NAN;
  if (floatPixels == 0)
  {
    floatMax = NAN;
  }
  if (pixels == 0)
  {
    maxError = NAN;
  }
  std::printf("RESULT dataset=%s config=%s size=%d tets=%lld views=%d frames=%zu ms_median=%.3f "
              "ms_min=%.3f ms_max=%.3f sort_ms=%.3f gather_ms=%.3f draw_ms=%.3f flush_ms=%.3f "
              "composite_ms=%.3f upload_ms=%.3f readback_ms=%.3f layers_ms=%.3f rmse=%.6f max=%.6f "
              "over1=%.6f peak_mb=%.1f smp=%s threads=%d table=%s skipped=%lld culled=%lld "
              "lod_fraction=%.4f ranking_s=%.3f ranking_mb=%.1f lod_target_ms=%.0f "
              "lod_within25=%.3f lod_still=%.3f lod_trace=%s peel_passes=%.1f cells_per_ray=%.2f "
              "tiles_used=%.4f tile_passes=%.3f float_rmse=%.6f float_max=%.6f floor_rmse=%.6f "
              "folded_px=%.0f peel_ms=%.3f cast_ms=%.3f still_ms=%.3f edit_ms=%.3f "
              "edit_table_ms=%.3f edit_visibility_ms=%.3f edit_gather_ms=%.3f "
              "edit_upload_ms=%.3f edit_draw_ms=%.3f lod_percent=%g lod_full_ms=%.3f "
              "lod_budget_ms=%.3f lod_settled_ms=%.3f lod_ratio=%.3f lod_scale=%.3f "
              "lod_faces=%.4f lod_rmse=%.3f lod_max=%.3f lod_error_scale=%.3f "
              "lod_still_scale=%.3f lod_scale_trace=%s floor_full_ms=%.3f floor_ms=%.3f "
              "floor_tiny_ms=%.3f floor_order_ms=%.3f floor_draw_ms=%.3f floor_peel_ms=%.3f "
              "floor_cast_ms=%.3f floor_passes=%.1f floor_empty_ms=%.3f\n",
    dataset.c_str(), rowConfig.c_str(), o.Size, static_cast<long long>(tets), viewsDone,
    frame.size(), Median(frame),
    frame.empty() ? NAN : *std::min_element(frame.begin(), frame.end()),
    frame.empty() ? NAN : *std::max_element(frame.begin(), frame.end()), Median(sort),
    Median(gather), Median(draw), Median(flush), Median(composite), Median(upload),
    Median(readback), Median(layers), rmse, maxError, pixels > 0 ? over1 / pixels : NAN,
    PeakMegabytes(), vtkSMPTools::GetBackend(), vtkSMPTools::GetEstimatedNumberOfThreads(),
    tableText.c_str(), skipped, culled, Median(lodFractions), rankingSeconds, rankingMB,
    1000.0 * lodTarget, lodWithin, lodStill, TraceText(lodTrace).c_str(), Median(peelPasses),
    Median(cellsPerRay), Median(tilesUsed), Median(tilePasses), floatRmse, floatMax, floorRmse,
    foldedPixels, Median(peelMs), Median(castMs), Median(stillMs), Median(editMs),
    Median(editTable), Median(editVisibility), Median(editGather), Median(editUpload),
    Median(editDraw), budgetPercent > 0.0 ? budgetPercent : NAN, budget.FullMs, budget.BudgetMs,
    Median(budget.Settled), Median(budget.Settled) / budget.BudgetMs, Median(budget.Scales),
    Median(budget.Faces), budget.RMSE, budget.Max, budget.ErrorScale, budgetStillScale,
    TraceText(budget.ScaleTrace, "%.2f").c_str(), floor.FullMs, floor.Ms, floor.TinyMs,
    floor.OrderMs, floor.DrawMs, floor.PeelMs, floor.CastMs, floor.Passes, floor.EmptyMs);
  return EXIT_SUCCESS;
}

std::map<std::string, std::string> ParseResult(const std::string& line)
{
  std::map<std::string, std::string> fields;
  std::stringstream in(line.substr(7));
  std::string item;
  while (in >> item)
  {
    const size_t eq = item.find('=');
    if (eq != std::string::npos)
    {
      fields[item.substr(0, eq)] = item.substr(eq + 1);
    }
  }
  return fields;
}

using Row = std::map<std::string, std::string>;

const char* const kColumns[] = { "dataset", "config", "size", "tets", "views", "frames",
  "ms_median", "ms_min", "ms_max", "sort_ms", "gather_ms", "draw_ms", "flush_ms", "composite_ms",
  "upload_ms", "readback_ms", "layers_ms", "mtets_per_s", "rmse", "max", "over1", "peak_mb", "smp",
  "threads", "table", "skipped", "culled", "lod_fraction", "ranking_s", "ranking_mb",
  "lod_target_ms", "lod_within25", "lod_still", "lod_trace", "peel_passes", "cells_per_ray",
  "tiles_used", "tile_passes", "float_rmse", "float_max", "floor_rmse", "folded_px", "peel_ms",
  "cast_ms", "still_ms", "edit_ms", "edit_table_ms", "edit_visibility_ms", "edit_gather_ms",
  "edit_upload_ms", "edit_draw_ms", "lod_percent", "lod_full_ms", "lod_budget_ms", "lod_settled_ms",
  "lod_ratio", "lod_scale", "lod_faces", "lod_rmse", "lod_max", "lod_error_scale",
  "lod_still_scale", "lod_scale_trace", "floor_full_ms", "floor_ms", "floor_tiny_ms",
  "floor_order_ms", "floor_draw_ms", "floor_peel_ms", "floor_cast_ms", "floor_passes",
  "floor_empty_ms", "rounds", "command" };

/// A CSV field, quoted where it holds a comma or a quote.
std::string CsvField(const std::string& text)
{
  if (text.find_first_of(",\"") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

/// The fields of one CSV line (quoted fields as CsvField writes them).
std::vector<std::string> CsvFields(const std::string& line)
{
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
    {
      fields.back() += '"';
      ++i;
    }
    else if (c == '"')
    {
      quoted = !quoted;
    }
    else if (c == ',' && !quoted)
    {
      fields.emplace_back();
    }
    else
    {
      fields.back() += c;
    }
  }
  return fields;
}

/// Runs a worker and returns its RESULT fields (empty when it failed).
Row RunChild(const std::string& command)
{
  FILE* pipe = popen(command.c_str(), "r");
  std::string result;
  char buffer[4096];
  while (pipe && std::fgets(buffer, sizeof(buffer), pipe))
  {
    if (std::string(buffer).rfind("RESULT ", 0) == 0)
    {
      result = buffer;
    }
  }
  if (pipe)
  {
    pclose(pipe);
  }
  return result.empty() ? Row() : ParseResult(result);
}

/// One row from a configuration's rounds (--rounds; each round starts one
/// configuration later): each time is the median
/// over the rounds of the per-round medians (min and max over all), the peak
/// memory the largest; errors and counts are the first round's (the images do
/// not change between rounds). Interleaving the rounds spreads this machine's
/// slow drifts over every configuration alike.
Row MergeRounds(const std::vector<Row>& rounds)
{
  Row merged = rounds.front();
  merged["rounds"] = std::to_string(rounds.size());
  if (rounds.size() < 2)
  {
    return merged;
  }
  auto values = [&](const char* key)
  {
    std::vector<double> v;
    for (const Row& r : rounds)
    {
      const auto it = r.find(key);
      const double x = it == r.end() ? NAN : std::atof(it->second.c_str());
      if (std::isfinite(x))
      {
        v.push_back(x);
      }
    }
    std::sort(v.begin(), v.end());
    return v;
  };
  auto text = [](double x)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.3f", x);
    return std::string(buffer);
  };
  for (const char* key : { "ms_median", "sort_ms", "gather_ms", "draw_ms", "flush_ms",
         "composite_ms", "upload_ms", "readback_ms", "layers_ms", "peel_ms", "cast_ms" })
  {
    const std::vector<double> v = values(key);
    if (!v.empty())
    {
      merged[key] = text(Median(v));
    }
  }
  const std::vector<double> lows = values("ms_min"), highs = values("ms_max"),
                            peaks = values("peak_mb"), frames = values("frames");
  if (!lows.empty())
  {
    merged["ms_min"] = text(lows.front());
    merged["ms_max"] = text(highs.back());
  }
  if (!peaks.empty())
  {
    merged["peak_mb"] = text(peaks.back());
  }
  double total = 0.0;
  for (double f : frames)
  {
    total += f;
  }
  merged["frames"] = std::to_string(static_cast<long long>(total));
  return merged;
}

void WriteCsv(const std::vector<Row>& rows, const std::string& path)
{
  std::ofstream csv(path);
  for (size_t c = 0; c < sizeof(kColumns) / sizeof(kColumns[0]); ++c)
  {
    csv << (c ? "," : "") << kColumns[c];
  }
  csv << "\n";
  for (const Row& r : rows)
  {
    for (size_t c = 0; c < sizeof(kColumns) / sizeof(kColumns[0]); ++c)
    {
      const auto it = r.find(kColumns[c]);
      csv << (c ? "," : "") << (it == r.end() ? "" : CsvField(it->second));
    }
    csv << "\n";
  }
}

std::vector<Row> ReadCsv(const std::string& path)
{
  std::vector<Row> rows;
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> header;
  if (std::getline(in, line))
  {
    header = CsvFields(line);
  }
  while (std::getline(in, line))
  {
    const std::vector<std::string> fields = CsvFields(line);
    Row r;
    for (size_t c = 0; c < header.size() && c < fields.size(); ++c)
    {
      r[header[c]] = fields[c];
    }
    rows.push_back(r);
  }
  return rows;
}

double Value(const Row& r, const char* key)
{
  const auto it = r.find(key);
  return it == r.end() ? NAN : std::atof(it->second.c_str());
}

/// A value as a table shows it ("-" where it is not a number).
std::string FormatValue(double v, const char* format = "%.3f")
{
  if (!std::isfinite(v))
  {
    return "-";
  }
  char text[64];
  std::snprintf(text, sizeof(text), format, v);
  return text;
}

std::string Cell(const Row& r, const char* key, const char* format = "%.3f")
{
  return FormatValue(Value(r, key), format);
}

/// MISSION.md's exact: RMSE < 5e-4 and max < 0.01 (on the float result).
bool IsExact(double rmse, double max)
{
  return rmse < 5e-4 && max < 0.01;
}

/// A row's error and whether it is exact (MISSION.md: RMSE < 5e-4 and max <
/// 0.01 on the float result). Rows with a float result (the project's mappers,
/// runs from this version on) are judged on it and also give the 8-bit
/// window's error and its floor; older rows only have the window's error.
std::string ErrorText(const Row& r)
{
  std::string text;
  double rmse = Value(r, "rmse"), max = Value(r, "max");
  const bool hasFloat = std::isfinite(Value(r, "float_rmse"));
  if (hasFloat)
  {
    rmse = Value(r, "float_rmse");
    max = Value(r, "float_max");
    text = "float result RMSE " + Cell(r, "float_rmse", "%.5f") + ", max " +
      Cell(r, "float_max", "%.4f");
  }
  else
  {
    text = "RMSE " + Cell(r, "rmse", "%.5f") + ", max " + Cell(r, "max", "%.4f");
  }
  text += IsExact(rmse, max) ? " (exact" : " (not exact";
  text += hasFloat ? ": RMSE < 5e-4 and max < 0.01 on the float result)"
                   : ": RMSE < 5e-4 and max < 0.01, on the 8-bit window)";
  if (std::isfinite(Value(r, "folded_px")) && Value(r, "folded_px") > 0)
  {
    text += "; " + Cell(r, "folded_px", "%.0f") +
      " pixels (all views) whose exact rays cross folded cells left out";
  }
  if (hasFloat)
  {
    text += "; in the 8-bit window RMSE " + Cell(r, "rmse", "%.5f") + ", max " +
      Cell(r, "max", "%.4f") + " (rounding alone: " + Cell(r, "floor_rmse", "%.5f") + ")";
  }
  return text;
}

/// The CPU model and core count (from /proc/cpuinfo).
std::string Machine()
{
  std::ifstream info("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  int cores = 0;
  while (std::getline(info, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      model = line.substr(line.find(':') + 2);
      ++cores;
    }
  }
  return model + " (" + std::to_string(cores) + " logical CPUs)";
}

/// The SMP backends and thread counts the rows ran with, e.g. "STDThread (2 threads)".
std::string SmpBackends(const std::vector<Row>& rows)
{
  std::vector<std::string> seen;
  for (const Row& r : rows)
  {
    const auto smp = r.find("smp");
    const auto threads = r.find("threads");
    const std::string text = smp == r.end() || smp->second.empty()
      ? std::string("not recorded")
      : smp->second + " (" + (threads == r.end() ? "?" : threads->second) + " threads)";
    if (std::find(seen.begin(), seen.end(), text) == seen.end())
    {
      seen.push_back(text);
    }
  }
  std::string out;
  for (size_t i = 0; i < seen.size(); ++i)
  {
    out += (i ? ", " : "") + seen[i];
  }
  return out.empty() ? "none" : out;
}

/// ", from rows measured by `a`, `b`" where the rows came from other runs.
std::string MeasuredBy(const std::vector<Row>& rows, const std::string& command)
{
  std::vector<std::string> commands;
  for (const Row& r : rows)
  {
    const auto it = r.find("command");
    if (it != r.end() && !it->second.empty() && it->second != command &&
      std::find(commands.begin(), commands.end(), it->second) == commands.end())
    {
      commands.push_back(it->second);
    }
  }
  std::string text;
  for (size_t i = 0; i < commands.size(); ++i)
  {
    text += (i ? ", `" : ", from rows measured by `") + commands[i] + "`";
  }
  return text;
}

/// A row of the level of detail's section: a havs-lod-* configuration, or
/// any row a level-of-detail run measured (its full frame, havs-default, is
/// the section's 100 %, measured beside it on the same machine).
bool IsLevelOfDetail(const Row& r)
{
  return (r.count("config") && r.at("config").rfind("havs-lod-", 0) == 0) ||
    (r.count("command") && r.at("command").find("havs-lod-") != std::string::npos);
}

/// A row of the transfer-function edits' section: an edit-* configuration.
bool IsEdit(const Row& r)
{
  return r.count("config") && r.at("config").rfind("edit-", 0) == 0;
}

/// A row of an edit run (its edit-* rows and the reference it made): none
/// of them in the main tables.
bool IsEditRun(const Row& r)
{
  return IsEdit(r) || (r.count("command") && r.at("command").find("edit-") != std::string::npos);
}

/// A row of an isosurface run (issue 46: its iso-* and isomix-* rows, the
/// composite rows beside them and the reference it made): the isosurfaces'
/// section, none of them in the main tables.
bool IsIsoRun(const Row& r)
{
  return (r.count("config") && IsoModeOf(r.at("config")) != NoIsoSurfaces) ||
    (r.count("command") &&
      (r.at("command").find(",iso-") != std::string::npos ||
        r.at("command").find(" iso-") != std::string::npos ||
        r.at("command").find("isomix-") != std::string::npos ||
        r.at("command").find("isoshade-") != std::string::npos));
}

/// A row of a translucent run (issue 46: its translucent-* rows, the rows
/// beside them and the reference it made): the translucent geometry's
/// section, none of them in the main tables.
bool IsTranslucentRun(const Row& r)
{
  return (r.count("config") && TranslucentPrefix(r.at("config")) > 0) ||
    (r.count("command") && r.at("command").find("translucent-") != std::string::npos);
}

/// A row of the frame budgets' section: a lod-<percent>-* configuration.
bool IsBudget(const Row& r)
{
  return r.count("config") && StartsBudget(r.at("config"), 0);
}

/// A row of the frame floors (in the frame budgets' section): a floor-*
/// configuration.
bool IsFloor(const Row& r)
{
  return r.count("config") && r.at("config").rfind("floor-", 0) == 0;
}

/// A row of a frame-budget run (its lod-<percent>-* and floor-* rows and the
/// reference it made): none of them in the other tables.
bool IsBudgetRun(const Row& r)
{
  if (IsBudget(r) || IsFloor(r))
  {
    return true;
  }
  const auto it = r.find("command");
  if (it == r.end())
  {
    return false;
  }
  // (A floor-* configuration in the run's --configs list.)
  if (it->second.find(" floor-") != std::string::npos ||
    it->second.find(",floor-") != std::string::npos)
  {
    return true;
  }
  for (size_t at = it->second.find("lod-"); at != std::string::npos;
       at = it->second.find("lod-", at + 1))
  {
    if (StartsBudget(it->second, at))
    {
      return true;
    }
  }
  return false;
}

/// The frame budgets' section: per data set, mapper and budget (a share of
/// the full frame), the settled frames against the budget, the detail they
/// drew, the interactive frame's error and the still frame's.
std::string BudgetReport(const std::vector<Row>& allRows)
{
  std::vector<Row> rows;
  std::copy_if(allRows.begin(), allRows.end(), std::back_inserter(rows), IsBudget);
  if (rows.empty())
  {
    return std::string();
  }
  // Grouped by data set and mapper (in the order first measured), the
  // largest budget first.
  std::vector<std::string> datasets, mappers;
  auto mapperOf = [](const Row& r)
  {
    double percent = 0.0;
    std::string config;
    ParseBudget(r.at("config"), percent, config);
    return config;
  };
  for (const Row& r : rows)
  {
    if (std::find(datasets.begin(), datasets.end(), r.at("dataset")) == datasets.end())
      datasets.push_back(r.at("dataset"));
    if (std::find(mappers.begin(), mappers.end(), mapperOf(r)) == mappers.end())
      mappers.push_back(mapperOf(r));
  }
  auto index = [](const std::vector<std::string>& v, const std::string& x)
  { return std::find(v.begin(), v.end(), x) - v.begin(); };
  std::stable_sort(rows.begin(), rows.end(),
    [&](const Row& a, const Row& b)
    {
      const auto ka = std::make_tuple(
        index(datasets, a.at("dataset")), index(mappers, mapperOf(a)), -Value(a, "lod_percent"));
      const auto kb = std::make_tuple(
        index(datasets, b.at("dataset")), index(mappers, mapperOf(b)), -Value(b, "lod_percent"));
      return ka < kb;
    });
  std::ostringstream md;
  md << "\n## Frame budgets\n\n"
     << "lod-<percent>-<configuration>: that configuration with a frame budget of that share "
        "of its full frame (vtkHAVSMapperBase::SetLevelOfDetailTargetSeconds). At view 0 the "
        "camera turns 3° a frame: 5 frames with no budget (VTK's still rate), their median the "
        "full frame; then 60 frames with the budget (the camera turns 180° in them: a frame's "
        "cost changes with the view), of which the last 30 are the settled "
        "frames (their median time, the share within 25 % of the budget, the median image "
        "scale and, for HAVS, the median share of internal faces drawn). The stage timers are "
        "off, as in a user's interactive frames. The level of detail is the same for the three "
        "mappers: a reduced image (the volume drawn at a scale of the viewport along each axis, "
        "as many pixels as the last frames' times say fit the budget: a "
        "vtkHAVSLevelOfDetailController on the share of the full frame's detail), upsampled "
        "bilinearly (premultiplied) over the viewport in the composite, the edges kept sharp "
        "(vtkHAVSMapperBase::EdgeUpsampling: no volume where no boundary face lies in front of "
        "the opaque depth; dropped at the smallest image once a frame there misses the budget, "
        "so a row settled there has plain bilinear's error); HAVS also draws a subset "
        "of its internal faces, the image and the faces each the square root of the detail, and "
        "its subset frames use the centroid order of the faces they draw. Interactive frame: "
        "the budget still set, view 0 drawn 3 times (the controller keeps its detail), the "
        "window's RGB against the exact image (RMSE and max, in units of 1/255, pixels whose "
        "exact rays cross folded cells left out). Still frame: the budget back to 0, view 0 "
        "once, judged as above on the float result (its image scale should be 1: the exact "
        "image). The target: a settled median at most 1.25 times the budget; a miss is named "
        "in the table with its cause: where the settled frames drew the smallest image (scale "
        "0.1, 1 % of the pixels; HAVS also 1 % of its internal faces) and still took more than "
        "the budget, the frame's floor, its part that drawing fewer pixels does not shrink, is "
        "above it; where they drew more, a floor within 25 % of the budget leaves the pixels "
        "too little (the floor changes with the view by more than that), else the controller "
        "missed. The floors and their parts are measured by the floor-* rows, without the "
        "edges' mask (below the table: "
        "HAVS's face sort and gather; the ray caster's boundary faces drawn twice a peeling "
        "pass; the cell projection's cell order and every cell's faces drawn, on llvmpipe). "
        "These rows come from their own runs: compare their times with each other, not with "
        "the tables above.\n\n"
     << "| data set | size | mapper | tets | budget | full ms | budget ms | settled ms | median / "
        "budget | within 25 % | image scale | HAVS faces | interactive RMSE / max (1/255) | "
        "still frame |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  // The floors measured for a data set and mapper (floor-* rows).
  std::vector<Row> floors;
  std::copy_if(allRows.begin(), allRows.end(), std::back_inserter(floors), IsFloor);
  auto floorOf = [&](const Row& r) -> const Row*
  {
    for (const Row& f : floors)
    {
      if (f.at("dataset") == r.at("dataset") && f.at("config").substr(6) == mapperOf(r))
      {
        return &f;
      }
    }
    return nullptr;
  };
  std::ostringstream traces;
  for (const Row& r : rows)
  {
    const double ratio = Value(r, "lod_ratio"), scale = Value(r, "lod_scale");
    std::string ratioText = Cell(r, "lod_ratio", "%.2f");
    if (std::isfinite(ratio) && ratio > 1.25)
    {
      // At the smallest image the floor is over the budget; above it, a
      // floor within 25 % of the budget leaves the pixels too little (the
      // floor changes with the view more than that), else the controller.
      const Row* f = floorOf(r);
      const double floorShare = f ? Value(*f, "floor_ms") / Value(r, "lod_budget_ms") : NAN;
      ratioText = "**" + ratioText + "** miss: " +
        (scale <= 0.1 + 1e-3 ? "the smallest image over budget"
            : floorShare >= 0.8
            ? "the floor is " + FormatValue(100.0 * floorShare, "%.0f") + " % of the budget"
            : "above the smallest image (the controller)");
      if (f)
      {
        ratioText += " (floor " + Cell(*f, "floor_ms", "%.1f") + " ms, " +
          FormatValue(100.0 * floorShare, "%.0f") + " % of the budget; " +
          Cell(*f, "floor_tiny_ms", "%.1f") + " ms at 0.01 % of the pixels)";
      }
    }
    const double stillScale = Value(r, "lod_still_scale");
    const bool hasFloat = std::isfinite(Value(r, "float_rmse"));
    const double stillRmse = hasFloat ? Value(r, "float_rmse") : Value(r, "rmse");
    const double stillMax = hasFloat ? Value(r, "float_max") : Value(r, "max");
    std::string still = IsExact(stillRmse, stillMax) ? "exact" : "**not exact**";
    still += std::string(hasFloat ? " (float result RMSE " : " (RMSE ") +
      Cell(r, hasFloat ? "float_rmse" : "rmse", "%.5f") + ", max " +
      Cell(r, hasFloat ? "float_max" : "max", "%.4f") + "; scale " +
      Cell(r, "lod_still_scale", "%.2f") + ")";
    if (std::isfinite(stillScale) && stillScale < 1.0)
    {
      still = "**reduced** " + still;
    }
    md << "| " << r.at("dataset") << " | " << (r.count("size") ? r.at("size") : "-") << " | "
       << mapperOf(r) << " | " << Cell(r, "tets", "%.0f") << " | " << Cell(r, "lod_percent", "%g")
       << " % | " << Cell(r, "lod_full_ms", "%.1f") << " | " << Cell(r, "lod_budget_ms", "%.1f")
       << " | " << Cell(r, "lod_settled_ms", "%.1f") << " | " << ratioText << " | "
       << Cell(r, "lod_within25", "%.2f") << " | " << Cell(r, "lod_scale", "%.2f") << " | "
       << Cell(r, "lod_faces", "%.3f") << " | " << Cell(r, "lod_rmse", "%.2f") << " / "
       << Cell(r, "lod_max", "%.1f") << " | " << still << " |\n";
    traces << "- " << r.at("dataset") << " " << r.at("config") << ": "
           << (r.count("lod_trace") ? r.at("lod_trace") : "-") << "\n";
  }
  // The budgets met, and the misses' causes.
  int met = 0, floorMisses = 0, otherMisses = 0;
  for (const Row& r : rows)
  {
    const double ratio = Value(r, "lod_ratio");
    met += ratio <= 1.25 ? 1 : 0;
    floorMisses += ratio > 1.25 && Value(r, "lod_scale") <= 0.1 + 1e-3 ? 1 : 0;
    otherMisses += ratio > 1.25 && Value(r, "lod_scale") > 0.1 + 1e-3 ? 1 : 0;
  }
  md << "\nMet (median / budget at most 1.25): " << met << " of " << rows.size() << "; missed at "
     << "the smallest image (the floor above the budget): " << floorMisses
     << "; missed above it: " << otherMisses << ".\n";
  if (!floors.empty())
  {
    md << "\n### The floors: a frame at the smallest images\n\n"
       << "floor-<configuration>: the camera turning 3° a frame as in the budgets' runs, with no "
          "budget, the "
          "frame at three fixed image scales (vtkHAVSMapperBase::SetImageScale): 1 (the full "
          "frame, over the budgets' 5 full frames' views), 0.1 (the level of detail's smallest "
          "image, 1 % of the pixels) and 0.01 (0.01 % of them), each over the budgets' 30 "
          "settled frames' views (HAVS draws the same share of its internal faces as of its "
          "pixels). Medians, the stage timers on (each stage ends with the "
          "GPU's work; on the blunt fin at scale 0.1 frames with and without them were within this "
          "machine's noise of each other, ±15 % from block to block). A frame that costs at "
          "0.01 % of the pixels what it costs at 1 % spends that time on something other than "
          "pixels: the parts at scale 0.1 say on what: the order (the cell projection's MPVO "
          "cell order on the CPU; HAVS's face sort and gather), the draw, and the ray caster's "
          "peeling (drawing the boundary faces twice a pass: the nearest entry's key, then its "
          "cell) and casting, from GPU "
          "timestamps, with its peeling passes. Empty window: the same window's frame with the "
          "volume hidden (what the window costs without a mapper). A budget below the floor "
          "cannot be met by drawing fewer pixels; on llvmpipe the rasterizer's cost per "
          "triangle is a CPU's (its vertex processing and binning run on the main thread).\n\n"
       << "| data set | mapper | tets | full ms | floor ms (1 % pixels) | at 0.01 % | floor / full "
          "| order ms | draw ms | peeling ms | casting ms | peeling passes | empty window ms |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& f : floors)
    {
      md << "| " << f.at("dataset") << " | " << f.at("config").substr(6) << " | "
         << Cell(f, "tets", "%.0f") << " | " << Cell(f, "floor_full_ms", "%.1f") << " | "
         << Cell(f, "floor_ms", "%.1f") << " | " << Cell(f, "floor_tiny_ms", "%.1f") << " | "
         << FormatValue(Value(f, "floor_ms") / Value(f, "floor_full_ms"), "%.2f") << " | "
         << Cell(f, "floor_order_ms", "%.1f") << " | " << Cell(f, "floor_draw_ms", "%.1f") << " | "
         << Cell(f, "floor_peel_ms", "%.1f") << " | " << Cell(f, "floor_cast_ms", "%.1f") << " | "
         << Cell(f, "floor_passes", "%.0f") << " | " << Cell(f, "floor_empty_ms", "%.2f") << " |\n";
    }
  }
  md << "\nFrame times (ms; the first 30 while settling, the last 30 settled):\n\n" << traces.str();
  return md.str();
}

/// The translucent geometry's section (issue 46): per data set, size and
/// mapper, the frame without and with the translucent plane intermixed, and
/// A row's image size ("" when it has none).
std::string SizeOf(const Row& r)
{
  return r.count("size") ? r.at("size") : std::string();
}

/// The first of `rows` with `like`'s data set and size and configuration `config`.
const Row* FindRow(const std::vector<Row>& rows, const Row& like, const std::string& config)
{
  for (const Row& r : rows)
  {
    if (r.at("dataset") == like.at("dataset") && SizeOf(r) == SizeOf(like) &&
      r.at("config") == config)
    {
      return &r;
    }
  }
  return nullptr;
}

/// the error of the latter against the exact image with the plane.
std::string TranslucentReport(const std::vector<Row>& allRows)
{
  std::vector<Row> rows;
  std::copy_if(allRows.begin(), allRows.end(), std::back_inserter(rows), IsTranslucentRun);
  std::ostringstream table;
  for (const Row& r : rows)
  {
    const std::string& config = r.at("config");
    if (TranslucentPrefix(config) == 0)
    {
      continue;
    }
    const std::string plain = config.substr(TranslucentPrefix(config));
    const Row* without = FindRow(rows, r, plain);
    const bool hasFloat = std::isfinite(Value(r, "float_rmse"));
    const double ratio = without ? Value(r, "ms_median") / Value(*without, "ms_median") : NAN;
    char ratioText[32];
    std::snprintf(ratioText, sizeof(ratioText), "%.2f", ratio);
    table << "| " << r.at("dataset") << " | " << SizeOf(r) << " | " << plain << " | "
          << (without ? Cell(*without, "ms_median", "%.1f") : "-") << " | "
          << Cell(r, "ms_median", "%.1f") << " | " << (std::isfinite(ratio) ? ratioText : "-")
          << " | "
          << (hasFloat
                 ? Cell(r, "float_rmse", "%.2g") + " / " + Cell(r, "float_max", "%.2g") + " (float)"
                 : Cell(r, "rmse", "%.2g") + " / " + Cell(r, "max", "%.2g") + " (window)")
          << " |\n";
  }
  if (table.str().empty())
  {
    return std::string();
  }
  std::ostringstream md;
  md << "\n## Translucent geometry\n\n"
     << "translucent-<configuration>: that configuration with a lit translucent plane (opacity "
        "0.45, normal (0.3, 0.45, 1)) through the data set's centre, across it, and the "
        "renderer's pass a `vtkHAVSIntermixPass`: the plane is peeled into a layer and the "
        "project's mappers composite it at its depth inside the volume (the volume drawn once "
        "before the layer and once to the end); VTK's PT is drawn over the plane (VTK's "
        "order). Times as above (medians over the views; the peeling and the plane's own "
        "draws included); the ratio is against the same configuration without the plane in "
        "the same run. Error: against the exact image with the plane (the reference with the "
        "peeled layer as an event along each ray), the float result for the project's mappers "
        "(MISSION.md's exact: RMSE < 5e-4, max < 0.01), the 8-bit window for PT.\n\n"
     << "| data set | size | configuration | without the plane ms | with the plane ms | with / "
        "without | error RMSE / max |\n"
     << "|---|---|---|---|---|---|---|\n"
     << table.str();
  return md.str();
}

/// The isosurfaces' section (issue 46): per data set, size and mapper, the
/// composite frame beside the isosurface blend's and the composite with the
/// isosurfaces inside, with their errors against the exact reference of each.
std::string IsoReport(const std::vector<Row>& allRows)
{
  std::vector<Row> rows;
  std::copy_if(allRows.begin(), allRows.end(), std::back_inserter(rows), IsIsoRun);
  std::ostringstream table;
  for (const Row& r : rows)
  {
    const std::string& config = r.at("config");
    if (IsoModeOf(config) != NoIsoSurfaces || config == "reference" ||
      !FindRow(rows, r, "iso-" + config))
    {
      continue;
    }
    const Row* iso = FindRow(rows, r, "iso-" + config);
    const Row* mixed = FindRow(rows, r, "isomix-" + config);
    const Row* shaded = FindRow(rows, r, "isoshade-" + config);
    const double composite = Value(r, "ms_median");
    auto ratio = [composite](const Row* x)
    {
      char text[32];
      std::snprintf(text, sizeof(text), "%.2f", x ? Value(*x, "ms_median") / composite : NAN);
      return std::string(x && std::isfinite(Value(*x, "ms_median")) ? text : "-");
    };
    auto error = [](const Row* x)
    { return x ? Cell(*x, "float_rmse", "%.2g") + " / " + Cell(*x, "float_max", "%.2g") : "-"; };
    table << "| " << r.at("dataset") << " | " << SizeOf(r) << " | " << config << " | "
          << Cell(r, "ms_median", "%.1f") << " | " << Cell(*iso, "ms_median", "%.1f") << " | "
          << ratio(iso) << " | " << error(iso) << " | "
          << (mixed ? Cell(*mixed, "ms_median", "%.1f") : "-") << " | " << ratio(mixed) << " | "
          << error(mixed) << " | " << (shaded ? Cell(*shaded, "ms_median", "%.1f") : "-") << " | "
          << ratio(shaded) << " | " << error(shaded) << " |\n";
  }
  if (table.str().empty())
  {
    return std::string();
  }
  std::ostringstream md;
  md << "\n## Isosurfaces\n\n"
     << "iso-<configuration>: that configuration with the isosurface blend (`SetBlendMode(5)`; "
        "two isovalues, at 35 % and 65 % of the scalar range, in the volume property's "
        "`GetIsoSurfaceValues()`): each crossing takes the transfer functions' colour and "
        "opacity at its value, nothing between. isomix-<configuration>: the composite volume "
        "with the same isosurfaces inside (`IsoSurfacesInComposite`). isoshade-<configuration>: "
        "the isosurface blend lit (`ShadeOn`, the renderer's headlight; normals of the "
        "interpolated point gradients; HAVS takes its fragment-list path for them). Times as "
        "above (medians "
        "over the views); the ratios are against the same configuration's composite frame in "
        "the same run. Error: the float result against the exact reference of the same mode "
        "(vtkHAVSReferenceRenderer's isosurface events), RMSE / max (MISSION.md's exact: "
        "RMSE < 5e-4, max < 0.01). havs-default-noclamp and cellproj-floatiso, where present: "
        "the testing controls `NoFaceClampForTesting` (HAVS's isosurface fragments as the "
        "rasterizer gives them) and `FloatIsoStretchesForTesting` (the cell projection's "
        "stretches and face scalars from its float planes and field): what taking the "
        "crossings on the pixel's exact ray in double costs and buys.\n\n"
     << "| data set | size | configuration | composite ms | isosurfaces ms | iso / composite | "
        "iso float RMSE / max | composite with isosurfaces ms | mixed / composite | mixed "
        "float RMSE / max | shaded isosurfaces ms | shaded / composite | shaded float RMSE / "
        "max |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
     << table.str();
  return md.str();
}

/// The transfer-function edits' section (issue 45): per data set, size and
/// mapper, a new view, a still redraw, an edit and the edit's parts.
std::string EditReport(const std::vector<Row>& allRows)
{
  // A run with -gputable configurations: its rows go to their own table, each
  // beside the same configuration on the CPU's table from that run.
  auto gpuRun = [](const Row& r)
  { return r.count("command") && r.at("command").find(GPUTableSuffix) != std::string::npos; };
  std::vector<Row> rows, gpuRows;
  for (const Row& r : allRows)
  {
    if (IsEdit(r))
    {
      (gpuRun(r) ? gpuRows : rows).push_back(r);
    }
  }
  if (rows.empty() && gpuRows.empty())
  {
    return std::string();
  }
  std::ostringstream md;
  md << "\n## Transfer-function edits\n\n"
     << "edit-<configuration>: that configuration's views as above (a new view: the median "
        "frame, the camera moved), then at view 0 15 frames that rebuild nothing (a still "
        "redraw; 7 where one takes a second or more), each followed by an edit, the middle opacity "
        "node moved by 10 % of its value "
        "and back, the camera still (interleaved, so that the machine's drift weighs both "
        "alike; medians). An edit's parts: the table (every project mapper's "
        "`GetLastTableSeconds`: the pre-integrated table, with the automatic resolution its "
        "candidates, from its last choice, and their error probes), HAVS's cell visibility, "
        "face gather, uploads and "
        "draw (its stage times, `MeasureStageTimes` on for HAVS and the cell projection: each "
        "stage ends with the GPU's work), the other two mappers' draw. The target (issue 45): "
        "an edit costs at most 1.1 times a still redraw.\n\n"
     << "| data set | size | configuration | tets | new view ms | still ms | edit ms | edit / "
        "still | edit / view | table ms | visibility ms | gather ms | upload ms | draw ms |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    const double still = Value(r, "still_ms"), edit = Value(r, "edit_ms"),
                 view = Value(r, "ms_median");
    char ratios[64];
    std::snprintf(ratios, sizeof(ratios), "%.2f | %.2f", edit / still, edit / view);
    md << "| " << r.at("dataset") << " | " << (r.count("size") ? r.at("size") : "-") << " | "
       << r.at("config").substr(5) << " | " << Cell(r, "tets", "%.0f") << " | "
       << Cell(r, "ms_median", "%.1f") << " | " << Cell(r, "still_ms", "%.1f") << " | "
       << Cell(r, "edit_ms", "%.1f") << " | " << ratios << " | " << Cell(r, "edit_table_ms", "%.1f")
       << " | " << Cell(r, "edit_visibility_ms", "%.1f") << " | "
       << Cell(r, "edit_gather_ms", "%.1f") << " | " << Cell(r, "edit_upload_ms", "%.1f") << " | "
       << Cell(r, "edit_draw_ms", "%.1f") << " |\n";
  }
  if (!gpuRows.empty())
  {
    md << "\n### The table built on the GPU\n\n"
       << "<configuration>-gputable: the same mapper with `PreIntegrationOnGPU` on (the table's "
          "entries built by a compute shader from the CPU's fine samples and read back, "
          "`vtkHAVSGLTableBuilder`), beside it on the CPU's table, in one run. Here the "
          "\"GPU\" is llvmpipe on the same 2 cores: what it shows is the cost of the route "
          "there, not on a GPU (the GPU check's table cases measure it there: "
          "`Apps/GPUBench/gpu_check.sh`). The other two candidates, incremental rebuilds and "
          "partial pre-integration, are counted in `table-candidates.md` "
          "(`Apps/havs_table_candidates.py`).\n\n"
       << "| data set | size | configuration | CPU table ms | GPU table ms | GPU / CPU | still ms "
          "(CPU, GPU) | edit / still, CPU table | edit / still, GPU table |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& g : gpuRows)
    {
      std::string base;
      if (!StripGPUTable(g.at("config"), base))
      {
        continue;
      }
      for (const Row& c : gpuRows)
      {
        if (c.at("config") != base || c.at("dataset") != g.at("dataset") ||
          (c.count("size") ? c.at("size") : "") != (g.count("size") ? g.at("size") : ""))
        {
          continue;
        }
        char figures[256];
        std::snprintf(figures, sizeof(figures), "%.1f | %.1f | %.1f | %.1f, %.1f | %.2f | %.2f",
          Value(c, "edit_table_ms"), Value(g, "edit_table_ms"),
          Value(g, "edit_table_ms") / Value(c, "edit_table_ms"), Value(c, "still_ms"),
          Value(g, "still_ms"), Value(c, "edit_ms") / Value(c, "still_ms"),
          Value(g, "edit_ms") / Value(g, "still_ms"));
        md << "| " << g.at("dataset") << " | " << (g.count("size") ? g.at("size") : "-") << " | "
           << base.substr(5) << " | " << figures << " |\n";
      }
    }
  }
  return md.str();
}

/// The level of detail's section (issue 18): per data set and size, each
/// strategy's time and error at each fixed share of internal faces beside the
/// full frame (havs-default), and the rotations with a frame budget.
std::string LevelOfDetailReport(const std::vector<Row>& allRows)
{
  std::vector<Row> rows;
  std::copy_if(allRows.begin(), allRows.end(), std::back_inserter(rows), IsLevelOfDetail);
  std::vector<std::pair<std::string, std::string>> groups;
  for (const Row& r : rows)
  {
    const auto group = std::make_pair(r.at("dataset"), SizeOf(r));
    if (IsLevelOfDetail(r) && std::find(groups.begin(), groups.end(), group) == groups.end())
    {
      groups.push_back(group);
    }
  }
  if (groups.empty())
  {
    return std::string();
  }
  std::ostringstream md;
  md << "\n## Dynamic level of detail\n\n"
     << "havs-lod-<strategy>-<percent>: the default settings drawing every boundary face and that "
        "share of the internal faces, ranked by the strategy (vtkHAVSInternalFaceRanking; "
        "topology: layers peeled from the boundary, view: normal clusters facing the view, field: "
        "stratified on the scalar histogram, area: area times a random number, random: the "
        "control), segments from the long-segment table (over the bounding-box diagonal). 100 % "
        "is havs-default. Error against the exact reference as above; ranking: the "
        "preprocessing time and memory of the strategy. havs-lod-rotate-<ms>: the defaults with "
        "that frame budget (vtkHAVSMapperBase::SetLevelOfDetailTargetSeconds) while the camera "
        "turns 3° a frame for 60 frames, then one still frame (the rows below were measured "
        "before the level of detail's reduced image existed: HAVS's face subset alone met the "
        "budget; Frame budgets, further down, has both mechanisms for the three mappers). "
        "These rows come from their own "
        "runs, with the full frame (havs-default) measured beside them: compare their times with "
        "each other, not with the tables above (another day, maybe another machine). Plot: "
        "`benchmark_lod.png` (time and "
        "RMSE against the share of internal faces, per strategy).\n\n"
     << "![level of detail](benchmark_lod.png)\n";
  const char* const strategies[] = { "topology", "view", "field", "area", "random" };
  for (const auto& group : groups)
  {
    const std::string& dataset = group.first;
    auto find = [&](const std::string& config) -> const Row*
    {
      for (const Row& r : rows)
      {
        if (r.at("dataset") == dataset && SizeOf(r) == group.second && r.at("config") == config)
          return &r;
      }
      return nullptr;
    };
    std::vector<int> percents;
    for (const Row& r : rows)
    {
      if (r.at("dataset") != dataset || SizeOf(r) != group.second ||
        r.at("config").rfind("havs-lod-", 0) != 0 ||
        r.at("config").find("rotate") != std::string::npos)
        continue;
      const int p = std::atoi(r.at("config").c_str() + r.at("config").rfind('-') + 1);
      if (std::find(percents.begin(), percents.end(), p) == percents.end())
        percents.push_back(p);
    }
    std::sort(percents.begin(), percents.end());
    const Row* full = find("havs-default");
    md << "\n### " << dataset << " (" << group.second << "²)\n\n";
    if (!percents.empty())
    {
      md << "| strategy |";
      for (int p : percents)
        md << " " << p << " % ms | RMSE |";
      md << " ranking s | ranking MB |\n|---|";
      for (size_t i = 0; i < percents.size(); ++i)
        md << "---|---|";
      md << "---|---|\n";
      std::map<int, std::pair<double, std::string>> best; // percent -> (RMSE, strategy)
      for (const char* strategy : strategies)
      {
        const Row* any = nullptr;
        std::ostringstream line;
        line << "| " << strategy << " |";
        for (int p : percents)
        {
          const Row* r = find(std::string("havs-lod-") + strategy + "-" + std::to_string(p));
          line << " " << (r ? Cell(*r, "ms_median", "%.1f") : "-") << " | "
               << (r ? Cell(*r, "rmse", "%.5f") : "-") << " |";
          if (r)
          {
            any = r;
            const double e = Value(*r, "rmse");
            if (!best.count(p) || e < best[p].first)
              best[p] = std::make_pair(e, std::string(strategy));
          }
        }
        if (!any)
          continue;
        md << line.str() << " " << Cell(*any, "ranking_s", "%.3f") << " | "
           << Cell(*any, "ranking_mb", "%.1f") << " |\n";
      }
      if (full)
      {
        md << "\nEvery face (havs-default): " << Cell(*full, "ms_median", "%.1f") << " ms, RMSE "
           << Cell(*full, "rmse", "%.5f") << ". Lowest error:";
        for (const auto& b : best)
        {
          const Row* r = find("havs-lod-" + b.second.second + "-" + std::to_string(b.first));
          md << " at " << b.first << " % " << b.second.second << " (" << std::setprecision(3)
             << (r ? Value(*r, "ms_median") / Value(*full, "ms_median") : NAN)
             << "× the full frame's time);";
        }
        md << "\n";
      }
    }
    for (const Row& r : rows)
    {
      if (r.at("dataset") != dataset || SizeOf(r) != group.second ||
        r.at("config").rfind("havs-lod-rotate-", 0) != 0)
        continue;
      const double target = Value(r, "lod_target_ms");
      md << "\n"
         << r.at("config") << ": a " << Cell(r, "lod_target_ms", "%.0f")
         << " ms budget while turning; the last 30 of 60 frames took "
         << Cell(r, "ms_median", "%.1f") << " ms (median; min " << Cell(r, "ms_min", "%.1f")
         << ", max " << Cell(r, "ms_max", "%.1f") << "), " << std::setprecision(3)
         << 100.0 * Value(r, "lod_within25") << " % of them within 25 % of the budget ("
         << (std::abs(Value(r, "ms_median") - target) <= 0.25 * target ? "converged"
                                                                       : "not converged")
         << "), drawing a median " << std::setprecision(3) << 100.0 * Value(r, "lod_fraction")
         << " % of the internal faces. The still frame after it drew " << std::setprecision(3)
         << 100.0 * Value(r, "lod_still") << " % of them: " << ErrorText(r)
         << ". Frame times (ms): " << (r.count("lod_trace") ? r.at("lod_trace") : "-") << ".\n";
    }
  }
  return md.str();
}

std::string Report(const std::vector<Row>& allRows, const Options& o, const std::string& command)
{
  // The level of detail's rows have their own section.
  std::vector<Row> rows;
  std::copy_if(allRows.begin(), allRows.end(), std::back_inserter(rows),
    [](const Row& r)
    {
      return !IsLevelOfDetail(r) && !IsEditRun(r) && !IsBudgetRun(r) && !IsIsoRun(r) &&
        !IsTranslucentRun(r);
    });
  std::string renderer = "(unknown)";
  {
    vtkSmartPointer<vtkRenderWindow> window;
    window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow());
    if (window)
    {
      window->Render();
      const std::string caps = window->ReportCapabilities();
      const size_t a = caps.find("OpenGL renderer string:");
      if (a != std::string::npos)
      {
        renderer = caps.substr(a + 24, caps.find('\n', a) - a - 24);
      }
    }
  }
  std::ostringstream md;
  md << "# vtkHAVS benchmark: run time against error\n\n"
     << "Generated by `" << command << "` (not edited by hand)" << MeasuredBy(rows, command)
     << ". GL renderer: " << renderer << "; machine generating this report: " << Machine()
     << "; vtkSMPTools backend of the measured rows: " << SmpBackends(rows) << ".\n\n"
     << "Each configuration ran in its own process over the fixed viewpoints (the 6 axis "
        "directions and the 8 cube diagonals, after two warm-up frames, one for ZSweep and "
        "RayCast, which run on the CPU). Times are ms per frame "
        "with the GPU work finished (median, min, max); HAVS's stages are medians. Rows with "
        "a rounds column above 1 ran that many times, every configuration once a round, "
        "round-robin, each round starting one configuration later (a process's place in the "
        "round changed its time by up to 10 %): their times are the medians over the rounds "
        "(min and max over all). "
        "Error: the "
        "colour seen in the window (8 bits a channel) against the exact reference "
        "(vtkHAVSReferenceRenderer); float RMSE / float max: the project's mappers' float "
        "result (each view drawn once more, untimed), on which MISSION.md defines exact "
        "(RMSE < 5e-4, max < 0.01): the window's rounding to 1/255 alone costs up to "
        "1/255/sqrt(12) = 1.1e-3 RMSE where the volume covers the whole image. "
        "raster-bound draws the same faces in the same order with a trivial shader (the lower "
        "bound of any face-based method here, its centroid sort included); sort-bound is the "
        "centroid sort alone. Every HAVS frame sorts (as when the camera moves). "
        "havs-k6-untagged is k = 6 with boundary tagging off (wrong on non-convex meshes; its "
        "time against havs-k6 is what tagging costs; convex meshes skip tagging anyway). "
        "-mpvo rows draw the faces in the MPVO order (vtkHAVSVisibilityOrder) instead of the "
        "centroid order, made exact across the gaps of a non-convex mesh by the boundary "
        "layers (-mpvo, per frame) or by the convexification (-mpvo-convex, built once per "
        "mesh, before the timed frames); -auto rows use the Automatic order "
        "(centroid until a frame has order violations, that frame again and the later ones "
        "with MPVO). "
        "reference is the exact renderer (vtkHAVSReferenceRenderer, on the CPU) making the "
        "cached reference images in its own process before the timed configurations run; its "
        "time is given only for the views it computed (not those read from the cache). "
        "`× raster bound` and `× HAVS k=6` are time ratios. Stock mappers: PT as VTK makes it; "
        "ZSweep and RayCast with ImageSampleDistance 1, AutoAdjustSampleDistances off and "
        "vtkUnstructuredGridLinearRayIntegrator. gen1M/gen4M/gen10M: tetrahedralized blocks of "
        "60³/94³/127³ cubes (5 tets each) with the field sin(6x) cos(5y) + z. A configuration "
        "whose frames passed the time budget stopped early: its row says how many views it "
        "measured. Absolute times mean something only on a GPU.\n";
  auto sizeOf = [&](const Row& r)
  {
    const auto it = r.find("size");
    return it == r.end() || it->second.empty() ? std::to_string(o.Size) : it->second;
  };
  std::vector<std::pair<std::string, std::string>> groups; // (data set, size)
  for (const Row& r : rows)
  {
    const auto group = std::make_pair(r.at("dataset"), sizeOf(r));
    if (std::find(groups.begin(), groups.end(), group) == groups.end())
    {
      groups.push_back(group);
    }
  }
  for (const auto& group : groups)
  {
    const std::string& dataset = group.first;
    const std::string& size = group.second;
    // The rows of one configuration in this group (data set and size).
    auto rowsOf = [&](const std::string& config)
    {
      std::vector<const Row*> found;
      for (const Row& r : rows)
      {
        if (r.at("dataset") == dataset && sizeOf(r) == size && r.at("config") == config)
          found.push_back(&r);
      }
      return found;
    };
    double bound = NAN, havs6 = NAN;
    std::map<std::string, double> ms;
    std::string tets = "?";
    for (const Row& r : rows)
    {
      if (r.at("dataset") != dataset || sizeOf(r) != size)
        continue;
      ms[r.at("config")] = Value(r, "ms_median");
      tets = r.at("tets");
    }
    bound = ms.count("raster-bound") ? ms["raster-bound"] : NAN;
    havs6 = ms.count("havs-k6") ? ms["havs-k6"] : NAN;
    md << "\n## " << dataset << " (" << tets << " tets, " << size << "²)\n\n"
       << "| configuration | views | ms median | min | max | sort | draw | flush | composite | "
          "Mtets/s | × raster bound | × HAVS k=6 | peak MB | RMSE | max error | px > 1/255 | "
          "float RMSE | float max |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows)
    {
      if (r.at("dataset") != dataset || sizeOf(r) != size)
        continue;
      const double t = Value(r, "ms_median");
      char ratio1[32], ratio2[32];
      std::snprintf(ratio1, sizeof(ratio1), "%.2f", t / bound);
      std::snprintf(ratio2, sizeof(ratio2), "%.2f", t / havs6);
      md << "| " << r.at("config") << " | " << r.at("views") << " | "
         << Cell(r, "ms_median", "%.1f") << " | " << Cell(r, "ms_min", "%.1f") << " | "
         << Cell(r, "ms_max", "%.1f") << " | " << Cell(r, "sort_ms", "%.1f") << " | "
         << Cell(r, "draw_ms", "%.1f") << " | " << Cell(r, "flush_ms", "%.1f") << " | "
         << Cell(r, "composite_ms", "%.1f") << " | " << Cell(r, "mtets_per_s") << " | "
         << (std::isfinite(t / bound) ? ratio1 : "-") << " | "
         << (std::isfinite(t / havs6) ? ratio2 : "-") << " | " << Cell(r, "peak_mb", "%.0f")
         << " | " << Cell(r, "rmse", "%.5f") << " | " << Cell(r, "max", "%.4f") << " | "
         << Cell(r, "over1", "%.4f") << " | " << Cell(r, "float_rmse", "%.5f") << " | "
         << Cell(r, "float_max", "%.4f") << " |\n";
    }
    // The stages of one frame, HAVS's rows (medians of each stage: they need not add up
    // to the median total; "other" is the rest: VTK's render, the window, the clear).
    md << "\nStages (ms, medians; order is the sort or MPVO order without its boundary layers "
          "and gather, which follow; other is the frame's rest: VTK's render pass, the "
          "clear):\n\n"
       << "| configuration | total | order | boundary layers | gather | upload | draw | "
          "resolve | read-backs | composite | other |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows)
    {
      if (r.at("dataset") != dataset || sizeOf(r) != size || !std::isfinite(Value(r, "sort_ms")))
        continue;
      const double total = Value(r, "ms_median");
      const double sortMs = Value(r, "sort_ms");
      const double gatherMs = std::isfinite(Value(r, "gather_ms")) ? Value(r, "gather_ms") : 0.0;
      const double layersMs = std::isfinite(Value(r, "layers_ms")) ? Value(r, "layers_ms") : 0.0;
      double known = sortMs;
      for (const char* stage :
        { "upload_ms", "draw_ms", "flush_ms", "readback_ms", "composite_ms" })
      {
        known += std::isfinite(Value(r, stage)) ? Value(r, stage) : 0.0;
      }
      char order[32], other[32];
      std::snprintf(order, sizeof(order), "%.1f", sortMs - gatherMs - layersMs);
      std::snprintf(other, sizeof(other), "%.1f", total - known);
      md << "| " << r.at("config") << " | " << Cell(r, "ms_median", "%.1f") << " | " << order
         << " | " << Cell(r, "layers_ms", "%.1f") << " | " << Cell(r, "gather_ms", "%.1f") << " | "
         << Cell(r, "upload_ms", "%.1f") << " | " << Cell(r, "draw_ms", "%.1f") << " | "
         << Cell(r, "flush_ms", "%.1f") << " | " << Cell(r, "readback_ms", "%.1f") << " | "
         << Cell(r, "composite_ms", "%.1f") << " | " << other << " |\n";
    }
    // The draw shader feature by feature: each variant of havs-k6 changes one thing.
    if (std::isfinite(havs6))
    {
      std::map<std::string, Row> byConfig;
      for (const Row& r : rows)
      {
        if (r.at("dataset") == dataset && sizeOf(r) == size)
          byConfig[r.at("config")] = r;
      }
      const Row& base = byConfig["havs-k6"];
      const char* const variants[][2] = { { "havs-k6-count", "the order-violation counter on" },
        { "havs-k6-untagged", "boundary tagging off" },
        { "havs-k6-noterm", "early ray termination off" },
        { "havs-k6-opaque", "an opaque actor in the scene (the depth cut)" },
        { "havs-k6-table64", "a 64³ table instead of 128³" },
        { "havs-k6-table256", "a 256³ table instead of 128³" },
        { "havs-k6-auto", "the Automatic order" }, { "havs-k6-mpvo", "the MPVO order" } };
      bool header = false;
      for (const auto& v : variants)
      {
        if (!byConfig.count(v[0]))
          continue;
        if (!header)
        {
          md << "\nFeatures, one at a time against havs-k6 (" << Cell(base, "ms_median", "%.1f")
             << " ms, draw " << Cell(base, "draw_ms", "%.1f") << " ms):\n\n"
             << "| configuration | what changes | total | Δ total | draw | Δ draw | RMSE |\n"
             << "|---|---|---|---|---|---|---|\n";
          header = true;
        }
        const Row& r = byConfig[v[0]];
        char dt[32], dd[32];
        std::snprintf(dt, sizeof(dt), "%+.1f", Value(r, "ms_median") - havs6);
        std::snprintf(dd, sizeof(dd), "%+.1f", Value(r, "draw_ms") - Value(base, "draw_ms"));
        md << "| " << v[0] << " | " << v[1] << " | " << Cell(r, "ms_median", "%.1f") << " | " << dt
           << " | " << Cell(r, "draw_ms", "%.1f") << " | " << dd << " | " << Cell(r, "rmse", "%.5f")
           << " |\n";
      }
    }
    // The measures of the default settings.
    if (ms.count("havs-default"))
    {
      Row def;
      for (const Row* r : rowsOf("havs-default"))
      {
        def = *r;
      }
      const double t = ms["havs-default"];
      md << "\nDefault settings (havs-default): " << Cell(def, "ms_median", "%.1f") << " ms, "
         << ErrorText(def);
      if (def.count("table") && !def.at("table").empty() && def.at("table") != "-")
      {
        md << "; table " << def.at("table") << " (resolution:measured error, chosen automatically)";
      }
      if (ms.count("havs-default-table128"))
      {
        for (const Row* r : rowsOf("havs-default-table128"))
        {
          md << "; with the fixed 128³ table instead: " << Cell(*r, "ms_median", "%.1f")
             << " ms (draw " << Cell(*r, "draw_ms", "%.1f") << ", automatic draw "
             << Cell(def, "draw_ms", "%.1f") << "), RMSE " << Cell(*r, "rmse", "%.5f") << ", max "
             << Cell(*r, "max", "%.4f");
        }
      }
      if (def.count("skipped") && !def.at("skipped").empty() && def.at("skipped") != "-1")
      {
        md << "; " << def.at("skipped") << " invisible tetrahedra skipped";
      }
      for (const Row* r : rowsOf("havs-default-noskip"))
      {
        md << "; with every cell drawn (havs-default-noskip): " << Cell(*r, "ms_median", "%.1f")
           << " ms (draw " << Cell(*r, "draw_ms", "%.1f") << "), so skipping takes "
           << std::setprecision(3) << t / Value(*r, "ms_median") << "× its time";
      }
      if (def.count("culled") && !def.at("culled").empty() && def.at("culled") != "0" &&
        def.at("culled") != "-1")
      {
        md << "; " << def.at("culled")
           << " tetrahedra off-screen in the last view (culled: not ordered, not drawn)";
      }
      for (const Row* r : rowsOf("havs-default-nocull"))
      {
        md << "; with every cell ordered and drawn (havs-default-nocull): "
           << Cell(*r, "ms_median", "%.1f") << " ms (sort " << Cell(*r, "sort_ms", "%.1f")
           << ", draw " << Cell(*r, "draw_ms", "%.1f") << "; default sort "
           << Cell(def, "sort_ms", "%.1f") << "), so culling takes " << std::setprecision(3)
           << t / Value(*r, "ms_median") << "× its time";
      }
      for (const Row* r : rowsOf("havs-default-sat"))
      {
        md << "; with saturated pixels rejected before the shader on this path too "
              "(havs-default-sat): "
           << Cell(*r, "ms_median", "%.1f") << " ms (draw " << Cell(*r, "draw_ms", "%.1f") << "), "
           << std::setprecision(3) << Value(*r, "ms_median") / t << "× the default's time";
      }
      if (ms.count("raster-bound"))
      {
        md << "; " << std::setprecision(3) << t / ms["raster-bound"] << "× raster-bound";
      }
      if (ms.count("pt"))
      {
        for (const Row* r : rowsOf("pt"))
        {
          md << "; " << std::setprecision(3) << t / ms["pt"] << "× the time of PT (RMSE "
             << Cell(*r, "rmse", "%.5f") << ")";
        }
      }
      // Issue 16: the exact default costs at most 5 % more than the centroid
      // order where that order is already exact. The fastest centroid row
      // (havs-kN with nothing else on: no order, counter, opaque actor or
      // tagging change) whose float result is exact.
      const Row* centroid = nullptr;
      for (const auto& entry : ms)
      {
        const std::string& name = entry.first;
        const bool plain =
          name.rfind("havs-k", 0) == 0 && name.find_first_of('-', 6) == std::string::npos;
        for (const Row* r : plain ? rowsOf(name) : std::vector<const Row*>())
        {
          const double e = Value(*r, "float_rmse"), m = Value(*r, "float_max");
          if (std::isfinite(e) && IsExact(e, m) &&
            (!centroid || Value(*r, "ms_median") < Value(*centroid, "ms_median")))
          {
            centroid = r;
          }
        }
      }
      if (centroid)
      {
        md << "; the centroid order is exact here at " << centroid->at("config") << " ("
           << Cell(*centroid, "ms_median", "%.1f") << " ms, float RMSE "
           << Cell(*centroid, "float_rmse", "%.5f") << ", max "
           << Cell(*centroid, "float_max", "%.4f") << "): the defaults take "
           << std::setprecision(3) << t / Value(*centroid, "ms_median") << "× its time";
      }
      else
      {
        md << "; the centroid order is exact at none of the measured k here";
      }
      md << ".\n";
    }
    if (ms.count("cellproj"))
    {
      // vtkHAVSCellProjectionMapper against HAVS's defaults and PT (issue 22).
      for (const Row* row : rowsOf("cellproj"))
      {
        const Row& r = *row;
        md << "\nCell projection (cellproj, the exact MPVO cell order): "
           << Cell(r, "ms_median", "%.1f") << " ms (order " << Cell(r, "sort_ms", "%.1f")
           << ", draw " << Cell(r, "draw_ms", "%.1f") << "), " << ErrorText(r);
        for (const char* other : { "havs-default", "pt", "raster-bound" })
        {
          if (ms.count(other))
          {
            md << "; " << std::setprecision(3) << ms["cellproj"] / ms[other] << "× " << other;
          }
        }
        md << ".\n";
      }
    }
    if (ms.count("tetraycast"))
    {
      // vtkHAVSRayCastMapper against HAVS's defaults, the cell projection and PT (issue 21).
      for (const Row* row : rowsOf("tetraycast"))
      {
        const Row& r = *row;
        md << "\nGPU ray casting (tetraycast, re-entries by depth peeling): "
           << Cell(r, "ms_median", "%.1f") << " ms (draw " << Cell(r, "draw_ms", "%.1f");
        if (std::isfinite(Value(r, "peel_ms")) && std::isfinite(Value(r, "cast_ms")))
        {
          md << ": peeling " << Cell(r, "peel_ms", "%.1f") << ", casting "
             << Cell(r, "cast_ms", "%.1f") << ", GPU timestamps";
        }
        md << "), " << ErrorText(r) << "; per view (medians) " << Cell(r, "peel_passes", "%.0f")
           << " peeling passes, " << Cell(r, "cells_per_ray", "%.1f")
           << " cells crossed per ray, rays in " << Cell(r, "tiles_used", "%.2f")
           << " of the screen tiles with " << Cell(r, "tile_passes", "%.2f")
           << " passes each on average";
        for (const char* other : { "havs-default", "cellproj", "pt", "raster-bound" })
        {
          if (ms.count(other))
          {
            md << "; " << std::setprecision(3) << ms["tetraycast"] / ms[other] << "× " << other;
          }
        }
        md << ".";
        // Which wins, and why: per covered pixel HAVS shades about one
        // fragment per face its ray crosses, about one per cell crossed (the
        // cells a ray crosses, plus one per entry); the ray caster takes one
        // walk step per cell crossed, plus one peeled boundary fragment per
        // entry. The raster bound is what HAVS's fragments cost with nothing
        // done in them.
        if (ms.count("havs-default") && ms.count("raster-bound"))
        {
          const double versusHAVS = ms["tetraycast"] / ms["havs-default"];
          const double versusRaster = ms["tetraycast"] / ms["raster-bound"];
          md << " " << (versusHAVS < 1.0 ? "The ray caster wins here" : "HAVS wins here")
             << ": both do about one unit of work per cell a ray crosses ("
             << Cell(r, "cells_per_ray", "%.1f")
             << " on average), HAVS a rasterized fragment with a k-buffer insertion, the ray "
                "caster a walk step (four plane tests, a neighbour, a table look-up) in "
                "registers; the walk "
             << (versusRaster < 1.0 ? "costs less than a fragment that does nothing (the ray "
                                      "caster takes "
                                    : "costs more than a fragment that does nothing (the ray "
                                      "caster takes ")
             << std::setprecision(3) << versusRaster
             << "× the raster bound, the time HAVS's faces take to rasterize with a trivial "
                "shader)";
          if (Value(r, "peel_passes") > 1.0)
          {
            md << ", and its " << Cell(r, "peel_passes", "%.0f")
               << " peeling passes each rasterize the boundary again";
          }
          md << ".";
        }
        md << "\n";
      }
    }
    if (std::isfinite(havs6) &&
      (ms.count("pt") || ms.count("zsweep") || ms.count("raycast") || ms.count("raster-bound")))
    {
      md << "\nHAVS k=6 takes";
      for (const char* other : { "pt", "zsweep", "raycast", "raster-bound" })
      {
        if (ms.count(other))
        {
          md << " " << std::setprecision(3) << havs6 / ms[other] << "× the time of " << other
             << ";";
        }
      }
      md << "\n";
    }
  }
  md << LevelOfDetailReport(allRows);
  md << BudgetReport(allRows);
  md << EditReport(allRows);
  md << IsoReport(allRows);
  md << TranslucentReport(allRows);
  md << "\nCSV: `benchmark.csv`. Plots: `benchmark_time_error.png` (time against RMSE, one "
        "panel per data set, Pareto front dashed, the face-raster bound as a line), "
        "`benchmark_stages.png` (HAVS's stages, stacked), `benchmark_time_tets.png` (time "
        "against the number of tets), `benchmark_time_pixels.png` (time against the number of "
        "pixels).\n\n"
     << "![time against error](benchmark_time_error.png)\n\n"
     << "![stages](benchmark_stages.png)\n\n"
     << "![time against tets](benchmark_time_tets.png)\n\n"
     << "![time against pixels](benchmark_time_pixels.png)\n";
  return md.str();
}
}

int main(int argc, char* argv[])
{
  Options o;
  o.Self = argv[0];
  std::string datasets, configs, fromCsv;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--quick")
      o.Quick = true;
    else if (a == "--worker")
      o.Worker = true;
    else if (a == "--size")
      o.Size = std::max(16, std::atoi(next().c_str()));
    else if (a == "--sizes")
    {
      for (const std::string& v : havsapp::SplitList(next()))
      {
        o.Sizes.push_back(std::max(16, std::atoi(v.c_str())));
      }
    }
    else if (a == "--views")
      o.Views = std::min(14, std::max(1, std::atoi(next().c_str())));
    else if (a == "--repeats")
      o.Repeats = std::max(1, std::atoi(next().c_str()));
    else if (a == "--rounds")
      o.Rounds = std::max(1, std::atoi(next().c_str()));
    else if (a == "--budget")
      o.Budget = std::atof(next().c_str());
    else if (a == "--datasets")
      datasets = next();
    else if (a == "--configs")
      configs = next();
    else if (a == "--output-dir")
      o.OutputDir = next();
    else if (a == "--cache-dir")
      o.CacheDir = next();
    else if (a == "--from-csv")
      fromCsv = next();
    else if (a == "--dump-case")
      o.DumpCase = next();
    else if (a == "--dump-kinds")
      o.DumpKinds = havsapp::SplitList(next());
    else
    {
      std::cout
        << "usage: havs_benchmark [--quick] [--size N | --sizes a,b] [--views N] [--repeats N] "
           "[--datasets a,b] [--configs a,b] [--output-dir DIR] [--cache-dir DIR] "
           "[--budget SECONDS] [--from-csv FILE] [--dump-case DIR [--dump-kinds a,b]] "
           "[--rounds N]\n";
      return a == "--help" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }
  if (o.Quick)
  {
    // A small subset; explicit --size, --views, --repeats, --budget win.
    bool set[4] = { false, false, false, false };
    for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      set[0] = set[0] || a == "--size";
      set[1] = set[1] || a == "--views";
      set[2] = set[2] || a == "--repeats";
      set[3] = set[3] || a == "--budget";
    }
    o.Size = set[0] ? o.Size : 256;
    o.Views = set[1] ? o.Views : 2;
    o.Repeats = set[2] ? o.Repeats : 1;
    o.Budget = set[3] ? o.Budget : 60;
  }
  o.DataSets = havsapp::SplitList(!datasets.empty()
      ? datasets
      : (o.Quick ? "loxpostvtk,bluntfin"
                 : "loxpostvtk,bluntfin,combustor,loxpost,gen1M,gen4M,gen10M"));
  o.Configs = havsapp::SplitList(!configs.empty()
      ? configs
      : (o.Quick ? "havs-default,havs-k2,havs-k6,havs-k14,raster-bound,sort-bound,pt,raycast"
                 : "havs-default,havs-k1,havs-k2,havs-k4,havs-k6,havs-k8,havs-k14,havs-k14-table32,"
                   "havs-k14-table64,havs-k6-count,havs-k6-untagged,havs-k6-noterm,havs-k6-opaque,"
                   "havs-k6-table64,havs-k6-table256,havs-k6-auto,havs-k6-mpvo,"
                   "havs-k1-mpvo,havs-k2-mpvo,havs-k2-mpvo-convex,havs-k2-auto,havs-lists,"
                   "cellproj,tetraycast,raster-bound,sort-bound,pt,"
                   "zsweep,raycast"));
  if (o.Worker)
  {
    return RunWorker(o);
  }
  if (!o.DumpCase.empty())
  {
    return DumpCases(o);
  }

  std::ostringstream commandLine;
  commandLine << "build/bin/havs_benchmark";
  for (int i = 1; i < argc; ++i)
  {
    commandLine << " " << argv[i];
  }
  const std::string command = commandLine.str();

  // Coordinator: every (data set, configuration) in a child process, unless
  // the report is only made again from an earlier run's CSV.
  std::system(("mkdir -p '" + o.OutputDir + "' '" + o.CacheDir + "'").c_str());
  const std::string csvPath = o.OutputDir + "/benchmark.csv";
  std::vector<Row> rows;
  if (!fromCsv.empty())
  {
    for (const std::string& file : havsapp::SplitList(fromCsv))
    {
      std::vector<Row> more = ReadCsv(file);
      for (Row& r : more)
      {
        if (r["size"].empty())
        {
          r["size"] = std::to_string(o.Size);
        }
      }
      rows.insert(rows.end(), more.begin(), more.end());
    }
  }
  else
  {
    if (o.Sizes.empty())
    {
      o.Sizes.push_back(o.Size);
    }
    for (const std::string& dataset : o.DataSets)
    {
      for (int size : o.Sizes)
      {
        // The exact reference first, in its own process, for every view.
        std::vector<std::string> configs = o.Configs;
        configs.erase(std::remove(configs.begin(), configs.end(), "reference"), configs.end());
        configs.insert(configs.begin(), "reference");
        // Each round runs every configuration once (the reference only in
        // the first); the rows are merged over the rounds (MergeRounds).
        const size_t first = rows.size();
        std::map<std::string, std::vector<Row>> rounds;
        for (int round = 0; round < o.Rounds; ++round)
        {
          // Each round starts one configuration later (the reference aside):
          // a process's place in the round (the first after another data set
          // or the reference ran measurably slower, up to 10 %) is spread
          // over the configurations alike.
          std::vector<std::string> order(configs.begin() + 1, configs.end());
          if (!order.empty())
          {
            std::rotate(order.begin(), order.begin() + round % order.size(), order.end());
          }
          if (round == 0)
          {
            order.insert(order.begin(), configs.front());
          }
          for (const std::string& config : order)
          {
            std::ostringstream cmd;
            cmd << "'" << o.Self << "' --worker --datasets " << dataset << " --configs " << config
                << " --size " << size << " --views " << o.Views << " --repeats " << o.Repeats
                << " --budget " << o.Budget << " --cache-dir '" << o.CacheDir << "' 2>/dev/null";
            std::cerr << "havs_benchmark: " << dataset << " / " << config;
            if (o.Rounds > 1)
            {
              std::cerr << " (round " << round + 1 << " of " << o.Rounds << ")";
            }
            std::cerr << std::endl;
            Row r = RunChild(cmd.str());
            if (r.empty())
            {
              std::cerr << "havs_benchmark: " << dataset << " / " << config << " failed"
                        << std::endl;
              continue;
            }
            r["command"] = command;
            rounds[config].push_back(r);
            // After every row: a long run keeps what it measured.
            rows.resize(first);
            for (const std::string& c : configs)
            {
              if (rounds.count(c))
              {
                Row m = MergeRounds(rounds[c]);
                const double ms = std::atof(m["ms_median"].c_str());
                m["mtets_per_s"] =
                  std::to_string(ms > 0 ? std::atof(m["tets"].c_str()) / (ms * 1000.0) : NAN);
                rows.push_back(m);
              }
            }
            WriteCsv(rows, csvPath);
          }
        }
      }
    }
  }
  WriteCsv(rows, csvPath);
  const std::string report = Report(rows, o, command);
  std::ofstream(o.OutputDir + "/benchmarks.md") << report;
  std::cout << report;
  // Plots, where matplotlib is there.
  // The plot script: the source tree's (HAVS_SOURCE_DIR), else the installed
  // one beside this program (<prefix>/share/vtkHAVS).
  const char* source = std::getenv("HAVS_SOURCE_DIR");
  std::string script = std::string(source ? source : ".") + "/Apps/havs_benchmark_plots.py";
  if (!source)
  {
    const std::string self = o.Self;
    const std::string installed =
      self.substr(0, self.find_last_of('/') + 1) + "../share/vtkHAVS/havs_benchmark_plots.py";
    if (std::ifstream(installed).good())
    {
      script = installed;
    }
  }
  std::system(
    ("/usr/bin/python3 '" + script + "' '" + csvPath + "' '" + o.OutputDir + "'").c_str());
  return EXIT_SUCCESS;
}
