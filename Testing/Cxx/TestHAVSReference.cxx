/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSReference.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSReferenceRenderer against closed forms:
// - constant slab (parallel view of the unit box): 1 - exp(-tau L) to 1e-6;
// - linear ramp along the view: 1 - exp(-L tau_max / 2) to 1e-6;
// - a single tetrahedron from several directions (perspective and parallel):
//   1 - exp(-tau chord), the chord clipped independently against the four
//   face planes;
// - watertightness: rays aligned with the block's vertices and edges (pixel
//   centres on the grid lines) hit exactly one entry and one exit face of the
//   convex block — never missed, never doubled; and the same at oblique views;
// - against VTK's vtkUnstructuredGridVolumeRayCastMapper on the LOX post.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkHAVSImageMetrics.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
void ParallelAlongZ(vtkCamera* camera, double scale)
{
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.5, 0.5, 0.5);
  camera->SetPosition(0.5, 0.5, 10.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(scale);
  camera->SetClippingRange(1.0, 20.0);
}

/// Largest |alpha - expected| over pixels whose centre is inside [m, 1-m]^2.
double SlabError(
  vtkHAVSReferenceRenderer* ref, double scale, double expected, double margin, int component = 3)
{
  const int* size = ref->GetSize();
  double worst = 0.0;
  for (int j = 0; j < size[1]; ++j)
  {
    for (int i = 0; i < size[0]; ++i)
    {
      const double x = 0.5 + scale * ((i + 0.5) / size[0] * 2 - 1);
      const double y = 0.5 + scale * ((j + 0.5) / size[1] * 2 - 1);
      if (x > margin && x < 1 - margin && y > margin && y < 1 - margin)
      {
        worst = std::max(
          worst, std::fabs(ref->GetImage()->GetComponent(j * size[0] + i, component) - expected));
      }
    }
  }
  return worst;
}

/// Boundary entries and exits per covered pixel: returns the number of
/// pixels that do not have exactly one of each.
int CountBadCrossings(vtkHAVSReferenceRenderer* ref, int* covered, int* ties)
{
  const int* size = ref->GetSize();
  int bad = 0;
  *covered = 0;
  *ties = 0;
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(size[0]) * size[1]; ++p)
  {
    int entries = 0, exits = 0;
    const auto* b = ref->GetPixelFragmentsBegin(p);
    const auto* e = ref->GetPixelFragmentsEnd(p);
    for (const auto* f = b; f != e; ++f)
    {
      entries += (f->Boundary && !f->Exit) ? 1 : 0;
      exits += f->Exit ? 1 : 0;
      *ties += (f + 1 != e && f[1].Distance == f->Distance) ? 1 : 0;
    }
    if (b != e)
    {
      ++*covered;
      bad += (entries == 1 && exits == 1) ? 0 : 1;
    }
  }
  return bad;
}

/// Length of the ray's chord through the tetrahedron (clipping against the
/// four face planes, independent of the renderer's intersection code).
double Chord(const double v[4][3], const double origin[3], const double dir[3])
{
  double t0 = 0.0, t1 = 1e30;
  static const int faces[4][4] = { { 0, 1, 2, 3 }, { 0, 1, 3, 2 }, { 0, 2, 3, 1 }, { 1, 2, 3, 0 } };
  for (const auto& f : faces)
  {
    double a[3], b[3], n[3], d[3], o[3];
    vtkMath::Subtract(v[f[1]], v[f[0]], a);
    vtkMath::Subtract(v[f[2]], v[f[0]], b);
    vtkMath::Cross(a, b, n);
    vtkMath::Subtract(v[f[3]], v[f[0]], d);
    if (vtkMath::Dot(n, d) > 0) // make n point outward
    {
      vtkMath::MultiplyScalar(n, -1.0);
    }
    vtkMath::Subtract(origin, v[f[0]], o);
    const double num = -vtkMath::Dot(n, o), den = vtkMath::Dot(n, dir);
    if (den == 0.0)
    {
      if (num < 0)
      {
        return 0.0;
      }
      continue;
    }
    const double t = num / den;
    if (den < 0)
    {
      t0 = std::max(t0, t);
    }
    else
    {
      t1 = std::min(t1, t);
    }
  }
  return std::max(0.0, t1 - t0);
}
}

