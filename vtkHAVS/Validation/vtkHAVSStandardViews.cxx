/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSStandardViews.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSStandardViews.h"

#include "vtkCamera.h"
#include "vtkDataSet.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSStandardViews);

//------------------------------------------------------------------------------
void vtkHAVSStandardViews::GetDirection(int view, double d[3])
{
  static const double axes[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
    { 0, 0, 1 }, { 0, 0, -1 } };
  if (view < 6)
  {
    std::copy(axes[view], axes[view] + 3, d);
    return;
  }
  const int b = view - 6;
  d[0] = (b & 1) ? 1 : -1;
  d[1] = (b & 2) ? 1 : -1;
  d[2] = (b & 4) ? 1 : -1;
}

//------------------------------------------------------------------------------
void vtkHAVSStandardViews::PlaceCamera(vtkCamera* camera, vtkDataSet* data, int view)
{
  double bounds[6], centre[3], d[3];
  data->GetBounds(bounds);
  for (int k = 0; k < 3; ++k)
  {
    centre[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
  }
  GetDirection(view, d);
  const double norm = vtkMath::Norm(d);
  const double radius = 0.5 * data->GetLength();
  const double distance = radius / std::sin(vtkMath::RadiansFromDegrees(15.0));
  camera->SetViewAngle(30.0);
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + distance * d[0] / norm, centre[1] + distance * d[1] / norm,
    centre[2] + distance * d[2] / norm);
  const bool vertical = view == 2 || view == 3; // looking along y: x is up
  camera->SetViewUp(vertical ? 1 : 0, vertical ? 0 : 1, 0);
  camera->SetClippingRange(distance - radius * 1.01, distance + radius * 1.01);
}

//------------------------------------------------------------------------------
void vtkHAVSStandardViews::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfViews: " << NumberOfViews << "\n";
}

VTK_ABI_NAMESPACE_END
