/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSNearDegenerate.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Near-degenerate cells in bulk (issue 43), through the three mappers: 2,000
// mutually intersecting slivers (random triangles in [-0.25, 1.25]^3, the
// fourth point 1e-11 above each triangle's centroid: a broken mesher's output)
// through and around a valid box (4^3 cubes, [0, 1]^3, s = z), random
// scalars in the box's range.
//
// Defined result: a tetrahedron thinner than vtkHAVSFaceSet's
// MinimumRelativeThickness (2^-20) of the mesh's extent along its thin
// direction is dropped as degenerate (the GPU's float coordinates and depths cannot
// tell its faces apart). The exact image of the scene is then the box's:
// along a ray a sliver adds at most sigma_max h / |cos theta| of optical
// depth (h = 1e-11, sigma_max = -ln(1 - 0.8) / (diagonal / 8) = 7.4 here), so
// all 2,000 together change a ray by less than 1e-3 unless it meets one at
// |cos theta| < 1e-7. Checked: every mapper against the exact reference of
// the box (MISSION's exact bound; the level-of-detail path's bound where HAVS
// drew a subset), finite; the 2,000 counted (GetNumberOfDegenerateTetrahedra)
// and warned about (more than vtkHAVSMesh::DegenerateWarningShare); cells just
// above the bound kept.
// Controls (each must fail the same check): the reference with twice the
// box's density (the check can fail); and the slivers kept
// (MinimumRelativeThickness 0, as before this rule): HAVS and the cell
// projection draw a wrong image (HAVS lit a third of the pixels before; the
// ray caster's image is printed: its walk from cell to cell meets each sliver
// alone and stays near the box's).
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestProperties.h"
#include "havsTestStress.h"

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <random>
#include <string>

using namespace havstest::stress;

namespace
{
constexpr int kSlivers = 2000;

/// The box with `slivers` slivers `thickness` thick (seeded: the same each run).
vtkSmartPointer<vtkUnstructuredGrid> BoxWithSlivers(
  vtkUnstructuredGrid* box, int slivers, double thickness)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  vtkDataArray* boxScalars = box->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < box->GetNumberOfPoints(); ++i)
  {
    points->InsertNextPoint(box->GetPoint(i));
    scalars->InsertNextValue(boxScalars->GetTuple1(i));
  }
  grid->AllocateEstimate(box->GetNumberOfCells() + slivers, 4);
  for (vtkIdType c = 0; c < box->GetNumberOfCells(); ++c)
  {
    vtkNew<vtkIdList> ids;
    box->GetCellPoints(c, ids);
    grid->InsertNextCell(box->GetCellType(c), ids);
  }
  std::mt19937 random(43);
  std::uniform_real_distribution<double> position(-0.25, 1.25);
  std::uniform_real_distribution<double> value(0.0, 1.0);
  for (int s = 0; s < slivers; ++s)
  {
    double x[4][3];
    for (int v = 0; v < 3; ++v)
    {
      for (int k = 0; k < 3; ++k)
      {
        x[v][k] = position(random);
      }
    }
    const double a[3] = { x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2] };
    const double b[3] = { x[2][0] - x[0][0], x[2][1] - x[0][1], x[2][2] - x[0][2] };
    double n[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0] };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; ++k)
    {
      x[3][k] = (x[0][k] + x[1][k] + x[2][k]) / 3.0 + thickness * n[k] / length;
    }
    vtkIdType ids[4];
    for (int v = 0; v < 4; ++v)
    {
      ids[v] = points->InsertNextPoint(x[v]);
      scalars->InsertNextValue(value(random));
    }
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(scalars);
  return grid;
}

/// A mapper of the three at its defaults (HAVS and the cell projection as
/// the stress suite makes them), its float result kept.
vtkSmartPointer<vtkUnstructuredGridVolumeMapper> MakeOne(int which)
{
  if (which < 2)
  {
    return MakeMapper(which == 1);
  }
  auto rays = vtkSmartPointer<vtkHAVSRayCastMapper>::New();
  rays->KeepFloatResultOn();
  return rays;
}

const char* MapperName(int which)
{
  return which == 0 ? "HAVS" : (which == 1 ? "cell projection" : "ray caster");
}

vtkHAVSMapperBase* Base(vtkUnstructuredGridVolumeMapper* mapper)
{
  return vtkHAVSMapperBase::SafeDownCast(mapper);
}
}

