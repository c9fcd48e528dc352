/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewScene.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsViewScene.h"

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSIntermixPass.h"
#include "vtkHAVSMapperBase.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkTextProperty.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace havsview
{
namespace
{
const char* const kMapperNames[] = { "HAVS", "HAVS cell projection", "PT (VTK)", "ZSweep (VTK)",
  "RayCast (VTK)", "HAVS ray caster" };
const int kKBufferSizes[] = { 1, 2, 3, 4, 6, 8, 12 };
// vtkVolumeMapper's numbers: composite, maximum, minimum, additive.
const int kBlendModes[] = { 0, 1, 2, 4, 5 };
const char* const kBlendNames[] = { "composite", "maximum", "minimum", "", "additive",
  "isosurfaces" };

std::string Format(const char* format, double value)
{
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

const char* OrderName(int order)
{
  switch (order)
  {
    case vtkHAVSVolumeMapper::VisibilityOrderCentroid:
      return "centroid";
    case vtkHAVSVolumeMapper::VisibilityOrderMPVO:
      return "MPVO";
    default:
      return "automatic";
  }
}
}

//------------------------------------------------------------------------------
Scene::Scene()
{
  this->Renderer->SetBackground(0.0, 0.0, 0.0);
  this->Renderer->SetLayer(0);
  this->Volume->SetProperty(this->Property);
  this->Renderer->AddVolume(this->Volume);

  this->Status->GetTextProperty()->SetFontSize(14);
  this->Status->GetTextProperty()->SetColor(0.95, 0.95, 0.95);
  this->Status->GetTextProperty()->SetVerticalJustificationToTop();
  this->Status->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Status->GetPositionCoordinate()->SetValue(0.01, 0.985);
  this->Renderer->AddViewProp(this->Status);

  this->Help->GetTextProperty()->SetFontSize(14);
  this->Help->GetTextProperty()->SetColor(0.95, 0.9, 0.6);
  this->Help->GetTextProperty()->SetVerticalJustificationToTop();
  this->Help->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Help->GetPositionCoordinate()->SetValue(0.01, 0.9);
  this->Help->SetInput(Scene::KeyHelp().c_str());
  this->Help->SetVisibility(0);
  this->Renderer->AddViewProp(this->Help);
}

//------------------------------------------------------------------------------
Scene::~Scene() = default;

//------------------------------------------------------------------------------
void Scene::SetMesh(vtkUnstructuredGrid* grid, const std::string& name)
{
  this->Grid = grid;
  this->Name = name;
  double range[2] = { 0.0, 1.0 };
  vtkDataArray* scalars = grid->GetPointData()->GetScalars();
  if (!scalars)
  {
    scalars = grid->GetCellData()->GetScalars();
  }
  if (scalars)
  {
    scalars->GetRange(range);
  }
  if (!(range[1] > range[0]))
  {
    range[1] = range[0] + 1.0;
  }
  // The tests' ramp (havsTestProperties' MakeRampProperty): opacity 0 at the
  // low end, 0.24 at 30 %, 0.8 at the high end, unit distance 1/8 of the
  // bounding box's diagonal.
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[0] + 0.3 * (range[1] - range[0]), 0.24);
  opacity->AddPoint(range[1], 0.8);
  vtkNew<vtkColorTransferFunction> color;
  this->Property->SetColor(color);
  this->Property->SetScalarOpacity(opacity);
  this->Property->SetScalarOpacityUnitDistance(grid->GetLength() / 8.0);
  this->Property->ShadeOff();
  this->Property->SetInterpolationTypeToLinear();
  this->Editor.SetProperty(this->Property, range);
  this->Editor.SetColorPreset(0);
  for (auto& mapper : this->Mappers)
  {
    if (mapper)
    {
      mapper->SetInputDataObject(grid);
    }
  }
  this->SetMapper(this->Mapper);
  this->Renderer->ResetCamera();
}

//------------------------------------------------------------------------------
void Scene::AddToWindow(vtkRenderWindow* window)
{
  window->AddRenderer(this->Renderer);
  window->AddRenderer(this->Editor.GetRenderer());
}

//------------------------------------------------------------------------------
vtkAbstractVolumeMapper* Scene::MakeMapper(int kind)
{
  vtkSmartPointer<vtkAbstractVolumeMapper> mapper;
  switch (kind)
  {
    case MapperHAVS:
      mapper.TakeReference(vtkHAVSVolumeMapper::New());
      break;
    case MapperCellProjection:
      mapper.TakeReference(vtkHAVSCellProjectionMapper::New());
      break;
    case MapperPT:
      mapper.TakeReference(vtkProjectedTetrahedraMapper::New());
      break;
    case MapperZSweep:
      mapper.TakeReference(vtkUnstructuredGridVolumeZSweepMapper::New());
      break;
    case MapperTetRayCast:
      mapper.TakeReference(vtkHAVSRayCastMapper::New());
      break;
    default:
      mapper.TakeReference(vtkUnstructuredGridVolumeRayCastMapper::New());
      break;
  }
  if (this->Grid)
  {
    mapper->SetInputDataObject(this->Grid);
  }
  this->Mappers[kind] = mapper;
  this->ApplyLevelOfDetail(mapper);
  return mapper;
}

//------------------------------------------------------------------------------
vtkHAVSVolumeMapper* Scene::GetHAVSMapper()
{
  vtkAbstractVolumeMapper* mapper = this->Mappers[MapperHAVS]
    ? this->Mappers[MapperHAVS].GetPointer()
    : this->MakeMapper(MapperHAVS);
  return vtkHAVSVolumeMapper::SafeDownCast(mapper);
}

//------------------------------------------------------------------------------
std::string Scene::SetMapper(int kind)
{
  if (kind < 0 || kind >= NumberOfMappers)
  {
    return "no such mapper";
  }
  this->Mapper = kind;
  vtkAbstractVolumeMapper* mapper =
    this->Mappers[kind] ? this->Mappers[kind].GetPointer() : this->MakeMapper(kind);
  this->ApplyBlendMode(mapper);
  this->Volume->SetMapper(mapper);
  return std::string("mapper: ") + kMapperNames[kind];
}

//------------------------------------------------------------------------------
std::string Scene::NextMapper()
{
  return this->SetMapper((this->Mapper + 1) % NumberOfMappers);
}

//------------------------------------------------------------------------------
vtkAbstractVolumeMapper* Scene::GetMapper() const
{
  return this->Mappers[this->Mapper];
}

//------------------------------------------------------------------------------
std::string Scene::GetMapperName() const
{
  return kMapperNames[this->Mapper];
}

//------------------------------------------------------------------------------
std::string Scene::SetKBufferSize(int k)
{
  vtkHAVSVolumeMapper* havs = this->GetHAVSMapper();
  havs->SetAutomaticKBufferSize(false);
  havs->SetKBufferSize(k);
  return "k = " + std::to_string(havs->GetKBufferSize());
}

//------------------------------------------------------------------------------
std::string Scene::NextKBufferSize()
{
  const int current = this->GetHAVSMapper()->GetKBufferSize();
  int next = kKBufferSizes[0];
  for (int k : kKBufferSizes)
  {
    if (k > current)
    {
      next = k;
      break;
    }
  }
  return this->SetKBufferSize(next);
}

//------------------------------------------------------------------------------
std::string Scene::ToggleAutomaticK()
{
  vtkHAVSVolumeMapper* havs = this->GetHAVSMapper();
  havs->SetAutomaticKBufferSize(!havs->GetAutomaticKBufferSize());
  return std::string("automatic k: ") + (havs->GetAutomaticKBufferSize() ? "on" : "off");
}

//------------------------------------------------------------------------------
std::string Scene::SetOrder(const std::string& name)
{
  int order = vtkHAVSVolumeMapper::VisibilityOrderAutomatic;
  if (name == "centroid")
  {
    order = vtkHAVSVolumeMapper::VisibilityOrderCentroid;
  }
  else if (name == "mpvo" || name == "MPVO")
  {
    order = vtkHAVSVolumeMapper::VisibilityOrderMPVO;
  }
  vtkHAVSVolumeMapper* havs = this->GetHAVSMapper();
  havs->SetVisibilityOrder(order);
  return std::string("order: ") + OrderName(order);
}

//------------------------------------------------------------------------------
std::string Scene::NextOrder()
{
  const int current = this->GetHAVSMapper()->GetVisibilityOrder();
  switch (current)
  {
    case vtkHAVSVolumeMapper::VisibilityOrderCentroid:
      return this->SetOrder("mpvo");
    case vtkHAVSVolumeMapper::VisibilityOrderMPVO:
      return this->SetOrder("automatic");
    default:
      return this->SetOrder("centroid");
  }
}

//------------------------------------------------------------------------------
std::string Scene::NextBlendMode()
{
  this->BlendMode = (this->BlendMode + 1) % static_cast<int>(sizeof(kBlendModes) / sizeof(int));
  for (auto& mapper : this->Mappers)
  {
    this->ApplyBlendMode(mapper);
  }
  return std::string("blend: ") + kBlendNames[kBlendModes[this->BlendMode]];
}

//------------------------------------------------------------------------------
void Scene::ApplyBlendMode(vtkAbstractVolumeMapper* mapper)
{
  auto* ug = vtkUnstructuredGridVolumeMapper::SafeDownCast(mapper);
  if (!ug)
  {
    return;
  }
  const int blend = kBlendModes[this->BlendMode];
  if (blend == vtkHAVSMapperBase::ISOSURFACE_BLEND || this->IsoSurfacesInComposite)
  {
    this->EnsureIsoValues();
  }
  // The isosurfaces and the mixed mode are the project's mappers' (VTK's
  // unstructured-grid mappers have neither: they stay composite).
  auto* base = vtkHAVSMapperBase::SafeDownCast(mapper);
  ug->SetBlendMode(blend == vtkHAVSMapperBase::ISOSURFACE_BLEND && !base ? 0 : blend);
  if (base)
  {
    base->SetIsoSurfacesInComposite(this->IsoSurfacesInComposite);
  }
}

//------------------------------------------------------------------------------
void Scene::EnsureIsoValues()
{
  // Two isovalues, at 30 % and 65 % of the scalar range, when none is set.
  vtkContourValues* values = this->Property->GetIsoSurfaceValues();
  vtkDataArray* scalars = this->Grid ? this->Grid->GetPointData()->GetScalars() : nullptr;
  if (values->GetNumberOfContours() > 0 || !scalars)
  {
    return;
  }
  double range[2];
  scalars->GetRange(range);
  values->SetValue(0, range[0] + 0.30 * (range[1] - range[0]));
  values->SetValue(1, range[0] + 0.65 * (range[1] - range[0]));
}

//------------------------------------------------------------------------------
std::string Scene::ToggleIsoSurfacesInComposite()
{
  this->IsoSurfacesInComposite = !this->IsoSurfacesInComposite;
  for (auto& mapper : this->Mappers)
  {
    this->ApplyBlendMode(mapper);
  }
  return std::string("isosurfaces in the volume: ") + (this->IsoSurfacesInComposite ? "on" : "off");
}

//------------------------------------------------------------------------------
std::string Scene::ToggleShading()
{
  // The property's ShadeOn: the project's mappers light their isosurfaces
  // (the volume between them stays unshaded); VTK's mappers shade as they do.
  this->Property->SetShade(this->Property->GetShade() ? 0 : 1);
  return std::string("isosurfaces shaded: ") + (this->Property->GetShade() ? "on" : "off");
}

//------------------------------------------------------------------------------
std::string Scene::ToggleTranslucentPlane()
{
  if (this->Plane)
  {
    this->Renderer->RemoveActor(this->Plane);
    this->Renderer->SetPass(nullptr);
    this->Plane = nullptr;
    return "translucent plane: off";
  }
  if (!this->Grid)
  {
    return "translucent plane: no mesh";
  }
  // A lit plane through the centre, across the mesh, tilted; the renderer's
  // pass peels it and the project's mappers intermix it.
  this->Plane = vtkHAVSDataSets::MakeTranslucentPlane(this->Grid);
  this->Renderer->AddActor(this->Plane);
  if (!this->Intermix)
  {
    this->Intermix = vtkSmartPointer<vtkHAVSIntermixPass>::New();
  }
  this->Renderer->SetPass(this->Intermix);
  return "translucent plane: on (intermixed by the project's mappers; PT, ZSweep and RayCast "
         "draw the volume over it)";
}

//------------------------------------------------------------------------------
std::string Scene::ToggleLevelOfDetail()
{
  this->LevelOfDetail = !this->LevelOfDetail;
  for (const auto& mapper : this->Mappers)
  {
    this->ApplyLevelOfDetail(mapper);
  }
  return std::string("level of detail: ") + (this->LevelOfDetail ? "on" : "off");
}

//------------------------------------------------------------------------------
void Scene::ApplyLevelOfDetail(vtkAbstractVolumeMapper* mapper) const
{
  // The project's three: the reduced image; HAVS also its face subset.
  if (auto* base = vtkHAVSMapperBase::SafeDownCast(mapper))
  {
    base->SetImageReduction(this->LevelOfDetail);
  }
  if (auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper))
  {
    havs->SetLevelOfDetail(this->LevelOfDetail);
  }
}

