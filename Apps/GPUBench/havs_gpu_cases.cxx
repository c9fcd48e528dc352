/*=========================================================================

  Project:   vtkHAVS
  Module:    havs_gpu_cases.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_gpu_cases: a frame case's large arrays, made again where the case was
// carried without them (issue 47).
//
//   havs_gpu_cases CASE_DIR... [--check]
//
// A case written by `havs_benchmark --dump-case` holds the frame's camera,
// transfer functions, mapper and mesh (a .havsmesh file beside the case, or
// "mesh generated N": the benchmark's procedural block, made here from
// vtkHAVSGeneratedBlock.h). This program renders that frame through the
// GL-free core mappers of vtkHAVS::Core (no OpenGL, no window): their draw
// writes the arrays the GPU would have drawn from instead of drawing them
// (Apps/GPUBench/README.md) and the pre-integration table: HAVS's vertices
// with the boundary faces' own and its faces in draw order; the cell projection's points,
// tetrahedra, windings, cell records and order; the ray caster's points, boundary, neighbours and
// cell records. The same core code made them where the case was captured, so havs_gpu_bench then
// draws the captured frame. A table case (mapper table): the CPU's table, timed, and the inputs
// of the GPU's build of it (MakeTableCase).
// --check: compare with the arrays already in the case instead of writing
// (each file byte for byte; exits 1 on a difference).
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSGeneratedBlock.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSRayCastMesh.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
/// Where the mappers' draws write: the case directory, or a check of it.
struct Sink
{
  std::string Dir;
  bool Check = false;
  int Written = 0;
  int Differences = 0;

  template <typename T>
  void Put(const std::string& name, const std::vector<T>& values)
  {
    const std::string path = this->Dir + "/" + name;
    const char* bytes = reinterpret_cast<const char*>(values.data());
    const size_t size = values.size() * sizeof(T);
    if (this->Check)
    {
      std::ifstream in(path, std::ios::binary);
      std::string old((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      const bool same = old.size() == size && std::memcmp(old.data(), bytes, size) == 0;
      std::printf("  %s: %s (%zu bytes)\n", name.c_str(), same ? "the same" : "DIFFERS", size);
      this->Differences += same ? 0 : 1;
    }
    else
    {
      std::ofstream(path, std::ios::binary).write(bytes, static_cast<std::streamsize>(size));
    }
    ++this->Written;
  }

  /// The pre-integration table as the GPU holds it (vtkHAVSGLTable uploads
  /// the core table's floats as they are).
  void PutTable(vtkHAVSPreIntegrationTable* table)
  {
    const size_t n = static_cast<size_t>(table->GetScalarResolution()) *
      table->GetScalarResolution() * table->GetLengthResolution() * 4;
    this->Put("table.f32", std::vector<float>(table->GetTable(), table->GetTable() + n));
  }
};

// --- the core mappers, drawing into files ------------------------------------------
class CaseHAVSMapper : public vtkHAVSVolumeMapper
{
public:
  static CaseHAVSMapper* New();
  vtkTypeMacro(CaseHAVSMapper, vtkHAVSVolumeMapper);
  Sink* Out = nullptr;
  bool IsKBufferPathSupported(vtkRenderWindow*, int path) override
  {
    return path == KBufferPathFramebufferFetch;
  }

protected:
  int ChooseKBufferPath(vtkRenderer*, int) override { return KBufferPathFramebufferFetch; }
  int GetMaximumK(int) override { return 64; }
  bool CompositeKeptResult(vtkRenderer*) override { return true; }
  bool DrawFrame(vtkRenderer*, const FrameRequest& request, FrameResult&) override
  {
    // As vtkHAVSGLMesh uploads them: the mesh's vertices, then the boundary
    // faces' own (tagging on), the faces in draw order.
    const vtkHAVSMesh& mesh = *request.Mesh;
    std::vector<float> points = mesh.GetVertexPoints(), scalars = mesh.GetVertexScalars();
    std::vector<float> taggedPoints, taggedScalars;
    std::vector<uint32_t> indices;
    if (!request.Tagging ||
      vtkHAVSMesh::MakeTaggedVertices(points, scalars, mesh.GetVertexScalarComponents(),
        *request.DrawTriangles, *request.DrawBoundary, taggedPoints, taggedScalars, indices) == 0)
    {
      indices = *request.DrawTriangles;
    }
    points.insert(points.end(), taggedPoints.begin(), taggedPoints.end());
    scalars.insert(scalars.end(), taggedScalars.begin(), taggedScalars.end());
    this->Out->Put("points.f32", points);
    this->Out->Put("scalars.f32", scalars);
    this->Out->Put("indices.u32", indices);
    this->Out->PutTable(request.Table);
    return true;
  }
};
vtkStandardNewMacro(CaseHAVSMapper);

class CaseCellProjectionMapper : public vtkHAVSCellProjectionMapper
{
public:
  static CaseCellProjectionMapper* New();
  vtkTypeMacro(CaseCellProjectionMapper, vtkHAVSCellProjectionMapper);
  Sink* Out = nullptr;

protected:
  bool DrawCells(vtkRenderer*, const CellFrame& frame, double* drawSeconds) override
  {
    if (frame.Cells->empty() && frame.RestoreCells)
    {
      frame.RestoreCells();
    }
    this->Out->Put("points.f32", frame.Mesh->GetPoints());
    this->Out->Put("tetrahedra.u32", *frame.Tetrahedra);
    this->Out->Put("mirrored.u32", *frame.Mirrored);
    this->Out->Put("cells.f32", *frame.Cells);
    this->Out->Put("order.u32", *frame.Order);
    this->Out->PutTable(frame.Table);
    *drawSeconds = 0.0;
    return true;
  }
};
vtkStandardNewMacro(CaseCellProjectionMapper);

class CaseRayCastMapper : public vtkHAVSRayCastMapper
{
public:
  static CaseRayCastMapper* New();
  vtkTypeMacro(CaseRayCastMapper, vtkHAVSRayCastMapper);
  Sink* Out = nullptr;

protected:
  bool DrawRays(vtkRenderer*, const RayFrame& frame, RayCounts*) override
  {
    const vtkHAVSRayCastMesh& mesh = *frame.RayMesh;
    if (mesh.GetCells().empty() && mesh.GetNumberOfTetrahedra() > 0 && frame.RestoreCells)
    {
      frame.RestoreCells();
    }
    this->Out->Put("points.f32", frame.Mesh->GetPoints());
    this->Out->Put("boundary_faces.u32", mesh.GetBoundaryFaces());
    this->Out->Put("boundary_cells.u32", mesh.GetBoundaryCells());
    this->Out->Put("neighbours.i32", mesh.GetNeighbours());
    this->Out->Put("cells.f32", mesh.GetCells());
    this->Out->PutTable(frame.Table);
    return true;
  }
};
vtkStandardNewMacro(CaseRayCastMapper);

/// A volume without a shader property: VTK's is an OpenGL class (its base
/// has no instance without vtkRenderingOpenGL2), and no case has one.
class CaseVolume : public vtkVolume
{
public:
  static CaseVolume* New();
  vtkTypeMacro(CaseVolume, vtkVolume);
  vtkShaderProperty* GetShaderProperty() override { return nullptr; }
};
vtkStandardNewMacro(CaseVolume);

// --- the case's description ----------------------------------------------------------
struct Description
{
  std::map<std::string, std::vector<std::string>> Keys; // every line's words by its key
  std::string First(const std::string& key) const
  {
    auto it = this->Keys.find(key);
    return it == this->Keys.end() || it->second.empty() ? "" : it->second.front();
  }
  std::vector<double> Numbers(const std::string& key) const
  {
    std::vector<double> v;
    std::istringstream words(this->First(key));
    double x;
    while (words >> x)
    {
      v.push_back(x);
    }
    return v;
  }
};

bool ReadDescription(const std::string& dir, Description& d)
{
  std::ifstream in(dir + "/case.txt");
  if (!in)
  {
    std::fprintf(stderr, "havs_gpu_cases: cannot read %s/case.txt\n", dir.c_str());
    return false;
  }
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream words(line);
    std::string key, rest;
    if (!(words >> key) || key[0] == '#' || key == "uniform")
    {
      continue;
    }
    std::getline(words, rest);
    const size_t first = rest.find_first_not_of(' ');
    d.Keys[key].push_back(first == std::string::npos ? "" : rest.substr(first));
  }
  return true;
}

/// A .havsmesh file (havs_benchmark --dump-case): a text line "havsmesh 1
/// points P tetrahedra C scalars point|cell", then P x 3 doubles, C x 4
/// uint32 point ids, P or C doubles.
vtkSmartPointer<vtkUnstructuredGrid> ReadMesh(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string header;
  if (!std::getline(in, header))
  {
    std::fprintf(stderr, "havs_gpu_cases: cannot read %s\n", path.c_str());
    return nullptr;
  }
  std::istringstream words(header);
  std::string magic, p, c, s, association;
  int version = 0;
  long long points = 0, cells = 0;
  words >> magic >> version >> p >> points >> c >> cells >> s >> association;
  if (magic != "havsmesh" || version != 1 || points <= 0 || cells <= 0)
  {
    std::fprintf(stderr, "havs_gpu_cases: %s is not a .havsmesh file\n", path.c_str());
    return nullptr;
  }
  std::vector<double> xyz(3 * static_cast<size_t>(points));
  std::vector<uint32_t> ids(4 * static_cast<size_t>(cells));
  const bool onCells = association == "cell";
  std::vector<double> values(static_cast<size_t>(onCells ? cells : points));
  in.read(reinterpret_cast<char*>(xyz.data()), static_cast<std::streamsize>(xyz.size() * 8));
  in.read(reinterpret_cast<char*>(ids.data()), static_cast<std::streamsize>(ids.size() * 4));
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(values.size() * 8));
  if (!in)
  {
    std::fprintf(stderr, "havs_gpu_cases: %s is cut short\n", path.c_str());
    return nullptr;
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(points);
  std::memcpy(pts->GetVoidPointer(0), xyz.data(), xyz.size() * 8);
  grid->SetPoints(pts);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(cells + 1);
  connectivity->SetNumberOfValues(4 * cells);
  for (long long i = 0; i <= cells; ++i)
  {
    offsets->SetValue(i, 4 * i);
  }
  for (size_t i = 0; i < ids.size(); ++i)
  {
    connectivity->SetValue(static_cast<vtkIdType>(i), ids[i]);
  }
  vtkNew<vtkCellArray> cellArray;
  cellArray->SetData(offsets, connectivity);
  grid->SetCells(VTK_TETRA, cellArray);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("scalars");
  scalars->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::memcpy(scalars->GetVoidPointer(0), values.data(), values.size() * 8);
  if (onCells)
  {
    grid->GetCellData()->SetScalars(scalars);
  }
  else
  {
    grid->GetPointData()->SetScalars(scalars);
  }
  return grid;
}

vtkSmartPointer<vtkVolumeProperty> MakeProperty(const Description& d)
{
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  const auto colors = d.Keys.find("tf_color");
  const auto opacities = d.Keys.find("tf_opacity");
  if (colors == d.Keys.end() || opacities == d.Keys.end())
  {
    return nullptr;
  }
  for (const std::string& line : colors->second)
  {
    double x, r, g, b, mid, sharp;
    std::istringstream(line) >> x >> r >> g >> b >> mid >> sharp;
    color->AddRGBPoint(x, r, g, b, mid, sharp);
  }
  for (const std::string& line : opacities->second)
  {
    double x, y, mid, sharp;
    std::istringstream(line) >> x >> y >> mid >> sharp;
    opacity->AddPoint(x, y, mid, sharp);
  }
  color->SetColorSpace(std::atoi(d.First("tf_color_space").c_str()));
  color->SetClamping(std::atoi(d.First("tf_clamping").c_str()));
  opacity->SetClamping(std::atoi(d.First("tf_clamping").c_str()));
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(std::atof(d.First("tf_unit_distance").c_str()));
  property->SetShade(std::atoi(d.First("tf_shade").c_str()));
  property->SetInterpolationType(std::atoi(d.First("tf_interpolation").c_str()));
  return property;
}

bool PlaceCamera(const Description& d, vtkCamera* camera)
{
  const std::vector<double> position = d.Numbers("camera_position"),
                            focal = d.Numbers("camera_focal_point"),
                            up = d.Numbers("camera_view_up"),
                            range = d.Numbers("camera_clipping_range");
  if (position.size() != 3 || focal.size() != 3 || up.size() != 3 || range.size() != 2)
  {
    return false;
  }
  camera->SetPosition(position.data());
  camera->SetFocalPoint(focal.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(std::atof(d.First("camera_view_angle").c_str()));
  camera->SetParallelProjection(std::atoi(d.First("camera_parallel").c_str()));
  camera->SetParallelScale(std::atof(d.First("camera_parallel_scale").c_str()));
  camera->SetClippingRange(range.data());
  return true;
}

/// The case's mesh: its file beside the case, or the generated block (kept
/// for the next case of the same mesh).
vtkSmartPointer<vtkUnstructuredGrid> MeshOf(const std::string& dir, const Description& d,
  std::map<std::string, vtkSmartPointer<vtkUnstructuredGrid>>& meshes)
{
  const std::string mesh = d.First("mesh");
  auto it = meshes.find(mesh);
  if (it != meshes.end())
  {
    return it->second;
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  const double t0 = vtkTimerLog::GetUniversalTime();
  if (mesh.rfind("generated ", 0) == 0)
  {
    grid = vtkHAVSGeneratedBlock::Make(std::atoi(mesh.c_str() + 10));
  }
  else if (!mesh.empty())
  {
    const size_t slash = dir.find_last_of('/');
    grid =
      ReadMesh((slash == std::string::npos ? std::string(".") : dir.substr(0, slash)) + "/" + mesh);
  }
  if (grid)
  {
    std::printf("mesh %s: %lld tetrahedra, %lld points (%.2f s)\n", mesh.c_str(),
      static_cast<long long>(grid->GetNumberOfCells()),
      static_cast<long long>(grid->GetNumberOfPoints()), vtkTimerLog::GetUniversalTime() - t0);
    meshes[mesh] = grid;
  }
  return grid;
}

/**
 * A table case (mapper table, issue 45): the pre-integrated table of the
 * case's functions at its size, range and longest segment, built here on the
 * CPU (table.f32; its median build time of 5 in cpu_table_ms.txt), and the
 * inputs of the GPU's build (vtkHAVSPreIntegrationTable::Quadrature):
 * samples.f32 (tau, r, g, b a fine sample), steps.f32, table_samples.i32,
 * layers.f32.
 */
bool MakeTableCase(const std::string& dir, const Description& d, bool check, int* differences)
{
  vtkSmartPointer<vtkVolumeProperty> property = MakeProperty(d);
  const std::vector<double> size = d.Numbers("table");
  const std::vector<double> range = d.Numbers("scalar_range");
  const double maxLength = std::atof(d.First("max_length").c_str());
  if (!property || size.size() != 3 || range.size() != 2 || !(maxLength > 0.0))
  {
    std::fprintf(stderr,
      "havs_gpu_cases: %s: a table case needs tf_* lines, table, scalar_range and max_length\n",
      dir.c_str());
    return false;
  }
  vtkNew<vtkHAVSPreIntegrationTable> table;
  table->SetScalarResolution(static_cast<int>(size[0]));
  table->SetLengthResolution(static_cast<int>(size[2]));
  vtkHAVSPreIntegrationTable::Quadrature inputs;
  table->SetEntryBuilder(
    [&inputs](const vtkHAVSPreIntegrationTable::Quadrature& q, float*)
    {
      inputs = q;
      return false; // built here, on the CPU
    });
  std::vector<double> seconds;
  for (int i = 0; i < 5; ++i)
  {
    if (!table->Build(property, 0, range.data(), maxLength))
    {
      return false;
    }
    seconds.push_back(table->GetLastBuildSeconds());
  }
  std::sort(seconds.begin(), seconds.end());
  Sink sink;
  sink.Dir = dir;
  sink.Check = check;
  sink.PutTable(table);
  sink.Put("samples.f32", inputs.Samples);
  sink.Put("steps.f32", inputs.StepDepth);
  sink.Put("table_samples.i32", inputs.TableSample);
  sink.Put("layers.f32", inputs.LayerLength);
  std::ofstream(dir + "/cpu_table_ms.txt") << 1e3 * seconds[2] << "\n";
  std::printf("%s: table %d x %d x %d, %zu fine samples, %d arrays %s\n  CPU: table %.2f ms "
              "(median of 5; vtkSMPTools %s, %d threads)\n",
    dir.c_str(), table->GetBuiltScalarResolution(), table->GetBuiltScalarResolution(),
    table->GetBuiltLengthResolution(), inputs.Samples.size() / 4, sink.Written,
    check ? "checked" : "written", 1e3 * seconds[2], vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  *differences += sink.Differences;
  return true;
}

/// One case's arrays written (or checked); false when the case cannot be made.
bool MakeCase(const std::string& dir, bool check,
  std::map<std::string, vtkSmartPointer<vtkUnstructuredGrid>>& meshes, int* differences)
{
  Description d;
  if (!ReadDescription(dir, d))
  {
    return false;
  }
  const std::string mapperKind = d.First("mapper");
  if (mapperKind == "table")
  {
    return MakeTableCase(dir, d, check, differences);
  }
  const int width = std::atoi(d.First("width").c_str());
  const int height = std::atoi(d.First("height").c_str());
  vtkSmartPointer<vtkUnstructuredGrid> grid = MeshOf(dir, d, meshes);
  vtkSmartPointer<vtkVolumeProperty> property = MakeProperty(d);
  if (!grid || !property || width <= 0 || height <= 0)
  {
    std::fprintf(stderr,
      "havs_gpu_cases: %s: no mesh, transfer functions or size in case.txt (a case of "
      "havs_benchmark --dump-case names them)\n",
      dir.c_str());
    return false;
  }
  Sink sink;
  sink.Dir = dir;
  sink.Check = check;
  vtkSmartPointer<vtkHAVSMapperBase> mapper;
  if (mapperKind == "havs")
  {
    auto m = vtkSmartPointer<CaseHAVSMapper>::New();
    m->SetKBufferSize(std::atoi(d.First("k").c_str()));
    if (!d.First("havs_table_resolution").empty())
    {
      const int resolution = std::atoi(d.First("havs_table_resolution").c_str());
      m->AutomaticTableResolutionOff();
      m->SetTableScalarResolution(resolution);
      m->SetTableLengthResolution(resolution);
    }
    if (!d.First("havs_termination_opacity").empty())
    {
      m->SetEarlyRayTerminationOpacity(std::atof(d.First("havs_termination_opacity").c_str()));
    }
    m->Out = &sink;
    mapper = m;
  }
  else if (mapperKind == "cellprojection")
  {
    auto m = vtkSmartPointer<CaseCellProjectionMapper>::New();
    m->Out = &sink;
    mapper = m;
  }
  else if (mapperKind == "raycast")
  {
    auto m = vtkSmartPointer<CaseRayCastMapper>::New();
    m->Out = &sink;
    mapper = m;
  }
  else
  {
    std::fprintf(
      stderr, "havs_gpu_cases: %s: unknown mapper '%s'\n", dir.c_str(), mapperKind.c_str());
    return false;
  }
  // No OpenGL: VTK's base window and renderer give the size and the camera;
  // the mapper is rendered directly (the base renderer draws nothing).
  vtkNew<vtkRenderWindow> window;
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<CaseVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  if (!PlaceCamera(d, renderer->GetActiveCamera()))
  {
    std::fprintf(stderr, "havs_gpu_cases: %s: no camera in case.txt\n", dir.c_str());
    return false;
  }
  mapper->SetInputData(grid);
  const double t0 = vtkTimerLog::GetUniversalTime();
  mapper->Render(renderer, volume);
  std::printf("%s: %s, %d arrays %s (%.2f s)\n", dir.c_str(), mapperKind.c_str(), sink.Written,
    check ? "checked" : "written", vtkTimerLog::GetUniversalTime() - t0);
  // The CPU's part of the frame, reported apart from the GPU's draw.
  if (auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper))
  {
    vtkHAVSFrameStatistics* f = havs->GetLastFrameStatistics();
    std::printf("  CPU: mesh %.1f ms, table %.1f ms, order (sort) %.1f ms, gather %.1f ms\n",
      1e3 * f->GetMeshSeconds(), 1e3 * f->GetTableSeconds(), 1e3 * f->GetSortSeconds(),
      1e3 * f->GetGatherSeconds());
  }
  else if (auto* cells = vtkHAVSCellProjectionMapper::SafeDownCast(mapper))
  {
    std::printf("  CPU: order %.1f ms\n", 1e3 * cells->GetLastOrderSeconds());
  }
  *differences += sink.Differences;
  if (sink.Written == 0)
  {
    std::fprintf(
      stderr, "havs_gpu_cases: %s: the mapper drew nothing (see its errors)\n", dir.c_str());
    return false;
  }
  return true;
}
}

int main(int argc, char* argv[])
{
  std::vector<std::string> dirs;
  bool check = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--check")
      check = true;
    else if (a == "--help" || a[0] == '-')
    {
      std::printf("usage: havs_gpu_cases CASE_DIR... [--check]\n");
      return a == "--help" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
    else
    {
      std::string dir = a;
      while (dir.size() > 1 && dir.back() == '/')
      {
        dir.pop_back(); // the mesh file lies beside the case's directory
      }
      dirs.push_back(dir);
    }
  }
  std::printf("havs_gpu_cases: vtkSMPTools backend %s, %d threads\n",
    vtkSMPTools::GetBackend() ? vtkSMPTools::GetBackend() : "?",
    vtkSMPTools::GetEstimatedNumberOfThreads());
  std::map<std::string, vtkSmartPointer<vtkUnstructuredGrid>> meshes;
  int failures = 0, differences = 0;
  for (const std::string& dir : dirs)
  {
    failures += MakeCase(dir, check, meshes, &differences) ? 0 : 1;
  }
  if (check)
  {
    std::printf("havs_gpu_cases: %d arrays differ\n", differences);
  }
  return failures == 0 && differences == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
