/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFragmentListKBuffer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSFragmentListKBuffer
 * @brief   Per-pixel fragment lists, each sorted exactly at resolve.
 *
 * The exact fallback where neither framebuffer fetch nor an interlock exists
 * (OpenGL 4.4, or 4.3 with ARB_clear_texture): the draw appends every
 * fragment to its pixel's linked list (a head image, a node pool, an atomic
 * counter; the pool grows and the frame is drawn again when it overflows);
 * the resolve runs each list through a k-buffer of ListResolveCapacity
 * entries, which sorts any list of up to that many fragments exactly,
 * whatever order they came in. The result does not depend on k.
 */
#ifndef vtkHAVSFragmentListKBuffer_h
#define vtkHAVSFragmentListKBuffer_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSGLObjects.h" // For vtkHAVSGLBuffer, vtkHAVSGLImage
#include "vtkHAVSKBuffer.h"
#include "vtkHAVSOpenGL.h" // For GLuint

VTK_ABI_NAMESPACE_BEGIN

class vtkOpenGLRenderWindow;

class vtkHAVSFragmentListKBuffer : public vtkHAVSKBuffer
{
public:
  static vtkHAVSFragmentListKBuffer* New();
  vtkTypeMacro(vtkHAVSFragmentListKBuffer, vtkHAVSKBuffer);

  /// Whether the current context of `window` runs this path.
  static bool IsSupported(vtkOpenGLRenderWindow* window);

  int GetPath() const override;
  int GetMaximumK() const override;
  bool Allocate(vtkHAVSGLPassContext& context) override;
  bool Clear(vtkHAVSGLPassContext& context) override;
  bool Draw(vtkHAVSGLPassContext& context) override;
  bool Resolve(vtkHAVSGLPassContext& context) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkHAVSFragmentListKBuffer() = default;
  ~vtkHAVSFragmentListKBuffer() override = default;

private:
  vtkHAVSFragmentListKBuffer(const vtkHAVSFragmentListKBuffer&) = delete;
  void operator=(const vtkHAVSFragmentListKBuffer&) = delete;

  void GrowNodes(GLuint capacity);
  /// NodeGradients at the pool's capacity (shaded isosurfaces).
  void GrowNodeGradients();

  vtkHAVSGLImage Heads;          ///< each pixel's first node (R32UI)
  vtkHAVSGLBuffer Nodes;         ///< the node pool
  vtkHAVSGLBuffer NodeGradients; ///< (shaded isosurfaces) a gradient per node
  GLuint Capacity = 0;           ///< nodes the pool holds
  vtkHAVSGLBuffer Counter;       ///< nodes appended this frame
};

VTK_ABI_NAMESPACE_END
#endif
