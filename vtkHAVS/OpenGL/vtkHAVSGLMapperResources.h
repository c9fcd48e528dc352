/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLMapperResources.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLMapperResources
 * @brief   What each of the three GL mappers holds in its window the same way.
 *
 * The window the mapper draws in (its context made current at the start of
 * a frame; the resources of an earlier window released first), a watch on
 * that window's deletion (a window that goes away while the mapper is not
 * among its props, so that nobody tells the mapper to release, takes the
 * resources with it), the pre-integration table on the GPU
 * (vtkHAVSGLTable, uploaded when its version changes) and the frame's
 * targets (vtkHAVSGLFrameTargets: the result, the opaque depth, the kept
 * result). The mapper's own GPU objects (a vtkHAVSGLOwnObjects given to
 * Own) are released with them, with the context current.
 *
 * The cell projection and the ray caster also share here the frame's frame:
 * BeginFrame (targets at the view's size, the opaque depth), the textures
 * and uniforms their programs read alike, the blending of a front-to-back
 * (or order-independent) draw, and EndFrame (the extremum blends' resolve,
 * the result composited into the window).
 */
#ifndef vtkHAVSGLMapperResources_h
#define vtkHAVSGLMapperResources_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSMapperGraphics.h" // For vtkHAVSMapperGraphics
#include "vtkNew.h"                // For vtkNew

#include <memory> // For std::unique_ptr
#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSFramePlanes;
class vtkHAVSGLBuffer;
class vtkHAVSGLCellRecords;
class vtkHAVSGLFrameTargets;
class vtkHAVSGLSection;
class vtkHAVSGLTable;
class vtkHAVSGLTableBuilder;
class vtkHAVSMapperBase;
class vtkHAVSMesh;
class vtkHAVSViewFrame;
class vtkShaderProgram;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkWindow;

/// A mapper's own GPU objects, owned and released by its vtkHAVSGLMapperResources.
struct vtkHAVSGLOwnObjects
{
  virtual ~vtkHAVSGLOwnObjects() = default;
  /// Releases every GL name they hold in `window` (its context current).
  virtual void Release(vtkOpenGLRenderWindow* window) = 0;
};

class vtkHAVSGLMapperResources : public vtkHAVSMapperGraphics
{
public:
  static vtkHAVSGLMapperResources* New();
  vtkTypeMacro(vtkHAVSGLMapperResources, vtkHAVSMapperGraphics);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Takes the mapper's own GPU objects (a vtkHAVSGLOwnObjects): released
   * with everything else (Release, the window's deletion, the resources'
   * own end, the context current) and deleted with the resources. Returns them.
   */
  template <class Objects>
  Objects* Own(std::unique_ptr<Objects> objects)
  {
    Objects* own = objects.get();
    this->Owned = std::move(objects);
    return own;
  }

  /**
   * The renderer's OpenGL window, its context current and everything of an
   * earlier window released; nullptr, with an error through `mapper` naming
   * `mapperName`, when it is not an OpenGL window or has no OpenGL 4.3
   * (storage buffers, images), which `needs` says what for.
   */
  vtkOpenGLRenderWindow* Prepare(
    vtkRenderer* renderer, vtkObject* mapper, const char* mapperName, const char* needs);

  /// Releases everything in `window` (nullptr: in whichever window holds it).
  void Release(vtkWindow* window) override;
  /// The targets' kept float result (vtkHAVSGLFrameTargets::GetKeptResult).
  const std::vector<float>* GetKeptResult(int size[2]) override;
  vtkMTimeType GetKeptResultTime() override;
  /// Every vtkHAVSGLBuffer of the process (vtkHAVSGLBuffer::GetLiveBytes): with
  /// one mapper, its own.
  size_t GetMemoryBytes() const override;
  ///@{
  /// Translucent layers intermixed (vtkHAVSTranslucentLayers, through the targets).
  int BeginIntermix(vtkRenderer* renderer) override;
  void SetIntermixSlab(int slab) override;
  void EndIntermix(bool drawn) override;
  ///@}
  /// The table's entries built by the resources' vtkHAVSGLTableBuilder in
  /// `renderer`'s window (prepared as by Prepare).
  bool BuildTableEntries(vtkRenderer* renderer, vtkObject* mapper, const char* mapperName,
    const vtkHAVSPreIntegrationTable::Quadrature& inputs, float* table) override;

  /**
   * The start of a cell-projection or ray-cast frame: the window prepared
   * (Prepare), the targets at the view's size, the opaque depth captured
   * when `opaque`, the near plane's section of `planes` uploaded if new,
   * the coverage mask of `mesh` asked for (vtkHAVSGLFrameTargets::SetCoverage;
   * nullptr: none).
   * nullptr, with Prepare's error, without a usable window.
   */
  vtkOpenGLRenderWindow* BeginFrame(vtkRenderer* renderer, vtkObject* mapper,
    const char* mapperName, const char* needs, const vtkHAVSViewFrame& view, bool opaque,
    const vtkHAVSFramePlanes& planes, vtkHAVSMesh* mesh);
  /// The near plane's section this frame: its triangles (0: none), and its draw
  /// with each triangle's cell at `cellBinding`.
  int GetSectionTriangles() const { return this->SectionTriangles; }
  void DrawSection(unsigned int cellBinding);
  /// The table's, the cell optics', the additive nodes' and the opaque depth's textures active.
  void ActivateTextures();
  /**
   * The uniforms of the view every cell-projection and ray-casting program
   * reads (havsMCRC, havsDCRC, havsDirectionOfProjection, havsParallel,
   * havsViewportSize, havsPlaneCount, havsPlanesRC) and, with `eye`, the
   * eye, the direction and the clip-to-model matrix in the mesh's shifted
   * model coordinates (havsEyeMC, havsDirectionMC, havsDCMC) and the linear
   * part of eye-relative world to model (havsRCMC): the pixels' rays.
   */
  static void SetViewUniforms(vtkShaderProgram* program, const vtkHAVSViewFrame& view,
    vtkHAVSFramePlanes* planes, const double shift[3], bool eye);
  /**
   * Clip to model coordinates and the eye in model coordinates, in double
   * (havsDCMCd, havsEyeMCd), where `program` declares them: the isosurface
   * frames' pixel rays (the k-buffer library's havsPixelRayMCd). The
   * program is bound.
   */
  static void SetDoubleViewUniforms(vtkShaderProgram* program, const vtkHAVSViewFrame& view);
  /// The table's uniforms, the additive nodes' and the opaque depth's units (textures active).
  void SetTextureUniforms(vtkShaderProgram* program);
  /**
   * Where `mapper`'s frame shades its isosurfaces (vtkHAVSIsoSurfaces::Shaded):
   * their gradient fields (vtkHAVSMapperBase::GetIsoGradientFields) uploaded if
   * new and bound where the shaders read them (binding 13), true. False where
   * the frame does not shade them, or, with a warning (the surfaces then
   * unshaded), where the fields exceed `largestBuffer` bytes.
   */
  bool BindIsoShading(vtkHAVSMapperBase* mapper, size_t largestBuffer);
  /// Blending for a draw front to back under the result (composite) or order-independent.
  void SetBlending(int blend);
  /**
   * The frame's end: the extremum blends' resolve, the textures deactivated,
   * the framebuffer bindings popped, the result kept when `keep` and
   * composited into the window. False, with an error, when it failed.
   */
  bool EndFrame(int blend, bool keep, const vtkHAVSViewFrame& view, vtkObject* mapper);

  /**
   * The common part of the cell projection's and the ray caster's frame
   * cases (Apps/GPUBench/README.md, vtkHAVSGLFrameCapture), after the draw:
   * refuses, with `error`, a frame the stand-alone program does not draw
   * (another blend, opaque geometry, clipping planes, the near plane's
   * section, cell scalars); else makes `directory`, writes its table.f32 and
   * result.f32 and returns in `header` the first lines of case.txt (the
   * format, `mapper`, the size, the table's size, the records' split).
   */
  bool BeginCapture(const std::string& directory, const char* mapper, int blend, bool opaque,
    vtkHAVSFramePlanes* planes, const vtkHAVSViewFrame& view, const vtkHAVSGLCellRecords& records,
    std::string& header, std::string& error);

  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }
  vtkHAVSGLTable* GetTable() { return this->Table; }
  vtkHAVSGLFrameTargets* GetTargets() { return this->Targets; }

protected:
  vtkHAVSGLMapperResources();
  ~vtkHAVSGLMapperResources() override;

private:
  vtkHAVSGLMapperResources(const vtkHAVSGLMapperResources&) = delete;
  void operator=(const vtkHAVSGLMapperResources&) = delete;

  void OnWindowDeleted(vtkObject* window, unsigned long, void*);

  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned long WindowDeleteObserver = 0;
  vtkNew<vtkHAVSGLTable> Table;
  vtkNew<vtkHAVSGLTableBuilder> TableBuilder;
  vtkNew<vtkHAVSGLFrameTargets> Targets;
  std::unique_ptr<vtkHAVSGLOwnObjects> Owned;
  std::unique_ptr<vtkHAVSGLSection> Section; // the near plane's section (cell projection, rays)
  int SectionTriangles = 0;
  std::unique_ptr<vtkHAVSGLBuffer> IsoGradientFields; // the shaded isosurfaces' (BindIsoShading)
  bool WarnedIsoFields = false;
};

VTK_ABI_NAMESPACE_END
#endif
