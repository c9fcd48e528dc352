/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMapperBase.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSMapperBase
 * @brief   What the three vtkHAVS mappers share: settings, inputs, mesh, table and one frame's
 * skeleton.
 *
 * vtkHAVSVolumeMapper (HAVS: sorted faces, a k-buffer),
 * vtkHAVSCellProjectionMapper and vtkHAVSRayCastMapper derive from this
 * class, which holds once what each of them needs the same way:
 * - the input (any vtkDataSet or a composite data set of them), its bounds,
 *   the scalar selection (VTK's scalar mode and array, VectorMode,
 *   VectorComponent) and HigherOrderSubdivision;
 * - the prepared mesh (vtkHAVSMesh), which several mappers of the same input
 *   can share (SetMesh: ParaView's representation switches mapper without
 *   preparing the mesh again; GetLastMeshUpdate() says what a frame did);
 * - the pre-integration table of the volume's property
 *   (TableScalarResolution, TableLengthResolution), the near and clipping
 *   planes (vtkHAVSFramePlanes), the kept float result;
 * - the frame: Render() is the same for all three and calls one virtual,
 *   RenderView(), for what is specific:
 *     1. fire vtkCommand::VolumeMapperRenderStartEvent,
 *     2. check the blend mode (IsBlendModeSupported),
 *     3. update the input, prepare the mesh (MeshPrepared() tells the mapper),
 *     4. prepare the table (PrepareTable(), which HAVS overrides for its
 *        automatic resolution),
 *     5. the view (vtkHAVSViewFrame), skipped without pixels,
 *     6. RenderView(): the mapper's own order and draw,
 *     7. TimeToDraw (which vtkVolume adds into its estimated render time)
 *        and FrameFinished(),
 *     8. fire vtkCommand::VolumeMapperRenderEndEvent.
 *   Between the steps the render window's abort flag is checked
 *   (vtkRenderWindow::CheckAbortStatus, as VTK's projected tetrahedra do): an
 *   aborted frame draws nothing (GetLastFrameAborted()).
 *
 * Warnings that should be given once per mapper go through WarnOnce.
 *
 * The volume's shader property (vtkOpenGLShaderProperty) is read every frame
 * into vtkHAVSShaderHooks: the three mappers apply the same part of it, in
 * the pass that composites the volume's pixels over the scene
 * (`//VTK::CustomUniforms::Dec`, `//VTK::Base::Dec` and `//VTK::Base::Exit`
 * of vtkOpenGLGPUVolumeRayCastMapper's fragment tags, and the fragment custom
 * uniforms); for anything else in it the mapper warns once.
 */
#ifndef vtkHAVSMapperBase_h
#define vtkHAVSMapperBase_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h"          // For export macro
#include "vtkHAVSIsoSurfaces.h"         // For vtkHAVSIsoSurfaces
#include "vtkHAVSMemory.h"              // For vtkHAVSMemory::Part
#include "vtkHAVSPreIntegrationTable.h" // For vtkHAVSPreIntegrationTable::Quadrature
#include "vtkHAVSShaderHooks.h"         // For vtkHAVSShaderHooks
#include "vtkNew.h"                     // For vtkNew
#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkUnstructuredGridVolumeMapper.h"

#include <array>  // For std::array
#include <string> // For std::string
#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkFloatArray;
class vtkHAVSFramePlanes;
class vtkHAVSLevelOfDetailController;
class vtkHAVSMapperGraphics;
class vtkHAVSMesh;
class vtkHAVSPreIntegrationTable;
class vtkHAVSTableResolution;
class vtkHAVSViewFrame;

class VTKHAVSCORE_EXPORT vtkHAVSMapperBase : public vtkUnstructuredGridVolumeMapper
{
public:
  vtkTypeMacro(vtkHAVSMapperBase, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Releases the graphics layer's resources in `window` (all three mappers alike).
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * Blend modes beyond vtkUnstructuredGridVolumeMapper's composite and
   * maximum intensity, with vtkVolumeMapper's values: minimum intensity (all
   * three mappers) and additive (the cell projection and the ray caster).
   * IsBlendModeSupported() says which a mapper draws; another is an error.
   */
  static constexpr int MINIMUM_INTENSITY_BLEND = 2;
  static constexpr int ADDITIVE_BLEND = 4;
  static constexpr int ISOSURFACE_BLEND = 5;
  void SetBlendModeToMinimumIntensity() { this->SetBlendMode(MINIMUM_INTENSITY_BLEND); }
  void SetBlendModeToAdditive() { this->SetBlendMode(ADDITIVE_BLEND); }
  virtual bool IsBlendModeSupported(int mode);
  ///@}

  ///@{
  /**
   * The isosurface blend (all three mappers; vtkVolumeMapper's
   * ISOSURFACE_BLEND, 5), with VTK's semantics: the values are the volume
   * property's GetIsoSurfaceValues(); where a ray crosses one (found exactly:
   * the scalar is linear in a tetrahedron) the surface takes the transfer
   * functions' colour and opacity at that value, composited front to back,
   * and nothing contributes between the surfaces (vtkHAVSIsoSurfaces). Up to
   * vtkHAVSIsoSurfaces::MaximumCount values (more: the lowest ones, warned
   * once). With the property's ShadeOn the surfaces are lit by the
   * renderer's lights with the normals of the interpolated point gradients
   * (vtkHAVSIsoSurfaces::Shade, vtkHAVSPointGradients): the ray caster and
   * the cell projection from each cell's gradient field, HAVS on its
   * fragment-list path (whose nodes carry the fragments' gradients; such
   * frames take it whatever KBufferPath says). The volume between them stays
   * unshaded. Cell scalars have no crossings inside a cell: nothing is drawn
   * (warned once).
   *
   * IsoSurfacesInComposite (off by default): under the composite blend the
   * same surfaces are drawn inside the volume (the thesis' mixed mode): each
   * segment is split at its crossings.
   */
  void SetBlendModeToIsoSurface() { this->SetBlendMode(ISOSURFACE_BLEND); }
  vtkSetMacro(IsoSurfacesInComposite, bool);
  vtkGetMacro(IsoSurfacesInComposite, bool);
  vtkBooleanMacro(IsoSurfacesInComposite, bool);
  /// The surfaces the last frame drew (none outside the two modes above).
  const vtkHAVSIsoSurfaces& GetFrameIsoSurfaces() const { return this->FrameIsoSurfaces; }
  /**
   * The shaded isosurfaces' gradient fields (vtkHAVSPointGradients::
   * ComputeFields over the mesh's tetrahedra, model coordinates), made when
   * the mesh or its scalars changed; `version` changes with them. For the
   * graphics layer (not wrapped).
   */
  const std::vector<float>& GetIsoGradientFields(vtkMTimeType& version);
  /// The points' gradients themselves (3 floats a point, model coordinates;
  /// HAVS's vertices carry them), made as GetIsoGradientFields.
  const std::vector<float>& GetIsoPointGradients(vtkMTimeType& version);
  ///@}

  ///@{
  /**
   * The input: any vtkDataSet (vtkUnstructuredGridVolumeMapper's
   * SetInputData(vtkDataSet*) refuses what is not an unstructured grid), or a
   * composite data set of them (SetInputDataObject or a pipeline connection).
   * Cells that are not tetrahedra are split (vtkHAVSTetrahedralizer).
   */
  void SetInputData(vtkDataSet* input) override;
  void SetInputData(vtkUnstructuredGridBase* input) override;
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->Superclass::GetBounds(bounds); }
  ///@}

  ///@{
  /**
   * How a multi-component array becomes the scalar rendered, as
   * vtkSmartVolumeMapper::SetVectorMode: -1 (the default) the first component,
   * 0 the magnitude, 1 the component VectorComponent. The property's first
   * component's transfer functions colour it.
   */
  vtkSetClampMacro(VectorMode, int, -1, 1);
  vtkGetMacro(VectorMode, int);
  vtkSetClampMacro(VectorComponent, int, 0, 3);
  vtkGetMacro(VectorComponent, int);
  ///@}

  ///@{
  /**
   * Subdivision of quadratic and higher-order cells (vtkHAVSTetrahedralizer):
   * 0 (the default) splits them at their nodes only; n >= 1 refines every
   * non-linear hexahedron, tetrahedron, wedge and pyramid uniformly in its
   * parametric space, 2^n segments per edge, points and point data through
   * the cell's own interpolation (curved cells drawn curved), crack-free
   * across neighbours. Linear cells are unaffected. At most 6. A change
   * re-tessellates.
   */
  vtkSetClampMacro(HigherOrderSubdivision, int, 0, 6);
  vtkGetMacro(HigherOrderSubdivision, int);
  ///@}

  ///@{
  /**
   * Size of the pre-integrated table: entries along the front and back
   * scalar axes (default 128) and along the segment length (default 128),
   * 2 to 1024. The automatic resolution takes these as the largest allowed.
   */
  vtkSetClampMacro(TableScalarResolution, int, 2, 1024);
  vtkGetMacro(TableScalarResolution, int);
  vtkSetClampMacro(TableLengthResolution, int, 2, 1024);
  vtkGetMacro(TableLengthResolution, int);
  ///@}

  ///@{
  /**
   * The cheapest table within an error bound (vtkHAVSTableResolution), for
   * every mapper: on (default), each table build tries 32, 64, ... up to the
   * resolutions above and keeps the first whose mean error per unit distance,
   * measured against the adaptive integral, is at most TableErrorBound
   * (default 1e-4); a smaller table is built and sampled faster (a
   * transfer-function edit rebuilds it). Off: the resolutions above are used
   * as they are.
   */
  vtkSetMacro(AutomaticTableResolution, bool);
  vtkGetMacro(AutomaticTableResolution, bool);
  vtkBooleanMacro(AutomaticTableResolution, bool);
  void SetTableErrorBound(double bound);
  double GetTableErrorBound();
  ///@}

  ///@{
  /// The table in use: its resolutions (after the automatic choice) and, when
  /// chosen automatically, its measured error (else -1).
  int GetLastTableScalarResolution();
  int GetLastTableLengthResolution();
  double GetLastTableError();
  ///@}

  ///@{
  /**
   * Build the pre-integrated tables' entries on the GPU (off by default):
   * the same quadrature from the same fine samples of the functions, by a
   * compute shader in single precision (vtkHAVSGLTableBuilder), read back for
   * the CPU's users of the table (cell visibility, the automatic resolution's
   * probes). Entries agree with the CPU's to about 1e-6
   * (TestHAVSGLTableBuilder). Where the context cannot (no OpenGL 4.3, a
   * shader that does not compile, more than 1024 table scalars) the CPU
   * builds them, with an error.
   * Issue 45 measured it against the CPU's build (Documentation/benchmarks.md,
   * Transfer-function edits): on llvmpipe's 2 cores the CPU build is the
   * cheaper, hence off; on a GPU it was not measured.
   */
  vtkSetMacro(PreIntegrationOnGPU, bool);
  vtkGetMacro(PreIntegrationOnGPU, bool);
  vtkBooleanMacro(PreIntegrationOnGPU, bool);
  /// Whether the last table build ran on the GPU.
  vtkGetMacro(LastTableBuiltOnGPU, bool);
  ///@}

  ///@{
  /**
   * Where the near plane (the camera inside the mesh) or a clipping plane
   * cuts the mesh, the rays enter (or leave) the clipped volume where no face
   * lies: the mapper draws the mesh's section with the plane there, with the
   * interpolated scalar (vtkHAVSFramePlanes). HAVS draws the near plane's and
   * the clipping planes' sections; the cell projection and the ray caster
   * clip each segment analytically and draw the near plane's only. On by
   * default; off only as a negative control (the slab between the plane and
   * the first face behind it is then lost).
   */
  vtkSetMacro(PlaneSections, bool);
  vtkGetMacro(PlaneSections, bool);
  vtkBooleanMacro(PlaneSections, bool);
  ///@}

  /// Triangles of the planes' sections drawn in the last frame.
  vtkGetMacro(LastSectionTriangles, vtkIdType);

  ///@{
  /**
   * When on, each frame's premultiplied float RGBA result (before it is
   * blended into the window) is kept; GetFloatResult() copies it (4
   * components, width*height tuples, bottom row first, the renderer's
   * viewport) and returns false when none is kept.
   */
  vtkSetMacro(KeepFloatResult, bool);
  vtkGetMacro(KeepFloatResult, bool);
  vtkBooleanMacro(KeepFloatResult, bool);
  bool GetFloatResult(vtkFloatArray* rgba, int size[2]);
  /**
   * When the kept float result was made (a vtkTimeStamp's time, 0 when none
   * was): later than a vtkTimeStamp taken before a frame when that frame made
   * it (a frame that draws nothing keeps the last one).
   */
  vtkMTimeType GetFloatResultTime();
  ///@}

  ///@{
  /**
   * Translucent polygonal geometry intermixed with the volume per pixel (on
   * by default; it takes effect where the renderer's pass is a
   * vtkHAVSIntermixPass, which peels the translucent actors into layers):
   * under the composite and isosurface blends, each layer is composited at
   * its depth between the volume's pieces in front of and behind it, exactly.
   * The volume is drawn once per layer and once more, each time cut at the
   * next layer's depth (the opaque geometry's cut), and the pieces are
   * composited with the layers (vtkHAVSGLFrameTargets); the image reduction
   * of the level of detail is off for such frames. Off: the volume is
   * composited over the translucent scene as a whole (VTK's own order).
   * CanIntermix(): whether this frame would take the layers.
   */
  vtkSetMacro(IntermixTranslucentGeometry, bool);
  vtkGetMacro(IntermixTranslucentGeometry, bool);
  vtkBooleanMacro(IntermixTranslucentGeometry, bool);
  bool CanIntermix() const
  {
    return this->IntermixTranslucentGeometry &&
      (this->BlendMode == COMPOSITE_BLEND || this->BlendMode == ISOSURFACE_BLEND);
  }
  /// The translucent layers the last frame composited within the volume (0: none).
  vtkGetMacro(LastIntermixLayers, int);
  ///@}

  ///@{
  /**
   * The prepared mesh (never null). Mappers of the same input may share one:
   * `b->SetMesh(a->GetMesh())` makes b use (and keep up to date) a's mesh, so
   * that switching between them does not prepare it again. Each mapper still
   * prepares its own layout of it (the ray caster's records, the cell
   * projection's planes) when the mesh changed since that mapper last drew.
   * nullptr gives the mapper a mesh of its own again.
   */
  vtkHAVSMesh* GetMesh();
  void SetMesh(vtkHAVSMesh* mesh);
  ///@}

  /// Zero-volume tetrahedra the mesh dropped (they contribute nothing; a
  /// warning only above vtkHAVSMesh::DegenerateWarningShare of them).
  vtkIdType GetNumberOfDegenerateTetrahedra();

  /// What preparing the mesh did in the last frame.
  enum MeshUpdates
  {
    MeshNotPrepared = 0,   ///< the frame stopped before (no input, error, abort)
    MeshUnchanged = 1,     ///< as this mapper last drew it
    MeshBuilt = 2,         ///< built (or rebuilt) by this mapper from the input
    MeshScalarsMapped = 3, ///< a new time step: only the scalars mapped again
    MeshShared = 4         ///< prepared by another mapper sharing it since this one drew: no work
  };
  ///@{
  /// The last frame's mesh update (MeshUpdates), its seconds (0 unless built or mapped here).
  vtkGetMacro(LastMeshUpdate, int);
  vtkGetMacro(LastMeshSeconds, double);
  static const char* GetMeshUpdateName(int update);
  ///@}

  /// Whether the last frame was cut short by the render window's abort flag.
  vtkGetMacro(LastFrameAborted, bool);

  /// The seconds the last frame spent preparing its tables (step 4: the
  /// pre-integrated table and what depends on the transfer functions alone;
  /// about 0 when nothing was rebuilt): what a transfer-function edit adds.
  vtkGetMacro(LastTableSeconds, double);

  ///@{
  /**
   * Level of detail by a reduced image (all three mappers; on by default).
   * When the frame budget (LevelOfDetailTargetSeconds, else VTK's allocated
   * render time: vtkProp::GetAllocatedRenderTime, from the render window's
   * desired update rate, which VTK's interactor lowers while the user
   * interacts) is less than the last full frame took, a frame draws the volume
   * at a reduced scale of the viewport along each axis, as many pixels as the
   * last frames' times say fit (a vtkHAVSLevelOfDetailController on the share
   * of the full frame's detail), and the composite upsamples it (bilinear,
   * premultiplied; with EdgeUpsampling, edges kept sharp) over the viewport. A still frame (a
   * budget the last full frame fits) draws the whole viewport: the exact image. HAVS shares the
   * detail between the image and its face subset when its own LevelOfDetail
   * is on (vtkHAVSVolumeMapper: each takes the square root of the share).
   * Off: every frame draws the whole viewport (HAVS's face subset then has its
   * own controller, as before).
   */
  vtkSetMacro(ImageReduction, bool);
  vtkGetMacro(ImageReduction, bool);
  vtkBooleanMacro(ImageReduction, bool);
  /**
   * How a reduced image keeps the volume's edges sharp (on by default): the
   * mesh's boundary faces are drawn at every viewport pixel into a coverage
   * mask, behind which opaque geometry hides them; a pixel the mask leaves
   * empty gets nothing from the volume, as in the exact image, instead of
   * the reduced image's blur; a covered one upsamples bilinearly. The
   * silhouette and the edges of opaque geometry in front of the volume stay
   * as sharp as in a full frame; those of opaque geometry inside it, and
   * the volume's own features, are as blurred as the scale makes them. Not
   * where the near plane may cut the mesh's bounds (plain bilinear). Costs
   * one draw of the (front) boundary faces at the viewport's size, only in
   * reduced frames; where they can be: once the level of detail is at the
   * smallest image (MinimumImageScale) and a frame still took longer than
   * the budget, the next frames at the smallest image go without the mask,
   * until the image grows again (GetLastEdgeUpsampling). Off: plain bilinear.
   */
  vtkSetMacro(EdgeUpsampling, bool);
  vtkGetMacro(EdgeUpsampling, bool);
  vtkBooleanMacro(EdgeUpsampling, bool);
  /// Whether the last frame asked for the coverage mask (EdgeUpsampling, a
  /// reduced image, not dropped for the budget).
  vtkGetMacro(LastEdgeUpsampling, bool);
  /// The smallest scale a reduced image takes, per axis (default 0.1: 1 % of the pixels).
  vtkSetClampMacro(MinimumImageScale, double, 0.01, 1.0);
  vtkGetMacro(MinimumImageScale, double);
  /**
   * The largest scale any frame draws, per axis (default 1). Below 1 every
   * frame draws at most that, whatever the time: for tests, benchmarks and a
   * fixed interactive quality.
   */
  vtkSetClampMacro(ImageScale, double, 0.01, 1.0);
  vtkGetMacro(ImageScale, double);
  /**
   * The frame budget the level of detail aims at, in seconds: 0 (the
   * default) takes VTK's allocated render time; above 0 this budget instead
   * (ParaView's representation sets its interactive target here while the
   * user interacts, and an unlimited budget when still).
   */
  vtkSetClampMacro(LevelOfDetailTargetSeconds, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LevelOfDetailTargetSeconds, double);
  /// The last frame's image scale (per axis; 1: the whole viewport) and its
  /// share of the full frame's detail (pixels, and HAVS's faces).
  vtkGetMacro(LastImageScale, double);
  vtkGetMacro(LastDetail, double);
  /// The reduced image's controller (its gain and dead band).
  vtkHAVSLevelOfDetailController* GetImageReductionController();
  ///@}

  /**
   * One frame (see the class description): the same skeleton for the three
   * mappers; RenderView() is the mapper's own part.
   */
  void Render(vtkRenderer* renderer, vtkVolume* volume) final;

  /**
   * The part of the volume's shader property the last frame applied
   * (vtkHAVSShaderHooks, read at the start of Render; the GL layer's
   * composite applies it).
   */
  const vtkHAVSShaderHooks& GetShaderHooks() const { return this->ShaderHooks; }

  /**
   * Where the mapper's memory is (vtkHAVSMemory): the mesh (the tetrahedra,
   * their faces, points and scalars: shared by the mappers of one input), the
   * table, the mapper's own orders and records, and the GPU buffers. The
   * parts' arrays as allocated; not the input grid.
   */
  std::vector<vtkHAVSMemory::Part> GetMemoryParts() const;
  /// The sum of GetMemoryParts().
  size_t GetMemoryBytes() const;

  ///@{
  /**
   * The largest single GPU buffer the mapper makes, in bytes. A mesh whose
   * largest buffer would be larger is not drawn, with one error per mesh that
   * says what to do instead: HAVS's face indices, 12 bytes a face; the ray
   * caster's and the cell projection's cell records, 80 bytes a tetrahedron,
   * go in up to 4 buffers of at most this size (vtkHAVSCellGeometry), so the
   * ray caster's largest is 20 bytes a tetrahedron (its neighbours 16) and the
   * cell projection's its ordered faces' indices, 48 bytes a tetrahedron.
   * Default DefaultLargestGPUBuffer, 2^31 - 1 bytes: shaders address storage
   * buffers with 32-bit byte offsets, and llvmpipe's crash past 2 GiB (26.8
   * million tetrahedra's records in one buffer); the limit is what a buffer
   * can be addressed with, not what the GPU's memory holds.
   */
  static constexpr vtkIdType DefaultLargestGPUBuffer = 2147483647;
  vtkSetClampMacro(LargestGPUBuffer, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(LargestGPUBuffer, vtkIdType);
  ///@}
  /// The largest GPU buffer the prepared mesh needs (what it holds, its bytes).
  virtual vtkHAVSMemory::Part GetLargestGPUBufferNeed() const { return {}; }

  ///@{
  /**
   * Benchmark aid: the next frame writes the GPU inputs it drew from, its
   * shaders, uniforms and float result into this directory (a frame case of
   * Apps/GPUBench/havs_gpu_bench, described in Apps/GPUBench/README.md); the
   * setting is cleared after that frame. GetLastCaptureSucceeded() says
   * whether it was written (an error says why not). The GL mappers write it;
   * this base only holds the setting.
   */
  vtkSetStringMacro(CaptureDirectory);
  vtkGetStringMacro(CaptureDirectory);
  vtkGetMacro(LastCaptureSucceeded, bool);
  ///@}

protected:
  vtkHAVSMapperBase(const char* mapperName);
  ~vtkHAVSMapperBase() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  /// Adds the mapper's own parts to the memory ledger (GetMemoryParts).
  virtual void AddMemoryParts(std::vector<vtkHAVSMemory::Part>& vtkNotUsed(parts)) const {}
  /// Clears the last frame's statistics (called first in every frame).
  virtual void ResetLastFrame() {}
  /**
   * Called after the mesh was prepared, with what happened to it in this
   * frame (MeshUpdates) and whether it was built anew since this mapper last
   * drew (`rebuilt`: the mapper's own layout of it is made again; otherwise
   * anything but MeshUnchanged means new scalars: its fields only).
   */
  virtual void MeshPrepared(int update, bool rebuilt) = 0;
  /// The table for the volume's property (false, with an error, when it cannot be made).
  virtual bool PrepareTable(vtkVolume* volume);
  /// The frame's near and clipping planes and the mesh's sections with them
  /// (Planes, PlaneSections); warns once beyond 6 clipping planes.
  void UpdatePlanes(const vtkHAVSViewFrame& view);
  /// The mapper's own part of the frame: order, draw, statistics.
  virtual void RenderView(
    vtkRenderer* renderer, vtkVolume* volume, const vtkHAVSViewFrame& view) = 0;
  /// Called with the frame's time (TimeToDraw) after a frame that reached RenderView.
  virtual void FrameFinished(double vtkNotUsed(seconds)) {}
  /**
   * Whether the frame's detail (the share of the full frame's work the level
   * of detail allows, in (0, 1]) is shared with a subset of faces (HAVS with
   * its LevelOfDetail): then the pixels take its square root and the faces
   * the rest (FaceShare); otherwise the pixels take all of it.
   */
  virtual bool SharesDetailWithFaces() const { return false; }
  /// The share of the pixels a frame of this detail draws.
  double PixelShare(double detail) const;
  /// The smallest detail a frame draws: the one whose pixels are the smallest
  /// image's (MinimumImageScale squared, squared again when shared).
  double SmallestDetail() const;
  /// The frame's budget: LevelOfDetailTargetSeconds, else VTK's allocated render time.
  double FrameBudget(vtkVolume* volume) const;
  /// The frame's image scale: 1 unless the image reduction's budget asks for less.
  double ChooseImageScale(vtkVolume* volume);
  /// The frame's isosurfaces (FrameIsoSurfaces, their shading by `renderer`'s
  /// lights) and their once-only warnings.
  void PrepareIsoSurfaces(vtkRenderer* renderer, vtkVolume* volume);

  /// The blend the frame's passes draw: the isosurface blend is drawn as the
  /// composite one (front to back, in order), its segments made of surfaces.
  int GetFrameBlend() const
  {
    return this->BlendMode == ISOSURFACE_BLEND ? COMPOSITE_BLEND : this->BlendMode;
  }
  /// The graphics layer's kept float result (nullptr without one).
  const std::vector<float>* GetKeptResult(int size[2]);
  /// The graphics layer (the GL mapper's; not owned: it lives as long as the mapper).
  void SetGraphics(vtkHAVSMapperGraphics* graphics) { this->Graphics = graphics; }

  /// Whether the frame needs the opaque depth: opaque geometry, or an intermixed
  /// slab that ends at a layer.
  bool NeedsOpaqueDepth(vtkRenderer* renderer) const;
  /// Whether the render window asks to abort the frame (counts LastFrameAborted).
  bool AbortRequested(vtkRenderer* renderer);
  /// Warns once per mapper for `which` (vtkHAVSMapperInputs::OnceWarning).
  void WarnOnce(int which, const std::string& message);
  /// The mapper's name in messages ("vtkHAVSRayCastMapper", not its GL override's).
  const char* GetMapperName() const { return this->MapperName; }

  int VectorMode = -1;
  int VectorComponent = 0;
  int HigherOrderSubdivision = 0;
  int TableScalarResolution = 128;
  int TableLengthResolution = 128;
  bool KeepFloatResult = false;
  bool PlaneSections = true;
  vtkIdType LargestGPUBuffer = DefaultLargestGPUBuffer;
  vtkIdType LastSectionTriangles = 0;
  char* CaptureDirectory = nullptr;
  bool LastCaptureSucceeded = false;

  vtkSmartPointer<vtkHAVSMesh> Mesh;
  vtkNew<vtkHAVSPreIntegrationTable> Table;
  bool AutomaticTableResolution = true;
  bool PreIntegrationOnGPU = false;
  bool LastTableBuiltOnGPU = false;
  vtkRenderer* FrameRenderer = nullptr; ///< the renderer of the frame drawing now (else nullptr)
  /// The tables' EntryBuilder: the graphics layer's GPU build, where PreIntegrationOnGPU.
  bool BuildTableEntries(const vtkHAVSPreIntegrationTable::Quadrature& inputs, float* table);
  vtkNew<vtkHAVSTableResolution> TableChooser; ///< the automatic resolution's choice
  vtkTimeStamp TableBuildTime; ///< the table's version (changes when it was rebuilt)
  bool TableRebuilt = false;   ///< this frame rebuilt the table
  vtkNew<vtkHAVSFramePlanes> Planes;
  bool ImageReduction = true;
  double MinimumImageScale = 0.1;
  bool EdgeUpsampling = true;
  bool LastEdgeUpsampling = false;
  bool EdgesDroppedForBudget = false; // at the smallest image, over the budget
  double ImageScale = 1.0;
  double LevelOfDetailTargetSeconds = 0.0;
  double LastImageScale = 1.0;
  double LastDetail = 1.0;
  double FaceShare = 1.0; ///< the share of the frame's detail HAVS's faces take (1: none)
  bool IsoSurfacesInComposite = false;
  bool IntermixTranslucentGeometry = true;
  int LastIntermixLayers = 0;
  int IntermixSlab = 0; ///< the slab RenderView draws (0 outside intermixed frames)
  vtkHAVSIsoSurfaces FrameIsoSurfaces;
  /// What GetIsoGradientFields or GetIsoPointGradients made, and of which
  /// mesh (its build and scalar times).
  struct IsoGradients
  {
    std::vector<float> Values;
    vtkMTimeType Key[2] = { 0, 0 };
    vtkTimeStamp Time;
  };
  IsoGradients IsoGradientFields, IsoPointGradients;
  /// `made` again from the mesh's point gradients (`fields`: each cell's
  /// field of them, else the gradients) when the mesh or its scalars changed.
  const std::vector<float>& UpdateIsoGradients(
    IsoGradients& made, bool fields, vtkMTimeType& version);
  vtkNew<vtkHAVSLevelOfDetailController> ImageControl;

private:
  vtkHAVSMapperBase(const vtkHAVSMapperBase&) = delete;
  void operator=(const vtkHAVSMapperBase&) = delete;

  bool PrepareMesh(vtkVolume* volume);
  void PrepareShaderHooks(vtkVolume* volume);

  const char* MapperName;
  int LastMeshUpdate = MeshNotPrepared;
  double LastMeshSeconds = 0.0;
  bool LastFrameAborted = false;
  double LastTableSeconds = 0.0;
  vtkHAVSShaderHooks ShaderHooks;
  const vtkShaderProperty* ShaderHooksProperty = nullptr; // compared only, never used
  vtkHAVSMapperGraphics* Graphics = nullptr;
  vtkMTimeType SeenMeshBuild = 0; // the mesh's build and scalar times this mapper last drew
  vtkMTimeType SeenMeshScalars = 0;
  vtkMTimeType RefusedMeshBuild = 0; // the mesh build whose buffers were too large (said once)
  std::array<bool, 12> Warned{};     // vtkHAVSMapperInputs::NumberOfOnceWarnings
};

VTK_ABI_NAMESPACE_END
#endif
