/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceOrderPolicy.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSFaceOrderPolicy.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSViewFrame.h"
#include "vtkHAVSVisibilityOrder.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkObjectFactory.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSFaceOrderPolicy);

namespace
{
/// Whether a face's `cell` (NoCell: none) is drawn under the visibility
/// flags (none: every cell is).
bool IsVisibleCell(const std::vector<uint8_t>* visible, uint32_t cell)
{
  return cell != vtkHAVSFaceSet::NoCell &&
    (!visible || (cell < visible->size() && (*visible)[cell] != 0));
}

/// Whether a face's `cell` is not culled (no culling flags: none is).
bool IsUnculledCell(const std::vector<uint8_t>* culled, uint32_t cell)
{
  return cell != vtkHAVSFaceSet::NoCell &&
    (!culled || cell >= culled->size() || (*culled)[cell] == 0);
}
}

vtkHAVSFaceOrderPolicy::vtkHAVSFaceOrderPolicy() = default;
vtkHAVSFaceOrderPolicy::~vtkHAVSFaceOrderPolicy() = default;

//------------------------------------------------------------------------------
vtkHAVSFaceOrderPolicy::Plan vtkHAVSFaceOrderPolicy::Begin(
  vtkHAVSMesh* mesh, int k, int path, bool needsOrder, bool canProbe)
{
  Plan plan;
  if (!needsOrder)
  {
    plan.Order = -1;
    return plan;
  }
  if (this->Subset.Ranks)
  {
    // A level-of-detail frame: the centroid order of the faces it draws (a
    // fraction of them, sorted in a fraction of the time; the exact order
    // orders every face: 13 ms of an 18 ms boundary-only frame of the blunt
    // fin). Its segments are approximate anyway (the long-segment table); the
    // still frame goes back to the order asked for.
    plan.Order = vtkHAVSVolumeMapper::VisibilityOrderCentroid;
    return plan;
  }
  if (this->VisibilityOrder != vtkHAVSVolumeMapper::VisibilityOrderAutomatic)
  {
    plan.Order = this->VisibilityOrder;
    return plan;
  }
  const AutomaticKey key{ mesh->GetBuildTime(), k, path };
  if (!this->AutomaticDecided || !(key == this->LastAutomaticKey))
  {
    this->LastAutomaticKey = key;
    this->AutomaticExact = false;
    this->AutomaticDecided = true;
  }
  plan.Order = this->AutomaticExact ? vtkHAVSVolumeMapper::VisibilityOrderMPVO
                                    : vtkHAVSVolumeMapper::VisibilityOrderCentroid;
  plan.Probe = !this->AutomaticExact && canProbe;
  return plan;
}

//------------------------------------------------------------------------------
vtkHAVSFaceOrderPolicy::Plan vtkHAVSFaceOrderPolicy::ProbeResult(vtkIdType violations)
{
  Plan next;
  next.Order = -1;
  if (violations > 0)
  {
    this->AutomaticExact = true;
    next.Order = vtkHAVSVolumeMapper::VisibilityOrderMPVO;
  }
  return next;
}

//------------------------------------------------------------------------------
const std::vector<uint32_t>* vtkHAVSFaceOrderPolicy::MakeExactOrder(
  vtkHAVSMesh* mesh, vtkUnstructuredGrid* grid, const vtkHAVSViewFrame& view, bool& changed)
{
  if (this->ExactMeshTime != mesh->GetBuildTime())
  {
    this->Exact->Build(mesh->GetFaceSet(), grid, this->Progress);
    this->ExactMeshTime = mesh->GetBuildTime();
    this->ExactValid = false;
  }
  this->Exact->SetSkippedCells(this->Culled, this->CullingVersion);
  const vtkHAVSVisibilityOrder::ViewKey key =
    this->Exact->MakeViewKey(mesh->GetBuildTime(), view, this->NonConvexMethod);
  if (!this->ExactValid || !(key == this->LastExactKey))
  {
    this->Exact->SetNonConvexMethod(this->NonConvexMethod);
    this->Exact->SetViewSampling(view.GridToClip, view.Width, view.Height);
    this->Exact->Sort(view.EyeGrid, view.DirectionGrid, view.Parallel);
    this->LastExactKey = key;
    this->ExactValid = true;
    changed = true;
  }
  const std::vector<uint32_t>& order = this->Exact->GetOrder();
  if (static_cast<vtkIdType>(order.size()) + this->Exact->GetNumberOfSkippedFaces() !=
    mesh->GetFaceSet()->GetNumberOfFaces())
  {
    this->ExactValid = false;
    return nullptr;
  }
  return &order;
}

