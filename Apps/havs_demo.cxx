// havs_demo: what HAVS is for, on a real CFD grid. By default it renders the
// NASA blunt fin (PLOT3D bluntfinxyz.bin + bluntfinq.bin, Density, 187,395
// tetrahedra) with the project's three mappers -- vtkHAVSVolumeMapper at its
// exact order (MPVO with the boundary layers across the mesh's gaps, k = 2),
// vtkHAVSRayCastMapper and vtkHAVSCellProjectionMapper -- and with VTK's
// vtkProjectedTetrahedraMapper, vtkUnstructuredGridVolumeZSweepMapper and
// vtkUnstructuredGridVolumeRayCastMapper (ImageSampleDistance 1,
// AutoAdjustSampleDistances off, vtkUnstructuredGridLinearRayIntegrator) swapped
// into the same scene: same transfer function, camera and window size.
//
// Every mapper renders a first frame (not timed: faces, tables, shaders), then
// orbits the camera (--frames views; ZSweep and RayCast, which run on the CPU,
// only the first --slow-frames of them). The first frame is measured against
// the exact image of vtkHAVSReferenceRenderer (double-precision ray/face
// intersections, each segment integrated to 1e-6) on the colour seen in the
// window (the volume over the black background), with vtkHAVSImageMetrics.
//
// Output: a Markdown table on stdout (median ms per frame, HAVS's stage times,
// Mtets/s, RMSE, max error, share of pixels off by more than 1/255, time
// relative to HAVS) and one PNG: the exact reference and the six mappers'
// first frames in a row, each labelled with its time and error, and under each
// mapper its error against the exact image in false colour, amplified.
//
// Data: --dataset bluntfin|loxpost|combustor|loxpostvtk from $HAVS_DATA_DIR, or
// --data-dir, or <source dir>/../shared/data; or any --input .vtu/.vtk or
// --plot3d pair. Exits non-zero when a file cannot be read, a mapper reports
// an error or the reference fails.
#include "havsAppOptions.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSImageMetrics.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkFloatArray.h"
#include "vtkFreeTypeTools.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTextProperty.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h> // isatty

#ifndef HAVS_SOURCE_DIR
#define HAVS_SOURCE_DIR "."
#endif

namespace
{
//------------------------------------------------------------------------------
// Options
//------------------------------------------------------------------------------
struct Options
{
  std::string DataSet = "bluntfin";
  std::string DataDir;
  std::string Input;
  std::string Plot3DXYZ, Plot3DQ;
  int Plot3DFunction = 100;
  std::string Array;
  int Frames = 8;
  int SlowFrames = 2;
  int Width = 384, Height = 256;
  int K = 2;
  int Table = 256; // pre-integration table resolution (scalar and length axes)
  std::string Order = "mpvo";
  double Amplification = 16.0;
  std::vector<std::string> Mappers = { "havs", "tetraycast", "cellproj", "pt", "zsweep",
    "raycast" };
  std::string Output = "havs_demo.png";
};

void PrintUsage()
{
  std::cout
    << "usage: havs_demo [--dataset bluntfin|loxpost|combustor|loxpostvtk] [--data-dir DIR]\n"
       "                 [--input mesh.vtu|mesh.vtk] [--plot3d xyz.bin q.bin [function]]\n"
       "                 [--array name] [--frames N] [--slow-frames N] [--size W H] [--k K]\n"
       "                 [--table N]\n"
       "                 [--order mpvo|centroid|automatic] [--amplify A]\n"
       "                 [--mappers havs,tetraycast,cellproj,pt,zsweep,raycast]\n"
       "                 [--output out.png]\n"
       "Default: the NASA blunt fin (Density, 187,395 tets) at 384x256, the project's three\n"
       "mappers (HAVS with the MPVO order and k = 2, its GPU ray caster, its cell projection)\n"
       "beside VTK's ProjectedTetrahedra, ZSweep and RayCast mappers; 8 timed frames for the\n"
       "GPU mappers, the first 2 of them for ZSweep and RayCast.\n"
       "Data directory: --data-dir, else $HAVS_DATA_DIR, else <source>/../shared/data.\n"
       "--amplify A: the error that shows full red in the difference images is 1/A.\n"
       "--table N: HAVS's pre-integration table, N x N x N (default 256: with 128 the blunt\n"
       "fin's sharp transfer function is off by up to 0.016, with 256 by 0.008).\n";
}

/// Returns 0 to run, 1 for an error, 2 for --help.
int ParseArguments(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--help" || a == "-h")
    {
      return 2;
    }
    else if (a == "--dataset")
    {
      o.DataSet = next();
    }
    else if (a == "--data-dir")
    {
      o.DataDir = next();
    }
    else if (a == "--input")
    {
      o.Input = next();
    }
    else if (a == "--plot3d")
    {
      o.Plot3DXYZ = next();
      o.Plot3DQ = next();
      if (i + 1 < argc && argv[i + 1][0] != '-')
      {
        o.Plot3DFunction = std::atoi(next().c_str());
      }
    }
    else if (a == "--array")
    {
      o.Array = next();
    }
    else if (a == "--frames")
    {
      o.Frames = std::max(1, std::atoi(next().c_str()));
    }
    else if (a == "--slow-frames")
    {
      o.SlowFrames = std::max(1, std::atoi(next().c_str()));
    }
    else if (a == "--size")
    {
      o.Width = std::max(16, std::atoi(next().c_str()));
      o.Height = std::max(16, std::atoi(next().c_str()));
    }
    else if (a == "--table")
    {
      o.Table = std::max(2, std::min(1024, std::atoi(next().c_str())));
    }
    else if (a == "--k")
    {
      o.K = std::max(1, std::atoi(next().c_str()));
    }
    else if (a == "--order")
    {
      o.Order = next();
    }
    else if (a == "--amplify")
    {
      o.Amplification = std::max(1.0, std::atof(next().c_str()));
    }
    else if (a == "--mappers")
    {
      o.Mappers = havsapp::SplitList(next());
    }
    else if (a == "--output")
    {
      o.Output = next();
    }
    else
    {
      std::cerr << "havs_demo: unknown option " << a << std::endl;
      return 1;
    }
  }
  if (o.Order != "mpvo" && o.Order != "centroid" && o.Order != "automatic")
  {
    std::cerr << "havs_demo: --order must be mpvo, centroid or automatic." << std::endl;
    return 1;
  }
  for (const std::string& m : o.Mappers)
  {
    if (m != "havs" && m != "tetraycast" && m != "cellproj" && m != "pt" && m != "zsweep" &&
      m != "raycast")
    {
      std::cerr << "havs_demo: unknown mapper " << m
                << " (havs, tetraycast, cellproj, pt, zsweep, raycast)." << std::endl;
      return 1;
    }
  }
  if (o.Mappers.empty())
  {
    std::cerr << "havs_demo: --mappers lists no mapper." << std::endl;
    return 1;
  }
  return 0;
}

std::string Format(const char* format, ...)
{
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  return buffer;
}