//------------------------------------------------------------------------------
std::string Scene::ToggleViolationCount()
{
  vtkHAVSVolumeMapper* havs = this->GetHAVSMapper();
  havs->SetCountOrderViolations(!havs->GetCountOrderViolations());
  return std::string("order violations: ") +
    (havs->GetCountOrderViolations() ? "counted" : "not counted");
}

//------------------------------------------------------------------------------
std::string Scene::NextColorPreset()
{
  this->Editor.NextColorPreset();
  return "colour map: " + this->Editor.GetColorPresetName();
}

//------------------------------------------------------------------------------
std::string Scene::ToggleOverlay()
{
  this->Overlay = !this->Overlay;
  this->Status->SetVisibility(this->Overlay ? 1 : 0);
  this->Editor.SetVisible(this->Overlay);
  if (!this->Overlay)
  {
    this->Help->SetVisibility(0);
  }
  return std::string("overlay: ") + (this->Overlay ? "shown" : "hidden");
}

//------------------------------------------------------------------------------
std::string Scene::ToggleHelp()
{
  this->Help->SetVisibility(this->Help->GetVisibility() ? 0 : 1);
  return std::string();
}

//------------------------------------------------------------------------------
void Scene::UpdateStatus(double frameSeconds)
{
  std::ostringstream line;
  line << this->GetMapperName() << " | " << Format("%.1f ms", 1000.0 * frameSeconds);
  if (auto* havs = vtkHAVSVolumeMapper::SafeDownCast(this->GetMapper()))
  {
    vtkHAVSFrameStatistics* stats = havs->GetLastFrameStatistics();
    line << " | k " << stats->GetKBufferSize() << (havs->GetAutomaticKBufferSize() ? " (auto)" : "")
         << " | " << OrderName(stats->GetVisibilityOrder()) << " | violations ";
    if (stats->GetOrderViolations() >= 0)
    {
      line << stats->GetOrderViolations();
    }
    else
    {
      line << "not counted";
    }
    line << " | LOD " << Format("%.0f %%", 100.0 * stats->GetLevelOfDetailFraction())
         << " faces, image " << Format("%.0f %%", 100.0 * havs->GetLastImageScale()) << "\n"
         << stats->GetKBufferPathName() << " | ";
  }
  else if (auto* base = vtkHAVSMapperBase::SafeDownCast(this->GetMapper()))
  {
    line << " | LOD image " << Format("%.0f %%", 100.0 * base->GetLastImageScale()) << "\n";
  }
  else
  {
    line << "\n";
  }
  line << kBlendNames[kBlendModes[this->BlendMode]] << " | " << this->Editor.GetColorPresetName()
       << " | h: help";
  if (!this->LastAction.empty())
  {
    line << "\n" << this->LastAction;
  }
  this->Status->SetInput(line.str().c_str());
}