//------------------------------------------------------------------------------
bool vtkHAVSFaceOrderPolicy::Prepare(
  const Plan& plan, vtkHAVSMesh* mesh, vtkUnstructuredGrid* grid, const vtkHAVSViewFrame& view)
{
  const double start = vtkTimerLog::GetUniversalTime();
  bool ok = true;
  bool changed = false;
  const std::vector<uint32_t>* order = nullptr;
  int drawn = plan.Order;
  if (plan.Order == vtkHAVSVolumeMapper::VisibilityOrderMPVO)
  {
    order = this->MakeExactOrder(mesh, grid, view, changed);
    if (!order)
    {
      ok = false;
      drawn = vtkHAVSVolumeMapper::VisibilityOrderCentroid;
    }
  }
  if (drawn == vtkHAVSVolumeMapper::VisibilityOrderCentroid)
  {
    if (this->Culled || this->Subset.Ranks)
    {
      this->ListSortedFaces(mesh);
      this->Centroid->SetFaceSubset(&this->UnculledFaces, this->UnculledTime.GetMTime());
    }
    else
    {
      this->Centroid->SetFaceSubset(nullptr, 0);
    }
    changed = this->Centroid->Sort(
      mesh->GetFaceSet(), view.GridToWorld, view.EyeWorld, view.DirectionWorld, view.Parallel);
    order = &this->Centroid->GetOrder();
  }
  // The draw triangles: gathered for a new order or a new set of visible
  // cells; any order will do without one.
  const bool newOrder = changed || this->GatheredMesh != mesh->GetBuildTime() ||
    (drawn >= 0 && this->GatheredOrder != drawn);
  const bool gather = newOrder || this->GatheredVisibility != this->VisibilityVersion ||
    this->GatheredCulling != this->CullingVersion || !(this->GatheredSubset == this->Subset);
  this->LastGatherSeconds = 0.0;
  if (gather)
  {
    const double gatherStart = vtkTimerLog::GetUniversalTime();
    this->Gather(mesh, order);
    this->GatheredOrder = drawn;
    this->LastGatherSeconds = vtkTimerLog::GetUniversalTime() - gatherStart;
  }
  this->LastOrder = drawn;
  this->LastOrderedFaces = order ? static_cast<vtkIdType>(order->size()) : 0;
  this->LastReused = !newOrder;
  this->LastSeconds = vtkTimerLog::GetUniversalTime() - start;
  return ok;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceOrderPolicy::SetCellVisibility(
  const std::vector<uint8_t>* visible, vtkMTimeType version)
{
  this->Visible = visible;
  this->VisibilityVersion = visible ? version : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceOrderPolicy::SetCellCulling(
  const std::vector<uint8_t>* culled, vtkMTimeType version)
{
  this->Culled = culled;
  this->CullingVersion = culled ? version : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceOrderPolicy::SetFaceSubset(
  const std::vector<uint32_t>* ranks, uint32_t limit, vtkMTimeType version)
{
  this->Subset.Ranks = ranks;
  this->Subset.Limit = ranks ? limit : 0;
  this->Subset.Version = ranks ? version : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceOrderPolicy::ListSortedFaces(vtkHAVSMesh* mesh)
{
  // (The visibility matters only to a subset: without one a transfer-function
  // edit keeps the list, and the sort its order.)
  const vtkMTimeType visibility = this->Subset.Ranks ? this->VisibilityVersion : 0;
  if (this->UnculledMesh == mesh->GetBuildTime() && this->UnculledCulling == this->CullingVersion &&
    this->UnculledVisibility == visibility && this->UnculledSubset == this->Subset)
  {
    return;
  }
  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const std::vector<uint32_t>& faceCells = faces->GetFaceCells();
  const std::vector<uint8_t>& boundary = faces->GetBoundaryFlags();
  const std::vector<uint8_t>* culled = this->Culled;
  const std::vector<uint8_t>* visible = this->Visible;
  const size_t numFaces = faceCells.size() / 2;
  const std::vector<uint32_t>* ranks =
    this->Subset.Ranks && this->Subset.Ranks->size() == numFaces ? this->Subset.Ranks : nullptr;
  const uint32_t limit = this->Subset.Limit;
  this->UnculledFaces.clear();
  for (size_t f = 0; f < numFaces; ++f)
  {
    const uint32_t c0 = faceCells[2 * f], c1 = faceCells[2 * f + 1];
    if (!IsUnculledCell(culled, c0) && !IsUnculledCell(culled, c1))
    {
      continue;
    }
    // (As Gather: an internal face of the drawn cells beyond the limit is left out.)
    const bool internal =
      visible ? IsVisibleCell(visible, c0) == IsVisibleCell(visible, c1) : boundary[f] == 0;
    if (ranks && internal && (*ranks)[f] >= limit)
    {
      continue;
    }
    this->UnculledFaces.push_back(static_cast<uint32_t>(f));
  }
  this->UnculledMesh = mesh->GetBuildTime();
  this->UnculledCulling = this->CullingVersion;
  this->UnculledVisibility = visibility;
  this->UnculledSubset = this->Subset;
  this->UnculledTime.Modified();
}

//------------------------------------------------------------------------------
void vtkHAVSFaceOrderPolicy::Gather(vtkHAVSMesh* mesh, const std::vector<uint32_t>* order)
{
  vtkHAVSFaceSet* faces = mesh->GetFaceSet();
  const std::vector<uint32_t>& faceVertices = mesh->GetFaceVertexIds();
  const std::vector<uint8_t>& boundary = faces->GetBoundaryFlags();
  // An order may leave out the faces of culled cells only.
  const vtkIdType numFaces =
    order ? static_cast<vtkIdType>(order->size()) : faces->GetNumberOfFaces();
  this->DrawTriangles.resize(3 * numFaces);
  this->DrawBoundary.resize(numFaces);
  const std::vector<uint32_t>* ranks = this->Subset.Ranks;
  if (ranks && ranks->size() != static_cast<size_t>(faces->GetNumberOfFaces()))
  {
    ranks = nullptr; // not this mesh's ranking: every face
  }
  const uint32_t limit = this->Subset.Limit;
  if (!this->Visible && !this->Culled && !ranks)
  {
    for (vtkIdType i = 0; i < numFaces; ++i)
    {
      const uint32_t f = order ? (*order)[i] : static_cast<uint32_t>(i);
      this->DrawTriangles[3 * i] = faceVertices[3 * f];
      this->DrawTriangles[3 * i + 1] = faceVertices[3 * f + 1];
      this->DrawTriangles[3 * i + 2] = faceVertices[3 * f + 2];
      this->DrawBoundary[i] = boundary[f];
    }
  }
  else
  {
    // Faces with a kept cell (visible, not culled), in the same order; the
    // cells' visibility decides which are boundary faces (the face set's
    // normal points to the first cell: flipped where that one is the visible
    // one). Without a visibility set, the face set's boundary stays. The
    // level of detail drops the internal faces ranked at or after the limit.
    const std::vector<uint8_t>* visible = this->Visible;
    const std::vector<uint8_t>* culled = this->Culled;
    const std::vector<uint32_t>& faceCells = faces->GetFaceCells();
    auto isVisible = [&](uint32_t cell) { return IsVisibleCell(visible, cell); };
    auto isKept = [&](uint32_t cell)
    { return IsVisibleCell(visible, cell) && IsUnculledCell(culled, cell); };
    vtkIdType n = 0;
    for (vtkIdType i = 0; i < numFaces; ++i)
    {
      const uint32_t f = order ? (*order)[i] : static_cast<uint32_t>(i);
      const uint32_t c0 = faceCells[2 * static_cast<size_t>(f)];
      const uint32_t c1 = faceCells[2 * static_cast<size_t>(f) + 1];
      if (!isKept(c0) && !isKept(c1))
      {
        continue;
      }
      const bool front = isVisible(c0), back = isVisible(c1);
      const bool flip = visible && front && !back;
      const uint8_t flag = visible ? (front != back ? (flip ? 2 : 1) : 0) : boundary[f];
      if (ranks && flag == 0 && (*ranks)[f] >= limit)
      {
        continue; // an internal face the level of detail leaves out
      }
      this->DrawTriangles[3 * n] = faceVertices[3 * f];
      this->DrawTriangles[3 * n + 1] = faceVertices[3 * f + (flip ? 2 : 1)];
      this->DrawTriangles[3 * n + 2] = faceVertices[3 * f + (flip ? 1 : 2)];
      this->DrawBoundary[n] = flag;
      ++n;
    }
    this->DrawTriangles.resize(3 * n);
    this->DrawBoundary.resize(n);
  }
  this->GatheredMesh = mesh->GetBuildTime();
  this->GatheredVisibility = this->VisibilityVersion;
  this->GatheredCulling = this->CullingVersion;
  this->GatheredSubset = this->Subset;
  this->DrawOrderTime.Modified();
}

//------------------------------------------------------------------------------
void vtkHAVSFaceOrderPolicy::Invalidate()
{
  this->Centroid->Invalidate();
  this->ExactValid = false;
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSFaceOrderPolicy::GetLastCycleBreaks() const
{
  return this->LastOrder == vtkHAVSVolumeMapper::VisibilityOrderMPVO
    ? this->Exact->GetNumberOfCycleBreaks()
    : 0;
}

vtkIdType vtkHAVSFaceOrderPolicy::GetLastBoundaryRelations() const
{
  return this->Exact->GetNumberOfBoundaryRelations();
}

double vtkHAVSFaceOrderPolicy::GetLastBoundaryLayerSeconds() const
{
  return this->Exact->GetLastBoundaryLayerSeconds();
}

//------------------------------------------------------------------------------
void vtkHAVSFaceOrderPolicy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* orders[] = { "Centroid", "MPVO", "Automatic" };
  os << indent << "VisibilityOrder: " << orders[std::min(std::max(this->VisibilityOrder, 0), 2)]
     << ", NonConvexMethod " << this->NonConvexMethod << "\n";
  os << indent << "Last order: " << this->LastOrder << (this->LastReused ? " (reused)" : "") << ", "
     << this->LastSeconds << " s\n";
}

//------------------------------------------------------------------------------
void vtkHAVSFaceOrderPolicy::AddMemoryParts(std::vector<vtkHAVSMemory::Part>& parts) const
{
  parts.push_back({ "face order: centroid sort", this->Centroid->GetMemoryBytes() });
  parts.push_back({ "face order: exact (MPVO, boundary layers)", this->Exact->GetMemoryBytes() });
  parts.push_back({ "face order: the drawn faces",
    vtkHAVSMemory::Bytes(this->DrawTriangles, this->DrawBoundary, this->UnculledFaces) });
}

//------------------------------------------------------------------------------
size_t vtkHAVSFaceOrderPolicy::GetMemoryBytes() const
{
  std::vector<vtkHAVSMemory::Part> parts;
  this->AddMemoryParts(parts);
  return vtkHAVSMemory::Sum(parts);
}

VTK_ABI_NAMESPACE_END
