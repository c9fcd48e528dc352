/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSIntermix.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Translucent geometry intermixed with the volume (issue 46,
// vtkHAVSIntermixPass), for the mapper named by argument 1 (havs, raycast,
// cellprojection); argument 2: the data set ("box", or a vtkHAVSDataSets
// name); 3: the scene ("plane": a lit translucent plane cutting the data set
// obliquely through its centre; "nested": two nested translucent surfaces,
// the inner one red, lit and opaque 0.35, the outer unlit and opaque 0.3:
// on the LOX post open cylinders of radius 2 and 5 around its post (the z
// axis, radius 0.5), elsewhere spheres about the centre); 4: image size;
// 5: views (then one parallel view more).
// 1. The reference itself, on the box cut by an unlit plane: its image with
//    the plane's peeled layer as an event along each ray equals, pixel by
//    pixel, the reference clipped to the front half, then the layer, then
//    the reference clipped to the back half (the plane as a clipping plane,
//    each half drawn alone): a composition that shares no code with the
//    events. Control: the volume over the layer (VTK's order) differs.
// 2. The scene on the data set, each view: the mapper's intermixed float
//    result against the reference with the same layers (peeled from VTK's own
//    render of the actors), within the exact bound. Controls: VTK's order
//    (the volume composited over the translucent scene, what the mapper draws
//    with IntermixTranslucentGeometryOff) must miss it.
// 3. Drawn once: the window (8 bits) is the intermixed result over the
//    black background within 2/255 (the renderer drew no layer itself); with
//    the volume hidden, the pass composites the layers over the window as
//    VTK's depth peeling draws the actors (within 2/255). With an opaque
//    sphere in the scene too (view 0): the layers end at it and the volume
//    with them, against the reference cut at the window's depth.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMapperScenes.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSIntermixPass.h"
#include "vtkHAVSMapperBase.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSTranslucentLayers.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkContourValues.h"
#include "vtkCylinderSource.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
using Image = std::vector<float>;

/// The peeled layers of the last frame, read back.
struct Layers
{
  std::vector<vtkSmartPointer<vtkFloatArray>> Depth, RGBA;
};

Layers ReadLayers(vtkHAVSIntermixPass* pass)
{
  Layers layers;
  vtkHAVSTranslucentLayers* peeled = pass->GetLayers();
  for (int i = 0; i < peeled->GetNumberOfLayers(); ++i)
  {
    auto depth = vtkSmartPointer<vtkFloatArray>::New();
    auto rgba = vtkSmartPointer<vtkFloatArray>::New();
    peeled->ReadLayer(i, depth, rgba);
    layers.Depth.push_back(depth);
    layers.RGBA.push_back(rgba);
  }
  return layers;
}

/// The exact image with the layers as events (and clipped by `planes`, cut
/// at the window depth `depth`, when given).
Image Reference(vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int size,
  const Layers* layers, vtkPlaneCollection* planes = nullptr, vtkFloatArray* depth = nullptr,
  int blend = 0)
{
  auto reference = havstest::MakeReference(grid, property, camera, size);
  reference->SetClippingPlanes(planes);
  reference->SetOpaqueDepth(depth);
  reference->SetBlendMode(blend);
  for (size_t i = 0; layers && i < layers->Depth.size(); ++i)
  {
    reference->AddTranslucentLayer(layers->Depth[i], layers->RGBA[i]);
  }
  reference->Render();
  vtkFloatArray* image = reference->GetImage();
  return Image(image->GetPointer(0), image->GetPointer(0) + 4 * size * size);
}

/// Premultiplied `front` over `back`.
Image Over(const Image& front, const Image& back)
{
  Image out(front.size());
  for (size_t p = 0; p + 3 < front.size(); p += 4)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[p + c] = front[p + c] + (1.0f - front[p + 3]) * back[p + c];
    }
  }
  return out;
}

