/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTestUtilities.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSTestUtilities.h"

#include <cstdlib>
#include "vtkNew.h"

namespace havstest
{
namespace
{
std::string EnvOr(const char* name, const char* fallback)
{
  const char* v = std::getenv(name);
  return (v && *v) ? std::string(v) : std::string(fallback);
}
}

std::string DataDir()
{
  return EnvOr("HAVS_DATA_DIR", "../shared/data");
}

std::string OutputDir()
{
  return EnvOr("HAVS_TEST_OUTPUT_DIR", ".");
}

std::string BaselineDir()
{
  return EnvOr("HAVS_BASELINE_DIR", "Testing/Baseline");
}

int& Failures()
{
  static int failures = 0;
  return failures;
}

bool Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    ++Failures();
    std::cerr << "CHECK FAILED: " << what << std::endl;
  }
  return condition;
}

bool CheckNear(double a, double b, double tol, const std::string& what)
{
  const bool ok = std::isfinite(a) && std::isfinite(b) && std::fabs(a - b) <= tol;
  if (!ok)
  {
    ++Failures();
    std::cerr << "CHECK FAILED: " << what << ": " << a << " vs " << b << " (tol " << tol << ")"
              << std::endl;
  }
  return ok;
}
}

#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

namespace havstest
{
vtkSmartPointer<vtkUnstructuredGrid> MakeBox(int nx, int ny, int nz, double h, double a, double b)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx + 1, ny + 1, nz + 1);
  image->SetSpacing(h, h, h);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  s->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    s->SetValue(i, a + b * x[2]);
  }
  image->GetPointData()->SetScalars(s);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(image);
  tets->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = tets->GetOutput();
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> ReadPlot3D(
  const std::string& xyz, const std::string& q, int scalarFunction)
{
  vtkNew<vtkMultiBlockPLOT3DReader> reader;
  reader->SetXYZFileName((DataDir() + "/" + xyz).c_str());
  reader->SetQFileName((DataDir() + "/" + q).c_str());
  reader->AutoDetectFormatOn();
  reader->SetScalarFunctionNumber(scalarFunction);
  reader->Update();
  vtkDataSet* block = vtkDataSet::SafeDownCast(reader->GetOutput()->GetBlock(0));
  if (!block)
  {
    return nullptr;
  }
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(block);
  tets->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = tets->GetOutput();
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> ReadDataSet(const std::string& name)
{
  if (name == "bluntfin")
  {
    return ReadPlot3D("bluntfinxyz.bin", "bluntfinq.bin", 100);
  }
  if (name == "loxpost")
  {
    return ReadPlot3D("postxyz.bin", "postq.bin", 110);
  }
  if (name == "combustor")
  {
    return ReadPlot3D("combxyz.bin", "combq.bin", 100);
  }
  return ReadLoxPostVtk();
}

vtkSmartPointer<vtkUnstructuredGrid> ReadLoxPostVtk()
{
  vtkNew<vtkUnstructuredGridReader> reader;
  reader->SetFileName((DataDir() + "/post.vtk").c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (!grid || grid->GetNumberOfCells() == 0 || !grid->GetPointData()->GetArray("Pressure"))
  {
    std::cerr << "cannot read " << DataDir() << "/post.vtk" << std::endl;
    return nullptr;
  }
  grid->GetPointData()->SetActiveScalars("Pressure");
  return grid;
}

vtkSmartPointer<vtkVolumeProperty> MakeConstantProperty(
  double r, double g, double b, double opacity, double unitDistance)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(-1e6, r, g, b);
  color->AddRGBPoint(1e6, r, g, b);
  vtkNew<vtkPiecewiseFunction> alpha;
  alpha->AddPoint(-1e6, opacity);
  alpha->AddPoint(1e6, opacity);
  property->SetColor(color);
  property->SetScalarOpacity(alpha);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  return property;
}

vtkSmartPointer<vtkVolumeProperty> MakeRampProperty(
  double lo, double hi, double maxOpacity, double unitDistance)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  // Every opacity node is a colour node too, so that VTK's linear ray
  // integrator (which splits segments at colour nodes and only at the first
  // opacity node) integrates this property exactly.
  color->AddRGBPoint(lo, 0.1, 0.2, 1.0);
  color->AddRGBPoint(lo + 0.3 * (hi - lo), 0.16, 0.68, 0.58);
  color->AddRGBPoint(lo + 0.5 * (hi - lo), 0.2, 1.0, 0.3);
  color->AddRGBPoint(hi, 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> alpha;
  alpha->AddPoint(lo, 0.0);
  alpha->AddPoint(lo + 0.3 * (hi - lo), 0.3 * maxOpacity);
  alpha->AddPoint(hi, maxOpacity);
  property->SetColor(color);
  property->SetScalarOpacity(alpha);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  return property;
}

vtkSmartPointer<vtkVolumeProperty> MakeRampPropertyFor(vtkUnstructuredGrid* grid)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  return MakeRampProperty(range[0], range[1], 0.8, grid->GetLength() / 8.0);
}

vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height)
{
  vtkSmartPointer<vtkRenderWindow> window;
  window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow());
  if (window)
  {
    window->SetSize(width, height);
    window->SetMultiSamples(0);
  }
  return window;
}

std::vector<float> ReadRGBA(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkFloatArray> data;
  window->GetRGBAPixelData(0, 0, size[0] - 1, size[1] - 1, 0, data);
  std::vector<float> out(data->GetPointer(0), data->GetPointer(0) + 4 * size[0] * size[1]);
  return out;
}

ImageDifference Compare(const std::vector<float>& a, const std::vector<float>& b, size_t ignoreWorst)
{
  ImageDifference d;
  if (a.size() != b.size() || a.empty())
  {
    d.RMSE = d.Max = d.FractionOver1 = 1e30;
    return d;
  }
  const size_t pixels = a.size() / 4;
  std::vector<double> squares(pixels, 0.0), worst(pixels, 0.0);
  for (size_t p = 0; p < pixels; ++p)
  {
    for (int c = 0; c < 4; ++c)
    {
      const double e = std::fabs(double(a[4 * p + c]) - double(b[4 * p + c]));
      const double err = std::isfinite(e) ? e : 1.0;
      squares[p] += err * err;
      worst[p] = std::max(worst[p], err);
    }
  }
  // The ignoreWorst pixels with the largest error are left out.
  std::vector<uint8_t> kept(pixels, 1);
  if (ignoreWorst > 0)
  {
    std::vector<size_t> byError(pixels);
    for (size_t p = 0; p < pixels; ++p)
    {
      byError[p] = p;
    }
    const size_t n = std::min(ignoreWorst, pixels);
    std::partial_sort(byError.begin(), byError.begin() + n, byError.end(),
      [&](size_t x, size_t y) { return worst[x] > worst[y]; });
    for (size_t i = 0; i < n; ++i)
    {
      kept[byError[i]] = 0;
    }
  }
  double sum = 0;
  size_t over = 0, count = 0;
  for (size_t p = 0; p < pixels; ++p)
  {
    if (kept[p])
    {
      sum += squares[p];
      d.Max = std::max(d.Max, worst[p]);
      over += worst[p] > 1.0 / 255.0 ? 1 : 0;
      ++count;
    }
  }
  d.RMSE = std::sqrt(sum / std::max<size_t>(4 * count, 1));
  d.FractionOver1 = double(over) / double(std::max<size_t>(count, 1));
  return d;
}

void WritePNG(const std::vector<float>& rgba, int width, int height, const std::string& name)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < rgba.size(); ++i)
  {
    const float v = std::isfinite(rgba[i]) ? std::min(std::max(rgba[i], 0.0f), 1.0f) : 0.0f;
    out[i] = static_cast<unsigned char>(v * 255.0f + 0.5f);
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName((OutputDir() + "/" + name).c_str());
  writer->Write();
}

void WriteRGB(vtkUnsignedCharArray* rgb, int width, int height, const std::string& name)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->GetPointData()->SetScalars(rgb);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName((OutputDir() + "/" + name).c_str());
  writer->Write();
}

std::vector<float> ReadPNG(const std::string& path, int* width, int* height)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return {};
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  *width = dims[0];
  *height = dims[1];
  const int nc = image->GetNumberOfScalarComponents();
  std::vector<float> out(static_cast<size_t>(dims[0]) * dims[1] * 4, 1.0f);
  auto* in = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t p = 0; p < static_cast<size_t>(dims[0]) * dims[1]; ++p)
  {
    for (int c = 0; c < std::min(nc, 4); ++c)
    {
      out[4 * p + c] = in[nc * p + c] / 255.0f;
    }
  }
  return out;
}
}

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <map>
#include <memory>

namespace havstest
{
VolumeScene MakeScene(vtkUnstructuredGrid* grid, vtkAbstractVolumeMapper* mapper,
  vtkVolumeProperty* property, int width, int height)
{
  VolumeScene scene;
  scene.Window = MakeWindow(width, height);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Window->AddRenderer(scene.Renderer);
  mapper->SetInputDataObject(grid);
  scene.Volume = vtkSmartPointer<vtkVolume>::New();
  scene.Volume->SetMapper(mapper);
  scene.Volume->SetProperty(property);
  scene.Renderer->AddVolume(scene.Volume);
  return scene;
}

void PlaceCamera(vtkRenderer* renderer, double azimuth, double elevation, bool parallel)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetParallelProjection(parallel ? 1 : 0);
  renderer->ResetCamera();
  camera->Azimuth(azimuth);
  camera->Elevation(elevation);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera();
  renderer->ResetCameraClippingRange();
}

std::vector<float> FloatResult(vtkHAVSVolumeMapper* mapper)
{
  vtkNew<vtkFloatArray> result;
  int size[2] = { 0, 0 };
  if (!mapper->GetFloatResult(result, size))
  {
    return {};
  }
  return std::vector<float>(
    result->GetPointer(0), result->GetPointer(0) + 4 * size[0] * size[1]);
}