/// 187395 -> "187,395".
std::string WithThousands(long long n)
{
  std::string digits = std::to_string(n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
  {
    digits.insert(static_cast<size_t>(i), ",");
  }
  return digits;
}

double Now()
{
  return vtkTimerLog::GetUniversalTime();
}

enum class Line
{
  Transient, ///< repainted in place on a terminal, not written to a log
  Logged,    ///< repainted in place on a terminal, one line in a log
  Final      ///< ends the line on a terminal, one line in a log
};

/// A progress line on stderr: on a terminal the line is repainted in place;
/// redirected to a file, only the lines worth keeping are written.
void ShowProgress(const std::string& text, Line kind)
{
  static const bool terminal = isatty(fileno(stderr)) != 0;
  if (terminal)
  {
    std::fprintf(stderr, "\r\033[K%s%s", text.c_str(), kind == Line::Final ? "\n" : "");
  }
  else if (kind != Line::Transient)
  {
    std::fprintf(stderr, "%s\n", text.c_str());
  }
  std::fflush(stderr);
}

//------------------------------------------------------------------------------
// Errors reported by VTK objects
//------------------------------------------------------------------------------
/// Prints every error an observed object reports and remembers that there was one.
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject* caller, unsigned long, void* callData) override
  {
    ++this->Count;
    const char* message = static_cast<const char*>(callData);
    std::cerr << "\nhavs_demo: error from " << (caller ? caller->GetClassName() : "VTK") << ": "
              << (message ? message : "(no message)") << std::endl;
  }
  void Watch(vtkObject* object) { object->AddObserver(vtkCommand::ErrorEvent, this); }
  int Count = 0;
};

//------------------------------------------------------------------------------
// The scene: data set, transfer function, camera
//------------------------------------------------------------------------------
/// One node of a transfer function: both a colour node and an opacity node.
struct TransferNode
{
  double Value; ///< a scalar value, or a fraction of the scalar range (see ScenePreset)
  double Red, Green, Blue;
  double Opacity;
};

/// What a data set looks like in the demo.
struct ScenePreset
{
  std::string Title;
  std::string Caption; ///< what the picture shows (may be empty)
  std::vector<TransferNode> Nodes;
  bool NodesInScalarUnits = false;          ///< else fractions of the scalar range
  double UnitDistanceFraction = 0.1;        ///< ScalarOpacityUnitDistance / mesh diagonal
  double Direction[3] = { 0.3, 0.35, 1.0 }; ///< from the focal point towards the camera
  double ViewUp[3] = { 0.0, 1.0, 0.0 };
  double Zoom = 1.0; ///< > 1: closer than the whole mesh needs
};

/// A mesh and where it came from.
struct Scene
{
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  ScenePreset Preset;
  std::string Source; ///< files read
  std::string ArrayName;
};

/// Any other mesh: a rainbow ramp over the scalar range, more opaque towards
/// the top, seen obliquely from above (z up).
ScenePreset GenericPreset()
{
  ScenePreset p;
  // { fraction of the range, red, green, blue, opacity }
  p.Nodes = { { 0.0, 0.2, 0.4, 1.0, 0.0 }, { 0.25, 0.2, 0.8, 1.0, 0.15 },
    { 0.5, 0.6, 1.0, 0.3, 0.35 }, { 0.75, 1.0, 0.7, 0.2, 0.6 }, { 1.0, 1.0, 0.3, 0.2, 0.9 } };
  p.UnitDistanceFraction = 0.04;
  const double direction[3] = { 0.6, -1.0, 0.8 };
  const double up[3] = { 0.0, 0.0, 1.0 };
  std::copy(direction, direction + 3, p.Direction);
  std::copy(up, up + 3, p.ViewUp);
  return p;
}

/// The NASA blunt fin: a supersonic flow (+x) over a plate (z = 0) meets a fin
/// standing on it, its leading edge on the z axis; the mesh is the half y >= 0
/// (y = 0: the symmetry plane; the fin, 0.5 thick there, is a hole in it).
/// Seen through the symmetry plane, from upstream and above, the flow from
/// left to right. Density (free stream 1) in its own units: the free stream is
/// clear; the bow shock and the compressed layer it wraps around the fin glow
/// green to yellow, the stagnation line up the leading edge orange to red, and
/// the low-density boundary layer on the plate is a blue floor.
ScenePreset BluntFinPreset()
{
  ScenePreset p;
  p.Title = "NASA blunt fin";
  p.Caption = "Supersonic flow from the left over a plate meets a fin: the bow shock and the gas "
              "it compresses around the fin glow green to yellow, the stagnation line up the "
              "leading edge red; blue: the low-density boundary layer on the plate.";
  p.NodesInScalarUnits = true;
  // { density, red, green, blue, opacity }
  p.Nodes = { { 0.19, 0.45, 0.65, 1.0, 0.6 }, { 0.45, 0.3, 0.55, 1.0, 0.3 },
    { 0.75, 0.2, 0.4, 0.9, 0.0 }, { 1.25, 0.3, 0.8, 0.6, 0.0 }, { 1.6, 0.45, 1.0, 0.5, 0.3 },
    { 2.2, 1.0, 1.0, 0.4, 0.5 }, { 3.0, 1.0, 0.75, 0.2, 0.7 }, { 4.0, 1.0, 0.4, 0.12, 0.85 },
    { 4.98, 1.0, 0.25, 0.3, 1.0 } };
  p.UnitDistanceFraction = 0.01; // 0.24 in the mesh's units (its diagonal is 24)
  const double direction[3] = { -0.35, -1.0, 0.6 };
  const double up[3] = { 0.0, 0.0, 1.0 };
  std::copy(direction, direction + 3, p.Direction);
  std::copy(up, up + 3, p.ViewUp);
  p.Zoom = 1.12; // the far field upstream may leave the frame
  return p;
}

std::string DefaultDataDir(const Options& o)
{
  if (!o.DataDir.empty())
  {
    return o.DataDir;
  }
  const char* fromEnvironment = std::getenv("HAVS_DATA_DIR");
  if (fromEnvironment && *fromEnvironment)
  {
    return fromEnvironment;
  }
  return vtksys::SystemTools::CollapseFullPath(std::string(HAVS_SOURCE_DIR) + "/../shared/data");
}

bool IsReadable(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  return file.good() && file.peek() != std::ifstream::traits_type::eof();
}

/// Prints a clear error and returns false when a file cannot be read.
bool CheckReadable(const std::string& path)
{
  if (IsReadable(path))
  {
    return true;
  }
  std::cerr << "havs_demo: cannot read " << path
            << " (missing or empty). Set HAVS_DATA_DIR or --data-dir to the folder of the data "
               "sets (see ../shared/data/README.md), or give --input / --plot3d."
            << std::endl;
  return false;
}

/// A PLOT3D pair through the data-set catalogue (nullptr, with an error, when unreadable).
vtkSmartPointer<vtkUnstructuredGrid> ReadPLOT3D(
  const std::string& xyz, const std::string& q, int function)
{
  if (!CheckReadable(xyz) || !CheckReadable(q))
  {
    return nullptr;
  }
  return vtkHAVSDataSets::ReadPlot3D(xyz, q, function);
}

/// A .vtu or .vtk file through the data-set catalogue, tetrahedralized.
vtkSmartPointer<vtkUnstructuredGrid> ReadUnstructured(const std::string& path)
{
  if (!CheckReadable(path))
  {
    return nullptr;
  }
  return vtkHAVSDataSets::ReadFile(path);
}

