/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSDataSets.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSDataSets.h"

#include "vtkActor.h"
#include "vtkAppendFilter.h"
#include "vtkCallbackCommand.h"
#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkExtractCells.h"
#include "vtkHAVSGeneratedBlock.h"
#include "vtkHAVSTetrahedralizer.h"
#include "vtkHAVSVTKCompat.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkThreshold.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unistd.h>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSDataSets);

namespace
{
bool Readable(const std::string& path)
{
  return std::ifstream(path).good();
}

/// Counts the errors a reader reports, so that a file it could only partly
/// read is not taken for a mesh.
struct ReaderErrors
{
  int Count = 0;
  vtkNew<vtkCallbackCommand> Callback;
  explicit ReaderErrors(vtkObject* reader)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long, void* self, void*)
      { ++static_cast<ReaderErrors*>(self)->Count; });
    reader->AddObserver(vtkCommand::ErrorEvent, this->Callback);
  }
};

/**
 * While a VTK reader runs: a crash inside it (SIGSEGV, SIGBUS, SIGFPE, SIGILL,
 * or SIGABRT from a corrupted heap, on a corrupt file) is reported as such, naming the file, and
 * the process exits with status 3 instead of dying without a word. The previous handlers come back
 * afterwards. (A reader's crash cannot be recovered from: its state is unknown.)
 */
class ReaderCrashGuard
{
public:
  explicit ReaderCrashGuard(const std::string& path)
  {
    std::snprintf(Message(), kMessageSize,
      "vtkHAVSDataSets: VTK's reader crashed reading %s (a corrupt or truncated file?); "
      "exiting.\n",
      path.c_str());
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = &ReaderCrashGuard::OnCrash;
    sigemptyset(&action.sa_mask);
    for (int i = 0; i < kSignals; ++i)
    {
      sigaction(Signals()[i], &action, &this->Previous[i]);
    }
  }
  ~ReaderCrashGuard()
  {
    for (int i = 0; i < kSignals; ++i)
    {
      sigaction(Signals()[i], &this->Previous[i], nullptr);
    }
  }
  ReaderCrashGuard(const ReaderCrashGuard&) = delete;
  void operator=(const ReaderCrashGuard&) = delete;

private:
  static constexpr int kSignals = 5;
  static constexpr size_t kMessageSize = 4096;
  static const int* Signals()
  {
    static const int signals[kSignals] = { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT };
    return signals;
  }
  static char* Message()
  {
    static char message[kMessageSize];
    return message;
  }
  static void OnCrash(int)
  {
    // Only async-signal-safe calls here.
    const char* message = Message();
    ssize_t unused = write(2, message, std::strlen(message));
    (void)unused;
    _exit(3);
  }
  struct sigaction Previous[kSignals];
};

/**
 * A legacy .vtk file's declared counts (POINTS, CELLS, CELL_TYPES, OFFSETS,
 * CONNECTIVITY, POINT_DATA, CELL_DATA) checked against the file's size before
 * VTK's reader sees them: a count that is negative or needs more values than
 * the file has bytes makes the reader allocate absurd arrays or read past
 * what it allocated (VTK 9.2's reader corrupts its heap on `CELLS 2000000000`).
 * False with `why` for such a file.
 */
