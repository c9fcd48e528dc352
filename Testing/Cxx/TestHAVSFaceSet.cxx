// vtkHAVSFaceSet: unique faces, boundary flags, outward winding (also for an
// inverted cell), degenerate and non-tetrahedral cells, and a closed-surface
// check by the divergence theorem on a tetrahedralized block.
#include "vtkHAVSTestUtilities.h"

#include "vtkHAVSFaceSet.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <cmath>
#include <cstdlib>

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> Grid(const std::vector<std::array<double, 3>>& points,
  const std::vector<std::vector<vtkIdType>>& cells, int type = VTK_TETRA)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : points)
  {
    pts->InsertNextPoint(p.data());
  }
  grid->SetPoints(pts);
  for (const auto& c : cells)
  {
    grid->InsertNextCell(c.size() == 4 ? type : VTK_HEXAHEDRON, static_cast<vtkIdType>(c.size()),
      c.data());
  }
  return grid;
}

/// Outward normals: each boundary face's normal points away from `inside`
/// (valid for convex meshes); returns the number of wrong ones.
int WrongNormals(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid, const double inside[3])
{
  int wrong = 0;
  const auto& v = faces->GetFaceVertices();
  for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
  {
    if (!faces->GetBoundaryFlags()[f])
    {
      continue;
    }
    double p[3][3], a[3], b[3], n[3], d[3];
    for (int i = 0; i < 3; ++i)
    {
      grid->GetPoint(v[3 * f + i], p[i]);
    }
    for (int k = 0; k < 3; ++k)
    {
      a[k] = p[1][k] - p[0][k];
      b[k] = p[2][k] - p[0][k];
      d[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0 - inside[k];
    }
    vtkMath::Cross(a, b, n);
    wrong += vtkMath::Dot(n, d) > 0 ? 0 : 1;
  }
  return wrong;
}
}

int main()
{
  vtkNew<vtkHAVSFaceSet> faces;
  const std::vector<std::array<double, 3>> tetPoints = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 1, 1 } };

  // One tetrahedron: 4 boundary faces, outward.
  auto one = Grid(tetPoints, { { 0, 1, 2, 3 } });
  havstest::Check(faces->Build(one), "single tet builds");
  havstest::Check(faces->GetNumberOfFaces() == 4 && faces->GetNumberOfBoundaryFaces() == 4,
    "single tet: 4 boundary faces");
  const double c1[3] = { 0.25, 0.25, 0.25 };
  havstest::Check(WrongNormals(faces, one, c1) == 0, "single tet: outward");
  havstest::CheckNear(faces->GetLongestEdge(), std::sqrt(2.0), 1e-12, "longest edge");

  // The same tetrahedron inverted (negative volume): still outward.
  auto inverted = Grid(tetPoints, { { 0, 2, 1, 3 } });
  faces->Build(inverted);
  havstest::Check(WrongNormals(faces, inverted, c1) == 0, "inverted tet: still outward");

  // Two tetrahedra sharing face (1,2,3): 7 faces, 1 internal.
  auto two = Grid(tetPoints, { { 0, 1, 2, 3 }, { 4, 1, 3, 2 } });
  faces->Build(two);
  havstest::Check(faces->GetNumberOfFaces() == 7 && faces->GetNumberOfBoundaryFaces() == 6,
    "two tets: 7 faces, 6 boundary");

  // A degenerate (flat) tetrahedron and a hexahedron are counted and dropped.
  auto mixed = Grid({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 }, { 1, 0, 1 },
                      { 1, 1, 1 }, { 0, 1, 1 } },
    { { 0, 1, 2, 3 }, { 0, 1, 2, 4 }, { 0, 1, 4, 2, 3, 5, 6, 7 } });
  havstest::Check(faces->Build(mixed), "mixed grid builds");
  havstest::Check(faces->GetNumberOfTetrahedra() == 1 &&
      faces->GetNumberOfDegenerateTetrahedra() == 1 && faces->GetNumberOfSkippedCells() == 1,
    "mixed grid: 1 tet used, 1 degenerate, 1 skipped");

  // Nothing usable, or nothing at all: false, empty.
  vtkNew<vtkUnstructuredGrid> empty;
  havstest::Check(!faces->Build(empty) && faces->GetNumberOfFaces() == 0, "empty grid fails");
  havstest::Check(!faces->Build(nullptr), "null grid fails");

  // A tetrahedralized 4x3x2 block of cubes (5 tets per cube, as
  // vtkDataSetTriangleFilter makes them).
  auto block = havstest::MakeBox(4, 3, 2, 0.5, 0.0, 1.0);
  havstest::Check(faces->Build(block), "block builds");
  const vtkIdType tets = faces->GetNumberOfTetrahedra();
  const vtkIdType boundaryQuads = 2 * (4 * 3 + 3 * 2 + 4 * 2);
  std::cout << "block: " << tets << " tets, " << faces->GetNumberOfFaces() << " faces, "
            << faces->GetNumberOfBoundaryFaces() << " boundary" << std::endl;
  havstest::Check(tets == 4 * 3 * 2 * 5, "block: 5 tets per cube");
  havstest::Check(faces->GetNumberOfBoundaryFaces() == 2 * boundaryQuads,
    "block: two triangles per boundary quad");
  // Every tet has 4 faces: internal faces are shared by two.
  havstest::Check(4 * tets == faces->GetNumberOfBoundaryFaces() +
        2 * (faces->GetNumberOfFaces() - faces->GetNumberOfBoundaryFaces()),
    "block: face count consistent with sharing");
  const double centre[3] = { 1.0, 0.75, 0.5 };
  havstest::Check(WrongNormals(faces, block, centre) == 0, "block: boundary outward");
  // Divergence theorem: closed outward surface, sum (c . n_area) / 3 = volume.
  double volume = 0.0, areaVector[3] = { 0, 0, 0 };
  const auto& v = faces->GetFaceVertices();
  for (vtkIdType f = 0; f < faces->GetNumberOfFaces(); ++f)
  {
    if (!faces->GetBoundaryFlags()[f])
    {
      continue;
    }
    double p[3][3], a[3], b[3], n[3], c[3];
    for (int i = 0; i < 3; ++i)
    {
      block->GetPoint(v[3 * f + i], p[i]);
    }
    for (int k = 0; k < 3; ++k)
    {
      a[k] = p[1][k] - p[0][k];
      b[k] = p[2][k] - p[0][k];
      c[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0;
    }
    vtkMath::Cross(a, b, n);
    for (int k = 0; k < 3; ++k)
    {
      areaVector[k] += 0.5 * n[k];
    }
    volume += vtkMath::Dot(c, n) / 6.0;
  }
  havstest::CheckNear(vtkMath::Norm(areaVector), 0.0, 1e-9, "block: closed surface");
  havstest::CheckNear(volume, 2.0 * 1.5 * 1.0, 1e-9, "block: divergence theorem volume");
  // Centroids are stored relative to the bounds centre.
  const double* origin = faces->GetCentroidOrigin();
  havstest::CheckNear(origin[0], 1.0, 1e-12, "centroid origin x");
  return havstest::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
