/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSFaceSet.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSFaceSet: unique faces and boundary flags (single tet, two tets, a
// cube in 5 and in 6 tets, a non-manifold fan), outward winding also for
// inverted cells, degenerate and non-tetrahedral cells, failures, and a closed
// outward surface by the divergence theorem on tetrahedralized blocks (VTK's
// vtkDataSetTriangleFilter, and a shuffled, randomly inverted Kuhn grid).
#include "havsTestChecks.h"
#include "havsTestMessages.h"

#include "vtkDataSetTriangleFilter.h"
#include "vtkHAVSFaceSet.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

namespace
{
using Point = std::array<double, 3>;
using Cell = std::vector<vtkIdType>;

/// A grid of the given points; 4-point cells are tetrahedra, 8-point ones hexahedra.
vtkSmartPointer<vtkUnstructuredGrid> MakeGrid(
  const std::vector<Point>& points, const std::vector<Cell>& cells)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : points)
  {
    pts->InsertNextPoint(p.data());
  }
  grid->SetPoints(pts);
  grid->Allocate(static_cast<vtkIdType>(cells.size()));
  for (const auto& c : cells)
  {
    grid->InsertNextCell(
      c.size() == 4 ? VTK_TETRA : VTK_HEXAHEDRON, static_cast<vtkIdType>(c.size()), c.data());
  }
  return grid;
}

/// The unit cube's corners, corner i at (i & 1, (i >> 1) & 1, (i >> 2) & 1).
std::vector<Point> CubeCorners()
{
  std::vector<Point> corners;
  for (int i = 0; i < 8; ++i)
  {
    corners.push_back({ double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) });
  }
  return corners;
}

/// The cube in 5 tetrahedra: four corner tets around a central one.
std::vector<Cell> CubeInFive()
{
  return { { 0, 1, 2, 4 }, { 3, 1, 2, 7 }, { 5, 1, 4, 7 }, { 6, 2, 4, 7 }, { 1, 2, 4, 7 } };
}

/// The cube in 6 tetrahedra around the diagonal 0-7 (Kuhn).
std::vector<Cell> CubeInSix()
{
  return { { 0, 1, 3, 7 }, { 0, 1, 5, 7 }, { 0, 2, 3, 7 }, { 0, 2, 6, 7 }, { 0, 4, 5, 7 },
    { 0, 4, 6, 7 } };
}

/// The corners of boundary face f.
void FacePoints(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid, vtkIdType f, double p[3][3])
{
  for (int i = 0; i < 3; ++i)
  {
    grid->GetPoint(faces->GetFaceVertices()[3 * f + i], p[i]);
  }
}

/// (p1 - p0) x (p2 - p0): twice the area vector.
void FaceNormal(const double p[3][3], double n[3])
{
  double a[3], b[3];
  for (int k = 0; k < 3; ++k)
  {
    a[k] = p[1][k] - p[0][k];
    b[k] = p[2][k] - p[0][k];
  }
  vtkMath::Cross(a, b, n);
}

