/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLFrameTargets.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLFrameTargets
 * @brief   The per-viewport targets of a frame: opaque depth, float result, counter.
 *
 * - the opaque depth: a copy of the depth VTK's framebuffer holds when the
 *   volume is drawn (the opaque geometry, which ends the rays);
 * - the result: a float RGBA texture and its framebuffer, the premultiplied
 *   image the k-buffer's resolve writes and Composite() blends over VTK's
 *   framebuffer (ONE, ONE_MINUS_SRC_ALPHA);
 * - the order-violation counter (a storage buffer at binding 3: the count,
 *   then the first pixels);
 * - DrawFullViewport(): a full-viewport triangle for the clear, resolve and
 *   composite passes.
 */
#ifndef vtkHAVSGLFrameTargets_h
#define vtkHAVSGLFrameTargets_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSGLObjects.h" // For vtkHAVSGLBuffer, vtkHAVSGLVertexArray
#include "vtkHAVSOpenGL.h"    // For GLuint
#include "vtkObject.h"
#include "vtkSmartPointer.h"  // For vtkSmartPointer
#include "vtkTextureObject.h" // For vtkSmartPointer<vtkTextureObject>
#include "vtkTimeStamp.h"     // For vtkTimeStamp

#include <cstdint>          // For std::uint64_t
#include <initializer_list> // For std::initializer_list
#include <string>           // For std::string
#include <vector>           // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSFramePlanes;
class vtkHAVSMesh;
class vtkHAVSShaderHooks;
class vtkHAVSTranslucentLayers;
class vtkHAVSViewFrame;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

