/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestScenes.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

namespace havstest
{
vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height)
{
  vtkSmartPointer<vtkRenderWindow> window;
  window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow());
  if (window)
  {
    window->SetSize(width, height);
    window->SetMultiSamples(0);
  }
  return window;
}

VolumeScene MakeScene(vtkDataObject* grid, vtkAbstractVolumeMapper* mapper,
  vtkVolumeProperty* property, int width, int height)
{
  VolumeScene scene;
  scene.Window = MakeWindow(width, height);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Window->AddRenderer(scene.Renderer);
  mapper->SetInputDataObject(grid);
  scene.Volume = vtkSmartPointer<vtkVolume>::New();
  scene.Volume->SetMapper(mapper);
  scene.Volume->SetProperty(property);
  scene.Renderer->AddVolume(scene.Volume);
  return scene;
}

void AddOpaqueSphere(vtkRenderer* renderer)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.55, 0.5, 0.45);
  sphere->SetRadius(0.3);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
}

void PlaceCamera(vtkRenderer* renderer, double azimuth, double elevation, bool parallel)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetParallelProjection(parallel ? 1 : 0);
  renderer->ResetCamera();
  camera->Azimuth(azimuth);
  camera->Elevation(elevation);
  camera->OrthogonalizeViewUp();
  renderer->ResetCamera();
  renderer->ResetCameraClippingRange();
}

vtkSmartPointer<vtkUnstructuredGrid> LoadInsideMesh(const std::string& mesh)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = mesh == "box"
    ? vtkHAVSDataSets::MakeBox(10, 10, 10, 0.1, 0.0, 1.0)
    : vtkHAVSDataSets::Load(mesh);
  return grid && grid->GetNumberOfCells() > 0 ? grid : nullptr;
}

void PlaceCameraInside(vtkRenderer* renderer, vtkUnstructuredGrid* grid, bool box)
{
  double eye[3] = { 0.31, 0.355, 0.405 }, direction[3] = { 1.0, 0.4, 0.3 };
  if (!box)
  {
    double bounds[6];
    grid->GetBounds(bounds);
    const double f[3] = { 0.45, 0.6, 0.5 };
    for (int i = 0; i < 3; ++i)
    {
      eye[i] = bounds[2 * i] + f[i] * (bounds[2 * i + 1] - bounds[2 * i]);
    }
    direction[1] = 0.3;
    direction[2] = 0.2;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetParallelProjection(0);
  camera->SetPosition(eye);
  camera->SetFocalPoint(eye[0] + direction[0], eye[1] + direction[1], eye[2] + direction[2]);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(60.0);
  const double length = grid->GetLength();
  camera->SetClippingRange(0.05 * length, 2.0 * length);
}

void UseCentroidOrder(vtkHAVSVolumeMapper* mapper)
{
  mapper->SetVisibilityOrderToCentroid();
  mapper->SetKBufferSize(6);
}
}
