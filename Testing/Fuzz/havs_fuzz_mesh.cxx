/*=========================================================================

  Project:   vtkHAVS
  Module:    havs_fuzz_mesh.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// A fuzz target over the GL-free mesh preparation (issue 20): the bytes
// become a small vtkUnstructuredGrid (points with any coordinates, NaN and
// infinities included; cells of any type with any point ids, out of range and
// negative included; point or cell scalars with any values), which goes
// through vtkHAVSMesh::Build (the split into tetrahedra, face extraction,
// scalars), the centroid sort and the MPVO order (with the boundary layers and
// with the convexification) from a view the bytes choose. Any outcome is
// fine but a crash, a hang or a sanitizer report; an order, when made, must
// hold every face once.
//
// Built two ways (Testing/CMakeLists.txt): with clang's libFuzzer
// (-fsanitize=fuzzer,address,undefined; `bash .ci/fuzz`), and with a plain
// main (HAVS_FUZZ_STANDALONE) that runs a fixed-seed series of random and
// mutated inputs, which the default suite runs (TestHAVSFuzzMesh).
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSVisibilityOrder.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace
{
/// Reads the fuzzer's bytes front to back; zeros once they run out.
class ByteReader
{
public:
  ByteReader(const uint8_t* data, size_t size)
    : Data(data)
    , Size(size)
  {
  }
  uint8_t Byte() { return this->At < this->Size ? this->Data[this->At++] : 0; }
  uint32_t Word()
  {
    uint32_t w = 0;
    for (int i = 0; i < 4; ++i)
    {
      w = (w << 8) | this->Byte();
    }
    return w;
  }
  /// Mostly small grid coordinates; now and then an extreme or special value.
  double Coordinate()
  {
    const uint8_t kind = this->Byte();
    switch (kind % 16)
    {
      case 0:
        return std::numeric_limits<double>::quiet_NaN();
      case 1:
        return std::numeric_limits<double>::infinity() * ((kind & 16) ? 1 : -1);
      case 2:
        return 1e30 * ((kind & 16) ? 1 : -1);
      case 3:
        return 1e-30 * (this->Byte() - 128);
      case 4:
      {
        float f;
        const uint32_t w = this->Word();
        std::memcpy(&f, &w, sizeof(f));
        return f;
      }
      default:
        return (this->Byte() % 8) * 0.25 + (kind & 32 ? 1e6 : 0.0);
    }
  }
  bool Done() const { return this->At >= this->Size; }

private:
  const uint8_t* Data;
  size_t Size;
  size_t At = 0;
};

const int kCellTypes[] = { VTK_TETRA, VTK_TETRA, VTK_TETRA, VTK_TETRA, VTK_HEXAHEDRON, VTK_WEDGE,
  VTK_PYRAMID, VTK_TRIANGLE, VTK_VOXEL, VTK_QUADRATIC_TETRA, VTK_LINE, VTK_POLYHEDRON };
const int kCellSizes[] = { 4, 4, 4, 4, 8, 6, 5, 3, 8, 10, 2, 4 };

vtkSmartPointer<vtkUnstructuredGrid> MakeGrid(ByteReader& in, bool& cellScalars)
{
  const int numberOfPoints = 1 + in.Byte() % 48;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int p = 0; p < numberOfPoints; ++p)
  {
    const double x = in.Coordinate(), y = in.Coordinate(), z = in.Coordinate();
    points->InsertNextPoint(x, y, z);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  // One input in four mixes in other cells (split by VTK's ordered
  // triangulator, which dominates the time); the rest are tetrahedra.
  const bool mixed = (in.Byte() & 3) == 0;
  const int numberOfCells = in.Byte() % 40;
  grid->Allocate(numberOfCells);
  vtkNew<vtkIdList> ids;
  for (int c = 0; c < numberOfCells; ++c)
  {
    const uint8_t pick = in.Byte();
    const int which = mixed ? pick % static_cast<int>(sizeof(kCellTypes) / sizeof(int)) : 0;
    if (kCellTypes[which] == VTK_POLYHEDRON)
    {
      continue; // needs a face stream: not a mesh file's usual content
    }
    ids->SetNumberOfIds(kCellSizes[which]);
    for (int i = 0; i < kCellSizes[which]; ++i)
    {
      const uint8_t b = in.Byte();
      vtkIdType id = b % numberOfPoints;
      if (b >= 250)
      {
        id = (b == 255) ? -1 - in.Byte() : numberOfPoints + in.Byte(); // out of range
      }
      ids->SetId(i, id);
    }
    grid->InsertNextCell(kCellTypes[which], ids);
  }
  cellScalars = (in.Byte() & 3) == 0;
  const vtkIdType count = cellScalars ? grid->GetNumberOfCells() : numberOfPoints;
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("s");
  scalars->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    scalars->SetValue(i, static_cast<float>(in.Coordinate()));
  }
  if (cellScalars)
  {
    grid->GetCellData()->SetScalars(scalars);
  }
  else
  {
    grid->GetPointData()->SetScalars(scalars);
  }
  return grid;
}

void Require(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "havs_fuzz_mesh: violated: %s\n", what);
    std::abort();
  }
}

/// A perspective look-at (30 degrees, 16 x 16 pixels) from `eye` along
/// `direction`, as the model -> clip matrix the mapper gives (row-major).
void LookAt(const double eye[3], const double direction[3], double clip[16])
{
  double f[3] = { direction[0], direction[1], direction[2] };
  const double fl = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  for (double& v : f)
  {
    v /= fl;
  }
  const double up[3] = { 0.0, 0.0, 1.0 };
  double r[3] = { f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2],
    f[0] * up[1] - f[1] * up[0] };
  const double rl = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  for (double& v : r)
  {
    v /= rl;
  }
  const double u[3] = { r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2],
    r[0] * f[1] - r[1] * f[0] };
  const double t = 1.0 / std::tan(15.0 * 3.14159265358979 / 180.0);
  const double n = 0.01, far = 1e4;
  const double view[3][4] = {
    { r[0], r[1], r[2], -(r[0] * eye[0] + r[1] * eye[1] + r[2] * eye[2]) },
    { u[0], u[1], u[2], -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]) },
    { -f[0], -f[1], -f[2], (f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2]) },
  };
  for (int c = 0; c < 4; ++c)
  {
    clip[0 * 4 + c] = t * view[0][c];
    clip[1 * 4 + c] = t * view[1][c];
    clip[2 * 4 + c] =
      -(far + n) / (far - n) * view[2][c] + (c == 3 ? -2.0 * far * n / (far - n) : 0.0);
    clip[3 * 4 + c] = -view[2][c];
  }
}

/// Every face exactly once.
void RequirePermutation(const std::vector<uint32_t>& order, vtkIdType faces, const char* what)
{
  Require(static_cast<vtkIdType>(order.size()) == faces, what);
  std::vector<char> seen(order.size(), 0);
  for (uint32_t f : order)
  {
    Require(f < order.size() && !seen[f], what);
    seen[f] = 1;
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static const bool quiet = []
  {
    vtkObject::GlobalWarningDisplayOff(); // bad input warns by design
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    return true;
  }();
  (void)quiet;
  ByteReader in(data, size);
  bool cellScalars = false;
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeGrid(in, cellScalars);
  const uint8_t view = in.Byte();

  vtkNew<vtkHAVSMesh> mesh;
  vtkHAVSMesh::ScalarSelection selection;
  if (!mesh->Build(grid, selection) || !mesh->IsValid())
  {
    return 0;
  }
  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const vtkIdType numberOfFaces = faces->GetNumberOfFaces();

  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  const double angle = view * (2.0 * 3.14159265358979 / 256.0);
  const double direction[3] = { std::cos(angle), std::sin(angle), (view & 1) ? 0.3 : -0.2 };
  double bounds[6];
  mesh->GetGrid()->GetBounds(bounds);
  double eye[3];
  for (int k = 0; k < 3; ++k)
  {
    const double centre = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
    const double extent = bounds[2 * k + 1] - bounds[2 * k];
    eye[k] = (std::isfinite(centre) ? centre : 0.0) -
      3.0 * (std::isfinite(extent) ? extent + 1.0 : 1.0) * direction[k];
  }
  const bool parallel = (view & 2) != 0;

  vtkNew<vtkHAVSFaceSorter> sorter;
  sorter->Sort(faces, identity, eye, direction, parallel);
  RequirePermutation(sorter->GetOrder(), numberOfFaces, "the centroid order holds every face once");

  for (int method : { vtkHAVSVisibilityOrder::NonConvexBoundaryLayers,
         vtkHAVSVisibilityOrder::NonConvexConvexification })
  {
    vtkNew<vtkHAVSVisibilityOrder> order;
    order->SetNonConvexMethod(method);
    double clip[16];
    LookAt(eye, direction, clip);
    order->SetViewSampling(clip, 16, 16);
    if (order->Build(faces, mesh->GetGrid()))
    {
      order->Sort(eye, direction, parallel);
      if (!order->GetOrder().empty())
      {
        RequirePermutation(
          order->GetOrder(), numberOfFaces, "the MPVO order holds every face once");
      }
    }
  }
  return 0;
}

#if defined(HAVS_FUZZ_STANDALONE)
// A fixed-seed series: random inputs of random length, and single-byte
// mutations of the previous input (what libFuzzer's simplest mutator does).
int main(int argc, char* argv[])
{
  const long runs = argc > 1 ? std::atol(argv[1]) : 20000;
  std::mt19937 rng(argc > 2 ? static_cast<unsigned>(std::atol(argv[2])) : 20261203u);
  std::vector<uint8_t> input;
  for (long run = 0; run < runs; ++run)
  {
    if (run % 4 == 0 || input.empty())
    {
      input.resize(1 + rng() % 600);
      for (auto& b : input)
      {
        b = static_cast<uint8_t>(rng());
      }
    }
    else
    {
      input[rng() % input.size()] = static_cast<uint8_t>(rng());
    }
    LLVMFuzzerTestOneInput(input.data(), input.size());
  }
  std::printf(
    "havs_fuzz_mesh: %ld inputs, no crash, every order a permutation of the faces\n", runs);
  return 0;
}
#endif
