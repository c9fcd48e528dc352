/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellProjectionMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSCellProjectionMapper.h"

#include "vtkInformation.h"
#include "vtkUnstructuredGridBase.h"

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
#include <random>

VTK_ABI_NAMESPACE_BEGIN

vtkAbstractObjectFactoryNewMacro(vtkHAVSCellProjectionMapper);

//------------------------------------------------------------------------------
vtkHAVSCellProjectionMapper::vtkHAVSCellProjectionMapper()
  : vtkHAVSMapperBase("vtkHAVSCellProjectionMapper")
{
  // Only the near plane needs a section: where a clipping plane cuts a cell
  // the rasterizer still draws the cell's front face, and the ray starts on
  // the plane inside it.
  this->Planes->SetNearPlaneSectionsOnly(true);
}
vtkHAVSCellProjectionMapper::~vtkHAVSCellProjectionMapper() = default;

//------------------------------------------------------------------------------
bool vtkHAVSCellProjectionMapper::DrawCells(vtkRenderer*, const CellFrame&, double*)
{
  vtkErrorMacro("vtkHAVSCellProjectionMapper has no graphics layer: use its OpenGL override "
                "(vtkOpenGLHAVSCellProjectionMapper, from vtkHAVS::OpenGL).");
  return false;
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
const std::vector<uint32_t>* vtkHAVSCellProjectionMapper::MakeOrder(const vtkHAVSViewFrame& view)
{
  // The key of the order wanted: the unsorted blends draw the cells in the
  // mesh's own order (shuffled only as a testing aid), once per mesh; the
  // sorted ones per view, reused while the view's key holds.
  const bool unsorted = this->GetFrameBlend() != COMPOSITE_BLEND;
  const int kind = unsorted ? (this->ShuffleOrderForTesting ? 3 : 2) : this->CellOrder;
  const int method = kind == CellOrderMPVO ? this->NonConvexMethod : -1;
  if (kind == CellOrderMPVO && !this->OrderBuilt)
  {
    vtkUnstructuredGrid* grid = this->Mesh->GetGrid();
    if (!this->Order->Build(
          this->Mesh->GetFaceSet(), grid, [this](double p) { this->UpdateProgress(p); }))
    {
      vtkErrorMacro("The MPVO cell order could not be made for this mesh.");
      return nullptr;
    }
    this->OrderBuilt = true;
    this->OrderKeyValid = false;
  }
  vtkHAVSVisibilityOrder::ViewKey key;
  if (unsorted)
  {
    key.Mesh = this->GeometryTime.GetMTime();
    key.Method = -2 - kind; // no view in it
  }
  else
  {
    key = this->Order->MakeViewKey(this->GeometryTime.GetMTime(), view, method);
  }
  if (this->OrderKeyValid && key == this->OrderKey &&
    this->ReverseOrderForTesting == this->OrderReversed)
  {
    this->LastOrderReused = true;
    this->LastCycleBreaks = this->KeptCycleBreaks;
    return &this->Drawn;
  }
  this->KeptCycleBreaks = 0;
  const size_t count = this->Mesh->GetFaceSet()->GetTetrahedra().size() / 4;
  if (unsorted)
  {
    this->Drawn.resize(count);
    std::iota(this->Drawn.begin(), this->Drawn.end(), 0u);
    if (this->ShuffleOrderForTesting)
    {
      std::mt19937 random(12345u);
      std::shuffle(this->Drawn.begin(), this->Drawn.end(), random);
    }
  }
  else if (kind == CellOrderCentroid)
  {
    this->CentroidOrder(view);
    this->Drawn.swap(this->Centroid);
  }
  else
  {
    this->Order->SetNonConvexMethod(this->NonConvexMethod);
    this->Order->SetViewSampling(view.GridToClip, view.Width, view.Height);
    this->Order->Sort(view.EyeGrid, view.DirectionGrid, view.Parallel);
    this->KeptCycleBreaks = this->Order->GetNumberOfCycleBreaks();
    this->Drawn = this->Order->GetCellOrder();
  }
  if (this->ReverseOrderForTesting)
  {
    std::reverse(this->Drawn.begin(), this->Drawn.end());
  }
  this->OrderReversed = this->ReverseOrderForTesting;
  this->OrderKey = key;
  this->OrderKeyValid = true;
  this->OrderTime.Modified();
  this->LastCycleBreaks = this->KeptCycleBreaks;
  return &this->Drawn;
}

//------------------------------------------------------------------------------
vtkHAVSMemory::Part vtkHAVSCellProjectionMapper::GetLargestGPUBufferNeed() const
{
  // The cell records (vtkHAVSCellGeometry: planes and field, 80 bytes a
  // tetrahedron, in up to four buffers; the tetrahedra's point ids are 16).
  return { "cell records (80 bytes a tetrahedron, in at most 4 buffers)",
    vtkHAVSCellGeometry::LargestRecordBufferNeed(
      static_cast<size_t>(this->Mesh->GetFaceSet()->GetNumberOfTetrahedra())) };
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::AddMemoryParts(std::vector<vtkHAVSMemory::Part>& parts) const
{
  parts.push_back({ "cell order (MPVO)", this->Order->GetMemoryBytes() });
  parts.push_back(
    { "cell records and windings", vtkHAVSMemory::Bytes(this->Cells, this->Mirrored) });
  parts.push_back(
    { "centroid and drawn orders", vtkHAVSMemory::Bytes(this->Centroid, this->Drawn) });
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::ResetLastFrame()
{
  this->LastCellsDrawn = 0;
  this->LastCycleBreaks = 0;
  this->LastOrderReused = false;
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::ComputeCells()
{
  vtkHAVSCellGeometry::Compute(this->Mesh->GetPoints(), this->Mesh->GetScalars(),
    this->Mesh->GetFaceSet()->GetTetrahedra(), this->Cells, nullptr,
    this->Mesh->HasCellScalars() ? &this->Mesh->GetTetrahedronCodes() : nullptr);
  vtkHAVSCellGeometry::ComputeMirrored(
    this->Mesh->GetPoints(), this->Mesh->GetFaceSet()->GetTetrahedra(), this->Mirrored);
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::MeshPrepared(int update, bool rebuilt)
{
  // The cells' planes and fields: the order is kept for a new time step on
  // the same mesh, made again for a new mesh.
  if (update == MeshUnchanged && this->CellsComputed)
  {
    return;
  }
  this->CellsComputed = true;
  this->ComputeCells();
  this->FieldTime.Modified();
  if (rebuilt || this->GeometryTime.GetMTime() == 0)
  {
    this->GeometryTime.Modified();
    this->OrderBuilt = false;
    this->OrderKeyValid = false;
  }
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::RenderView(
  vtkRenderer* renderer, vtkVolume* vtkNotUsed(volume), const vtkHAVSViewFrame& view)
{
  // Where the near plane cuts the mesh (the camera inside it) the rays start
  // on its section: the GL near clip removes the front faces there.
  this->UpdatePlanes(view);

  // The cell order for the view.
  const double t0 = vtkTimerLog::GetUniversalTime();
  const std::vector<uint32_t>* order = this->MakeOrder(view);
  if (!order)
  {
    return;
  }
  this->LastOrderSeconds = vtkTimerLog::GetUniversalTime() - t0;

  // The draw: every cell's front faces in that order.
  CellFrame frame;
  frame.View = &view;
  frame.Mesh = this->Mesh;
  frame.Table = this->Table;
  frame.TableVersion = this->TableBuildTime.GetMTime();
  frame.Cells = &this->Cells;
  frame.Tetrahedra = &this->Mesh->GetFaceSet()->GetTetrahedra();
  frame.Mirrored = &this->Mirrored;
  frame.GeometryVersion = this->FieldTime.GetMTime();
  frame.Order = order;
  frame.OrderVersion = this->OrderTime.GetMTime();
  frame.Planes = this->Planes;
  frame.Blend = this->GetFrameBlend();
  frame.Opaque = this->NeedsOpaqueDepth(renderer);
  frame.KeepResult = this->KeepFloatResult;
  frame.WrongExit = this->WrongExitForTesting;
  frame.FloatIsoStretches = this->FloatIsoStretchesForTesting;
  frame.MeasureStages = this->MeasureStageTimes;
  frame.RestoreCells = [this]() { this->ComputeCells(); };
  if (this->DrawCells(renderer, frame, &this->LastDrawSeconds))
  {
    this->LastCellsDrawn = static_cast<vtkIdType>(order->size());
    // The GPU holds the cell records now: the host copy is freed (made again
    // through RestoreCells if the GPU loses them).
    std::vector<float>().swap(this->Cells);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSCellProjectionMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CellOrder: " << (this->CellOrder == CellOrderMPVO ? "MPVO" : "Centroid")
     << ", NonConvexMethod: " << this->NonConvexMethod << "\n";
  os << indent << "MeasureStageTimes: " << this->MeasureStageTimes << "\n";
  os << indent << "WrongExitForTesting: " << this->WrongExitForTesting
     << ", FloatIsoStretchesForTesting: " << this->FloatIsoStretchesForTesting
     << ", ReverseOrderForTesting: " << this->ReverseOrderForTesting
     << ", ShuffleOrderForTesting: " << this->ShuffleOrderForTesting << "\n";
  os << indent << "Last frame: " << this->LastCellsDrawn << " cells, " << this->LastCycleBreaks
     << " cycle breaks, order " << (this->LastOrderReused ? "reused, " : "")
     << this->LastOrderSeconds << " s, draw " << this->LastDrawSeconds << " s\n";
}

VTK_ABI_NAMESPACE_END