/// Reads --input, --plot3d or the named data set.
bool LoadScene(const Options& o, ErrorCounter* errors, Scene& scene)
{
  std::string array = o.Array;
  if (!o.Input.empty())
  {
    scene.Grid = ReadUnstructured(o.Input);
    scene.Source = o.Input;
    scene.Preset = GenericPreset();
    scene.Preset.Title = o.Input.substr(o.Input.find_last_of('/') + 1);
  }
  else if (!o.Plot3DXYZ.empty())
  {
    scene.Grid = ReadPLOT3D(o.Plot3DXYZ, o.Plot3DQ, o.Plot3DFunction);
    scene.Source = o.Plot3DXYZ + " + " + o.Plot3DQ;
    const bool bluntFin = o.Plot3DXYZ.find("bluntfin") != std::string::npos;
    scene.Preset = bluntFin && o.Plot3DFunction == 100 ? BluntFinPreset() : GenericPreset();
    scene.Preset.Title = o.Plot3DXYZ.substr(o.Plot3DXYZ.find_last_of('/') + 1);
  }
  else
  {
    const std::string dir = vtksys::SystemTools::CollapseFullPath(DefaultDataDir(o));
    if (o.DataSet == "bluntfin")
    {
      scene.Grid = ReadPLOT3D(dir + "/bluntfinxyz.bin", dir + "/bluntfinq.bin", 100);
      scene.Source = dir + "/bluntfin{xyz,q}.bin";
      scene.Preset = BluntFinPreset();
    }
    else if (o.DataSet == "loxpost")
    {
      scene.Grid = ReadPLOT3D(dir + "/postxyz.bin", dir + "/postq.bin", 110);
      scene.Source = dir + "/post{xyz,q}.bin";
      scene.Preset = GenericPreset();
      scene.Preset.Title = "NASA liquid-oxygen post";
    }
    else if (o.DataSet == "combustor")
    {
      scene.Grid = ReadPLOT3D(dir + "/combxyz.bin", dir + "/combq.bin", 100);
      scene.Source = dir + "/comb{xyz,q}.bin";
      scene.Preset = GenericPreset();
      scene.Preset.Title = "combustor";
    }
    else if (o.DataSet == "loxpostvtk")
    {
      scene.Grid = ReadUnstructured(dir + "/post.vtk");
      scene.Source = dir + "/post.vtk";
      scene.Preset = GenericPreset();
      scene.Preset.Title = "liquid-oxygen post (post.vtk)";
      array = array.empty() ? "Pressure" : array;
    }
    else
    {
      std::cerr << "havs_demo: unknown data set " << o.DataSet
                << " (bluntfin, loxpost, combustor, loxpostvtk)." << std::endl;
      return false;
    }
  }
  vtkUnstructuredGrid* grid = scene.Grid;
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    return false;
  }
  vtkPointData* pointData = grid->GetPointData();
  if (!array.empty() && !pointData->GetArray(array.c_str()))
  {
    std::cerr << "havs_demo: " << scene.Source << " has no point array \"" << array << "\"."
              << std::endl;
    return false;
  }
  if (!array.empty())
  {
    pointData->SetActiveScalars(array.c_str());
  }
  if (!pointData->GetScalars() && pointData->GetNumberOfArrays() > 0)
  {
    pointData->SetActiveScalars(pointData->GetArrayName(0));
  }
  if (!pointData->GetScalars())
  {
    std::cerr << "havs_demo: " << scene.Source << " has no point scalars to render." << std::endl;
    return false;
  }
  const char* name = pointData->GetScalars()->GetName();
  scene.ArrayName = name ? name : "scalars";
  return errors->Count == 0;
}

vtkSmartPointer<vtkVolumeProperty> MakeProperty(
  const ScenePreset& preset, const double range[2], double diagonal)
{
  const double lo = range[0], span = std::max(range[1] - range[0], 1e-30);
  // Every opacity node is also a colour node: VTK's
  // vtkUnstructuredGridLinearRayIntegrator (the ray-cast and ZSweep mappers'
  // exact integrator) splits segments at the colour nodes but, reading VTK
  // 9.2's source, only at the first opacity node, so it is exact only then.
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  for (const TransferNode& n : preset.Nodes)
  {
    const double value = preset.NodesInScalarUnits ? n.Value : lo + n.Value * span;
    color->AddRGBPoint(value, n.Red, n.Green, n.Blue);
    opacity->AddPoint(value, n.Opacity);
  }
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(preset.UnitDistanceFraction * diagonal);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  return property;
}