bool LegacyCountsPlausible(const std::string& path, std::string& why)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const long long bytes = static_cast<long long>(in.tellg());
  in.seekg(0);
  std::string line;
  int lines = 0;
  while (std::getline(in, line) && ++lines < 1000000)
  {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    static const char* const keywords[] = { "POINTS", "CELLS", "CELL_TYPES", "OFFSETS",
      "CONNECTIVITY", "POINT_DATA", "CELL_DATA" };
    bool counted = false;
    for (const char* k : keywords)
    {
      counted = counted || keyword == k;
    }
    if (!counted)
    {
      continue;
    }
    long long count = 0;
    if (!(words >> count))
    {
      continue; // e.g. "OFFSETS vtktypeint64": the count came on the CELLS line
    }
    // POINTS n: 3n values; CELLS n size: size values; the others: n values.
    long long values = keyword == "POINTS" ? 3 * count : count;
    long long size = 0;
    if (keyword == "CELLS" && (words >> size))
    {
      values = std::max(count, size);
    }
    if (count < 0 || size < 0 || values > bytes)
    {
      std::ostringstream text;
      text << "it declares " << keyword << " " << count << (size != 0 ? " " : "")
           << (size != 0 ? std::to_string(size) : std::string()) << ", "
           << (count < 0 || size < 0
                  ? "a negative count"
                  : "more values than a file of " + std::to_string(bytes) + " bytes holds");
      why = text.str();
      return false;
    }
  }
  return true;
}

