/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSIsoSurfaces.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// The isosurface blend (vtkVolumeMapper's ISOSURFACE_BLEND, issue 46) and the
// mixed mode (IsoSurfacesInComposite), for the mapper named by argument 1
// (havs, raycast, cellprojection); argument 2: the data set (combustor),
// 3: image size, 4: views, 5: "strict" (the isosurface blend's maximum over
// every pixel where both images show a surface: none of the size^2 / 2000
// worst left out as edge pixels; a pixel one image leaves empty is the
// silhouette's, a ray grazing the boundary; the rays through folded cells,
// which have no exact image, are left out and counted; the control, which
// must miss a pixel in one of the views: for the cell projection its
// stretches and face scalars from the float planes and field,
// FloatIsoStretchesForTesting; for HAVS its fragments' scalars and distances
// the rasterizer's, not the exact ray's on the face, NoFaceClampForTesting).
// 1. Analytic: the box [0, 1]^3 with s = z and the isovalue 0.55 (between
//    the vertices' planes): every pixel is the surface's premultiplied
//    colour at 0.55 (the ray crosses the plane z = 0.55 once) or empty.
// 2. A pair of isovalues (30 % and 65 % of the range) on the data set,
//    against the exact reference's isosurface blend: within the exact bound.
//    Control: the reference with both values shifted by 1 % of the range
//    must miss it.
// 3. The mixed mode (the composite volume with the same surfaces inside)
//    against the reference's: within the exact bound. Control: the composite
//    without the surfaces must miss it.
// 4. Shaded (the property's ShadeOn, the renderer's headlight): the plane of
//    1. seen along a parallel view is lit as Phong's model gives by hand (n =
//    +-z, the light and the eye along the view); the pair of 2. against the
//    reference with the same lights, within the exact bound. Controls: the
//    reference unshaded, and lit by a light turned 20 degrees, must miss.
//    HAVS shades them on the fragment-list path (its nodes carry the
//    fragments' gradients) and goes back to its own path after them. On the
//    first view also clipped by an oblique plane through the centre, against
//    the reference clipped by it (control: the unclipped reference misses).
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMapperScenes.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSIsoSurfaces.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
/// `image` with the pixels where either image is empty (no surface: the
/// silhouette, a ray grazing the boundary) cleared, and those of `folded`
/// (rays through folded cells: no exact image there).
std::vector<float> BothShow(const std::vector<float>& image, const std::vector<float>& other,
  const std::vector<uint8_t>& folded)
{
  std::vector<float> kept = image;
  for (size_t p = 0; p + 3 < kept.size() && p + 3 < other.size(); p += 4)
  {
    if (!(image[p + 3] > 1e-6f && other[p + 3] > 1e-6f) || (p / 4 < folded.size() && folded[p / 4]))
    {
      std::fill_n(kept.begin() + p, 4, 0.0f);
    }
  }
  return kept;
}

/// How many pixels of `image` are the colour `surface` (1e-5), empty (1e-6), or neither.
struct PlanePixels
{
  size_t OnSurface = 0, Empty = 0, Other = 0;
};
PlanePixels CountPlanePixels(const std::vector<float>& image, const double surface[4])
{
  PlanePixels n;
  for (size_t p = 0; p + 3 < image.size(); p += 4)
  {
    double toSurface = 0.0, toEmpty = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      toSurface = std::max(toSurface, std::fabs(image[p + c] - surface[c]));
      toEmpty = std::max(toEmpty, std::fabs(static_cast<double>(image[p + c])));
    }
    n.OnSurface += toSurface < 1e-5 ? 1 : 0;
    n.Empty += toEmpty < 1e-6 ? 1 : 0;
    n.Other += toSurface >= 1e-5 && toEmpty >= 1e-6 ? 1 : 0;
  }
  return n;
}

/// The exact image under `blend` (the mixed mode with `mixed`).
std::vector<float> Reference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkCamera* camera, int size, int blend, bool mixed)
{
  return havstest::ReferenceImage(
    grid, property, camera, size, nullptr, nullptr, blend, nullptr, mixed);
}
}

