/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSVolumeMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSVolumeMapper.h"

#include "vtkInformation.h"
#include "vtkUnstructuredGridBase.h"

#include "vtkHAVSCellVisibility.h"
#include "vtkHAVSFaceOrderPolicy.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSInternalFaceRanking.h"
#include "vtkHAVSLevelOfDetailController.h"
#include "vtkHAVSMapperInputs.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSTableResolution.h"
#include "vtkHAVSViewCulling.h"
#include "vtkHAVSViewFrame.h"
#include "vtkHAVSVisibilityOrder.h"

#include "vtkAlgorithm.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

vtkAbstractObjectFactoryNewMacro(vtkHAVSVolumeMapper);

namespace
{
// The warnings given once per mapper (vtkHAVSMapperInputs::OnceWarning).
using Inputs = vtkHAVSMapperInputs;
const int WarnPath = Inputs::WarnPath, WarnK = Inputs::WarnK;
}

//------------------------------------------------------------------------------
vtkHAVSVolumeMapper::vtkHAVSVolumeMapper()
  : vtkHAVSMapperBase("vtkHAVSVolumeMapper")
{
  this->FaceOrder->SetProgressCallback([this](double p) { this->UpdateProgress(p); });
  this->LongSegmentTable->SetEntryBuilder(
    [this](const vtkHAVSPreIntegrationTable::Quadrature& inputs, float* table)
    { return this->BuildTableEntries(inputs, table); });
}
vtkHAVSVolumeMapper::~vtkHAVSVolumeMapper() = default;

//------------------------------------------------------------------------------
const char* vtkHAVSVolumeMapper::GetKBufferPathName(int path)
{
  return vtkHAVSFrameRequest::GetPathName(path);
}
static_assert(static_cast<int>(vtkHAVSVolumeMapper::KBufferPathFramebufferFetch) ==
      static_cast<int>(vtkHAVSFrameRequest::PathFramebufferFetch) &&
    static_cast<int>(vtkHAVSVolumeMapper::KBufferPathFragmentShaderInterlock) ==
      static_cast<int>(vtkHAVSFrameRequest::PathFragmentShaderInterlock) &&
    static_cast<int>(vtkHAVSVolumeMapper::KBufferPathFragmentLists) ==
      static_cast<int>(vtkHAVSFrameRequest::PathFragmentLists),
  "the k-buffer paths of the mapper and of the frame request");

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::SetNonConvexMethodToIgnore()
{
  this->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexIgnore);
}

void vtkHAVSVolumeMapper::SetNonConvexMethodToBoundaryLayers()
{
  this->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexBoundaryLayers);
}