/// The mesh's points in the camera's frame around a focal point: the
/// extents across (right, up) and the distance the view needs to hold them all.
struct ViewFit
{
  double Right[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  double Up[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  double Distance = 0.0;
  double Radius = 0.0;
};

ViewFit FitView(vtkPoints* points, const double focal[3], const double d[3], const double right[3],
  const double up[3], double tanH, double tanV)
{
  ViewFit fit;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double rel[3];
    points->GetPoint(i, rel);
    vtkMath::Subtract(rel, focal, rel);
    const double x = vtkMath::Dot(rel, right), y = vtkMath::Dot(rel, up), z = vtkMath::Dot(rel, d);
    fit.Right[0] = std::min(fit.Right[0], x);
    fit.Right[1] = std::max(fit.Right[1], x);
    fit.Up[0] = std::min(fit.Up[0], y);
    fit.Up[1] = std::max(fit.Up[1], y);
    fit.Distance = std::max(fit.Distance, z + std::max(std::fabs(x) / tanH, std::fabs(y) / tanV));
    fit.Radius = std::max(fit.Radius, vtkMath::Norm(rel));
  }
  return fit;
}

/// The camera of the first frame: looking from the preset's direction, the
/// mesh centred and as large as the window allows (a small margin around).
void PlaceCamera(
  vtkCamera* camera, const ScenePreset& preset, vtkUnstructuredGrid* grid, double aspect)
{
  double bounds[6], focal[3], d[3], up[3], right[3];
  grid->GetBounds(bounds);
  for (int a = 0; a < 3; ++a)
  {
    focal[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    d[a] = preset.Direction[a];
    up[a] = preset.ViewUp[a];
  }
  vtkMath::Normalize(d);
  vtkMath::Cross(up, d, right);
  vtkMath::Normalize(right);
  vtkMath::Cross(d, right, up);
  const double viewAngle = 30.0;
  const double tanV = std::tan(vtkMath::RadiansFromDegrees(0.5 * viewAngle)) * preset.Zoom;
  const double tanH = tanV * aspect;
  // Centre the projected points, then back off until they all fit.
  const ViewFit around = FitView(grid->GetPoints(), focal, d, right, up, tanH, tanV);
  for (int a = 0; a < 3; ++a)
  {
    focal[a] += 0.5 * (around.Right[0] + around.Right[1]) * right[a] +
      0.5 * (around.Up[0] + around.Up[1]) * up[a];
  }
  const ViewFit fit = FitView(grid->GetPoints(), focal, d, right, up, tanH, tanV);
  const double distance = 1.03 * fit.Distance;
  camera->SetViewAngle(viewAngle);
  camera->SetFocalPoint(focal);
  camera->SetPosition(
    focal[0] + distance * d[0], focal[1] + distance * d[1], focal[2] + distance * d[2]);
  camera->SetViewUp(up);
  // The sphere around the focal point that holds the mesh: valid for the whole orbit.
  camera->SetClippingRange(
    std::max(0.01 * distance, distance - 1.01 * fit.Radius), distance + 1.01 * fit.Radius);
}

//------------------------------------------------------------------------------
// The mappers
//------------------------------------------------------------------------------
struct MapperRun
{
  std::string Key;   ///< havs, pt, zsweep, raycast
  std::string Name;  ///< as in the table
  std::string Label; ///< how it was set up, for the picture
  bool Slow = false; ///< runs on the CPU: fewer timed frames
  std::vector<double> FrameSeconds;
  std::vector<double> Sort, Draw, Flush;
  double FirstFrameSeconds = 0.0;
  std::vector<float> FirstImage; ///< RGBA as seen in the window, bottom row first
  double RMSE = 0.0, MaxError = 0.0, Over1 = 0.0;
  std::vector<unsigned char> Difference; ///< false colour, RGB, bottom row first
};

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// HAVS's run, the one the others' times are given relative to (nullptr when not run).
const MapperRun* FindHAVS(const std::vector<MapperRun>& runs)
{
  for (const MapperRun& run : runs)
  {
    if (run.Key == "havs")
    {
      return &run;
    }
  }
  return nullptr;
}

vtkSmartPointer<vtkHAVSVolumeMapper> MakeHAVS(const Options& o)
{
  auto havs = vtkSmartPointer<vtkHAVSVolumeMapper>::New();
  havs->SetKBufferSize(o.K);
  // --table names the size (256^3 by default: the demo's sharp transfer
  // function needs it to be exact), so the automatic choice is off.
  havs->AutomaticTableResolutionOff();
  havs->SetTableScalarResolution(o.Table);
  havs->SetTableLengthResolution(o.Table);
  havs->MeasureStageTimesOn();
  if (o.Order == "mpvo")
  {
    havs->SetVisibilityOrderToMPVO(); // the exact object-space order
    havs->SetNonConvexMethodToBoundaryLayers();
  }
  else if (o.Order == "automatic")
  {
    havs->SetVisibilityOrderToAutomatic();
  }
  else
  {
    havs->SetVisibilityOrderToCentroid();
  }
  return havs;
}

vtkSmartPointer<vtkUnstructuredGridVolumeMapper> MakeMapper(
  const std::string& key, const Options& o, MapperRun& run)
{
  run.Key = key;
  if (key == "havs")
  {
    run.Name = "HAVS";
    const char* order = o.Order == "mpvo" ? "MPVO order"
      : o.Order == "automatic"            ? "automatic order"
                                          : "centroid order";
    run.Label = Format("vtkHAVSVolumeMapper, %s, k = %d", order, o.K);
    return MakeHAVS(o);
  }
  if (key == "tetraycast" || key == "cellproj")
  {
    // The project's other two mappers, with HAVS's table size (--table).
    vtkSmartPointer<vtkHAVSMapperBase> mapper;
    if (key == "tetraycast")
    {
      run.Name = "HAVS RC";
      run.Label = "vtkHAVSRayCastMapper";
      mapper.TakeReference(vtkHAVSRayCastMapper::New());
    }
    else
    {
      run.Name = "HAVS CP";
      run.Label = "vtkHAVSCellProjectionMapper";
      mapper.TakeReference(vtkHAVSCellProjectionMapper::New());
    }
    mapper->AutomaticTableResolutionOff(); // HAVS's table, as HAVS draws it
    mapper->SetTableScalarResolution(o.Table);
    mapper->SetTableLengthResolution(o.Table);
    return mapper;
  }
  if (key == "pt")
  {
    run.Name = "PT";
    run.Label = "vtkProjectedTetrahedraMapper";
    return vtkSmartPointer<vtkProjectedTetrahedraMapper>::New();
  }
  run.Slow = true;
  if (key == "zsweep")
  {
    run.Name = "ZSweep";
    run.Label = "vtkUnstructuredGridVolumeZSweepMapper";
    auto zsweep = vtkSmartPointer<vtkUnstructuredGridVolumeZSweepMapper>::New();
    zsweep->SetImageSampleDistance(1.0);
    zsweep->AutoAdjustSampleDistancesOff();
    zsweep->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());
    return zsweep;
  }
  run.Name = "RayCast";
  run.Label = "vtkUnstructuredGridVolumeRayCastMapper";
  auto raycast = vtkSmartPointer<vtkUnstructuredGridVolumeRayCastMapper>::New();
  raycast->SetImageSampleDistance(1.0);
  raycast->AutoAdjustSampleDistancesOff();
  raycast->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());
  return raycast;
}

std::vector<float> ReadWindowRGBA(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkFloatArray> data;
  window->GetRGBAPixelData(0, 0, size[0] - 1, size[1] - 1, 0, data);
  return std::vector<float>(data->GetPointer(0), data->GetPointer(0) + 4 * size[0] * size[1]);
}

/// What the demo says about the machine, from the first window.
struct Platform
{
  std::string WindowBackend;
  std::string GLRenderer;
  std::string KBufferPath;
  int ActiveK = 0;
  std::string LastOrder;
  long long OrderViolations = 0;
  long long Faces = 0, BoundaryFaces = 0;
};

std::string GLRendererOf(vtkRenderWindow* window)
{
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    return "(unknown)";
  }
  const std::string caps = gl->ReportCapabilities();
  const std::string key = "OpenGL renderer string:";
  const size_t at = caps.find(key);
  if (at == std::string::npos)
  {
    return "(unknown)";
  }
  std::string value = caps.substr(at + key.size(), caps.find('\n', at) - at - key.size());
  value.erase(0, value.find_first_not_of(' '));
  return value;
}

void RecordHAVSState(vtkHAVSVolumeMapper* havs, Platform& platform)
{
  platform.KBufferPath = havs->GetActiveKBufferPathName();
  platform.ActiveK = havs->GetActiveKBufferSize();
  const int order = havs->GetLastVisibilityOrder();
  platform.LastOrder = order == vtkHAVSVolumeMapper::VisibilityOrderMPVO ? "MPVO"
    : order == vtkHAVSVolumeMapper::VisibilityOrderCentroid              ? "centroid"
                                                                         : "none";
  platform.OrderViolations = havs->GetLastOrderViolations();
  platform.Faces = havs->GetNumberOfFaces();
  platform.BoundaryFaces = havs->GetNumberOfBoundaryFaces();
}

