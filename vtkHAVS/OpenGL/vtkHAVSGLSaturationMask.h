/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLSaturationMask.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLSaturationMask
 * @brief   Rejects the fragments of saturated pixels before the k-buffer shader.
 *
 * Once a pixel's ray has ended (its opacity at the termination threshold, or
 * an opaque surface reached), every later fragment there is discarded by the
 * k-buffer shader, after it has loaded the pixel's entries (framebuffer
 * fetch) or entered its critical section (interlock). This cuts the face
 * draw into batches; after each, a full-viewport pass (the path's
 * SaturationMarkShader) marks the ended pixels in a stencil buffer, and the
 * next batches run with the stencil test `equal 0` and early fragment tests,
 * so those fragments never reach the shader (vtkHAVSVolumeMapper::
 * SkipSaturatedPixels). The shader would have discarded the same fragments:
 * the image does not change.
 *
 * It also counts, when asked, the pixels the last mark found (an occlusion
 * query; reading it waits for the GPU). The fragments that still run the
 * draw shader are counted by the shader itself, with the order violations
 * (havsCountShaded): llvmpipe's pipeline statistics count fragment-shader
 * invocations before the early stencil test, so they cannot show the skip.
 */
#ifndef vtkHAVSGLSaturationMask_h
#define vtkHAVSGLSaturationMask_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSGLObjects.h" // For vtkHAVSGLQueries
#include "vtkHAVSOpenGL.h"    // For GLuint
#include "vtkRenderbuffer.h"  // For vtkRenderbuffer
#include "vtkSmartPointer.h"  // For vtkSmartPointer
#include "vtkType.h"          // For vtkIdType

#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLPassContext;
class vtkShaderProgram;

class vtkHAVSGLSaturationMask
{
public:
  /// Batches of the face draw when saturated pixels are skipped.
  static constexpr int Batches = 4;

  vtkHAVSGLSaturationMask() = default;
  ~vtkHAVSGLSaturationMask() = default;

  /**
   * A stencil buffer of the context's viewport attached to the bound draw
   * framebuffer, every pixel unmarked. Call with the k-buffer's framebuffer
   * bound, before the draw.
   */
  void Attach(vtkHAVSGLPassContext& context);

  /**
   * The faces through `program` (bound). With `markShader` non-empty, in
   * Batches batches with the saturated pixels marked in between (the
   * framebuffer Attach()ed still bound); `storageBarrier`: the k-buffer lives
   * in a storage buffer (a barrier before each mark). `measure`: count the
   * pixels the last mark found (waits for the GPU).
   */
  void DrawFaces(vtkHAVSGLPassContext& context, vtkShaderProgram* program,
    const std::string& markShader, bool storageBarrier, bool measure);

  /// Pixels the last mark of the last DrawFaces found (-1: not measured).
  vtkIdType GetLastSaturatedPixels() const { return this->LastSaturatedPixels; }

  void ReleaseGraphicsResources();

private:
  vtkHAVSGLSaturationMask(const vtkHAVSGLSaturationMask&) = delete;
  void operator=(const vtkHAVSGLSaturationMask&) = delete;

  vtkSmartPointer<vtkRenderbuffer> Stencil; ///< depth-stencil, attached to the result's framebuffer
  vtkHAVSGLQueries Queries;                 ///< samples passed by the last mark
  vtkIdType LastSaturatedPixels = -1;
};

VTK_ABI_NAMESPACE_END
#endif
