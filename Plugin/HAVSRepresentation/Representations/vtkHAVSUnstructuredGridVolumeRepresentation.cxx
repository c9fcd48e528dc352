/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSUnstructuredGridVolumeRepresentation.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSUnstructuredGridVolumeRepresentation.h"

#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkBoundingBox.h"
#include "vtkCameraPass.h"
#include "vtkCellType.h"
#include "vtkContourValues.h"
#include "vtkDataSet.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSFramePlanes.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSIntermixPass.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkImageProcessingPass.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVLODVolume.h"
#include "vtkPVRenderView.h"
#include "vtkPVRenderViewDataDeliveryManager.h"
#include "vtkPlane.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVersionMacros.h"
#include "vtkVolumeProperty.h"
#include "vtkVolumeRepresentationPreprocessor.h"

#if __has_include("vtkIceTCompositePass.h")
#include "vtkHAVSRankCompositePass.h"
#include "vtkIceTCompositePass.h"
#define HAVS_PLUGIN_HAS_ICET 1
#else
class vtkHAVSRankCompositePass;
class vtkIceTCompositePass;
#endif

#include <dlfcn.h>

#include <algorithm>
#include <cmath>

VTK_ABI_NAMESPACE_BEGIN

namespace
{
/**
 * In place of ParaView's default pass (vtkPVDefaultPass: the delegate of the
 * view's camera pass, or the render pass of IceT's composite pass under MPI):
 * the steps of a vtkHAVSIntermixPass when the frame has translucent geometry
 * and a visible volume with a HAVS mapper (the translucent actors peeled, and
 * composited at their depths inside that volume when its mapper intermixes,
 * under it otherwise: VTK's order); ParaView's own pass otherwise, and for
 * selections. (ParaView's own pass would draw such volumes inside VTK's dual
 * depth peeling, UseDepthPeelingForVolumes, which only VTK's GPU ray caster
 * takes part in: a HAVS volume came out several times too bright there.)
 */
class vtkHAVSIntermixDefaultPass : public vtkRenderPass
{
public:
  static vtkHAVSIntermixDefaultPass* New();
  vtkTypeMacro(vtkHAVSIntermixDefaultPass, vtkRenderPass);

  void Render(const vtkRenderState* s) override
  {
    vtkRenderer* renderer = s->GetRenderer();
    vtkRenderPass* pass = this->Default;
    if (!renderer->GetSelector() && vtkHAVSIntermixPass::HasTranslucentGeometry(s) &&
      vtkHAVSIntermixPass::HasIntermixingVolume(renderer, false))
    {
      this->Intermix->RenderSteps(s);
      pass = this->Intermix;
    }
    else if (pass)
    {
      pass->Render(s);
    }
    this->NumberOfRenderedProps = pass ? pass->GetNumberOfRenderedProps() : 0;
  }
  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    if (this->Default)
    {
      this->Default->ReleaseGraphicsResources(window);
    }
    this->Intermix->ReleaseGraphicsResources(window);
  }

  vtkSmartPointer<vtkRenderPass> Default; ///< ParaView's pass it stands in for
  vtkNew<vtkHAVSIntermixPass> Intermix;

protected:
  vtkHAVSIntermixDefaultPass() = default;
  ~vtkHAVSIntermixDefaultPass() override = default;
};
vtkStandardNewMacro(vtkHAVSIntermixDefaultPass);

/// `pass`'s default pass replaced by a vtkHAVSIntermixDefaultPass (once).
void InstallIntermixIn(vtkIceTCompositePass* icet);

/**
 * Puts a vtkHAVSIntermixDefaultPass in place of ParaView's default pass in
 * `renderer`'s passes (serial: camera pass -> default pass, behind ParaView's
 * image processing passes; under MPI: camera pass -> IceT's composite pass ->
 * default pass, and a vtkHAVSRankCompositePass between the camera pass and
 * IceT's, which composites the ranks' volumes in float). Again every frame:
 * ParaView makes its passes anew when its settings change. Nothing when
 * another pass stands there (OSPRay, value passes) or one is in place
 * already. Returns the rank composite pass (nullptr in serial).
 */