/// The first frame (its image, not timed) and the timed orbit of one mapper.
bool RunMapper(vtkUnstructuredGridVolumeMapper* mapper, MapperRun& run, vtkUnstructuredGrid* grid,
  vtkVolumeProperty* property, vtkCamera* firstCamera, const Options& o, ErrorCounter* errors,
  Platform& platform)
{
  vtkSmartPointer<vtkRenderWindow> window;
  window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow());
  if (!window)
  {
    std::cerr << "havs_demo: no render window could be made." << std::endl;
    return false;
  }
  errors->Watch(window);
  errors->Watch(mapper);
  const int before = errors->Count;
  window->SetSize(o.Width, o.Height);
  vtkNew<vtkRenderer> renderer;
  errors->Watch(renderer);
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  mapper->SetInputData(grid);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->DeepCopy(firstCamera);

  const int frames = run.Slow ? std::min(o.SlowFrames, o.Frames) : o.Frames;
  const std::string name = "havs_demo: " + run.Name + ": ";
  const Line frameLine = run.Slow ? Line::Logged : Line::Transient;
  ShowProgress(name + "first frame (not timed) ...", frameLine);
  auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper);
  if (havs)
  {
    havs->CountOrderViolationsOn(); // the first frame says whether it was exact
  }
  double start = Now();
  window->Render(); // faces, tables, shaders: not timed
  window->WaitForCompletion();
  run.FirstFrameSeconds = Now() - start;
  run.FirstImage = ReadWindowRGBA(window);
  if (platform.WindowBackend.empty())
  {
    platform.WindowBackend = vtkHAVSRenderWindowFactory::GetBackendName(window);
    platform.GLRenderer = GLRendererOf(window);
  }
  if (havs)
  {
    RecordHAVSState(havs, platform);
    havs->CountOrderViolationsOff(); // the timed frames as a user's: no counter
  }
  const std::string first = Format("first frame %.2f s", run.FirstFrameSeconds);
  for (int f = 1; f <= frames && errors->Count == before; ++f)
  {
    ShowProgress(name + first + Format(", timed frame %d/%d ...", f, frames), frameLine);
    camera->Azimuth(360.0 / o.Frames); // view f of the orbit of --frames views
    start = Now();
    window->Render();
    window->WaitForCompletion();
    run.FrameSeconds.push_back(Now() - start);
    if (havs)
    {
      run.Sort.push_back(havs->GetLastFrameStatistics()->GetSortSeconds());
      run.Draw.push_back(havs->GetLastFrameStatistics()->GetDrawSeconds());
      run.Flush.push_back(havs->GetLastFrameStatistics()->GetFlushSeconds());
    }
  }
  ShowProgress(name + first +
      Format(", %zu timed frames, median %.1f ms", run.FrameSeconds.size(),
        1000.0 * Median(run.FrameSeconds)),
    Line::Final);
  mapper->ReleaseGraphicsResources(window);
  return errors->Count == before;
}

//------------------------------------------------------------------------------
// The exact reference
//------------------------------------------------------------------------------
/// The progress of the exact reference on stderr. vtkHAVSReferenceRenderer
/// reports up to 0.1 while it finds and sorts the ray/face intersections, then
/// after every twentieth of the pixels it integrated; on a terminal a ticker
/// repaints the line twice a second so that the elapsed time keeps moving.
class ReferenceProgress : public vtkCommand
{
public:
  static ReferenceProgress* New() { return new ReferenceProgress; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    if (callData)
    {
      this->Progress = *static_cast<double*>(callData);
      ShowProgress(this->Text(), Line::Logged);
    }
  }
  void Start()
  {
    this->StartTime = Now();
    this->Running = true;
    this->Ticker = std::thread(
      [this]()
      {
        std::unique_lock<std::mutex> lock(this->Mutex);
        while (this->Running)
        {
          ShowProgress(this->Text(), Line::Transient);
          this->Wake.wait_for(lock, std::chrono::milliseconds(500));
        }
      });
  }
  void Stop(bool ok)
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Running = false;
    }
    this->Wake.notify_all();
    if (this->Ticker.joinable())
    {
      this->Ticker.join();
    }
    ShowProgress(Format("havs_demo: exact reference: %s in %.1f s", ok ? "done" : "failed",
                   Now() - this->StartTime),
      Line::Final);
  }

private:
  std::string Text() const
  {
    const double progress = this->Progress, elapsed = Now() - this->StartTime;
    return Format("havs_demo: exact reference: %3.0f%% (%s), %.0f s", 100.0 * progress,
      progress < 0.1 ? "ray/face intersections" : "integrating the segments", elapsed);
  }
  std::atomic<double> Progress{ 0.0 };
  std::atomic<double> StartTime{ 0.0 };
  bool Running = false;
  std::mutex Mutex;
  std::condition_variable Wake;
  std::thread Ticker;
};

/// The exact image (premultiplied RGBA, bottom row first), or empty on failure.
std::vector<float> RenderReference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkCamera* camera, const Options& o, ErrorCounter* errors, double& seconds)
{
  vtkNew<vtkHAVSReferenceRenderer> reference;
  errors->Watch(reference);
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(o.Width, o.Height);
  vtkNew<ReferenceProgress> progress;
  reference->AddObserver(vtkCommand::ProgressEvent, progress);
  const double start = Now();
  progress->Start();
  const bool ok = reference->Render();
  progress->Stop(ok);
  seconds = Now() - start;
  if (!ok || !reference->GetImage())
  {
    std::cerr << "havs_demo: the exact reference could not be rendered." << std::endl;
    return {};
  }
  const float* exact = reference->GetImage()->GetPointer(0);
  return std::vector<float>(exact, exact + 4 * static_cast<size_t>(o.Width) * o.Height);
}

/// The colour seen in the window: RGB, alpha set to 0 (the window's alpha is not seen).
vtkSmartPointer<vtkFloatArray> SeenColour(const std::vector<float>& rgba)
{
  auto seen = vtkSmartPointer<vtkFloatArray>::New();
  seen->SetNumberOfComponents(4);
  seen->SetNumberOfTuples(static_cast<vtkIdType>(rgba.size() / 4));
  float* out = seen->GetPointer(0);
  for (size_t p = 0; p < rgba.size() / 4; ++p)
  {
    std::copy(&rgba[4 * p], &rgba[4 * p] + 3, out + 4 * p);
    out[4 * p + 3] = 0.0f;
  }
  return seen;
}

void MeasureError(MapperRun& run, vtkFloatArray* exact, double amplification)
{
  vtkNew<vtkHAVSImageMetrics> metrics;
  vtkSmartPointer<vtkFloatArray> seen = SeenColour(run.FirstImage);
  metrics->Compare(seen, exact);
  run.RMSE = metrics->GetRMSE();
  run.MaxError = metrics->GetMaxAbsError();
  run.Over1 = metrics->GetFractionOver1();
  metrics->SetScale(1.0 / amplification);
  vtkNew<vtkUnsignedCharArray> difference;
  metrics->DifferenceImage(seen, exact, difference);
  run.Difference.assign(
    difference->GetPointer(0), difference->GetPointer(0) + 3 * difference->GetNumberOfTuples());
}

//------------------------------------------------------------------------------
// The picture
//------------------------------------------------------------------------------
/// An RGB image, top row first, with text from vtkFreeTypeTools.
class Canvas
{
public:
  Canvas(int width, int height, const unsigned char background[3])
    : Width(width)
    , Height(height)
    , Pixels(3 * static_cast<size_t>(width) * height)
  {
    this->FillRectangle(0, 0, width, height, background);
  }

