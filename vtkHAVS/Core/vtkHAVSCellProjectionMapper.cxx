/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellProjectionMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSCellProjectionMapper.h"

#include "vtkHAVSCellGeometry.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSMapperInputs.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSViewFrame.h"
#include "vtkHAVSVisibilityOrder.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"

#include <algorithm>
#include <numeric>

vtkAbstractObjectFactoryNewMacro(vtkHAVSCellProjectionMapper);

//------------------------------------------------------------------------------
vtkHAVSCellProjectionMapper::vtkHAVSCellProjectionMapper() = default;
vtkHAVSCellProjectionMapper::~vtkHAVSCellProjectionMapper() = default;

//------------------------------------------------------------------------------
bool vtkHAVSCellProjectionMapper::DrawCells(vtkRenderer*, const CellFrame&, double*)
{
  vtkErrorMacro("vtkHAVSCellProjectionMapper has no graphics layer: use its OpenGL override "
                "(vtkOpenGLHAVSCellProjectionMapper, from vtkHAVS::OpenGL).");
  return false;
}

const std::vector<float>* vtkHAVSCellProjectionMapper::GetKeptResult(int[2])
{
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::WarnOnce(int which, const std::string& message)
{
  vtkHAVSMapperInputs::WarnOnceBy(this, this->Warned[which], message);
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::CentroidOrder(const vtkHAVSViewFrame& view)
{
  // Front to back by the centroid's eye distance (along the direction of
  // projection for a parallel camera), in grid coordinates.
  const std::vector<uint32_t>& tets = this->Mesh->GetFaceSet()->GetTetrahedra();
  const std::vector<float>& points = this->Mesh->GetPoints();
  const double* shift = this->Mesh->GetShift();
  const size_t count = tets.size() / 4;
  std::vector<double> key(count);
  for (size_t t = 0; t < count; ++t)
  {
    double c[3] = { 0, 0, 0 };
    for (int v = 0; v < 4; ++v)
    {
      for (int i = 0; i < 3; ++i)
      {
        c[i] += 0.25 * (points[3 * static_cast<size_t>(tets[4 * t + v]) + i] + shift[i]);
      }
    }
    double d = 0;
    for (int i = 0; i < 3; ++i)
    {
      d += view.Parallel ? c[i] * view.DirectionGrid[i]
                         : (c[i] - view.EyeGrid[i]) * (c[i] - view.EyeGrid[i]);
    }
    key[t] = d;
  }
  this->Centroid.resize(count);
  std::iota(this->Centroid.begin(), this->Centroid.end(), 0u);
  std::sort(this->Centroid.begin(), this->Centroid.end(),
    [&](uint32_t a, uint32_t b) { return key[a] < key[b]; });
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  this->LastCellsDrawn = 0;
  this->LastCycleBreaks = 0;
  if (this->BlendMode != COMPOSITE_BLEND)
  {
    vtkErrorMacro("Blend mode " << this->BlendMode
                                << " is not supported by vtkHAVSCellProjectionMapper yet "
                                   "(composite is).");
    return;
  }

  // The mesh, the table, the cells' planes and fields: each only when its inputs changed.
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update();
  }
  auto warnOnce = [this](int which, const std::string& m) { this->WarnOnce(which, m); };
  const auto state = vtkHAVSMapperInputs::PrepareMesh(
    this, volume, this->Mesh, "vtkHAVSCellProjectionMapper", warnOnce);
  if (state == vtkHAVSMapperInputs::MeshFailed)
  {
    return;
  }
  if (state == vtkHAVSMapperInputs::MeshRebuilt || this->Cells.empty())
  {
    vtkHAVSCellGeometry::Compute(this->Mesh->GetPoints(), this->Mesh->GetScalars(),
      this->Mesh->GetFaceSet()->GetTetrahedra(), this->Cells, this->Faces);
    this->GeometryTime.Modified();
    this->OrderBuilt = false;
  }
  bool rebuilt = false;
  if (!vtkHAVSMapperInputs::PrepareTable(this, volume, this->Mesh, this->Table,
        this->TableScalarResolution, this->TableLengthResolution, "vtkHAVSCellProjectionMapper",
        warnOnce, &rebuilt))
  {
    return;
  }
  if (rebuilt)
  {
    this->TableBuildTime.Modified();
  }

  // The view, and the cell order for it.
  const vtkHAVSViewFrame view = vtkHAVSViewFrame::Make(renderer, volume, this->Mesh->GetShift());
  if (!view.HasPixels())
  {
    return;
  }
  const double* b = this->Mesh->GetBounds();
  const double* shift = this->Mesh->GetShift();
  bool inside = true;
  for (int i = 0; i < 3; ++i)
  {
    const double e = view.EyeGrid[i] - shift[i];
    inside = inside && e >= b[2 * i] && e <= b[2 * i + 1];
  }
  if (inside && !view.Parallel)
  {
    this->WarnOnce(vtkHAVSMapperInputs::WarnOrder,
      "The camera is inside the mesh's bounds: vtkHAVSCellProjectionMapper does not draw the "
      "cells the near plane cuts yet.");
  }
  if (!this->Planes->Update(view, this->ClippingPlanes, this->Mesh, false))
  {
    this->WarnOnce(vtkHAVSMapperInputs::WarnPlanes,
      "More than 6 clipping planes; vtkHAVSCellProjectionMapper uses the first 6.");
  }
  const double t0 = vtkTimerLog::GetUniversalTime();
  const std::vector<uint32_t>* order = nullptr;
  if (this->CellOrder == CellOrderCentroid)
  {
    this->CentroidOrder(view);
    order = &this->Centroid;
  }
  else
  {
    if (!this->OrderBuilt)
    {
      auto* grid = vtkUnstructuredGrid::SafeDownCast(this->GetInput());
      if (!this->Order->Build(this->Mesh->GetFaceSet(), grid))
      {
        vtkErrorMacro("The MPVO cell order could not be made for this mesh.");
        return;
      }
      this->OrderBuilt = true;
    }
    this->Order->SetNonConvexMethod(this->NonConvexMethod);
    this->Order->SetViewSampling(view.GridToClip, view.Width, view.Height);
    this->Order->Sort(view.EyeGrid, view.DirectionGrid, view.Parallel);
    this->LastCycleBreaks = this->Order->GetNumberOfCycleBreaks();
    order = &this->Order->GetCellOrder();
  }
  if (this->ReverseOrderForTesting)
  {
    this->Reversed.assign(order->rbegin(), order->rend());
    order = &this->Reversed;
  }
  this->LastOrderSeconds = vtkTimerLog::GetUniversalTime() - t0;

  CellFrame frame;
  frame.View = &view;
  frame.Mesh = this->Mesh;
  frame.Table = this->Table;
  frame.TableVersion = this->TableBuildTime.GetMTime();
  frame.Cells = &this->Cells;
  frame.Faces = &this->Faces;
  frame.GeometryVersion = this->GeometryTime.GetMTime();
  frame.Order = order;
  frame.Planes = this->Planes;
  frame.Opaque = vtkHAVSMapperInputs::RendererHasOpaqueGeometry(renderer);
  frame.KeepResult = this->KeepFloatResult;
  frame.WrongExit = this->WrongExitForTesting;
  frame.MeasureStages = this->MeasureStageTimes;
  if (this->DrawCells(renderer, frame, &this->LastDrawSeconds))
  {
    this->LastCellsDrawn = static_cast<vtkIdType>(order->size());
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSCellProjectionMapper::GetFloatResult(vtkFloatArray* rgba, int size[2])
{
  return vtkHAVSMapperInputs::CopyResult(this->GetKeptResult(size), size, rgba);
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CellOrder: " << (this->CellOrder == CellOrderMPVO ? "MPVO" : "Centroid")
     << ", NonConvexMethod: " << this->NonConvexMethod << "\n";
  os << indent << "Table: " << this->TableScalarResolution << "^2 x " << this->TableLengthResolution
     << "\n";
  os << indent << "KeepFloatResult: " << this->KeepFloatResult
     << ", WrongExitForTesting: " << this->WrongExitForTesting << "\n";
  os << indent << "Last frame: " << this->LastCellsDrawn << " cells, " << this->LastCycleBreaks
     << " cycle breaks, order " << this->LastOrderSeconds << " s, draw " << this->LastDrawSeconds
     << " s\n";
}
