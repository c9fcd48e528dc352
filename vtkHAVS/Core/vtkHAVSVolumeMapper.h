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
 * Hardware-Assisted Visibility Sorting (Callahan, Ikits, Comba and Silva
 * 2005; Callahan 2005): the unique triangular faces of the tetrahedra are
 * ordered on the CPU and rasterized in that order; per pixel a k-buffer of k
 * entries (Bavoil et al. 2007) finishes the sort, and each ray segment
 * between two consecutive fragments is coloured from a pre-integrated
 * transfer-function table (Röttger, Kraus and Ertl 2000; Engel, Kraus and
 * Ertl 2001) and composited front to back. Boundary faces are wound outward,
 * so a segment that starts at an exit from the mesh (a hole, a cavity, a gap
 * between parts) contributes nothing.
 *
 * Optical model (as VTK's unstructured-grid integrators; Williams and Max
 * 1992): extinction opacity(s) / ScalarOpacityUnitDistance, emission colour(s)
 * times extinction, scalar linear along each segment, lengths in world space
 * after the volume's matrix.
 *
 * Input, scalars, mesh and table: as the other two mappers
 * (vtkHAVSMapperBase): any vtkDataSet or composite data set, every cell type
 * (split into tetrahedra, vtkHAVSTetrahedralizer), point or cell scalars
 * (chosen with SetScalarMode / SelectScalarArray). Blend modes: composite,
 * maximum and minimum intensity (these need no face order).
 *
 * This class is GL-free: it holds every setting and runs the algorithm of a
 * frame (vtkHAVSMapperBase::Render, then RenderView): prepare the mesh
 * (vtkHAVSMesh), prepare the table (vtkHAVSPreIntegrationTable), the view
 * (vtkHAVSViewFrame), the cells the transfer function hides, the planes
 * (vtkHAVSFramePlanes), the face order (vtkHAVSFaceOrderPolicy), draw, and
 * the frame's statistics (vtkHAVSFrameStatistics). Drawing is the graphics
 * layer's: New() returns the object-factory override, vtkOpenGLHAVSVolumeMapper
 * (module vtkHAVS::OpenGL; call vtk_module_autoinit with it, or import
 * vtkhavs in Python).
 *
 * The k-buffer path is chosen automatically — framebuffer fetch, else ordered
 * fragment-shader interlock, else per-pixel fragment lists sorted exactly at
 * resolve — or forced with SetKBufferPath.
 *
 * The face order is reused while neither the camera nor the volume's matrix
 * changes: a transfer-function edit only rebuilds the table.
 */
#ifndef vtkHAVSVolumeMapper_h
#define vtkHAVSVolumeMapper_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h"   // For export macro
#include "vtkHAVSFrameRequest.h" // For vtkHAVSFrameRequest, vtkHAVSFrameResult
#include "vtkHAVSMapperBase.h"
#include "vtkNew.h" // For vtkNew

#include <cstdint> // For uint32_t
#include <string>  // For std::string
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSCellVisibility;
class vtkHAVSFaceOrderPolicy;
class vtkHAVSFaceSorter;
class vtkHAVSInternalFaceRanking;
class vtkHAVSLevelOfDetailController;
class vtkHAVSFrameStatistics;
class vtkHAVSViewCulling;
class vtkRenderWindow;