vtkRenderPass* InstallIntermix(vtkRenderer* renderer)
{
  vtkRenderPass* pass = renderer ? renderer->GetPass() : nullptr;
  for (int depth = 0; pass && depth < 8; ++depth)
  {
    if (auto* camera = vtkCameraPass::SafeDownCast(pass))
    {
      vtkRenderPass* inner = camera->GetDelegatePass();
      if (vtkPVDefaultPass::SafeDownCast(inner))
      {
        vtkNew<vtkHAVSIntermixDefaultPass> intermix;
        intermix->Default = inner;
        camera->SetDelegatePass(intermix);
      }
#if HAVS_PLUGIN_HAS_ICET
      else if (auto* icet = vtkIceTCompositePass::SafeDownCast(inner))
      {
        InstallIntermixIn(icet);
        vtkNew<vtkHAVSRankCompositePass> ranks;
        ranks->SetIceTPass(icet);
        camera->SetDelegatePass(ranks);
        return ranks;
      }
      else if (auto* ranks = vtkHAVSRankCompositePass::SafeDownCast(inner))
      {
        InstallIntermixIn(ranks->GetIceTPass());
        return ranks;
      }
#endif
      return nullptr;
    }
    auto* processing = vtkImageProcessingPass::SafeDownCast(pass);
    pass = processing ? processing->GetDelegatePass() : nullptr;
  }
  return nullptr;
}

void InstallIntermixIn(vtkIceTCompositePass* icet)
{
#if HAVS_PLUGIN_HAS_ICET
  if (icet && vtkPVDefaultPass::SafeDownCast(icet->GetRenderPass()))
  {
    vtkNew<vtkHAVSIntermixDefaultPass> intermix;
    intermix->Default = icet->GetRenderPass();
    icet->SetRenderPass(intermix);
  }
#else
  (void)icet;
#endif
}
}

vtkStandardNewMacro(vtkHAVSUnstructuredGridVolumeRepresentation);

namespace
{
/// Whether this process's expat defers reparsing (expat >= 2.6, Debian 12's
/// 2.5.0-1+deb12u5) without vtkHAVSExpatFix preloaded: VTK 9.2's XML parser
/// then fails, and with it ParaView's redistribution of a grid between ranks.
bool ExpatBreaksVTKXML()
{
  return dlsym(RTLD_DEFAULT, "XML_SetReparseDeferralEnabled") != nullptr &&
    dlsym(RTLD_DEFAULT, "vtkHAVSExpatFixParserCount") == nullptr;
}

/// The box around every rank's (valid) kd box.
vtkBoundingBox UnionOfCuts(const std::vector<vtkBoundingBox>& cuts)
{
  vtkBoundingBox whole;
  for (const vtkBoundingBox& cut : cuts)
  {
    if (cut.IsValid())
    {
      whole.AddBox(cut);
    }
  }
  return whole;
}

/// Drops the polyhedron face arrays of a grid without polyhedra; whether it
/// did. VTK 9.2's vtkXMLPUnstructuredGridReader (ParaView 5.11's .pvtu
/// reader) gives its cell types array uninitialized to
/// vtkUnstructuredGrid::SetCells(types, cells), which takes any byte 42
/// (VTK_POLYHEDRON) left in that memory for a polyhedron and makes empty
/// Faces and FaceLocations arrays; the reader then fills in the cells and
/// leaves them empty. vtkDataSetTriangleFilter passes a grid of tetrahedra
/// through as it is, and vtkRedistributeDataSetFilter::SplitDataSet's
/// vtkExtractCells reads FaceLocations for every cell it extracts (the range
/// of an empty array is not [-1, -1]): past the end, a SIGSEGV.
bool DropStaleFaces(vtkUnstructuredGrid* grid)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
  // (VTK 9.4 keeps polyhedron faces in vtkCellArrays; the same repair.)
  if (!grid || (!grid->GetPolyhedronFaces() && !grid->GetPolyhedronFaceLocations()))
  {
    return false;
  }
#else
  if (!grid || (!grid->GetFaces() && !grid->GetFaceLocations()))
  {
    return false;
  }
#endif
  const vtkIdType cells = grid->GetNumberOfCells();
  for (vtkIdType i = 0; i < cells; ++i)
  {
    if (grid->GetCellType(i) == VTK_POLYHEDRON)
    {
      return false; // real polyhedra (not after the preprocessor's tetrahedralization)
    }
  }
  // The grid's own arrays are replaced, not changed: those it shares with
  // the reader's output stay as they are.
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
  grid->SetPolyhedralCells(grid->GetCellTypes(), grid->GetCells(), nullptr, nullptr);
#else
  grid->SetCells(grid->GetCellTypesArray(), grid->GetCells(), nullptr, nullptr);
#endif
  return true;
}