/// Whether `data` has point or cell scalars (or any array to make them from).
bool HasArrays(vtkDataSet* data)
{
  return data->GetPointData()->GetNumberOfArrays() > 0 ||
    data->GetCellData()->GetNumberOfArrays() > 0;
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
  threshold->Update();
  auto grid = vtkHAVSDataSets::Tetrahedralize(threshold->GetOutput());
  grid->GetPointData()->SetActiveScalars("RTData");
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> HollowSphere()
{
  auto box = vtkHAVSDataSets::MakeBox(16, 16, 16, 1.0 / 16, 0.0, 1.0);
  return vtkHAVSDataSets::KeepCells(box,
    [](const double* c)
    {
      const double r = std::sqrt(
        (c[0] - 0.5) * (c[0] - 0.5) + (c[1] - 0.5) * (c[1] - 0.5) + (c[2] - 0.5) * (c[2] - 0.5));
      return r > 0.22 && r < 0.48;
    });
}

vtkSmartPointer<vtkUnstructuredGrid> Torus()
{
  auto box = vtkHAVSDataSets::MakeBox(24, 24, 12, 1.0 / 24, 0.0, 2.0);
  return vtkHAVSDataSets::KeepCells(box,
    [](const double* c)
    {
      const double ring = std::sqrt((c[0] - 0.5) * (c[0] - 0.5) + (c[1] - 0.5) * (c[1] - 0.5));
      return (ring - 0.32) * (ring - 0.32) + (c[2] - 0.25) * (c[2] - 0.25) < 0.13 * 0.13;
    });
}

/// Two 1 x 1 x 1 blocks of 6^3 cubes (longest edge 0.29) with a gap of 0.08
/// between them along x.
vtkSmartPointer<vtkUnstructuredGrid> TwoBlocks()
{
  auto a = vtkHAVSDataSets::MakeBox(6, 6, 6, 1.0 / 6, 0.0, 1.0);
  auto b = vtkHAVSDataSets::MakeBox(6, 6, 6, 1.0 / 6, 0.0, 1.0);
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

struct RealDataSet
{
  const char* Name;
  const char* Stem; // PLOT3D: <stem>xyz.bin, <stem>q.bin; empty: post.vtk
  int Function;
};
const RealDataSet kRealDataSets[] = { { "bluntfin", "bluntfin", 100 }, { "loxpost", "post", 110 },
  { "combustor", "comb", 100 }, { "loxpostvtk", "", 0 } };
const char* const kMadeHere[] = { "gen1M", "gen4M", "gen10M", "box", "wavelet", "hollowsphere",
  "torus", "twoblocks" };
}

//------------------------------------------------------------------------------
std::string vtkHAVSDataSets::GetDataDirectory()
{
  const char* d = std::getenv("HAVS_DATA_DIR");
  return d && *d ? d : "../shared/data";
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkHAVSDataSets::GetNames()
{
  std::vector<std::string> names;
  for (const RealDataSet& d : kRealDataSets)
  {
    names.emplace_back(d.Name);
  }
  names.insert(names.end(), std::begin(kMadeHere), std::end(kMadeHere));
  return names;
}

//------------------------------------------------------------------------------
bool vtkHAVSDataSets::IsRealDataSet(const std::string& name)
{
  for (const RealDataSet& d : kRealDataSets)
  {
    if (name == d.Name)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSDataSets::Load(const std::string& name)
{
  const std::string dir = GetDataDirectory();
  for (const RealDataSet& d : kRealDataSets)
  {
    if (name != d.Name)
    {
      continue;
    }
    if (!*d.Stem)
    {
      return ReadFile(dir + "/post.vtk", "Pressure");
    }
    return ReadPlot3D(dir + "/" + d.Stem + "xyz.bin", dir + "/" + d.Stem + "q.bin", d.Function);
  }
  if (const int cubes = vtkHAVSGeneratedBlock::CubesOf(name))
  {
    return MakeGenerated(cubes);
  }
  if (name == "box")
  {
    return MakeBox(8, 8, 8, 0.125, 0.0, 1.0);
  }
  if (name == "wavelet")
  {
    return ThresholdedWavelet();
  }
  if (name == "hollowsphere")
  {
    return HollowSphere();
  }
  if (name == "torus")
  {
    return Torus();
  }
  if (name == "twoblocks")
  {
    return TwoBlocks();
  }
  vtkGenericWarningMacro("vtkHAVSDataSets: unknown data set '" << name << "'.");
  return nullptr;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSDataSets::ReadFile(
  const std::string& path, const std::string& array)
{
  if (!Readable(path))
  {
    vtkGenericWarningMacro("vtkHAVSDataSets: cannot open " << path);
    return nullptr;
  }
  vtkSmartPointer<vtkDataSet> data;
  const bool xml = path.size() > 4 && path.substr(path.size() - 4) == ".vtu";
  int readerErrors = 0;
  if (xml)
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    ReaderErrors errors(reader);
    reader->SetFileName(path.c_str());
    ReaderCrashGuard guard(path);
    reader->Update();
    data = reader->GetOutput();
    readerErrors = errors.Count;
  }
  else
  {
    std::string why;
    if (!LegacyCountsPlausible(path, why))
    {
      vtkGenericWarningMacro(
        "vtkHAVSDataSets: " << path << " is corrupt: " << why << "; not read.");
      return nullptr;
    }
    vtkNew<vtkUnstructuredGridReader> reader;
    ReaderErrors errors(reader);
    reader->SetFileName(path.c_str());
    ReaderCrashGuard guard(path);
    reader->Update();
    data = reader->GetOutput();
    readerErrors = errors.Count;
  }
  if (readerErrors > 0)
  {
    vtkGenericWarningMacro(
      "vtkHAVSDataSets: the reader reported " << readerErrors << " errors reading " << path);
    return nullptr;
  }
  if (!data || data->GetNumberOfCells() == 0)
  {
    vtkGenericWarningMacro("vtkHAVSDataSets: no cells read from " << path);
    return nullptr;
  }
  if (!HasArrays(data))
  {
    vtkGenericWarningMacro("vtkHAVSDataSets: " << path
                                               << " has no point or cell array to render (a "
                                                  "truncated file?)");
    return nullptr;
  }
  vtkPointData* pd = data->GetPointData();
  if (!array.empty())
  {
    if (!pd->GetArray(array.c_str()))
    {
      vtkGenericWarningMacro("vtkHAVSDataSets: " << path << " has no point array " << array);
      return nullptr;
    }
    pd->SetActiveScalars(array.c_str());
  }
  else if (!pd->GetScalars() && pd->GetNumberOfArrays() > 0)
  {
    pd->SetActiveScalars(pd->GetArrayName(0));
  }
  // Cells of a type VTK does not know (a corrupt type id): said, then left to
  // the split (which drops them).
  vtkIdType unknown = 0;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    unknown +=
      std::strcmp(havs_vtk::CellTypeClassName(data->GetCellType(c)), "UnknownClass") == 0 ? 1 : 0;
  }
  if (unknown > 0)
  {
    vtkGenericWarningMacro("vtkHAVSDataSets: " << path << ": " << unknown
                                               << " cells of a type VTK does not know; left out.");
  }
  // A grid of tetrahedra only is taken as it is (points and cells in order).
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  bool tetrahedra = grid != nullptr;
  for (vtkIdType c = 0; tetrahedra && c < grid->GetNumberOfCells(); ++c)
  {
    tetrahedra = grid->GetCellType(c) == VTK_TETRA;
  }
  if (tetrahedra)
  {
    return grid; // cells with point ids out of range: the mappers skip them, with a warning
  }
  // Other cells: split as the mappers split them, cells with point ids out of
  // range left out first (VTK's split would read past the points).
  vtkHAVSTetrahedralizer::Report report;
  auto split = vtkHAVSTetrahedralizer::Tetrahedralize(data, &report);
  if (report.InvalidCells > 0)
  {
    vtkGenericWarningMacro("vtkHAVSDataSets: " << path << ": " << report.InvalidCells
                                               << " cells refer to points that do not exist "
                                                  "and were left out.");
  }
  return split;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSDataSets::ReadPlot3D(
  const std::string& xyzPath, const std::string& qPath, int function)
{
  for (const std::string& path : { xyzPath, qPath })
  {
    if (!Readable(path))
    {
      vtkGenericWarningMacro("vtkHAVSDataSets: cannot open " << path);
      return nullptr;
    }
  }
  vtkNew<vtkMultiBlockPLOT3DReader> reader;
  ReaderErrors errors(reader);
  reader->SetXYZFileName(xyzPath.c_str());
  reader->SetQFileName(qPath.c_str());
  reader->AutoDetectFormatOn();
  reader->SetScalarFunctionNumber(function);
  {
    ReaderCrashGuard guard(xyzPath);
    reader->Update();
  }
  if (errors.Count > 0)
  {
    vtkGenericWarningMacro("vtkHAVSDataSets: the reader reported "
      << errors.Count << " errors reading " << xyzPath << " and " << qPath);
    return nullptr;
  }
  vtkDataSet* block = reader->GetOutput() && reader->GetOutput()->GetNumberOfBlocks() > 0
    ? vtkDataSet::SafeDownCast(reader->GetOutput()->GetBlock(0))
    : nullptr;
  if (!block || block->GetNumberOfCells() == 0)
  {
    vtkGenericWarningMacro("vtkHAVSDataSets: no grid read from " << xyzPath << " and " << qPath);
    return nullptr;
  }
  return Tetrahedralize(block);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSDataSets::Tetrahedralize(vtkDataSet* data)
{
  if (!data)
  {
    return nullptr;
  }
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(data);
  tets->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = tets->GetOutput();
  return grid;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSDataSets::MakeBox(
  int nx, int ny, int nz, double h, double a, double b)
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
  return Tetrahedralize(image);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkActor> vtkHAVSDataSets::MakeTranslucentPlane(vtkDataSet* data)
{
  double center[3];
  data->GetCenter(center);
  const double extent = 1.6 * data->GetLength();
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.5 * extent, -0.5 * extent, 0.0);
  plane->SetPoint1(0.5 * extent, -0.5 * extent, 0.0);
  plane->SetPoint2(-0.5 * extent, 0.5 * extent, 0.0);
  plane->SetResolution(8, 8);
  plane->SetCenter(center);
  plane->SetNormal(0.3, 0.45, 1.0);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.2, 0.8, 0.9);
  actor->GetProperty()->SetOpacity(0.45);
  return actor;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSDataSets::MakeGenerated(int n)
{
  return Tetrahedralize(vtkHAVSGeneratedBlock::Make(n)); // (tetrahedra: taken as they are)
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSDataSets::KeepCells(
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

//------------------------------------------------------------------------------
void vtkHAVSDataSets::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DataDirectory: " << GetDataDirectory() << "\n";
}

VTK_ABI_NAMESPACE_END
