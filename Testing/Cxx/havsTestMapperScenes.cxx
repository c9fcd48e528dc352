/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestMapperScenes.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestMapperScenes.h"

#include "havsTestChecks.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSMapperBase.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSStandardViews.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <cstdio>
#include <functional>

namespace havstest
{
vtkSmartPointer<vtkHAVSMapperBase> MakeMapperNamed(const std::string& name)
{
  if (name == "raycast")
  {
    return vtkSmartPointer<vtkHAVSRayCastMapper>::New();
  }
  if (name == "cellprojection")
  {
    return vtkSmartPointer<vtkHAVSCellProjectionMapper>::New();
  }
  return vtkSmartPointer<vtkHAVSVolumeMapper>::New();
}

vtkSmartPointer<vtkHAVSReferenceRenderer> MakeReference(
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int size)
{
  auto reference = vtkSmartPointer<vtkHAVSReferenceRenderer>::New();
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(size, size);
  return reference;
}

std::vector<float> ReferenceImage(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkCamera* camera, int size, vtkPlaneCollection* planes, vtkFloatArray* depth, int blend,
  vtkIdType* startedInside, bool isoInComposite)
{
  auto reference = MakeReference(grid, property, camera, size);
  reference->SetClippingPlanes(planes);
  reference->SetOpaqueDepth(depth);
  reference->SetBlendMode(blend);
  reference->SetIsoSurfacesInComposite(isoInComposite);
  reference->Render();
  if (startedInside)
  {
    *startedInside = reference->GetNumberOfStartedInside();
  }
  vtkFloatArray* image = reference->GetImage();
  return std::vector<float>(image->GetPointer(0), image->GetPointer(0) + 4 * size * size);
}

bool WithinExactBound(const ImageDifference& d)
{
  return d.RMSE < 5e-4 && d.Max < 0.01;
}

void PrintDifference(const std::string& what, const ImageDifference& d)
{
  std::printf("  %-58s RMSE %.6f  max %.6f  px > 1/255 %.3f %%\n", what.c_str(), d.RMSE, d.Max,
    100.0 * d.FractionOver1);
}

void PlaceStandardView(
  vtkRenderer* renderer, vtkUnstructuredGrid* grid, int v, int views, bool turned)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  const bool parallel = v == views;
  vtkHAVSStandardViews::PlaceCamera(camera, grid, parallel ? 3 : v);
  camera->SetParallelProjection(parallel ? 1 : 0);
  if (turned)
  {
    camera->Azimuth(7.0);
    camera->Elevation(5.0);
    camera->OrthogonalizeViewUp();
  }
  renderer->ResetCameraClippingRange();
  if (parallel)
  {
    camera->Azimuth(11.0);
    camera->Elevation(7.0);
    camera->OrthogonalizeViewUp();
    renderer->ResetCamera();
    renderer->ResetCameraClippingRange();
  }
}

int ClipPlanesScene(vtkHAVSMapperBase* mapper, int size, bool all)
{
  auto grid = vtkHAVSDataSets::Load("hollowsphere");
  if (!Check(grid && grid->GetNumberOfCells() > 0, "scene hollowsphere loads"))
  {
    return Result();
  }
  auto property = MakeRampPropertyFor(grid);
  mapper->KeepFloatResultOn();
  auto s = MakeScene(grid, mapper, property, size, size);
  double bounds[6], centre[3];
  grid->GetBounds(bounds);
  grid->GetCenter(centre);
  vtkNew<vtkPlane> first, second;
  first->SetOrigin(centre[0] + 0.1 * (bounds[1] - bounds[0]), centre[1], centre[2]);
  first->SetNormal(-0.8, 0.2, 0.3);
  second->SetOrigin(centre);
  second->SetNormal(0.1, -0.3, 1.0);
  const size_t edgePixels = static_cast<size_t>(size) * size / 2000;
  for (int n = 1; n <= 2; ++n)
  {
    vtkNew<vtkPlaneCollection> planes;
    planes->AddItem(first);
    if (n == 2)
    {
      planes->AddItem(second);
    }
    for (bool parallel : { false, true })
    {
      if (!all && parallel != (n == 2))
      {
        continue; // (the short run: one plane in perspective, two in parallel)
      }
      PlaceCamera(s.Renderer, 30.0, 20.0, parallel);
      mapper->SetClippingPlanes(planes);
      s.Window->Render();
      const auto clipped = FloatResult(mapper);
      const auto exact =
        ReferenceImage(grid, property, s.Renderer->GetActiveCamera(), size, planes);
      // (Not RemoveAllClippingPlanes: that would empty `planes` itself.)
      mapper->SetClippingPlanes(static_cast<vtkPlaneCollection*>(nullptr));
      s.Window->Render();
      const auto whole = FloatResult(mapper);
      const std::string name = std::to_string(n) + (n == 1 ? " plane, " : " planes, ") +
        (parallel ? "parallel" : "perspective");
      const auto d = Compare(clipped, exact, edgePixels);
      const auto control = Compare(whole, exact, edgePixels);
      PrintDifference("clipping, " + name, d);
      PrintDifference("clipping, " + name + ": control, without the planes", control);
      Check(WithinExactBound(d), "clipping, " + name + ": exact");
      Check(control.Max > 0.05, "clipping, " + name + ": control, the planes matter");
    }
  }
  return Result();
}