  void FillRectangle(int x, int y, int w, int h, const unsigned char rgb[3])
  {
    for (int r = std::max(0, y); r < std::min(this->Height, y + h); ++r)
    {
      for (int c = std::max(0, x); c < std::min(this->Width, x + w); ++c)
      {
        std::copy(rgb, rgb + 3, this->At(c, r));
      }
    }
  }

  /// An RGB image stored bottom row first (as VTK's), its top-left corner at (x, y).
  void PutBottomUp(int x, int y, int w, int h, const unsigned char* rgb)
  {
    for (int r = 0; r < h; ++r)
    {
      const unsigned char* row = rgb + 3 * static_cast<size_t>(h - 1 - r) * w;
      for (int c = 0; c < w; ++c)
      {
        if (x + c >= 0 && x + c < this->Width && y + r >= 0 && y + r < this->Height)
        {
          std::copy(row + 3 * c, row + 3 * c + 3, this->At(x + c, y + r));
        }
      }
    }
  }

  /// Text with its top-left corner at (x, y); returns its width in pixels.
  int PutText(int x, int y, const std::string& text, int size, bool bold, const double rgb[3])
  {
    vtkSmartPointer<vtkTextProperty> style = TextStyle(size, bold, rgb);
    vtkNew<vtkImageData> glyphs;
    int dims[2] = { 0, 0 };
    vtkFreeTypeTools* freeType = vtkFreeTypeTools::GetInstance();
    if (text.empty() || !freeType->RenderString(style, text, 72, glyphs, dims))
    {
      return 0;
    }
    // The image's extent has its origin at the anchor, the text's top left
    // (rows below it at negative j; the image may be padded beyond the text).
    int extent[6];
    glyphs->GetExtent(extent);
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      for (int i = extent[0]; i <= extent[1]; ++i)
      {
        const auto* src = static_cast<unsigned char*>(glyphs->GetScalarPointer(i, j, 0));
        const int cx = x + i, cy = y - j;
        if (src[3] == 0 || cx < 0 || cx >= this->Width || cy < 0 || cy >= this->Height)
        {
          continue;
        }
        unsigned char* dst = this->At(cx, cy);
        const double a = src[3] / 255.0;
        for (int c = 0; c < 3; ++c)
        {
          dst[c] = static_cast<unsigned char>(std::lround((1 - a) * dst[c] + a * src[c]));
        }
      }
    }
    return dims[0];
  }

  /// Words wrapped to lines no wider than `width`, one below the other from
  /// (x, y), `spacing` apart; returns the number of lines.
  int PutParagraph(
    int x, int y, int width, int spacing, const std::string& text, int size, const double rgb[3])
  {
    vtkSmartPointer<vtkTextProperty> style = TextStyle(size, false, rgb);
    std::istringstream words(text);
    std::string word, line;
    int lines = 0;
    auto flush = [&]()
    {
      this->PutText(x, y + lines++ * spacing, line, size, false, rgb);
      line.clear();
    };
    while (words >> word)
    {
      const std::string longer = line.empty() ? word : line + " " + word;
      int box[4] = { 0, 0, 0, 0 };
      vtkFreeTypeTools::GetInstance()->GetBoundingBox(style, longer, 72, box);
      if (!line.empty() && box[1] - box[0] > width)
      {
        flush();
        line = word;
      }
      else
      {
        line = longer;
      }
    }
    if (!line.empty())
    {
      flush();
    }
    return lines;
  }

  bool WritePNG(const std::string& path) const
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(this->Width, this->Height, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
    for (int r = 0; r < this->Height; ++r)
    {
      const unsigned char* row = this->Pixels.data() + 3 * static_cast<size_t>(r) * this->Width;
      std::copy(row, row + 3 * this->Width,
        out + 3 * static_cast<size_t>(this->Height - 1 - r) * this->Width);
    }
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName(path.c_str());
    writer->Write();
    return writer->GetErrorCode() == 0;
  }

private:
  static vtkSmartPointer<vtkTextProperty> TextStyle(int size, bool bold, const double rgb[3])
  {
    auto style = vtkSmartPointer<vtkTextProperty>::New();
    style->SetFontFamilyToArial();
    style->SetFontSize(size);
    style->SetBold(bold);
    style->SetColor(rgb[0], rgb[1], rgb[2]);
    style->SetJustificationToLeft();
    style->SetVerticalJustificationToTop();
    return style;
  }
  unsigned char* At(int x, int y)
  {
    return &this->Pixels[3 * (static_cast<size_t>(y) * this->Width + x)];
  }
  int Width, Height;
  std::vector<unsigned char> Pixels;
};

std::vector<unsigned char> ToBytes(const std::vector<float>& rgba)
{
  std::vector<unsigned char> rgb(3 * (rgba.size() / 4));
  for (size_t p = 0; p < rgba.size() / 4; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const float v = std::min(std::max(rgba[4 * p + c], 0.0f), 1.0f);
      rgb[3 * p + c] = static_cast<unsigned char>(v * 255.0f + 0.5f);
    }
  }
  return rgb;
}

/// "0.69×", "136×": a time relative to HAVS's.
std::string Ratio(double ratio)
{
  return Format(ratio >= 10.0 ? "%.0f\u00d7" : "%.2f\u00d7", ratio);
}

/// The false-colour ramp of vtkHAVSImageMetrics::DifferenceImage, as a bar with ticks.
void PutErrorLegend(Canvas& canvas, int x, int y, int width, double amplification)
{
  const double text[3] = { 0.85, 0.86, 0.9 };
  const double ramp[5][3] = { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 }, { 1, 1, 0 }, { 1, 0, 0 } };
  const double full = 255.0 / amplification; // full red, in steps of 1/255
  canvas.PutText(
    x, y, Format("Below: error against the exact image \u00d7%g", amplification), 15, true, text);
  canvas.PutText(
    x, y + 24, "per pixel, the largest colour-channel error, in false colour:", 13, false, text);
  canvas.PutText(x, y + 42, Format("black = exact, red = %.0f/255 or more", full), 13, false, text);
  const int barY = y + 66, barHeight = 20;
  const unsigned char frame[3] = { 140, 140, 140 };
  canvas.FillRectangle(x - 1, barY - 1, width + 2, barHeight + 2, frame);
  for (int c = 0; c < width; ++c)
  {
    const double t = 4.0 * c / std::max(1, width - 1);
    const int i = std::min(static_cast<int>(t), 3);
    const double f = t - i;
    unsigned char rgb[3];
    for (int k = 0; k < 3; ++k)
    {
      rgb[k] = static_cast<unsigned char>(255.0 * ((1 - f) * ramp[i][k] + f * ramp[i + 1][k]));
    }
    canvas.FillRectangle(x + c, barY, 1, barHeight, rgb);
  }
  for (int tick = 0; tick <= 4; ++tick)
  {
    const int tx = x + tick * (width - 1) / 4;
    canvas.FillRectangle(tx, barY + barHeight, 1, 5, frame);
    const std::string label = tick == 0 ? "0" : Format("%.0f/255", full * tick / 4.0);
    const int labelX = tick == 0 ? tx - 3 : tick == 4 ? tx - 44 : tx - 20;
    canvas.PutText(labelX, barY + barHeight + 8, label, 13, false, text);
  }
}

