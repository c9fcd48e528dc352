/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestScenes.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestScenes.h"

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

void UseCentroidOrder(vtkHAVSVolumeMapper* mapper)
{
  mapper->SetVisibilityOrderToCentroid();
  mapper->SetKBufferSize(6);
}
}