int OpaqueSphereScene(vtkHAVSMapperBase* mapper, int size)
{
  auto grid = vtkHAVSDataSets::MakeBox(10, 10, 10, 0.1, 0.0, 1.0);
  auto property = MakeRampPropertyFor(grid);
  mapper->KeepFloatResultOn();
  auto s = MakeScene(grid, mapper, property, size, size);
  AddOpaqueSphere(s.Renderer);
  PlaceCamera(s.Renderer, 25.0, 15.0, false);
  s.Window->Render();
  const auto image = FloatResult(mapper);
  vtkNew<vtkFloatArray> depth;
  s.Window->GetZbufferData(0, 0, size - 1, size - 1, depth);
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  const auto exact = ReferenceImage(grid, property, camera, size, nullptr, depth);
  const auto d = Compare(image, exact, static_cast<size_t>(size) * size / 2000);
  const auto control = Compare(ReferenceImage(grid, property, camera, size), exact);
  PrintDifference("opaque sphere: vs the reference cut at the surface", d);
  PrintDifference("opaque sphere: control, the reference through it", control);
  Check(WithinExactBound(d), "opaque sphere: the rays end at its surface");
  Check(control.RMSE > 10.0 * d.RMSE && control.Max > 0.05,
    "opaque sphere: negative control, the surface matters");
  return Result();
}
int CameraInsideScene(vtkHAVSMapperBase* mapper, const std::string& mesh, int size,
  const std::function<void()>& afterFrame)
{
  auto grid = LoadInsideMesh(mesh);
  if (!Check(grid != nullptr, "scene " + mesh + " loads"))
  {
    return Result();
  }
  auto property = MakeRampPropertyFor(grid);
  mapper->KeepFloatResultOn();
  auto s = MakeScene(grid, mapper, property, size, size);
  PlaceCameraInside(s.Renderer, grid, mesh == "box");
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  const size_t edgePixels = static_cast<size_t>(size) * size / 2000;
  for (int blend : { 0, 1, 2, 4 })
  {
    const char* const names[] = { "composite", "maximum intensity", "minimum intensity", "",
      "additive" };
    const std::string name = mesh + ", " + names[blend];
    mapper->SetBlendMode(blend);
    mapper->PlaneSectionsOn();
    s.Window->Render();
    const auto image = FloatResult(mapper);
    const vtkIdType triangles = mapper->GetLastSectionTriangles();
    if (afterFrame)
    {
      afterFrame();
    }
    mapper->PlaneSectionsOff();
    s.Window->Render();
    const auto without = FloatResult(mapper);
    mapper->PlaneSectionsOn();
    vtkIdType started = 0;
    const auto exact =
      ReferenceImage(grid, property, camera, size, nullptr, nullptr, blend, &started);
    const auto d = Compare(image, exact, edgePixels);
    const auto control = Compare(without, exact, edgePixels);
    std::printf("camera inside %s: %lld of %d rays start in the mesh, section %lld triangles\n",
      name.c_str(), static_cast<long long>(started), size * size,
      static_cast<long long>(triangles));
    PrintDifference(name + ": vs the reference", d);
    PrintDifference(name + ": control, without the near section", control);
    Check(started > size * size / 2 && triangles > 0,
      name + ": most rays start in the mesh, the section is drawn");
    Check(AllFinite(image), name + ": finite pixels");
    Check(WithinExactBound(d), name + ": exact with the camera inside");
    // The maximum sees the slab the section stands for only where the ray's
    // maximum lies in it (in neither scene): its control is reported.
    if (blend != 1)
    {
      Check(!WithinExactBound(control) && control.RMSE > 10.0 * d.RMSE,
        name + ": negative control, no section fails");
    }
  }
  return Result();
}
}