class VTKHAVSCORE_EXPORT vtkHAVSVolumeMapper : public vtkHAVSMapperBase
{
public:
  /// The graphics layer's override (vtkOpenGLHAVSVolumeMapper); nullptr without one.
  static vtkHAVSVolumeMapper* New();
  vtkTypeMacro(vtkHAVSVolumeMapper, vtkHAVSMapperBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum KBufferPaths
  {
    KBufferPathAutomatic = 0,
    KBufferPathFramebufferFetch = 1,
    KBufferPathFragmentShaderInterlock = 2,
    KBufferPathFragmentLists = 3
  };
  /// "Automatic", "FramebufferFetch", "FragmentShaderInterlock", "FragmentLists"; "None" else.
  static const char* GetKBufferPathName(int path);

  /// Composite, maximum and minimum intensity, isosurface (not additive).
  bool IsBlendModeSupported(int mode) override;

  ///@{
  /**
   * k: the number of k-buffer entries per pixel (the composited front plus
   * k - 1 waiting fragments; the incoming fragment is not counted). 1 … 14 on
   * the framebuffer-fetch path, up to 64 with interlock. The fragment-list
   * path sorts up to 64 fragments per pixel exactly whatever k is. Default 2:
   * with the default MPVO order every pixel's fragments arrive sorted but for
   * ties at equal distance, which k = 2 sorts (the defaults are exact: RMSE <
   * 5e-4 and max < 0.01 against the exact reference on the 14 standard views
   * of the blunt fin, the LOX post and the combustor, TestHAVSExactOrder).
   * With the centroid order use 6 to 14.
   */
  vtkSetClampMacro(KBufferSize, int, 1, 64);
  vtkGetMacro(KBufferSize, int);
  /**
   * Automatic k per view (default off: KBufferSize): the smallest k at which
   * the view has no order violation (the k-buffer sorted every pixel: the
   * image is exact), found by counted draws that are not composited (a
   * search: the last view's k, doubled until clean, then halved between the
   * last k with violations and the first without), for the face order in use.
   * Searched again when the view direction turns by more than 5 degrees, the
   * eye moves by more than 5 % of the mesh's diagonal, or the mesh, order or
   * path changes; between, the found k is used. When no k up to the path's
   * maximum is clean, the maximum is used. Composite blend only; the
   * statistics say the k drawn (GetKBufferSize()) and the search's draws
   * (GetAutomaticKDraws()).
   */
  vtkSetMacro(AutomaticKBufferSize, bool);
  vtkGetMacro(AutomaticKBufferSize, bool);
  vtkBooleanMacro(AutomaticKBufferSize, bool);
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
   * Whether `window` (an OpenGL window, initialized) can run `path`. False
   * without a graphics layer.
   */
  virtual bool IsKBufferPathSupported(vtkRenderWindow* window, int path);

  ///@{
  /**
   * Early ray termination: a pixel stops taking fragments once its opacity
   * reaches this value. 1 turns it off. Default 0.999 (the error it allows is
   * below 1/255).
   */
  vtkSetClampMacro(EarlyRayTerminationOpacity, double, 0.0, 1.0);
  vtkGetMacro(EarlyRayTerminationOpacity, double);
  ///@}

  // The table's resolutions and its automatic choice (AutomaticTableResolution,
  // TableErrorBound): vtkHAVSMapperBase.

  ///@{
  /**
   * Skip the cells the transfer function hides (default on;
   * vtkHAVSCellVisibility): a cell whose scalars span only values of zero
   * opacity is not drawn, and the faces between it and a visible cell act as
   * boundary faces, which BoundaryModeAutomatic then tags (the gap behind them
   * is empty), so the image stays exact. Recomputed in parallel after a
   * transfer-function edit; the mesh on the GPU is kept, the faces drawn are
   * gathered again. With BoundaryModeIgnore or GapLength the gaps are not
   * handled (a control, not a setting to use). Composite blend only; the
   * frame statistics count the cells skipped.
   */
  vtkSetMacro(SkipInvisibleCells, bool);
  vtkGetMacro(SkipInvisibleCells, bool);
  vtkBooleanMacro(SkipInvisibleCells, bool);
  /**
   * Skip the cells the frame cannot see (default on; vtkHAVSViewCulling): a
   * cell whose points all lie outside one plane of the view frustum (a
   * zoomed-in view) or on the discarded side of a clipping plane is neither
   * ordered (centroid or exact order) nor drawn. None of its fragments would
   * reach the image, so it stays the same. The frame statistics count them
   * (GetCulledCells(), GetFacesOrdered()).
   */
  vtkSetMacro(SkipOffscreenCells, bool);
  vtkGetMacro(SkipOffscreenCells, bool);
  vtkBooleanMacro(SkipOffscreenCells, bool);
  /**
   * Reject the fragments of saturated pixels before the k-buffer shader runs
   * (issue 17): the face draw is cut into batches, and after each a
   * full-viewport pass marks in a stencil buffer the pixels whose ray has
   * ended (opacity at EarlyRayTerminationOpacity, or an opaque surface
   * reached); the next batches' fragments there fail the early stencil test.
   * The shader would discard exactly those fragments itself, so the image is
   * the same; the saving is the shader's loads (framebuffer fetch) or its
   * critical section (interlock), the cost three full-viewport passes and
   * the stencil test. Composite blend; the fragment lists store every
   * fragment regardless. SkipSaturatedPixelsAutomatic (the default) uses it
   * on the interlock path only: on llvmpipe's framebuffer-fetch path the
   * shader's own discard is nearly as cheap, and two measurements disagreed
   * (the blunt fin at 512^2, nothing to skip / most rays ending early: 1.19x
   * / 1.03x the default's frame time in one run, 0.96x / 0.80x in another).
   * On (1) forces it on both paths, Off (0) never. The frame statistics give the pixels marked
   * and, with CountOrderViolations, the fragments that ran the shader
   * (GetSaturatedPixels, GetShadedFragments).
   */
  enum SaturatedPixelSkipping
  {
    SkipSaturatedPixelsNever = 0,
    SkipSaturatedPixelsAlways = 1,
    SkipSaturatedPixelsAutomatic = 2
  };
  vtkSetClampMacro(SkipSaturatedPixels, int, 0, 2);
  vtkGetMacro(SkipSaturatedPixels, int);
  vtkBooleanMacro(SkipSaturatedPixels, int);
  /**
   * Nearly invisible cells: also skip a cell when the table's opacity for
   * the longest segment over its scalar range is at most this (default 0:
   * only fully transparent cells, exact). Above 0 trades exactness for speed.
   */
  void SetInvisibleCellOpacity(double opacity);
  double GetInvisibleCellOpacity();
  ///@}

  ///@{
  /**
   * Dynamic level of detail (default on; composite blend): when the renderer
   * allocates the volume less time than its last full frame took (VTK's
   * interactor lowers the window's desired update rate's budget while the
   * user interacts and gives it back when they stop), a frame draws every
   * boundary face (and every face between a visible and an invisible cell)
   * and only the most important internal faces, as many as the last frames'
   * times say fit (vtkHAVSLevelOfDetailController). The skipped faces make
   * segments longer than any cell: those frames read a second table built
   * over the mesh's bounding-box diagonal (the thesis' method). A still frame
   * (the full budget) draws every face with the exact table: the exact image.
   * Off: every frame draws every face. With the base's ImageReduction on (the
   * default) the frame's detail is shared: the face subset takes the square
   * root of the share the budget allows and the reduced image the other
   * (PixelShare); the budget is vtkHAVSMapperBase::LevelOfDetailTargetSeconds.
   * With ImageReduction off the face subset alone meets the budget, by its
   * own controller (GetLevelOfDetailController).
   */
  vtkSetMacro(LevelOfDetail, bool);
  vtkGetMacro(LevelOfDetail, bool);
  vtkBooleanMacro(LevelOfDetail, bool);
  /**
   * The most internal faces any frame draws, as a fraction (default 1).
   * Below 1 every frame draws at most that many, whatever the time: for
   * tests, benchmarks and a fixed interactive quality. 0: the boundary only.
   */
  vtkSetClampMacro(LevelOfDetailFraction, double, 0.0, 1.0);
  vtkGetMacro(LevelOfDetailFraction, double);
  /**
   * How the internal faces are ranked (vtkHAVSInternalFaceRanking::Strategies:
   * 0 Topology, 1 ViewAligned, 2 Field, 3 Area (the default), 4 Random).
   * The ranking is made once per mesh (ViewAligned: its clusters once, their
   * order per view), when a frame first draws a subset.
   */
  vtkSetClampMacro(LevelOfDetailStrategy, int, 0, 4);
  vtkGetMacro(LevelOfDetailStrategy, int);
  void SetLevelOfDetailStrategyToTopology() { this->SetLevelOfDetailStrategy(0); }
  void SetLevelOfDetailStrategyToViewAligned() { this->SetLevelOfDetailStrategy(1); }
  void SetLevelOfDetailStrategyToField() { this->SetLevelOfDetailStrategy(2); }
  void SetLevelOfDetailStrategyToArea() { this->SetLevelOfDetailStrategy(3); }
  void SetLevelOfDetailStrategyToRandom() { this->SetLevelOfDetailStrategy(4); }
  /// The ranking (its preprocessing time and memory) and the controller.
  vtkHAVSInternalFaceRanking* GetLevelOfDetailRanking();
  vtkHAVSLevelOfDetailController* GetLevelOfDetailController();
  ///@}

  ///@{
  /**
   * When on, the mapper waits for the GPU at the end of each stage so that
   * the stage times of the frame statistics are real (costs a little). Off by
   * default.
   */
  vtkSetMacro(MeasureStageTimes, bool);
  vtkGetMacro(MeasureStageTimes, bool);
  vtkBooleanMacro(MeasureStageTimes, bool);
  ///@}

  ///@{
  /**
   * Benchmark aid: draw the ordered faces with a trivial shader and nothing
   * else (no k-buffer, nothing composited into the window): the time of the
   * rasterization alone, the lower bound of any face-based method on this
   * machine; the faces are those HAVS draws (invisible cells skipped alike).
   * Off by default.
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
   * The face order the k-buffer finishes (see vtkHAVSFaceOrderPolicy):
   * - Centroid: HAVS's sort of the face centroids by distance; nearly
   *   sorted, k absorbs the rest (raise k, e.g. to 6 or 14, with it).
   * - MPVO (default): an exact front-to-back order of the tetrahedra (Williams 1992,
   *   vtkHAVSVisibilityOrder), each face drawn when the one behind it is
   *   visited; with the non-convex method (SetNonConvexMethod) also across
   *   the gaps of a non-convex mesh. Without visibility cycles every pixel
   *   then needs only k = 1 (2 with fragments at equal distance).
   * - Automatic: the centroid order while the k-buffer keeps up with it; a
   *   frame with order violations is drawn again with MPVO at once, and MPVO
   *   stays for this mesh, k and k-buffer path.
   * GetLastVisibilityOrder() says which order the last frame used.
   */
  vtkSetClampMacro(VisibilityOrder, int, VisibilityOrderCentroid, VisibilityOrderAutomatic);
  vtkGetMacro(VisibilityOrder, int);
  void SetVisibilityOrderToCentroid() { this->SetVisibilityOrder(VisibilityOrderCentroid); }
  void SetVisibilityOrderToMPVO() { this->SetVisibilityOrder(VisibilityOrderMPVO); }
  void SetVisibilityOrderToAutomatic() { this->SetVisibilityOrder(VisibilityOrderAutomatic); }
  ///@}

  ///@{
  /**
   * MPVO on a non-convex mesh (vtkHAVSVisibilityOrder::NonConvexMethods):
   * BoundaryLayers (default; after Krishnan, Silva and Wei 2001: per frame,
   * the boundary faces' depth order at every pixel; exact on any boundary),
   * Convexification (Röttger, Guthe, Schieber and Ertl 2004: convex imaginary
   * cells around the mesh, built once per mesh, nothing per frame; needs a
   * closed, consistently wound boundary: inverted or dropped degenerate cells
   * break it locally), or Ignore (exact only where no ray re-enters the mesh).
   * Unused for a convex mesh.
   */
  vtkSetClampMacro(NonConvexMethod, int, 0, 2);
  vtkGetMacro(NonConvexMethod, int);
  void SetNonConvexMethodToIgnore();
  void SetNonConvexMethodToBoundaryLayers();
  void SetNonConvexMethodToConvexification();
  ///@}

  ///@{
  /**
   * Count order violations: fragments the k-buffer composited out of depth
   * order (nearer than what their pixel had been integrated to), i.e. pixels
   * where the face order plus k were not enough and the image is not exact.
   * Off by default (the counter is then compiled out of the shaders; Automatic
   * counts while it probes the centroid order). When on, the count is read
   * back after each frame (a GPU sync).
   */
  vtkSetMacro(CountOrderViolations, bool);
  vtkGetMacro(CountOrderViolations, bool);
  vtkBooleanMacro(CountOrderViolations, bool);
  ///@}

  ///@{
  /// Testing aid (a negative control): isosurface frames with the fragments
  /// as the rasterizer gives them (a shader variant without the code below).
  /// There a face fragment whose face's scalars come within 1e-2 of an
  /// isovalue takes its scalar and distance where the pixel centre's ray
  /// meets the face, in double (vtkHAVSKBufferLib.glsl, havsOnFace): the
  /// rasterizer interpolates at vertices snapped to 1/256 pixel, and an
  /// isovalue within that of a face's scalar came out on the wrong side of
  /// it; elsewhere, and where that ray passes outside the face (a pixel centre
  /// the rasterizer covers just outside a sliver seen edge-on), the fragment's
  /// scalar is kept within its face's vertex scalars and its distance within
  /// the face's (havsClampToFace). Off by default.
  vtkSetMacro(NoFaceClampForTesting, bool);
  vtkGetMacro(NoFaceClampForTesting, bool);
  ///@}

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

  /**
   * What the last frame did: path, k, order, violations, counts, times.
   */
  vtkHAVSFrameStatistics* GetLastFrameStatistics();

  ///@{
  /// Shorthands for the last frame's statistics.
  int GetActiveKBufferPath();
  const char* GetActiveKBufferPathName();
  int GetActiveKBufferSize();
  int GetLastVisibilityOrder();
  vtkIdType GetLastOrderViolations();
  ///@}

  ///@{
  /// Mesh statistics of the current input.
  vtkIdType GetNumberOfFaces();
  vtkIdType GetNumberOfBoundaryFaces();
  vtkIdType GetNumberOfTetrahedra();
  /// Whether the current input is one convex body (after its first frame).
  bool IsInputConvex();
  ///@}

  ///@{
  /// MPVO on a non-convex mesh: imaginary cells and the seconds the
  /// convexification took (once per mesh).
  vtkIdType GetNumberOfImaginaryCells();
  double GetConvexificationSeconds();
  ///@}

  /// The next frame orders the faces again even if the view has not changed (benchmarks).
  void InvalidateFaceOrder();

  /**
   * The face-order policy (its centroid sorter's order is the last centroid
   * frame's draw order; statistics and test aids).
   */
  vtkHAVSFaceOrderPolicy* GetFaceOrderPolicy();
  /// Its centroid sorter.
  vtkHAVSFaceSorter* GetFaceSorter();

  /**
   * The pre-integrated table of the last frame (e.g. for the software
   * k-buffer, which must sample the same table).
   */
  vtkHAVSPreIntegrationTable* GetPreIntegrationTable();

#ifndef __VTK_WRAP__
  /// The graphics layer's side: one frame's request and result (vtkHAVSFrameRequest.h).
  using FrameRequest = vtkHAVSFrameRequest;
  using FrameResult = vtkHAVSFrameResult;
#endif

protected:
  vtkHAVSVolumeMapper();
  ~vtkHAVSVolumeMapper() override;

  ///@{
  /// The frame's HAVS part (vtkHAVSMapperBase::Render calls them in order).
  void ResetLastFrame() override;
  void AddMemoryParts(std::vector<vtkHAVSMemory::Part>& parts) const override;
  vtkHAVSMemory::Part GetLargestGPUBufferNeed() const override;
  void MeshPrepared(int update, bool rebuilt) override;
  bool PrepareTable(vtkVolume* volume) override;
  void RenderView(vtkRenderer* renderer, vtkVolume* volume, const vtkHAVSViewFrame& view) override;
  void FrameFinished(double seconds) override;
  /// With LevelOfDetail (composite blend): the face subset takes part of the detail.
  bool SharesDetailWithFaces() const override;
  ///@}

  ///@{
  /**
   * The graphics layer (vtkOpenGLHAVSVolumeMapper): the path the window can
   * run for the requested one (0: none), the largest k of a path, one frame
   * drawn (false, with an error, when it could not), the kept result of a
   * frame drawn without compositing composited now.
   */
  virtual int ChooseKBufferPath(vtkRenderer* renderer, int requested);
  virtual int GetMaximumK(int path);
  virtual bool DrawFrame(vtkRenderer* renderer, const FrameRequest& request, FrameResult& result);
  virtual bool CompositeKeptResult(vtkRenderer* renderer);
  ///@}

  int KBufferSize = 2;
  bool AutomaticKBufferSize = false;
  int KBufferPath = KBufferPathAutomatic;
  double EarlyRayTerminationOpacity = 0.999;
  bool SkipInvisibleCells = true;
  bool SkipOffscreenCells = true;
  int SkipSaturatedPixels = SkipSaturatedPixelsAutomatic;
  bool LevelOfDetail = true;
  double LevelOfDetailFraction = 1.0;
  int LevelOfDetailStrategy = 3; // vtkHAVSInternalFaceRanking::Area
  bool MeasureStageTimes = false;
  bool FaceRasterBoundMode = false;
  int BoundaryMode = BoundaryAutomatic;
  int VisibilityOrder = VisibilityOrderMPVO;
  int NonConvexMethod = 1; // vtkHAVSVisibilityOrder::NonConvexBoundaryLayers
  bool CountOrderViolations = false;
  bool NoFaceClampForTesting = false;

private:
  vtkHAVSVolumeMapper(const vtkHAVSVolumeMapper&) = delete;
  void operator=(const vtkHAVSVolumeMapper&) = delete;

  bool PrepareLongSegmentTable(vtkVolume* volume);
  /// Automatic k: whether the view moved far enough from the last search's.
  bool NeedsKSearch(const vtkHAVSViewFrame& view, int order, int path);
  /// Automatic k: the search's counted draws; returns the k found, and in
  /// `kept` whether the last draw was at that k (its result kept, not composited).
  int SearchK(vtkRenderer* renderer, FrameRequest request, int maxK, bool& kept, FrameResult& last);
  double ChooseLevelOfDetail(
    vtkVolume* volume, const vtkHAVSViewFrame& view, FrameRequest& request);
  FrameRequest MakeRequest(const vtkHAVSViewFrame& view, int path, int k, bool opaque);
  /// The frame's draw: the face order and the k-buffer (Automatic's probe and
  /// the automatic k may draw more than once); false when nothing was drawn.
  bool DrawOrdered(vtkRenderer* renderer, const vtkHAVSViewFrame& view, int path, int maxK,
    FrameRequest& request, FrameResult& result);
  /// Every statistic of a drawn frame, from its request and result.
  void RecordStatistics(int path, const FrameRequest& request, const FrameResult& result);
  /// The uploads of one draw added to the frame's (a frame may draw more than once).
  void RecordUploads(const FrameResult& result);

  vtkNew<vtkHAVSFaceOrderPolicy> FaceOrder;
  vtkNew<vtkHAVSCellVisibility> Visibility;
  vtkNew<vtkHAVSViewCulling> Culling;
  vtkNew<vtkHAVSInternalFaceRanking> Ranking;
  vtkNew<vtkHAVSLevelOfDetailController> LevelOfDetailControl;
  vtkNew<vtkHAVSPreIntegrationTable> LongSegmentTable;
  vtkTimeStamp LongSegmentTableBuildTime;
  // Automatic k: the k found and the view, mesh, order and path it was found for.
  struct KSearchKey
  {
    double Eye[3] = { 0, 0, 0 };
    double Direction[3] = { 0, 0, 0 };
    vtkMTimeType Mesh = 0;
    int Order = -2;
    int Path = 0;
  };
  KSearchKey LastKSearch;
  int FoundK = 0; // 0: none yet
  int KSearchDraws = 0;
  FrameResult KSearchUploads;  // what the search's draws uploaded
  bool SkippingCells = false;  // this frame skips invisible cells
  double DrawnFraction = -1.0; // the level of detail's fraction drawn (-1: nothing drawn)
  vtkNew<vtkHAVSFrameStatistics> LastFrame;
};

VTK_ABI_NAMESPACE_END
#endif