int TestHAVSIsoSurfaces(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "havs";
  const std::string dataSet = argc > 2 ? argv[2] : "combustor";
  const int size = argc > 3 ? std::atoi(argv[3]) : 96;
  const int views = argc > 4 ? std::atoi(argv[4]) : 2;
  const bool strict = argc > 5 && std::string(argv[5]) == "strict";
  const int iso = vtkHAVSMapperBase::ISOSURFACE_BLEND;

  // 1. Analytic: one plane; then 4a, the same plane shaded along a parallel view.
  {
    auto grid = vtkHAVSDataSets::MakeBox(10, 10, 10, 0.1, 0.0, 1.0);
    auto property = havstest::MakeRampPropertyFor(grid);
    property->GetIsoSurfaceValues()->SetValue(0, 0.55);
    double surface[4];
    vtkHAVSIsoSurfaces::SurfaceColor(property, 0.55, surface);
    auto mapper = havstest::MakeMapperNamed(name);
    mapper->KeepFloatResultOn();
    mapper->SetBlendModeToIsoSurface();
    auto s = havstest::MakeScene(grid, mapper, property, size, size);
    havstest::PlaceCamera(s.Renderer, 25.0, 35.0, false);
    s.Window->Render();
    {
      const std::vector<float> image = havstest::FloatResult(mapper);
      const PlanePixels n = CountPlanePixels(image, surface);
      std::printf("%s: the plane z = 0.55 (colour %.4f %.4f %.4f, opacity %.4f): %zu pixels on "
                  "it, %zu empty, %zu other\n",
        name.c_str(), surface[0], surface[1], surface[2], surface[3], n.OnSurface, n.Empty,
        n.Other);
      // (Other: pixels on the plane's silhouette, where the box's edge cuts it.)
      havstest::Check(
        n.OnSurface > image.size() / 4 / 10 && n.Other <= static_cast<size_t>(2 * size),
        name + ": analytic: each pixel is the surface's colour or empty");
    }

    // 4a.
    property->ShadeOn();
    property->SetAmbient(0.2);
    property->SetDiffuse(0.7);
    property->SetSpecular(0.4);
    property->SetSpecularPower(8.0);
    vtkNew<vtkCamera> parallel; // (PlaceCamera turns the camera it is given)
    s.Renderer->SetActiveCamera(parallel);
    havstest::PlaceCamera(s.Renderer, 25.0, 35.0, true);
    s.Window->Render();
    s.Window->Render(); // (the headlight placed at the camera)
    const std::vector<float> image = havstest::FloatResult(mapper);
    // n = +-z turned towards the eye; light and eye both along -dop.
    double dop[3];
    s.Renderer->GetActiveCamera()->GetDirectionOfProjection(dop);
    const double nl = std::fabs(dop[2]);
    const double rv = 2.0 * nl * nl - 1.0;
    const double a = surface[3];
    double lit[4] = { 0, 0, 0, a };
    for (int c = 0; c < 3; ++c)
    {
      const double color = surface[c] / a;
      const double value =
        0.2 * color + 0.7 * nl * color + (rv > 0.0 ? 0.4 * std::pow(rv, 8.0) : 0.0);
      lit[c] = std::min(1.0, std::max(0.0, value)) * a;
    }
    const double* expected = lit;
    const PlanePixels n = CountPlanePixels(image, expected);
    const size_t onSurface = n.OnSurface, other = n.Other; // (empty: the box's outside)
    std::printf("%s: the plane z = 0.55 shaded (n.l %.4f): expected %.4f %.4f %.4f (unshaded "
                "%.4f %.4f %.4f): %zu pixels on it, %zu other\n",
      name.c_str(), nl, expected[0], expected[1], expected[2], surface[0], surface[1], surface[2],
      onSurface, other);
    havstest::Check(onSurface > image.size() / 4 / 10 && other <= static_cast<size_t>(2 * size),
      name + ": shaded plane: each pixel is Phong's colour or empty");
    havstest::Check(std::fabs(lit[0] - surface[0]) > 0.01 || std::fabs(lit[1] - surface[1]) > 0.01,
      name + ": control: the lit colour differs from the unshaded one");
    if (auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper))
    {
      const int shadedPath = havs->GetActiveKBufferPath();
      property->ShadeOff();
      s.Window->Render();
      const int ownPath = havs->GetActiveKBufferPath();
      std::printf("havs: shaded isosurfaces on path %d, unshaded on %d\n", shadedPath, ownPath);
      havstest::Check(shadedPath == vtkHAVSVolumeMapper::KBufferPathFragmentLists &&
          ownPath != vtkHAVSVolumeMapper::KBufferPathFragmentLists,
        "havs: shaded isosurfaces on the fragment lists, then back to its own path");
    }
  }

  // 2. and 3. On the data set.
  auto grid = vtkHAVSDataSets::Load(dataSet);
  if (!havstest::Check(grid && grid->GetNumberOfCells() > 0, dataSet + " loads"))
  {
    return havstest::Result();
  }
  auto property = havstest::MakeRampPropertyFor(grid);
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  const double span = range[1] - range[0];
  const double values[2] = { range[0] + 0.30 * span, range[0] + 0.65 * span };
  auto shifted = vtkSmartPointer<vtkVolumeProperty>::New();
  shifted->DeepCopy(property);
  for (int i = 0; i < 2; ++i)
  {
    property->GetIsoSurfaceValues()->SetValue(i, values[i]);
    shifted->GetIsoSurfaceValues()->SetValue(i, values[i] + 0.01 * span);
  }
  auto mapper = havstest::MakeMapperNamed(name);
  mapper->KeepFloatResultOn();
  auto s = havstest::MakeScene(grid, mapper, property, size, size);
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  const size_t edge = static_cast<size_t>(size) * size / 2000;
  // The strict check's control (some view must miss a pixel; counted over the
  // views): the cell projection's stretches and face scalars in float; HAVS's
  // fragments as the rasterizer gives them.
  auto* cells = vtkHAVSCellProjectionMapper::SafeDownCast(mapper);
  auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper);
  const std::string controlName =
    cells ? "the stretches in float" : "the fragments the rasterizer's";
  auto setControl = [&](bool on)
  {
    if (cells)
    {
      cells->SetFloatIsoStretchesForTesting(on);
    }
    if (havs)
    {
      havs->SetNoFaceClampForTesting(on);
    }
  };
  int controlMisses = 0, controlViews = 0;
  for (int v = 0; v < views; ++v)
  {
    havstest::PlaceStandardView(s.Renderer, grid, v, views, true);
    const std::string at = name + " " + dataSet + " view " + std::to_string(v);

    mapper->SetBlendModeToIsoSurface();
    mapper->IsoSurfacesInCompositeOff();
    s.Window->Render();
    const auto surfaces = havstest::FloatResult(mapper);
    const auto exact = Reference(grid, property, camera, size, iso, false);
    const auto d = havstest::Compare(surfaces, exact, edge);
    const auto control =
      havstest::Compare(surfaces, Reference(grid, shifted, camera, size, iso, false), edge);
    havstest::PrintDifference(at + ": isosurfaces", d);
    havstest::PrintDifference(at + ": control, values 1 % off", control);
    havstest::Check(havstest::WithinExactBound(d), at + ": the isosurface pair is exact");
    havstest::Check(!havstest::WithinExactBound(control), at + ": control: 1 % off misses");
    if (strict)
    {
      // Every pixel: an isovalue within rounding of a face the ray crosses
      // was crossed in both cells or in neither where each cell computed
      // the face's scalar from its own field (the ray caster before it
      // carried the exit scalar on): one surface too many or too few at a
      // pixel or two a view, 0.05 to 0.06 off on the LOX post at 128^2.
      // (MISSION.md: the rays through folded cells have no exact image; left
      // out and counted, as the benchmark does.)
      std::vector<uint8_t> folded;
      const vtkIdType foldedCount =
        havstest::MakeReference(grid, property, camera, size)->ComputeFoldedPixels(folded);
      const auto all =
        havstest::Compare(BothShow(surfaces, exact, folded), BothShow(exact, surfaces, folded), 0);
      havstest::PrintDifference(at + ": isosurfaces, every pixel both show (" +
          std::to_string(foldedCount) + " folded left out)",
        all);
      havstest::Check(havstest::WithinExactBound(all),
        at + ": the isosurface pair is exact at every pixel both show");
      if (cells || havs)
      {
        setControl(true);
        s.Window->Render();
        const auto unfixed = havstest::FloatResult(mapper);
        setControl(false);
        const auto u =
          havstest::Compare(BothShow(unfixed, exact, folded), BothShow(exact, unfixed, folded), 0);
        havstest::PrintDifference(at + ": control, " + controlName, u);
        controlMisses += havstest::WithinExactBound(u) ? 0 : 1;
        ++controlViews;
      }
    }

    mapper->SetBlendModeToComposite();
    mapper->IsoSurfacesInCompositeOn();
    s.Window->Render();
    const auto mixed = havstest::FloatResult(mapper);
    const auto exactMixed = Reference(grid, property, camera, size, 0, true);
    const auto dm = havstest::Compare(mixed, exactMixed, edge);
    const auto controlMixed =
      havstest::Compare(Reference(grid, property, camera, size, 0, false), exactMixed, edge);
    havstest::PrintDifference(at + ": mixed", dm);
    havstest::PrintDifference(at + ": control, the volume alone", controlMixed);
    havstest::Check(havstest::WithinExactBound(dm), at + ": the mixed mode is exact");
    havstest::Check(!havstest::WithinExactBound(controlMixed),
      at + ": control: the volume without its surfaces misses");
    mapper->IsoSurfacesInCompositeOff();

    // 4b. Shaded, against the reference with the renderer's lights.
    {
      property->ShadeOn();
      property->SetAmbient(0.25);
      property->SetDiffuse(0.7);
      property->SetSpecular(0.3);
      property->SetSpecularPower(12.0);
      mapper->SetBlendModeToIsoSurface();
      s.Window->Render();
      const auto shaded = havstest::FloatResult(mapper);
      auto reference = havstest::MakeReference(grid, property, camera, size);
      reference->SetBlendMode(iso);
      reference->SetLights(s.Renderer->GetLights());
      // The reference's image as it is set up now.
      auto exactNow = [&]()
      {
        reference->Render();
        vtkFloatArray* ri = reference->GetImage();
        return std::vector<float>(ri->GetPointer(0), ri->GetPointer(0) + 4 * size * size);
      };
      const std::vector<float> exactShaded = exactNow();
      const auto ds = havstest::Compare(shaded, exactShaded, edge);
      const auto unlit = havstest::Compare(shaded, exact, edge);
      // Control: a light turned 20 degrees about the view-up.
      vtkNew<vtkLightCollection> turned;
      vtkNew<vtkLight> light;
      light->SetLightTypeToSceneLight();
      light->SetPositional(false);
      vtkCamera* c = camera;
      double position[3], focal[3], up[3];
      c->GetPosition(position);
      c->GetFocalPoint(focal);
      c->GetViewUp(up);
      vtkNew<vtkCamera> turnedCamera;
      turnedCamera->SetPosition(position);
      turnedCamera->SetFocalPoint(focal);
      turnedCamera->SetViewUp(up);
      turnedCamera->Azimuth(20.0);
      light->SetPosition(turnedCamera->GetPosition());
      light->SetFocalPoint(focal);
      turned->AddItem(light);
      reference->SetLights(turned);
      const std::vector<float> exactTurned = exactNow();
      const auto dt = havstest::Compare(shaded, exactTurned, edge);
      havstest::PrintDifference(at + ": shaded isosurfaces", ds);
      havstest::PrintDifference(at + ": control, unshaded", unlit);
      havstest::PrintDifference(at + ": control, the light turned 20 degrees", dt);
      havstest::Check(havstest::WithinExactBound(ds), at + ": the shaded isosurfaces are exact");
      havstest::Check(!havstest::WithinExactBound(unlit), at + ": control: unshaded misses");
      havstest::Check(!havstest::WithinExactBound(dt), at + ": control: a turned light misses");
      // The mixed mode shaded: the surfaces lit inside the (unshaded) volume.
      mapper->SetBlendModeToComposite();
      mapper->IsoSurfacesInCompositeOn();
      s.Window->Render();
      const auto mixedShaded = havstest::FloatResult(mapper);
      reference->SetLights(s.Renderer->GetLights());
      reference->SetBlendMode(0);
      reference->SetIsoSurfacesInComposite(true);
      const std::vector<float> exactMixedShaded = exactNow();
      const auto dms = havstest::Compare(mixedShaded, exactMixedShaded, edge);
      const auto controlMs = havstest::Compare(mixedShaded, exactMixed, edge);
      havstest::PrintDifference(at + ": mixed, shaded", dms);
      havstest::PrintDifference(at + ": control, mixed unshaded", controlMs);
      havstest::Check(havstest::WithinExactBound(dms), at + ": the shaded mixed mode is exact");
      havstest::Check(
        !havstest::WithinExactBound(controlMs), at + ": control: the mixed mode unshaded misses");
      mapper->IsoSurfacesInCompositeOff();

      // 4c. Shaded and clipped (the first view): an oblique clipping plane
      // through the grid's centre, where HAVS draws the plane's section as
      // fragments with the gradients interpolated at its vertices (the
      // clip redistribution under MPI gives every rank such planes).
      if (v == 0)
      {
        double center[3];
        grid->GetCenter(center);
        vtkNew<vtkPlane> plane;
        plane->SetOrigin(center);
        plane->SetNormal(0.8, -0.3, 0.5);
        vtkNew<vtkPlaneCollection> planes;
        planes->AddItem(plane);
        mapper->SetClippingPlanes(planes);
        mapper->SetBlendModeToIsoSurface();
        s.Window->Render();
        const auto clipped = havstest::FloatResult(mapper);
        reference->SetBlendMode(iso);
        reference->SetIsoSurfacesInComposite(false);
        reference->SetClippingPlanes(planes);
        const std::vector<float> exactClipped = exactNow();
        const auto dc = havstest::Compare(clipped, exactClipped, edge);
        const auto controlC = havstest::Compare(clipped, exactShaded, edge);
        havstest::PrintDifference(at + ": shaded, clipped", dc);
        havstest::PrintDifference(at + ": control, shaded, not clipped", controlC);
        // Tighter than the exact bound: the shaded surfaces agree to about
        // 2e-5 everywhere (4b), and HAVS's sections without their gradients
        // (a crossing behind the plane lit by its far end's normal alone) were
        // 2e-5 RMSE, 1.9e-3 max off here, inside the exact bound.
        havstest::Check(havstest::WithinExactBound(dc) && dc.Max < 2e-4,
          at + ": the shaded clipped isosurfaces are exact (max < 2e-4)");
        havstest::Check(!havstest::WithinExactBound(controlC),
          at + ": control: the isosurfaces without the plane miss");
        mapper->SetClippingPlanes(static_cast<vtkPlaneCollection*>(nullptr));
      }
      property->ShadeOff();
    }
  }
  if (controlViews > 0)
  {
    std::printf("%s %s: control: %d of %d views miss with %s\n", name.c_str(), dataSet.c_str(),
      controlMisses, controlViews, controlName.c_str());
    havstest::Check(controlMisses > 0,
      name + " " + dataSet + ": control: " + controlName + ", a view misses a pixel");
  }
  return havstest::Result();
}