/// The view's data delivery manager, which knows the kd-tree's cuts (one box
/// per rank, in the data's coordinates); nullptr outside a render view.
vtkPVRenderViewDataDeliveryManager* DeliveryManager(vtkInformation* inInfo)
{
  auto* view = vtkPVView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
  return view ? vtkPVRenderViewDataDeliveryManager::SafeDownCast(view->GetDeliveryManager())
              : nullptr;
}
}

//------------------------------------------------------------------------------
vtkHAVSUnstructuredGridVolumeRepresentation::vtkHAVSUnstructuredGridVolumeRepresentation()
{
  this->HAVSMapper = vtkHAVSVolumeMapper::New();
  static bool warnedExpat = false;
  if (!warnedExpat && ExpatBreaksVTKXML())
  {
    warnedExpat = true;
    vtkWarningMacro("This expat defers reparsing (expat >= 2.6, or Debian 12's security update "
                    "2.5.0-1+deb12u5), which breaks VTK 9.2's XML readers: .vtu files and the "
                    "redistribution of grids between MPI ranks fail. Start ParaView with "
                    "LD_PRELOAD=<vtkHAVS>/lib/libvtkHAVSExpatFix.so (see the vtkHAVS user guide).");
  }
  // The three mappers, one prepared mesh: switching between them does not
  // tetrahedralize and index the grid again (GetHAVSLastMeshUpdate says so).
  // New() gives nullptr without the graphics layer's override
  // (vtkHAVS::OpenGL, which this module links): then that one is not offered.
  this->RayCastMapper = vtkHAVSRayCastMapper::New();
  this->CellProjectionMapper = vtkHAVSCellProjectionMapper::New();
  const std::pair<const char*, vtkHAVSMapperBase*> mappers[] = { { "HAVS", this->HAVSMapper },
    { "HAVS Ray Cast", this->RayCastMapper },
    { "HAVS Cell Projection", this->CellProjectionMapper } };
  for (const auto& named : mappers)
  {
    if (named.second)
    {
      named.second->SetMesh(this->HAVSMapper->GetMesh());
      this->AddVolumeMapper(named.first, named.second);
      this->Mappers.emplace_back(named.first, named.second);
    }
  }
  this->SetActiveVolumeMapper("HAVS");
  // Exactly coincident points only (a cut through a vertex makes a new point
  // on it); the point data of the first is kept (they are equal there).
  this->PieceMerge->ToleranceIsAbsoluteOn();
  this->PieceMerge->SetAbsoluteTolerance(0.0);
  this->PieceMerge->RemoveUnusedPointsOff();
  this->PieceMerge->AveragePointDataOff();
}

//------------------------------------------------------------------------------
vtkHAVSUnstructuredGridVolumeRepresentation::~vtkHAVSUnstructuredGridVolumeRepresentation()
{
  for (const auto& named : this->Mappers)
  {
    named.second->Delete();
  }
}