int TestHAVSNearDegenerate(int, char*[])
{
  auto box = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(box);
  auto denser = havstest::MakeRampPropertyFor(box);
  denser->SetScalarOpacityUnitDistance(0.5 * property->GetScalarOpacityUnitDistance());
  auto scene = BoxWithSlivers(box, kSlivers, 1e-11);
  const size_t edge = kPairSize * kPairSize / 2000;

  // The bound itself, on the face set: in the unit box (extent 1 along the
  // sliver's normal, z) a sliver 2e-6 thick is kept, one 5e-7 thick is
  // dropped, and the bound 0 keeps both.
  {
    auto thickness = [](double relative, double bound)
    {
      auto one = vtkHAVSDataSets::MakeBox(1, 1, 1, 1.0, 0.0, 1.0);
      auto grid = BoxWithSlivers(one, 0, 0.0);
      vtkNew<vtkPoints> points;
      points->DeepCopy(grid->GetPoints());
      const vtkIdType ids[4] = { points->InsertNextPoint(0.1, 0.1, 0.5),
        points->InsertNextPoint(0.9, 0.1, 0.5), points->InsertNextPoint(0.5, 0.9, 0.5),
        points->InsertNextPoint(0.5, 0.4, 0.5 + relative) };
      auto scalars = vtkDoubleArray::SafeDownCast(grid->GetPointData()->GetScalars());
      for (int v = 0; v < 4; ++v)
      {
        scalars->InsertNextValue(0.5);
      }
      grid->SetPoints(points);
      grid->InsertNextCell(VTK_TETRA, 4, ids);
      vtkNew<vtkHAVSFaceSet> faces;
      faces->SetMinimumRelativeThickness(bound);
      faces->Build(grid);
      return faces->GetNumberOfThinTetrahedra();
    };
    const double bound = vtkHAVSFaceSet::DefaultMinimumRelativeThickness;
    havstest::Check(thickness(2e-6, bound) == 0, "a sliver 2e-6 of the extent thick is kept");
    havstest::Check(thickness(5e-7, bound) == 1, "a sliver 5e-7 of the extent thick is dropped");
    havstest::Check(thickness(5e-7, 0.0) == 0, "with the bound 0 it is kept");
  }

  PairReferences references;
  for (int which = 0; which < 3; ++which)
  {
    const std::string name = MapperName(which);
    auto mapper = MakeOne(which);
    const Pair p = RenderWithReference(scene, property, mapper, references);
    const auto& exact = references.Get(box, property, p.Camera);
    const auto d = havstest::Compare(p.Image, exact, edge);
    const auto wrong = havstest::Compare(p.Image, references.Get(box, denser, p.Camera), edge);
    Print(name + ": against the box's exact image", d);
    Print(name + ": control, twice the density", wrong);
    havstest::Check(
      Accurate(d, p.Subset), name + (p.Subset ? ": within the level-of-detail bound" : ": exact"));
    havstest::Check(!Accurate(wrong, p.Subset), name + ": the control (twice the density) fails");
    havstest::Check(havstest::AllFinite(p.Image), name + ": finite");
    havstest::Check(CoveredPixels(exact) >= 100, name + ": the box shows");
    const vtkIdType degenerate = Base(mapper)->GetNumberOfDegenerateTetrahedra();
    havstest::Check(degenerate == kSlivers && p.Warnings >= 1 && p.Errors == 0,
      name + ": the " + std::to_string(kSlivers) + " slivers counted (" +
        std::to_string(degenerate) + ") and warned about (" + std::to_string(p.Warnings) + ")");

    // Control: the slivers kept, as before the bound.
    auto kept = MakeOne(which);
    Base(kept)->GetMesh()->GetFaceSet()->SetMinimumRelativeThickness(0.0);
    const Pair q = RenderWithReference(scene, property, kept, references);
    const auto k = havstest::Compare(q.Image, exact, edge);
    Print(name + ": control, the slivers kept", k);
    havstest::Check(Base(kept)->GetNumberOfDegenerateTetrahedra() == 0,
      name + ": with the bound 0 no sliver is dropped");
    if (which < 2)
    {
      havstest::Check(!Accurate(k, q.Subset), name + ": the control (the slivers kept) fails");
    }
  }
  return havstest::Result();
}