struct Summary
{
  std::string Title;
  std::string Caption;
  std::string Subtitle;
  std::vector<std::string> Platform; ///< lines under the error legend
  double ReferenceSeconds = 0.0;
};

const int kTextColumnWidth = 340; ///< the narrowest column its text fits in
const double kWhite[3] = { 1.0, 1.0, 1.0 };
const double kGrey[3] = { 0.78, 0.8, 0.84 };
const double kGreen[3] = { 0.55, 0.95, 0.55 };

/// Where the panels of one column go.
struct ColumnLayout
{
  int X, ImageX; ///< the column's left edge, the images' left edge
  int HeaderY, ImageY, DifferenceHeaderY, DifferenceY;
};

void PutReferenceColumn(Canvas& canvas, const ColumnLayout& at, const std::vector<float>& exact,
  const Summary& summary, const Options& o)
{
  canvas.PutText(at.X, at.HeaderY, "Exact reference", 18, true, kGreen);
  canvas.PutText(
    at.X, at.HeaderY + 26, "vtkHAVSReferenceRenderer, double precision:", 13, false, kGrey);
  canvas.PutText(at.X, at.HeaderY + 44,
    Format("watertight, segments to 1e-6; %.0f s on the CPU", summary.ReferenceSeconds), 13, false,
    kGrey);
  canvas.PutBottomUp(at.ImageX, at.ImageY, o.Width, o.Height, ToBytes(exact).data());
  PutErrorLegend(
    canvas, at.X + 6, at.DifferenceHeaderY + 4, kTextColumnWidth - 20, o.Amplification);
  int y = at.DifferenceHeaderY + 136;
  for (const std::string& line : summary.Platform)
  {
    canvas.PutText(at.X + 6, y, line, 13, false, kGrey);
    y += 18;
  }
}

void PutMapperColumn(Canvas& canvas, const ColumnLayout& at, const MapperRun& run,
  const MapperRun* havs, const Options& o)
{
  const double seconds = Median(run.FrameSeconds);
  std::string speed = Format("%.0f ms/frame", 1000.0 * seconds);
  if (havs && &run != havs && Median(havs->FrameSeconds) > 0)
  {
    speed += " = " + Ratio(seconds / Median(havs->FrameSeconds)) + " HAVS";
  }
  const bool isHAVS = &run == havs;
  const int nameWidth =
    canvas.PutText(at.X, at.HeaderY, run.Name, 18, true, isHAVS ? kGreen : kWhite);
  canvas.PutText(at.X + nameWidth + 10, at.HeaderY + 2, speed, 16, false, kWhite);
  canvas.PutText(at.X, at.HeaderY + 26, run.Label, 13, false, kGrey);
  canvas.PutText(at.X, at.HeaderY + 44,
    Format(
      "RMSE %.5f   max %.4f   %.1f%% of pixels > 1/255", run.RMSE, run.MaxError, 100.0 * run.Over1),
    13, false, isHAVS ? kGreen : kGrey);
  canvas.PutBottomUp(at.ImageX, at.ImageY, o.Width, o.Height, ToBytes(run.FirstImage).data());
  canvas.PutText(at.X, at.DifferenceHeaderY + 6,
    Format("|%s \u2212 exact| \u00d7%g", run.Name.c_str(), o.Amplification), 14, true, kGrey);
  canvas.PutBottomUp(at.ImageX, at.DifferenceY, o.Width, o.Height, run.Difference.data());
}

/// Columns: the exact reference, then every mapper; row 1 the images, row 2
/// the difference images (the error legend under the reference). Columns are
/// at least as wide, and the lower row as tall, as their text needs.
bool WritePicture(const std::vector<MapperRun>& runs, const std::vector<float>& exact,
  const Summary& summary, const Options& o)
{
  const int gap = 8, margin = 14, headerHeight = 68, differenceHeader = 30;
  const int columnWidth = std::max(o.Width, kTextColumnWidth);
  const int lowerRow = std::max(o.Height, 215); // the legend and the machine's lines
  const int columns = static_cast<int>(runs.size()) + 1;
  const int width = 2 * margin + columns * columnWidth + (columns - 1) * gap;
  // The subtitle wraps to the width: draw it on a scratch canvas to count its lines.
  const unsigned char background[3] = { 28, 30, 34 };
  Canvas scratch(width, 200, background);
  const int textWidth = width - 2 * margin;
  const int captionLines = scratch.PutParagraph(0, 0, textWidth, 18, summary.Caption, 14, kWhite);
  const int subtitleLines = scratch.PutParagraph(0, 0, textWidth, 18, summary.Subtitle, 14, kGrey);
  const int titleHeight = 52 + 18 * (captionLines + subtitleLines);
  const int height =
    titleHeight + headerHeight + o.Height + gap + differenceHeader + lowerRow + margin;
  Canvas canvas(width, height, background);
  canvas.PutText(margin, 12, summary.Title, 22, true, kWhite);
  canvas.PutParagraph(margin, 42, textWidth, 18, summary.Caption, 14, kWhite);
  canvas.PutParagraph(margin, 42 + 18 * captionLines, textWidth, 18, summary.Subtitle, 14, kGrey);
  const MapperRun* havs = FindHAVS(runs);
  for (int column = 0; column < columns; ++column)
  {
    ColumnLayout at;
    at.X = margin + column * (columnWidth + gap);
    at.ImageX = at.X + (columnWidth - o.Width) / 2;
    at.HeaderY = titleHeight;
    at.ImageY = titleHeight + headerHeight;
    at.DifferenceHeaderY = at.ImageY + o.Height + gap;
    at.DifferenceY = at.DifferenceHeaderY + differenceHeader;
    if (column == 0)
    {
      PutReferenceColumn(canvas, at, exact, summary, o);
    }
    else
    {
      PutMapperColumn(canvas, at, runs[column - 1], havs, o);
    }
  }
  return canvas.WritePNG(o.Output);
}

//------------------------------------------------------------------------------
// The table
//------------------------------------------------------------------------------
std::string StageMilliseconds(const std::vector<double>& seconds)
{
  return seconds.empty() ? std::string("-") : Format("%.1f", 1000.0 * Median(seconds));
}

