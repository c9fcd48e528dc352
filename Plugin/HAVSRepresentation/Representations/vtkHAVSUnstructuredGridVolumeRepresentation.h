/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSUnstructuredGridVolumeRepresentation.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSUnstructuredGridVolumeRepresentation
 * @brief   ParaView's unstructured-grid volume representation, rendering with HAVS.
 *
 * A vtkUnstructuredGridVolumeRepresentation that renders with one of the
 * three vtkHAVS mappers, registered as "HAVS" (vtkHAVSVolumeMapper, active
 * by default), "HAVS Ray Cast" (vtkHAVSRayCastMapper) and "HAVS Cell
 * Projection" (vtkHAVSCellProjectionMapper), chosen with SetHAVSMapper (the
 * stock mappers stay registered by the SI class but are not selected here:
 * ParaView's "Volume" representation offers them). The three share one
 * prepared mesh (vtkHAVSMapperBase::SetMesh): switching mapper does not
 * tetrahedralize the grid again (GetHAVSLastMeshUpdate). ParaView's data
 * redistribution, ordered compositing, transfer functions and block selection
 * work as for the stock "Volume" representation; the plugin's XML shows it as
 * the "HAVS Volume" representation type.
 *
 * Under MPI (pvbatch, pvserver) ParaView splits the grid over the ranks
 * along a kd-tree and IceT composites the ranks' images in the order of
 * their kd boxes. That order is exact only when each rank's piece lies in
 * its box; ParaView's stock representation sends a cell that straddles a
 * cut whole to one rank, and the parts that stick out are blended in the
 * wrong order (a seam along the cuts). This representation asks for every
 * cell that touches a box to go to its rank, and each rank clips its piece
 * to its box with the mappers' clipping planes (SetRedistribution,
 * RedistributionClip, the default), or for the cells on the cuts to be split
 * there by ParaView (RedistributionSplit); RedistributionWholeCells is
 * ParaView's stock behaviour, kept as a control. The split leaves points
 * where a cut passes through a vertex as new points on the vertex (clipped
 * edges at parameter 0): the split piece's exactly coincident points are
 * merged before the mapper sees it, so the cells still meet face to face.
 * With UseDataPartitions on
 * (the user's own partition, nothing moved) the image is exact when the
 * ranks' pieces' bounding boxes do not overlap; when they do the
 * representation warns once and says so.
 *
 * Level of detail: while the user interacts ParaView would swap the volume
 * for its LOD geometry (an outline or a surface); HAVS stays interactive
 * instead, so this representation keeps the volume and renders it with
 * InteractiveKBufferSize entries (default 2) until the still render, which
 * uses the full k. The ray caster and the cell projection have no level of
 * detail of their own: while interacting ParaView's LOD applies to them, as
 * to the stock mappers.
 *
 * The settings are forwarded to the mappers on every rank: the shared ones
 * (table size, higher-order subdivision) to all three, the early ray
 * termination to HAVS and the ray caster, the others (k, face order, level
 * of detail, ...) to vtkHAVSVolumeMapper, the peeling limit to the ray caster.
 */
#ifndef vtkHAVSUnstructuredGridVolumeRepresentation_h
#define vtkHAVSUnstructuredGridVolumeRepresentation_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSRepresentationsModule.h"   // For export macro
#include "vtkNew.h"                         // For vtkNew
#include "vtkPlaneCollection.h"             // For vtkNew<vtkPlaneCollection>
#include "vtkSmartPointer.h"                // For vtkSmartPointer
#include "vtkStaticCleanUnstructuredGrid.h" // For vtkNew<vtkStaticCleanUnstructuredGrid>
#include "vtkUnstructuredGridVolumeRepresentation.h"
#include "vtkWeakPointer.h" // For vtkWeakPointer

#include <map>     // For std::map
#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSCellProjectionMapper;
class vtkHAVSMapperBase;
class vtkHAVSRayCastMapper;
class vtkHAVSVolumeMapper;

class VTKHAVSREPRESENTATIONS_EXPORT vtkHAVSUnstructuredGridVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  static vtkHAVSUnstructuredGridVolumeRepresentation* New();
  vtkTypeMacro(
    vtkHAVSUnstructuredGridVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Which of vtkHAVS's mappers renders: "HAVS" (vtkHAVSVolumeMapper, the
   * default), "HAVS Ray Cast" (vtkHAVSRayCastMapper: GPU ray casting
   * through the tetrahedra, no sorting) or "HAVS Cell Projection"
   * (vtkHAVSCellProjectionMapper: the cells in the exact order). Any other
   * name is an error and keeps the mapper.
   */
  void SetHAVSMapper(const char* name);
  const char* GetHAVSMapper() { return this->HAVSMapperName.c_str(); }
  ///@}

  ///@{
  /// Forwarded to every mapper (vtkHAVSMapperBase's shared settings).
  void SetHAVSTableResolution(int resolution);
  void SetHAVSHigherOrderSubdivision(int level);
  ///@}

  /// Forwarded to HAVS and the ray caster (the cell projection has no early termination).
  void SetHAVSEarlyRayTerminationOpacity(double opacity);

  /// What the active mapper's last frame did with the prepared mesh
  /// (vtkHAVSMapperBase::MeshUpdates: 2 built, 4 shared, prepared by another
  /// of the representation's mappers; 1 unchanged; 0 before a frame).
  int GetHAVSLastMeshUpdate();

  ///@{
  /// Forwarded to vtkHAVSRayCastMapper (see there): the most depth-peeling
  /// passes per frame (0: as many as the mesh needs, the default).
  void SetHAVSMaximumPeelPasses(int passes);
  ///@}

  /// The depth-peeling passes of the last frame the ray caster drew on this
  /// rank (0 before one).
  int GetHAVSLastPeelPasses();

  ///@{
  /// Forwarded to vtkHAVSVolumeMapper (see there).
  void SetHAVSKBufferSize(int k);
  int GetHAVSKBufferSize();
  void SetHAVSAutomaticTable(int automatic);
  void SetHAVSSkipHiddenCells(int skip);
  void SetHAVSBoundaryMode(int mode);
  void SetHAVSVisibilityOrder(int order);
  void SetHAVSNonConvexMethod(int method);
  void SetHAVSCountOrderViolations(int count);
  void SetHAVSLODStrategy(int strategy);
  ///@}

  ///@{
  /**
   * Forwarded to the three mappers (vtkHAVSMapperBase): the blend mode
   * (vtkVolumeMapper's values; 5 the isosurfaces) and the mixed mode; the
   * isovalues go to the volume property (vtkVolumeProperty::GetIsoSurfaceValues,
   * as ParaView's image volume representation sets them).
   */
  void SetHAVSBlendMode(int mode);
  void SetHAVSIsoSurfacesInComposite(int on);
  /**
   * Translucent surfaces of the view composited at their depths inside the
   * volume (vtkHAVSMapperBase::IntermixTranslucentGeometry, on by default):
   * the representation puts a vtkHAVSIntermixPass's steps in place of
   * ParaView's default pass in the view's renderer (serially behind the
   * camera pass, under MPI behind IceT's composite pass), which stand aside
   * (ParaView's pass draws) in frames without translucent geometry or without
   * an intermixing volume, and for selections.
   */
  void SetHAVSIntermixTranslucentGeometry(int on);
  void SetNumberOfIsosurfaces(int count);
  void SetIsosurfaceValue(int i, double value);
  /**
   * The isosurfaces lit (the volume property's Shade and its lighting
   * coefficients; vtkHAVSIsoSurfaces::Shade): the view's lights, the normal
   * of the interpolated point gradients, for the three mappers. The volume
   * between them stays unshaded.
   */
  void SetHAVSShade(int on);
  void SetHAVSAmbient(double value);
  void SetHAVSDiffuse(double value);
  void SetHAVSSpecular(double value);
  void SetHAVSSpecularPower(double value);
  ///@}

  /// The order violations of the last frame this rank rendered (counted when
  /// SetHAVSCountOrderViolations is on or while Automatic probes; -1 when not
  /// counted).
  int GetHAVSLastOrderViolations();

  ///@{
  /**
   * The mappers' level of detail while the user interacts (on by default,
   * all three mappers): keep the volume, drawn within
   * InteractiveTargetSeconds by a reduced image (vtkHAVSMapperBase's
   * ImageReduction, upsampled with the edges kept sharp: EdgeUpsampling) and,
   * for HAVS, the boundary faces and as many
   * of the most important internal faces (vtkHAVSVolumeMapper::SetLevelOfDetail)
   * as fit, with InteractiveKBufferSize entries; the whole image, every face,
   * when still. Off: ParaView's own LOD (its outline or surface geometry) as
   * for the stock mappers.
   */
  vtkSetMacro(InteractiveLOD, bool);
  vtkGetMacro(InteractiveLOD, bool);
  ///@}

  ///@{
  /// The frame time the mappers aim at while the user interacts (seconds; 0.1 by default).
  vtkSetClampMacro(InteractiveTargetSeconds, double, 0.001, 10.0);
  vtkGetMacro(InteractiveTargetSeconds, double);
  ///@}

  /// The fraction of the internal faces the last frame drew (1: all).
  double GetHAVSLastLODFraction();

  ///@{
  /// k while the user interacts (ParaView's LOD renders); default 2.
  vtkSetClampMacro(InteractiveKBufferSize, int, 1, 64);
  vtkGetMacro(InteractiveKBufferSize, int);
  ///@}

  /// The k of the last frame this rank rendered (0 before one).
  int GetHAVSActiveKBufferSize();

  /// How cells that straddle the kd-tree's cuts are distributed over MPI ranks.
  enum Redistributions
  {
    RedistributionWholeCells = 0, ///< ParaView's stock: whole to one rank (seams)
    RedistributionSplit = 1,      ///< split at the cuts by ParaView (exact)
    RedistributionClip = 2        ///< sent whole to every box they touch, clipped there by
                                  ///< the mapper (exact; the default)
  };

  ///@{
  /**
   * How the grid is distributed over the ranks for ordered compositing (see
   * Redistributions; RedistributionClip by default). Serial runs are not
   * affected. RedistributionClip adds up to six clipping planes (the inner
   * faces of the rank's kd box) after the active mapper's own planes, which
   * share vtkHAVSFramePlanes::MaximumClippingPlanes with them (a warning says
   * when some of the mapper's own do not fit). Measured against the split
   * (benchmarks-parallel.md): the same image, a first frame 4 to 6 times
   * cheaper (ParaView's clipping of the cut cells and the mapper's first
   * draw of the split piece), fewer tetrahedra drawn.
   */
  void SetRedistribution(int mode);
  vtkGetMacro(Redistribution, int);
  ///@}

  /// The clipping planes this rank's mapper got from its kd box in the last
  /// frame (RedistributionClip; 0 otherwise).
  vtkGetMacro(LastRegionPlanes, int);

  ///@{
  /**
   * Under MPI: composite the ranks' volume images in float (on by default)
   * instead of IceT's 8-bit blend, in still frames where the view shows this
   * volume alone (vtkHAVSRankCompositePass: the mapper keeps its float
   * result, the displaying rank puts the ranks' results together in the kd
   * boxes' order and rounds once). IceT's 8-bit arithmetic alone leaves up to
   * 0.55/255 RMSE at 8 ranks; the float composite the exact image's 8-bit
   * rounding. Frames with other visible props, and interactive frames, keep
   * IceT's image.
   */
  vtkSetMacro(FloatComposite, bool);
  vtkGetMacro(FloatComposite, bool);
  ///@}

  /// What the last frame of the view did: 1 the ranks composited in float,
  /// 0 IceT's 8-bit image, -1 not parallel (serial, or no frame yet).
  int GetLastFloatComposite();
  /// Seconds this rank spent in the last frame's float composite (the gather,
  /// and on the displaying rank the composite; 0 without one).
  double GetLastFloatCompositeSeconds();

  /**
   * This representation always renders with the mapper SetHAVSMapper chose:
   * any name (e.g. a default pushed by an inherited proxy definition)
   * selects that one.
   */
  void SetActiveVolumeMapper(const char* name) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkHAVSUnstructuredGridVolumeRepresentation();
  ~vtkHAVSUnstructuredGridVolumeRepresentation() override;

  /// The superclass's, then the piece's stale polyhedron face arrays dropped
  /// (see DropStaleFaces in the .cxx): ParaView 5.11's redistribution
  /// crashes on them.
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkHAVSUnstructuredGridVolumeRepresentation(
    const vtkHAVSUnstructuredGridVolumeRepresentation&) = delete;
  void operator=(const vtkHAVSUnstructuredGridVolumeRepresentation&) = delete;

  vtkHAVSMapperBase* FindMapper(const std::string& name) const;
  void UpdateRegionPlanes(vtkInformation* inInfo, vtkHAVSMapperBase* active);
  void WarnIfPartitionsOverlap(vtkInformation* inInfo);

  vtkHAVSVolumeMapper* HAVSMapper;
  vtkHAVSRayCastMapper* RayCastMapper;
  vtkHAVSCellProjectionMapper* CellProjectionMapper;
  std::vector<std::pair<std::string, vtkHAVSMapperBase*>> Mappers; // the offered, by name
  std::string HAVSMapperName = "HAVS";
  int KBufferSize = 2;
  int InteractiveKBufferSize = 2;
  bool InteractiveLOD = true;
  double InteractiveTargetSeconds = 0.1;
  int Redistribution = RedistributionClip;
  int LastRegionPlanes = 0;
  bool FloatComposite = true;
  vtkWeakPointer<vtkObject> RankComposite; // the view's vtkHAVSRankCompositePass (MPI)
  bool WarnedOverlap = false;
  bool WarnedPlanes = false;
  vtkNew<vtkPlaneCollection> RegionPlanes; // the user's planes and this rank's kd box (clip)
  std::map<vtkHAVSMapperBase*, vtkSmartPointer<vtkPlaneCollection>> UserPlanes; // each mapper's own
  vtkNew<vtkStaticCleanUnstructuredGrid> PieceMerge; // the split piece's coincident points
};

VTK_ABI_NAMESPACE_END
#endif
