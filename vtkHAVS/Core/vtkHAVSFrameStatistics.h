/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFrameStatistics.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSFrameStatistics
 * @brief   What one frame of vtkHAVSVolumeMapper did: path, k, order, counts, times.
 *
 * Plain C++, no OpenGL. The mapper fills one per frame
 * (vtkHAVSVolumeMapper::GetLastFrameStatistics()); everything a user, a test
 * or the benchmark reads about the last frame is here, in one place, from C++
 * and Python:
 *
 * - what ran: the k-buffer path and k (0 for the extremum blend modes), the
 *   face order (vtkHAVSVolumeMapper::VisibilityOrders, -1 when none was
 *   needed), whether boundary fragments were tagged, the planes that cut the
 *   mesh and their sections;
 * - the order: whether the previous one was reused, cycle breaks, the
 *   boundary-layer relations of the exact order and their time;
 * - the result: order violations (fragments composited out of depth order,
 *   counted on the GPU when asked) and where the first ones were;
 * - stage times in seconds (exact only with MeasureStageTimes on; the GPU is
 *   not waited for otherwise);
 * - the work done again: whether the table was built, and which of the
 *   mesh's geometry, its scalars, the face order and the table were uploaded
 *   (each only when its inputs changed: a still camera and a
 *   transfer-function edit rebuild and upload the table only).
 */
#ifndef vtkHAVSFrameStatistics_h
#define vtkHAVSFrameStatistics_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkObject.h"

#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkIntArray;