void PrintTable(const std::vector<MapperRun>& runs, vtkIdType tets)
{
  std::printf(
    "| mapper | timed frames | median ms/frame | sort ms | draw ms | flush ms | Mtets/s | "
    "RMSE | max error | px > 1/255 | time / HAVS |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  const MapperRun* havsRun = FindHAVS(runs);
  const double havs = havsRun ? Median(havsRun->FrameSeconds) : 0.0;
  for (const MapperRun& r : runs)
  {
    const double seconds = Median(r.FrameSeconds);
    const std::string ratio = havs > 0 ? Format("%.2f", seconds / havs) : std::string("-");
    std::printf("| %s | %zu | %.1f | %s | %s | %s | %.3f | %.5f | %.4f | %.2f%% | %s |\n",
      r.Name.c_str(), r.FrameSeconds.size(), 1000.0 * seconds, StageMilliseconds(r.Sort).c_str(),
      StageMilliseconds(r.Draw).c_str(), StageMilliseconds(r.Flush).c_str(),
      seconds > 0 ? tets / (seconds * 1e6) : 0.0, r.RMSE, r.MaxError, 100.0 * r.Over1,
      ratio.c_str());
  }
}

void PrintSetup(const Scene& scene, const Options& o, const Platform& platform,
  const std::vector<MapperRun>& runs, double referenceSeconds)
{
  const vtkIdType tets = scene.Grid->GetNumberOfCells();
  std::printf("\nvtkHAVS demo: %s (%s), %s tets, %dx%d\n", scene.Preset.Title.c_str(),
    scene.ArrayName.c_str(), WithThousands(tets).c_str(), o.Width, o.Height);
  std::printf("Data: %s\n", scene.Source.c_str());
  std::printf("Window backend: %s, %s; SMP backend: %s (%d threads)\n",
    platform.WindowBackend.c_str(), platform.GLRenderer.c_str(), vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  for (const MapperRun& r : runs)
  {
    if (r.Key == "havs")
    {
      const std::string order =
        o.Order == "mpvo" ? "MPVO order (non-convex method BoundaryLayers)" : o.Order + " order";
      std::printf("HAVS = vtkHAVSVolumeMapper: %s, k = %d, k-buffer path %s; %s faces (%s "
                  "boundary); first frame drawn in the %s order with %lld order violations\n",
        order.c_str(), platform.ActiveK, platform.KBufferPath.c_str(),
        WithThousands(platform.Faces).c_str(), WithThousands(platform.BoundaryFaces).c_str(),
        platform.LastOrder.c_str(), platform.OrderViolations);
    }
  }
  std::printf(
    "HAVS RC = vtkHAVSRayCastMapper (GPU ray casting through the tetrahedra, "
    "depth-peeled re-entries); HAVS CP = vtkHAVSCellProjectionMapper (the cells in the "
    "exact MPVO order, each fragment integrating its cell); both with HAVS's %d^3 table.\n",
    o.Table);
  std::printf("PT = vtkProjectedTetrahedraMapper; ZSweep = vtkUnstructuredGridVolumeZSweepMapper "
              "and RayCast = vtkUnstructuredGridVolumeRayCastMapper with ImageSampleDistance 1, "
              "AutoAdjustSampleDistances off, vtkUnstructuredGridLinearRayIntegrator.\n");
  std::printf("Timing: a first frame (not timed), then an orbit of %d views about the vertical; "
              "the GPU mappers render all %d, ZSweep and RayCast (CPU) only the first %d.\n",
    o.Frames, o.Frames, std::min(o.SlowFrames, o.Frames));
  std::printf("Error: the first frame's colour seen in the window (over black) against the exact "
              "reference (vtkHAVSReferenceRenderer, %.1f s).\n\n",
    referenceSeconds);
}

/// The picture's title, subtitle and the lines about the machine.
Summary Summarize(
  const Scene& scene, const Options& o, const Platform& platform, double referenceSeconds)
{
  Summary summary;
  summary.Caption = scene.Preset.Caption;
  summary.Title =
    Format("%s: %s, %s tetrahedra, %d\u00d7%d", scene.Preset.Title.c_str(), scene.ArrayName.c_str(),
      WithThousands(scene.Grid->GetNumberOfCells()).c_str(), o.Width, o.Height);
  summary.Subtitle = Format("The same mesh, transfer function, camera and window for every "
                            "mapper. Time: median per frame over an orbit of %d views (ZSweep "
                            "and RayCast: the first %d). Error: the first view's colour, as seen "
                            "over black, against the exact image.",
    o.Frames, std::min(o.SlowFrames, o.Frames));
  summary.Platform = {
    Format("Window: %s, %s", platform.WindowBackend.c_str(), platform.GLRenderer.c_str()),
    Format("SMP backend: %s (%d threads)", vtkSMPTools::GetBackend(),
      vtkSMPTools::GetEstimatedNumberOfThreads()),
    Format(
      "HAVS k-buffer path: %s", platform.KBufferPath.empty() ? "-" : platform.KBufferPath.c_str()),
    "HAVS, HAVS RC, HAVS CP, PT: OpenGL;",
    "ZSweep and RayCast run on the CPU.",
  };
  summary.ReferenceSeconds = referenceSeconds;
  return summary;
}

} // namespace

int main(int argc, char* argv[])
{
  const double programStart = Now();
  Options o;
  const int parsed = ParseArguments(argc, argv, o);
  if (parsed != 0)
  {
    PrintUsage();
    return parsed == 2 ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  vtkNew<ErrorCounter> errors;

  Scene scene;
  std::cerr << "havs_demo: loading ..." << std::endl;
  if (!LoadScene(o, errors, scene))
  {
    return EXIT_FAILURE;
  }
  vtkUnstructuredGrid* grid = scene.Grid;
  const double loadSeconds = Now() - programStart;
  std::cerr << "havs_demo: " << WithThousands(grid->GetNumberOfCells()) << " tets from "
            << scene.Source << " (" << Format("%.1f", loadSeconds) << " s)" << std::endl;
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  vtkSmartPointer<vtkVolumeProperty> property =
    MakeProperty(scene.Preset, range, grid->GetLength());
  vtkNew<vtkCamera> firstCamera;
  PlaceCamera(firstCamera, scene.Preset, grid, static_cast<double>(o.Width) / o.Height);

  // The mappers in the order given (by default HAVS, PT, ZSweep, RayCast).
  Platform platform;
  std::vector<MapperRun> runs;
  const double mappersStart = Now();
  for (const std::string& key : o.Mappers)
  {
    MapperRun run;
    vtkSmartPointer<vtkUnstructuredGridVolumeMapper> mapper = MakeMapper(key, o, run);
    if (!RunMapper(mapper, run, grid, property, firstCamera, o, errors, platform))
    {
      std::cerr << "havs_demo: " << run.Name << " failed." << std::endl;
      return EXIT_FAILURE;
    }
    runs.push_back(std::move(run));
  }
  const double mappersSeconds = Now() - mappersStart;

  double referenceSeconds = 0.0;
  const std::vector<float> exact =
    RenderReference(grid, property, firstCamera, o, errors, referenceSeconds);
  if (exact.empty() || errors->Count > 0)
  {
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkFloatArray> exactSeen = SeenColour(exact);
  for (MapperRun& run : runs)
  {
    MeasureError(run, exactSeen, o.Amplification);
  }

  PrintSetup(scene, o, platform, runs, referenceSeconds);
  PrintTable(runs, grid->GetNumberOfCells());

  const Summary summary = Summarize(scene, o, platform, referenceSeconds);
  if (!WritePicture(runs, exact, summary, o))
  {
    std::cerr << "havs_demo: could not write " << o.Output << std::endl;
    return EXIT_FAILURE;
  }
  std::printf("\nPicture (exact reference | ");
  for (size_t i = 0; i < runs.size(); ++i)
  {
    std::printf("%s%s", runs[i].Name.c_str(), i + 1 < runs.size() ? " | " : "");
  }
  std::printf("; below: errors x%g): %s\n", o.Amplification, o.Output.c_str());
  std::printf("Total %.0f s: load %.1f s, mappers %.1f s, exact reference %.1f s.\n",
    Now() - programStart, loadSeconds, mappersSeconds, referenceSeconds);
  return errors->Count == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