namespace
{
std::map<vtkObject*, std::unique_ptr<Messages>>& MessageStore()
{
  static std::map<vtkObject*, std::unique_ptr<Messages>> store;
  return store;
}

void OnMessage(vtkObject* caller, unsigned long event, void*, void* callData)
{
  Messages* m = MessageStore()[caller].get();
  if (event == vtkCommand::ErrorEvent)
  {
    ++m->Errors;
  }
  else
  {
    ++m->Warnings;
  }
  if (callData)
  {
    m->Text += static_cast<const char*>(callData);
    m->Text += "\n";
  }
}
}

Messages* CountMessages(vtkObject* object)
{
  auto& slot = MessageStore()[object];
  slot.reset(new Messages);
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(OnMessage);
  object->AddObserver(vtkCommand::ErrorEvent, callback);
  object->AddObserver(vtkCommand::WarningEvent, callback);
  return slot.get();
}

bool AllFinite(const std::vector<float>& values)
{
  for (float v : values)
  {
    if (!std::isfinite(v))
    {
      return false;
    }
  }
  return true;
}
}

// Non-convex meshes shared by the boundary and visibility-order tests.
#include "vtkAppendFilter.h"
#include "vtkCell.h"
#include "vtkExtractCells.h"
#include "vtkIdList.h"
#include "vtkRTAnalyticSource.h"
#include "vtkThreshold.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"

#include <functional>

namespace havstest
{
/// The cells of `grid` whose centroid satisfies `keep`.
vtkSmartPointer<vtkUnstructuredGrid> KeepCells(
  vtkUnstructuredGrid* grid, const std::function<bool(const double*)>& keep)
{
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdList* points = grid->GetCell(c)->GetPointIds();
    double centroid[3] = { 0, 0, 0 };
    for (vtkIdType i = 0; i < points->GetNumberOfIds(); ++i)
    {
      double x[3];
      grid->GetPoint(points->GetId(i), x);
      for (int k = 0; k < 3; ++k)
      {
        centroid[k] += x[k] / points->GetNumberOfIds();
      }
    }
    if (keep(centroid))
    {
      ids->InsertNextId(c);
    }
  }
  vtkNew<vtkExtractCells> extract;
  extract->SetInputData(grid);
  extract->SetCellList(ids);
  extract->Update();
  return extract->GetOutput();
}

vtkSmartPointer<vtkUnstructuredGrid> ThresholdedWavelet()
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-8, 8, -8, 8, -8, 8);
  vtkNew<vtkThreshold> threshold;
  threshold->SetInputConnection(wavelet->GetOutputPort());
  threshold->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "RTData");
  threshold->SetLowerThreshold(160.0);
  threshold->SetUpperThreshold(1000.0);
  threshold->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(threshold->GetOutputPort());
  tets->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = tets->GetOutput();
  grid->GetPointData()->SetActiveScalars("RTData");
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> HollowSphere()
{
  auto box = havstest::MakeBox(16, 16, 16, 1.0 / 16, 0.0, 1.0);
  return KeepCells(box, [](const double* c) {
    const double r = std::sqrt((c[0] - 0.5) * (c[0] - 0.5) + (c[1] - 0.5) * (c[1] - 0.5) +
      (c[2] - 0.5) * (c[2] - 0.5));
    return r > 0.22 && r < 0.48;
  });
}

vtkSmartPointer<vtkUnstructuredGrid> Torus()
{
  auto box = havstest::MakeBox(24, 24, 12, 1.0 / 24, 0.0, 2.0);
  return KeepCells(box, [](const double* c) {
    const double ring = std::sqrt((c[0] - 0.5) * (c[0] - 0.5) + (c[1] - 0.5) * (c[1] - 0.5));
    return (ring - 0.32) * (ring - 0.32) + (c[2] - 0.25) * (c[2] - 0.25) < 0.13 * 0.13;
  });
}

/// Two 1 x 1 x 1 blocks of 6^3 cubes (longest edge 0.29) with a gap of 0.08
/// between them along x.
vtkSmartPointer<vtkUnstructuredGrid> TwoBlocks()
{
  auto a = havstest::MakeBox(6, 6, 6, 1.0 / 6, 0.0, 1.0);
  auto b = havstest::MakeBox(6, 6, 6, 1.0 / 6, 0.0, 1.0);
  vtkNew<vtkTransform> shift;
  shift->Translate(1.08, 0.0, 0.0);
  vtkNew<vtkTransformFilter> moved;
  moved->SetInputData(b);
  moved->SetTransform(shift);
  vtkNew<vtkAppendFilter> both;
  both->AddInputData(a);
  both->AddInputConnection(moved->GetOutputPort());
  both->MergePointsOff();
  both->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = both->GetOutput();
  grid->GetPointData()->SetActiveScalars("s");
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> LoadMesh(const std::string& name)
{
  if (name == "wavelet")
    return ThresholdedWavelet();
  if (name == "hollowsphere")
    return HollowSphere();
  if (name == "torus")
    return Torus();
  if (name == "twoblocks")
    return TwoBlocks();
  return ReadDataSet(name);
}
}