class VTKHAVSCORE_EXPORT vtkHAVSFrameStatistics : public vtkObject
{
public:
  static vtkHAVSFrameStatistics* New();
  vtkTypeMacro(vtkHAVSFrameStatistics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Back to "no frame": every count and time zero, path none, order -1.
  void Reset();

  ///@{
  /// The k-buffer path (vtkHAVSVolumeMapper::KBufferPaths; 0: none) and k.
  vtkSetMacro(KBufferPath, int);
  vtkGetMacro(KBufferPath, int);
  const char* GetKBufferPathName() const;
  vtkSetMacro(KBufferSize, int);
  vtkGetMacro(KBufferSize, int);
  ///@}

  ///@{
  /// The face order drawn (vtkHAVSVolumeMapper::VisibilityOrders; -1: none).
  vtkSetMacro(VisibilityOrder, int);
  vtkGetMacro(VisibilityOrder, int);
  /// Whether the order is the previous frame's (nothing re-sorted).
  vtkSetMacro(OrderReused, bool);
  vtkGetMacro(OrderReused, bool);
  /// Exact order: tetrahedra taken out of order to break visibility cycles.
  vtkSetMacro(CycleBreaks, vtkIdType);
  vtkGetMacro(CycleBreaks, vtkIdType);
  /// Exact order with the boundary layers: relations found, and their seconds.
  vtkSetMacro(BoundaryRelations, vtkIdType);
  vtkGetMacro(BoundaryRelations, vtkIdType);
  vtkSetMacro(BoundaryLayerSeconds, double);
  vtkGetMacro(BoundaryLayerSeconds, double);
  ///@}

  ///@{
  /// Whether opaque geometry could end the rays (the depth was copied and the
  /// shaders compiled with the cut; off when the renderer has none).
  vtkSetMacro(OpaqueGeometry, bool);
  vtkGetMacro(OpaqueGeometry, bool);
  ///@}

  ///@{
  /// Boundary fragments tagged; planes cutting the mesh (near and clipping);
  /// triangles of their sections and the seconds those took.
  vtkSetMacro(Tagging, bool);
  vtkGetMacro(Tagging, bool);
  vtkSetMacro(PlaneCount, int);
  vtkGetMacro(PlaneCount, int);
  vtkSetMacro(SectionTriangles, vtkIdType);
  vtkGetMacro(SectionTriangles, vtkIdType);
  vtkSetMacro(SectionSeconds, double);
  vtkGetMacro(SectionSeconds, double);
  ///@}

  ///@{
  /// Fragments composited out of depth order (-1 when the frame did not count
  /// them: vtkHAVSVolumeMapper::SetCountOrderViolations).
  vtkSetMacro(OrderViolations, vtkIdType);
  vtkGetMacro(OrderViolations, vtkIdType);
  /// Where the first ones were: x, y in the viewport, two values each.
  void SetOrderViolationPixels(const std::vector<int>& xy) { this->ViolationPixels = xy; }
  const std::vector<int>& GetOrderViolationPixelList() const { return this->ViolationPixels; }
  /// The same into an array of 2-component tuples; returns their number.
  int GetOrderViolationPixels(vtkIntArray* pixels) const;
  ///@}

  ///@{
  /// With opaque geometry: whether its depth came from a multisampled
  /// framebuffer (resolved by a blit), and whether it was captured at all
  /// (false: the rays were not cut, a warning said so once).
  vtkSetMacro(OpaqueDepthMultisampled, bool);
  vtkGetMacro(OpaqueDepthMultisampled, bool);
  vtkSetMacro(OpaqueDepthCaptured, bool);
  vtkGetMacro(OpaqueDepthCaptured, bool);
  ///@}

  ///@{
  /// Fragment-list path: fragments stored.
  vtkSetMacro(Fragments, vtkIdType);
  vtkGetMacro(Fragments, vtkIdType);
  /// Pixels whose ray had ended at the last saturation mark of the draw, their
  /// later fragments rejected before the shader (vtkHAVSVolumeMapper::
  /// SkipSaturatedPixels); -1 when not read (read when the frame is measured,
  /// its result kept or its violations counted: reading waits for the GPU).
  vtkSetMacro(SaturatedPixels, vtkIdType);
  vtkGetMacro(SaturatedPixels, vtkIdType);
  /// Fragments that ran the k-buffer draw shader (framebuffer-fetch and
  /// interlock paths), counted by the shader with the order violations
  /// (vtkHAVSVolumeMapper::CountOrderViolations); -1 when not counted.
  vtkSetMacro(ShadedFragments, vtkIdType);
  vtkGetMacro(ShadedFragments, vtkIdType);
  /// Faces drawn (internal and boundary).
  vtkSetMacro(FacesDrawn, vtkIdType);
  vtkGetMacro(FacesDrawn, vtkIdType);
  /// Faces in the face order the frame drew (0 without one): the faces of
  /// culled cells are not ordered (vtkHAVSVolumeMapper::SkipOffscreenCells).
  vtkSetMacro(FacesOrdered, vtkIdType);
  vtkGetMacro(FacesOrdered, vtkIdType);
  ///@}

  ///@{
  /// Stage times in seconds: face order (sort and gather; the boundary layers
  /// and the gather are parts of it, see BoundaryLayerSeconds), upload, draw,
  /// flush (resolve), read-backs (violation count, kept result), composite;
  /// the table's last build (kept until the next build).
  vtkSetMacro(SortSeconds, double);
  vtkGetMacro(SortSeconds, double);
  vtkSetMacro(GatherSeconds, double);
  vtkGetMacro(GatherSeconds, double);
  vtkSetMacro(UploadSeconds, double);
  vtkGetMacro(UploadSeconds, double);
  vtkSetMacro(DrawSeconds, double);
  vtkGetMacro(DrawSeconds, double);
  vtkSetMacro(FlushSeconds, double);
  vtkGetMacro(FlushSeconds, double);
  vtkSetMacro(ReadbackSeconds, double);
  vtkGetMacro(ReadbackSeconds, double);
  vtkSetMacro(CompositeSeconds, double);
  vtkGetMacro(CompositeSeconds, double);
  vtkSetMacro(TableSeconds, double);
  vtkGetMacro(TableSeconds, double);
  ///@}

  ///@{
  /**
   * What the frame did to the mesh (vtkHAVSMesh::Updates: 0 nothing, 1 made
   * it again, 2 mapped a new time step's scalars only) and the seconds it took.
   */
  vtkSetMacro(MeshUpdate, int);
  vtkGetMacro(MeshUpdate, int);
  vtkSetMacro(MeshSeconds, double);
  vtkGetMacro(MeshSeconds, double);
  ///@}

  ///@{
  /**
   * The work the frame did again, each only when its inputs changed: the
   * pre-integration table built (the transfer function, the scalar range, the
   * unit distance or the table size changed), and the uploads to the GPU of
   * the mesh's geometry (a new mesh), its scalars only (a new time step on the
   * same mesh), the face order (a new order, i.e. the camera or the mesh
   * changed) and the table. The order itself: GetOrderReused().
   */
  vtkSetMacro(TableRebuilt, bool);
  vtkGetMacro(TableRebuilt, bool);
  vtkSetMacro(GeometryUploaded, bool);
  vtkGetMacro(GeometryUploaded, bool);
  vtkSetMacro(ScalarsUploaded, bool);
  vtkGetMacro(ScalarsUploaded, bool);
  vtkSetMacro(OrderUploaded, bool);
  vtkGetMacro(OrderUploaded, bool);
  vtkSetMacro(TableUploaded, bool);
  vtkGetMacro(TableUploaded, bool);
  ///@}

  ///@{
  /**
   * Tetrahedra not drawn because the transfer function hides them
   * (vtkHAVSVolumeMapper::SkipInvisibleCells), and the seconds their
   * visibility took to compute this frame (0 when it was kept).
   */
  vtkSetMacro(InvisibleCells, vtkIdType);
  vtkGetMacro(InvisibleCells, vtkIdType);
  vtkSetMacro(VisibilitySeconds, double);
  vtkGetMacro(VisibilitySeconds, double);
  ///@}

  ///@{
  /**
   * Tetrahedra not drawn because the frame cannot see them: outside the view
   * frustum or cut away by a clipping plane
   * (vtkHAVSVolumeMapper::SkipOffscreenCells), and the seconds that took.
   */
  vtkSetMacro(CulledCells, vtkIdType);
  vtkGetMacro(CulledCells, vtkIdType);
  vtkSetMacro(CullingSeconds, double);
  vtkGetMacro(CullingSeconds, double);
  ///@}

  ///@{
  /**
   * The level of detail (vtkHAVSVolumeMapper::SetLevelOfDetail): the fraction
   * of the internal faces the frame drew (1: all), whether its segments came
   * from the long-segment table, the seconds the ranking of the internal
   * faces took this frame (0 when reused), and the mapper's whole frame time
   * (wall clock, the draw finished), which the controller reads.
   */
  vtkSetMacro(LevelOfDetailFraction, double);
  vtkGetMacro(LevelOfDetailFraction, double);
  vtkSetMacro(LongSegmentTable, bool);
  vtkGetMacro(LongSegmentTable, bool);
  vtkSetMacro(RankingSeconds, double);
  vtkGetMacro(RankingSeconds, double);
  vtkSetMacro(FrameSeconds, double);
  vtkGetMacro(FrameSeconds, double);
  ///@}

  /// Automatic k (vtkHAVSVolumeMapper::SetAutomaticKBufferSize): the counted
  /// draws this frame's search made (0: the last view's k was kept).
  vtkSetMacro(AutomaticKDraws, int);
  vtkGetMacro(AutomaticKDraws, int);

protected:
  vtkHAVSFrameStatistics() = default;
  ~vtkHAVSFrameStatistics() override = default;

private:
  vtkHAVSFrameStatistics(const vtkHAVSFrameStatistics&) = delete;
  void operator=(const vtkHAVSFrameStatistics&) = delete;

  int KBufferPath = 0;
  int KBufferSize = 0;
  int VisibilityOrder = -1;
  bool OrderReused = false;
  vtkIdType CycleBreaks = 0;
  vtkIdType BoundaryRelations = 0;
  double BoundaryLayerSeconds = 0.0;
  bool Tagging = false;
  bool OpaqueGeometry = false;
  bool OpaqueDepthMultisampled = false;
  bool OpaqueDepthCaptured = false;
  int PlaneCount = 0;
  vtkIdType SectionTriangles = 0;
  double SectionSeconds = 0.0;
  vtkIdType OrderViolations = -1;
  std::vector<int> ViolationPixels;
  vtkIdType Fragments = 0;
  vtkIdType SaturatedPixels = -1;
  vtkIdType ShadedFragments = -1;
  vtkIdType FacesDrawn = 0;
  vtkIdType FacesOrdered = 0;
  double LevelOfDetailFraction = 1.0;
  bool LongSegmentTable = false;
  double RankingSeconds = 0.0;
  double FrameSeconds = 0.0;
  int AutomaticKDraws = 0;
  double SortSeconds = 0.0;
  double GatherSeconds = 0.0;
  double UploadSeconds = 0.0;
  double DrawSeconds = 0.0;
  double FlushSeconds = 0.0;
  double CompositeSeconds = 0.0;
  double ReadbackSeconds = 0.0;
  double TableSeconds = 0.0;
  int MeshUpdate = 0;
  double MeshSeconds = 0.0;
  bool TableRebuilt = false;
  bool GeometryUploaded = false;
  bool ScalarsUploaded = false;
  bool OrderUploaded = false;
  bool TableUploaded = false;
  vtkIdType InvisibleCells = 0;
  double VisibilitySeconds = 0.0;
  vtkIdType CulledCells = 0;
  double CullingSeconds = 0.0;
};

VTK_ABI_NAMESPACE_END
#endif