int TestHAVSReference(int, char*[])
{
  vtkNew<vtkHAVSReferenceRenderer> ref;
  vtkNew<vtkCamera> camera;
  ref->SetCamera(camera);

  // Constant slab: tau = 0.5 / 0.25 = 2, L = 1.
  auto box = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.5, 0.0);
  auto constant = havstest::MakeConstantProperty(0.2, 0.6, 0.9, 0.5, 0.25);
  ref->SetInputData(box);
  ref->SetProperty(constant);
  ref->SetSize(33, 33); // odd: pixel centres on x = 0.5 and on the grid lines
  ParallelAlongZ(camera, 0.625);
  havstest::Check(ref->Render(), "slab renders");
  double err = SlabError(ref, 0.625, 1.0 - std::exp(-2.0), 0.0);
  std::cout << "constant slab: max error " << err << std::endl;
  havstest::Check(err < 1e-6, "constant slab to 1e-6");
  int covered = 0, ties = 0;
  int bad = CountBadCrossings(ref, &covered, &ties);
  std::cout << "aligned rays: " << covered << " covered pixels, " << bad
            << " without exactly one entry and one exit, " << ties << " tied fragments"
            << std::endl;
  havstest::Check(bad == 0, "aligned rays: one entry and one exit each");
  havstest::Check(ties > 0, "the aligned view does hit shared edges and vertices");

  // Clipping planes whose kept interval lies just outside the mesh: the
  // tetrahedron (0,0,0) (1,0,0) (0,1,0) (0,0,1) seen along +z, its rays
  // leaving it through the face x + y + z = 1, and planes parallel to that
  // face keeping 1 + 1e-4 <= x + y + z <= 1.5, where no cell is. VTK's
  // tetrahedron counts a point 1e-4 outside it as inside (EvaluatePosition's
  // 1e-3 tolerance): taken so, each ray started inside at the first plane
  // and ran on to the second with the cell's value (alpha up to 0.5).
  // Expected: nothing. Control: the planes keeping 0.5 <= x + y + z <= 1.5
  // draw the tetrahedron's part there.
  {
    vtkNew<vtkUnstructuredGrid> corner;
    vtkNew<vtkPoints> cornerPoints;
    cornerPoints->SetDataTypeToDouble();
    const double c[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    for (const auto& p : c)
    {
      cornerPoints->InsertNextPoint(p);
    }
    corner->SetPoints(cornerPoints);
    const vtkIdType cornerIds[4] = { 0, 1, 2, 3 };
    corner->InsertNextCell(VTK_TETRA, 4, cornerIds);
    vtkNew<vtkDoubleArray> cornerScalars;
    cornerScalars->SetNumberOfTuples(4);
    cornerScalars->Fill(0.5);
    corner->GetPointData()->SetScalars(cornerScalars);
    vtkNew<vtkCamera> below;
    below->ParallelProjectionOn();
    below->SetPosition(0.3, 0.3, -10.0);
    below->SetFocalPoint(0.3, 0.3, 0.5);
    below->SetViewUp(0, 1, 0);
    below->SetParallelScale(0.5);
    below->SetClippingRange(1.0, 20.0);
    vtkNew<vtkHAVSReferenceRenderer> clipped;
    clipped->SetInputData(corner);
    clipped->SetProperty(constant);
    clipped->SetCamera(below);
    clipped->SetSize(32, 32);
    auto maxAlpha = [&](double from)
    {
      const double n = 1.0 / std::sqrt(3.0);
      vtkNew<vtkPlane> nearer, farther;
      nearer->SetOrigin(from, 0, 0);
      nearer->SetNormal(n, n, n); // keeps x + y + z >= from
      farther->SetOrigin(1.5, 0, 0);
      farther->SetNormal(-n, -n, -n); // keeps x + y + z <= 1.5
      vtkNew<vtkPlaneCollection> planes;
      planes->AddItem(nearer);
      planes->AddItem(farther);
      clipped->SetClippingPlanes(planes);
      clipped->Render();
      double largest = 0.0;
      for (vtkIdType i = 0; i < clipped->GetImage()->GetNumberOfTuples(); ++i)
      {
        largest = std::max(largest, clipped->GetImage()->GetComponent(i, 3));
      }
      return largest;
    };
    const double outside = maxAlpha(1.0 + 1e-4);
    const double control = maxAlpha(0.5);
    std::cout << "planes just outside the mesh: max alpha " << outside
              << "; control, planes keeping x + y + z in [0.5, 1.5]: max alpha " << control
              << std::endl;
    havstest::Check(outside == 0.0, "planes keeping only the outside of the mesh: nothing drawn");
    havstest::Check(control > 0.3, "control: planes keeping part of the mesh draw it");
  }

  // Linear ramp along the view: s = z, opacity(s) = s, unit distance 1.
  auto ramp = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
  auto rampProperty = havstest::MakeConstantProperty(0.2, 0.6, 0.9, 1.0, 1.0);
  rampProperty->GetScalarOpacity()->RemoveAllPoints();
  rampProperty->GetScalarOpacity()->AddPoint(0.0, 0.0);
  rampProperty->GetScalarOpacity()->AddPoint(1.0, 1.0);
  ref->SetInputData(ramp);
  ref->SetProperty(rampProperty);
  ref->Render();
  err = SlabError(ref, 0.625, 1.0 - std::exp(-0.5), 0.0);
  std::cout << "linear ramp: max error " << err << std::endl;
  havstest::Check(err < 1e-6, "linear ramp to 1e-6");

  // The order-independent blends on the ramp (s = z along the view),
  // opacity(s) = 0.2 + 0.6 s, colour (0.2, 0.6, 0.9), unit distance 1:
  // maximum intensity = colour * 0.8 and 0.8 (s = 1); minimum = colour * 0.2
  // and 0.2 (s = 0); additive = the integral of (0.2 + 0.6 z) z over [0, 1] =
  // 0.3, grey, opacity 1. Control: the composite image is none of these.
  rampProperty->GetScalarOpacity()->RemoveAllPoints();
  rampProperty->GetScalarOpacity()->AddPoint(0.0, 0.2);
  rampProperty->GetScalarOpacity()->AddPoint(1.0, 0.8);
  struct BlendCase
  {
    const char* Name;
    int Mode;
    double Red, Alpha;
  };
  for (const BlendCase& c :
    { BlendCase{ "maximum intensity", 1, 0.2 * 0.8, 0.8 },
      BlendCase{ "minimum intensity", 2, 0.2 * 0.2, 0.2 }, BlendCase{ "additive", 4, 0.3, 1.0 } })
  {
    ref->SetBlendMode(c.Mode);
    ref->Render();
    const double red = SlabError(ref, 0.625, c.Red, 0.0, 0);
    const double alpha = SlabError(ref, 0.625, c.Alpha, 0.0, 3);
    ref->SetBlendMode(0);
    ref->Render();
    const double control = SlabError(ref, 0.625, c.Red, 0.0, 0);
    std::cout << c.Name << " blend on the ramp: max error red " << red << ", alpha " << alpha
              << "; control (composite) " << control << std::endl;
    havstest::Check(red < 1e-6 && alpha < 1e-6, std::string(c.Name) + " blend: the closed form");
    havstest::Check(control > 1e-2, std::string(c.Name) + " blend: control, composite differs");
  }

  // Oblique views of the block: still one entry and one exit per ray.
  for (double angle : { 17.0, 45.0, 90.0 })
  {
    camera->SetParallelProjection(angle == 45.0 ? 1 : 0);
    camera->SetFocalPoint(0.5, 0.5, 0.5);
    camera->SetPosition(0.5, 0.5, 4.0);
    camera->SetViewUp(0, 1, 0);
    camera->SetParallelScale(1.0);
    camera->Azimuth(angle);
    camera->Elevation(angle / 2);
    camera->OrthogonalizeViewUp();
    camera->SetClippingRange(0.5, 10.0);
    ref->ComputeFragments();
    bad = CountBadCrossings(ref, &covered, &ties);
    std::cout << "oblique " << angle << ": " << covered << " covered, " << bad << " bad, " << ties
              << " ties" << std::endl;
    havstest::Check(bad == 0 && covered > 100, "oblique rays: one entry and one exit each");
  }

  // A single tetrahedron, constant scalar, from several directions.
  const double v[4][3] = { { 0.1, 0.0, 0.0 }, { 1.0, 0.2, 0.1 }, { 0.3, 0.9, 0.2 },
    { 0.4, 0.3, 1.0 } };
  vtkNew<vtkUnstructuredGrid> tet;
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : v)
  {
    pts->InsertNextPoint(p);
  }
  tet->SetPoints(pts);
  vtkIdType ids[4] = { 0, 1, 2, 3 };
  tet->InsertNextCell(VTK_TETRA, 4, ids);
  vtkNew<vtkDoubleArray> s;
  s->SetNumberOfTuples(4);
  s->Fill(0.5);
  tet->GetPointData()->SetScalars(s);
  ref->SetInputData(tet);
  ref->SetProperty(constant);
  ref->SetSize(24, 24);
  double worst = 0.0;
  for (int view = 0; view < 6; ++view)
  {
    camera->SetParallelProjection(view % 2);
    camera->SetFocalPoint(0.45, 0.35, 0.3);
    camera->SetPosition(0.45, 0.35, 3.0);
    camera->SetViewUp(0, 1, 0);
    camera->SetParallelScale(0.8);
    camera->Azimuth(60.0 * view);
    camera->Elevation(25.0 * (view % 3) - 20.0);
    camera->OrthogonalizeViewUp();
    camera->SetClippingRange(0.1, 10.0);
    ref->Render();
    // Each pixel's ray, rebuilt from the camera the same way VTK maps pixels.
    vtkNew<vtkMatrix4x4> clipToWorld;
    vtkMatrix4x4::Invert(camera->GetCompositeProjectionTransformMatrix(1.0, -1, 1), clipToWorld);
    for (int j = 0; j < 24; ++j)
    {
      for (int i = 0; i < 24; ++i)
      {
        double n[4] = { (i + 0.5) / 12.0 - 1, (j + 0.5) / 12.0 - 1, -1, 1 },
               f[4] = { n[0], n[1], 1, 1 };
        double pn[4], pf[4], dir[3];
        clipToWorld->MultiplyPoint(n, pn);
        clipToWorld->MultiplyPoint(f, pf);
        for (int k = 0; k < 3; ++k)
        {
          pn[k] /= pn[3];
          dir[k] = pf[k] / pf[3] - pn[k];
        }
        vtkMath::Normalize(dir);
        const double expected = 1.0 - std::exp(-2.0 * Chord(v, pn, dir));
        worst = std::max(worst, std::fabs(ref->GetImage()->GetComponent(j * 24 + i, 3) - expected));
      }
    }
  }
  std::cout << "single tetrahedron, 6 views: max error " << worst << std::endl;
  havstest::Check(worst < 1e-6, "single tetrahedron to 1e-6");

  // Against VTK's ray-cast mapper (linear integrator) on the LOX post.
  auto post = vtkHAVSDataSets::Load("loxpostvtk");
  if (havstest::Check(post != nullptr, "LOX post read"))
  {
    auto property = havstest::MakeRampPropertyFor(post);
    vtkNew<vtkUnstructuredGridVolumeRayCastMapper> raycast;
    raycast->SetImageSampleDistance(1.0);
    raycast->AutoAdjustSampleDistancesOff();
    raycast->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());
    auto scene = havstest::MakeScene(post, raycast, property, 96, 96);
    havstest::PlaceCamera(scene.Renderer, 35.0, 25.0, false);
    scene.Window->Render();
    const std::vector<float> window = havstest::ReadRGBA(scene.Window);
    ref->SetInputData(post);
    ref->SetProperty(property);
    ref->SetCamera(scene.Renderer->GetActiveCamera());
    ref->SetSize(96, 96);
    ref->Render();
    // The window holds colour over a black background; compare colours.
    vtkNew<vtkFloatArray> a, b;
    a->SetNumberOfComponents(4);
    b->SetNumberOfComponents(4);
    a->SetNumberOfTuples(96 * 96);
    b->SetNumberOfTuples(96 * 96);
    for (vtkIdType p = 0; p < 96 * 96; ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        a->SetComponent(p, c, window[4 * p + c]);
        b->SetComponent(p, c, ref->GetImage()->GetComponent(p, c));
      }
      a->SetComponent(p, 3, 0.0);
      b->SetComponent(p, 3, 0.0);
    }
    vtkNew<vtkHAVSImageMetrics> metrics;
    metrics->Compare(a, b);
    std::cout << "reference vs vtkUnstructuredGridVolumeRayCastMapper (LOX post, 96^2): RMSE "
              << metrics->GetRMSE() << ", max " << metrics->GetMaxAbsError()
              << ", pixels > 4/255: " << 100 * metrics->GetFractionOver4() << " %" << std::endl;
    havstest::Check(metrics->GetRMSE() < 0.01, "reference agrees with the ray-cast mapper");
  }
  return havstest::Result();
}