/// The layers composited back to front (premultiplied): the translucent scene alone.
Image LayersComposite(const Layers& layers, size_t pixels)
{
  Image out(4 * pixels, 0.0f);
  for (size_t i = layers.Depth.size(); i-- > 0;)
  {
    const float* c = layers.RGBA[i]->GetPointer(0);
    for (size_t p = 0; p < pixels; ++p)
    {
      const float a = std::min(1.0f, std::max(0.0f, c[4 * p + 3]));
      for (int k = 0; k < 3; ++k)
      {
        out[4 * p + k] = a * c[4 * p + k] + (1.0f - a) * out[4 * p + k];
      }
      out[4 * p + 3] = a + (1.0f - a) * out[4 * p + 3];
    }
  }
  return out;
}

/// Colour channels only, alpha set to 1 (the window's alpha is not the scene's).
Image ColourOnly(const Image& image)
{
  Image out(image);
  for (size_t p = 3; p < out.size(); p += 4)
  {
    out[p] = 1.0f;
  }
  return out;
}

vtkSmartPointer<vtkActor> MakeActor(
  vtkAlgorithm* source, const double color[3], double opacity, bool lit)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetOpacity(opacity);
  actor->GetProperty()->SetLighting(lit);
  return actor;
}

/// A square of the plane through `center` with `normal`, `extent` wide.
vtkSmartPointer<vtkPlaneSource> MakePlane(
  const double center[3], const double normal[3], double extent)
{
  auto plane = vtkSmartPointer<vtkPlaneSource>::New();
  plane->SetOrigin(-0.5 * extent, -0.5 * extent, 0.0);
  plane->SetPoint1(0.5 * extent, -0.5 * extent, 0.0);
  plane->SetPoint2(-0.5 * extent, 0.5 * extent, 0.0);
  plane->SetResolution(8, 8);
  plane->SetCenter(center[0], center[1], center[2]);
  plane->SetNormal(normal[0], normal[1], normal[2]);
  return plane;
}

/// 1. The reference's events against the clipped halves.
void CheckReference(int size)
{
  auto grid = vtkHAVSDataSets::MakeBox(8, 8, 8, 0.125, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(grid);
  auto mapper = havstest::MakeMapperNamed("raycast");
  auto scene = havstest::MakeScene(grid, mapper, property, size, size);
  const double center[3] = { 0.5, 0.5, 0.5 }, normal[3] = { 0.35, 0.25, 1.0 };
  const double red[3] = { 1.0, 0.3, 0.2 };
  auto source = MakePlane(center, normal, 3.0);
  auto actor = MakeActor(source, red, 0.45, false);
  scene.Renderer->AddActor(actor);
  vtkNew<vtkHAVSIntermixPass> pass;
  scene.Renderer->SetPass(pass);
  havstest::PlaceCamera(scene.Renderer, 30.0, 25.0, false);
  scene.Window->Render();
  const Layers layers = ReadLayers(pass);
  havstest::Check(layers.Depth.size() == 1, "reference: the plane peels into one layer");
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const Image events = Reference(grid, property, camera, size, &layers);

  // The halves: the side the camera is on first.
  double n[3];
  source->GetNormal(n);
  double eye[3];
  camera->GetPosition(eye);
  const double side =
    (eye[0] - center[0]) * n[0] + (eye[1] - center[1]) * n[1] + (eye[2] - center[2]) * n[2];
  const double s = side > 0 ? 1.0 : -1.0;
  vtkNew<vtkPlane> frontPlane, backPlane;
  frontPlane->SetOrigin(center[0], center[1], center[2]);
  frontPlane->SetNormal(s * n[0], s * n[1], s * n[2]);
  backPlane->SetOrigin(center[0], center[1], center[2]);
  backPlane->SetNormal(-s * n[0], -s * n[1], -s * n[2]);
  vtkNew<vtkPlaneCollection> front, back;
  front->AddItem(frontPlane);
  back->AddItem(backPlane);
  const Image frontHalf = Reference(grid, property, camera, size, nullptr, front);
  const Image backHalf = Reference(grid, property, camera, size, nullptr, back);
  const size_t pixels = static_cast<size_t>(size) * size;
  const Image plane = LayersComposite(layers, pixels);
  const Image halves = Over(frontHalf, Over(plane, backHalf));
  const auto d = havstest::Compare(events, halves);
  const Image volume = Reference(grid, property, camera, size, nullptr);
  const auto control = havstest::Compare(Over(volume, plane), halves);
  havstest::PrintDifference("reference: events vs front half, plane, back half", d);
  havstest::PrintDifference("reference: control, the volume over the plane", control);
  havstest::Check(d.RMSE < 1e-5 && d.Max < 1e-4, "reference: the events are the halves' composite");
  havstest::Check(control.Max > 0.05, "reference: control: VTK's order differs");

  // The plane as polygons (rasterized exactly by the reference, no GL): the
  // peeled layer is that surface, and the mapper's intermixed image is exact against it.
  source->Update();
  auto exact = havstest::MakeReference(grid, property, camera, size);
  const double rgba[4] = { red[0], red[1], red[2], 0.45 };
  exact->AddTranslucentSurface(source->GetOutput(), rgba);
  exact->Render();
  const Image polygons(
    exact->GetImage()->GetPointer(0), exact->GetImage()->GetPointer(0) + 4 * pixels);
  mapper->KeepFloatResultOn();
  scene.Window->Render();
  const auto peeled = havstest::Compare(events, polygons, pixels / 2000);
  const auto drawn = havstest::Compare(havstest::FloatResult(mapper), polygons, pixels / 2000);
  const auto unlit = havstest::Compare(havstest::FloatResult(mapper), volume, pixels / 2000);
  havstest::PrintDifference("reference: the peeled layer vs the polygons", peeled);
  havstest::PrintDifference("reference: the ray caster intermixed vs the polygons", drawn);
  havstest::PrintDifference("reference: control, the ray caster vs the volume alone", unlit);
  havstest::Check(havstest::WithinExactBound(peeled) && havstest::WithinExactBound(drawn),
    "reference: the peeled plane is the plane; the intermixed image is exact against it");
  havstest::Check(!havstest::WithinExactBound(unlit), "reference: control: the plane shows");
}
}