class vtkHAVSGLFrameTargets : public vtkObject
{
public:
  static vtkHAVSGLFrameTargets* New();
  vtkTypeMacro(vtkHAVSGLFrameTargets, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  static constexpr unsigned int LoggedViolations = 16; ///< pixels logged with the count

  void SetContext(vtkOpenGLRenderWindow* window) { this->Window = window; }

  /**
   * Sets the viewport's full size and the image drawn (smaller when the level
   * of detail reduces it: Composite() then upsamples it over the viewport).
   * The depth copy and the result are allocated at the full size, and again
   * only when that changes: a reduced frame draws into the result's lower
   * left corner, so a level of detail that changes the drawn size every
   * frame reallocates nothing (the per-pixel buffers of the passes follow
   * GetAllocatedSize() for the same reason).
   */
  void Resize(int fullWidth, int fullHeight, int width, int height);
  void Resize(int width, int height) { this->Resize(width, height, width, height); }
  /// The image drawn (the result's lower left corner) and the viewport's size.
  const int* GetSize() const { return this->Size; }
  const int* GetFullSize() const { return this->FullSize; }
  /// The size per-pixel buffers are allocated at (the viewport's: every drawn size fits).
  const int* GetAllocatedSize() const { return this->FullSize; }
  /**
   * Sets havsOpaqueDepthScale, the viewport's pixels per drawn pixel along
   * each axis (the passes read the full-size depth copy at the drawn pixel's
   * centre: vtkHAVSKBufferLib's havsOpaqueDistance).
   */
  void SetDepthScaleUniform(vtkShaderProgram* program) const;

  /**
   * Copies the depth of VTK's current (read) framebuffer at the viewport. A
   * multisampled framebuffer (an X window's, VTK's default) is resolved by a
   * blit into a single-sample depth texture of the framebuffer's own depth
   * format; where that fails, the far plane everywhere, and `reporter` (the
   * mapper) warns once.
   */
  void CaptureOpaqueDepth(int x, int y, int width, int height, vtkObject* reporter);
  /// Whether the last capture read a multisampled framebuffer; whether it got
  /// its depth (false: the far plane, no cut).
  bool GetLastCaptureMultisampled() const { return this->LastCaptureMultisampled; }
  bool GetLastCaptureResolved() const { return this->LastCaptureResolved; }
  vtkTextureObject* GetOpaqueDepth() { return this->OpaqueDepth; }

  /// The result's framebuffer bound for drawing, one colour attachment.
  void BindResult();
  /// The result's framebuffer bound for reading its colour attachment.
  void BindResultForReading();

  /// A new RGBA32F texture of this size (nearest, clamped), in `window`.
  static vtkSmartPointer<vtkTextureObject> NewFloatTexture(
    vtkOpenGLRenderWindow* window, int width, int height);
  vtkTextureObject* GetResult() { return this->Result; }
  /**
   * A copy of the drawn result (lower left corner), for a resolve that
   * reads what the draw wrote while writing the result; a texture of the
   * result's size, kept between frames.
   */
  vtkTextureObject* CopyResult();
  /// Reads the result back (width * height RGBA floats, bottom row first).
  void ReadResult(std::vector<float>& rgba);
  /// Reads the result back into the kept copy (the mappers' KeepFloatResult);
  /// in an intermixed frame, once, after the last slab (the intermixed sum).
  void KeepResult();
  /// The kept copy and its size; nullptr before one.
  const std::vector<float>* GetKeptResult(int size[2]) const;
  /// When the kept result was last read back (0: never).
  vtkMTimeType GetKeptResultTime() const { return this->KeptTime.GetMTime(); }

  /// Zeroes the order-violation counter and binds it (binding 3).
  void ResetViolationCounter();
  /// The count, and the first pixels (x, y) into `pixels`.
  std::uint64_t ReadViolationCounter(std::vector<int>& pixels, std::uint64_t* shaded = nullptr);

  /**
   * The volume's edges in a reduced frame (the level of detail's): the mesh
   * whose boundary faces Composite() draws at the viewport's full size into
   * a coverage mask, before it upsamples (vtkHAVSCoverageFS): the pixels no
   * boundary face covers in front of the opaque depth (`opaque`: whether
   * this frame captured it) stay empty, as in the exact image, and the
   * covered ones upsample bilinearly (vtkHAVSCompositeFS): the silhouette
   * and the edges of opaque geometry in front stay sharp.
   * Called once a frame, after Resize(); nothing is drawn for a full-size
   * frame, nor where the near plane cuts the mesh's bounds (`planes`:
   * vtkHAVSFramePlanes::GetNearPlaneCutsMesh; the volume is then seen
   * through the section, not a boundary face: plain bilinear).
   * The boundary faces' positions go to the GPU at the first reduced frame
   * of a mesh (9 floats a boundary face).
   */
  void SetCoverage(
    vtkHAVSMesh* mesh, const vtkHAVSViewFrame& view, const vtkHAVSFramePlanes& planes, bool opaque);

  /// Composites the result over VTK's framebuffer (viewport, of the full
  /// size, set by the caller), with the shader hooks last set applied; a
  /// reduced result is upsampled (bilinear, premultiplied; with the coverage
  /// mask where SetCoverage() gave one).
  bool Composite(int originX, int originY);
  /**
   * Translucent layers intermixed with the volume (vtkHAVSIntermixPass;
   * nullptr: none). SetIntermixSlab(i) before each slab's draw: for i below
   * the layers' count, CaptureOpaqueDepth() then takes the nearer of the
   * opaque depth and layer i's, and Composite() adds the slab to the
   * intermixed sum (vtkHAVSIntermixFS) without drawing into the window; the
   * last slab's Composite() writes the sum into the result (kept when a slab
   * asked KeepResult()) and composites it.
   */
  void SetIntermix(vtkHAVSTranslucentLayers* layers);
  void SetIntermixSlab(int slab) { this->IntermixSlab = slab; }
  vtkHAVSTranslucentLayers* GetIntermixLayers() const { return this->IntermixLayers; }

  /// The volume's shader hooks the composite applies (the mapper's; nullptr: none).
  void SetShaderHooks(const vtkHAVSShaderHooks* hooks) { this->Hooks = hooks; }

  /**
   * The end of a cell-projection or ray-cast frame, after its draw and its
   * blend's resolve (`resolved`: whether the resolve's program could be
   * built): the float result kept when `keep`, `textures` deactivated, the
   * framebuffer bindings the frame pushed popped, the viewport put back on
   * (originX, originY) at the full size, and the result composited there.
   * False, with an error from `reporter`, when the resolve failed; false
   * when the composite did.
   */
  bool EndFrame(bool resolved, bool keep, std::initializer_list<vtkTextureObject*> textures,
    int originX, int originY, vtkObject* reporter);

  /// A full-viewport triangle (the vertex shader makes it from gl_VertexID).
  void DrawFullViewport();

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkHAVSGLFrameTargets() = default;
  ~vtkHAVSGLFrameTargets() override = default;

private:
  vtkHAVSGLFrameTargets(const vtkHAVSGLFrameTargets&) = delete;
  void operator=(const vtkHAVSGLFrameTargets&) = delete;

  void ReleaseSizeDependent(vtkWindow* window);
  /// Reads the result back into the kept copy, now.
  void ReadKeptResult();
  /// The depth of the read framebuffer at the viewport, into the opaque depth.
  void CaptureFramebufferDepth(int x, int y, int width, int height, vtkObject* reporter);
  /// The opaque depth made the nearer of itself and `layerDepth`'s.
  void ClampOpaqueDepth(vtkTextureObject* layerDepth);
  /// Adds the slab drawn to the intermixed sum (the last: the sum into the result).
  bool AccumulateIntermix(int originX, int originY);
  /// Draws the coverage mask SetCoverage() asked for (false: none could be drawn).
  bool DrawCoverage();
  /// The vtkTextureObject depth format of the read framebuffer's depth, -1 if none.
  static int ReadFramebufferDepthFormat();

  vtkOpenGLRenderWindow* Window = nullptr;
  const vtkHAVSShaderHooks* Hooks = nullptr;
  std::string CompositeSource;         // the composite's fragment shader, hooks applied
  vtkMTimeType CompositeHooksTime = 0; // the hooks' Time it was composed for
  int Size[2] = { 0, 0 };
  int FullSize[2] = { 0, 0 };
  vtkSmartPointer<vtkTextureObject> OpaqueDepth;
  int OpaqueDepthFormat = -1;
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthResolveFramebuffer;
  bool LastCaptureMultisampled = false;
  bool LastCaptureResolved = false;
  bool WarnedUnresolvedDepth = false;
  vtkSmartPointer<vtkTextureObject> Result;
  vtkSmartPointer<vtkTextureObject> ResultCopy;
  vtkHAVSTranslucentLayers* IntermixLayers = nullptr; // this frame's, not owned
  int IntermixSlab = 0;
  bool IntermixKeep = false; // a slab asked KeepResult()
  vtkHAVSGLImage IntermixSum, IntermixPrevious, IntermixTransmittance;
  GLuint ClampFramebuffer = 0;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ResultFramebuffer;
  std::vector<float> KeptResult;
  int KeptSize[2] = { 0, 0 };
  vtkTimeStamp KeptTime; // when KeptResult was read back
  vtkHAVSGLBuffer ViolationCounter;
  vtkHAVSGLVertexArray EmptyVertexArray;
  // The coverage mask (SetCoverage): this frame's request, the boundary
  // faces' positions, the mask and its framebuffer.
  vtkHAVSMesh* CoverageMesh = nullptr; // the mapper's, not owned
  float CoverageModelToClip[16] = {};
  bool CoverageOpaque = false;
  bool CoverageFlipFacing = false;
  bool CoverageDrawn = false;
  vtkHAVSGLBuffer CoveragePoints;
  vtkHAVSGLVertexArray CoverageArray;
  GLsizei CoverageVertices = 0;
  vtkSmartPointer<vtkTextureObject> Coverage;
  vtkSmartPointer<vtkOpenGLFramebufferObject> CoverageFramebuffer;
};

VTK_ABI_NAMESPACE_END
#endif
