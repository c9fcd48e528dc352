/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSViewFrame.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSViewFrame.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
vtkHAVSViewFrame vtkHAVSViewFrame::Make(
  vtkRenderer* renderer, vtkVolume* volume, const double shift[3], double imageScale)
{
  vtkHAVSViewFrame f;
  renderer->GetTiledSizeAndOrigin(&f.FullWidth, &f.FullHeight, &f.OriginX, &f.OriginY);
  f.Width = f.FullWidth;
  f.Height = f.FullHeight;
  if (imageScale > 0.0 && imageScale < 1.0 && f.FullWidth > 0 && f.FullHeight > 0)
  {
    f.Width = std::max(1, static_cast<int>(std::lround(imageScale * f.FullWidth)));
    f.Height = std::max(1, static_cast<int>(std::lround(imageScale * f.FullHeight)));
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->GetPosition(f.EyeWorld);
  camera->GetDirectionOfProjection(f.DirectionWorld);
  camera->GetClippingRange(f.ClippingRange);
  f.Parallel = camera->GetParallelProjection() != 0;
  if (f.Parallel)
  {
    // The eye at most one bounds diagonal in front of the volume's centre,
    // on the camera's axis (see the class comment): every distance to the
    // volume then lies below one and a half diagonals. A camera nearer stays.
    double bounds[6];
    volume->GetBounds(bounds);
    if (vtkMath::AreBoundsInitialized(bounds))
    {
      double toCentre[3], diagonal2 = 0.0;
      for (int i = 0; i < 3; ++i)
      {
        toCentre[i] = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]) - f.EyeWorld[i];
        diagonal2 += (bounds[2 * i + 1] - bounds[2 * i]) * (bounds[2 * i + 1] - bounds[2 * i]);
      }
      const double diagonal = std::sqrt(diagonal2);
      const double move = std::max(0.0, vtkMath::Dot(toCentre, f.DirectionWorld) - diagonal);
      for (int i = 0; i < 3; ++i)
      {
        f.EyeWorld[i] += move * f.DirectionWorld[i];
      }
      f.ClippingRange[0] -= move;
      f.ClippingRange[1] -= move;
    }
  }

  vtkMatrix4x4* gridToWorld = volume->GetMatrix();
  f.FlipFacing = gridToWorld->Determinant() < 0.0;
  vtkNew<vtkMatrix4x4> modelToGrid, modelToWorld, worldToClip, worldToEyeRelative, clipToWorld,
    matrix;
  for (int i = 0; i < 3; ++i)
  {
    modelToGrid->SetElement(i, 3, shift[i]);
    worldToEyeRelative->SetElement(i, 3, -f.EyeWorld[i]);
  }
  vtkMatrix4x4::Multiply4x4(gridToWorld, modelToGrid, modelToWorld);
  worldToClip->DeepCopy(
    camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
  vtkMatrix4x4::Invert(worldToClip, clipToWorld);

  vtkMatrix4x4::Multiply4x4(worldToEyeRelative, modelToWorld, matrix);
  vtkMatrix4x4::DeepCopy(f.ModelToEyeRelative, matrix);
  vtkMatrix4x4::Multiply4x4(worldToClip, modelToWorld, matrix);
  vtkMatrix4x4::DeepCopy(f.ModelToClip, matrix);
  vtkMatrix4x4::Multiply4x4(worldToEyeRelative, clipToWorld, matrix);
  vtkMatrix4x4::DeepCopy(f.ClipToEyeRelative, matrix);
  vtkMatrix4x4::Multiply4x4(worldToClip, gridToWorld, matrix);
  vtkMatrix4x4::DeepCopy(f.GridToClip, matrix);
  vtkMatrix4x4::DeepCopy(f.GridToWorld, gridToWorld);

  // The eye and the direction of projection in the grid's coordinates.
  vtkNew<vtkMatrix4x4> worldToGrid;
  vtkMatrix4x4::Invert(gridToWorld, worldToGrid);
  double eye[4] = { f.EyeWorld[0], f.EyeWorld[1], f.EyeWorld[2], 1.0 };
  double direction[4] = { f.DirectionWorld[0], f.DirectionWorld[1], f.DirectionWorld[2], 0.0 };
  worldToGrid->MultiplyPoint(eye, eye);
  worldToGrid->MultiplyPoint(direction, direction);
  for (int i = 0; i < 3; ++i)
  {
    f.EyeGrid[i] = eye[i] / eye[3];
    f.DirectionGrid[i] = direction[i];
  }
  return f;
}

//------------------------------------------------------------------------------
void vtkHAVSViewFrame::ToColumnMajor(const double rowMajor[16], float columnMajor[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      columnMajor[c * 4 + r] = static_cast<float>(rowMajor[r * 4 + c]);
    }
  }
}

VTK_ABI_NAMESPACE_END
