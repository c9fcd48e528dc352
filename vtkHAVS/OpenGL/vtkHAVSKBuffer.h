/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSKBuffer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSKBuffer
 * @brief   One k-buffer path on the GPU: allocate, clear, draw, resolve, release.
 *
 * The per-pixel k-buffer of HAVS (Callahan, Ikits, Comba and Silva 2005;
 * Bavoil et al. 2007): each fragment of the faces, drawn in order, is
 * inserted among the k entries of its pixel; the nearest entry and the
 * newcomer bound a ray segment, composited front to back from the table; the
 * resolve flushes what is left in depth order into the frame's result. The
 * read-modify-write of a pixel's entries must not race; the three paths do it
 * their own way:
 * - vtkHAVSFramebufferFetchKBuffer: colour attachments read in the shader
 *   (EXT_shader_framebuffer_fetch, coherent, ordered per primitive), k <= 14;
 * - vtkHAVSInterlockKBuffer: a per-pixel storage buffer inside an ordered
 *   fragment-shader interlock (ARB/NV), k <= 64;
 * - vtkHAVSFragmentListKBuffer: every fragment appended to a per-pixel list,
 *   each list sorted exactly at resolve (any order in, up to 64 fragments per
 *   pixel; the result does not depend on k).
 * A frame calls Allocate, Clear, Draw and Resolve in that order, with the
 * frame's vtkHAVSGLPassContext; each returns false when a shader could not be
 * built.
 */
#ifndef vtkHAVSKBuffer_h
#define vtkHAVSKBuffer_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSGLSaturationMask.h" // For vtkHAVSGLSaturationMask
#include "vtkObject.h"

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLPassContext;
class vtkShaderProgram;
class vtkWindow;

class vtkHAVSKBuffer : public vtkObject
{
public:
  vtkTypeMacro(vtkHAVSKBuffer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The path (vtkHAVSVolumeMapper::KBufferPaths) and its largest k.
  virtual int GetPath() const = 0;
  virtual int GetMaximumK() const = 0;

  /// Storage for the context's viewport and k (kept while they are unchanged).
  virtual bool Allocate(vtkHAVSGLPassContext& context) = 0;
  /// Every pixel's k-buffer empty.
  virtual bool Clear(vtkHAVSGLPassContext& context) = 0;
  /// The faces, in draw order, through the k-buffer.
  virtual bool Draw(vtkHAVSGLPassContext& context) = 0;
  /// The entries left leave in depth order into the result (bound by the caller).
  virtual bool Resolve(vtkHAVSGLPassContext& context) = 0;
  virtual void ReleaseGraphicsResources(vtkWindow* window) = 0;

  /// Fragments stored in the last frame (fragment lists; 0 elsewhere).
  vtkIdType GetLastFragmentCount() const { return this->LastFragmentCount; }
  /// The pixels the last frame's last saturation mark found
  /// (vtkHAVSGLSaturationMask; -1 when not measured).
  vtkIdType GetLastSaturatedPixels() const { return this->Saturation.GetLastSaturatedPixels(); }

protected:
  vtkHAVSKBuffer() = default;
  ~vtkHAVSKBuffer() override = default;

  /**
   * The faces through `program`, skipping saturated pixels when the frame
   * asks for it (markShader: the path's vtkHAVSShaders::
   * SaturationMarkShader) and measuring what vtkHAVSGLSaturationMask measures
   * when the frame waits for the GPU anyway. Call Saturation.Attach() with
   * the draw framebuffer bound before.
   */
  void DrawFaces(vtkHAVSGLPassContext& context, vtkShaderProgram* program, bool storageBuffer);

  vtkIdType LastFragmentCount = 0;
  vtkHAVSGLSaturationMask Saturation;

private:
  vtkHAVSKBuffer(const vtkHAVSKBuffer&) = delete;
  void operator=(const vtkHAVSKBuffer&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif
