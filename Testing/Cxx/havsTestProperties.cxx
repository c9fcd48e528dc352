/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestProperties.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestProperties.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

namespace havstest
{
vtkSmartPointer<vtkVolumeProperty> MakeConstantProperty(
  double r, double g, double b, double opacity, double unitDistance)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(-1e6, r, g, b);
  color->AddRGBPoint(1e6, r, g, b);
  vtkNew<vtkPiecewiseFunction> alpha;
  alpha->AddPoint(-1e6, opacity);
  alpha->AddPoint(1e6, opacity);
  property->SetColor(color);
  property->SetScalarOpacity(alpha);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  return property;
}

vtkSmartPointer<vtkVolumeProperty> MakeRampProperty(
  double lo, double hi, double maxOpacity, double unitDistance)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  // Every opacity node is a colour node too, so that VTK's linear ray
  // integrator (which splits segments at colour nodes and only at the first
  // opacity node) integrates this property exactly.
  color->AddRGBPoint(lo, 0.1, 0.2, 1.0);
  color->AddRGBPoint(lo + 0.3 * (hi - lo), 0.16, 0.68, 0.58);
  color->AddRGBPoint(lo + 0.5 * (hi - lo), 0.2, 1.0, 0.3);
  color->AddRGBPoint(hi, 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> alpha;
  alpha->AddPoint(lo, 0.0);
  alpha->AddPoint(lo + 0.3 * (hi - lo), 0.3 * maxOpacity);
  alpha->AddPoint(hi, maxOpacity);
  property->SetColor(color);
  property->SetScalarOpacity(alpha);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  return property;
}

vtkSmartPointer<vtkVolumeProperty> MakeRampPropertyFor(vtkUnstructuredGrid* grid)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  return MakeRampProperty(range[0], range[1], 0.8, grid->GetLength() / 8.0);
}

vtkSmartPointer<vtkVolumeProperty> MakeBenchmarkPropertyFor(vtkUnstructuredGrid* grid)
{
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  auto property = MakeRampProperty(range[0], range[1], 0.8, grid->GetLength() / 8.0);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  opacity->RemoveAllPoints();
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[0] + 0.3 * (range[1] - range[0]), 0.1);
  opacity->AddPoint(range[1], 0.8);
  return property;
}

}