int TestHAVSIntermix(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "havs";
  const std::string dataSet = argc > 2 ? argv[2] : "box";
  const std::string sceneName = argc > 3 ? argv[3] : "plane";
  const int size = argc > 4 ? std::atoi(argv[4]) : 96;
  const int views = argc > 5 ? std::atoi(argv[5]) : 2;

  if (name == "havs")
  {
    CheckReference(size);
  }

  // 2. The scene on the data set.
  vtkSmartPointer<vtkUnstructuredGrid> grid = dataSet == "box"
    ? vtkHAVSDataSets::MakeBox(8, 8, 8, 0.125, 0.0, 1.0)
    : vtkHAVSDataSets::Load(dataSet);
  if (!havstest::Check(grid && grid->GetNumberOfCells() > 0, dataSet + " loads"))
  {
    return havstest::Result();
  }
  auto property = havstest::MakeBenchmarkPropertyFor(grid);
  auto mapper = havstest::MakeMapperNamed(name);
  mapper->KeepFloatResultOn();
  auto scene = havstest::MakeScene(grid, mapper, property, size, size);
  double bounds[6], center[3];
  grid->GetBounds(bounds);
  grid->GetCenter(center);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  std::vector<vtkSmartPointer<vtkActor>> actors;
  if (sceneName == "nested")
  {
    // Around the LOX post's post (the z axis, radius 0.5): two open cylinders
    // of radius 2 and 5; elsewhere two spheres about the centre.
    const bool post = dataSet == "loxpost";
    const double red[3] = { 1.0, 0.25, 0.2 }, grey[3] = { 0.8, 0.85, 0.9 };
    for (int i = 0; i < 2; ++i)
    {
      vtkSmartPointer<vtkAlgorithm> source;
      if (post)
      {
        vtkNew<vtkCylinderSource> cylinder;
        cylinder->SetRadius(i == 0 ? 2.0 : 5.0);
        cylinder->SetHeight(1.2 * (bounds[5] - bounds[4]));
        cylinder->SetResolution(96);
        cylinder->CappingOff();
        vtkNew<vtkTransform> transform;
        transform->Translate(0.0, 0.0, 0.5 * (bounds[4] + bounds[5]));
        transform->RotateX(90.0);
        auto placed = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
        placed->SetInputConnection(cylinder->GetOutputPort());
        placed->SetTransform(transform);
        source = placed;
      }
      else
      {
        auto sphere = vtkSmartPointer<vtkSphereSource>::New();
        sphere->SetCenter(center);
        sphere->SetRadius((i == 0 ? 0.12 : 0.22) * diagonal);
        sphere->SetThetaResolution(48);
        sphere->SetPhiResolution(32);
        source = sphere;
      }
      actors.push_back(MakeActor(source, i == 0 ? red : grey, i == 0 ? 0.35 : 0.3, i == 0));
    }
  }
  else
  {
    actors.push_back(vtkHAVSDataSets::MakeTranslucentPlane(grid));
  }
  for (auto& actor : actors)
  {
    scene.Renderer->AddActor(actor);
  }
  vtkNew<vtkHAVSIntermixPass> pass;
  scene.Renderer->SetPass(pass);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const size_t pixels = static_cast<size_t>(size) * size;
  double range[2];
  grid->GetScalarRange(range);
  property->GetIsoSurfaceValues()->SetValue(0, range[0] + 0.30 * (range[1] - range[0]));
  property->GetIsoSurfaceValues()->SetValue(1, range[0] + 0.65 * (range[1] - range[0]));
  for (int v = 0; v <= views; ++v) // the last: a parallel view
  {
    havstest::PlaceStandardView(scene.Renderer, grid, v, views, true);
    const std::string at = name + " " + dataSet + " " + sceneName + " view " + std::to_string(v);
    mapper->IntermixTranslucentGeometryOn();
    scene.Volume->VisibilityOn();
    scene.Window->Render();
    const Image intermixed = havstest::FloatResult(mapper);
    const Image window = havstest::ReadRGBA(scene.Window);
    const Layers layers = ReadLayers(pass);
    std::printf("%s: %d layers, %d taken by the mapper\n", at.c_str(),
      pass->GetLayers()->GetNumberOfLayers(), mapper->GetLastIntermixLayers());
    havstest::Check(mapper->GetLastIntermixLayers() == pass->GetLayers()->GetNumberOfLayers() &&
        mapper->GetLastIntermixLayers() >= 1,
      at + ": the mapper takes every layer");
    const Image exact = Reference(grid, property, camera, size, &layers);
    // The exact bound leaves out the size^2 / 2000 worst (edge) pixels, as every exactness test.
    const size_t edge = pixels / 2000;
    const auto d = havstest::Compare(intermixed, exact, edge);
    const auto every = havstest::Compare(intermixed, exact);
    havstest::PrintDifference(at + ": intermixed vs the reference", d);
    havstest::PrintDifference(at + ": the same, every pixel", every);
    havstest::Check(havstest::AllFinite(intermixed) && havstest::WithinExactBound(d),
      at + ": the intermixed image is exact");

    // Control: VTK's order, the volume over the translucent scene.
    mapper->IntermixTranslucentGeometryOff();
    scene.Window->Render();
    const Image volume = havstest::FloatResult(mapper);
    const Image vtkOrder = Over(volume, LayersComposite(layers, pixels));
    const auto control = havstest::Compare(vtkOrder, exact, edge);
    // The volume alone against its reference: where the worst pixels come from.
    havstest::PrintDifference(at + ": the volume alone vs its reference, every pixel",
      havstest::Compare(volume, Reference(grid, property, camera, size, nullptr)));
    havstest::PrintDifference(at + ": control, the volume over the surfaces", control);
    havstest::Check(
      !havstest::WithinExactBound(control), at + ": control: VTK's order misses the bound");
    havstest::Check(mapper->GetLastIntermixLayers() == 0, at + ": off: no layer taken");
    const Image windowOff = havstest::ReadRGBA(scene.Window);

    // 3. Drawn once: the window is the intermixed result over black.
    const auto drawn = havstest::Compare(ColourOnly(window), ColourOnly(intermixed));
    const auto drawnOff = havstest::Compare(ColourOnly(windowOff), ColourOnly(vtkOrder));
    havstest::PrintDifference(at + ": window vs the intermixed result", drawn);
    havstest::PrintDifference(at + ": off: window vs the volume over the surfaces", drawnOff);
    havstest::Check(drawn.Max <= 2.5 / 255, at + ": the window shows the intermixed image once");
    havstest::Check(drawnOff.Max <= 2.5 / 255, at + ": off: the window shows VTK's order");
    // Control: the surfaces drawn twice (by the renderer too, under the
    // intermixed image) would be told apart by the check above.
    const Image twice = Over(intermixed, LayersComposite(layers, pixels));
    havstest::Check(havstest::Compare(ColourOnly(twice), ColourOnly(intermixed)).Max > 3.0 / 255,
      at + ": control: the surfaces drawn twice would show");

    // The isosurface blend (two values, 30 % and 65 % of the range) intermixed too.
    if (v == 0)
    {
      mapper->SetBlendModeToIsoSurface();
      mapper->IntermixTranslucentGeometryOn();
      scene.Window->Render();
      const Image iso = havstest::FloatResult(mapper);
      const int isoBlend = vtkHAVSMapperBase::ISOSURFACE_BLEND;
      const Image exactIso =
        Reference(grid, property, camera, size, &layers, nullptr, nullptr, isoBlend);
      const Image isoAlone =
        Reference(grid, property, camera, size, nullptr, nullptr, nullptr, isoBlend);
      const auto di = havstest::Compare(iso, exactIso, pixels / 2000);
      const auto ci =
        havstest::Compare(Over(isoAlone, LayersComposite(layers, pixels)), exactIso, pixels / 2000);
      havstest::PrintDifference(at + ": isosurfaces intermixed vs the reference", di);
      havstest::PrintDifference(at + ": control, the isosurfaces over the surfaces", ci);
      havstest::Check(mapper->GetLastIntermixLayers() > 0 && havstest::WithinExactBound(di),
        at + ": the isosurfaces intermixed are exact");
      havstest::Check(!havstest::WithinExactBound(ci), at + ": control: VTK's order misses");
      mapper->SetBlendModeToComposite();
    }
  }

  // 3. The volume hidden: the layers as VTK's depth peeling draws the actors.
  {
    scene.Volume->VisibilityOff();
    scene.Window->Render();
    const Image peeledByPass = havstest::ReadRGBA(scene.Window);
    scene.Renderer->SetPass(nullptr);
    scene.Renderer->SetUseDepthPeeling(1);
    scene.Renderer->SetMaximumNumberOfPeels(16);
    scene.Renderer->SetOcclusionRatio(0.0);
    scene.Window->Render();
    const Image peeledByVTK = havstest::ReadRGBA(scene.Window);
    const auto d = havstest::Compare(ColourOnly(peeledByPass), ColourOnly(peeledByVTK));
    havstest::PrintDifference(name + ": the surfaces alone, the pass vs VTK's peeling", d);
    havstest::Check(d.Max <= 2.5 / 255, name + ": the pass draws the surfaces as VTK does");
    scene.Renderer->SetUseDepthPeeling(0);
    scene.Renderer->SetPass(pass);
    scene.Volume->VisibilityOn();
  }

  // 3. With an opaque sphere too (view 0).
  if (dataSet == "box")
  {
    havstest::AddOpaqueSphere(scene.Renderer);
    havstest::PlaceStandardView(scene.Renderer, grid, 0, views, true);
    mapper->IntermixTranslucentGeometryOn();
    scene.Window->Render();
    const Image intermixed = havstest::FloatResult(mapper);
    const Layers layers = ReadLayers(pass);
    vtkNew<vtkFloatArray> depth;
    scene.Window->GetZbufferData(0, 0, size - 1, size - 1, depth);
    const Image exact = Reference(grid, property, camera, size, &layers, nullptr, depth);
    const auto d = havstest::Compare(intermixed, exact, pixels / 2000);
    const auto control = havstest::Compare(
      intermixed, Reference(grid, property, camera, size, &layers), pixels / 2000);
    havstest::PrintDifference(name + ": with an opaque sphere", d);
    havstest::PrintDifference(name + ": control, the reference through the sphere", control);
    havstest::Check(havstest::WithinExactBound(d), name + ": opaque and translucent: exact");
    havstest::Check(
      !havstest::WithinExactBound(control), name + ": control: the sphere ends the rays");
  }
  return havstest::Result();
}
