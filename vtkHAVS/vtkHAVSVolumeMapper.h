/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSVolumeMapper.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSVolumeMapper
 * @brief   Unstructured-grid volume mapper: HAVS with a GPU k-buffer.
 *
 * Hardware-Assisted Visibility Sorting (Callahan et al.): the unique
 * triangular faces of the tetrahedra are sorted by centroid distance on the
 * CPU (parallel LSD radix sort) and rasterized in that order; per pixel a
 * k-buffer of k entries finishes the sort, and each ray segment between two
 * consecutive fragments is coloured from a pre-integrated transfer-function
 * table and composited front to back. Boundary faces are oriented outward, so
 * a segment that starts at an exit from the mesh (a hole, a cavity, a gap
 * between parts) contributes nothing.
 *
 * Optical model (as VTK's unstructured-grid integrators): extinction
 * opacity(s) / ScalarOpacityUnitDistance, emission colour(s) times extinction,
 * scalar linear along each segment, lengths in world space after the volume's
 * matrix.
 *
 * Input: a vtkUnstructuredGrid of tetrahedra with point scalars (chosen with
 * SetScalarMode / SelectScalarArray). Other cells are skipped with a warning;
 * cell scalars are not supported yet (error). Blend modes: composite, maximum
 * and minimum intensity (these skip the sort).
 *
 * The k-buffer path (see vtkHAVSKBufferRenderer) is chosen automatically —
 * framebuffer fetch, else ordered fragment-shader interlock, else per-pixel
 * fragment lists sorted exactly at resolve — or forced with SetKBufferPath.
 *
 * The face sort is reused while neither the camera nor the volume's matrix
 * changes: a transfer-function edit only rebuilds the table.
 */
#ifndef vtkHAVSVolumeMapper_h
#define vtkHAVSVolumeMapper_h

#include "vtkHAVSModule.h" // For export macro
#include "vtkUnstructuredGridVolumeMapper.h"

#include <memory> // For std::unique_ptr

class vtkFloatArray;
class vtkIntArray;
class vtkHAVSFaceSet;
class vtkMatrix4x4;
class vtkOpenGLRenderWindow;
class vtkHAVSFaceSorter;
class vtkHAVSKBufferRenderer;
class vtkHAVSPreIntegrationTable;
class vtkRenderWindow;

class VTKHAVS_EXPORT vtkHAVSVolumeMapper : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkHAVSVolumeMapper* New();
  vtkTypeMacro(vtkHAVSVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum KBufferPaths
  {
    KBufferPathAutomatic = 0,
    KBufferPathFramebufferFetch = 1,
    KBufferPathFragmentShaderInterlock = 2,
    KBufferPathFragmentLists = 3
  };

  /**
   * Minimum intensity projection (the superclass has composite and maximum
   * intensity): the same value as vtkVolumeMapper's.
   */
  static constexpr int MINIMUM_INTENSITY_BLEND = 2;
  void SetBlendModeToMinimumIntensity() { this->SetBlendMode(MINIMUM_INTENSITY_BLEND); }

  ///@{
  /**
   * k: the number of k-buffer entries per pixel (the composited front plus
   * k - 1 waiting fragments; the incoming fragment is not counted). 1 … 14 on
   * the framebuffer-fetch path, up to 64 with interlock. The fragment-list
   * path sorts up to 64 fragments per pixel exactly whatever k is. Default 6.
   */
  vtkSetClampMacro(KBufferSize, int, 1, 64);
  vtkGetMacro(KBufferSize, int);
  ///@}

  ///@{
  /**
   * Which k-buffer path to use; Automatic (default) takes the best one the
   * context has. A forced path the context lacks falls back to Automatic with
   * a warning.
   */
  vtkSetClampMacro(KBufferPath, int, KBufferPathAutomatic, KBufferPathFragmentLists);
  vtkGetMacro(KBufferPath, int);
  void SetKBufferPathToAutomatic() { this->SetKBufferPath(KBufferPathAutomatic); }
  void SetKBufferPathToFramebufferFetch() { this->SetKBufferPath(KBufferPathFramebufferFetch); }
  void SetKBufferPathToFragmentShaderInterlock()
  {
    this->SetKBufferPath(KBufferPathFragmentShaderInterlock);
  }
  void SetKBufferPathToFragmentLists() { this->SetKBufferPath(KBufferPathFragmentLists); }
  ///@}

  /**
   * Whether `window` (an OpenGL window, initialized) can run `path`.
   */
  static bool IsKBufferPathSupported(vtkRenderWindow* window, int path);

  ///@{
  /**
   * The path and k the last frame ran with (0 and "None" before a frame).
   */
  vtkGetMacro(ActiveKBufferPath, int);
  const char* GetActiveKBufferPathName();
  vtkGetMacro(ActiveKBufferSize, int);
  ///@}

  ///@{
  /**
   * Early ray termination: a pixel stops taking fragments once its opacity
   * reaches this value. 1 turns it off. Default 0.999 (the error it allows is
   * below 1/255).
   */
  vtkSetClampMacro(EarlyRayTerminationOpacity, double, 0.0, 1.0);
  vtkGetMacro(EarlyRayTerminationOpacity, double);
  ///@}

  ///@{
  /**
   * Size of the pre-integrated table: entries along the front and back
   * scalar axes (default 128) and along the segment length (default 128).
   */
  vtkSetClampMacro(TableScalarResolution, int, 2, 1024);
  vtkGetMacro(TableScalarResolution, int);
  vtkSetClampMacro(TableLengthResolution, int, 2, 1024);
  vtkGetMacro(TableLengthResolution, int);
  ///@}

  ///@{
  /**
   * When on, the mapper waits for the GPU at the end of each stage so that
   * the stage times below are real (costs a little). Off by default.
   */
  vtkSetMacro(MeasureStageTimes, bool);
  vtkGetMacro(MeasureStageTimes, bool);
  vtkBooleanMacro(MeasureStageTimes, bool);
  ///@}

  ///@{
  /**
   * Benchmark aid: draw the sorted faces with a trivial shader and nothing
   * else (no k-buffer, nothing composited into the window): the time of the
   * rasterization alone, the lower bound of any face-based method on this
   * machine. Off by default.
   */
  vtkSetMacro(FaceRasterBoundMode, bool);
  vtkGetMacro(FaceRasterBoundMode, bool);
  vtkBooleanMacro(FaceRasterBoundMode, bool);
  ///@}

  enum VisibilityOrders
  {
    VisibilityOrderCentroid = 0,
    VisibilityOrderMPVO = 1,
    VisibilityOrderAutomatic = 2
  };

  ///@{
  /**
   * The face order the k-buffer finishes:
   * - Centroid (default): HAVS's sort of the face centroids by distance;
   *   nearly sorted, k absorbs the rest.
   * - MPVO (vtkHAVSVisibilityOrder): an exact front-to-back order of the
   *   tetrahedra, each face drawn when the one behind it is visited; with the
   *   non-convex method (SetNonConvexMethod) also across the gaps of a
   *   non-convex mesh. Without visibility cycles every pixel then needs only
   *   k = 1 (2 with fragments at equal distance).
   * - Automatic: the centroid order while the k-buffer keeps up with it; a
   *   frame with order violations (GetLastOrderViolations) is drawn again
   *   with MPVO at once, and MPVO stays for this mesh, k and k-buffer path.
   *   GetLastVisibilityOrder() says which order the last frame used.
   */
  vtkSetClampMacro(VisibilityOrder, int, VisibilityOrderCentroid, VisibilityOrderAutomatic);
  vtkGetMacro(VisibilityOrder, int);
  void SetVisibilityOrderToCentroid() { this->SetVisibilityOrder(VisibilityOrderCentroid); }
  void SetVisibilityOrderToMPVO() { this->SetVisibilityOrder(VisibilityOrderMPVO); }
  void SetVisibilityOrderToAutomatic() { this->SetVisibilityOrder(VisibilityOrderAutomatic); }
  ///@}

  /// The order the last frame was drawn with (Centroid or MPVO; -1: none, extremum modes).
  vtkGetMacro(LastVisibilityOrder, int);

  enum NonConvexMethods
  {
    NonConvexIgnore = 0,
    NonConvexBoundaryLayers = 1,
    NonConvexConvexification = 2
  };

  ///@{
  /**
   * MPVO on a non-convex mesh (see vtkHAVSVisibilityOrder): BoundaryLayers
   * (default; seed 003's idea: per frame, the boundary faces' depth order at
   * every pixel; exact on any boundary), Convexification (seed 004: convex
   * imaginary cells around the mesh, built once per mesh, nothing per frame;
   * needs a closed, consistently wound boundary: inverted or dropped
   * degenerate cells break it locally), or Ignore (exact only where no ray
   * re-enters the mesh). Unused for a convex mesh.
   */
  vtkSetClampMacro(NonConvexMethod, int, NonConvexIgnore, NonConvexConvexification);
  vtkGetMacro(NonConvexMethod, int);
  ///@}

  ///@{
  /**
   * Count order violations: fragments the k-buffer composited out of depth
   * order (nearer than what their pixel had been integrated to), i.e. pixels
   * where the face order plus k were not enough and the image is not exact.
   * On by default; the count is read back after each frame (a GPU sync).
   */
  vtkSetMacro(CountOrderViolations, bool);
  vtkGetMacro(CountOrderViolations, bool);
  vtkBooleanMacro(CountOrderViolations, bool);
  ///@}

  /// Order violations of the last frame (0 when not counted).
  vtkGetMacro(LastOrderViolations, vtkIdType);

  /**
   * Where the last frame's first order violations were (up to 16): pixel x, y
   * in the renderer's viewport, two components per tuple. Returns their number.
   */
  int GetLastOrderViolationPixels(vtkIntArray* pixels);

  ///@{
  /// MPVO on a non-convex mesh: imaginary cells and the seconds the
  /// convexification took (once per mesh); boundary-layer relations of the
  /// last frame and their seconds.
  vtkIdType GetNumberOfImaginaryCells();
  double GetConvexificationSeconds();
  vtkIdType GetLastBoundaryRelations();
  double GetLastBoundaryLayerSeconds();
  ///@}

  /// The next frame orders the faces again even if the view has not changed (benchmarks).
  void InvalidateFaceOrder();

  /// MPVO: the tetrahedra taken out of order to break visibility cycles in the last frame.
  vtkGetMacro(LastCycleBreaks, vtkIdType);

  enum BoundaryModes
  {
    BoundaryAutomatic = 0,
    BoundaryTagging = 1,
    BoundaryIgnore = 2,
    BoundaryGapLength = 3
  };

  ///@{
  /**
   * How segments outside the mesh (holes, cavities, gaps between parts, a
   * concave outline) are told from segments inside it.
   * - Automatic (default): boundary tagging, except for a convex mesh
   *   (vtkHAVSFaceSet::IsConvex, decided once per input), where it cannot
   *   change the image and is skipped.
   * - Tagging: always tag. Every fragment of a boundary face carries its role
   *   (entry or exit, from the facing of the outward-wound face); a segment
   *   whose front is an exit contributes nothing. Exact for any mesh, any k.
   * - Ignore: no tagging; every gap is filled as if it were volume (wrong for
   *   non-convex meshes; a negative control).
   * - GapLength: VTK 5's HAVS heuristic, for comparison: a segment longer than
   *   the longest edge contributes nothing (misses short gaps, drops long
   *   segments of sparse k-buffers).
   */
  vtkSetClampMacro(BoundaryMode, int, BoundaryAutomatic, BoundaryGapLength);
  vtkGetMacro(BoundaryMode, int);
  void SetBoundaryModeToAutomatic() { this->SetBoundaryMode(BoundaryAutomatic); }
  void SetBoundaryModeToTagging() { this->SetBoundaryMode(BoundaryTagging); }
  void SetBoundaryModeToIgnore() { this->SetBoundaryMode(BoundaryIgnore); }
  void SetBoundaryModeToGapLength() { this->SetBoundaryMode(BoundaryGapLength); }
  ///@}

  ///@{
  /**
   * Where the near plane or a clipping plane cuts the mesh, the rays enter
   * (or leave) the clipped volume where no face lies: the mapper draws the
   * mesh's section with the plane there, with the interpolated scalar, as an
   * entry (exit) fragment. On by default; off only for comparison (a
   * negative control: the slab between the plane and the first face behind
   * it is then lost).
   */
  vtkSetMacro(PlaneSections, bool);
  vtkGetMacro(PlaneSections, bool);
  vtkBooleanMacro(PlaneSections, bool);
  ///@}

  /// Whether the current input is one convex body (after its first frame).
  bool IsInputConvex();

  ///@{
  /**
   * What the last frame did at its boundaries and planes: whether boundary
   * fragments were tagged; how many planes cut the mesh (the near plane when
   * it lies inside the mesh's bounds, and the clipping planes); the triangles
   * of their sections with the mesh (drawn as the fragments where the rays
   * enter or leave the clipped volume) and the seconds spent making them.
   */
  vtkGetMacro(LastTagging, bool);
  vtkGetMacro(LastPlaneCount, int);
  vtkGetMacro(LastSectionTriangles, vtkIdType);
  vtkGetMacro(LastSectionSeconds, double);
  ///@}

  ///@{
  /**
   * Stage times of the last frame, in seconds.
   */
  vtkGetMacro(LastSortSeconds, double);
  vtkGetMacro(LastDrawSeconds, double);
  vtkGetMacro(LastFlushSeconds, double);
  vtkGetMacro(LastCompositeSeconds, double);
  vtkGetMacro(LastTableSeconds, double);
  /// True when the last frame reused the previous face order.
  vtkGetMacro(LastSortReused, bool);
  ///@}

  ///@{
  /**
   * When on, each frame's premultiplied float RGBA result (before it is
   * blended into the window) is kept and can be read with GetFloatResult().
   */
  vtkSetMacro(KeepFloatResult, bool);
  vtkGetMacro(KeepFloatResult, bool);
  vtkBooleanMacro(KeepFloatResult, bool);
  ///@}

  /**
   * The last frame's result (4 components, width*height tuples, bottom row
   * first, the renderer's viewport). Returns false when none is kept.
   */
  bool GetFloatResult(vtkFloatArray* rgba, int size[2]);

  ///@{
  /**
   * Mesh statistics of the current input.
   */
  vtkIdType GetNumberOfFaces();
  vtkIdType GetNumberOfBoundaryFaces();
  vtkIdType GetNumberOfTetrahedra();
  ///@}

  /**
   * The per-frame centroid sorter (its order is the draw order of the last
   * frame; statistics and test aids).
   */
  vtkHAVSFaceSorter* GetFaceSorter();

  /**
   * The pre-integrated table of the last frame (e.g. for the software
   * k-buffer, which must sample the same table).
   */
  vtkHAVSPreIntegrationTable* GetPreIntegrationTable();

  void Render(vtkRenderer* renderer, vtkVolume* volume) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkHAVSVolumeMapper();
  ~vtkHAVSVolumeMapper() override;

  int KBufferSize = 6;
  int KBufferPath = KBufferPathAutomatic;
  int ActiveKBufferPath = 0;
  int ActiveKBufferSize = 0;
  double EarlyRayTerminationOpacity = 0.999;
  int TableScalarResolution = 128;
  int TableLengthResolution = 128;
  bool MeasureStageTimes = false;
  bool KeepFloatResult = false;
  bool FaceRasterBoundMode = false;
  int BoundaryMode = BoundaryAutomatic;
  int VisibilityOrder = VisibilityOrderCentroid;
  int LastVisibilityOrder = -1;
  int NonConvexMethod = NonConvexBoundaryLayers;
  bool CountOrderViolations = true;
  vtkIdType LastOrderViolations = 0;
  vtkIdType LastCycleBreaks = 0;
  bool PlaneSections = true;
  bool LastTagging = false;
  int LastPlaneCount = 0;
  vtkIdType LastSectionTriangles = 0;
  double LastSectionSeconds = 0.0;

  double LastSortSeconds = 0.0;
  double LastDrawSeconds = 0.0;
  double LastFlushSeconds = 0.0;
  double LastCompositeSeconds = 0.0;
  double LastTableSeconds = 0.0;
  bool LastSortReused = false;

private:
  vtkHAVSVolumeMapper(const vtkHAVSVolumeMapper&) = delete;
  void operator=(const vtkHAVSVolumeMapper&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  bool UpdateMesh(vtkVolume* volume);
  bool UpdateTable(vtkVolume* volume);
  int ChoosePath(vtkRenderWindow* window);
  /// Orders the faces (order: a VisibilityOrders value) and renders the
  /// frame prepared in Internal; false when it could not.
  bool DrawFrame(vtkRenderer* renderer, vtkOpenGLRenderWindow* window, vtkVolume* volume, int order);
  bool UpdatePlanes(vtkRenderer* renderer, const double eye[3], const double direction[3],
    bool parallel, const vtkMatrix4x4* modelToEyeRelative);
};

#endif