//------------------------------------------------------------------------------
int vtkHAVSUnstructuredGridVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  // The piece the view delivers and redistributes (ProcessViewRequest's
  // REQUEST_UPDATE in the superclass): a shallow copy of the tetrahedralized
  // input, owned by the preprocessor.
  if (DropStaleFaces(vtkUnstructuredGrid::SafeDownCast(this->Preprocessor->GetOutputDataObject(0))))
  {
    vtkDebugMacro("Dropped the input's empty polyhedron face arrays (no polyhedra).");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::SetActiveVolumeMapper(const char*)
{
  this->Superclass::SetActiveVolumeMapper(this->HAVSMapperName.c_str());
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSMapper(const char* name)
{
  const std::string wanted = name ? name : "";
  if (!this->FindMapper(wanted))
  {
    std::string known;
    for (const auto& named : this->Mappers)
    {
      known += (known.empty() ? "\"" : ", \"") + named.first + "\"";
    }
    vtkErrorMacro("Unknown HAVS mapper \"" << wanted << "\" (" << known << ").");
    return;
  }
  if (wanted != this->HAVSMapperName)
  {
    this->HAVSMapperName = wanted;
    this->Superclass::SetActiveVolumeMapper(this->HAVSMapperName.c_str());
    this->Modified();
  }
}

vtkHAVSMapperBase* vtkHAVSUnstructuredGridVolumeRepresentation::FindMapper(
  const std::string& name) const
{
  for (const auto& named : this->Mappers)
  {
    if (named.first == name)
    {
      return named.second;
    }
  }
  return nullptr;
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSLastMeshUpdate()
{
  vtkHAVSMapperBase* active = this->FindMapper(this->HAVSMapperName);
  return active ? active->GetLastMeshUpdate() : 0;
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSMaximumPeelPasses(int passes)
{
  if (this->RayCastMapper)
  {
    this->RayCastMapper->SetMaximumPeelPasses(passes);
  }
  this->Modified();
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSLastPeelPasses()
{
  return this->RayCastMapper ? this->RayCastMapper->GetLastPeelPasses() : 0;
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSKBufferSize(int k)
{
  if (this->KBufferSize != k)
  {
    this->KBufferSize = k;
    this->HAVSMapper->SetKBufferSize(k);
    this->Modified();
  }
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSKBufferSize()
{
  return this->KBufferSize;
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSActiveKBufferSize()
{
  return this->HAVSMapper->GetActiveKBufferSize();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSEarlyRayTerminationOpacity(double opacity)
{
  this->HAVSMapper->SetEarlyRayTerminationOpacity(opacity);
  if (this->RayCastMapper)
  {
    this->RayCastMapper->SetEarlyRayTerminationOpacity(opacity);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSTableResolution(int resolution)
{
  for (const auto& named : this->Mappers)
  {
    named.second->SetTableScalarResolution(resolution);
    named.second->SetTableLengthResolution(resolution);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSHigherOrderSubdivision(int level)
{
  for (const auto& named : this->Mappers)
  {
    named.second->SetHigherOrderSubdivision(level);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSAutomaticTable(int automatic)
{
  for (const auto& named : this->Mappers)
  {
    named.second->SetAutomaticTableResolution(automatic != 0);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSSkipHiddenCells(int skip)
{
  this->HAVSMapper->SetSkipInvisibleCells(skip != 0);
  this->HAVSMapper->SetSkipOffscreenCells(skip != 0);
  this->HAVSMapper->SetSkipSaturatedPixels(skip != 0
      ? vtkHAVSVolumeMapper::SkipSaturatedPixelsAutomatic
      : vtkHAVSVolumeMapper::SkipSaturatedPixelsNever);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSBoundaryMode(int mode)
{
  this->HAVSMapper->SetBoundaryMode(mode);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSVisibilityOrder(int order)
{
  this->HAVSMapper->SetVisibilityOrder(order);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSNonConvexMethod(int method)
{
  this->HAVSMapper->SetNonConvexMethod(method);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSCountOrderViolations(int count)
{
  this->HAVSMapper->SetCountOrderViolations(count != 0);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSLODStrategy(int strategy)
{
  this->HAVSMapper->SetLevelOfDetailStrategy(strategy);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSBlendMode(int mode)
{
  for (const auto& named : this->Mappers)
  {
    named.second->SetBlendMode(mode);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSIntermixTranslucentGeometry(int on)
{
  for (const auto& named : this->Mappers)
  {
    named.second->SetIntermixTranslucentGeometry(on != 0);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSIsoSurfacesInComposite(int on)
{
  for (const auto& named : this->Mappers)
  {
    named.second->SetIsoSurfacesInComposite(on != 0);
  }
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetNumberOfIsosurfaces(int count)
{
  this->Property->GetIsoSurfaceValues()->SetNumberOfContours(count);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetIsosurfaceValue(int i, double value)
{
  this->Property->GetIsoSurfaceValues()->SetValue(i, value);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSShade(int on)
{
  this->Property->SetShade(on != 0 ? 1 : 0);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSAmbient(double value)
{
  this->Property->SetAmbient(value);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSDiffuse(double value)
{
  this->Property->SetDiffuse(value);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSSpecular(double value)
{
  this->Property->SetSpecular(value);
  this->Modified();
}

void vtkHAVSUnstructuredGridVolumeRepresentation::SetHAVSSpecularPower(double value)
{
  this->Property->SetSpecularPower(value);
  this->Modified();
}

double vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSLastLODFraction()
{
  return this->HAVSMapper->GetLastFrameStatistics()->GetLevelOfDetailFraction();
}

int vtkHAVSUnstructuredGridVolumeRepresentation::GetHAVSLastOrderViolations()
{
  return static_cast<int>(this->HAVSMapper->GetLastOrderViolations());
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::SetRedistribution(int mode)
{
  if (mode < RedistributionWholeCells || mode > RedistributionClip)
  {
    vtkErrorMacro("Unknown redistribution " << mode << " (0 whole cells, 1 split, 2 clip); kept "
                                            << this->Redistribution << ".");
    return;
  }
  if (mode != this->Redistribution)
  {
    this->Redistribution = mode;
    this->MarkModified(); // the view redistributes again
  }
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::UpdateRegionPlanes(
  vtkInformation* inInfo, vtkHAVSMapperBase* active)
{
  // RegionPlanes is this representation's collection: the user's own planes of
  // the active mapper (any collection it holds that is not ours, kept in
  // UserPlanes) followed by this rank's kd box. A mapper that is not active
  // gets its own planes back.
  for (const auto& named : this->Mappers)
  {
    vtkHAVSMapperBase* mapper = named.second;
    if (mapper->GetClippingPlanes() != this->RegionPlanes)
    {
      this->UserPlanes[mapper] = mapper->GetClippingPlanes();
    }
    else if (mapper != active)
    {
      mapper->SetClippingPlanes(this->UserPlanes[mapper]);
    }
  }
  vtkPlaneCollection* user = this->UserPlanes[active];
  this->RegionPlanes->RemoveAllItems();
  this->LastRegionPlanes = 0;
  auto* controller = vtkMultiProcessController::GetGlobalController();
  auto* delivery = DeliveryManager(inInfo);
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const bool clip = this->Redistribution == RedistributionClip && !this->UseDataPartitions &&
    ranks > 1 && delivery && static_cast<int>(delivery->GetCuts().size()) == ranks;
  const std::vector<vtkBoundingBox> cuts =
    clip ? delivery->GetCuts() : std::vector<vtkBoundingBox>();
  const vtkBoundingBox whole = UnionOfCuts(cuts);
  if (!clip || !cuts[rank].IsValid() || !whole.IsValid())
  {
    if (active->GetClippingPlanes() == this->RegionPlanes)
    {
      active->SetClippingPlanes(user);
    }
    return;
  }
  // This rank's kd box, clipped only where it meets another rank's (the
  // outer faces hold the whole grid). The cuts are in the data's
  // coordinates, the mappers' planes in world coordinates: through the
  // volume's matrix (points by M, normals by M^-T).
  const vtkBoundingBox& box = cuts[rank];
  vtkNew<vtkMatrix4x4> matrix;
  this->Actor->GetMatrix(matrix);
  vtkNew<vtkMatrix4x4> inverseTranspose;
  vtkMatrix4x4::Invert(matrix, inverseTranspose);
  inverseTranspose->Transpose();
  const double tolerance = 1e-9 * whole.GetDiagonalLength();
  std::vector<vtkSmartPointer<vtkPlane>> region;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      const double at = side == 0 ? box.GetMinPoint()[axis] : box.GetMaxPoint()[axis];
      const double outer = side == 0 ? whole.GetMinPoint()[axis] : whole.GetMaxPoint()[axis];
      if (std::abs(at - outer) <= tolerance)
      {
        continue;
      }
      double origin[4] = { 0.0, 0.0, 0.0, 1.0 };
      box.GetCenter(origin);
      origin[axis] = at;
      double normal[4] = { 0.0, 0.0, 0.0, 0.0 };
      normal[axis] = side == 0 ? 1.0 : -1.0; // into the box: that side is kept
      matrix->MultiplyPoint(origin, origin);
      inverseTranspose->MultiplyPoint(normal, normal);
      auto plane = vtkSmartPointer<vtkPlane>::New();
      plane->SetOrigin(origin[0] / origin[3], origin[1] / origin[3], origin[2] / origin[3]);
      plane->SetNormal(normal[0], normal[1], normal[2]);
      region.push_back(plane);
    }
  }
  // The user's planes first, as many as fit beside the box's (the mappers use
  // vtkHAVSFramePlanes::MaximumClippingPlanes); the box's are all needed, or
  // the cells this rank shares with its neighbours would be drawn twice.
  const int room = vtkHAVSFramePlanes::MaximumClippingPlanes - static_cast<int>(region.size());
  const int own = user ? user->GetNumberOfItems() : 0;
  for (int i = 0; i < std::min(own, room); ++i)
  {
    this->RegionPlanes->AddItem(user->GetItem(i));
  }
  if (own > room && !this->WarnedPlanes)
  {
    this->WarnedPlanes = true;
    vtkWarningMacro("The HAVS mapper's own clipping planes ("
      << own << ") and this rank's kd box (" << region.size() << " planes) exceed the mappers' "
      << vtkHAVSFramePlanes::MaximumClippingPlanes << "; only the first " << std::max(room, 0)
      << " of the mapper's planes are used (Redistribution: clip to the region). Use the split "
         "redistribution to keep them all.");
  }
  for (const auto& plane : region)
  {
    this->RegionPlanes->AddItem(plane);
  }
  this->LastRegionPlanes = static_cast<int>(region.size());
  if (active->GetClippingPlanes() != this->RegionPlanes)
  {
    active->SetClippingPlanes(this->RegionPlanes);
  }
  this->RegionPlanes->Modified();
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::WarnIfPartitionsOverlap(vtkInformation* inInfo)
{
  // With UseDataPartitions ParaView composites the ranks in the order of
  // their pieces' bounding boxes (the cuts are those boxes): exact when they
  // are disjoint, not when two overlap (a ray may cross one, the other, then
  // the first again).
  auto* controller = vtkMultiProcessController::GetGlobalController();
  auto* delivery = DeliveryManager(inInfo);
  if (this->WarnedOverlap || !this->UseDataPartitions || !controller ||
    controller->GetNumberOfProcesses() < 2 || !delivery)
  {
    return;
  }
  const std::vector<vtkBoundingBox>& cuts = delivery->GetCuts();
  const double tolerance = 1e-6 * UnionOfCuts(cuts).GetDiagonalLength();
  for (size_t i = 0; i < cuts.size(); ++i)
  {
    for (size_t j = i + 1; j < cuts.size(); ++j)
    {
      if (!cuts[i].IsValid() || !cuts[j].IsValid())
      {
        continue;
      }
      bool overlap = true;
      for (int axis = 0; axis < 3 && overlap; ++axis)
      {
        const double lo = std::max(cuts[i].GetMinPoint()[axis], cuts[j].GetMinPoint()[axis]);
        const double hi = std::min(cuts[i].GetMaxPoint()[axis], cuts[j].GetMaxPoint()[axis]);
        overlap = hi - lo > tolerance;
      }
      if (overlap)
      {
        this->WarnedOverlap = true;
        vtkWarningMacro("UseDataPartitions: the pieces of ranks "
          << i << " and " << j
          << " have overlapping bounding boxes, so ParaView's compositing in the order of "
             "those boxes cannot be exact (seams where they overlap). Turn UseDataPartitions "
             "off to let ParaView redistribute the grid (split at its kd-tree's cuts), or "
             "partition the data into disjoint boxes.");
        return;
      }
    }
  }
}

//------------------------------------------------------------------------------
int vtkHAVSUnstructuredGridVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }
  if (request_type == vtkPVView::REQUEST_UPDATE() && !this->UseDataPartitions)
  {
    // The superclass asked for whole cells (ASSIGN_TO_ONE_REGION); replace it.
    if (this->Redistribution == RedistributionSplit)
    {
      vtkPVRenderView::SetRedistributionModeToSplitBoundaryCells(inInfo, this);
    }
    else if (this->Redistribution == RedistributionClip)
    {
      vtkPVRenderView::SetRedistributionModeToDuplicateBoundaryCells(inInfo, this);
    }
  }
  vtkAbstractVolumeMapper* active = this->GetActiveVolumeMapper();
  if (request_type != vtkPVView::REQUEST_RENDER() || !vtkHAVSMapperBase::SafeDownCast(active))
  {
    return 1;
  }
  // Translucent surfaces of the view intermixed with this volume (the mappers'
  // IntermixTranslucentGeometry), through the view's renderer's passes.
  if (auto* view = vtkPVRenderView::SafeDownCast(this->GetView()))
  {
    this->RankComposite = InstallIntermix(view->GetRenderer());
  }
  // Under MPI the ranks' still frames composited in float
  // (vtkHAVSRankCompositePass) from the mappers' kept float results.
  {
    auto* global = vtkMultiProcessController::GetGlobalController();
    const bool parallel = global && global->GetNumberOfProcesses() > 1;
    const bool still = !inInfo->Has(vtkPVRenderView::USE_LOD());
    for (const auto& named : this->Mappers)
    {
      named.second->SetKeepFloatResult(named.second == active && parallel && still &&
        this->FloatComposite && this->RankComposite != nullptr);
    }
  }
  this->UpdateRegionPlanes(inInfo, vtkHAVSMapperBase::SafeDownCast(active));
  this->WarnIfPartitionsOverlap(inInfo);
  vtkAlgorithmOutput* producer = vtkPVRenderView::GetPieceProducer(inInfo, this);
  vtkDataSet* piece =
    producer ? vtkDataSet::SafeDownCast(producer->GetProducer()->GetOutputDataObject(0)) : nullptr;
  if (!piece || piece->GetNumberOfCells() == 0)
  {
    this->Actor->SetMapper(nullptr); // an empty piece of a parallel run: nothing to draw
    return 1;
  }
  auto* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1 && !this->UseDataPartitions &&
    this->Redistribution == RedistributionSplit && vtkUnstructuredGrid::SafeDownCast(piece))
  {
    // The cells split at the cuts meet their neighbours through points
    // ParaView's clip made anew on existing vertices: merged, or the faces
    // there would not match (false boundary faces, zero-volume tetrahedra).
    this->PieceMerge->SetInputConnection(producer);
    active->SetInputConnection(this->PieceMerge->GetOutputPort());
  }
  // The mappers' own level of detail instead of ParaView's LOD geometry: keep
  // the volume while interacting, drawn within the interactive target time
  // (a reduced image, upsampled; HAVS also a subset of the internal faces and
  // fewer k-buffer entries); the whole image, every face, when still (an
  // unlimited budget). ParaView's own image reduction (remote rendering's
  // image reduction factor) shrinks the viewport the mapper is given: the
  // mapper's controller times its frames at that size and reduces only what
  // the target still asks for, so the two do not multiply.
  auto* mapper = vtkHAVSMapperBase::SafeDownCast(active);
  const bool interactive = inInfo->Has(vtkPVRenderView::USE_LOD()) != 0;
  if (!this->InteractiveLOD)
  {
    this->HAVSMapper->SetKBufferSize(this->KBufferSize);
    mapper->SetLevelOfDetailTargetSeconds(VTK_DOUBLE_MAX);
    return 1; // ParaView's LOD geometry while interacting
  }
  this->Actor->SetEnableLOD(0);
  mapper->SetLevelOfDetailTargetSeconds(
    interactive ? this->InteractiveTargetSeconds : VTK_DOUBLE_MAX);
  this->HAVSMapper->SetKBufferSize(
    interactive ? std::min(this->InteractiveKBufferSize, this->KBufferSize) : this->KBufferSize);
  return 1;
}

//------------------------------------------------------------------------------
int vtkHAVSUnstructuredGridVolumeRepresentation::GetLastFloatComposite()
{
#if HAVS_PLUGIN_HAS_ICET
  if (auto* ranks = vtkHAVSRankCompositePass::SafeDownCast(this->RankComposite))
  {
    return ranks->GetLastFloatComposite();
  }
#endif
  return -1;
}

double vtkHAVSUnstructuredGridVolumeRepresentation::GetLastFloatCompositeSeconds()
{
#if HAVS_PLUGIN_HAS_ICET
  auto* ranks = vtkHAVSRankCompositePass::SafeDownCast(this->RankComposite);
  if (ranks && ranks->GetLastFloatComposite() == 1)
  {
    return ranks->GetLastCompositeSeconds();
  }
#endif
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkHAVSUnstructuredGridVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HAVSMapper: " << this->HAVSMapperName << "\n";
  os << indent << "KBufferSize: " << this->KBufferSize << "\n";
  os << indent << "InteractiveLOD: " << this->InteractiveLOD << "\n";
  os << indent << "InteractiveKBufferSize: " << this->InteractiveKBufferSize << "\n";
  os << indent << "InteractiveTargetSeconds: " << this->InteractiveTargetSeconds << "\n";
  os << indent << "Redistribution: " << this->Redistribution << "\n";
  os << indent << "LastRegionPlanes: " << this->LastRegionPlanes << "\n";
  os << indent << "FloatComposite: " << this->FloatComposite << "\n";
  os << indent << "LastFloatComposite: " << this->GetLastFloatComposite() << "\n";
  for (const auto& named : this->Mappers)
  {
    os << indent << named.first << ":\n";
    named.second->PrintSelf(os, indent.GetNextIndent());
  }
}

VTK_ABI_NAMESPACE_END