//------------------------------------------------------------------------------
bool Scene::Screenshot(
  vtkRenderWindow* window, const std::string& path, std::string& error, bool overlay)
{
  const bool status = this->Status->GetVisibility() != 0;
  const bool help = this->Help->GetVisibility() != 0;
  const bool editor = this->Editor.GetVisible();
  if (!overlay)
  {
    this->Status->SetVisibility(0);
    this->Help->SetVisibility(0);
    this->Editor.SetVisible(false);
  }
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(grab->GetOutput());
  writer->Write();
  const bool written = writer->GetErrorCode() == 0;

  this->Status->SetVisibility(status ? 1 : 0);
  this->Help->SetVisibility(help ? 1 : 0);
  this->Editor.SetVisible(editor);
  if (!written)
  {
    error = "could not write " + path;
    return false;
  }
  if (overlay)
  {
    return true;
  }

  // Everything the exact reference needs to draw the same image.
  std::ofstream state(path + ".txt");
  state << std::setprecision(17);
  const int* size = window->GetSize();
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  double v[3];
  state << "dataset " << this->Name << "\n";
  state << "size " << size[0] << " " << size[1] << "\n";
  state << "mapper " << this->Mapper << " " << this->GetMapperName() << "\n";
  state << "blend " << kBlendModes[this->BlendMode] << "\n";
  camera->GetPosition(v);
  state << "camera_position " << v[0] << " " << v[1] << " " << v[2] << "\n";
  camera->GetFocalPoint(v);
  state << "camera_focal_point " << v[0] << " " << v[1] << " " << v[2] << "\n";
  camera->GetViewUp(v);
  state << "camera_view_up " << v[0] << " " << v[1] << " " << v[2] << "\n";
  state << "camera_view_angle " << camera->GetViewAngle() << "\n";
  state << "camera_parallel " << camera->GetParallelProjection() << " "
        << camera->GetParallelScale() << "\n";
  camera->GetClippingRange(v);
  state << "camera_clipping_range " << v[0] << " " << v[1] << "\n";
  state << "unit_distance " << this->Property->GetScalarOpacityUnitDistance() << "\n";
  vtkPiecewiseFunction* opacity = this->Property->GetScalarOpacity();
  state << "opacity " << opacity->GetSize();
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    double node[4];
    opacity->GetNodeValue(i, node);
    state << " " << node[0] << " " << node[1] << " " << node[2] << " " << node[3];
  }
  state << "\n";
  vtkColorTransferFunction* color = this->Property->GetRGBTransferFunction();
  state << "color " << color->GetSize();
  for (int i = 0; i < color->GetSize(); ++i)
  {
    double node[6];
    color->GetNodeValue(i, node);
    state << " " << node[0] << " " << node[1] << " " << node[2] << " " << node[3] << " " << node[4]
          << " " << node[5];
  }
  state << "\n";
  if (!state)
  {
    error = "could not write " + path + ".txt";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string Scene::KeyHelp()
{
  return "mouse: left rotate, middle (or shift+left) pan, right/wheel zoom;\n"
         "  on the editor (bottom): drag a node, left click adds, right click removes\n"
         "k  next k (1 2 3 4 6 8 12)      K  automatic k on/off\n"
         "o  next order (centroid, MPVO, automatic)\n"
         "m  next mapper (HAVS, HAVS cell projection, PT, ZSweep, RayCast)\n"
         "b  next blend mode (composite, maximum, minimum, additive, isosurfaces)\n"
         "i  isosurfaces in the volume on/off  g  isosurfaces shaded on/off\n"
         "p  a translucent plane through the mesh on/off (intermixed)\n"
         "l  level of detail on/off       c  next colour map\n"
         "v  count order violations on/off\n"
         "t  overlay (status, editor) on/off\n"
         "s  screenshot (overlay hidden)  r  reset camera\n"
         "h  this help                    q, Esc  quit";
}
}
