/*=========================================================================

  Project:   vtkHAVS
  Module:    havs_consumer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// An outside program built against an installed vtkHAVS: renders a
// tetrahedralized block with a linear field through vtkHAVSVolumeMapper in a
// headless window and checks that the image is not empty (the volume covers
// the middle of the window) and that the volume is where it should be (the
// corners stay background).
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cstdlib>
#include <iostream>
#include <string>

int main()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(9, 9, 9);
  image->SetSpacing(0.125, 0.125, 0.125);
  image->SetOrigin(-0.5, -0.5, -0.5);
  vtkNew<vtkDoubleArray> field;
  field->SetName("field");
  field->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    field->SetValue(i, x[0] + x[1] + x[2]);
  }
  image->GetPointData()->SetScalars(field);
  vtkNew<vtkDataSetTriangleFilter> tetrahedralize;
  tetrahedralize->SetInputData(image);

  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(-1.5, 0.2, 0.4, 1.0);
  color->AddRGBPoint(1.5, 1.0, 0.6, 0.2);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(-1.5, 0.5);
  opacity->AddPoint(1.5, 0.9);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.5);

  vtkNew<vtkHAVSVolumeMapper> mapper;
  mapper->SetInputConnection(tetrahedralize->GetOutputPort());
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  renderer->SetBackground(0, 0, 0);
  vtkSmartPointer<vtkRenderWindow> window;
  window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow());
  if (!window)
  {
    std::cerr << "havs_consumer: no render window" << std::endl;
    return EXIT_FAILURE;
  }
  window->SetSize(64, 64);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  window->Render();

  vtkNew<vtkFloatArray> rgba;
  window->GetRGBAPixelData(0, 0, 63, 63, 0, rgba);
  const float* centre = rgba->GetPointer(4 * (32 * 64 + 32));
  const float* corner = rgba->GetPointer(0);
  const float centreSum = centre[0] + centre[1] + centre[2];
  const float cornerSum = corner[0] + corner[1] + corner[2];
  std::cout << "havs_consumer: " << mapper->GetClassName() << ", path "
            << mapper->GetActiveKBufferPathName() << ", centre RGB " << centre[0] << " "
            << centre[1] << " " << centre[2] << ", corner RGB sum " << cornerSum << std::endl;
  if (std::string(mapper->GetClassName()) != "vtkOpenGLHAVSVolumeMapper")
  {
    std::cerr << "havs_consumer: FAIL: vtkHAVSVolumeMapper::New() did not give the OpenGL "
                 "override (vtk_module_autoinit of vtkHAVS::OpenGL)"
              << std::endl;
    return EXIT_FAILURE;
  }
  if (!(centreSum > 0.3f) || cornerSum != 0.0f)
  {
    std::cerr << "havs_consumer: FAIL: the volume is not drawn where it should be" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "havs_consumer: PASS" << std::endl;
  return EXIT_SUCCESS;
}
