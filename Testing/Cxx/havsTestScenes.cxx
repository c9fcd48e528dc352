/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestScenes.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestScenes.h"

#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
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

VolumeScene MakeScene(vtkUnstructuredGrid* grid, vtkAbstractVolumeMapper* mapper,
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