/// Boundary faces whose normal does not point away from `inside` (a point
/// inside a convex mesh).
int InwardFaces(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid, const double inside[3])
{
  int inward = 0;
  for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
  {
    if (!faces->GetBoundaryFlags()[f])
    {
      continue;
    }
    double p[3][3], n[3], d[3];
    FacePoints(faces, grid, f, p);
    FaceNormal(p, n);
    for (int k = 0; k < 3; ++k)
    {
      d[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0 - inside[k];
    }
    inward += vtkMath::Dot(n, d) > 0.0 ? 0 : 1;
  }
  return inward;
}

/// Over the boundary faces: the norm of the summed area vectors (0 for a
/// closed surface) and the divergence-theorem volume sum (c . n_area) / 3
/// (the enclosed volume when every normal points out).
struct SurfaceIntegrals
{
  double AreaVectorNorm = 0.0;
  double Volume = 0.0;
};
SurfaceIntegrals IntegrateBoundary(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid)
{
  double areaVector[3] = { 0, 0, 0 };
  SurfaceIntegrals result;
  for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
  {
    if (!faces->GetBoundaryFlags()[f])
    {
      continue;
    }
    double p[3][3], n[3], c[3];
    FacePoints(faces, grid, f, p);
    FaceNormal(p, n);
    for (int k = 0; k < 3; ++k)
    {
      c[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0;
      areaVector[k] += 0.5 * n[k];
    }
    result.Volume += vtkMath::Dot(c, n) / 6.0;
  }
  result.AreaVectorNorm = vtkMath::Norm(areaVector);
  return result;
}

/// Faces with the same point ids stored twice.
int DuplicateFaces(vtkHAVSFaceSet* faces)
{
  std::set<std::array<uint32_t, 3>> seen;
  int duplicates = 0;
  for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
  {
    std::array<uint32_t, 3> ids;
    std::copy_n(faces->GetFaceVertices().begin() + 3 * f, 3, ids.begin());
    std::sort(ids.begin(), ids.end());
    duplicates += seen.insert(ids).second ? 0 : 1;
  }
  return duplicates;
}

/// Largest distance between a stored centroid (plus the origin) and the
/// centroid computed in double.
double CentroidError(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid)
{
  double error = 0.0;
  const double* origin = faces->GetCentroidOrigin();
  for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
  {
    double p[3][3];
    FacePoints(faces, grid, f, p);
    for (int k = 0; k < 3; ++k)
    {
      const double exact = (p[0][k] + p[1][k] + p[2][k]) / 3.0;
      error = std::max(error, std::fabs(faces->GetCentroids()[3 * f + k] + origin[k] - exact));
    }
  }
  return error;
}

/// Checks the counts, uniqueness, consistency (4 uses per tet), outward
/// winding seen from `inside`, a closed surface and the enclosed volume.
void CheckConvexMesh(const std::string& name, vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid,
  vtkIdType tets, vtkIdType numFaces, vtkIdType boundary, const double inside[3], double volume)
{
  havstest::Check(faces->Build(grid), name + ": builds");
  havstest::Check(faces->GetNumberOfTetrahedra() == tets,
    name + ": tetrahedra " + std::to_string(faces->GetNumberOfTetrahedra()));
  havstest::Check(faces->GetNumberOfFaces() == numFaces,
    name + ": faces " + std::to_string(faces->GetNumberOfFaces()));
  havstest::Check(faces->GetNumberOfBoundaryFaces() == boundary,
    name + ": boundary faces " + std::to_string(faces->GetNumberOfBoundaryFaces()));
  const auto& flags = faces->GetBoundaryFlags();
  havstest::Check(std::count(flags.begin(), flags.end(), uint8_t(1)) == boundary,
    name + ": flags agree with the boundary count");
  havstest::Check(4 * tets == boundary + 2 * (numFaces - boundary),
    name + ": each internal face shared by two tets");
  havstest::Check(faces->GetNumberOfNonManifoldFaces() == 0, name + ": manifold");
  havstest::Check(DuplicateFaces(faces) == 0, name + ": each face stored once");
  havstest::Check(InwardFaces(faces, grid, inside) == 0, name + ": boundary faces wound outward");
  const SurfaceIntegrals s = IntegrateBoundary(faces, grid);
  havstest::CheckNear(s.AreaVectorNorm, 0.0, 1e-9 * volume, name + ": closed surface");
  havstest::CheckNear(s.Volume, volume, 1e-9 * volume, name + ": divergence theorem volume");
  havstest::Check(CentroidError(faces, grid) < 1e-6, name + ": centroids");
}

/// n^3 unit cubes, 6 Kuhn tetrahedra each, point ids shuffled, cells in random
/// order, and every other tetrahedron (at random) inverted.
vtkSmartPointer<vtkUnstructuredGrid> ShuffledKuhnGrid(int n, unsigned seed)
{
  std::mt19937 random(seed);
  const int np = n + 1;
  std::vector<vtkIdType> newId(static_cast<size_t>(np) * np * np);
  std::iota(newId.begin(), newId.end(), vtkIdType(0));
  std::shuffle(newId.begin(), newId.end(), random);
  std::vector<Point> points(newId.size());
  for (int k = 0; k < np; ++k)
  {
    for (int j = 0; j < np; ++j)
    {
      for (int i = 0; i < np; ++i)
      {
        points[newId[i + np * (j + np * k)]] = { double(i), double(j), double(k) };
      }
    }
  }
  std::vector<Cell> cells;
  const auto cube = CubeInSix();
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        for (const auto& tet : cube)
        {
          Cell cell;
          for (vtkIdType corner : tet)
          {
            const int ci = i + (corner & 1), cj = j + ((corner >> 1) & 1),
                      ck = k + ((corner >> 2) & 1);
            cell.push_back(newId[ci + np * (cj + np * ck)]);
          }
          if (random() % 2)
          {
            std::swap(cell[0], cell[1]);
          }
          cells.push_back(cell);
        }
      }
    }
  }
  std::shuffle(cells.begin(), cells.end(), random);
  return MakeGrid(points, cells);
}
}