void vtkHAVSVolumeMapper::SetNonConvexMethodToConvexification()
{
  this->SetNonConvexMethod(vtkHAVSVisibilityOrder::NonConvexConvexification);
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::IsBlendModeSupported(int mode)
{
  return mode == COMPOSITE_BLEND || mode == MAXIMUM_INTENSITY_BLEND ||
    mode == MINIMUM_INTENSITY_BLEND || mode == ISOSURFACE_BLEND;
}

//------------------------------------------------------------------------------
// The graphics layer's hooks: without one (this class alone), nothing draws.
bool vtkHAVSVolumeMapper::IsKBufferPathSupported(vtkRenderWindow*, int)
{
  return false;
}

int vtkHAVSVolumeMapper::ChooseKBufferPath(vtkRenderer*, int)
{
  return 0;
}

int vtkHAVSVolumeMapper::GetMaximumK(int)
{
  return 0;
}

bool vtkHAVSVolumeMapper::DrawFrame(vtkRenderer*, const FrameRequest&, FrameResult&)
{
  vtkErrorMacro("vtkHAVSVolumeMapper has no graphics layer: create it with New() after "
                "vtk_module_autoinit of vtkHAVS::OpenGL (Python: import vtkhavs).");
  return false;
}

bool vtkHAVSVolumeMapper::CompositeKeptResult(vtkRenderer*)
{
  return false;
}

//------------------------------------------------------------------------------
vtkHAVSMemory::Part vtkHAVSVolumeMapper::GetLargestGPUBufferNeed() const
{
  // The faces' indices in draw order, three 32-bit point ids a face.
  return { "face indices (12 bytes a face)",
    12 * static_cast<size_t>(this->Mesh->GetFaceSet()->GetNumberOfFaces()) };
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::AddMemoryParts(std::vector<vtkHAVSMemory::Part>& parts) const
{
  this->FaceOrder->AddMemoryParts(parts);
  parts.push_back({ "invisible-cell skipping and culling",
    this->Visibility->GetMemoryBytes() + this->Culling->GetMemoryBytes() });
  parts.push_back({ "level-of-detail ranking", this->Ranking->GetMemoryBytes() });
  parts.push_back({ "long-segment table", this->LongSegmentTable->GetMemoryBytes() });
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::ResetLastFrame()
{
  this->LastFrame->Reset();
  this->DrawnFraction = -1.0;
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::MeshPrepared(int update, bool rebuilt)
{
  if (rebuilt)
  {
    this->LevelOfDetailControl->Reset();
    this->FaceOrder->Invalidate();
  }
  if (update == MeshBuilt || update == MeshScalarsMapped)
  {
    this->LastFrame->SetMeshUpdate(this->Mesh->GetLastUpdate());
    this->LastFrame->SetMeshSeconds(this->Mesh->GetLastUpdateSeconds());
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::PrepareTable(vtkVolume* volume)
{
  const bool ok = this->Superclass::PrepareTable(volume);
  this->LastFrame->SetTableRebuilt(this->TableRebuilt);
  this->LastFrame->SetTableSeconds(this->AutomaticTableResolution
      ? this->TableChooser->GetLastSeconds()
      : this->Table->GetLastBuildSeconds());
  return ok;
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::PrepareLongSegmentTable(vtkVolume* volume)
{
  // The main table's resolutions, lengths up to the bounding-box diagonal.
  const double diagonal = this->Mesh->GetDiagonal();
  bool rebuilt = false;
  const bool ok = vtkHAVSMapperInputs::PrepareTable(
    this, volume, this->Mesh, this->LongSegmentTable, this->Table->GetBuiltScalarResolution(),
    this->Table->GetBuiltLengthResolution(), "vtkHAVSVolumeMapper",
    [this](int which, const std::string& m) { this->WarnOnce(which, m); }, &rebuilt, nullptr,
    std::max(diagonal, this->Mesh->GetFaceSet()->GetLongestEdge()));
  if (rebuilt)
  {
    this->LongSegmentTableBuildTime.Modified();
  }
  return ok;
}

//------------------------------------------------------------------------------
double vtkHAVSVolumeMapper::ChooseLevelOfDetail(
  vtkVolume* volume, const vtkHAVSViewFrame& view, FrameRequest& request)
{
  vtkHAVSFrameStatistics* stats = this->LastFrame;
  double fraction = 1.0;
  if (this->BlendMode == COMPOSITE_BLEND)
  {
    fraction = this->LevelOfDetailFraction;
    if (this->LevelOfDetail && this->ImageReduction)
    {
      fraction = std::min(fraction, this->FaceShare); // the base's detail, shared (PixelShare)
    }
    else if (this->LevelOfDetail)
    {
      fraction = std::min(fraction, this->LevelOfDetailControl->Choose(this->FrameBudget(volume)));
    }
  }
  vtkHAVSFaceSet* faces = this->Mesh->GetFaceSet();
  const vtkIdType internal = faces->GetNumberOfFaces() - faces->GetNumberOfBoundaryFaces();
  const vtkIdType limit = static_cast<vtkIdType>(std::floor(fraction * internal + 0.5));
  if (limit >= internal)
  {
    this->FaceOrder->SetFaceSubset(nullptr, 0, 0);
    return 1.0;
  }
  const double rankStart = vtkTimerLog::GetUniversalTime();
  this->Ranking->SetStrategy(this->LevelOfDetailStrategy);
  bool ranked = this->Ranking->Update(this->Mesh, [this](double p) { this->UpdateProgress(p); });
  ranked = this->Ranking->UpdateView(view.DirectionGrid) || ranked;
  if (ranked)
  {
    stats->SetRankingSeconds(vtkTimerLog::GetUniversalTime() - rankStart);
  }
  if (!this->PrepareLongSegmentTable(volume))
  {
    this->FaceOrder->SetFaceSubset(nullptr, 0, 0);
    return 1.0;
  }
  this->FaceOrder->SetFaceSubset(
    &this->Ranking->GetRanks(), static_cast<uint32_t>(limit), this->Ranking->GetRankVersion());
  request.Table = this->LongSegmentTable;
  request.TableVersion = this->LongSegmentTableBuildTime.GetMTime();
  stats->SetLongSegmentTable(true);
  return internal > 0 ? static_cast<double>(limit) / internal : 1.0;
}

bool vtkHAVSVolumeMapper::NeedsKSearch(const vtkHAVSViewFrame& view, int order, int path)
{
  const KSearchKey& last = this->LastKSearch;
  if (this->FoundK == 0 || last.Mesh != this->Mesh->GetBuildTime() || last.Order != order ||
    last.Path != path)
  {
    return true;
  }
  const double* d = view.DirectionGrid;
  const double* e = last.Direction;
  const double dot = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
  const double norms = std::sqrt(
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]));
  const double cosLimit = std::cos(vtkMath::RadiansFromDegrees(5.0));
  if (!(norms > 0.0) || dot < cosLimit * norms)
  {
    return true;
  }
  return std::sqrt(vtkMath::Distance2BetweenPoints(view.EyeGrid, last.Eye)) >
    0.05 * this->Mesh->GetDiagonal();
}

int vtkHAVSVolumeMapper::SearchK(
  vtkRenderer* renderer, FrameRequest request, int maxK, bool& kept, FrameResult& last)
{
  // Counted draws, not composited (each keeps its result).
  request.Composite = false;
  request.CountViolations = true;
  this->KSearchDraws = 0;
  this->KSearchUploads = FrameResult();
  int lastK = 0;
  bool failed = false;
  auto clean = [&](int k)
  {
    request.K = k;
    FrameResult r;
    if (!this->DrawFrame(renderer, request, r))
    {
      failed = true;
      return false;
    }
    ++this->KSearchDraws;
    lastK = k;
    last = r;
    this->KSearchUploads.GeometryUploaded |= r.GeometryUploaded;
    this->KSearchUploads.ScalarsUploaded |= r.ScalarsUploaded;
    this->KSearchUploads.TableUploaded |= r.TableUploaded;
    this->KSearchUploads.OrderUploaded |= r.OrderUploaded;
    return r.Violations == 0;
  };
  const int start =
    std::max(1, std::min(this->FoundK > 0 ? this->FoundK : this->KBufferSize, maxK));
  int bad = 0, good = 0; // the largest k with violations, the smallest without
  (clean(start) ? good : bad) = start;
  while (good == 0 && bad < maxK && !failed)
  {
    const int k = std::min(2 * bad, maxK);
    (clean(k) ? good : bad) = k;
  }
  while (good - bad > 1 && !failed)
  {
    const int k = (good + bad) / 2;
    (clean(k) ? good : bad) = k;
  }
  if (failed)
  {
    kept = false;
    return std::min(this->KBufferSize, maxK);
  }
  if (good == 0)
  {
    this->WarnOnce(vtkHAVSMapperInputs::WarnAutomaticK,
      "Automatic k: no k up to " + std::to_string(maxK) +
        " draws this view without order violations; using k = " + std::to_string(maxK) +
        " (the MPVO order needs k = 2).");
    good = maxK;
  }
  kept = lastK == good;
  KSearchKey& key = this->LastKSearch;
  const vtkHAVSViewFrame& view = *request.View;
  std::copy(view.EyeGrid, view.EyeGrid + 3, key.Eye);
  std::copy(view.DirectionGrid, view.DirectionGrid + 3, key.Direction);
  key.Mesh = this->Mesh->GetBuildTime();
  key.Order = this->FaceOrder->GetLastOrder();
  key.Path = request.Path;
  return good;
}

//------------------------------------------------------------------------------
vtkHAVSInternalFaceRanking* vtkHAVSVolumeMapper::GetLevelOfDetailRanking()
{
  return this->Ranking;
}

vtkHAVSLevelOfDetailController* vtkHAVSVolumeMapper::GetLevelOfDetailController()
{
  return this->LevelOfDetailControl;
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::SetInvisibleCellOpacity(double opacity)
{
  if (opacity != this->Visibility->GetOpacityThreshold())
  {
    this->Visibility->SetOpacityThreshold(opacity);
    this->Modified();
  }
}

double vtkHAVSVolumeMapper::GetInvisibleCellOpacity()
{
  return this->Visibility->GetOpacityThreshold();
}

//------------------------------------------------------------------------------
vtkHAVSVolumeMapper::FrameRequest vtkHAVSVolumeMapper::MakeRequest(
  const vtkHAVSViewFrame& view, int path, int k, bool opaque)
{
  FrameRequest r;
  r.View = &view;
  r.Mesh = this->Mesh;
  r.Table = this->Table;
  r.TableVersion = this->TableBuildTime.GetMTime();
  r.Planes = this->Planes;
  r.Path = path;
  r.K = k;
  r.BlendMode = this->GetFrameBlend();
  r.TerminationOpacity = static_cast<float>(this->EarlyRayTerminationOpacity);
  r.CellScalars = this->Mesh->HasCellScalars();
  r.IsoSurfaces = this->FrameIsoSurfaces.ShaderMode(this->BlendMode);
  r.IsoShade = this->FrameIsoSurfaces.Shaded; // (the fragment-list path: see RenderView)
  r.IsoExact = !this->NoFaceClampForTesting;
  if (r.IsoShade)
  {
    r.PointGradients = &this->GetIsoPointGradients(r.PointGradientsVersion);
  }
  r.Tagging = this->BoundaryMode == BoundaryTagging ||
    (this->BoundaryMode == BoundaryAutomatic &&
      (!this->Mesh->GetFaceSet()->IsConvex() || this->SkippingCells));
  r.GapLength = this->BoundaryMode == BoundaryGapLength
    ? static_cast<float>(this->Table->GetMaxLength())
    : 3.0e38f;
  r.RasterBoundOnly = this->FaceRasterBoundMode;
  r.Opaque = opaque;
  r.MeasureStages = this->MeasureStageTimes;
  r.KeepResult = this->KeepFloatResult;
  r.SkipSaturated = this->GetFrameBlend() == COMPOSITE_BLEND &&
    (this->SkipSaturatedPixels == SkipSaturatedPixelsAlways ||
      (this->SkipSaturatedPixels == SkipSaturatedPixelsAutomatic &&
        path == KBufferPathFragmentShaderInterlock));
  return r;
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::RenderView(
  vtkRenderer* renderer, vtkVolume* volume, const vtkHAVSViewFrame& view)
{
  // (1-3, the mesh, the table and the view: vtkHAVSMapperBase::Render.)
  vtkHAVSFrameStatistics* stats = this->LastFrame;
  const bool composite = this->GetFrameBlend() == COMPOSITE_BLEND;

  // 4. The cells the transfer function hides (composite blend: the extremum
  // modes look at every scalar); recomputed only for a new table or mesh. The
  // raster-bound mode draws the same faces as HAVS would.
  this->SkippingCells = false;
  if (this->SkipInvisibleCells && composite)
  {
    const double visibilityStart = vtkTimerLog::GetUniversalTime();
    const vtkMTimeType before = this->Visibility->GetVisibilityVersion();
    this->Visibility->Update(this->Mesh, this->Table, this->TableBuildTime.GetMTime());
    if (this->Visibility->GetVisibilityVersion() != before)
    {
      stats->SetVisibilitySeconds(vtkTimerLog::GetUniversalTime() - visibilityStart);
    }
    this->SkippingCells = this->Visibility->GetNumberOfInvisibleCells() > 0;
    stats->SetInvisibleCells(this->Visibility->GetNumberOfInvisibleCells());
  }
  this->FaceOrder->SetCellVisibility(
    this->SkippingCells ? &this->Visibility->GetVisible() : nullptr,
    this->Visibility->GetVisibilityVersion());

  // 5. The k-buffer: the path the window runs, and k within its reach. Shaded
  // isosurfaces take the fragment lists (the only path whose entries carry
  // the fragments' gradients).
  const bool isoShade = this->FrameIsoSurfaces.Shaded;
  const int path =
    this->ChooseKBufferPath(renderer, isoShade ? KBufferPathFragmentLists : this->KBufferPath);
  if (isoShade && path != KBufferPathFragmentLists)
  {
    this->FrameIsoSurfaces.Shaded = false;
    this->WarnOnce(Inputs::WarnIsoShading,
      "The fragment-list path, which shaded isosurfaces need, is not supported by this OpenGL "
      "context: the isosurfaces are drawn unshaded (said once).");
  }
  if (path == 0)
  {
    vtkErrorMacro("This OpenGL context has none of the k-buffer paths (it needs OpenGL 4.3 with "
                  "EXT_shader_framebuffer_fetch, or fragment-shader interlock, or OpenGL 4.4).");
    return;
  }
  if (this->KBufferPath != KBufferPathAutomatic && path != this->KBufferPath && !isoShade)
  {
    const std::string message = std::string("The k-buffer path ") +
      GetKBufferPathName(this->KBufferPath) +
      " is not supported by this OpenGL context; choosing automatically.";
    this->WarnOnce(WarnPath, message.c_str());
  }
  const int maxK = this->GetMaximumK(path);
  const int k = std::min(
    this->AutomaticKBufferSize && this->FoundK > 0 ? this->FoundK : this->KBufferSize, maxK);
  if (this->KBufferSize > maxK && !this->AutomaticKBufferSize)
  {
    const std::string message = "k = " + std::to_string(this->KBufferSize) + " exceeds the " +
      GetKBufferPathName(path) + " path's maximum; using k = " + std::to_string(maxK) + ".";
    this->WarnOnce(WarnK, message.c_str());
  }
  FrameRequest request = this->MakeRequest(view, path, k, this->NeedsOpaqueDepth(renderer));

  // 6. The near and clipping planes, and the mesh's sections with them.
  this->UpdatePlanes(view);

  // 7. The cells outside the view frustum or cut away by a clipping plane.
  this->FaceOrder->SetCellCulling(nullptr, 0);
  if (this->SkipOffscreenCells)
  {
    std::vector<std::array<double, 4>> planes = vtkHAVSViewCulling::FrustumPlanes(view.ModelToClip);
    for (int i = 0; i < this->Planes->GetNumberOfPlanes(); ++i)
    {
      planes.push_back(this->Planes->GetModelPlane(i));
    }
    this->Culling->Update(this->Mesh, planes);
    stats->SetCulledCells(this->Culling->GetNumberOfCulledCells());
    stats->SetCullingSeconds(this->Culling->GetLastSeconds());
    if (this->Culling->GetNumberOfCulledCells() > 0)
    {
      this->FaceOrder->SetCellCulling(
        &this->Culling->GetCulled(), this->Culling->GetCullingVersion());
    }
  }

  // 8. The level of detail: every boundary face and the most important
  // internal faces, as many as the time allocated allows.
  const double fraction = this->ChooseLevelOfDetail(volume, view, request);
  stats->SetLevelOfDetailFraction(fraction);
  request.Finish = this->LevelOfDetail;

  // 9. The face order and the draw, 10. the frame's statistics.
  FrameResult result;
  if (this->DrawOrdered(renderer, view, path, maxK, request, result))
  {
    this->RecordStatistics(path, request, result);
    this->DrawnFraction = fraction;
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::DrawOrdered(vtkRenderer* renderer, const vtkHAVSViewFrame& view, int path,
  int maxK, FrameRequest& request, FrameResult& result)
{
  // Automatic's probe may ask for a second draw in the exact order; the
  // automatic k searches with counted draws when the view moved far enough.
  const bool composite = this->GetFrameBlend() == COMPOSITE_BLEND;
  this->FaceOrder->SetVisibilityOrder(this->VisibilityOrder);
  this->FaceOrder->SetNonConvexMethod(this->NonConvexMethod);
  vtkHAVSFaceOrderPolicy::Plan plan =
    this->FaceOrder->Begin(this->Mesh, request.K, path, composite, !this->FaceRasterBoundMode);
  vtkUnstructuredGrid* grid = this->Mesh->GetGrid();
  for (;;)
  {
    if (!this->FaceOrder->Prepare(plan, this->Mesh, grid, view))
    {
      vtkErrorMacro("The MPVO order could not be made for this mesh; using the centroid order.");
    }
    request.DrawTriangles = &this->FaceOrder->GetDrawTriangles();
    request.DrawBoundary = &this->FaceOrder->GetDrawBoundaryFlags();
    request.DrawOrderVersion = this->FaceOrder->GetDrawOrderVersion();
    request.Composite = !plan.Probe;
    request.CountViolations = composite && (this->CountOrderViolations || plan.Probe);
    if (!plan.Probe && composite && this->AutomaticKBufferSize && !this->FaceRasterBoundMode)
    {
      if (this->NeedsKSearch(view, this->FaceOrder->GetLastOrder(), path))
      {
        bool kept = false;
        FrameResult last;
        this->FoundK = this->SearchK(renderer, request, maxK, kept, last);
        this->LastFrame->SetAutomaticKDraws(this->KSearchDraws);
        // (The first draw of the search uploads what changed; later ones nothing.)
        this->RecordUploads(this->KSearchUploads);
        if (kept)
        {
          // The search's last draw was at the k found: it is the frame.
          request.K = this->FoundK;
          result = last;
          if (!this->CountOrderViolations)
          {
            request.CountViolations = false;
          }
          return this->CompositeKeptResult(renderer);
        }
      }
      request.K = this->FoundK;
    }
    result = FrameResult();
    const bool drawn = this->DrawFrame(renderer, request, result);
    this->RecordUploads(result);
    if (!drawn)
    {
      return false;
    }
    if (!plan.Probe)
    {
      return true;
    }
    plan = this->FaceOrder->ProbeResult(result.Violations);
    if (plan.Order < 0)
    {
      // The probe was exact: it is the frame.
      return this->CompositeKeptResult(renderer);
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::RecordUploads(const FrameResult& result)
{
  vtkHAVSFrameStatistics* stats = this->LastFrame;
  stats->SetGeometryUploaded(stats->GetGeometryUploaded() || result.GeometryUploaded);
  stats->SetScalarsUploaded(stats->GetScalarsUploaded() || result.ScalarsUploaded);
  stats->SetOrderUploaded(stats->GetOrderUploaded() || result.OrderUploaded);
  stats->SetTableUploaded(stats->GetTableUploaded() || result.TableUploaded);
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::RecordStatistics(
  int path, const FrameRequest& request, const FrameResult& result)
{
  vtkHAVSFrameStatistics* stats = this->LastFrame;
  const bool composite = this->GetFrameBlend() == COMPOSITE_BLEND;
  stats->SetKBufferPath(path);
  stats->SetKBufferSize(composite ? request.K : 0);
  stats->SetVisibilityOrder(this->FaceOrder->GetLastOrder());
  stats->SetOrderReused(this->FaceOrder->GetLastReused());
  stats->SetCycleBreaks(this->FaceOrder->GetLastCycleBreaks());
  stats->SetBoundaryRelations(this->FaceOrder->GetLastBoundaryRelations());
  stats->SetBoundaryLayerSeconds(this->FaceOrder->GetLastBoundaryLayerSeconds());
  stats->SetSortSeconds(this->FaceOrder->GetLastSeconds());
  stats->SetGatherSeconds(this->FaceOrder->GetLastGatherSeconds());
  stats->SetTagging(request.Tagging);
  stats->SetPlaneCount(this->Planes->GetNumberOfPlanes());
  stats->SetSectionTriangles(this->Planes->GetNumberOfSectionTriangles());
  stats->SetSectionSeconds(this->Planes->GetSectionSeconds());
  stats->SetOrderViolations(request.CountViolations ? result.Violations : -1);
  stats->SetOrderViolationPixels(result.ViolationPixels);
  stats->SetFragments(result.Fragments);
  stats->SetSaturatedPixels(result.SaturatedPixels);
  stats->SetShadedFragments(result.ShadedFragments);
  stats->SetFacesDrawn(static_cast<vtkIdType>(this->FaceOrder->GetDrawTriangles().size() / 3));
  stats->SetFacesOrdered(this->FaceOrder->GetLastOrderedFaces());
  stats->SetOpaqueGeometry(request.Opaque);
  stats->SetOpaqueDepthMultisampled(result.OpaqueDepthMultisampled);
  stats->SetOpaqueDepthCaptured(result.OpaqueDepthCaptured);
  stats->SetUploadSeconds(result.UploadSeconds);
  stats->SetReadbackSeconds(result.ReadbackSeconds);
  stats->SetDrawSeconds(result.DrawSeconds);
  stats->SetFlushSeconds(result.FlushSeconds);
  stats->SetCompositeSeconds(result.CompositeSeconds);
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::FrameFinished(double seconds)
{
  // The frame's time (TimeToDraw, set by the base) for the statistics and,
  // after a drawn frame, the level of detail's controller.
  if (this->DrawnFraction < 0.0)
  {
    return;
  }
  this->LastFrame->SetFrameSeconds(seconds);
  if (this->LevelOfDetail)
  {
    this->LevelOfDetailControl->FrameDrawn(this->DrawnFraction, seconds);
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::SharesDetailWithFaces() const
{
  return this->LevelOfDetail && this->BlendMode == COMPOSITE_BLEND;
}

//------------------------------------------------------------------------------
vtkHAVSFrameStatistics* vtkHAVSVolumeMapper::GetLastFrameStatistics()
{
  return this->LastFrame;
}

int vtkHAVSVolumeMapper::GetActiveKBufferPath()
{
  return this->LastFrame->GetKBufferPath();
}

const char* vtkHAVSVolumeMapper::GetActiveKBufferPathName()
{
  return this->LastFrame->GetKBufferPathName();
}

int vtkHAVSVolumeMapper::GetActiveKBufferSize()
{
  return this->LastFrame->GetKBufferSize();
}

int vtkHAVSVolumeMapper::GetLastVisibilityOrder()
{
  return this->LastFrame->GetVisibilityOrder();
}

vtkIdType vtkHAVSVolumeMapper::GetLastOrderViolations()
{
  return this->LastFrame->GetOrderViolations();
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSVolumeMapper::GetNumberOfFaces()
{
  return this->Mesh->GetFaceSet()->GetNumberOfFaces();
}

vtkIdType vtkHAVSVolumeMapper::GetNumberOfBoundaryFaces()
{
  return this->Mesh->GetFaceSet()->GetNumberOfBoundaryFaces();
}

vtkIdType vtkHAVSVolumeMapper::GetNumberOfTetrahedra()
{
  return this->Mesh->GetFaceSet()->GetNumberOfTetrahedra();
}

bool vtkHAVSVolumeMapper::IsInputConvex()
{
  return this->Mesh->IsValid() && this->Mesh->GetFaceSet()->IsConvex();
}

vtkIdType vtkHAVSVolumeMapper::GetNumberOfImaginaryCells()
{
  return this->FaceOrder->GetExactOrder()->GetNumberOfImaginaryCells();
}

double vtkHAVSVolumeMapper::GetConvexificationSeconds()
{
  return this->FaceOrder->GetExactOrder()->GetConvexificationSeconds();
}

void vtkHAVSVolumeMapper::InvalidateFaceOrder()
{
  this->FaceOrder->Invalidate();
}

vtkHAVSFaceOrderPolicy* vtkHAVSVolumeMapper::GetFaceOrderPolicy()
{
  return this->FaceOrder;
}

vtkHAVSFaceSorter* vtkHAVSVolumeMapper::GetFaceSorter()
{
  return this->FaceOrder->GetCentroidSorter();
}

//------------------------------------------------------------------------------
vtkHAVSPreIntegrationTable* vtkHAVSVolumeMapper::GetPreIntegrationTable()
{
  return this->Table;
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KBufferSize: " << this->KBufferSize
     << ", AutomaticKBufferSize: " << this->AutomaticKBufferSize << "\n";
  os << indent << "KBufferPath (requested): " << GetKBufferPathName(this->KBufferPath) << "\n";
  os << indent << "EarlyRayTerminationOpacity: " << this->EarlyRayTerminationOpacity << "\n";
  os << indent << "SkipOffscreenCells: " << this->SkipOffscreenCells << "\n";
  os << indent << "SkipSaturatedPixels: " << this->SkipSaturatedPixels << "\n";
  os << indent << "SkipInvisibleCells: " << this->SkipInvisibleCells << " (opacity "
     << this->Visibility->GetOpacityThreshold() << ")\n";
  os << indent << "MeasureStageTimes: " << this->MeasureStageTimes << "\n";
  os << indent << "FaceRasterBoundMode: " << this->FaceRasterBoundMode << "\n";
  os << indent << "LevelOfDetail: " << this->LevelOfDetail
     << ", LevelOfDetailFraction: " << this->LevelOfDetailFraction
     << ", LevelOfDetailStrategy: " << this->LevelOfDetailStrategy << "\n";
  const char* orders[] = { "Centroid", "MPVO", "Automatic" };
  const char* methods[] = { "Ignore", "BoundaryLayers", "Convexification" };
  os << indent << "VisibilityOrder: " << orders[this->VisibilityOrder] << "\n";
  os << indent << "NonConvexMethod: " << methods[this->NonConvexMethod] << "\n";
  os << indent << "CountOrderViolations: " << this->CountOrderViolations << "\n";
  os << indent << "NoFaceClampForTesting: " << this->NoFaceClampForTesting << "\n";
  static const char* const boundaryModes[] = { "Automatic", "Tagging", "Ignore", "GapLength" };
  os << indent << "BoundaryMode: " << boundaryModes[this->BoundaryMode] << "\n";
  os << indent << "Mesh data:\n";
  this->Mesh->PrintSelf(os, indent.GetNextIndent());
  os << indent << "LastFrame:\n";
  this->LastFrame->PrintSelf(os, indent.GetNextIndent());
}

VTK_ABI_NAMESPACE_END