int TestHAVSFaceSet(int, char*[])
{
  vtkNew<vtkHAVSFaceSet> faces;
  const havstest::Messages* messages = havstest::CountMessages(faces);
  const std::vector<Point> tetPoints = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 1, 1 } };

  // One tetrahedron, and the same one inverted (negative volume).
  const double tetInside[3] = { 0.25, 0.25, 0.25 };
  CheckConvexMesh(
    "single tet", faces, MakeGrid(tetPoints, { { 0, 1, 2, 3 } }), 1, 4, 4, tetInside, 1.0 / 6.0);
  havstest::CheckNear(faces->GetLongestEdge(), std::sqrt(2.0), 1e-12, "single tet: longest edge");
  CheckConvexMesh(
    "inverted tet", faces, MakeGrid(tetPoints, { { 0, 2, 1, 3 } }), 1, 4, 4, tetInside, 1.0 / 6.0);

  // Two tetrahedra sharing the face (1, 2, 3): a convex bipyramid.
  const double bipyramidInside[3] = { 0.4, 0.4, 0.4 };
  CheckConvexMesh("two tets", faces, MakeGrid(tetPoints, { { 0, 1, 2, 3 }, { 4, 1, 3, 2 } }), 2, 7,
    6, bipyramidInside, 0.5);

  // The unit cube: 12 boundary triangles either way; 5 tets share 4 internal
  // faces (16 in all), 6 tets share 6 (18 in all).
  const double cubeCentre[3] = { 0.5, 0.5, 0.5 };
  CheckConvexMesh(
    "cube in 5", faces, MakeGrid(CubeCorners(), CubeInFive()), 5, 16, 12, cubeCentre, 1.0);
  havstest::CheckNear(faces->GetLongestEdge(), std::sqrt(2.0), 1e-12, "cube in 5: longest edge");
  CheckConvexMesh(
    "cube in 6", faces, MakeGrid(CubeCorners(), CubeInSix()), 6, 18, 12, cubeCentre, 1.0);
  havstest::CheckNear(faces->GetLongestEdge(), std::sqrt(3.0), 1e-12, "cube in 6: longest edge");

  // The same cubes with inverted cells (two points swapped: negative volume):
  // the winding comes from the geometry, not from the cell's point order.
  auto invertedFive = CubeInFive();
  std::swap(invertedFive[1][0], invertedFive[1][1]);
  std::swap(invertedFive[4][2], invertedFive[4][3]);
  CheckConvexMesh("cube in 5, two tets inverted", faces, MakeGrid(CubeCorners(), invertedFive), 5,
    16, 12, cubeCentre, 1.0);
  auto invertedSix = CubeInSix();
  for (auto& tet : invertedSix)
  {
    std::swap(tet[0], tet[3]);
  }
  CheckConvexMesh("cube in 6, all inverted", faces, MakeGrid(CubeCorners(), invertedSix), 6, 18, 12,
    cubeCentre, 1.0);

  // Three tetrahedra on one face: a non-manifold face, stored once, internal.
  const std::vector<Point> fanPoints = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.2, 0.2, 1 },
    { 0.2, 0.2, -1 }, { 0.3, 0.3, 2 } };
  havstest::Check(
    faces->Build(MakeGrid(fanPoints, { { 0, 1, 2, 3 }, { 0, 1, 2, 4 }, { 2, 1, 0, 5 } })),
    "non-manifold fan builds");
  havstest::Check(faces->GetNumberOfFaces() == 10 && faces->GetNumberOfBoundaryFaces() == 9 &&
      faces->GetNumberOfNonManifoldFaces() == 1,
    "non-manifold fan: 10 faces, 9 boundary, 1 non-manifold");

  // Degenerate tetrahedra (flat, repeated point) and a hexahedron are counted
  // and dropped; a tiny but well-shaped tetrahedron is not degenerate.
  std::vector<Point> mixedPoints = CubeCorners();
  mixedPoints.push_back({ 0.5, 0.5, 0.0 });     // 8: in the plane z = 0
  mixedPoints.push_back({ 2.0, 2.0, 2.0 });     // 9
  mixedPoints.push_back({ 2.00001, 2.0, 2.0 }); // 10
  mixedPoints.push_back({ 2.0, 2.00001, 2.0 }); // 11
  mixedPoints.push_back({ 2.0, 2.0, 2.00001 }); // 12
  auto mixed = MakeGrid(mixedPoints,
    { { 0, 1, 2, 4 }, { 0, 1, 2, 8 }, { 0, 1, 1, 4 }, { 0, 1, 3, 2, 4, 5, 7, 6 },
      { 9, 10, 11, 12 } });
  havstest::Check(faces->Build(mixed), "mixed grid builds");
  havstest::Check(faces->GetNumberOfTetrahedra() == 2, "mixed grid: 2 tets used");
  havstest::Check(faces->GetNumberOfDegenerateTetrahedra() == 2, "mixed grid: 2 degenerate");
  havstest::Check(faces->GetNumberOfSkippedCells() == 1, "mixed grid: the hexahedron skipped");
  havstest::Check(faces->GetNumberOfFaces() == 8 && faces->GetNumberOfBoundaryFaces() == 8,
    "mixed grid: 8 boundary faces");
  havstest::CheckNear(faces->GetLongestEdge(), std::sqrt(2.0), 1e-12,
    "mixed grid: longest edge over the used tets only");

  // Failures report an error and leave everything empty (the cell counts say why).
  havstest::Check(messages->Errors == 0, "no error for a usable grid");
  const vtkMTimeType before = faces->GetBuildTime();
  havstest::Check(!faces->Build(nullptr) && messages->Errors == 1, "null grid fails");
  havstest::Check(faces->GetBuildTime() > before, "build time modified");
  vtkNew<vtkUnstructuredGrid> empty;
  havstest::Check(!faces->Build(empty) && messages->Errors == 2, "empty grid fails");
  havstest::Check(faces->GetNumberOfFaces() == 0 && faces->GetFaceVertices().empty() &&
      faces->GetCentroids().empty() && faces->GetNumberOfTetrahedra() == 0,
    "failed build leaves no faces");
  auto onlyBad = MakeGrid(mixedPoints, { { 0, 1, 2, 8 }, { 0, 1, 3, 2, 4, 5, 7, 6 } });
  havstest::Check(!faces->Build(onlyBad) && messages->Errors == 3, "no usable tet fails");
  std::cout << "errors reported:\n" << messages->Text << std::endl;
  havstest::Check(faces->GetNumberOfFaces() == 0 && faces->GetNumberOfSkippedCells() == 1 &&
      faces->GetNumberOfDegenerateTetrahedra() == 1,
    "no usable tet: empty, with the counts");

  // A 4x4x4 block of voxels through VTK's vtkDataSetTriangleFilter (5 tets
  // per voxel), away from the origin: two boundary triangles per boundary quad.
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 5, 5);
  image->SetSpacing(0.5, 0.25, 2.0);
  image->SetOrigin(10.0, -20.0, 30.0);
  vtkNew<vtkDataSetTriangleFilter> tetrahedralize;
  tetrahedralize->SetInputData(image);
  tetrahedralize->Update();
  vtkUnstructuredGrid* block = tetrahedralize->GetOutput();
  const vtkIdType blockTets = 4 * 4 * 4 * 5;
  const vtkIdType boundaryQuads = 6 * 4 * 4;
  const vtkIdType blockFaces = (4 * blockTets + 2 * boundaryQuads) / 2;
  const double blockCentre[3] = { 11.0, -19.5, 34.0 };
  CheckConvexMesh("image block", faces, block, blockTets, blockFaces, 2 * boundaryQuads,
    blockCentre, 2.0 * 1.0 * 8.0);
  havstest::CheckNear(faces->GetCentroidOrigin()[2], 34.0, 1e-12, "centroid origin");
  // The same cells given one type (SetCells(VTK_TETRA, cells): VTK 9.6 holds
  // the types as a vtkConstantArray, where GetCellTypesArray() is nullptr; the
  // face set crashed on it before).
  vtkNew<vtkUnstructuredGrid> singleType;
  singleType->SetPoints(block->GetPoints());
  singleType->SetCells(VTK_TETRA, block->GetCells());
  CheckConvexMesh("image block, one cell type", faces, singleType, blockTets, blockFaces,
    2 * boundaryQuads, blockCentre, 2.0 * 1.0 * 8.0);

  // Shuffled point ids, shuffled cells, random inversions.
  const int n = 8;
  const double kuhnCentre[3] = { n / 2.0, n / 2.0, n / 2.0 };
  const vtkIdType kuhnTets = 6 * n * n * n;
  CheckConvexMesh("shuffled Kuhn grid", faces, ShuffledKuhnGrid(n, 11), kuhnTets,
    (4 * kuhnTets + 12 * n * n) / 2, 12 * n * n, kuhnCentre, double(n * n * n));

  std::ostringstream printed;
  faces->Print(printed);
  havstest::Check(
    printed.str().find("NumberOfBoundaryFaces: " + std::to_string(12 * n * n)) != std::string::npos,
    "PrintSelf prints the counts");
  return havstest::Result();
}
